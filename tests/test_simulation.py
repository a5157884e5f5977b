"""simulate(): exact DVA against closed forms and the Jacobian, numeric convergence, errors."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.kinematics import jacobian
from robotconf.motion import QUANTITIES, Motion, simulate
from robotconf.signals import Constant, Cubic, Quintic, RepeatingSequence, Sine


def paper_robot() -> rc.Robot:
    return rc.Robot(
        [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
        end_effector=(40, 0, 0),
    )


def mixed_robot() -> rc.Robot:
    return rc.Robot(
        [
            rc.Module("Rz", a=(0.1, 0.2, 0.5)),
            rc.Module("Tx", a=(0.3, 0, 0)),
            rc.Module("Ry", a=(0, 0.4, 0.2)),
            rc.Module("fixed", a=(0.1, -0.2, 0.3)),
            rc.DHLink(theta=0.3, d=0.2, a=0.5, alpha=0.7, joint="R"),
            rc.DHLink(theta=0.1, d=0.1, a=0.2, alpha=-0.4, joint="P", convention="modified"),
            rc.Module("Rx", a=(0.2, 0.1, 0)),
        ],
        end_effector=(0.3, -0.1, 0.2),
    )


def all_sines(robot: rc.Robot) -> dict[str, Sine]:
    return {
        name: Sine(amplitude=0.4 + 0.1 * i, bias=0.1 * i, frequency=0.3 + 0.13 * i, phase=i)
        for i, name in enumerate(robot.coordinate_names)
    }


def test_paper_sawtooth_matches_closed_forms() -> None:
    motion = simulate(paper_robot(), {"q3": RepeatingSequence()}, t_end=10.0, dt=1e-3)
    t = motion.t
    assert t.shape == (10001,) and t[-1] == pytest.approx(10.0)
    q3 = np.mod(t, 2.0)
    np.testing.assert_allclose(motion.q[:, 2], q3, atol=1e-12)
    ee = motion.points.index("EE")
    pos, vel, acc = motion.position[:, ee], motion.velocity[:, ee], motion.acceleration[:, ee]
    np.testing.assert_allclose(pos[:, 0], 30 + 40 * np.cos(q3), atol=1e-11)
    np.testing.assert_allclose(pos[:, 1], 0.0, atol=1e-12)
    np.testing.assert_allclose(pos[:, 2], 20 - 40 * np.sin(q3), atol=1e-11)
    # q̇3 = 1, q̈3 = 0 away from (and, right-sided, also at) the kinks.
    np.testing.assert_allclose(vel[:, 0], -40 * np.sin(q3), atol=1e-11)
    np.testing.assert_allclose(vel[:, 2], -40 * np.cos(q3), atol=1e-11)
    np.testing.assert_allclose(acc[:, 0], -40 * np.cos(q3), atol=1e-11)
    np.testing.assert_allclose(acc[:, 2], 40 * np.sin(q3), atol=1e-11)
    np.testing.assert_allclose(vel[:, 1], 0.0, atol=1e-12)
    np.testing.assert_allclose(motion.angular_velocity[:, ee], [[0, 1, 0]] * t.size, atol=1e-15)
    # Frames M1, M2 stand still; M3's origin is fixed at (30, 0, 20).
    assert np.all(motion.velocity[:, :3] == 0.0) and np.all(motion.acceleration[:, :3] == 0.0)
    np.testing.assert_allclose(motion.position[:, 2], [[30, 0, 20]] * t.size)
    np.testing.assert_allclose(motion.displacement[:, ee], pos - pos[0])


@pytest.mark.parametrize("frame", range(8))
def test_analytic_velocity_equals_jacobian_times_qdot(frame: int) -> None:
    robot = mixed_robot()
    motion = simulate(robot, all_sines(robot), t_end=3.0, dt=0.01)
    j = jacobian(robot, motion.q, frame=None if frame == robot.n else frame)
    twist = np.einsum("tkn,tn->tk", j, motion.qd)
    np.testing.assert_allclose(motion.velocity[:, frame], twist[:, :3], rtol=0, atol=1e-12)
    np.testing.assert_allclose(motion.angular_velocity[:, frame], twist[:, 3:], atol=1e-12)
    assert np.abs(twist).max() > 0.1  # the check is not vacuous


def test_analytic_acceleration_is_the_derivative_of_analytic_velocity() -> None:
    robot = mixed_robot()
    dt = 1e-4
    motion = simulate(robot, all_sines(robot), t_end=2.0, dt=dt)
    slope = np.gradient(motion.velocity, dt, axis=0)[2:-2]  # O(dt²) ≈ 1e-8 · |v'''|
    np.testing.assert_allclose(motion.acceleration[2:-2], slope, rtol=0, atol=5e-5)
    assert np.abs(motion.acceleration).max() > 0.5


@pytest.mark.parametrize("quantity", ["velocity", "acceleration", "angular_velocity"])
def test_numeric_converges_at_second_order(quantity: str) -> None:
    robot = mixed_robot()
    signals = all_sines(robot)
    errors, scale = [], 0.0
    for dt in (4e-3, 2e-3, 1e-3):
        exact = simulate(robot, signals, t_end=2.0, dt=dt)
        approx = simulate(robot, signals, t_end=2.0, dt=dt, method="numeric")
        errors.append(np.abs(approx.quantity(quantity) - exact.quantity(quantity)).max())
        scale = np.abs(exact.quantity(quantity)).max()
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    assert errors[-1] < 1e-3 * scale
    np.testing.assert_allclose(ratios, 4.0, rtol=0.05)  # halving dt quarters the error


def test_numeric_coordinate_derivatives_and_table_shape_match_analytic() -> None:
    robot = paper_robot()
    kwargs = {"signals": {"q2": Quintic(end=1.0, duration=2.0)}, "t_end": 2.0, "dt": 1e-3}
    exact = simulate(robot, **kwargs)
    approx = simulate(robot, **kwargs, method="numeric")
    assert approx.method == "numeric" and exact.method == "analytic"
    np.testing.assert_allclose(approx.qd, exact.qd, atol=1e-5)
    np.testing.assert_allclose(approx.qdd, exact.qdd, atol=1e-3)
    np.testing.assert_array_equal(approx.position, exact.position)


def test_numeric_shows_spikes_at_sawtooth_kinks() -> None:
    dt = 1e-3
    motion = simulate(
        paper_robot(), {"q3": RepeatingSequence()}, t_end=5.0, dt=dt, method="numeric"
    )
    ee_vz = motion.velocity[:, -1, 2]
    spike = np.argmax(np.abs(ee_vz[100:-100])) + 100
    assert motion.t[spike] == pytest.approx(2.0, abs=1.5 * dt)
    assert abs(ee_vz[spike]) > 100 * 40  # far beyond the smooth |v| ≤ 40
    np.testing.assert_array_equal(motion.kinks()["q3"], [0.0, 2.0, 4.0])


def test_unsignalled_coordinates_hold_the_modules_q_and_keys_may_be_indices() -> None:
    robot = paper_robot().with_q([0.3, -0.2, 0.5])
    motion = simulate(robot, {2: Sine(), "Q1": 0.7}, t_end=1.0, dt=0.1, t0=0.5)
    np.testing.assert_allclose(motion.t, 0.5 + 0.1 * np.arange(6))
    np.testing.assert_array_equal(motion.q[:, 1], -0.2)
    np.testing.assert_array_equal(motion.q[:, 0], 0.7)
    np.testing.assert_allclose(motion.q[:, 2], Sine().value(motion.t))
    assert motion.signals == {"q3": Sine(), "q1": Constant(0.7)}
    np.testing.assert_allclose(motion.position[:, :3], robot.frame_origins(motion.q))
    np.testing.assert_allclose(motion.position[:, 3], robot.end_effector(motion.q))
    assert np.all(motion.displacement[0] == 0.0)
    still = simulate(robot, None, t_end=1.0, dt=0.5)
    assert np.all(still.velocity == 0) and np.all(still.q == robot.q)


def test_motion_is_read_only_and_describes_itself() -> None:
    motion = simulate(paper_robot(), {"q1": Cubic()}, t_end=1.0, dt=0.25)
    assert isinstance(motion, Motion)
    assert motion.points == ("M1", "M2", "M3", "EE")
    assert motion.dt == pytest.approx(0.25)
    assert "5 samples" in repr(motion) and "Cubic(" in repr(motion)
    with pytest.raises(ValueError, match="read-only"):
        motion.position[0, 0, 0] = 1.0
    with pytest.raises(ValueError, match="read-only"):
        motion.q[0, 0] = 1.0
    assert motion.columns().shape == (4 * len(QUANTITIES) * 3, 5)
    with pytest.raises(ValueError, match="quantity: invalid value 'speed'"):
        motion.quantity("speed")


def test_time_grid_includes_t_end_despite_rounding() -> None:
    motion = simulate(paper_robot(), {}, t_end=0.3, dt=0.1)
    assert motion.t.size == 4
    motion = simulate(paper_robot(), {}, t_end=1.0, dt=0.3)
    np.testing.assert_allclose(motion.t, [0, 0.3, 0.6, 0.9])


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"dt": 0.0}, r"dt: must be positive, got 0.0; allowed: a time step > 0"),
        ({"dt": -1e-3}, r"dt: must be positive, got -0.001"),
        ({"dt": np.nan}, r"dt: must be finite"),
        ({"t_end": 0.0}, r"t_end: must be later than t0, got 0.0; allowed: a time after t0"),
        ({"t_end": 1.0, "t0": 2.0}, r"t_end: must be later than t0"),
        ({"t0": "0"}, r"t0: text is not a number"),
        (
            {"signals": {"q7": Sine()}},
            r"signals: unknown module 'q7'; allowed: an index 0 to 2, .*name \(q1 to q3\)",
        ),
        ({"signals": {"q0": Sine()}}, r"signals: unknown module 'q0'"),
        ({"signals": {3: Sine()}}, r"signals: out of range: 3; allowed: an index 0 to 2"),
        ({"signals": {True: Sine()}}, r"signals: not an integer: True"),
        ({"signals": {"q1": Sine(), 0: Sine()}}, r"q1 is given twice"),
        ({"signals": [Sine()]}, r"signals: not a dict"),
        ({"signals": {"q1": "sine"}}, r"signals\['q1'\]: invalid value 'sine'"),
        ({"signals": {"q1": np.nan}}, r"signals\['q1'\]: invalid value nan"),
        ({"method": "euler"}, r"method: unknown method 'euler'; allowed: 'analytic'"),
        (
            {"t_end": 1e6, "dt": 1e-4},
            r"dt: too many samples at 0.0001; allowed: at most 10,000,000 time samples",
        ),
        ({"max_sample_points": 100}, r"too many at 0.001; allowed: at most 100 samples × points"),
        ({"method": "numeric", "t_end": 0.2, "dt": 0.1}, r"t_end: too few samples .*: 3"),
    ],
)
def test_bad_input(kwargs, match) -> None:  # type: ignore[no-untyped-def]
    arguments = {"signals": {"q3": RepeatingSequence()}, "t_end": 10.0, **kwargs}
    with pytest.raises(ValueError, match=match):
        simulate(paper_robot(), **arguments)
