"""Placing unit shapes in the 3D scene: position, orientation and scale of each drawn item.

Every shape is drawn once at unit size along three.js's y axis (its cylinders' axis) and
then moved by a transform ``T(position) · R · S(scale)``. These helpers turn points and
directions that the core computed into such transforms; they hold no kinematics, only the
drawing convention.
"""

from __future__ import annotations

import numpy as np

__all__ = ["Placement", "align_y", "compose", "quaternions"]


class Placement:
    """Positions (…, 3), rotations (…, 3, 3) and scales (…, 3) of drawn items.

    Parameters
    ----------
    position : ndarray, shape (..., 3)
    rotation : ndarray, shape (..., 3, 3)
    scale : ndarray, shape (..., 3)
    """

    __slots__ = ("position", "rotation", "scale")

    def __init__(self, position: np.ndarray, rotation: np.ndarray, scale: np.ndarray) -> None:
        self.position = position
        self.rotation = rotation
        self.scale = scale

    def matrices(self) -> np.ndarray:
        """Homogeneous 4×4 transforms, shape (..., 4, 4)."""
        return compose(self.position, self.rotation, self.scale)


def align_y(direction: np.ndarray) -> np.ndarray:
    """Rotations that turn the y axis onto unit ``direction`` (…, 3) → (…, 3, 3).

    The shortest-arc rotation (Rodrigues' formula about ``y × d``) for ``d`` in the upper
    half (``d_y ≥ 0``); below, the shortest arc onto ``−d`` followed by a half turn about
    x, so the formula never divides by ``1 + d_y`` near zero and stays orthonormal to
    rounding next to ``−y``. NaN or zero directions give the identity.

    Examples
    --------
    >>> align_y(np.array([1.0, 0.0, 0.0])).round(12) @ [0, 1, 0]
    array([1., 0., 0.])
    >>> align_y(np.array([1e-9, -1.0, 0.0])) @ [0, 1, 0]
    array([ 1.e-09, -1.e+00,  0.e+00])
    """
    d = np.nan_to_num(np.asarray(direction, dtype=float))
    norm = np.linalg.norm(d, axis=-1, keepdims=True)
    d = np.where(norm > 0, d / np.where(norm > 0, norm, 1.0), [0.0, 1.0, 0.0])
    lower = d[..., 1] < 0
    # Work with e = ±d in the upper half: 1 + e_y ≥ 1, no cancellation anywhere.
    e = np.where(lower[..., None], -d, d)
    x, c, z = e[..., 0], e[..., 1], e[..., 2]
    # y × e = (z, 0, −x); cos θ = e_y; Rodrigues with k = (z, 0, −x)/sin θ folded in.
    factor = 1.0 / (1.0 + c)
    out = np.empty(d.shape[:-1] + (3, 3))
    out[..., 0, 0] = c + z * z * factor
    out[..., 0, 1] = x
    out[..., 0, 2] = -x * z * factor
    out[..., 1, 0] = -x
    out[..., 1, 1] = c
    out[..., 1, 2] = -z
    out[..., 2, 0] = -x * z * factor
    out[..., 2, 1] = z
    out[..., 2, 2] = c + x * x * factor
    # R(d) = R(−d) · Rx(π): Rx(π) turns y onto −y, R(−d) turns −y onto d.
    out[..., :, 1:] = np.where(lower[..., None, None], -out[..., :, 1:], out[..., :, 1:])
    return out


def compose(position: np.ndarray, rotation: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """``T(position) · R · S(scale)`` as 4×4 matrices, shape (..., 4, 4).

    Examples
    --------
    >>> compose(np.array([1.0, 2, 3]), np.eye(3), np.array([2.0, 2, 2]))[:3]
    array([[2., 0., 0., 1.],
           [0., 2., 0., 2.],
           [0., 0., 2., 3.]])
    """
    out = np.zeros(position.shape[:-1] + (4, 4))
    out[..., :3, :3] = rotation * scale[..., None, :]
    out[..., :3, 3] = position
    out[..., 3, 3] = 1.0
    return out


def quaternions(rotation: np.ndarray) -> np.ndarray:
    """Unit quaternions ``(x, y, z, w)`` (three.js order) of rotations (…, 3, 3).

    Shepperd's method: pick the largest of ``w, x, y, z`` to divide by, so no branch
    loses precision.

    Examples
    --------
    >>> quaternions(np.eye(3))
    array([0., 0., 0., 1.])
    """
    r = np.asarray(rotation, dtype=float)
    m00, m11, m22 = r[..., 0, 0], r[..., 1, 1], r[..., 2, 2]
    candidates = np.stack(
        [1 + m00 + m11 + m22, 1 + m00 - m11 - m22, 1 - m00 + m11 - m22, 1 - m00 - m11 + m22],
        axis=-1,
    )
    pick = np.argmax(candidates, axis=-1)
    root = np.sqrt(np.maximum(np.take_along_axis(candidates, pick[..., None], -1)[..., 0], 1e-300))
    half = 0.5 / root
    w = np.select(
        [pick == 0, pick == 1, pick == 2],
        [0.5 * root, (r[..., 2, 1] - r[..., 1, 2]) * half, (r[..., 0, 2] - r[..., 2, 0]) * half],
        (r[..., 1, 0] - r[..., 0, 1]) * half,
    )
    x = np.select(
        [pick == 0, pick == 1, pick == 2],
        [(r[..., 2, 1] - r[..., 1, 2]) * half, 0.5 * root, (r[..., 0, 1] + r[..., 1, 0]) * half],
        (r[..., 0, 2] + r[..., 2, 0]) * half,
    )
    y = np.select(
        [pick == 0, pick == 1, pick == 2],
        [(r[..., 0, 2] - r[..., 2, 0]) * half, (r[..., 0, 1] + r[..., 1, 0]) * half, 0.5 * root],
        (r[..., 1, 2] + r[..., 2, 1]) * half,
    )
    z = np.select(
        [pick == 0, pick == 1, pick == 2],
        [
            (r[..., 1, 0] - r[..., 0, 1]) * half,
            (r[..., 0, 2] + r[..., 2, 0]) * half,
            (r[..., 1, 2] + r[..., 2, 1]) * half,
        ],
        0.5 * root,
    )
    return np.stack([x, y, z, w], axis=-1)
