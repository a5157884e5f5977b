"""The answer of ``ik_all_many``: every closed-form solution of T targets, in one table."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field

import numpy as np

from ..closed_form._solutions import IKSolutions

__all__ = ["IKSolutionSets"]


@dataclass(frozen=True, eq=False)
class IKSolutionSets:
    """Every closed-form solution of T targets: one row per solution, all targets together.

    ``sets[k]`` is the :class:`~robotconf.inverse_kinematics.IKSolutions` of target
    ``k`` — the same as ``ik_all(robot, targets[k])`` gives (to round-off) — and the
    arrays serve a caller that works on all rows at once (the cell's reach maps).

    Attributes
    ----------
    q : ndarray, shape (R, n)
        Every verified solution, the rows of target 0 first (as ``IKSolutions.q``).
    labels : tuple of str, length R
        Each row's branch.
    within_limits : ndarray of bool, shape (R,)
    target : ndarray of int, shape (R,)
        The target each row solves (ascending).
    counts : ndarray of int, shape (T,)
        Solutions per target.
    reasons : tuple of str, length T
        As ``IKSolutions.reason``, per target.
    family : str

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.inverse_kinematics import ik_all_many
    >>> sets = ik_all_many(rc.preset("planar_2r", l1=1, l2=1), [[1, 1, 0], [3, 0, 0]])
    >>> sets.counts, sets.target, sets.labels
    (array([2, 0]), array([0, 0]), ('elbow down', 'elbow up'))
    >>> sets[1].reason
    'the target is 1 beyond the reach: it is 3 from the first axis, and the arm reaches 2'
    """

    q: np.ndarray
    labels: tuple[str, ...]
    within_limits: np.ndarray
    target: np.ndarray
    counts: np.ndarray
    reasons: tuple[str, ...]
    family: str
    _starts: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        for array in (self.q, self.within_limits, self.target, self.counts):
            array.setflags(write=False)
        starts = np.concatenate([[0], np.cumsum(self.counts)])
        object.__setattr__(self, "_starts", starts)

    def __len__(self) -> int:
        return len(self.reasons)

    def __getitem__(self, k: int) -> IKSolutions:
        index = range(len(self))[k]  # negative indices, and an IndexError past the end
        rows = slice(int(self._starts[index]), int(self._starts[index + 1]))
        return IKSolutions(
            self.q[rows],
            self.labels[rows],
            self.within_limits[rows],
            self.family,
            self.reasons[index],
        )

    def __iter__(self) -> Iterator[IKSolutions]:
        return (self[k] for k in range(len(self)))

    def __str__(self) -> str:
        targets = len(self)
        solved = int(np.count_nonzero(self.counts))
        return (
            f"{self.family}: {targets} target{'' if targets == 1 else 's'}, {len(self.q)} "
            f"solutions ({solved} target{'' if solved == 1 else 's'} with at least one, "
            f"{int(self.within_limits.sum())} solutions within the limits)"
        )

    def __repr__(self) -> str:
        return f"<IKSolutionSets {self}>"
