"""The module takes the CLI's ranges (config/quantities.hpp): a value out of range is an
InputError, a ValueError naming the argument, raised before any work; a long walk stops when a
signal handler raises."""
import signal
import subprocess
import sys
import time

import pytest

import gaitopt
from conftest import FIVE_LINK, ROOT

GAIT = str(ROOT / "configs/gaits/mu2004.yaml")
RABBIT_OCP = str(ROOT / "configs/ocp/rabbit_kelly2017.yaml")


@pytest.fixture(scope="module")
def walker():
    # The shipped five-link robot's heel is too short for the polynomial gait (it falls); the
    # long-heel fixture walks it for hundreds of steps.
    return gaitopt.Robot(str(ROOT / "tests/apps/mu2004_five_link_long_heel.yaml"))


@pytest.mark.parametrize("steps, gain_scale, message", [
    (2**31 - 1, 1.0, r"^steps: expected a number in \[1, 100000\], got 2147483647$"),
    (0, 1.0, r"^steps: expected a number in \[1, 100000\], got 0$"),
    (2, 1e308, r"^gain_scale: expected a number in \[0.001, 1000\], got 1e\+308$"),
    (2, float("nan"), r"^gain_scale: expected a number in \[0.001, 1000\], got nan$"),
])
def test_simulate_takes_the_cli_s_ranges(robot, poly_gait, steps, gain_scale, message):
    # The shipped robot falls within two steps: had a value been taken, the call would end soon.
    with pytest.raises(ValueError, match=message) as e:
        gaitopt.simulate(robot, poly_gait, steps=steps, gain_scale=gain_scale)
    assert e.value.exit_code == 2  # the CLI's bad input


@pytest.mark.parametrize("call", [
    lambda robot, gait: gaitopt.design_poly(robot, GAIT, 1e-300),
    lambda robot, gait: gait.resample(0),
    lambda robot, gait: gaitopt.optimize(RABBIT_OCP, rate_hz=2e6),
], ids=["design_poly", "resample", "optimize"])
def test_a_sample_rate_outside_the_cli_s_is_refused(robot, poly_gait, call):
    with pytest.raises(ValueError, match=r"^rate_hz: expected a number in \[1, 1e\+06\] \[Hz\]"):
        call(robot, poly_gait)


# Its grid of 1e20 * 0.7 samples overflowed `long`, and the call spun forever: it runs in a child
# process so that the old behaviour fails the test instead of hanging the suite.
WRITE_AT_1E20 = """
import sys, time, gaitopt
robot = gaitopt.Robot(sys.argv[1])
gait = gaitopt.design_poly(robot, sys.argv[2])
start = time.monotonic()
try:
    gaitopt.write_trajectory(gait, robot, sys.argv[3], rate_hz=1e20)
    outcome = "returned"
except ValueError as e:
    outcome = f"ValueError: {e}"
print(f"{time.monotonic() - start:.3f} {outcome}")
"""


def test_write_trajectory_refuses_a_rate_of_1e20_at_once(tmp_path):
    try:
        child = subprocess.run([sys.executable, "-c", WRITE_AT_1E20, FIVE_LINK, GAIT,
                                str(tmp_path)], capture_output=True, text=True, timeout=60)
    except subprocess.TimeoutExpired:
        pytest.fail("write_trajectory(rate_hz=1e20) still running after 60 s")
    seconds, outcome = child.stdout.split(" ", 1)
    assert outcome.startswith("ValueError: rate_hz: expected a number in [1, 1e+06] [Hz], got "
                              "1e+20"), child.stdout + child.stderr
    assert float(seconds) < 1
    assert not any(tmp_path.iterdir()), "nothing may be written"


class Alarm(Exception):
    pass


def test_a_long_walk_stops_when_a_signal_handler_raises(walker, poly_gait):
    # 300 steps take 10 to 30 s; Python runs the handler only when the walk asks it to.
    def ring(signum, frame):
        raise Alarm

    previous = signal.signal(signal.SIGALRM, ring)
    start = time.monotonic()
    try:
        signal.alarm(1)
        with pytest.raises(Alarm):
            gaitopt.simulate(walker, poly_gait, steps=300)
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)
    assert time.monotonic() - start < 4


THETA = [0.1, 0.2, 0.0, 3.0, 3.1]


@pytest.mark.parametrize("call, message", [
    (lambda r: r.kinetic_energy(THETA, [1e200, 0, 0, 0, 0]),
     r"^dtheta\[0\]: expected a number in \[-1000, 1000\] \[rad/s\], got 1e\+200"),
    (lambda r: r.mass_matrix([float("nan")] * 5), r"^theta: expected finite numbers"),
    (lambda r: r.potential_energy([0, 0, 0, 0, 1e308]),
     r"^theta\[4\]: expected a number in \[-12.566.*, 12.566.*\] \[rad\], got 1e\+308"),
    (lambda r: r.forward_dynamics(THETA, [0] * 5, [float("inf"), 0, 0, 0, 0]),
     r"^tau: expected finite numbers"),
], ids=["rate", "nan", "angle", "torque"])
def test_dynamics_take_the_states_inspect_takes(robot, call, message):
    # The CLI's `inspect --state` refuses these; the module returned inf or NaN energies.
    with pytest.raises(gaitopt.InputError, match=message) as e:
        call(robot)
    assert e.value.exit_code == 2
