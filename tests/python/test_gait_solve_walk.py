"""Gaits from Python: the polynomial gait's boundary conditions and work-energy balance (Mu
ch. 3), an OCP solve whose cost equals the CLI's on the same config, a closed-loop walk that
stays on its reference, and the CLI's exit codes as exception types."""
import json
import subprocess

import numpy as np
import pytest

import gaitopt
from conftest import ROOT

RABBIT_OCP = str(ROOT / "configs/ocp/rabbit_kelly2017.yaml")


def test_poly_gait_boundary_conditions(robot, poly_gait):
    g = poly_gait
    assert g.step_length == pytest.approx(0.35)  # configs/gaits/mu2004.yaml
    assert g.duration == pytest.approx(0.7)
    assert [p for p, _ in g.phase_durations] == ["SSP", "DSP"]
    theta = g.theta
    assert theta.shape == (len(g), 5) and g.t.shape == (len(g),)
    # The swing tip leaves the ground at the start and lands one step length ahead at touchdown
    # (the last SSP knot), on level ground.
    touchdown = g.phase.index("DSP") - 1
    np.testing.assert_allclose(robot.swing_tip(theta[0]), [-0.35, 0.0], atol=1e-9)
    np.testing.assert_allclose(robot.swing_tip(theta[touchdown]), [0.35, 0.0], atol=1e-9)
    # Periodic after relabelling (Mu sec. 2.4): the end posture is the start posture with the legs
    # swapped (links 1,2 <-> 5,4, torso kept); a leg link relabelled runs the other way along
    # itself, so its absolute angle turns by pi.
    expected = theta[0][[4, 3, 2, 1, 0]] + np.pi * np.array([1, 1, 0, 1, 1])
    wrapped = np.angle(np.exp(1j * (theta[-1] - expected)))
    np.testing.assert_allclose(wrapped, 0, atol=1e-6)


def test_poly_gait_torques_do_the_work_the_energy_changes_by(robot, poly_gait):
    # Work-energy theorem in single support, B pinned (the ground does no work): the joints' work,
    # the integral of tau . qdot with qdot = M dtheta the joint rates (Mu 2.41-2.43), is the
    # change of K + P (Mu 2.3, 2.4), a law the torques keep only if the dynamics that made them
    # derive from K and P. Trapezoid over the 1 kHz samples, O(h^2): measured 7.1e-5 J (2.8e-4 J
    # at 500 Hz) of the 8.3 J the joints exchange; tau . dtheta in place of tau . qdot is 5.2 J off.
    g = poly_gait
    ssp = slice(0, g.phase.index("DSP"))  # up to the touchdown, the last SSP knot
    theta, dtheta = g.theta[ssp], g.dtheta[ssp]
    qdot = np.column_stack([dtheta[:, 0], dtheta[:, :-1] - dtheta[:, 1:]])
    work = np.trapz(np.einsum("ij,ij->i", g.tau[ssp], qdot), g.t[ssp])
    energy = [robot.kinetic_energy(th, d) + robot.potential_energy(th)
              for th, d in zip(theta, dtheta)]
    assert work == pytest.approx(energy[-1] - energy[0], abs=3e-4)


def test_written_folder_is_on_one_grid_and_reads_back(robot, poly_gait, tmp_path):
    # DSP time 0.6 s and end 0.7 s are off the 128 Hz grid: trajectory.csv holds t_i = i / 128,
    # summary.json the touchdown's two states and the end's, and reading gives the step back.
    step = poly_gait.resample(128)
    assert gaitopt.write_trajectory(step, robot, str(tmp_path), rate_hz=128) == 90
    t = np.loadtxt(tmp_path / "trajectory.csv", delimiter=",", skiprows=1, usecols=0)
    np.testing.assert_allclose(t, np.arange(90) / 128, rtol=0, atol=1e-12)
    summary = json.loads((tmp_path / "summary.json").read_text())
    [switch] = summary["phase_switches"]
    assert switch["t"] == pytest.approx(0.6) and summary["step_end"]["t"] == step.duration
    back = gaitopt.read_trajectory(str(tmp_path / "trajectory.csv"), robot)
    np.testing.assert_array_equal(back.t, step.t)
    np.testing.assert_array_equal(back.theta, step.theta)
    np.testing.assert_array_equal(back.dtheta, step.dtheta)
    assert back.phase == step.phase


