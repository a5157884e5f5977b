"""Distances of many capsules to the cell's objects and to each other, with a broad phase.

Exact distances (:mod:`._box`, :mod:`._cylinder`, :mod:`._triangle`, :mod:`._segments`)
cost tens of operations per pair; most pairs of a motion are far apart. So every pair
first gets cheap bounds from bounding balls — the capsule's ball about its midpoint
(half its length plus its radius) and the object's ball about its centre:

    lower bound  |m − c| − (ℓ/2 + r) − R_out   ≤ sd ≤   |m − c| + ℓ/2 − r − R_in   upper bound

(``R_in``: a ball about the centre inside the object; for a mesh ``−R_out``). The centre
distances of all pairs come from one matrix product. Only pairs whose lower bound does not
exceed the cutoff are measured exactly; the others are reported as ``+inf`` ("farther
than the cutoff"). The cutoff is a margin, or the least upper bound of each sample (every
sample's least distance exact), or of the whole motion (only its least distance exact:
``cell.check`` asks for contacts and the motion's least clearance, which prunes far more).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ._box import segment_box_distance
from ._cylinder import segment_cylinder_distance
from ._segments import dot, point_segment_distance, segment_segment_distance
from ._triangle import segment_triangle_distance

__all__ = ["Obstacle", "Obstacles", "capsule_obstacle_distances", "capsule_pair_distances"]

_EPS = np.finfo(float).eps


@dataclass(frozen=True)
class Obstacle:
    """One object in the cell's frame: its kind, world pose and size numbers.

    ``params``: box half edge lengths (3,); cylinder (radius, half length); sphere
    (radius,); mesh: its triangles in the cell's frame (F, 3, 3).
    """

    kind: str
    pose: np.ndarray
    params: np.ndarray
    bound: float
    inner: float


class Obstacles:
    """The objects of a cell, arranged for vectorized queries."""

    def __init__(self, items: Sequence[Obstacle]):
        self.items = tuple(items)
        count = len(self.items)
        self.centers = np.array([o.pose[:3, 3] for o in self.items]).reshape(count, 3)
        self.bound = np.array([o.bound for o in self.items])
        self.inner = np.array([o.inner for o in self.items])
        self.kinds = np.array([o.kind for o in self.items])
        self.rotations = np.array([o.pose[:3, :3] for o in self.items]).reshape(count, 3, 3)
        self._box = np.array(
            [o.params if o.kind == "box" else np.zeros(3) for o in self.items]
        ).reshape(count, 3)
        self._cyl = np.array(
            [o.params if o.kind == "cylinder" else np.zeros(2) for o in self.items]
        ).reshape(count, 2)
        self._sphere = np.array([o.params[0] if o.kind == "sphere" else 0.0 for o in self.items])

    def __len__(self) -> int:
        return len(self.items)

    def _local(self, points: np.ndarray, index: np.ndarray) -> np.ndarray:
        return np.einsum("nji,nj->ni", self.rotations[index], points - self.centers[index])

    def exact(self, a: np.ndarray, b: np.ndarray, r: np.ndarray, index: np.ndarray) -> np.ndarray:
        """Signed distances of capsules (a, b, r) to objects ``index``, shape (N,)."""
        out = np.empty(len(index))
        for kind in np.unique(self.kinds[index]) if len(index) else ():
            k = self.kinds[index] == kind
            obj = index[k]
            if kind == "mesh":
                out[k] = self._mesh(a[k], b[k], obj)
                continue
            la, lb = self._local(a[k], obj), self._local(b[k], obj)
            if kind == "box":
                out[k] = segment_box_distance(la, lb, 0.5 * self._box[obj])
            elif kind == "cylinder":
                out[k] = segment_cylinder_distance(
                    la, lb, self._cyl[obj, 0], 0.5 * self._cyl[obj, 1]
                )
            else:
                out[k] = point_segment_distance(np.zeros(3), la, lb) - self._sphere[obj]
        return out - r

    def _mesh(self, a: np.ndarray, b: np.ndarray, obj: np.ndarray) -> np.ndarray:
        out = np.full(len(obj), np.inf)
        for o in np.unique(obj):
            rows = np.flatnonzero(obj == o)
            tri = self.items[o].params  # (F, 3, 3) in the cell frame
            centre = tri.mean(axis=1)
            reach = np.linalg.norm(tri - centre[:, None], axis=2).max(axis=1)
            mid = 0.5 * (a[rows] + b[rows])
            half = 0.5 * np.linalg.norm(b[rows] - a[rows], axis=1)
            gap = np.linalg.norm(mid[:, None] - centre[None], axis=2)
            lower = gap - half[:, None] - reach[None]
            upper = gap + half[:, None] + reach[None]
            keep = lower <= upper.min(axis=1, keepdims=True)
            pr, pt = np.nonzero(keep)
            exact = segment_triangle_distance(
                a[rows][pr], b[rows][pr], tri[pt, 0], tri[pt, 1], tri[pt, 2]
            )
            best = np.full(len(rows), np.inf)
            np.minimum.at(best, pr, exact)
            out[rows] = best
        return out


def _centre_distance(m: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """|m_i − c_j| for all pairs via one matrix product, and its round-off bound."""
    mm = dot(m, m)[..., :, None]
    cc = dot(c, c)[..., None, :]
    squared = mm + cc - 2.0 * (m @ np.swapaxes(c, -1, -2))
    slack = 4.0 * np.sqrt(_EPS * (mm + cc))
    return np.sqrt(np.maximum(squared, 0.0)), slack


def capsule_obstacle_distances(
    segments: np.ndarray,
    radii: np.ndarray,
    obstacles: Obstacles,
    margin: float = -np.inf,
    per_sample: bool = True,
) -> np.ndarray:
    """Signed distances of capsules to objects, shape (T, L, O); ``inf`` where pruned.

    Parameters
    ----------
    segments : ndarray, shape (T, L, 2, 3)
        Capsule ends in the cell's frame.
    radii : ndarray, shape (L,)
    obstacles : Obstacles
    margin : float
        Pairs are measured exactly when their lower bound is at most
        ``max(margin, least upper bound of their sample)``: every sample's least
        distance is exact, and so is every pair closer than ``margin``.
    per_sample : bool
        False: the least upper bound over all samples instead, so only the least
        distance of the whole motion (and pairs closer than ``margin``) is exact.
    """
    t, links = segments.shape[:2]
    out = np.full((t, links, len(obstacles)), np.inf)
    if not len(obstacles):
        return out
    a, b = segments[..., 0, :], segments[..., 1, :]
    mid = 0.5 * (a + b).reshape(-1, 3)
    half = 0.5 * np.sqrt(dot(b - a, b - a)).reshape(-1)
    r = np.broadcast_to(radii, (t, links)).reshape(-1)
    gap, slack = _centre_distance(mid, obstacles.centers)
    upper = (gap + slack + half[:, None] - r[:, None] - obstacles.inner[None]).reshape(t, -1)
    cutoff = np.maximum(upper.min(axis=1) if per_sample else np.full(t, upper.min()), margin)
    lower = gap - slack - (half + r)[:, None] - obstacles.bound[None]
    limit = np.repeat(cutoff, links)
    rows, cols = np.nonzero(lower <= limit[:, None])
    if len(rows):
        flat_a, flat_b = a.reshape(-1, 3), b.reshape(-1, 3)
        # Second stage: the segment itself (not its ball) against the object's ball.
        near = point_segment_distance(obstacles.centers[cols], flat_a[rows], flat_b[rows])
        keep = near - r[rows] - obstacles.bound[cols] <= limit[rows] + 4.0 * _EPS * (1.0 + near)
        rows, cols = rows[keep], cols[keep]
        out.reshape(-1, len(obstacles))[rows, cols] = obstacles.exact(
            flat_a[rows], flat_b[rows], r[rows], cols
        )
    return out


def capsule_pair_distances(
    first: np.ndarray,
    first_radii: np.ndarray,
    second: np.ndarray,
    second_radii: np.ndarray,
    pairs: np.ndarray | None = None,
    margin: float = -np.inf,
    per_sample: bool = True,
) -> np.ndarray:
    """Signed distances between two sets of capsules per sample; ``inf`` where pruned.

    Parameters
    ----------
    first, second : ndarray, shape (T, L1, 2, 3) and (T, L2, 2, 3)
    first_radii, second_radii : ndarray, shapes (L1,), (L2,)
    pairs : ndarray of int, shape (P, 2), optional
        Only these (i, j); the result is then (T, P), else (T, L1, L2).
    margin, per_sample
        As for :func:`capsule_obstacle_distances`.
    """
    t = first.shape[0]
    if pairs is None:
        grid = np.indices((first.shape[1], second.shape[1])).reshape(2, -1).T
        return capsule_pair_distances(
            first, first_radii, second, second_radii, grid, margin, per_sample
        ).reshape(t, first.shape[1], second.shape[1])
    out = np.full((t, len(pairs)), np.inf)
    if not len(pairs):
        return out
    i, j = pairs[:, 0], pairs[:, 1]
    a1, b1 = first[:, i, 0], first[:, i, 1]
    a2, b2 = second[:, j, 0], second[:, j, 1]
    r = first_radii[i] + second_radii[j]
    gap = np.sqrt(dot(0.5 * (a1 + b1 - a2 - b2), 0.5 * (a1 + b1 - a2 - b2)))
    h1, h2 = 0.5 * np.sqrt(dot(b1 - a1, b1 - a1)), 0.5 * np.sqrt(dot(b2 - a2, b2 - a2))
    upper = gap + h1 + h2 - r
    lower = gap - h1 - h2 - r
    cutoff = np.maximum(upper.min(axis=1) if per_sample else np.full(t, upper.min()), margin)
    rows, cols = np.nonzero(lower <= cutoff[:, None])
    if len(rows):
        out[rows, cols] = (
            segment_segment_distance(a1[rows, cols], b1[rows, cols], a2[rows, cols], b2[rows, cols])
            - r[cols]
        )
    return out
