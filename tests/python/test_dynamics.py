"""Robot and dynamics from Python: D symmetric positive definite, the energy identities of the
Lagrangian form (Mu 2.35 to 2.38), forward and inverse dynamics inverse to each other."""
from xml.etree import ElementTree

import numpy as np
import pytest

import gaitopt

RNG = np.random.default_rng(17)


def random_state(n):
    return RNG.uniform(-0.6, 0.6, n), RNG.uniform(-2, 2, n)


def test_robot_parameters(robot):
    # Mu (2004) Table 2.1: five links, 29.81 kg in all.
    assert robot.n_links == 5
    assert robot.total_mass == pytest.approx(29.81)
    assert len(robot.link_names) == 5 and robot.link_lengths.shape == (5,)


def test_mass_matrix_symmetric_positive_definite(robot):
    for _ in range(20):
        theta, _ = random_state(robot.n_links)
        d = robot.mass_matrix(theta)
        assert d.shape == (5, 5)
        np.testing.assert_allclose(d, d.T, atol=1e-12)
        assert np.linalg.eigvalsh(d).min() > 0


def test_kinetic_energy_is_the_mass_matrix_quadratic_form(robot):
    # K = 1/2 dtheta^T D(theta) dtheta (Mu 2.4 and 2.36 with the stance tip pinned).
    for _ in range(20):
        theta, dtheta = random_state(robot.n_links)
        k = robot.kinetic_energy(theta, dtheta)
        assert k == pytest.approx(0.5 * dtheta @ robot.mass_matrix(theta) @ dtheta, rel=1e-12)


def test_gravity_vector_is_the_potential_energy_gradient(robot):
    # G = dP/dtheta (Mu 2.38), checked by central differences.
    theta, _ = random_state(robot.n_links)
    h = 1e-6
    grad = [(robot.potential_energy(theta + h * e) - robot.potential_energy(theta - h * e)) /
            (2 * h) for e in np.eye(robot.n_links)]
    np.testing.assert_allclose(robot.gravity_vector(theta), grad, atol=1e-6)


def test_unforced_motion_conserves_energy(robot):
    # With tau = 0 the stance-pinned chain conserves K + P: dE/dt = dtheta^T (D ddtheta + H + G)
    # minus the torques' power = 0. A short RK4 run keeps E to integration error.
    theta, dtheta = random_state(robot.n_links)
    zero = np.zeros(robot.n_links)

    def f(x):
        return np.concatenate([x[5:], robot.forward_dynamics(x[:5], x[5:], zero)])

    def energy(x):
        return robot.kinetic_energy(x[:5], x[5:]) + robot.potential_energy(x[:5])

    x, dt = np.concatenate([theta, dtheta]), 1e-4
    e0 = energy(x)
    for _ in range(1000):
        k1 = f(x)
        k2 = f(x + dt / 2 * k1)
        k3 = f(x + dt / 2 * k2)
        k4 = f(x + dt * k3)
        x = x + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    assert energy(x) == pytest.approx(e0, abs=1e-6 * max(1.0, abs(e0)))


def test_inverse_dynamics_inverts_forward_dynamics(robot):
    theta, dtheta = random_state(robot.n_links)
    tau = RNG.uniform(-20, 20, robot.n_links)
    ddtheta = robot.forward_dynamics(theta, dtheta, tau)
    np.testing.assert_allclose(robot.inverse_dynamics(theta, dtheta, ddtheta), tau, atol=1e-9)


def test_wrong_sizes_and_bad_files_are_input_errors(robot, tmp_path):
    with pytest.raises(gaitopt.InputError, match="theta: expected 5 values"):
        robot.mass_matrix(np.zeros(3))
    bad = tmp_path / "robot.yaml"
    bad.write_text("name: x\nlinks: nope\n")
    with pytest.raises(ValueError) as info:  # InputError is a ValueError
        gaitopt.Robot(str(bad))
    assert info.value.exit_code == 2 and str(bad) in str(info.value)
    with pytest.raises(gaitopt.InputError):
        gaitopt.Robot(str(tmp_path / "missing.yaml"))


def test_urdf_holds_the_links_with_their_masses_and_the_joints(robot):
    # The URDF of export-urdf: every link with its mass, two feet of 0.05 kg, and a revolute
    # joint per link (the stance ankle, the n - 1 chain joints, the swing ankle).
    root = ElementTree.fromstring(robot.urdf())
    masses = {link.get("name"): float(link.find("inertial/mass").get("value"))
              for link in root.iter("link")}
    assert sum(masses.values()) == pytest.approx(robot.total_mass + 2 * 0.05, abs=1e-12)
    assert set(robot.link_names) <= set(masses) and len(masses) == robot.n_links + 2
    assert len(list(root.iter("joint"))) == robot.n_links + 1
