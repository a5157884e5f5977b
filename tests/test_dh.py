"""Denavit–Hartenberg: standard (paper eq. 9–10) and modified (Craig), never guessed."""

import numpy as np
import pytest

import robotconf as rc

from .conftest import assert_transform_close, reference_dh, reference_poses

# PUMA 560 lengths in metres (Craig, Introduction to Robotics, 3rd ed., §3.7 and §4.7).
A2, A3, D3, D4 = 0.4318, 0.0203, 0.15005, 0.4318


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_dh_matrix_matches_written_out_formula(convention, rng):
    for theta, d, a, alpha in rng.uniform(-3, 3, (50, 4)):
        assert_transform_close(
            rc.dh_matrix(theta, d, a, alpha, convention=convention),
            reference_dh(theta, d, a, alpha, convention),
        )


def test_standard_dh_is_the_product_of_four_elementary_transforms():
    theta, d, a, alpha = 0.3, 1.2, -0.7, 0.9
    product = (
        rc.transfer_matrix("Rz", theta)
        @ rc.transfer_matrix("Tz", d)
        @ rc.transfer_matrix("Tx", a)
        @ rc.transfer_matrix("Rx", alpha)
    )
    assert_transform_close(rc.dh_matrix(theta, d, a, alpha), product)
    modified = (
        rc.transfer_matrix("Rx", alpha)
        @ rc.transfer_matrix("Tx", a)
        @ rc.transfer_matrix("Rz", theta)
        @ rc.transfer_matrix("Tz", d)
    )
    assert_transform_close(rc.dh_matrix(theta, d, a, alpha, convention="modified"), modified)


def test_conventions_differ_so_neither_is_guessed():
    standard = rc.dh_matrix(0.3, 1.0, 2.0, 0.5, convention="standard")
    modified = rc.dh_matrix(0.3, 1.0, 2.0, 0.5, convention="modified")
    assert np.abs(standard - modified).max() > 0.1
    assert "convention='modified'" in repr(rc.DHLink(a=1.0, convention="modified"))


def test_dh_matrix_batched_theta(rng):
    theta = rng.uniform(-3, 3, 20)
    batch = rc.dh_matrix(theta, 0.2, 0.5, -0.4)
    for sample, value in zip(batch, theta, strict=True):
        assert_transform_close(sample, reference_dh(value, 0.2, 0.5, -0.4, "standard"))


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_planar_2r_closed_form(convention, rng):
    l1, l2 = 0.7, 0.45
    if convention == "standard":
        rows = [(0, 0, l1, 0, "R"), (0, 0, l2, 0, "R")]
        tip = (0, 0, 0)
    else:  # modified: a_{i-1} sits on the next row, the last length goes to the tool point
        rows = [(0, 0, 0, 0, "R"), (0, 0, l1, 0, "R")]
        tip = (l2, 0, 0)
    arm = rc.Robot.from_dh(rows, convention=convention, end_effector=tip)
    q = rng.uniform(-np.pi, np.pi, (200, 2))
    expected = np.stack(
        [
            l1 * np.cos(q[:, 0]) + l2 * np.cos(q.sum(1)),
            l1 * np.sin(q[:, 0]) + l2 * np.sin(q.sum(1)),
            np.zeros(len(q)),
        ],
        axis=1,
    )
    np.testing.assert_allclose(arm.end_effector(q), expected, atol=1e-12)


def puma_standard() -> rc.Robot:
    """PUMA 560, standard DH as in Corke's Robotics Toolbox (d1 = 0)."""
    half = np.pi / 2
    rows = [
        (0, 0, 0, half, "R"),
        (0, 0, A2, 0, "R"),
        (0, D3, A3, -half, "R"),
        (0, D4, 0, half, "R"),
        (0, 0, 0, -half, "R"),
        (0, 0, 0, 0, "R"),
    ]
    return rc.Robot.from_dh(rows, convention="standard")


