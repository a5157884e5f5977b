"""``method="backward"``: the backward differences of Simulink's Derivative block.

The block outputs ``Δu/Δt = (u(t) − u(t − dt)) / dt`` and 0 at the first step (its
initial output); acceleration is a second block on that velocity. The numbers below are
derived by hand from those two rules, then checked against ``np.diff`` as an independent
computation.
"""

from __future__ import annotations

import json
import tracemalloc
from dataclasses import dataclass

import numpy as np
import pytest

import robotconf as rc
from robotconf import InvalidInputError
from robotconf import signals as sg
from robotconf.motion import (
    METHODS,
    SimulationSettings,
    backward_derivative,
    backward_second_derivative,
    simulate,
)
from robotconf.motion._memory import simulation_bytes

DT = 1e-3  # the paper's step
L3 = 40.0  # the paper robot's last link


def slider() -> rc.Robot:
    """One Tx joint with the EE at its frame origin: x_EE = q."""
    return rc.Robot([rc.Module("Tx")])


# -- the method is known everywhere ---------------------------------------------------------


def test_backward_is_a_method_of_settings_and_files():
    assert METHODS == ("analytic", "numeric", "backward")
    assert SimulationSettings(1.0, method=" Backward ").method == "backward"
    assert SimulationSettings.from_dict({"t_end": 1, "method": "BACKWARD"}).method == "backward"
    setup = rc.Setup(rc.preset("paper"), {"q3": sg.RepeatingSequence()}, {"t_end": 4.0})
    data = json.loads(setup.to_json())
    data["simulation"]["method"] = "backward"
    back = rc.load_setup(json.dumps(data))
    assert back.simulate_kwargs() == {"t_end": 4.0, "method": "backward"}
    motion = rc.simulate(back.robot, back.signals, **back.simulate_kwargs())
    assert motion.method == "backward"
    assert "method='backward'" in repr(motion)


def test_an_unknown_method_lists_backward():
    with pytest.raises(InvalidInputError, match=r"'backward' \(backward differences"):
        SimulationSettings(1.0, method="euler")


# -- hand-derived values ----------------------------------------------------------------


def test_ramp_gives_one_after_the_first_sample():
    # q = t: (q[k] − q[k−1]) / dt = dt/dt = 1 for k ≥ 1; the block starts at 0.
    motion = simulate(slider(), {"q1": sg.Ramp(slope=1.0)}, t_end=0.01, dt=DT, method="backward")
    velocity = motion.velocity[:, -1, 0]
    assert velocity[0] == 0.0
    np.testing.assert_allclose(velocity[1:], 1.0, rtol=1e-9)
    np.testing.assert_allclose(motion.qd[:, 0], velocity, rtol=1e-12, atol=0)
    # The second block sees its input step from 0 to 1 at k = 1: 1/dt = 1000, then 0.
    acceleration = motion.acceleration[:, -1, 0]
    assert acceleration[0] == 0.0
    assert acceleration[1] == pytest.approx(1.0 / DT, rel=1e-9)
    np.testing.assert_allclose(acceleration[2:], 0.0, atol=1e-6)


def test_a_parabola_lags_half_a_step():
    # x = t² at dt = 1: backward velocity 2k − 1 (the slope at k − ½), acceleration 2.
    x = np.arange(6.0) ** 2
    np.testing.assert_array_equal(backward_derivative(x, 1.0), [0, 1, 3, 5, 7, 9])
    np.testing.assert_array_equal(backward_second_derivative(x, 1.0), [0, 1, 2, 2, 2, 2])


