"""Roll, pitch, yaw: a rotation → rpy → rotation round trip stays at round-off everywhere,
the gimbal lock at pitch = ±90° and its neighbourhood included (hypothesis)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import robotconf as rc
from robotconf.kinematics import matrix_from_rpy, rotation_matrix, rpy_from_matrix

EPS = np.finfo(float).eps
#: A rotation built from a few products of sines and cosines is orthonormal only to a few
#: ulp, and rebuilding it adds as many: 10 ulp of 1.
ROUND_OFF = 10 * EPS

angles = st.floats(-np.pi, np.pi, allow_nan=False)
sides = st.sampled_from([-1.0, 1.0])
quaternions = st.lists(st.floats(-1.0, 1.0), min_size=4, max_size=4).filter(
    lambda v: float(np.linalg.norm(v)) > 0.1
)
# Distances from the lock, 1e-17 … 0.1 rad, either side, and the lock itself.
offsets = st.one_of(
    st.just(0.0),
    st.builds(
        lambda exponent, sign: sign * 10.0**exponent,
        st.floats(-17.0, -1.0),
        st.sampled_from([-1.0, 1.0]),
    ),
)


def round_trip_error(rotation: np.ndarray) -> float:
    return float(np.max(np.abs(matrix_from_rpy(*rpy_from_matrix(rotation)) - rotation)))


def from_quaternion(q: np.ndarray) -> np.ndarray:
    """An independent way to build rotations: the unit quaternion's matrix."""
    w, x, y, z = q / np.linalg.norm(q)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


@settings(max_examples=400, deadline=None)
@given(quaternions)
def test_any_rotation_comes_back_to_round_off(quaternion):
    assert round_trip_error(from_quaternion(np.array(quaternion))) <= ROUND_OFF


@settings(max_examples=400, deadline=None)
@given(angles, sides, offsets, angles)
def test_rotations_next_to_the_gimbal_lock_come_back_to_round_off(roll, side, offset, yaw):
    rotation = matrix_from_rpy(roll, side * np.pi / 2 + offset, yaw)
    assert round_trip_error(rotation) <= ROUND_OFF


@settings(max_examples=400, deadline=None)
@given(angles, sides, angles, st.floats(-16.0, -3.0), st.integers(0, 2**32 - 1))
def test_rotations_turned_slightly_off_the_lock_come_back_to_round_off(
    roll, side, yaw, exponent, seed
):
    # Off the lock in any direction, not only along pitch.
    turn = np.random.default_rng(seed).normal(size=3)
    turn *= 10.0**exponent / np.linalg.norm(turn)
    rotation = matrix_from_rpy(roll, side * np.pi / 2, yaw) @ rotation_matrix(turn)
    assert round_trip_error(rotation) <= ROUND_OFF


def test_a_case_the_usual_formula_misses_by_1e_8():
    # cos(pitch) ≈ 1e-8: reading roll from r21, r22 (both ~1e-8) loses 8 digits.
    rotation = matrix_from_rpy(-0.56, np.pi / 2, 2.57) @ rotation_matrix([-9.7e-9, 3e-9, 2.3e-9])
    assert round_trip_error(rotation) <= ROUND_OFF


@pytest.mark.parametrize(
    ("rotation", "expected"),
    [
        (np.eye(3), (0.0, 0.0, 0.0)),
        ([[0, 0, 1], [0, 1, 0], [-1, 0, 0]], (0.0, np.pi / 2, 0.0)),  # Ry(90°): yaw set to 0
        ([[0, 0, -1], [0, 1, 0], [1, 0, 0]], (0.0, -np.pi / 2, 0.0)),
        ([[-1, 0, 0], [0, -1, 0], [0, 0, 1]], (0.0, 0.0, np.pi)),  # Rz(180°)
    ],
)
def test_exact_cases(rotation, expected):
    np.testing.assert_allclose(rpy_from_matrix(rotation), expected, atol=1e-15)


def test_urdf_and_reach_tab_read_the_one_home():
    from robotconf import io
    from robotconf.panel.actions import _reach as reach_actions
    from robotconf.panel.state import _reach as reach_state

    assert io.rpy_from_matrix is rpy_from_matrix
    assert reach_state.rpy_from_matrix is rpy_from_matrix
    assert reach_actions.rpy_from_matrix is rpy_from_matrix


def test_a_puma_pose_next_to_the_lock_survives_the_reach_tabs_pose_switch():
    # The Reach tab shows a pose as x, y, z, roll, pitch, yaw and rebuilds it from them:
    # a wrist pose 1e-9 rad from pitch = 90° keeps the solution where it was.
    from robotconf.panel.state import ReachState, target_numbers, target_of

    robot = rc.preset("puma560")
    target = target_of((0.4, 0.1, 0.2, 0.3, np.pi / 2 - 1e-9, -0.6), "pose")
    found = rc.ik(robot, target, mode="pose")
    assert found.success
    moved = robot.with_q(found.q)
    pose = moved.end_effector_pose()
    rebuilt = target_of(target_numbers(ReachState(mode="pose"), moved), "pose")
    assert np.max(np.abs(rebuilt - pose)) <= ROUND_OFF
    again = rc.ik(robot, rebuilt, q0=found.q, mode="pose")
    assert np.max(np.abs(again.q - found.q)) <= 1e-9
