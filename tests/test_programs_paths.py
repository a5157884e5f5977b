"""LIN and CIRC moves: the end effector stays on its line or circle, at the trapezoid's speed.

The geometry is checked against the points given (not against the path objects), and
the speed against the trapezoid written out here from L, v and a.
"""

from __future__ import annotations

import numpy as np
import pytest

from robotconf.kinematics import rotation_matrix as exp_rotation
from robotconf.kinematics import rotation_vector as log_rotation
from robotconf.presets import preset
from robotconf.programs import CIRC, LIN, PTP, Program, arc_path, line_path

START_Q = [0.0, 0.3, -0.5]

# Geometry is the point here; these paths exceed the default joint accelerations.
pytestmark = pytest.mark.filterwarnings("ignore:the program has:UserWarning")


@pytest.fixture(scope="module")
def paper():
    return preset("paper")


def _trapezoid_speed(t, length, v, a):
    """Path speed of a rest-to-rest trapezoid (triangle when L < v²/a), by hand."""
    if length >= v * v / a:
        blend, duration, peak = v / a, length / v + v / a, v
    else:
        blend = np.sqrt(length / a)
        duration, peak = 2 * blend, a * blend
    speed = np.where(t < blend, a * t, peak)
    speed = np.where(t > duration - blend, a * (duration - t), speed)
    return np.clip(speed, 0, None), duration


@pytest.mark.parametrize(("speed", "accel"), [(20.0, 40.0), (20.0, 10.0)])
def test_lin_stays_on_its_segment_at_the_trapezoid_speed(paper, speed, accel):
    start = paper.end_effector(START_Q)
    goal = np.array([55.0, 12.0, 32.0])
    length = float(np.linalg.norm(goal - start))  # 19.4 mm: ≥ v²/a = 10, then < 40
    prog = Program(paper, [PTP(q=START_Q), LIN(position=goal, speed=speed, accel=accel)])
    motion = prog.simulate(dt=2e-3)
    lin = prog.segments[1]
    expected_speed, duration = _trapezoid_speed(motion.t - lin.start, length, speed, accel)
    assert lin.duration == pytest.approx(duration, rel=1e-12)
    inside = motion.t >= lin.start
    ee = motion.trace[inside]
    direction = (goal - start) / length
    along = (ee - start) @ direction
    off_line = ee - start - along[:, None] * direction
    assert np.abs(off_line).max() < 1e-9
    assert along.min() > -1e-9 and along.max() < length + 1e-9
    np.testing.assert_allclose(ee[-1], goal, atol=1e-9)
    path_speed = np.linalg.norm(motion.velocity[inside, -1], axis=1)
    np.testing.assert_allclose(path_speed, expected_speed[inside], rtol=1e-7, atol=1e-7)
    # The velocity points along the line, forwards.
    moving = path_speed > 1e-6
    np.testing.assert_allclose(
        motion.velocity[inside, -1][moving] / path_speed[moving, None],
        np.tile(direction, (int(moving.sum()), 1)),
        atol=1e-7,
    )


def test_circ_stays_on_its_circle_and_passes_through_the_via_point(paper):
    start = paper.end_effector(START_Q)
    via, end = np.array([50.0, 20.0, 30.0]), np.array([40.0, 10.0, 30.0])
    prog = Program(paper, [PTP(q=START_Q), CIRC(via=via, end=end, speed=15.0, accel=30.0)])
    motion = prog.simulate(dt=1e-3)
    # The circumcentre, computed independently: equidistant from the three points and in
    # their plane (a 3×3 linear system).
    normal = np.cross(via - start, end - start)
    system = np.array([2 * (via - start), 2 * (end - start), normal])
    rhs = [via @ via - start @ start, end @ end - start @ start, normal @ start]
    centre = np.linalg.solve(system, rhs)
    radius = np.linalg.norm(start - centre)
    circ = prog.segments[1]
    ee = motion.trace[motion.t >= circ.start]
    assert np.abs(np.linalg.norm(ee - centre, axis=1) - radius).max() < 1e-9
    assert np.abs((ee - centre) @ (normal / np.linalg.norm(normal))).max() < 1e-9
    np.testing.assert_allclose(ee[-1], end, atol=1e-9)
    # The via point lies on the path (exactly, at its angle) and the samples pass it
    # within one step of travel; the speed along the arc is again the trapezoid's.
    gaps = np.linalg.norm(ee - via, axis=1)
    assert gaps.min() <= 15.0 * 1e-3
    path = circ.path
    e1 = (start - centre) / radius
    e2 = np.cross(normal / np.linalg.norm(normal), e1)
    angle_via = np.mod(np.arctan2((via - centre) @ e2, (via - centre) @ e1), 2 * np.pi)
    angle_end = np.mod(np.arctan2((end - centre) @ e2, (end - centre) @ e1), 2 * np.pi)
    assert 0 < angle_via < angle_end  # the arc goes through the via point, not around it
    np.testing.assert_allclose(
        path.positions(np.array([angle_via / angle_end]))[0], via, atol=1e-12
    )
    length = radius * angle_end
    expected_speed, duration = _trapezoid_speed(motion.t - circ.start, length, 15.0, 30.0)
    assert circ.duration == pytest.approx(duration, rel=1e-12)
    inside = motion.t >= circ.start
    speeds = np.linalg.norm(motion.velocity[inside, -1], axis=1)
    np.testing.assert_allclose(speeds, expected_speed[inside], rtol=1e-7, atol=1e-7)