def test_paper_sawtooth_spike_at_a_drop():
    # q3 rises at 1 rad/s and drops from 2 to 0 at t = 2 s: the sample before the drop is
    # q3(1.999) = 1.999, the one at it q3(2) = 0, so the backward q̇3 there is
    # (0 − 1.999) / 0.001 = −1999 rad/s. The central difference spreads the same jump over
    # two steps: (q3(2.001) − q3(1.999)) / 0.002 = (0.001 − 1.999) / 0.002 = −999 rad/s.
    robot = rc.preset("paper")
    saw = {"q3": sg.RepeatingSequence()}
    backward = simulate(robot, saw, t_end=4.0, dt=DT, method="backward")
    central = simulate(robot, saw, t_end=4.0, dt=DT, method="numeric")
    exact = simulate(robot, saw, t_end=4.0, dt=DT)
    k = 2000  # t = 2 s
    assert backward.t[k] == pytest.approx(2.0)
    assert backward.qd[k, 2] == pytest.approx(-1999.0, rel=1e-9)
    assert central.qd[k, 2] == pytest.approx(-999.0, rel=1e-9)
    assert central.qd[k + 1, 2] == pytest.approx(1.0, rel=1e-9)  # central: k − 1 and k only
    assert central.qd[k - 1, 2] == pytest.approx(-999.0, rel=1e-9)
    assert backward.qd[[k - 1, k + 1], 2] == pytest.approx([1.0, 1.0], rel=1e-9)  # k only
    assert backward.qd[k, 2] / central.qd[k, 2] == pytest.approx(1999 / 999)
    assert exact.qd[k, 2] == 1.0  # analytic: the right-sided slope, no spike

    # The EE's x = 30 + 40 cos q3 jumps from 30 + 40 cos 1.999 to 70: Δx/dt ≈ 56 609 mm/s.
    ee = backward.points.index("EE")
    jump = L3 * (1.0 - np.cos(1.999))
    assert backward.velocity[k, ee, 0] == pytest.approx(jump / DT, rel=1e-9)
    assert backward.velocity[k, ee, 0] == pytest.approx(56_609.5, abs=0.5)
    central_jump = L3 * (np.cos(0.001) - np.cos(1.999))
    assert central.velocity[k, ee, 0] == pytest.approx(central_jump / (2 * DT), rel=1e-9)
    assert abs(exact.velocity[:, ee]).max() <= L3 + 1e-9  # the analytic speed: l3·q̇3


def test_half_the_sawtooth_drops_one_radian():
    # q3 = 0.5·sawtooth rises to 1 rad: the sample before the drop is 0.5·1.999 = 0.9995,
    # so the backward spike is −0.9995/0.001 = −999.5 rad/s (Δq/dt, about −1000).
    robot = rc.preset("paper")
    for half in (0.5 * sg.RepeatingSequence(), sg.RepeatingSequence(values=[0, 1])):
        motion = simulate(robot, {"q3": half}, t_end=3.0, dt=DT, method="backward")
        assert motion.qd[2000, 2] == pytest.approx(-999.5, rel=1e-9)


def test_the_first_samples_are_the_blocks_initial_output_and_start_up():
    # The EE starts moving down at l3·q̇3 = 40 mm/s, but the block shows 0 first; at
    # k = 1 it shows (z(dt) − z(0))/dt = −40 sin(dt)/dt, and the second block divides
    # that step from 0 by dt: −40 sin(dt)/dt² ≈ −40 000 mm/s².
    robot = rc.preset("paper")
    motion = simulate(robot, {"q3": sg.RepeatingSequence()}, 1.0, method="backward")
    ee = motion.points.index("EE")
    np.testing.assert_array_equal(motion.velocity[0], 0.0)
    np.testing.assert_array_equal(motion.acceleration[0], 0.0)
    np.testing.assert_array_equal(motion.angular_velocity[0], 0.0)
    v1 = -L3 * np.sin(DT) / DT
    assert motion.velocity[1, ee, 2] == pytest.approx(v1, rel=1e-9)
    assert motion.acceleration[1, ee, 2] == pytest.approx(v1 / DT, rel=1e-9)


def test_the_last_sample_is_differenced_like_every_other():
    # t_end = 10 s falls on a drop. Backward: the same Δx/dt as at t = 2 s. Central: the
    # one-sided (3x[N] − 4x[N−1] + x[N−2]) / 2dt, about 3Δx/2dt, three times its own
    # inner spike, an effect of where the data end.
    robot = rc.preset("paper")
    saw = {"q3": sg.RepeatingSequence()}
    backward = simulate(robot, saw, t_end=10.0, dt=DT, method="backward")
    central = simulate(robot, saw, t_end=10.0, dt=DT, method="numeric")
    ee = backward.points.index("EE")
    vx_b, vx_c = backward.velocity[:, ee, 0], central.velocity[:, ee, 0]
    assert vx_b[-1] == pytest.approx(vx_b[2000], rel=1e-6)
    assert 2.9 < vx_c[-1] / vx_c[2000] < 3.1
    x = central.position[:, ee, 0]
    assert vx_c[-1] == pytest.approx((3 * x[-1] - 4 * x[-2] + x[-3]) / (2 * DT), rel=1e-9)


# -- agreement with an independent computation ---------------------------------------------


