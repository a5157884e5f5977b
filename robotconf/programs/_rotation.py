"""Rotation vectors: the log and exp maps of rotation matrices, batched over a leading axis.

Orientation along a LIN or CIRC path is slerp: ``R(u) = R0 · exp(u·θ k̂)`` with
``θ k̂ = log(R0ᵀ R1)``, the shortest turn from the start to the end orientation. The
turn's axis ``R0 k̂`` is fixed in the base frame, so the angular velocity is
``ω = R0 k̂ · θ u̇`` and its rate ``ω̇ = R0 k̂ · θ ü`` (no other terms).
"""

from __future__ import annotations

import numpy as np

__all__ = ["log_rotation", "exp_rotation", "rotation_error"]


def _skew_part(r: np.ndarray) -> np.ndarray:
    return np.stack(
        [r[..., 2, 1] - r[..., 1, 2], r[..., 0, 2] - r[..., 2, 0], r[..., 1, 0] - r[..., 0, 1]],
        axis=-1,
    )


def log_rotation(r: np.ndarray) -> np.ndarray:
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
    >>> np.round(log_rotation(exp_rotation(np.array([0.0, 0.0, 3.0]))), 12)
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


def exp_rotation(w: np.ndarray) -> np.ndarray:
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
    >>> np.round(exp_rotation(np.array([0.0, 0.0, np.pi / 2])), 12) + 0.0
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


def rotation_error(target: np.ndarray, actual: np.ndarray) -> np.ndarray:
    """The turn still needed, in the base frame: ``log(R_target · R_actualᵀ)``, (..., 3).

    >>> rotation_error(exp_rotation(np.array([0.1, 0, 0])), np.eye(3)).round(12) + 0.0
    array([0.1, 0. , 0. ])
    """
    return log_rotation(target @ np.swapaxes(actual, -1, -2))