def test_reading_a_gait_of_another_robot_or_a_failed_solve_is_refused(robot, poly_gait, tmp_path):
    # The file alone checks only the number of links: RABBIT also has five.
    gaitopt.write_trajectory(poly_gait, robot, str(tmp_path / "g"), rate_hz=100)
    rabbit = gaitopt.Robot(str(ROOT / "configs/robots/rabbit.yaml"))
    with pytest.raises(gaitopt.InputError, match="the gait is of robot 'mu2004_five_link', not "
                                                 "of robot 'rabbit'"):
        gaitopt.read_trajectory(str(tmp_path / "g" / "trajectory.csv"), rabbit)
    (tmp_path / "g" / "FAILED.txt").write_text("a failed solve")
    with pytest.raises(gaitopt.InputError, match="holds a failed solve"):
        gaitopt.read_trajectory(str(tmp_path / "g" / "trajectory.csv"), robot)


def test_written_folder_follows_the_cli_out_rules(robot, poly_gait, tmp_path):
    # A folder of the user's files is refused and left whole; a missing one is created, and
    # gaitopt's own is replaced, but not once a file was added to it since (notes beside the
    # gait, which replacing it would delete).
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "summary.json").write_text("user data")
    with pytest.raises(gaitopt.InputError, match="holds files that gaitopt did not write"):
        gaitopt.write_trajectory(poly_gait, robot, str(mine), rate_hz=100)
    assert (mine / "summary.json").read_text() == "user data"
    assert not (mine / "trajectory.csv").exists()
    new = tmp_path / "new" / "gait"
    assert gaitopt.write_trajectory(poly_gait, robot, str(new), rate_hz=100) > 0
    rows_100 = len((new / "trajectory.csv").read_text().splitlines())
    assert gaitopt.write_trajectory(poly_gait, robot, str(new), rate_hz=50) > 0
    assert len((new / "trajectory.csv").read_text().splitlines()) < rows_100  # replaced
    (new / "notes.md").write_text("mine")
    with pytest.raises(gaitopt.InputError, match="holds 'notes.md', which gaitopt did not write"):
        gaitopt.write_trajectory(poly_gait, robot, str(new), rate_hz=100)
    assert (new / "notes.md").read_text() == "mine" and (new / "summary.json").exists()


def test_optimize_cost_equals_the_cli(cli, tmp_path):
    py = gaitopt.optimize(RABBIT_OCP)
    assert py["status"] == "Solve_Succeeded" and py["max_violation"] < 1e-6
    out = tmp_path / "rabbit"
    subprocess.run([cli, "optimize", "--config", RABBIT_OCP, "--out", str(out), "--quiet",
                    "--no-plots"], check=True, cwd=ROOT, capture_output=True)
    summary = json.loads((out / "summary.json").read_text())
    assert py["cost"] == pytest.approx(summary["cost"], rel=1e-9)
    assert py["iterations"] == summary["iterations"]
    traj = py["trajectory"]
    assert traj.duration == pytest.approx(summary["duration"])
    assert traj.step_length == pytest.approx(summary["step_length"])
    assert py["breaches"] == summary["between_nodes"]["breaches"] == []
    assert py["unjudged"] == [] and "unjudged" not in summary["between_nodes"]  # 1 kHz: all judged
    coarse = gaitopt.optimize(RABBIT_OCP, rate_hz=200)
    assert coarse["unjudged"] == ["max_rate_mismatch", "max_acceleration_mismatch"]


def test_optimize_lists_the_breaches_of_the_export_contract():
    # The default problem with its double support collocated in theta instead of Mu's reduced
    # coordinates: the leading tip drifts 0.59 mm between the points
    # (results/dsp_coordinates.md).
    py = gaitopt.optimize(str(ROOT / "configs/ocp/mu2004_walk.yaml"),
                          set=["constraints.dsp_reduced_coordinates=false",
                               "phases[1].first_segment=null"])
    # and, as in reduced coordinates, the swing knee turns faster than the robot file allows
    assert [b["check"] for b in py["breaches"]] == ["max_dsp_tip_drift", "max_joint_rate_use"]
    assert py["breaches"][0]["value"] > 1e-4 and py["breaches"][0]["bound"] == 1e-6