def test_arc_geometry_of_a_quarter_circle():
    arc = arc_path(
        np.array([1.0, 0, 0]),
        np.array([np.sqrt(0.5), np.sqrt(0.5), 0]),
        np.array([0, 1.0, 0]),
        np.eye(3),
        np.eye(3),
    )
    assert arc is not None
    np.testing.assert_allclose(arc.centre, 0, atol=1e-15)
    assert arc.radius == pytest.approx(1.0) and arc.sweep == pytest.approx(np.pi / 2)
    assert arc.length == pytest.approx(np.pi / 2)
    # Clockwise order (via past the end) gives the long way round: 3/4 of the circle.
    long_way = arc_path(
        np.array([1.0, 0, 0]), np.array([-1.0, 0, 0]), np.array([0, 1.0, 0]), np.eye(3), np.eye(3)
    )
    assert long_way is not None and long_way.sweep == pytest.approx(1.5 * np.pi)
    line = np.array([[0.0, 0, 0], [1.0, 1, 1], [2.0, 2, 2]])
    assert arc_path(*line, np.eye(3), np.eye(3)) is None


def test_pose_lin_slerps_the_orientation_about_a_fixed_axis():
    puma = preset("puma560")
    q0 = np.array([0.2, 0.7, -2.6, 0.1, 0.8, 0.3])
    start = puma.end_effector_pose(q0)
    goal = start.copy()
    turn = np.array([0.0, 0.3, 0.2])  # 0.36 rad about a fixed base axis
    goal[:3, :3] = exp_rotation(turn) @ start[:3, :3]
    goal[:3, 3] += [-0.05, 0.03, 0.02]
    prog = Program(puma, [PTP(q=q0), LIN(pose=goal)])
    assert prog.mode == "pose"
    motion = prog.simulate(dt=5e-3)
    lin = prog.segments[1]
    inside = motion.t >= lin.start
    poses = puma.end_effector_pose(motion.q[inside])
    # u along the line from the positions; the orientation must be exp(u·w)·R0.
    chord = goal[:3, 3] - start[:3, 3]
    u = (poses[:, :3, 3] - start[:3, 3]) @ chord / (chord @ chord)
    expected = exp_rotation(u[:, None] * turn) @ start[:3, :3]
    assert np.abs(poses[:, :3, :3] - expected).max() < 1e-9
    np.testing.assert_allclose(poses[-1], goal, atol=1e-9)
    # Angular velocity ∥ w throughout, with |ω| = θ·u̇ = θ·|v|/L.
    omega = motion.angular_velocity[inside, -1]
    speed = np.linalg.norm(motion.velocity[inside, -1], axis=1)
    np.testing.assert_allclose(omega, speed[:, None] / np.linalg.norm(chord) * turn, atol=1e-8)


def test_held_orientation_stays_put():
    puma = preset("puma560")
    q0 = np.array([0.2, 0.7, -2.6, 0.1, 0.8, 0.3])
    start = puma.end_effector_pose(q0)
    goal = start.copy()
    goal[:3, 3] += [-0.05, 0.0, 0.05]
    goal[:3, :3] = exp_rotation(np.array([0.4, 0, 0])) @ start[:3, :3]
    prog = Program(puma, [PTP(q=q0), LIN(pose=goal, orientation="hold")])
    motion = prog.simulate(dt=1e-2)
    poses = puma.end_effector_pose(motion.q[motion.t >= prog.segments[1].start])
    assert np.abs(poses[:, :3, :3] - start[:3, :3]).max() < 1e-9
    np.testing.assert_allclose(poses[-1, :3, 3], goal[:3, 3], atol=1e-9)


def test_rotation_log_and_exp_are_inverse_also_near_a_half_turn():
    rng = np.random.default_rng(3)
    axes = rng.normal(size=(200, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    angles = np.concatenate([rng.uniform(0, np.pi, 190), np.pi - np.logspace(-12, -2, 10)])
    vectors = axes * angles[:, None]
    back = log_rotation(exp_rotation(vectors))
    np.testing.assert_allclose(back, vectors, atol=1e-9)
    assert np.abs(log_rotation(np.eye(3))).max() == 0.0


def test_line_path_of_zero_length_turns_only():
    path = line_path(np.ones(3), np.ones(3), np.eye(3), exp_rotation(np.array([0, 0, 1.0])))
    assert path.length == 0.0 and path.angle == pytest.approx(1.0)
