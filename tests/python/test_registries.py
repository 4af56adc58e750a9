"""One list of names per registry (sim/controllers/controller_registry.cpp,
sim/walk/ground_registry.cpp): `gaitopt simulate --help` and `gaitopt stability --help` list
exactly the controllers and grounds the Python module does, with the same descriptions; the
module refuses an unknown name listing the registered ones, and its ground argument selects the
ground's own walk."""
import re
import subprocess

import pytest

import gaitopt
from conftest import ROOT

LONG_HEEL = str(ROOT / "tests/apps/mu2004_five_link_long_heel.yaml")


def help_text(cli, command):
    return subprocess.run([cli, command, "--help"], check=True, capture_output=True,
                          text=True).stdout


def listed(text, option):
    """name -> description of the "  NAME: description" lines under `option` in a --help text,
    up to the next option."""
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.lstrip().startswith(option + " "))
    entries = {}
    for line in lines[start + 1:]:
        if line.lstrip().startswith("-"):
            break
        m = re.fullmatch(r"\s+([a-z0-9_]+): (.+)", line)
        if m:
            entries[m.group(1)] = m.group(2)
    return entries


@pytest.mark.parametrize("command", ["simulate", "stability"])
def test_the_cli_help_lists_exactly_the_registered_names(cli, command):
    text = help_text(cli, command)
    assert listed(text, "--controller") == gaitopt.controllers()
    assert listed(text, "--ground") == gaitopt.grounds()
    # The set --controller checks its value against (CLI11's IsMember), in registration order.
    accepted = re.search(r"--controller TEXT:\{([^}]*)\}", text)
    assert accepted, text
    assert accepted.group(1).split(",") == list(gaitopt.controllers())


def test_the_registries_hold_the_shipped_controllers_and_grounds():
    # The shipped ones at least (the comparisons above would pass on empty registries); a new
    # entry adds to them.
    shipped_controllers = {"computed_torque", "computed_torque_plan_dsp", "sliding_mode",
                           "mu_sliding_mode", "mu_sliding_mode_plan_dsp", "hzd"}
    assert shipped_controllers <= set(gaitopt.controllers())
    assert {"rigid", "impedance", "lcp", "dart"} <= set(gaitopt.grounds())
    shipped = {p.stem for p in (ROOT / "configs/grounds").glob("*.yaml")}
    assert shipped == set(gaitopt.grounds())


def test_unknown_names_are_refused_listing_the_registered_ones(robot, poly_gait):
    with pytest.raises(gaitopt.InputError) as info:
        gaitopt.simulate(robot, poly_gait, steps=1, controller="pid")
    assert "unknown controller 'pid'" in str(info.value)
    assert all(name in str(info.value) for name in gaitopt.controllers()), info.value
    with pytest.raises(gaitopt.InputError) as info:
        gaitopt.simulate(robot, poly_gait, steps=1, ground="ice")
    assert all(name in str(info.value) for name in gaitopt.grounds()), info.value


def test_the_ground_argument_walks_that_grounds_model(poly_gait):
    # One step on the time-stepping LCP ground: its own impact ("lcp", not the rigid walk's
    # "double"), and the step still advances the planned 0.35 m within a few mm (the CLI's
    # simulate test: the LCP walk stays within a few mm of the rigid one).
    robot = gaitopt.Robot(LONG_HEEL)
    rigid = gaitopt.simulate(robot, poly_gait, steps=1)
    lcp = gaitopt.simulate(robot, poly_gait, steps=1, ground="lcp")
    assert rigid["steps"][0]["impact"] == "double"
    assert lcp["steps_completed"] == 1 and lcp["steps"][0]["impact"] == "lcp", lcp["failure"]
    assert lcp["steps"][0]["advance"] == pytest.approx(rigid["steps"][0]["advance"], abs=5e-3)
