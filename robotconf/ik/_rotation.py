"""The rotation vector (axis times angle) of many rotation matrices at once.

The numeric solver measures an orientation error as the rotation vector of
``R_target · Rᵀ``: its direction is the axis and its length the angle (0 … π) of the
turn still needed. Two formulas cover the whole range without losing digits:

- angles up to 90° (``cos θ ≥ 0``): the skew part ``s = vee(R − Rᵀ)/2 = sin θ · u`` gives
  the axis, and ``θ = atan2(|s|, cos θ)`` the angle (exact for tiny angles too);
- larger angles: ``sin θ`` shrinks towards 180°, so the axis comes from the symmetric
  part instead, ``(R + Rᵀ)/2 − cos θ · I = (1 − cos θ) · u uᵀ``, its sign from ``s``.
"""

from __future__ import annotations

import numpy as np

__all__ = ["rotation_vector", "rotation_matrix"]


def rotation_vector(rotation: np.ndarray) -> np.ndarray:
    """Axis × angle of rotation matrices (the matrix logarithm, as a vector).

    Parameters
    ----------
    rotation : ndarray, shape (B, 3, 3)
        Proper rotation matrices.

    Returns
    -------
    ndarray, shape (B, 3)
        ``θ · u`` with ``0 ≤ θ ≤ π`` (radians) and unit axis ``u``; at exactly 180° either
        of the two equivalent axes.

    Examples
    --------
    A quarter turn about z:

    >>> turn = np.array([[[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]])
    >>> rotation_vector(turn).round(12) + 0.0
    array([[0.        , 0.        , 1.57079633]])
    """
    r = rotation
    skew = 0.5 * np.stack(
        (r[:, 2, 1] - r[:, 1, 2], r[:, 0, 2] - r[:, 2, 0], r[:, 1, 0] - r[:, 0, 1]), axis=-1
    )
    cos = np.clip(0.5 * (r[:, 0, 0] + r[:, 1, 1] + r[:, 2, 2] - 1.0), -1.0, 1.0)
    sin = np.linalg.norm(skew, axis=-1)
    angle = np.arctan2(sin, cos)
    # Small turns: θ/sin θ → 1, so s itself is the answer where sin θ underflows.
    ratio = np.divide(angle, sin, out=np.ones_like(angle), where=sin > 1e-300)
    out = skew * ratio[:, np.newaxis]
    wide = cos < 0.0
    if np.any(wide):
        rw, cw, sw = r[wide], cos[wide], skew[wide]
        symmetric = 0.5 * (rw + rw.transpose(0, 2, 1)) - cw[:, np.newaxis, np.newaxis] * np.eye(3)
        diagonal = np.einsum("bii->bi", symmetric)
        best = np.argmax(diagonal, axis=-1)
        rows = np.arange(len(best))
        column = symmetric[rows, :, best]
        axis = column / np.linalg.norm(column, axis=-1, keepdims=True)
        flip = np.einsum("bi,bi->b", axis, sw) < 0.0
        axis[flip] *= -1.0
        out[wide] = axis * angle[wide, np.newaxis]
    return out


def rotation_matrix(vector: np.ndarray) -> np.ndarray:
    """Rotation matrices from rotation vectors (Rodrigues' formula).

    Parameters
    ----------
    vector : ndarray, shape (B, 3)
        Axis × angle (radians).

    Returns
    -------
    ndarray, shape (B, 3, 3)

    Examples
    --------
    >>> v = np.array([[0.3, -1.2, 2.0]])
    >>> np.allclose(rotation_vector(rotation_matrix(v)), v)
    True
    """
    angle = np.linalg.norm(vector, axis=-1)
    safe = np.where(angle > 0.0, angle, 1.0)
    u = vector / safe[:, np.newaxis]
    k = np.zeros((len(vector), 3, 3))
    k[:, 0, 1], k[:, 0, 2], k[:, 1, 2] = -u[:, 2], u[:, 1], -u[:, 0]
    k -= k.transpose(0, 2, 1)
    s = np.sin(angle)[:, np.newaxis, np.newaxis]
    c = (1.0 - np.cos(angle))[:, np.newaxis, np.newaxis]
    return np.eye(3) + s * k + c * (k @ k)
