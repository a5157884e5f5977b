"""Robot.at(q): one kernel pass gives every number a picture needs, equal to the robot's own.

Each number of a snapshot is compared, bit for bit, with the robot method that computes
it alone; ``Robot.with_q``'s short path (q checked once, links otherwise kept) is compared
with building the robot from scratch.
"""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.kinematics import RobotSnapshot


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    return bool(np.array_equal(a, b, equal_nan=True))


@pytest.mark.parametrize("name", rc.preset_names())
def test_snapshot_numbers_are_the_robot_methods_numbers(name):
    robot = rc.preset(name)
    rng = np.random.default_rng(7)
    for q in rng.uniform(-3.0, 3.0, (20, robot.n)):
        at = robot.at(q)
        assert isinstance(at, RobotSnapshot)
        assert _same(at.frame_poses, robot.frame_poses(q))
        assert _same(at.frame_origins, robot.frame_origins(q))
        assert _same(at.end_effector, robot.end_effector(q))
        assert _same(at.end_effector_pose, robot.end_effector_pose(q))
        axes = rc.joint_axes(robot, q)
        assert at.joint_axes.joints == axes.joints
        assert _same(at.joint_axes.point, axes.point)
        assert _same(at.joint_axes.direction, axes.direction)
        expected = rc.robot_points(robot, q)
        assert [p.name for p in at.points] == [p.name for p in expected]
        assert all(_same(a.position, b.position) for a, b in zip(at.points, expected, strict=True))


def test_the_paper_robot_pointing_up_by_hand():
    robot = rc.preset("paper")  # l1 = 20, l2 = 30, l3 = 40
    at = robot.at([0.0, -np.pi / 2, 0.0])
    np.testing.assert_allclose(at.end_effector, [0, 0, 90], atol=1e-12)
    np.testing.assert_allclose(at.frame_origins, [[0, 0, 0], [0, 0, 20], [0, 0, 50]], atol=1e-12)
    np.testing.assert_allclose(at.joint_axes.direction[1], [0, 1, 0])
    assert str(at.points[-1]) == "EE (0.0, 0.0, 90.0)"


def test_default_q_is_the_robots_own_and_arrays_are_read_only():
    robot = rc.preset("paper").with_q([0.1, 0.2, 0.3])
    at = robot.at()
    assert _same(at.q, robot.q) and at.robot is robot
    with pytest.raises(ValueError, match="read-only"):
        at.frame_poses[0, 0, 0] = 5.0


def test_one_configuration_only():
    robot = rc.preset("paper")
    with pytest.raises(rc.InvalidInputError, match="q"):
        robot.at(np.zeros((4, 3)))
    with pytest.raises(rc.InvalidInputError, match="q"):
        robot.at([0.0, np.nan, 0.0])


def test_an_overflowing_prismatic_coordinate_is_named():
    robot = rc.Robot([rc.Module("Tx"), rc.Module("Tx", a=(1e150, 0, 0))])
    with pytest.raises(rc.InvalidInputError):
        robot.at([1.7e308, 1.7e308])


@pytest.mark.parametrize("name", rc.preset_names())
def test_with_q_equals_a_robot_built_from_scratch(name):
    robot = rc.preset(name)
    q = np.random.default_rng(3).uniform(-2.0, 2.0, robot.n)
    fast = robot.with_q(q)
    links = [link.with_q(float(v)) for link, v in zip(robot.modules, q, strict=True)]
    active = None if robot.active == robot.n else robot.active
    slow = rc.Robot(links, robot.end_effector_point, active=active, name=robot.name)
    assert fast == slow and hash(fast) == hash(slow)
    assert _same(fast.frame_poses(), slow.frame_poses())
    assert robot.with_q(robot.q) == robot


def test_with_q_still_refuses_what_a_link_refuses():
    robot = rc.preset("paper")
    with pytest.raises(rc.InvalidInputError, match=r"modules\[1\]"):
        robot.with_q([0.0, 1e200, 0.0])
    with pytest.raises(rc.InvalidInputError, match="q"):
        robot.with_q([0.0, 0.0])