def test_walk_stays_on_the_reference(poly_gait):
    # The polynomial gait's ZMP leaves the shipped 5 cm heel (its ankle saturates and it falls):
    # the long-heel fixture of tests/apps keeps everything else and carries its ankle torque.
    robot = gaitopt.Robot(str(ROOT / "tests/apps/mu2004_five_link_long_heel.yaml"))
    w = gaitopt.simulate(robot, poly_gait, steps=3)
    assert w["steps_completed"] == 3 and not w["fell"], w["failure"]
    assert w["max_tracking_error"] < 2e-3  # as the CLI's simulate test: 1.3e-3 rad
    for s in w["steps"]:
        assert s["advance"] == pytest.approx(0.35, abs=1e-3)
    err = np.abs(w["theta"] - w["theta_ref"]).max()
    assert err == pytest.approx(w["max_tracking_error"], rel=1e-6, abs=1e-9)
    assert w["t"].shape[0] == w["theta"].shape[0] and np.all(np.diff(w["t"]) >= 0)


def test_errors_carry_the_cli_exit_codes(robot, tmp_path):
    with pytest.raises(gaitopt.InputError) as info:
        gaitopt.optimize(str(tmp_path / "missing.yaml"))
    assert info.value.exit_code == 2
    # A bad value of set= is named as Python's argument, not as the CLI's --set.
    config = str(ROOT / "configs/ocp/mu2004_walk.yaml")
    with pytest.raises(gaitopt.InputError, match=r"\(set constraints.friction_margin=-1\)") as info:
        gaitopt.optimize(config, set=["constraints.friction_margin=-1"])
    assert "--set" not in str(info.value)
    with pytest.raises(gaitopt.InputError, match=r"^set: key 'phases\[5\].segments'"):
        gaitopt.optimize(config, set=["phases[5].segments=3"])
    with pytest.raises(gaitopt.InputError, match="steps"):
        gaitopt.simulate(robot, gaitopt.design_poly(robot, str(ROOT / "configs/gaits/mu2004.yaml")),
                         steps=0)
    with pytest.raises(gaitopt.InputError):
        gaitopt.simulate(robot, gaitopt.design_poly(robot, str(ROOT / "configs/gaits/mu2004.yaml")),
                         controller="pid")
    # A step longer than the legs reach is valid input describing something impossible: exit 3.
    long_step = tmp_path / "long.yaml"
    text = (ROOT / "configs/gaits/mu2004.yaml").read_text()
    long_step.write_text(text.replace("step_length: 0.35", "step_length: 1.5"))
    assert "step_length: 1.5" in long_step.read_text()
    with pytest.raises(gaitopt.InfeasibleError) as info:
        gaitopt.design_poly(robot, str(long_step))
    assert info.value.exit_code == 3
    assert issubclass(gaitopt.NotConvergedError, gaitopt.GaitoptError)
    assert gaitopt.NotConvergedError.exit_code == 4


def test_shipped_files_are_found_by_their_configs_path_from_any_folder(tmp_path, monkeypatch):
    # As the CLI's --config, --robot and --gait: the docs' snippet runs outside the checkout.
    monkeypatch.chdir(tmp_path)
    robot = gaitopt.Robot("configs/robots/rabbit.yaml")
    assert robot.name == "rabbit"
    assert gaitopt.optimize("configs/ocp/rabbit_kelly2017.yaml", rate_hz=200)["cost"] == \
        pytest.approx(390.79, abs=0.01)
    five = gaitopt.Robot("configs/robots/mu2004_five_link.yaml")
    assert gaitopt.design_poly(five, "configs/gaits/mu2004.yaml", 100).duration == \
        pytest.approx(0.7)
    walk = gaitopt.simulate(five, gaitopt.design_poly(five, "configs/gaits/mu2004.yaml", 100),
                            steps=1, ground="configs/grounds/rigid.yaml")  # a ground file too
    assert len(walk["steps"]) == 1
    missing = "/".join(["configs", "robots", "nobody.yaml"])  # found nowhere: named as given
    with pytest.raises(gaitopt.InputError, match=missing):
        gaitopt.Robot(missing)


