"""robot_points / format_point: the labelled points shared by the plot, scene and report."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.kinematics import RobotPoint, format_point, robot_points


def test_paper_parking_position_points(paper_robot):
    points = robot_points(paper_robot)
    assert [p.name for p in points] == ["M1", "M2", "M3", "EE"]
    expected = [(0, 0, 0), (0, 0, 20), (30, 0, 20), (70, 0, 20)]
    for point, xyz in zip(points, expected, strict=True):
        np.testing.assert_array_equal(point.position, xyz)
    assert [str(p) for p in points] == [
        "M1 (0.0, 0.0, 0.0)",
        "M2 (0.0, 0.0, 20.0)",
        "M3 (30.0, 0.0, 20.0)",
        "EE (70.0, 0.0, 20.0)",
    ]


def test_points_follow_q_and_unpack_as_pairs(paper_robot):
    q = [np.pi / 2, 0.0, -np.pi / 2]  # base turned to +y; Ry(-90°) points the last link up
    name, xyz = robot_points(paper_robot, q)[-1]
    assert name == "EE"
    np.testing.assert_allclose(xyz, [0, 30, 60], atol=1e-12)
    assert isinstance(robot_points(paper_robot, q)[0], RobotPoint)


def test_points_use_module_names_and_robot_q():
    robot = rc.Robot(
        [rc.Module("Tz", q=2.0, name="lift"), rc.Module("Tx", a=(0, 0, 1))],
        end_effector=(1, 0, 0),
    )
    points = robot_points(robot)
    assert [p.name for p in points] == ["lift", "M2", "EE"]
    np.testing.assert_array_equal(points[-1].position, [1.0, 0.0, 3.0])


def test_format_point_digits_and_negative_zero():
    assert format_point("EE", [70, -1e-17, 20]) == "EE (70.0, 0.0, 20.0)"
    assert format_point("M1", [-0.04, 1.25, 2], digits=2) == "M1 (-0.04, 1.25, 2.00)"
    assert format_point("P", [1.6, -0.4, 0], digits=0) == "P (2, 0, 0)"


def test_robot_points_rejects_a_trajectory(paper_robot):
    with pytest.raises(rc.InvalidInputError, match="q: got a trajectory"):
        robot_points(paper_robot, np.zeros((2, 3)))


def test_robot_points_rejects_bad_q(paper_robot):
    with pytest.raises(rc.InvalidInputError, match=r"expected shape \(3,\)"):
        robot_points(paper_robot, [0, 0])


def test_robot_points_rejects_non_robot():
    with pytest.raises(rc.InvalidInputError, match="robot: not a robot"):
        robot_points("paper")


def test_format_point_rejects_bad_digits():
    with pytest.raises(rc.InvalidInputError, match="digits: out of range"):
        format_point("EE", [0, 0, 0], digits=16)
    with pytest.raises(rc.InvalidInputError, match="digits: not an integer"):
        format_point("EE", [0, 0, 0], digits=1.0)


def test_format_point_rejects_bad_name_and_vector():
    with pytest.raises(rc.InvalidInputError, match="name: not text"):
        format_point(3, [0, 0, 0])
    with pytest.raises(rc.InvalidInputError, match="xyz: entry 1 must be finite"):
        format_point("EE", [0, np.nan, 0])
