"""Closest distances between points and segments, vectorized over leading axes.

A capsule is a segment swept by a ball, so every distance of the cell starts here: the
signed distance of two capsules is the distance of their segments minus both radii.
"""

from __future__ import annotations

import numpy as np

__all__ = ["point_segment_distance", "segment_segment_distance", "dot"]


def dot(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``Σ u_k v_k`` over the last axis (shape ``(...)``)."""
    return np.einsum("...k,...k->...", u, v)


def point_segment_distance(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distance from points ``p`` to the segments ``a–b``, shape ``(...)``.

    Parameters
    ----------
    p, a, b : ndarray, shape (..., 3)
        Points and segment ends (broadcast); a segment may have ``a == b`` (a point).

    Examples
    --------
    >>> p = np.array([[0.0, 1, 0], [3.0, 0, 0]])
    >>> point_segment_distance(p, np.zeros(3), np.array([2.0, 0, 0]))
    array([1., 1.])
    """
    d = b - a
    length2 = dot(d, d)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(length2 > 0.0, dot(p - a, d) / np.where(length2 > 0.0, length2, 1.0), 0.0)
    t = np.clip(t, 0.0, 1.0)
    gap = p - (a + t[..., np.newaxis] * d)
    return np.sqrt(dot(gap, gap))


def segment_segment_distance(
    a1: np.ndarray, b1: np.ndarray, a2: np.ndarray, b2: np.ndarray
) -> np.ndarray:
    """Distance between segments ``a1–b1`` and ``a2–b2``, shape ``(...)``.

    The squared distance of ``a1 + s·d1`` and ``a2 + t·d2`` is a convex quadratic on the
    square ``0 ≤ s, t ≤ 1``: its minimum is the critical point when that lies inside, or
    else on an edge of the square, where one parameter is 0 or 1 and the distance is a
    point–segment distance. All five candidates are measured directly and the least kept,
    so nearly parallel segments (an ill-conditioned critical point) lose nothing: a
    poorly placed interior candidate can only be an overestimate.

    Examples
    --------
    >>> a1, b1 = np.array([[0.0, 0, 0]]), np.array([[2.0, 0, 0]])
    >>> a2, b2 = np.array([[1.0, -1, 1]]), np.array([[1.0, 1, 1]])
    >>> segment_segment_distance(a1, b1, a2, b2)  # crossing 1 apart
    array([1.])
    """
    d1 = b1 - a1
    d2 = b2 - a2
    r = a1 - a2
    aa = dot(d1, d1)
    ee = dot(d2, d2)
    bb = dot(d1, d2)
    c = dot(d1, r)
    f = dot(d2, r)
    denom = aa * ee - bb * bb
    ok = denom > 1e-14 * np.maximum(aa * ee, np.finfo(float).tiny)
    safe = np.where(ok, denom, 1.0)
    s = (bb * f - c * ee) / safe
    t = (aa * f - bb * c) / safe
    inside = ok & (s > 0.0) & (s < 1.0) & (t > 0.0) & (t < 1.0)
    gap = (a1 + s[..., np.newaxis] * d1) - (a2 + t[..., np.newaxis] * d2)
    interior = np.where(inside, np.sqrt(dot(gap, gap)), np.inf)
    edges = np.minimum(
        np.minimum(point_segment_distance(a1, a2, b2), point_segment_distance(b1, a2, b2)),
        np.minimum(point_segment_distance(a2, a1, b1), point_segment_distance(b2, a1, b1)),
    )
    return np.minimum(interior, edges)