def puma_modified() -> rc.Robot:
    """PUMA 560, modified DH exactly as Craig's Figure 3.21 table."""
    half = np.pi / 2
    rows = [
        (0, 0, 0, 0, "R"),
        (0, 0, 0, -half, "R"),
        (0, D3, A2, 0, "R"),
        (0, D4, A3, -half, "R"),
        (0, 0, 0, half, "R"),
        (0, 0, 0, -half, "R"),
    ]
    return rc.Robot.from_dh(rows, convention="modified")


def test_puma_standard_zero_pose():
    # Corke's p560.fkine(qz): identity rotation, position (a2 + a3, -d3, d4).
    expected = np.eye(4)
    expected[:3, 3] = (A2 + A3, -D3, D4)
    assert_transform_close(puma_standard().end_effector_pose(np.zeros(6)), expected)


def test_puma_modified_matches_craigs_closed_form(rng):
    # Craig eq. 3.14: the wrist position 0P6 of the PUMA 560.
    q = rng.uniform(-np.pi, np.pi, (300, 6))
    c1, s1 = np.cos(q[:, 0]), np.sin(q[:, 0])
    c2, s2 = np.cos(q[:, 1]), np.sin(q[:, 1])
    c23, s23 = np.cos(q[:, 1] + q[:, 2]), np.sin(q[:, 1] + q[:, 2])
    reach = A2 * c2 + A3 * c23 - D4 * s23
    expected = np.stack(
        [c1 * reach - D3 * s1, s1 * reach + D3 * c1, -A3 * s23 - A2 * s2 - D4 * c23], axis=1
    )
    np.testing.assert_allclose(puma_modified().end_effector(q), expected, atol=1e-12)


@pytest.mark.parametrize("robot_factory", [puma_standard, puma_modified])
def test_puma_poses_match_independent_products(robot_factory, rng):
    robot = robot_factory()
    for q in rng.uniform(-np.pi, np.pi, (20, 6)):
        assert_transform_close(robot.frame_poses(q), reference_poses(robot, q))


def test_prismatic_row_adds_q_to_d():
    link = rc.DHLink(theta=0.4, d=0.5, a=0.2, alpha=0.1, joint="P")
    assert_transform_close(link.matrix(0.25), reference_dh(0.4, 0.75, 0.2, 0.1, "standard"))
    revolute = rc.DHLink(theta=0.4, d=0.5, a=0.2, alpha=0.1, joint="R")
    assert_transform_close(revolute.matrix(0.25), reference_dh(0.65, 0.5, 0.2, 0.1, "standard"))


def test_from_dh_accepts_dicts_and_links():
    robot = rc.Robot.from_dh(
        [
            {"theta": 0, "d": 0.1, "a": 0.3, "alpha": 0, "joint": "R", "name": "shoulder"},
            rc.DHLink(a=0.2, joint="P", convention="standard"),
        ]
    )
    assert robot.module_names == ("shoulder", "M2")
    assert robot.joint_types == ("revolute", "prismatic")


def test_robot_mixes_modules_and_dh_links(rng):
    robot = rc.Robot(
        [
            rc.Module("Rz", a=(0, 0, 0.5)),
            rc.DHLink(theta=0.1, d=0.2, a=0.3, alpha=np.pi / 2, joint="R"),
            rc.Module("Tx", a=(0.1, 0, 0)),
            rc.DHLink(theta=0.2, d=0.0, a=0.4, alpha=-0.3, joint="P", convention="modified"),
        ],
        end_effector=(0.05, 0.01, 0.02),
    )
    for q in rng.uniform(-2, 2, (10, 4)):
        poses = reference_poses(robot, q)
        assert_transform_close(robot.frame_poses(q), poses)
        ee = poses[-1] @ np.array([0.05, 0.01, 0.02, 1.0])
        np.testing.assert_allclose(robot.end_effector(q), ee[:3], atol=1e-12)


def test_dh_link_repr_round_trips():
    link = rc.DHLink(theta=0.1, d=0.2, a=0.3, alpha=-0.4, joint="P", convention="modified", q=0.5)
    assert eval(repr(link), {"DHLink": rc.DHLink}) == link
