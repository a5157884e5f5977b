"""Geometric Jacobian against central differences of frame_poses."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.kinematics import jacobian


@pytest.fixture
def rng() -> np.random.Generator:
    return np.random.default_rng(20240601)


def paper_robot() -> rc.Robot:
    return rc.Robot(
        [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
        end_effector=(40, 0, 0),
    )


def mixed_robot(active: int | None = None) -> rc.Robot:
    """Every kind of link: rotations, translations, fixed, none and DH rows."""
    return rc.Robot(
        [
            rc.Module("Rz", a=(0.1, 0.2, 0.5)),
            rc.Module("Tx", a=(0.3, 0, 0)),
            rc.Module("Ry", a=(0, 0.4, 0.2)),
            rc.Module("fixed", a=(0.1, -0.2, 0.3)),
            rc.DHLink(theta=0.3, d=0.2, a=0.5, alpha=0.7, joint="R"),
            rc.Module("none"),
            rc.DHLink(theta=0.1, d=0.1, a=0.2, alpha=-0.4, joint="P", convention="modified"),
            rc.Module("Rx", a=(0.2, 0.1, 0)),
            rc.DHLink(theta=0.0, d=0.3, a=0.1, alpha=1.1, joint="R", convention="modified"),
        ],
        end_effector=(0.3, -0.1, 0.2),
        active=active,
    )


def _point_poses(robot: rc.Robot, q: np.ndarray, frame: int | None) -> np.ndarray:
    if frame is None:
        return robot.end_effector_pose(q)
    return robot.frame_poses(q)[..., frame, :, :]


def finite_difference_jacobian(
    robot: rc.Robot, q: np.ndarray, frame: int | None, h: float = 1e-6
) -> np.ndarray:
    """(T, 6, n): linear rows from dp/dq, angular rows from vee(dR/dq · Rᵀ)."""
    out = np.empty((q.shape[0], 6, robot.n))
    for j in range(robot.n):
        step = np.zeros(robot.n)
        step[j] = h
        plus = _point_poses(robot, q + step, frame)
        minus = _point_poses(robot, q - step, frame)
        centre = _point_poses(robot, q, frame)
        out[:, :3, j] = (plus[..., :3, 3] - minus[..., :3, 3]) / (2 * h)
        d_rot = (plus[..., :3, :3] - minus[..., :3, :3]) / (2 * h)
        spin = d_rot @ np.swapaxes(centre[..., :3, :3], -1, -2)
        out[:, 3:, j] = np.stack([spin[..., 2, 1], spin[..., 0, 2], spin[..., 1, 0]], axis=-1)
    return out


@pytest.mark.parametrize("frame", [None, 0, 1, 2, 3, 4, 5, 6, 7, 8])
def test_jacobian_matches_central_differences(rng: np.random.Generator, frame) -> None:  # type: ignore[no-untyped-def]
    robot = mixed_robot()
    q = rng.uniform(-np.pi, np.pi, size=(25, robot.n))
    expected = finite_difference_jacobian(robot, q, frame)
    got = jacobian(robot, q, frame=frame)
    assert got.shape == (25, 6, robot.n)
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-7)
    if frame is not None:  # joints after the frame do not move it
        assert np.all(got[:, :, frame + 1 :] == 0.0)


def test_inactive_none_and_fixed_modules_give_zero_columns(rng: np.random.Generator) -> None:
    robot = mixed_robot(active=5)
    q = rng.uniform(-1, 1, size=(10, robot.n))
    got = jacobian(robot, q)
    np.testing.assert_allclose(got, finite_difference_jacobian(robot, q, None), atol=1e-7)
    for j in (3, 5, 6, 7, 8):  # fixed, none, and everything after the 5 active modules
        assert np.all(got[:, :, j] == 0.0)
    assert np.all(np.abs(got[:, :, 4]).sum(axis=1) > 0)


def test_paper_robot_closed_form() -> None:
    robot = paper_robot()
    q3 = 0.8
    j = jacobian(robot, [0.0, 0.0, q3])
    assert j.shape == (6, 3)
    # EE x = 30 + 40 cos q3, z = 20 − 40 sin q3 → ∂/∂q3 = (−40 sin q3, 0, −40 cos q3).
    np.testing.assert_allclose(j[:3, 2], [-40 * np.sin(q3), 0, -40 * np.cos(q3)], atol=1e-12)
    np.testing.assert_allclose(j[3:, 2], [0, 1, 0], atol=1e-15)
    np.testing.assert_allclose(j[3:, 0], [0, 0, 1], atol=1e-15)
    # Names and indices agree; "EE" is the default.
    np.testing.assert_array_equal(
        jacobian(robot, [0, 0, q3], frame="M2"), jacobian(robot, [0, 0, q3], 1)
    )
    np.testing.assert_array_equal(jacobian(robot, [0, 0, q3], "EE"), j)
    # The robot resolves the frame: a coordinate name and " ee " name the same frames.
    np.testing.assert_array_equal(
        jacobian(robot, [0, 0, q3], frame="q2"), jacobian(robot, [0, 0, q3], 1)
    )
    np.testing.assert_array_equal(jacobian(robot, [0, 0, q3], " ee "), j)
    np.testing.assert_allclose(jacobian(robot, [0, 0, q3], "M2")[:3, 0], [0, 0, 0], atol=1e-15)
    np.testing.assert_array_equal(jacobian(robot.with_q([0, 0, q3])), j)


def test_prismatic_column_is_the_axis() -> None:
    robot = rc.Robot([rc.Module("Rz"), rc.Module("Tx", a=(1, 0, 0))], end_effector=(0, 0, 1))
    j = jacobian(robot, [np.pi / 2, 0.5])
    np.testing.assert_allclose(j[:, 1], [0, 1, 0, 0, 0, 0], atol=1e-15)
    np.testing.assert_allclose(j[:3, 0], [-1.5, 0, 0], atol=1e-15)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"frame": "M7"}, r"frame: unknown module 'M7'; allowed: an index 0 to 2, .*or 'EE'"),
        ({"frame": 3}, r"frame: out of range: 3; allowed: .*index 0 to 2"),
        ({"frame": -1}, r"frame: out of range: -1"),
        ({"frame": True}, r"frame: not an integer: True"),
        ({"frame": 1.0}, r"frame: not an integer: 1.0"),
        ({"q": [0, 0]}, r"q: expected shape \(3,\) or \(T, 3\)"),
        ({"q": [0, np.nan, 0]}, r"q: q2 must be finite"),
    ],
)
def test_bad_input(kwargs, match) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ValueError, match=match):
        jacobian(paper_robot(), **{"q": [0, 0, 0], **kwargs})