def test_paths_may_be_pathlib_paths(robot, poly_gait, tmp_path):
    five = gaitopt.Robot(ROOT / "configs/robots/mu2004_five_link.yaml")
    gait = gaitopt.design_poly(five, ROOT / "configs/gaits/mu2004.yaml", 100)
    assert gaitopt.write_trajectory(gait, five, tmp_path / "g", rate_hz=100) == 71
    back = gaitopt.read_trajectory(tmp_path / "g" / "trajectory.csv", five)
    np.testing.assert_array_equal(back.theta, gait.resample(100).theta)
    assert gaitopt.optimize(ROOT / "configs/ocp/rabbit_kelly2017.yaml", rate_hz=200)["cost"] == \
        pytest.approx(390.79, abs=0.01)


def test_optimize_starts_where_the_cli_starts(cli, tmp_path):
    # A straight-leg config has no polynomial gait: it starts from its straight-leg guess, as
    # the CLI does (it was refused, naming an empty file).
    config = str(ROOT / "configs/ocp/three_link_walk.yaml")
    py = gaitopt.optimize(config, rate_hz=200)
    subprocess.run([cli, "optimize", "--config", config, "--out", str(tmp_path / "t"), "--quiet",
                    "--no-plots"], check=True, cwd=ROOT, capture_output=True)
    summary = json.loads((tmp_path / "t" / "summary.json").read_text())
    assert py["cost"] == pytest.approx(summary["cost"], rel=1e-9)
    assert py["iterations"] == summary["iterations"]


def test_threads_solve_side_by_side_through_mumps():
    # Debian's MUMPS keeps state shared by its instances: two threads solving through it at once
    # crashed the interpreter (a segfault, or MUMPS's own abort).
    from concurrent.futures import ThreadPoolExecutor
    config = str(ROOT / "configs/ocp/mu2004_walk.yaml")
    solve = lambda _: gaitopt.optimize(config, rate_hz=100, set=["solver.linear_solver=mumps"])
    alone = solve(None)["cost"]
    with ThreadPoolExecutor(2) as pool:
        costs = [r["cost"] for r in pool.map(solve, range(4))]
    assert costs == [alone] * 4


def test_a_gait_is_written_and_walked_only_with_its_robot(poly_gait, tmp_path):
    # RABBIT has five links as the five-link robot has: only the name tells the gaits apart, and
    # the written summary would call the five-link gait RABBIT's.
    rabbit = gaitopt.Robot(str(ROOT / "configs/robots/rabbit.yaml"))
    with pytest.raises(gaitopt.InputError, match="a gait of robot 'mu2004_five_link', not of "
                                                 "robot 'rabbit'"):
        gaitopt.write_trajectory(poly_gait, rabbit, str(tmp_path / "g"), rate_hz=100)
    assert not (tmp_path / "g").exists()
    with pytest.raises(gaitopt.InputError, match="a gait of robot 'mu2004_five_link'"):
        gaitopt.simulate(rabbit, poly_gait, steps=1)


def test_a_walk_that_would_not_fit_in_memory_is_refused_before_it_is_walked(robot, poly_gait):
    # Every sample is kept: 100000 steps of 0.7 s on the LCP ground's 1 ms steps would take
    # about 100 GB (the walk ran until the system killed it).
    with pytest.raises(gaitopt.InputError, match="steps: 100000 steps of 0.7 s at 1000 rows per "
                                                 "second keep about 105 GB"):
        gaitopt.simulate(robot, poly_gait, steps=100000, ground="lcp")


def test_a_one_sample_gait_is_not_walked(robot, poly_gait, tmp_path):
    gaitopt.write_trajectory(poly_gait, robot, str(tmp_path / "g"), rate_hz=100)
    csv = tmp_path / "g" / "trajectory.csv"
    lines = csv.read_text().splitlines(True)
    header = [line for line in lines if line[0] in "#t"]
    csv.write_text("".join(header + [line for line in lines if line[0] not in "#t"][:1]))
    (tmp_path / "g" / "summary.json").unlink()  # which would refuse the file as truncated
    one = gaitopt.read_trajectory(str(csv), robot)
    assert len(one) == 1
    with pytest.raises(gaitopt.InputError, match="at least 2 samples"):
        gaitopt.simulate(robot, one, steps=1)
