"""Distances of many capsules to the cell's objects and to each other, with a broad phase.

(See :func:`capsule_obstacle_distances` for the stages against objects.)

Exact distances (:mod:`._box`, :mod:`._cylinder`, :mod:`._triangle`, :mod:`._segments`)
cost tens of operations per pair; most pairs of a motion are far apart. So every pair
first meets cheap lower bounds of its signed distance — a box around each link over a
chunk of samples against a box around each object, the same per sample, then the
separation along the object's own axes (for two capsules: along the line through their
midpoints). Only pairs whose bound does not exceed the cutoff are measured exactly; the
others are reported as ``+inf`` ("farther than the cutoff"). The cutoff is a margin, or
each sample's least distance measured on its most promising pair (every sample's least
distance exact), or the motion's: the least exact distance over a few most promising
pairs and the pairs measured before (``known``), so only the motion's least distance is
exact. ``cell.check`` asks for that, and of the pairs in contact only when they are and
how deep each contact goes (:mod:`._contacts`), which prunes far more.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ._box import segment_box_distance
from ._cylinder import segment_cylinder_distance, segment_cylinder_lower_bound
from ._segments import point_segment_distance, segment_segment_distance
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


def _extent(item: Obstacle) -> np.ndarray:
    """Half sizes of an axis-aligned box around the object, about its pose's origin."""
    turn = item.pose[:3, :3]
    if item.kind == "box":
        return np.abs(turn) @ (0.5 * item.params)
    if item.kind == "cylinder":
        axis = turn[:, 2]
        return item.params[0] * np.sqrt(np.maximum(1.0 - axis**2, 0.0)) + 0.5 * item.params[
            1
        ] * np.abs(axis)
    if item.kind == "sphere":
        return np.full(3, item.params[0])
    corners = item.params.reshape(-1, 3)  # a mesh's triangles, already in the cell frame
    return np.maximum(
        corners.max(axis=0) - item.pose[:3, 3], item.pose[:3, 3] - corners.min(axis=0)
    )


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
        extent = np.array([_extent(o) for o in self.items]).reshape(count, 3)
        self.low = self.centers - extent  # axis-aligned boxes around each object (cell frame)
        self.high = self.centers + extent

    def __len__(self) -> int:
        return len(self.items)

    def _local(self, points: np.ndarray, index: np.ndarray) -> np.ndarray:
        return np.einsum("nji,nj->ni", self.rotations[index], points - self.centers[index])

    def lower_bound(self, a: np.ndarray, b: np.ndarray, r: np.ndarray, index: np.ndarray):
        """A cheap lower bound of each capsule's signed distance to objects ``index``, (N,).

        A box: the largest separation along its three face normals (the capsule spans
        ``|m_k| ± (|d_k|/2 + r)`` there); a cylinder: along its axis, and across it from
        the axis; a sphere: exact; a mesh: its bounding ball against the segment. Each is
        the separation along some direction, never more than the signed distance, and
        tight where a face is nearest — a long link over a large table, say.
        """
        la, lb = self._local(a, index), self._local(b, index)
        m = 0.5 * (la + lb)
        e = 0.5 * np.abs(lb - la)
        kinds = self.kinds[index]
        box = np.max(np.abs(m) - 0.5 * self._box[index] - e, axis=1)
        axial = np.abs(m[:, 2]) - 0.5 * self._cyl[index, 1] - e[:, 2]
        radial = np.hypot(m[:, 0], m[:, 1]) - self._cyl[index, 0] - np.hypot(e[:, 0], e[:, 1])
        ball = point_segment_distance(np.zeros(3), la, lb)
        out = np.select(
            [kinds == "box", kinds == "cylinder", kinds == "sphere"],
            [box, np.maximum(axial, radial), ball - self._sphere[index]],
            ball - self.bound[index],
        )
        return out - r

    def upper_bound(self, a: np.ndarray, b: np.ndarray, r: np.ndarray, index: np.ndarray):
        """A cheap upper bound of each capsule's signed distance to objects ``index``, (N,).

        The signed distance of one point of the segment (the one nearest the object's
        centre) to a box, cylinder or sphere, less the radius: a part of a body is never
        deeper in, nor farther from, a convex object than the whole. A mesh: ``inf``.
        """
        la, lb = self._local(a, index), self._local(b, index)
        d = lb - la
        length2 = np.einsum("nk,nk->n", d, d)
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.clip(-np.einsum("nk,nk->n", la, d) / length2, 0.0, 1.0)
        p = la + np.where(length2 > 0.0, t, 0.0)[:, None] * d
        kinds = self.kinds[index]
        q = np.abs(p) - 0.5 * self._box[index]
        box = np.sqrt(np.einsum("nk,nk->n", *(2 * (np.maximum(q, 0.0),)))) + np.minimum(
            q.max(axis=1), 0.0
        )
        across = np.hypot(p[:, 0], p[:, 1]) - self._cyl[index, 0]
        along = np.abs(p[:, 2]) - 0.5 * self._cyl[index, 1]
        cylinder = np.hypot(np.maximum(across, 0.0), np.maximum(along, 0.0)) + np.minimum(
            np.maximum(across, along), 0.0
        )
        ball = np.sqrt(np.einsum("nk,nk->n", p, p)) - self._sphere[index]
        out = np.select(
            [kinds == "box", kinds == "cylinder", kinds == "sphere"], [box, cylinder, ball], np.inf
        )
        return out - r

    def tighter_bound(self, a: np.ndarray, b: np.ndarray, r: np.ndarray, index: np.ndarray):
        """A lower bound dearer than :meth:`lower_bound`, (N,): a cylinder's without its
        band search (:func:`~._cylinder.segment_cylinder_lower_bound`); ``−inf`` else."""
        out = np.full(len(index), -np.inf)
        k = np.flatnonzero(self.kinds[index] == "cylinder")
        if len(k):
            obj = index[k]
            la, lb = self._local(a[k], obj), self._local(b[k], obj)
            out[k] = (
                segment_cylinder_lower_bound(la, lb, self._cyl[obj, 0], 0.5 * self._cyl[obj, 1])
                - r[k]
            )
        return out

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


