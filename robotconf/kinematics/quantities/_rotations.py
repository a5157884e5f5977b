"""Rotations as three numbers: rotation vectors (the log and exp maps) and URDF's
roll, pitch, yaw — one home for each formula, batched over leading axes.

- A **rotation vector** ``θ k̂`` is the axis times the angle (0 ≤ θ ≤ π). The inverse
  kinematics measures an orientation error with it, and a LIN or CIRC move slerps its
  orientation with it: ``R(u) = exp(u · log(R1 R0ᵀ)) R0``.
- **Roll, pitch, yaw** are turns about the base frame's fixed x, y and z axes, in that
  order: ``R = Rz(yaw) · Ry(pitch) · Rx(roll)`` (URDF's ``rpy``; the panel's Reach tab
  types a pose that way).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import as_float_array, one_line

__all__ = ["rotation_vector", "rotation_matrix", "rpy_from_matrix", "matrix_from_rpy"]

#: Below this ``cos(pitch)`` (round-off: gimbal lock) :func:`rpy_from_matrix` sets yaw to 0;
#: doing so moves the rebuilt rotation by at most π·cos(pitch).
_GIMBAL_LOCK = 1e-17


def _skew_part(r: np.ndarray) -> np.ndarray:
    return np.stack(
        [r[..., 2, 1] - r[..., 1, 2], r[..., 0, 2] - r[..., 2, 0], r[..., 1, 0] - r[..., 0, 1]],
        axis=-1,
    )


def rotation_vector(r: np.ndarray) -> np.ndarray:
    """The rotation vector ``θ k̂`` (rad) of rotation matrices, ``0 ≤ θ ≤ π``.

    Parameters
    ----------
    r : ndarray, shape (..., 3, 3)
        Rotation matrices (orthonormal, det +1).

    Returns
    -------
    ndarray, shape (..., 3)

    Notes
    -----
    ``θ = atan2(|v|, (tr R − 1)/2)`` with ``v`` the axis part ``½(R − Rᵀ)∨``, accurate at
    small angles; near ``θ = π`` (where ``v`` vanishes) the axis comes from the
    symmetric part ``(R + Rᵀ)/2 − cos θ·I = (1 − cos θ) k̂ k̂ᵀ``, its largest column,
    signed by ``v``.

    Examples
    --------
    >>> np.round(rotation_vector(rotation_matrix(np.array([0.0, 0.0, 3.0]))), 12)
    array([0., 0., 3.])
    """
    r = np.asarray(r, dtype=float)
    v = 0.5 * _skew_part(r)
    sin = np.linalg.norm(v, axis=-1)
    cos = 0.5 * (np.trace(r, axis1=-2, axis2=-1) - 1.0)
    angle = np.arctan2(sin, cos)
    with np.errstate(divide="ignore", invalid="ignore"):
        factor = np.where(sin > 1e-12, angle / sin, 1.0 + angle**2 / 6.0)
    out = v * factor[..., np.newaxis]
    near_pi = cos < -0.99
    if np.any(near_pi):
        rows = r[near_pi]
        sym = 0.5 * (rows + np.swapaxes(rows, -1, -2))
        sym -= cos[near_pi][:, np.newaxis, np.newaxis] * np.eye(3)
        column = np.argmax(np.einsum("...ii->...i", sym), axis=-1)
        axis = np.take_along_axis(sym, column[:, np.newaxis, np.newaxis], axis=-1)[..., 0]
        axis /= np.linalg.norm(axis, axis=-1, keepdims=True)
        sign = np.where(np.einsum("...i,...i->...", axis, v[near_pi]) < 0.0, -1.0, 1.0)
        out[near_pi] = axis * (sign * angle[near_pi])[:, np.newaxis]
    return out


def rotation_matrix(w: np.ndarray) -> np.ndarray:
    """Rotation matrices of rotation vectors (Rodrigues' formula).

    Parameters
    ----------
    w : ndarray, shape (..., 3)
        ``θ k̂`` (rad).

    Returns
    -------
    ndarray, shape (..., 3, 3)

    Examples
    --------
    >>> np.round(rotation_matrix(np.array([0.0, 0.0, np.pi / 2])), 12) + 0.0
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])
    """
    w = np.asarray(w, dtype=float)
    angle = np.linalg.norm(w, axis=-1)
    small = angle < 1e-8
    safe = np.where(small, 1.0, angle)
    a = np.where(small, 1.0 - angle**2 / 6.0, np.sin(safe) / safe)
    b = np.where(small, 0.5 - angle**2 / 24.0, (1.0 - np.cos(safe)) / safe**2)
    k = np.zeros((*w.shape[:-1], 3, 3))
    k[..., 0, 1], k[..., 0, 2], k[..., 1, 2] = -w[..., 2], w[..., 1], -w[..., 0]
    k[..., 1, 0], k[..., 2, 0], k[..., 2, 1] = w[..., 2], -w[..., 1], w[..., 0]
    return np.eye(3) + a[..., np.newaxis, np.newaxis] * k + b[..., np.newaxis, np.newaxis] * (k @ k)


def matrix_from_rpy(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """``Rz(yaw) · Ry(pitch) · Rx(roll)``, shape (3, 3); angles in radians.

    >>> matrix_from_rpy(0.0, 0.0, math.pi / 2).round(12) + 0.0
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])
    """
    cr, sr = math.cos(roll), math.sin(roll)
    cp, sp = math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    return np.array(
        [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ]
    )


def rpy_from_matrix(rotation: Any) -> tuple[float, float, float]:
    """URDF's roll, pitch, yaw of a rotation matrix: ``R = Rz(yaw)·Ry(pitch)·Rx(roll)``.

    Parameters
    ----------
    rotation : array-like, shape (3, 3)
        A rotation matrix.

    Returns
    -------
    (roll, pitch, yaw) : floats, radians
        With pitch in [−π/2, π/2]; where ``cos(pitch)`` is below 1e-17 (gimbal lock: only
        roll − yaw or roll + yaw is defined) yaw is set to 0.

    Notes
    -----
    ``pitch = atan2(−r₂₀, √(r₀₀² + r₁₀²))`` and ``yaw = atan2(r₁₀, r₀₀)``; roll is then read
    from what is left once yaw is undone, ``Rz(−yaw)·R = Ry(pitch)·Rx(roll)``, whose middle
    row is ``(0, cos roll, −sin roll)`` whatever the pitch:
    ``roll = atan2(sin(yaw)·r₀₂ − cos(yaw)·r₁₂, cos(yaw)·r₁₁ − sin(yaw)·r₀₁)``. Near
    pitch = ±90° the yaw comes from two tiny entries and is only known to about
    ``ε / cos(pitch)``, but roll absorbs that error exactly (only roll ∓ yaw matters
    there), so ``matrix_from_rpy`` rebuilds the rotation to round-off everywhere. Reading
    roll from ``r₂₁, r₂₂`` instead, the usual formula, divides their rounding by
    ``cos(pitch)`` and misses by up to 1e-8 next to the lock.

    Examples
    --------
    >>> c, s = np.cos(0.3), np.sin(0.3)
    >>> np.round(rpy_from_matrix([[1, 0, 0], [0, c, -s], [0, s, c]]), 12) + 0.0
    array([0.3, 0. , 0. ])
    >>> np.round(rpy_from_matrix([[0, 0, 1], [0, 1, 0], [-1, 0, 0]]), 12) + 0.0  # Ry(π/2)
    array([0.        , 1.57079633, 0.        ])
    """
    allowed = "a 3×3 rotation matrix of finite numbers"
    r = as_float_array(rotation, "rotation", allowed)
    if r.shape != (3, 3) or not np.isfinite(r).all():
        raise InvalidInputError(
            "rotation", one_line(rotation), allowed, problem="expected finite shape (3, 3):"
        )
    cos_pitch = math.hypot(r[0, 0], r[1, 0])
    pitch = math.atan2(-r[2, 0], cos_pitch)
    yaw = math.atan2(r[1, 0], r[0, 0]) if cos_pitch > _GIMBAL_LOCK else 0.0
    cy, sy = math.cos(yaw), math.sin(yaw)
    roll = math.atan2(sy * r[0, 2] - cy * r[1, 2], cy * r[1, 1] - sy * r[0, 1])
    return (roll, pitch, yaw)
