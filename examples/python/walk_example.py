#!/usr/bin/python3
"""gaitopt from Python: a robot's dynamics, the polynomial gait, the optimal gait and a walk.

Run from the repository root after a build (make demo or make test):
    PYTHONPATH=build/python /usr/bin/python3 examples/python/walk_example.py
"""
import numpy as np

import gaitopt

robot = gaitopt.Robot("configs/robots/mu2004_five_link.yaml")
theta, dtheta = np.full(5, 0.1), np.zeros(5)
print(f"{robot.name}: {robot.n_links} links, {robot.total_mass:.2f} kg")
print("D(theta) eigenvalues:", np.linalg.eigvalsh(robot.mass_matrix(theta)).round(4))
print(f"P(theta) = {robot.potential_energy(theta):.3f} J")

poly = gaitopt.design_poly(robot, "configs/gaits/mu2004.yaml")
print(f"polynomial gait: {poly.step_length} m in {poly.duration} s, "
      f"peak |tau| {np.abs(poly.tau).max():.1f} N m")

try:
    opt = gaitopt.optimize("configs/ocp/mu2004_walk.yaml")
except gaitopt.GaitoptError as e:  # InputError (exit code 2), InfeasibleError (3), ...
    raise SystemExit(f"optimize failed (CLI exit code {e.exit_code}): {e}")
print(f"optimal gait: {opt['status']} after {opt['iterations']} iterations, "
      f"cost {opt['cost']:.2f} N^2 m^2 s")

walk = gaitopt.simulate(robot, opt["trajectory"], steps=5)
print(f"walk: {walk['steps_completed']} steps, max tracking error "
      f"{walk['max_tracking_error']:.2e} rad, advances "
      f"{[round(s['advance'], 4) for s in walk['steps']]} m")
