"""Presets: every robot checked at a known pose with hand-derived or published numbers."""

import numpy as np
import pytest

import robotconf as rc
from robotconf import InvalidInputError
from robotconf.presets import PRESETS

from .conftest import reference_dh

PI = np.pi
DEG = PI / 180


def test_names_and_registry():
    assert rc.preset_names() == (
        "paper",
        "cartesian",
        "cylindrical",
        "spherical",
        "scara",
        "articulated",
        "planar_2r",
        "planar_3r",
        "stanford",
        "puma560",
        "ur5",
    )


@pytest.mark.parametrize("name", list(PRESETS))
def test_every_preset_is_named_cited_and_has_valid_ranges(name):
    robot = rc.preset(name)
    assert robot.name
    doc = PRESETS[name].__doc__ + __import__(PRESETS[name].__module__, fromlist=["_"]).__doc__
    sources = ("Spong", "Siciliano", "Corke", "Grosz", "Universal Robots")
    assert any(source in doc for source in sources)
    limits = robot.joint_limits()
    assert limits.shape == (robot.n, 2)
    assert np.all(limits[:, 0] < limits[:, 1])  # every preset link is a joint
    assert all(link.limits is not None for link in robot.modules)  # explicit, not defaults


def test_paper_reproduces_the_validation_case():
    robot = rc.preset("paper")
    np.testing.assert_array_equal(
        robot.frame_origins([0, 0, 0]), [[0, 0, 0], [0, 0, 20], [30, 0, 20]]
    )
    np.testing.assert_array_equal(robot.end_effector([0, 0, 0]), [70, 0, 20])
    # q2 = π/2 turns the arm about y: x → −z, so the 70-long arm points down from z = 20.
    np.testing.assert_allclose(robot.end_effector([0, PI / 2, 0]), [0, 0, -50], atol=1e-12)


def test_cartesian():
    np.testing.assert_array_equal(rc.preset("cartesian").end_effector([10, 20, 5]), [10, 20, 5])
    np.testing.assert_array_equal(rc.preset("cartesian").joint_limits()[0], [0, 50])


def test_cylindrical_matches_its_closed_form(rng):
    robot = rc.preset("cylindrical")  # h = 20, tool = 10
    q = rng.uniform(-2, 2, size=(50, 3))
    r = q[:, 2] + 10
    expected = np.stack([r * np.cos(q[:, 0]), r * np.sin(q[:, 0]), 20 + q[:, 1]], axis=1)
    np.testing.assert_allclose(robot.end_effector(q), expected, atol=1e-12)
    np.testing.assert_allclose(robot.end_effector([PI / 2, 15, 20]), [0, 30, 35], atol=1e-12)


def test_spherical_matches_its_closed_form(rng):
    robot = rc.preset("spherical")  # h = 20, tool = 10
    q = rng.uniform(-2, 2, size=(50, 3))
    r = q[:, 2] + 10
    expected = np.stack(
        [
            r * np.cos(q[:, 1]) * np.cos(q[:, 0]),
            r * np.cos(q[:, 1]) * np.sin(q[:, 0]),
            20 - r * np.sin(q[:, 1]),
        ],
        axis=1,
    )
    np.testing.assert_allclose(robot.end_effector(q), expected, atol=1e-12)


def test_scara_known_pose():
    # Arm along y then back along x: (30, 40); height h − q3 − d4 = 40 − 5 − 10 = 25.
    robot = rc.preset("scara")
    np.testing.assert_allclose(
        robot.end_effector([PI / 2, -PI / 2, 5, 0]), [30, 40, 25], atol=1e-12
    )
    np.testing.assert_allclose(robot.joint_limits()[0], [-130 * DEG, 130 * DEG])


def test_articulated_known_pose():
    robot = rc.preset("articulated")
    np.testing.assert_allclose(robot.end_effector([0, PI / 2, -PI / 2]), [40, 0, 50], atol=1e-12)
    np.testing.assert_allclose(robot.end_effector([PI / 2, 0, 0]), [0, 70, 20], atol=1e-12)


def test_planar_arms_match_their_closed_forms(rng):
    q = rng.uniform(-PI, PI, size=(50, 3))
    two = rc.preset("planar_2r", l1=2.0, l2=1.5).end_effector(q[:, :2])
    c1, s1 = np.cos(q[:, 0]), np.sin(q[:, 0])
    c12, s12 = np.cos(q[:, 0] + q[:, 1]), np.sin(q[:, 0] + q[:, 1])
    np.testing.assert_allclose(two[:, 0], 2 * c1 + 1.5 * c12, atol=1e-12)
    np.testing.assert_allclose(two[:, 1], 2 * s1 + 1.5 * s12, atol=1e-12)
    np.testing.assert_allclose(
        rc.preset("planar_3r").end_effector([PI / 2, -PI / 2, -PI / 2]), [30, 20, 0], atol=1e-12
    )


