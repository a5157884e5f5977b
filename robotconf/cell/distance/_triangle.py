"""The signed distance of a segment and a triangle, exact and vectorized.

A mesh is its triangles (a surface): its distance to a capsule is the least over them.

- **apart**: the least of the segment's ends to the triangle (projection onto the plane
  when it falls inside, else the nearest edge) and the segment to each edge — the
  minimum of the convex distance on a segment × triangle product lies on one of these
  boundary pieces unless the segment crosses the triangle (distance 0).
- **crossing**: the penetration depth of two convex polytopes is attained on a
  separating axis: the triangle's normal or ``d × e_k`` for its three edges; the signed
  distance is the largest interval separation over them (negative: the depth).
"""

from __future__ import annotations

import numpy as np

from ._box import interval_separation
from ._segments import dot, point_segment_distance, segment_segment_distance

__all__ = ["segment_triangle_distance", "point_triangle_distance"]


def _inside(p: np.ndarray, t0: np.ndarray, e1: np.ndarray, e2: np.ndarray) -> np.ndarray:
    """Whether each point's projection onto its triangle's plane falls inside it."""
    rel = p - t0
    d11, d12, d22 = dot(e1, e1), dot(e1, e2), dot(e2, e2)
    r1, r2 = dot(rel, e1), dot(rel, e2)
    area2 = d11 * d22 - d12 * d12
    safe = np.where(area2 > 0.0, area2, 1.0)
    u = (d22 * r1 - d12 * r2) / safe
    v = (d11 * r2 - d12 * r1) / safe
    return (area2 > 0.0) & (u >= 0.0) & (v >= 0.0) & (u + v <= 1.0)


def point_triangle_distance(p: np.ndarray, t0: np.ndarray, t1: np.ndarray, t2: np.ndarray):
    """Distance from points to triangles, shape (N,); all inputs (N, 3).

    Examples
    --------
    >>> tri = [np.array([[0.0, 0, 0]]), np.array([[1.0, 0, 0]]), np.array([[0.0, 1, 0]])]
    >>> point_triangle_distance(np.array([[0.2, 0.2, 3.0]]), *tri)
    array([3.])
    """
    e1, e2 = t1 - t0, t2 - t0
    normal = np.cross(e1, e2)
    area = np.sqrt(dot(normal, normal))
    plane = np.abs(dot(p - t0, normal)) / np.where(area > 0.0, area, 1.0)
    edges = np.minimum(
        point_segment_distance(p, t0, t1),
        np.minimum(point_segment_distance(p, t1, t2), point_segment_distance(p, t2, t0)),
    )
    return np.where(_inside(p, t0, e1, e2), np.minimum(plane, edges), edges)


def _crosses(a, b, t0, t1, t2) -> np.ndarray:
    """Whether the segment passes through the triangle from one side to the other."""
    e1, e2 = t1 - t0, t2 - t0
    normal = np.cross(e1, e2)
    sa, sb = dot(a - t0, normal), dot(b - t0, normal)
    opposite = sa * sb < 0.0
    t = np.where(opposite, sa / np.where(opposite, sa - sb, 1.0), 0.0)
    return opposite & _inside(a + t[:, None] * (b - a), t0, e1, e2)


def _separation(a, b, t0, t1, t2) -> np.ndarray:
    d = b - a
    corners = (t0, t1, t2)
    axes = [np.cross(t1 - t0, t2 - t0)]
    axes += [np.cross(d, corners[(k + 1) % 3] - corners[k]) for k in range(3)]
    best = np.full(a.shape[0], -np.inf)
    for axis in axes:
        norm = np.sqrt(dot(axis, axis))
        # Any direction's separation is a lower bound of the signed distance, so a
        # cross product of nearly parallel edges (a noisy direction) is harmless.
        usable = norm > 0.0
        unit = axis / np.where(norm > 0.0, norm, 1.0)[:, None]
        pa, pb = dot(unit, a), dot(unit, b)
        pt = np.stack([dot(unit, c) for c in corners], axis=1)
        sep = interval_separation(np.minimum(pa, pb), np.maximum(pa, pb), pt.min(1), pt.max(1))
        best = np.where(usable, np.maximum(best, sep), best)
    return best


def segment_triangle_distance(a, b, t0, t1, t2) -> np.ndarray:
    """Signed distance of segments and triangles, shape (N,); all inputs (N, 3).

    Returns the distance when apart and ``−`` the penetration depth when the segment
    crosses the triangle (the shortest translation that frees it).

    Examples
    --------
    >>> tri = [np.array([[0.0, 0, 0]]), np.array([[4.0, 0, 0]]), np.array([[0.0, 4, 0]])]
    >>> segment_triangle_distance(np.array([[1.0, 1, 1]]), np.array([[1.0, 1, 2]]), *tri)
    array([1.])
    >>> segment_triangle_distance(np.array([[1.0, 1, -0.5]]), np.array([[1.0, 1, 2]]), *tri)
    array([-0.5])
    """
    apart = np.minimum(
        np.minimum(point_triangle_distance(a, t0, t1, t2), point_triangle_distance(b, t0, t1, t2)),
        np.minimum(
            segment_segment_distance(a, b, t0, t1),
            np.minimum(
                segment_segment_distance(a, b, t1, t2), segment_segment_distance(a, b, t2, t0)
            ),
        ),
    )
    touching = (apart <= 0.0) | _crosses(a, b, t0, t1, t2)
    if not np.any(touching):
        return apart
    out = apart.copy()
    k = touching
    out[k] = np.minimum(_separation(a[k], b[k], t0[k], t1[k], t2[k]), 0.0)
    return out
