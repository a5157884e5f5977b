"""Locating a frame from measured points: exact data, noisy data against the error the
noise should give (derived here independently), and bad input."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import robotconf as rc
from robotconf.calibration import MAX_POINTS, locate_frame
from robotconf.kinematics import rotation_matrix, rotation_vector

#: Six points on a robot's base plate and column (mm), spread as a tracker would measure.
BASE_POINTS = np.array(
    [
        [150.0, 0.0, 0.0],
        [-75.0, 130.0, 0.0],
        [-75.0, -130.0, 0.0],
        [0.0, 0.0, 400.0],
        [100.0, 50.0, 650.0],
        [-40.0, 90.0, 250.0],
    ]
)
NOISE = 0.1  # mm per coordinate


def true_pose(seed: int = 3) -> np.ndarray:
    rng = np.random.default_rng(seed)
    pose = np.eye(4)
    pose[:3, :3] = rotation_matrix(rng.normal(size=3))
    pose[:3, 3] = rng.uniform(-2000, 2000, 3)
    return pose


def expected_covariance(nominal: np.ndarray, pose: np.ndarray, sigma: float) -> np.ndarray:
    """The linearized least-squares covariance of (turn, origin), derived here from the
    normal equations: with u_i the centred points in the world and δc the centroid's
    error, the residual is ε_i − δc − δθ × u_i; Σ u_i = 0 decouples δc (σ²/N per axis)
    from δθ (σ² (Σ [u_i]×ᵀ[u_i]×)⁻¹), and the origin t = c − R n̄ moves by
    δc + (R n̄) × δθ."""
    rotation = pose[:3, :3]
    centred = (nominal - nominal.mean(axis=0)) @ rotation.T

    def cross(v: np.ndarray) -> np.ndarray:
        return np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])

    normal = sum(cross(u).T @ cross(u) for u in centred)
    turn = sigma**2 * np.linalg.inv(normal)
    lever = cross(rotation @ nominal.mean(axis=0))
    origin = sigma**2 / len(nominal) * np.eye(3) + lever @ turn @ lever.T
    out = np.zeros((6, 6))
    out[:3, :3], out[3:, 3:] = turn, origin
    out[3:, :3] = lever @ turn
    out[:3, 3:] = out[3:, :3].T
    return out


def pose_error(found: np.ndarray, truth: np.ndarray) -> np.ndarray:
    """(turn vector of R_found·R_trueᵀ, t_found − t_true)."""
    turn = rotation_vector(found[:3, :3] @ truth[:3, :3].T)
    return np.concatenate([turn, found[:3, 3] - truth[:3, 3]])


def measure(pose: np.ndarray, rng: np.random.Generator, points: np.ndarray = BASE_POINTS):
    exact = points @ pose[:3, :3].T + pose[:3, 3]
    return exact + rng.normal(scale=NOISE, size=exact.shape)


def test_exact_points_give_the_exact_pose():
    pose = true_pose()
    fit = rc.locate_frame(BASE_POINTS @ pose[:3, :3].T + pose[:3, 3], BASE_POINTS)
    np.testing.assert_allclose(fit.pose, pose, atol=1e-12 * 2000)
    assert fit.max_error < 1e-9
    assert fit.pose[3].tolist() == [0.0, 0.0, 0.0, 1.0]
    assert np.linalg.det(fit.rotation) == pytest.approx(1.0, abs=1e-14)


def test_a_base_from_six_points_with_0_1_mm_noise_is_within_the_expected_error():
    pose = true_pose()
    expected = expected_covariance(BASE_POINTS, pose, NOISE)
    # The base plate holds the origin, near the points: its expected error is of the order
    # of the noise, σ·√(3/N) plus the turn's error times the lever from the centroid.
    origin_rms = float(np.sqrt(np.trace(expected[3:, 3:])))
    assert 0.05 < origin_rms < 0.2
    fit = locate_frame(measure(pose, np.random.default_rng(11)), BASE_POINTS)
    error = pose_error(fit.pose, pose)
    assert np.linalg.norm(error[3:]) <= 3 * origin_rms
    # The library's own covariance is the derivation above (at the fitted rotation).
    np.testing.assert_allclose(fit.covariance(NOISE), expected, rtol=1e-3, atol=1e-12)
    # Its noise estimate from the residuals is near the true 0.1 mm (12 degrees of freedom).
    assert 0.05 < fit.noise < 0.16


def test_over_many_measurements_the_error_matches_the_derived_covariance():
    pose = true_pose(5)
    expected = expected_covariance(BASE_POINTS, pose, NOISE)
    rng = np.random.default_rng(2)
    errors = np.array(
        [pose_error(locate_frame(measure(pose, rng), BASE_POINTS).pose, pose) for _ in range(2000)]
    )
    # The origin's rms error matches the derivation within sampling error (2000 trials:
    # about 2 %), and the whole 6-vector's squared Mahalanobis distance averages 6.
    measured_rms = float(np.sqrt(np.mean(np.sum(errors[:, 3:] ** 2, axis=1))))
    assert measured_rms == pytest.approx(np.sqrt(np.trace(expected[3:, 3:])), rel=0.06)
    mahalanobis = np.einsum("ti,ij,tj->t", errors, np.linalg.inv(expected), errors)
    assert float(np.mean(mahalanobis)) == pytest.approx(6.0, abs=0.35)


def test_residuals_point_at_a_misread_point():
    pose = true_pose()
    measured = BASE_POINTS @ pose[:3, :3].T + pose[:3, 3]
    measured[4] += [0.0, 2.0, 0.0]  # one point misread by 2 mm
    fit = locate_frame(measured, BASE_POINTS)
    assert int(np.argmax(fit.errors)) == 4
    assert fit.errors.shape == (6,) and fit.residuals.shape == (6, 3)
    np.testing.assert_allclose(fit.rms, np.sqrt(np.mean(fit.errors**2)))


def test_three_points_are_enough_and_a_table_is_found_in_the_robots_frame():
    corners = np.array([[0.0, 0.0, 0.0], [800.0, 0.0, 0.0], [0.0, 600.0, 0.0]])
    pose = true_pose(7)
    fit = locate_frame(corners @ pose[:3, :3].T + pose[:3, 3], corners)
    np.testing.assert_allclose(fit.pose, pose, atol=1e-9)


def test_nearly_collinear_points_warn_and_collinear_points_are_refused():
    line = np.array([[0.0, 0.0, 0.0], [100.0, 0.0, 0.0], [200.0, 0.0, 0.0]])
    near = line + [[0, 0, 0], [0, 0.5, 0], [0, 0, 0]]  # 0.5 mm off a 200 mm line
    with pytest.warns(UserWarning, match="nearly on one line"):
        locate_frame(near, near)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        locate_frame(BASE_POINTS, BASE_POINTS)  # no warning for a good spread
    with pytest.raises(rc.InvalidInputError, match="lie on one line") as caught:
        locate_frame(line, line)
    assert caught.value.field == "nominal"
    with pytest.raises(rc.InvalidInputError, match="all points coincide"):
        locate_frame(np.ones((4, 3)), np.ones((4, 3)))


@pytest.mark.parametrize(
    ("measured", "nominal", "field", "words"),
    [
        (BASE_POINTS[:2], BASE_POINTS[:2], "measured", "too few points"),
        (BASE_POINTS, BASE_POINTS[:5], "nominal", "expected 6 rows, got 5"),
        (BASE_POINTS[:, :2], BASE_POINTS, "measured", "shape (N, 3)"),
        (BASE_POINTS.ravel(), BASE_POINTS, "measured", "shape (N, 3)"),
        (np.where(np.eye(6, 3) == 1, np.nan, BASE_POINTS), BASE_POINTS, "measured", "finite"),
        (BASE_POINTS, BASE_POINTS * 1e149, "nominal", "too large"),
        ("1, 2, 3", BASE_POINTS, "measured", "text"),
        ([[1, 2, True]] * 3, BASE_POINTS[:3], "measured", "boolean"),
    ],
)
def test_bad_points_are_refused_naming_the_input(measured, nominal, field, words):
    with pytest.raises(rc.InvalidInputError) as caught:
        locate_frame(measured, nominal)
    assert caught.value.field == field
    assert words in str(caught.value)


def test_too_many_points_are_refused_before_any_work():
    huge = [[0.0, 0.0, 0.0]] * (MAX_POINTS + 1)
    with pytest.raises(rc.InvalidInputError, match="too many points"):
        locate_frame(huge, huge)


def test_huge_but_allowed_coordinates_stay_finite():
    pose = true_pose()
    points = BASE_POINTS * 1e146  # |x| up to 6.5e148 ≤ 1e150
    fit = locate_frame(points @ pose[:3, :3].T, points)
    np.testing.assert_allclose(fit.rotation, pose[:3, :3], atol=1e-12)
    assert np.all(np.isfinite(fit.covariance(1.0)))
