"""URDF export, read back by an independent library (yourdfpy) and compared pose by pose."""

from __future__ import annotations

import io
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import robotconf as rc
from robotconf.io import PLACEHOLDER_EFFORT, rpy_from_matrix, to_urdf
from tests.conftest import assert_transform_close

yourdfpy = pytest.importorskip("yourdfpy")

PI = np.pi


def load_back(text: str):
    model = yourdfpy.URDF.load(io.BytesIO(text.encode("utf-8")), load_meshes=False)
    assert model.validate(), model._errors
    return model


def assert_same_kinematics(robot: rc.Robot, rng, samples: int = 20, scale: float = 1.0) -> None:
    """Every module frame and the EE pose agree with yourdfpy's forward kinematics."""
    text = to_urdf(robot, scale=scale)
    model = load_back(text)
    links = [e.get("name") for e in ET.fromstring(text).iter("link")]
    moving = [i for i, link in enumerate(robot.modules) if link.is_joint and i < robot.active]
    assert model.actuated_joint_names == [f"q{i + 1}" for i in moving]
    limits = robot.joint_limits()
    for _ in range(samples):
        q = rng.uniform(limits[:, 0], limits[:, 1])
        # Prismatic coordinates are lengths, so they scale too.
        factor = [scale if robot.joint_types[i] == "prismatic" else 1.0 for i in moving]
        model.update_cfg({f"q{i + 1}": q[i] * f for i, f in zip(moving, factor, strict=True)})
        poses = robot.frame_poses(q)
        for i, name in enumerate(robot.module_names):
            frame = name if name in links else name.replace(" ", "_")
            expected = poses[i].copy()
            expected[:3, 3] *= scale
            assert_transform_close(model.get_transform(frame, "base_link"), expected, 1e-9)
        expected = robot.end_effector_pose(q).copy()
        expected[:3, 3] *= scale
        assert_transform_close(model.get_transform("end_effector", "base_link"), expected, 1e-9)


# Standard DH of the PUMA 560 (Corke, Robotics Toolbox `mdl_puma560`), metres.
PUMA_STANDARD = [
    (0, 0, 0, PI / 2, "R"),
    (0, 0, 0.4318, 0, "R"),
    (0, 0.15005, 0.0203, -PI / 2, "R"),
    (0, 0.4318, 0, PI / 2, "R"),
    (0, 0, 0, -PI / 2, "R"),
    (0, 0, 0, 0, "R"),
]
# The same arm in Craig's modified DH (Craig, Introduction to Robotics, table 3.4).
PUMA_MODIFIED = [
    (0, 0, 0, 0, "R"),
    (0, 0, 0, -PI / 2, "R"),
    (0, 0.15005, 0.4318, 0, "R"),
    (0, 0.4318, 0.0203, -PI / 2, "R"),
    (0, 0, 0, PI / 2, "R"),
    (0, 0, 0, -PI / 2, "R"),
]
# UR5 as Universal Robots publishes it (standard DH), metres.
UR5 = [
    (0, 0.089159, 0, PI / 2, "R"),
    (0, 0, -0.425, 0, "R"),
    (0, 0, -0.39225, 0, "R"),
    (0, 0.10915, 0, PI / 2, "R"),
    (0, 0.09465, 0, -PI / 2, "R"),
    (0, 0.0823, 0, 0, "R"),
]


def test_paper_robot_round_trip(paper_robot, rng):
    assert_same_kinematics(paper_robot, rng)


def test_paper_robot_parking_position_in_urdf(paper_robot):
    model = load_back(paper_robot.to_urdf())
    model.update_cfg([0.0, 0.0, 0.0])
    np.testing.assert_allclose(model.get_transform("end_effector", "base_link")[:3, 3], [70, 0, 20])
    np.testing.assert_allclose(model.get_transform("M3", "base_link")[:3, 3], [30, 0, 20])


def test_prismatic_robot_with_none_fixed_and_named_modules(rng):
    robot = rc.Robot(
        [
            rc.Module("Tz", a=(0.1, 0.2, 0.3), name="lift", limits=(0.0, 0.5)),
            rc.Module("none"),
            rc.Module("Tx", a=(0, 0, 0.1)),
            rc.Module("fixed", a=(0.05, -0.02, 0.0), name="bracket"),
            rc.Module("Ty", a=(0, 0.1, 0)),
            rc.Module("Rx", a=(0.2, 0, 0)),
        ],
        end_effector=(0.0, 0.1, -0.05),
    )
    assert_same_kinematics(robot, rng)
    text = robot.to_urdf()
    joints = {e.get("name"): e for e in ET.fromstring(text).iter("joint")}
    assert joints["q2"].get("type") == "fixed" and joints["q4"].get("type") == "fixed"
    assert joints["q1"].find("limit").get("lower") == "0"
    assert joints["q1"].find("limit").get("upper") == "0.5"
    assert joints["q3"].find("axis").get("xyz") == "1 0 0"


def test_inactive_modules_become_fixed(paper_robot, rng):
    robot = paper_robot.with_active(1)
    assert_same_kinematics(robot, rng, samples=5)
    joints = {e.get("name"): e.get("type") for e in ET.fromstring(robot.to_urdf()).iter("joint")}
    assert joints == {"q1": "revolute", "q2": "fixed", "q3": "fixed", "end_effector_joint": "fixed"}