def _box_separation(low: np.ndarray, high: np.ndarray, obstacles: Obstacles) -> np.ndarray:
    """Gaps between capsules' and objects' axis-aligned boxes, (M, O) (negative: overlap)."""
    out = np.maximum(
        low[:, None, 0] - obstacles.high[None, :, 0], obstacles.low[None, :, 0] - high[:, None, 0]
    )
    for k in (1, 2):
        np.maximum(out, low[:, None, k] - obstacles.high[None, :, k], out=out)
        np.maximum(out, obstacles.low[None, :, k] - high[:, None, k], out=out)
    return out


#: Samples per chunk of the first stage: a chunk's links are boxed over its samples.
CHUNK = 32

#: How many chunk pairs with the least bounds are measured first (every sample of them)
#: to set the cutoff of a whole-motion query.
PROBES = 4


def _chunk_boxes(low: np.ndarray, high: np.ndarray, size: int) -> tuple[np.ndarray, np.ndarray]:
    """Boxes around each link over each chunk of ``size`` samples: (chunks·L, 3) twice."""
    t, links = low.shape[:2]
    full = t // size
    parts_low = [low[: full * size].reshape(full, size, links * 3).min(axis=1)]
    parts_high = [high[: full * size].reshape(full, size, links * 3).max(axis=1)]
    if t > full * size:  # the last, shorter chunk
        parts_low.append(low[full * size :].reshape(-1, links * 3).min(axis=0, keepdims=True))
        parts_high.append(high[full * size :].reshape(-1, links * 3).max(axis=0, keepdims=True))
    return np.concatenate(parts_low).reshape(-1, 3), np.concatenate(parts_high).reshape(-1, 3)


