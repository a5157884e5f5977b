"""Where the scene draws each joint: on the joint's own axis, for every kind of link.

A revolute joint turns about a line and a prismatic joint slides along one; the core
(``rc.joint_axes``) gives that line. For a standard DH row it is the previous frame's z
axis, through the previous frame's origin — |a_i| away from frame i's origin, where a
marker centred on frame i would float beside the axis. Each check below measures, with
real robots (PUMA 560, UR5, the paper's R_zR_yR_y, a modified-DH arm, the Stanford arm's
prismatic boom), the distance from every marker's centre to its axis line and the angle
between the marker's direction and the axis.
"""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.scene import RobotDrawing, align_y, robot_size

Y = np.array([0.0, 1.0, 0.0])


def _modified_arm() -> rc.Robot:
    """A 3R arm in Craig's convention with offsets in a, d and a twist (no preset has one)."""
    return rc.Robot.from_dh(
        [
            (0.0, 0.3, 0.0, 0.0, "R"),
            (0.2, 0.1, 0.25, -np.pi / 2, "R"),
            (-0.4, 0.05, 0.4, 0.0, "R"),
        ],
        convention="modified",
        end_effector=(0.3, 0.0, 0.0),
    )


ROBOTS = {
    "puma560": lambda: rc.preset("puma560"),
    "ur5": lambda: rc.preset("ur5"),
    "paper": lambda: rc.preset("paper"),
    "modified": _modified_arm,
    "stanford": lambda: rc.preset("stanford"),
    "cartesian": lambda: rc.preset("cartesian"),
    "scara": lambda: rc.preset("scara"),
}


def _configurations(robot: rc.Robot) -> np.ndarray:
    rng = np.random.default_rng(7)
    lo, hi = robot.joint_limits().T
    return np.vstack([robot.q, rng.uniform(lo, hi, (4, robot.n))])


def _distance_to_line(x: np.ndarray, point: np.ndarray, direction: np.ndarray) -> float:
    offset = x - point
    return float(np.linalg.norm(offset - np.dot(offset, direction) * direction))


@pytest.mark.parametrize("name", sorted(ROBOTS))
def test_every_joint_marker_sits_on_its_axis_along_it(name: str) -> None:
    robot = ROBOTS[name]()
    drawing = RobotDrawing(robot, robot_size(robot))
    for q in _configurations(robot):
        placement = drawing.placements(q)
        axes = rc.joint_axes(robot, q)
        for i, joint in enumerate(axes.joints):
            if joint is None:
                continue
            k = drawing.paths.index(f"modules/{i}/joint")
            centre, rotation = placement.position[k], placement.rotation[k]
            point, direction = axes.point[i], axes.direction[i]
            assert _distance_to_line(centre, point, direction) < 1e-9, (name, i, q)
            # The unit shape's length runs along y: after the rotation, along the axis.
            np.testing.assert_allclose(rotation @ Y, direction, atol=1e-12)
            np.testing.assert_allclose(rotation @ rotation.T, np.eye(3), atol=1e-12)


def test_puma_shoulder_marker_is_at_the_shoulder_not_the_elbow() -> None:
    # PUMA joint 2 turns about z1 through frame 1's origin; frame 2's origin is a2 = 0.4318 m
    # along the upper arm, at the elbow.
    robot = rc.preset("puma560")
    drawing = RobotDrawing(robot, robot_size(robot))
    placement = drawing.placements(robot.q)
    poses = robot.frame_poses(robot.q)
    centre = placement.position[drawing.paths.index("modules/1/joint")]
    np.testing.assert_allclose(centre, poses[0, :3, 3], atol=1e-12)
    assert np.linalg.norm(centre - poses[1, :3, 3]) > 0.4
    np.testing.assert_allclose(
        placement.rotation[drawing.paths.index("modules/1/joint")] @ Y, poses[0, :3, 2]
    )


def test_modified_dh_marker_is_about_its_own_z_axis() -> None:
    robot = _modified_arm()
    drawing = RobotDrawing(robot, robot_size(robot))
    q = np.array([0.3, -0.7, 1.1])
    placement = drawing.placements(q)
    poses = robot.frame_poses(q)
    for i in range(robot.n):
        k = drawing.paths.index(f"modules/{i}/joint")
        z, origin = poses[i, :3, 2], poses[i, :3, 3]
        np.testing.assert_allclose(placement.rotation[k] @ Y, z, atol=1e-12)
        assert _distance_to_line(placement.position[k], origin, z) < 1e-9


def test_prismatic_box_runs_along_the_slide_from_where_it_starts() -> None:
    # Stanford's boom (row 3, standard DH) slides along z2 from frame 2's origin by q3 = d3.
    robot = rc.preset("stanford")
    drawing = RobotDrawing(robot, robot_size(robot))
    q = robot.q.copy()
    q[0], q[1], q[2] = 0.4, -0.6, 0.9
    placement = drawing.placements(q)
    k = drawing.paths.index("modules/2/joint")
    poses = robot.frame_poses(q)
    start, z = poses[1, :3, 3], poses[1, :3, 2]
    length = placement.scale[k, 1]
    centre = placement.position[k]
    np.testing.assert_allclose(placement.rotation[k] @ Y, z, atol=1e-12)
    assert _distance_to_line(centre, start, z) < 1e-9
    # The box covers the slide: from its start to the slid frame, both on the axis.
    np.testing.assert_allclose(length, 0.9, atol=1e-12)
    np.testing.assert_allclose(centre - 0.5 * length * z, start, atol=1e-12)
    np.testing.assert_allclose(centre + 0.5 * length * z, poses[2, :3, 3], atol=1e-12)


@pytest.mark.parametrize("exponent", np.arange(-12, -2, 0.5))
def test_align_y_stays_a_rotation_next_to_minus_y(exponent: float) -> None:
    angle = 10.0**exponent
    for azimuth in (0.0, 1.0, 2.5, 4.0):
        d = np.array(
            [np.sin(angle) * np.cos(azimuth), -np.cos(angle), np.sin(angle) * np.sin(azimuth)]
        )
        for sign in (1.0, -1.0):  # next to −y and next to +y
            r = align_y(sign * d)
            np.testing.assert_allclose(r @ r.T, np.eye(3), atol=1e-12, rtol=0)
            np.testing.assert_allclose(r @ Y, sign * d, atol=1e-12, rtol=0)
            assert np.linalg.det(r) == pytest.approx(1.0, abs=1e-12)


def test_align_y_exactly_minus_y_and_batches() -> None:
    r = align_y(np.array([[0.0, -1.0, 0.0], [0.0, 1.0, 0.0], [0.0, -2.0, 1e-300]]))
    np.testing.assert_allclose(r[0] @ Y, [0, -1, 0])
    np.testing.assert_allclose(r[1], np.eye(3))
    np.testing.assert_allclose(r[2] @ r[2].T, np.eye(3), atol=1e-15)
