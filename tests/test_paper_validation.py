"""The paper's validation case (§3, Figures 13–15) and hand-derived configurations."""

import numpy as np
import pytest

from .conftest import L1, L2, L3, assert_transform_close


def test_parking_position_frame_origins(paper_robot):
    origins = paper_robot.frame_origins([0, 0, 0])
    np.testing.assert_array_equal(origins, [[0, 0, 0], [0, 0, 20], [30, 0, 20]])


def test_parking_position_end_effector(paper_robot):
    np.testing.assert_array_equal(paper_robot.end_effector([0, 0, 0]), [70, 0, 20])


def test_parking_position_matrices_match_figure_13(paper_robot):
    # Figure 13: M1 = I, M2 = Trans(0, 0, 20), M3 = Trans(30, 0, 20), EE = Trans(70, 0, 20).
    poses = paper_robot.frame_poses([0, 0, 0])
    expected = np.tile(np.eye(4), (3, 1, 1))
    expected[1, :3, 3] = (0, 0, 20)
    expected[2, :3, 3] = (30, 0, 20)
    np.testing.assert_array_equal(poses, expected)
    ee = np.eye(4)
    ee[:3, 3] = (70, 0, 20)
    np.testing.assert_array_equal(paper_robot.end_effector_pose([0, 0, 0]), ee)


def test_transfer_matrices_are_eq_17_to_19(paper_robot):
    q1, q2, q3 = 0.3, -0.4, 1.1
    a1, a2, a3 = paper_robot.transfer_matrices([q1, q2, q3])
    c, s = np.cos, np.sin
    assert_transform_close(
        a1, [[c(q1), -s(q1), 0, 0], [s(q1), c(q1), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
    )
    assert_transform_close(
        a2, [[c(q2), 0, s(q2), 0], [0, 1, 0, 0], [-s(q2), 0, c(q2), L1], [0, 0, 0, 1]]
    )
    assert_transform_close(
        a3, [[c(q3), 0, s(q3), L2], [0, 1, 0, 0], [-s(q3), 0, c(q3), 0], [0, 0, 0, 1]]
    )


def test_default_q_is_the_modules_own(paper_robot):
    robot = paper_robot.with_q([np.pi / 2, 0, 0])
    np.testing.assert_allclose(robot.end_effector(), [0, 70, 20], atol=1e-12)
    np.testing.assert_allclose(robot.transfer_matrices()[0], robot.transfer_matrices(robot.q)[0])


@pytest.mark.parametrize(
    ("q", "origins", "ee"),
    [
        # q1 = 90°: the whole arm turns about z, x becomes y.
        ((np.pi / 2, 0, 0), [[0, 0, 0], [0, 0, 20], [0, 30, 20]], [0, 70, 20]),
        # q2 = 90°: Ry maps x to -z, so the arm points straight down from (0, 0, 20).
        ((0, np.pi / 2, 0), [[0, 0, 0], [0, 0, 20], [0, 0, -10]], [0, 0, -50]),
        # q3 = -90°: the last link points straight up from (30, 0, 20).
        ((0, 0, -np.pi / 2), [[0, 0, 0], [0, 0, 20], [30, 0, 20]], [30, 0, 60]),
        # q2 = 180°: the arm folds back over the base.
        ((0, np.pi, 0), [[0, 0, 0], [0, 0, 20], [-30, 0, 20]], [-70, 0, 20]),
    ],
)
def test_hand_derived_configurations(paper_robot, q, origins, ee):
    np.testing.assert_allclose(paper_robot.frame_origins(q), origins, atol=1e-12)
    np.testing.assert_allclose(paper_robot.end_effector(q), ee, atol=1e-12)


def test_closed_form_end_effector(paper_robot, rng):
    # p_EE = (c1 (l2 c2 + l3 c23), s1 (l2 c2 + l3 c23), l1 − l2 s2 − l3 s23), derived by hand.
    q = rng.uniform(-np.pi, np.pi, (500, 3))
    q1, q2, q3 = q.T
    reach = L2 * np.cos(q2) + L3 * np.cos(q2 + q3)
    expected = np.stack(
        [np.cos(q1) * reach, np.sin(q1) * reach, L1 - L2 * np.sin(q2) - L3 * np.sin(q2 + q3)],
        axis=1,
    )
    np.testing.assert_allclose(paper_robot.end_effector(q), expected, rtol=0, atol=1e-12)