@pytest.mark.parametrize(
    ("rows", "convention"),
    [(PUMA_STANDARD, "standard"), (PUMA_MODIFIED, "modified"), (UR5, "standard")],
    ids=["puma560-standard", "puma560-modified", "ur5"],
)
def test_dh_robots_round_trip(rows, convention, rng):
    robot = rc.Robot.from_dh(rows, convention=convention, end_effector=(0, 0, 0.05))
    assert_same_kinematics(robot, rng)


@pytest.mark.parametrize("name", rc.preset_names())
def test_every_preset_round_trips(name, rng):
    assert_same_kinematics(rc.preset(name), rng, samples=10)


def test_dh_with_constant_theta_and_prismatic_rows(rng):
    rows = [
        {"theta": 0.3, "d": 0.2, "a": 0.1, "alpha": -0.7, "joint": "R"},
        {"theta": -1.1, "d": 0.4, "a": 0.25, "alpha": PI / 2, "joint": "P", "limits": (0, 0.3)},
        {"theta": PI / 2, "d": 0.0, "a": 0.0, "alpha": PI / 2, "joint": "R"},
    ]
    for convention in ("standard", "modified"):
        assert_same_kinematics(rc.Robot.from_dh(rows, convention=convention), rng)


def test_scale_converts_lengths_and_prismatic_limits(rng):
    robot = rc.Robot(
        [rc.Module("Rz"), rc.Module("Tz", a=(0, 0, 20), limits=(0, 100))], end_effector=(40, 0, 0)
    )
    assert_same_kinematics(robot, rng, samples=5, scale=0.001)
    limit = ET.fromstring(to_urdf(robot, scale=0.001)).find("joint[@name='q2']/limit")
    assert (limit.get("lower"), limit.get("upper")) == ("0", "0.1")


def test_limits_and_placeholders_written():
    robot = rc.Robot([rc.Module("Rz", limits=(-1.0, 2.5))])
    limit = ET.fromstring(robot.to_urdf()).find("joint/limit")
    assert limit.attrib == {
        "lower": "-1",
        "upper": "2.5",
        "effort": str(int(PLACEHOLDER_EFFORT)),
        "velocity": "1",
    }
    custom = ET.fromstring(to_urdf(robot, effort=150, velocity=3.15)).find("joint/limit")
    assert (custom.get("effort"), custom.get("velocity")) == ("150", "3.15")


def test_xml_is_well_formed_with_unique_escaped_names(rng):
    robot = rc.Robot(
        [
            rc.Module("Rz", name="my arm"),
            rc.Module("Ry", a=(0, 0, 1), name="my_arm"),  # same URDF name once sanitized
            rc.Module("Tx", name="end_effector"),
            rc.Module("Rx", name='<b>&"x"'),
            rc.Module("Ry", name="base_link"),
        ],
        end_effector=(1, 0, 0),
        name='arm <R&D> "v2"',
    )
    text = robot.to_urdf()
    root = ET.fromstring(text)
    assert root.get("name") == 'arm <R&D> "v2"'
    links = [e.get("name") for e in root.iter("link")]
    joints = [e.get("name") for e in root.iter("joint")]
    assert len(set(links)) == len(links) and len(set(joints)) == len(joints)
    assert links == [
        "base_link",
        "my_arm",
        "my_arm_2",
        "end_effector_2",
        "_b___x_",
        "base_link_2",
        "end_effector",
    ]
    for joint in root.iter("joint"):  # every parent and child is a declared link
        assert joint.find("parent").get("link") in links
        assert joint.find("child").get("link") in links
    model = load_back(text)
    model.update_cfg([0.1, 0.2, 0.3, 0.4, 0.5])
    expected = robot.end_effector_pose([0.1, 0.2, 0.3, 0.4, 0.5])
    assert_transform_close(model.get_transform("end_effector", "base_link"), expected, 1e-12)


@pytest.mark.parametrize("pitch", [PI / 2, -PI / 2, 0.4])
def test_rpy_from_matrix_rebuilds_the_rotation(pitch):
    def rot(axis, angle):
        c, s = np.cos(angle), np.sin(angle)
        i, j = (axis + 1) % 3, (axis + 2) % 3
        r = np.eye(3)
        r[i, i], r[i, j], r[j, i], r[j, j] = c, -s, s, c
        return r

    rotation = rot(2, 0.7) @ rot(1, pitch) @ rot(0, -1.2)
    roll, p, yaw = rpy_from_matrix(rotation)
    np.testing.assert_allclose(rot(2, yaw) @ rot(1, p) @ rot(0, roll), rotation, atol=1e-12)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"scale": 0}, "scale: must be positive"),
        ({"scale": -1e-3}, "scale: must be positive"),
        ({"scale": float("nan")}, "scale: must be finite"),
        ({"effort": 0}, "effort: must be positive"),
        ({"velocity": "fast"}, "velocity: text is not a number"),
        ({"name": 5}, "name: not text"),
    ],
)
def test_bad_options(paper_robot, kwargs, match):
    with pytest.raises(rc.InvalidInputError, match=match):
        to_urdf(paper_robot, **kwargs)


def test_bad_robot():
    with pytest.raises(rc.InvalidInputError, match="robot: not a robot"):
        to_urdf([rc.Module("Rz")])
