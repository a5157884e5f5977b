"""Contacts along a motion with few exact distances: only where a contact may be deepest.

``cell.check`` needs, of the pairs in contact (closer than the margin), only which
samples they are in contact at and each contact's deepest sample and depth. A cheap
upper bound below the margin proves a contact without the exact distance; within each
run of contact samples of one pair, only the samples whose lower bound does not exceed
the run's least upper bound can be its deepest, and only those are measured exactly.
The others keep their upper bound: below the margin, and above the run's depth.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from ._obstacles import Obstacles

__all__ = ["contacts_sparingly"]


def contacts_sparingly(
    obstacles: Obstacles,
    capsules: tuple[np.ndarray, np.ndarray, np.ndarray],
    rows: np.ndarray,
    cols: np.ndarray,
    lower: np.ndarray,
    limit: np.ndarray,
    links: int,
    margin: float,
    tolerance: float,
) -> np.ndarray:
    """Distances of candidate pairs, exact except inside contacts away from their depth.

    Parameters
    ----------
    obstacles : Obstacles
    capsules : tuple of ndarray
        Segment ends (N, 3) twice and radii (N,) of the candidates.
    rows, cols : ndarray of int, shape (N,)
        ``sample·links + link`` and the object of each candidate.
    lower : ndarray, shape (N,)
        Lower bounds of their signed distances.
    limit : ndarray, shape (N,)
        The cutoff at their samples (with its round-off allowance): farther is ``inf``.
    links : int
    margin : float
        Closer than this is a contact.
    tolerance : float
        Round-off allowed between the bounds and the exact distance.

    Returns
    -------
    ndarray, shape (N,)
        The exact signed distance, or an upper bound below ``margin`` where the pair is
        in contact and that sample cannot be its contact's deepest (the exact distance
        there exceeds the contact's depth by more than ``tolerance``).
    """
    a, b, r = capsules
    upper = obstacles.upper_bound(a, b, r, cols)
    sure = upper < margin - tolerance
    values = upper.copy()
    measure = np.flatnonzero(~sure)
    tighter = obstacles.tighter_bound(a[measure], b[measure], r[measure], cols[measure])
    far = tighter > limit[measure]
    values[measure[far]] = np.inf
    measure = measure[~far]
    values[measure] = obstacles.exact(a[measure], b[measure], r[measure], cols[measure])
    inside = np.flatnonzero(values < margin)
    if not len(inside):
        return values
    sample, link = np.divmod(rows[inside], links)
    column = link * (int(cols.max()) + 1) + cols[inside]
    order = np.lexsort((sample, column))
    inside, sample, column = inside[order], sample[order], column[order]
    starts = np.ones(len(inside), dtype=bool)
    starts[1:] = (column[1:] != column[:-1]) | (sample[1:] != sample[:-1] + 1)
    first = np.flatnonzero(starts)
    run = np.cumsum(starts) - 1
    # Each run's most promising sample (least upper bound) first: its exact distance
    # bounds the run's depth more tightly than any upper bound.
    deepest = np.minimum.reduceat(values[inside], first)
    probe = inside[(values[inside] == deepest[run]) & sure[inside]]
    values[probe] = obstacles.exact(a[probe], b[probe], r[probe], cols[probe])
    sure[probe] = False
    deepest = np.minimum.reduceat(values[inside], first)
    ceiling = np.full(len(values), -np.inf)  # the depth a sample must reach to count
    ceiling[inside] = deepest[run] + tolerance
    redo = inside[sure[inside] & (lower[inside] <= ceiling[inside])]
    tighter = obstacles.tighter_bound(a[redo], b[redo], r[redo], cols[redo])
    redo = redo[tighter <= ceiling[redo]]
    values[redo] = obstacles.exact(a[redo], b[redo], r[redo], cols[redo])
    return values
