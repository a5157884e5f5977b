"""The cell's geometry by hand: poses, URDF shape conventions, link capsules, radii, mounts."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.kinematics import matrix_from_rpy


def test_pose_is_translation_and_urdf_rpy():
    p = rc.pose([1, 2, 3], [0.1, 0.2, 0.3])
    assert np.array_equal(p[:3, :3], matrix_from_rpy(0.1, 0.2, 0.3))
    assert p[:3, 3].tolist() == [1, 2, 3] and p[3].tolist() == [0, 0, 0, 1]


def _sphere_probe(shape, point):
    """Clearance of a tiny robot link (a 1-long segment ending at ``point``) to ``shape``."""
    cell = rc.Cell()
    cell.add_robot(
        "probe",
        rc.Robot([rc.Module("Tz")], end_effector=(0, 0, 1)),
        radius=0.5,
        base=rc.pose(point),
    )
    cell.add(shape)
    return cell.clearance("probe", [0.0]).distance


def test_shapes_follow_urdf():
    # A box's size is its full edges, centred at its pose.
    box = rc.Box([4, 6, 8], pose=rc.pose([10, 0, 0]))
    assert _sphere_probe(box, [13, 0, -0.5]) == pytest.approx(1 - 0.5, abs=1e-12)
    # A cylinder's axis is its local z: turned about x, it lies along y.
    cyl = rc.Cylinder(1, 10, pose=rc.pose([0, 0, 0], [np.pi / 2, 0, 0]))
    assert _sphere_probe(cyl, [0, 4.9, 2.0]) == pytest.approx(1.0 - 0.5, abs=1e-9)  # beside it
    assert _sphere_probe(cyl, [0, 7.0, -0.5]) == pytest.approx(2.0 - 0.5, abs=1e-9)  # off its end
    ball = rc.Sphere(2, pose=rc.pose([0, 0, 5]))
    assert _sphere_probe(ball, [0, 0, -2]) == pytest.approx(6 - 2 - 0.5, abs=1e-12)  # tip at z = −1


def test_link_capsules_of_the_paper_arm_by_hand():
    cell = rc.Cell()
    cell.add_robot("arm", rc.preset("paper"), base=rc.pose([100, 0, 0], [0, 0, np.pi / 2]))
    segments, radii = cell.link_capsules("arm", [0, 0, np.pi / 2])
    # Column 20 up, upper arm 30 along the base's x (the cell's y), forearm 40 down.
    expected = [
        [[100, 0, 0], [100, 0, 20]],
        [[100, 0, 20], [100, 30, 20]],
        [[100, 30, 20], [100, 30, -20]],
    ]
    assert np.allclose(segments, expected, atol=1e-12)
    assert radii.tolist() == [3.6, 3.6, 3.6]  # 4 % of 20 + 30 + 40
    many, _ = cell.link_capsules("arm", np.zeros((5, 3)))
    assert many.shape == (5, 3, 2, 3)


def test_coinciding_points_are_merged_and_radii_overridden():
    puma = rc.preset("puma560")
    cell = rc.Cell()
    cell.add_robot("puma", puma, radius={2: 0.1, "link 3": 0.05})
    names = cell.link_names("puma")
    segments, radii = cell.link_capsules("puma", np.zeros(6))
    assert len(names) == len(radii) == segments.shape[0] < puma.n + 1
    assert np.all(np.linalg.norm(segments[:, 1] - segments[:, 0], axis=1) > 0)
    assert radii[1] == 0.1 and radii[2] == 0.05
    with pytest.raises(rc.InvalidInputError):
        cell.add_robot("bad", puma, radius=[0.1, 0.2])


def test_a_mount_lets_the_base_stand_on_the_table():
    table = rc.Box([100, 100, 10], pose=rc.pose([0, 0, -5]), name="table")
    loose, mounted = rc.Cell(), rc.Cell()
    loose.add_robot("arm", rc.preset("paper"))
    mounted.add_robot("arm", rc.preset("paper"), mount="table")
    for cell in (loose, mounted):
        cell.add(table)
    assert loose.clearance("arm", [0, 0, 0]).distance == pytest.approx(-3.6)  # the column's cap
    assert mounted.clearance("arm", [0, 0, 0]).distance == pytest.approx(20 - 3.6)  # the upper arm


def test_tool_capsules_move_with_the_flange():
    tool = rc.Tool(
        tcp=rc.pose([0, 0, 5]),
        capsules=[((0, 0, 0), (0, 0, 5), 1.0), ((0, -2, 5), (0, 2, 5), 0.5)],
        name="gripper",
    )
    cell = rc.Cell()
    cell.add_robot("arm", rc.preset("paper"), tool=tool)
    assert cell.link_names("arm")[-2:] == ("gripper 1", "gripper 2")
    segments, radii = cell.link_capsules("arm", [0, 0, 0])
    assert np.allclose(segments[-1], [[70, -2, 25], [70, 2, 25]]) and radii[-1] == 0.5
    with pytest.raises(rc.InvalidInputError) as caught:
        rc.Tool(capsules=[((0, 0, 0), (1, 0, 0), -1)])
    assert caught.value.field == "tool.capsules[0][2]"


def test_mesh_arrays_are_checked():
    with pytest.raises(rc.InvalidInputError) as caught:
        rc.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 3]])
    assert caught.value.field == "faces"
    with pytest.raises(rc.InvalidInputError) as caught:
        rc.Mesh([[0, 0, np.nan], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    assert caught.value.field == "vertices"
