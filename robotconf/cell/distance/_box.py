"""The signed distance of a segment and a box, exact and vectorized.

In the box's own frame (centred, axes along its edges, half edge lengths ``h``):

- **apart**: the squared distance of ``p(t) = a + t·d`` to the box,
  ``f(t) = Σ_k max(|p_k(t)| − h_k, 0)²``, is convex and piecewise quadratic, with at
  most six breakpoints where ``|p_k(t)| = h_k``. On each piece the minimum is a clamped
  closed form; the least over the pieces (measured with the true ``f``) is the distance.
- **overlapping**: the penetration depth of two convex polytopes is attained on a
  separating-axis direction: a face normal of either shape or the cross product of an
  edge of each. A segment has no face and one edge, so the axes are the box's three
  face normals and ``d × e_k``; the signed distance is the largest separation
  ``max(lo_seg − hi_box, lo_box − hi_seg)`` over them (negative: the depth).
"""

from __future__ import annotations

import numpy as np

from ._segments import dot

__all__ = ["segment_box_distance", "interval_separation"]


def interval_separation(lo1: np.ndarray, hi1: np.ndarray, lo2: np.ndarray, hi2: np.ndarray):
    """Signed gap between intervals ``[lo1, hi1]`` and ``[lo2, hi2]`` (negative: overlap)."""
    return np.maximum(lo1 - hi2, lo2 - hi1)


def _squared_gap(p: np.ndarray, h: np.ndarray) -> np.ndarray:
    out = np.maximum(np.abs(p) - h, 0.0)
    return dot(out, out)


def _apart(a: np.ndarray, d: np.ndarray, h: np.ndarray) -> np.ndarray:
    """Distance of the segments ``a + t·d`` (0 ≤ t ≤ 1) to the boxes, shape (N,)."""
    n = a.shape[0]
    with np.errstate(divide="ignore", invalid="ignore"):
        cuts = np.concatenate([(h - a) / d, (-h - a) / d], axis=1)
    cuts = np.where(np.isfinite(cuts), np.clip(cuts, 0.0, 1.0), 0.0)
    knots = np.sort(np.concatenate([np.zeros((n, 1)), cuts, np.ones((n, 1))], axis=1), axis=1)
    lo, hi = knots[:, :-1], knots[:, 1:]  # (N, 7) pieces
    mid = 0.5 * (lo + hi)
    p_mid = a[:, np.newaxis, :] + mid[..., np.newaxis] * d[:, np.newaxis, :]
    sign = np.sign(p_mid)
    active = np.abs(p_mid) > h[:, np.newaxis, :]
    # On a piece, f(t) = Σ_active (s_k a_k − h_k + t s_k d_k)²: minimum at t*.
    c0 = np.where(active, sign * a[:, np.newaxis, :] - h[:, np.newaxis, :], 0.0)
    c1 = np.where(active, sign * d[:, np.newaxis, :], 0.0)
    curvature = np.sum(c1 * c1, axis=2)
    with np.errstate(divide="ignore", invalid="ignore"):
        t_star = np.where(curvature > 0.0, -np.sum(c0 * c1, axis=2) / curvature, mid)
    t_star = np.clip(np.nan_to_num(t_star, nan=0.0), lo, hi)
    points = a[:, np.newaxis, :] + t_star[..., np.newaxis] * d[:, np.newaxis, :]
    best = np.min(_squared_gap(points, h[:, np.newaxis, :]), axis=1)
    ends = np.minimum(_squared_gap(a, h), _squared_gap(a + d, h))
    return np.sqrt(np.minimum(best, ends))


def _overlap(a: np.ndarray, b: np.ndarray, h: np.ndarray) -> np.ndarray:
    """Largest separation over the separating axes (−penetration depth when overlapping)."""
    d = b - a
    eye = np.eye(3)
    axes = [np.broadcast_to(eye[k], a.shape) for k in range(3)]
    length = np.sqrt(dot(d, d))
    for k in range(3):
        axis = np.cross(d, eye[k])
        norm = np.sqrt(dot(axis, axis))
        usable = norm > 1e-12 * np.maximum(length, np.finfo(float).tiny)
        axes.append(
            np.where(usable[:, np.newaxis], axis / np.where(usable, norm, 1.0)[:, np.newaxis], 0.0)
        )
    best = np.full(a.shape[0], -np.inf)
    for axis in axes:
        pa, pb = dot(axis, a), dot(axis, b)
        reach = dot(np.abs(axis), h)
        sep = interval_separation(np.minimum(pa, pb), np.maximum(pa, pb), -reach, reach)
        usable = dot(axis, axis) > 0.0
        best = np.where(usable, np.maximum(best, sep), best)
    return best


def segment_box_distance(a: np.ndarray, b: np.ndarray, half: np.ndarray) -> np.ndarray:
    """Signed distance of segments and centred, axis-aligned boxes, shape (N,).

    Parameters
    ----------
    a, b : ndarray, shape (N, 3)
        Segment ends in each box's frame.
    half : ndarray, shape (N, 3)
        Half edge lengths (> 0).

    Returns
    -------
    ndarray, shape (N,)
        Distance when apart, ``−`` the penetration depth when the segment enters the box
        (the shortest translation of the segment that clears the box).

    Examples
    --------
    >>> h = np.ones((1, 3))
    >>> segment_box_distance(np.array([[2.0, 0, 0]]), np.array([[3.0, 0, 0]]), h)
    array([1.])
    >>> segment_box_distance(np.array([[-2.0, 0.5, 0]]), np.array([[2.0, 0.5, 0]]), h)
    array([-0.5])
    """
    apart = _apart(a, b - a, half)
    inside = apart <= 0.0
    if not np.any(inside):
        return apart
    out = apart.copy()
    out[inside] = _overlap(a[inside], b[inside], half[inside])
    return out