def _expand(chunk_rows: np.ndarray, cols: np.ndarray, links: int, t: int):
    """(sample·L + link, object) of every sample of the chunk pairs (chunk·L + link, object)."""
    chunk, link = np.divmod(chunk_rows, links)
    sample = (chunk * CHUNK)[:, None] + np.arange(CHUNK)[None, :]
    inside = sample < t
    rows = (sample * links + link[:, None])[inside]
    return rows, np.broadcast_to(cols[:, None], sample.shape)[inside]


def capsule_obstacle_distances(
    segments: np.ndarray,
    radii: np.ndarray,
    obstacles: Obstacles,
    margin: float = -np.inf,
    per_sample: bool = True,
    skip: np.ndarray | None = None,
    known: float = np.inf,
) -> np.ndarray:
    """Signed distances of capsules to objects, shape (T, L, O); ``inf`` where pruned.

    Four stages, each a lower bound of the signed distance: the gap between a box around
    each link over :data:`CHUNK` samples and a box around each object (a few comparisons
    per chunk, link and object), the same per sample for the pairs left, the separation
    along each object's own axes (:meth:`Obstacles.lower_bound`), and the exact distance
    for the pairs whose bounds do not exceed the cutoff.

    Parameters
    ----------
    segments : ndarray, shape (T, L, 2, 3)
        Capsule ends in the cell's frame.
    radii : ndarray, shape (L,)
    obstacles : Obstacles
    margin : float
        Pairs closer than ``margin`` are always measured exactly.
    per_sample : bool
        True: each sample's cutoff is ``max(margin, d)`` with ``d`` the exact distance of
        its chunk's most promising pair, so every sample's least distance is exact.
        False: one cutoff, ``max(margin, U)`` with U the least exact distance over the
        :data:`PROBES` most promising chunk pairs (and ``known``), so only the motion's
        least distance is exact; of the pairs closer than ``margin``, each contact's
        deepest sample is exact and the others may hold an upper bound below ``margin``
        (:func:`~._contacts.contacts_sparingly`).
    skip : ndarray of bool, shape (L, O), optional
        Pairs never measured (``inf``): a robot's base links and what it stands on.
    known : float
        With ``per_sample`` False: a distance already measured elsewhere in the motion
        (other pairs'), so pairs provably farther than it cannot hold the least one.
    """
    t, links = segments.shape[:2]
    count = len(obstacles)
    out = np.full((t, links, count), np.inf)
    if not count or not t:
        return out
    flat_a = segments[..., 0, :].reshape(-1, 3)
    flat_b = segments[..., 1, :].reshape(-1, 3)
    r = np.broadcast_to(radii, (t, links)).reshape(-1)
    low = np.minimum(flat_a, flat_b) - r[:, None]
    high = np.maximum(flat_a, flat_b) + r[:, None]
    chunk_low, chunk_high = _chunk_boxes(low.reshape(t, links, 3), high.reshape(t, links, 3), CHUNK)
    coarse = _box_separation(chunk_low, chunk_high, obstacles)  # (chunks·L, O)
    if skip is not None:
        coarse[np.tile(skip, (len(coarse) // links, 1))] = np.inf
    chunks = len(coarse) // links
    per_chunk = coarse.reshape(chunks, links * count)
    if per_sample:
        best = np.argmin(per_chunk, axis=1)
        usable = np.isfinite(per_chunk[np.arange(chunks), best])
        rows, cols = _expand(
            (np.arange(chunks) * links + best // count)[usable], (best % count)[usable], links, t
        )
        measured = np.full(t, np.inf)
        measured[rows // links] = obstacles.exact(flat_a[rows], flat_b[rows], r[rows], cols)
        limit = np.maximum(measured, margin)
    else:
        order = np.argsort(coarse.ravel())[:PROBES]
        order = order[np.isfinite(coarse.ravel()[order])]
        rows, cols = _expand(order // count, order % count, links, t)
        found = obstacles.exact(flat_a[rows], flat_b[rows], r[rows], cols)
        limit = np.full(t, max(float(np.min(found, initial=known)), margin))
    # The bounds and the exact distance round differently: a bound equal to the cutoff
    # may come out a few ulps above it, so every stage allows the round-off of the scene.
    size = max(
        float(np.abs(low).max()),
        float(np.abs(high).max()),
        float(np.abs(obstacles.low).max()),
        float(np.abs(obstacles.high).max()),
    )
    with np.errstate(invalid="ignore"):
        limit = np.where(
            np.isfinite(limit), limit + 64.0 * _EPS * (1.0 + size + np.abs(limit)), limit
        )
    padded = np.concatenate([limit, np.full(chunks * CHUNK - t, -np.inf)])
    chunk_limit = np.repeat(padded.reshape(chunks, CHUNK).max(axis=1), links)
    chunk_rows, cols = np.nonzero(coarse <= chunk_limit[:, None])
    rows, cols = _expand(chunk_rows, cols, links, t)
    if not len(rows):
        return out
    sample_limit = limit[rows // links]
    gap = np.maximum(low[rows] - obstacles.high[cols], obstacles.low[cols] - high[rows]).max(axis=1)
    keep = gap <= sample_limit
    rows, cols, sample_limit = rows[keep], cols[keep], sample_limit[keep]
    bound = obstacles.lower_bound(flat_a[rows], flat_b[rows], r[rows], cols)
    keep = bound <= sample_limit
    rows, cols = rows[keep], cols[keep]
    if per_sample or not np.isfinite(margin):
        exact = obstacles.exact(flat_a[rows], flat_b[rows], r[rows], cols)
    else:
        # Imported here: the contacts' stage takes an Obstacles, so at module level the two
        # files would import each other.
        from ._contacts import contacts_sparingly

        tolerance = 64.0 * _EPS * (1.0 + size + abs(margin))
        exact = contacts_sparingly(
            obstacles,
            (flat_a[rows], flat_b[rows], r[rows]),
            rows,
            cols,
            bound[keep],
            sample_limit[keep],
            links,
            margin,
            tolerance,
        )
    out.reshape(-1, count)[rows, cols] = exact
    return out


def capsule_pair_distances(
    first: np.ndarray,
    first_radii: np.ndarray,
    second: np.ndarray,
    second_radii: np.ndarray,
    pairs: np.ndarray | None = None,
    margin: float = -np.inf,
    per_sample: bool = True,
    known: float = np.inf,
) -> np.ndarray:
    """Signed distances between two sets of capsules per sample; ``inf`` where pruned.

    Parameters
    ----------
    first, second : ndarray, shape (T, L1, 2, 3) and (T, L2, 2, 3)
    first_radii, second_radii : ndarray, shapes (L1,), (L2,)
    pairs : ndarray of int, shape (P, 2), optional
        Only these (i, j); the result is then (T, P), else (T, L1, L2).
    margin, per_sample, known
        As for :func:`capsule_obstacle_distances`.
    """
    t = first.shape[0]
    if pairs is None:
        grid = np.indices((first.shape[1], second.shape[1])).reshape(2, -1).T
        return capsule_pair_distances(
            first, first_radii, second, second_radii, grid, margin, per_sample, known
        ).reshape(t, first.shape[1], second.shape[1])
    out = np.full((t, len(pairs)), np.inf)
    if not len(pairs) or not t:
        return out
    i, j = pairs[:, 0], pairs[:, 1]
    r = first_radii[i] + second_radii[j]

    def boxes(caps: np.ndarray, radii: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        grow = radii[None, :, None]
        a, b = caps[:, :, 0], caps[:, :, 1]
        return np.minimum(a, b) - grow, np.maximum(a, b) + grow  # (T, L, 3) each

    low1, high1 = boxes(first, first_radii)
    chunk_low1, chunk_high1 = _chunk_boxes(low1, high1, CHUNK)
    if second is first and second_radii is first_radii:  # a robot's own pairs
        low2, high2, chunk_low2, chunk_high2 = low1, high1, chunk_low1, chunk_high1
    else:
        low2, high2 = boxes(second, second_radii)
        chunk_low2, chunk_high2 = _chunk_boxes(low2, high2, CHUNK)
    chunks = len(chunk_low1) // first.shape[1]
    c1 = np.arange(chunks)[:, None] * first.shape[1] + i[None, :]
    c2 = np.arange(chunks)[:, None] * second.shape[1] + j[None, :]
    coarse = np.maximum(chunk_low1[c1] - chunk_high2[c2], chunk_low2[c2] - chunk_high1[c1]).max(
        axis=2
    )

    def exact(sample: np.ndarray, pair: np.ndarray) -> np.ndarray:
        p1, p2 = first[sample, i[pair]], second[sample, j[pair]]
        return segment_segment_distance(p1[:, 0], p1[:, 1], p2[:, 0], p2[:, 1]) - r[pair]

    def expand(chunk: np.ndarray, pair: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        sample = (chunk * CHUNK)[:, None] + np.arange(CHUNK)[None, :]
        inside = sample < t
        return sample[inside], np.broadcast_to(pair[:, None], sample.shape)[inside]

    if per_sample:
        best = np.argmin(coarse, axis=1)
        sample, pair = expand(np.arange(chunks), best)
        limit = np.full(t, np.inf)
        limit[sample] = exact(sample, pair)
        limit = np.maximum(limit, margin)
    else:
        order = np.argsort(coarse.ravel())[:PROBES]
        sample, pair = expand(*np.divmod(order, len(pairs)))
        limit = np.full(t, max(float(exact(sample, pair).min(initial=known)), margin))
    size = max(
        float(np.abs(low1).max()),
        float(np.abs(high1).max()),
        float(np.abs(low2).max()),
        float(np.abs(high2).max()),
    )
    limit = limit + 64.0 * _EPS * (1.0 + size + np.abs(limit))
    padded = np.concatenate([limit, np.full(chunks * CHUNK - t, -np.inf)])
    chunk, pair = np.nonzero(coarse <= padded.reshape(chunks, CHUNK).max(axis=1)[:, None])
    sample, pair = expand(chunk, pair)
    gap = np.maximum(
        low1[sample, i[pair]] - high2[sample, j[pair]],
        low2[sample, j[pair]] - high1[sample, i[pair]],
    ).max(axis=1)
    keep = gap <= limit[sample]
    sample, pair = sample[keep], pair[keep]
    keep = _axis_separation(first[sample, i[pair]], second[sample, j[pair]], r[pair])
    keep = keep <= limit[sample]
    sample, pair = sample[keep], pair[keep]
    out[sample, pair] = exact(sample, pair)
    return out


def _axis_separation(first: np.ndarray, second: np.ndarray, radii: np.ndarray) -> np.ndarray:
    """A lower bound of capsule pairs' signed distances, (N,), for segments (N, 2, 3) twice.

    Their separation along two axes, the larger: the line through the segments'
    midpoints, and the common normal ``d1 × d2`` (the distance itself when the nearest
    points lie inside both segments). Along an axis ``u`` the capsules span
    ``m·u ± (|d·u|/2 + r)``. Tighter than boxes for links side by side at a slant, as a
    robot's wrist links are; ``−inf`` along an axis of length 0.
    """
    d1, d2 = first[:, 1] - first[:, 0], second[:, 1] - second[:, 0]
    between = 0.5 * (second[:, 0] + second[:, 1] - first[:, 0] - first[:, 1])

    def along(axis: np.ndarray) -> np.ndarray:
        length = np.sqrt(np.einsum("nk,nk->n", axis, axis))
        gap = np.abs(np.einsum("nk,nk->n", between, axis)) - 0.5 * (
            np.abs(np.einsum("nk,nk->n", d1, axis)) + np.abs(np.einsum("nk,nk->n", d2, axis))
        )
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(length > 0.0, gap / length, -np.inf)

    return np.maximum(along(between), along(np.cross(d1, d2))) - radii
