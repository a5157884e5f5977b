"""What a family's solver finds for T targets at once, before the forward-kinematics check.

The one-target solvers append rows to a list as they find them; over T targets every
target has the same branches in the same order (the loops of the one-target solver,
unrolled), some of them missing. So the batch keeps a fixed (T, B) table: each branch's
joint values, whether the target has it, and its label; per target the reason the first
missing branch gave (the one-target solver keeps the first), the notes, and whether the
target hit a degenerate case (a double root, a free joint) that the one-target solver
words itself.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from itertools import product

import numpy as np

__all__ = ["Branches", "FirstReason", "label_table"]


@dataclass
class Branches:
    """A family's branches for T targets.

    Attributes
    ----------
    values : ndarray, shape (T, B, m)
        One value per moving joint (chain order) per branch (NaN-free; meaningless where
        ``valid`` is False).
    valid : ndarray of bool, shape (T, B)
        The branch exists for that target.
    labels : ndarray of object, shape (T, B)
        Its label (as the one-target solver writes it).
    reasons : list of str, length T
        Why a branch is missing (the first reason found), ``""`` otherwise.
    notes : list of tuple of str, length T
    degenerate : ndarray of bool, shape (T,)
        Targets the one-target solver must answer (double roots, free joints).
    """

    values: np.ndarray
    valid: np.ndarray
    labels: np.ndarray
    reasons: list[str]
    notes: list[tuple[str, ...]]
    degenerate: np.ndarray


class FirstReason:
    """Per target, the first reason offered (the one-target solvers keep the first)."""

    def __init__(self, count: int):
        self.text = [""] * count
        self.given = np.zeros(count, dtype=bool)

    def offer(self, where: np.ndarray, words: Callable[[int], str]) -> None:
        """Give ``words(t)`` to every target ``t`` in ``where`` that has no reason yet."""
        for t in np.flatnonzero(where & ~self.given).tolist():
            self.text[t] = words(t)
        self.given |= where


def label_table(*parts: Sequence[str]) -> np.ndarray:
    """Every label made of one word per part, joined by ", ", as a flat object array
    indexed by the parts' indices in mixed radix (first part slowest).

    >>> label_table(("a", "b"), ("x", "y"))[1 * 2 + 0]
    'b, x'
    """
    return np.array([", ".join(words) for words in product(*parts)], dtype=object)