def _spong_stanford(q, d1=0.412, d2=0.154, d6=0.263):
    """Spong, Hutchinson & Vidyasagar (2006) Example 3.5: position part of T_6^0 (+ d1)."""
    t1, t2, d3, t4, t5, _ = q
    c1, s1, c2, s2 = np.cos(t1), np.sin(t1), np.cos(t2), np.sin(t2)
    c4, s4, c5, s5 = np.cos(t4), np.sin(t4), np.cos(t5), np.sin(t5)
    return np.array(
        [
            c1 * s2 * d3 - s1 * d2 + d6 * (c1 * c2 * c4 * s5 + c1 * c5 * s2 - s1 * s4 * s5),
            s1 * s2 * d3 + c1 * d2 + d6 * (c1 * s4 * s5 + c2 * c4 * s1 * s5 + c5 * s1 * s2),
            d1 + c2 * d3 + d6 * (c2 * c5 - c4 * s2 * s5),
        ]
    )


def test_stanford_matches_spongs_closed_form(rng):
    robot = rc.preset("stanford")
    for q in rng.uniform(-2, 2, size=(20, 6)):
        np.testing.assert_allclose(robot.end_effector(q), _spong_stanford(q), atol=1e-12)
    np.testing.assert_allclose(
        robot.end_effector([0, PI / 2, 0.5, 0, 0, 0]), [0.763, 0.154, 0.412], atol=1e-12
    )
    np.testing.assert_allclose(robot.joint_limits()[2], [0.3048, 1.27], atol=1e-12)


def _compose(rows, q):
    pose = np.eye(4)
    for (d, a, alpha), qi in zip(rows, q, strict=True):
        pose = pose @ reference_dh(qi, d, a, alpha, "standard")
    return pose


PUMA = [
    (0, 0, PI / 2),
    (0, 0.4318, 0),
    (0.15005, 0.0203, -PI / 2),
    (0.4318, 0, PI / 2),
    (0, 0, -PI / 2),
    (0, 0, 0),
]


def test_puma560_textbook_poses(rng):
    robot = rc.preset("puma560")
    # Corke, Robotics, Vision and Control: fkine(qz) and fkine(qr) translations.
    np.testing.assert_allclose(
        robot.end_effector(np.zeros(6)), [0.4521, -0.15005, 0.4318], atol=1e-12
    )
    qr = [0, PI / 2, -PI / 2, 0, 0, 0]
    np.testing.assert_allclose(robot.end_effector(qr), [0.0203, -0.15005, 0.8636], atol=1e-12)
    np.testing.assert_allclose(robot.end_effector_pose(qr)[:3, :3], np.eye(3), atol=1e-12)
    for q in rng.uniform(-PI, PI, size=(10, 6)):
        np.testing.assert_allclose(robot.end_effector_pose(q), _compose(PUMA, q), atol=1e-12)
    np.testing.assert_allclose(np.rad2deg(robot.joint_limits()[1]), [-45, 225])


UR5 = [
    (0.089159, 0, PI / 2),
    (0, -0.425, 0),
    (0, -0.39225, 0),
    (0.10915, 0, PI / 2),
    (0.09465, 0, -PI / 2),
    (0.0823, 0, 0),
]


def test_ur5_zero_pose_and_random_poses(rng):
    robot = rc.preset("ur5")
    expected = [-0.81725, -0.19145, -0.005491]  # -(a2 + a3), -(d4 + d6), d1 - d5
    np.testing.assert_allclose(robot.end_effector(np.zeros(6)), expected, atol=1e-12)
    np.testing.assert_allclose(_compose(UR5, np.zeros(6))[:3, 3], expected, atol=1e-12)
    for q in rng.uniform(-PI, PI, size=(10, 6)):
        np.testing.assert_allclose(robot.end_effector_pose(q), _compose(UR5, q), atol=1e-12)
    np.testing.assert_allclose(robot.joint_limits(), [[-2 * PI, 2 * PI]] * 6)


def test_tool_override_moves_the_flange_point():
    # At q = 0 the UR5's flange z axis is the base's −y axis.
    np.testing.assert_allclose(
        rc.preset("ur5", tool=0.1).end_effector(np.zeros(6)),
        [-0.81725, -0.29145, -0.005491],
        atol=1e-12,
    )


def test_overrides_change_dimensions():
    np.testing.assert_array_equal(
        rc.preset("paper", l1=25, l3=50).end_effector([0, 0, 0]), [80, 0, 25]
    )
    assert rc.preset("PAPER") == rc.preset("paper")


@pytest.mark.parametrize(
    ("args", "kwargs", "match"),
    [
        (("nope",), {}, r"name: unknown preset 'nope'; allowed: paper, cartesian, .*, ur5"),
        ((3,), {}, r"name: unknown preset 3"),
        (
            ("paper",),
            {"l4": 1},
            r"l4: unknown override, value 1; allowed: the parameters of 'paper': l1, l2, l3",
        ),
        (("puma560",), {"a2": 1}, r"a2: unknown override.*'puma560': tool"),
        (("paper",), {"l1": float("nan")}, r"l1: must be finite"),
        (("scara",), {"stroke": -1}, r"limits: lower limit must be below upper limit"),
    ],
)
def test_preset_errors(args, kwargs, match):
    with pytest.raises(InvalidInputError, match=match):
        rc.preset(*args, **kwargs)