def test_agrees_with_np_diff_on_every_point_and_quantity():
    robot = rc.preset("paper")
    driving = {
        "q1": sg.Sine(amplitude=0.7, frequency=0.3),
        "q2": sg.Quintic(start=0.0, end=1.0, duration=1.5),
        "q3": sg.RepeatingSequence(),
    }
    dt = 0.01
    motion = simulate(robot, driving, t_end=5.0, dt=dt, method="backward")
    x = motion.position
    velocity = np.diff(x, axis=0) / dt
    np.testing.assert_allclose(motion.velocity[1:], velocity, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(
        motion.acceleration[2:], np.diff(x, n=2, axis=0) / dt**2, rtol=1e-9, atol=1e-6
    )
    np.testing.assert_allclose(motion.acceleration[1], velocity[0] / dt, rtol=1e-12)
    np.testing.assert_allclose(motion.qd[1:], np.diff(motion.q, axis=0) / dt, rtol=1e-12)
    np.testing.assert_allclose(
        motion.qdd[2:], np.diff(motion.q, n=2, axis=0) / dt**2, rtol=1e-9, atol=1e-6
    )
    assert not motion.qd[0].any() and not motion.qdd[0].any()


def test_smooth_motion_converges_at_first_order():
    # Backward differences are O(dt): ten times smaller dt, about ten times smaller error.
    robot = rc.preset("paper")
    driving = {"q1": sg.Sine(frequency=0.5), "q2": sg.Sine(amplitude=0.5, frequency=0.25)}
    errors = []
    for dt in (1e-2, 1e-3):
        exact = simulate(robot, driving, t_end=2.0, dt=dt)
        approx = simulate(robot, driving, t_end=2.0, dt=dt, method="backward")
        errors.append(np.abs(approx.velocity - exact.velocity)[1:].max())
    assert 8 < errors[0] / errors[1] < 12
    assert errors[1] < 0.5  # mm/s: about max|a|·dt/2 with accelerations near 700 mm/s²


def test_angular_velocity_of_a_steady_turn():
    # Rz at 2 rad/s: Ṙ Rᵀ from a backward Ṙ is (I − Rz(−2dt))/dt, whose z part is
    # sin(2dt)/dt (2 − O(dt²)); the first sample is the block's 0.
    dt = 0.01
    robot = rc.Robot([rc.Module("Rz")], end_effector=(1, 0, 0))
    motion = simulate(robot, {"q1": sg.Ramp(slope=2.0)}, 1.0, dt=dt, method="backward")
    omega = motion.angular_velocity[:, -1]
    np.testing.assert_array_equal(omega[0], 0.0)
    np.testing.assert_allclose(omega[1:, 2], np.sin(2 * dt) / dt, rtol=1e-9)
    np.testing.assert_allclose(omega[1:, :2], 0.0, atol=1e-12)


# -- limits -------------------------------------------------------------------------------


@dataclass(frozen=True)
class Alternating(rc.signals.Signal):
    """±level, flipping every 0.5 s (the real signals refuse levels this extreme)."""

    level: float = 1.5e308

    def _value(self, t: np.ndarray) -> np.ndarray:
        return np.where(np.mod(t, 1.0) < 0.5, -self.level, self.level)

    def _velocity(self, t: np.ndarray) -> np.ndarray:
        return np.zeros(t.shape)

    def _acceleration(self, t: np.ndarray) -> np.ndarray:
        return np.zeros(t.shape)


def test_overflowing_differences_name_the_signal():
    with pytest.raises(InvalidInputError) as caught:
        simulate(slider(), {"q1": Alternating()}, t_end=2.0, dt=0.5, method="backward")
    assert caught.value.field == "signals[q1]"
    assert "the finite-difference velocities of q1 overflow" in str(caught.value)


def test_two_samples_are_enough():
    # Unlike the central method (4 samples), the block needs no neighbours ahead.
    motion = simulate(slider(), {"q1": sg.Ramp()}, t_end=1.0, dt=1.0, method="backward")
    np.testing.assert_array_equal(motion.qd[:, 0], [0.0, 1.0])
    np.testing.assert_array_equal(motion.qdd[:, 0], [0.0, 1.0])


def test_memory_estimate_is_at_least_the_measured_peak():
    robot = rc.preset("paper")
    driving = {i: sg.Sine(frequency=1.0 + i) + sg.Ramp() for i in range(robot.n)}
    samples = 50_001
    simulate(robot, driving, t_end=0.01, method="backward")  # warm up imports and caches
    tracemalloc.start()
    try:
        start = tracemalloc.get_traced_memory()[0]
        simulate(robot, driving, t_end=(samples - 1) * 1e-3, method="backward")
        peak = tracemalloc.get_traced_memory()[1] - start
    finally:
        tracemalloc.stop()
    estimate = simulation_bytes(robot.n, samples, "backward", driving.values())
    assert peak <= estimate, f"measured {peak} > estimated {estimate:.0f}"
    assert estimate < 1.5 * peak + 8 * 1024**2
