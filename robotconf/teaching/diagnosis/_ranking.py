"""Ranking the explanations of a wrong answer, so that the checker names one mistake.

Several candidate mistakes may fit the same answer: a single R_y written with the signs
of R_x is the joint turning the wrong way *and* a transposed rotation; an answer at q = 0
is close to a calculator in degree mode. Each fitting candidate becomes an
:class:`Explanation` and is scored, best first, by

1. whether it explains **all** the wrong entries;
2. how many wrong entries it explains;
3. whether it rests on more than one entry (a single matching number may be chance);
4. how specific and simple it is (its tier: a coarse rounding, then one slip in a named
   module, the same slip repeated, a transpose or swap, a sign or a zero in one entry);
5. how closely the numbers agree (exact beats "within tolerance");
6. the order the families list their candidates in.

A partial match needs at least two entries, and none of the entries the mistake changes
may be right: a match on one coincidental entry is dropped.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..reading._tolerance import SCALE_FLOOR
from ._candidate import Candidate
from ._hints import close
from ._rounding import coarse_roundings

__all__ = ["Explanation", "ENTRY_TIER", "ROUNDING_TIER", "equivalent", "match", "rank", "sentence"]

#: Tiers of the entry-level explanations (the candidates' own tiers lie between them).
ROUNDING_TIER, ENTRY_TIER = 0, 4


@dataclass(frozen=True, eq=False)
class Explanation:
    """One way of explaining (some of) the wrong entries.

    Attributes
    ----------
    code : str
        The mistake's code.
    message : str
        Its sentence (empty for an entry-level explanation: the entry hints say it).
    entries : frozenset of (int, int)
        The wrong entries it explains (0-based).
    full : bool
        Whether it explains every wrong entry.
    tier : int
        Specificity (lower is more specific).
    residual : float
        Largest disagreement with the student's numbers, in units of the tolerance
        (0: exact, 1: just within tolerance).
    order : int
        Position in the list of candidates (the last tie-breaker).
    reading : str
        The short phrase for an equivalent reading (see :class:`Candidate`).
    values : ndarray, shape (K, rows, cols), or None
        The candidate's numbers; ``None`` for an entry-level explanation.
    """

    code: str
    message: str
    entries: frozenset[tuple[int, int]]
    full: bool
    tier: int
    residual: float = 0.0
    order: int = 0
    reading: str = ""
    values: np.ndarray | None = None

    def key(self) -> tuple[bool, int, bool, int, float, int]:
        """The ranking key: smaller is better."""
        count = len(self.entries)
        return (not self.full, -count, count < 2, self.tier, round(self.residual, 6), self.order)


def match(
    candidates: list[Candidate],
    wrong: set[tuple[int, int]],
    s_values: np.ndarray,
    e_values: np.ndarray,
    tol: float,
    student: Any = None,
) -> list[Explanation]:
    """The candidates that explain all or a fair share of the wrong entries.

    A full explanation: the student's answer equals the candidate wherever the mistake
    changes anything, and every wrong entry is such a place. A partial one: the mistake
    explains at least two of the wrong entries and at least half of the entries it
    changes, and none of them is right (a right entry there would contradict the
    mistake); the rest is another error. A typed number equals the candidate's when it
    agrees within ``tol`` or is the candidate's number rounded to the digits typed (a
    student who rounds the result of a mistake to two decimals made that mistake); such
    an entry counts as a residual of 1, and at least one explained entry must agree
    within ``tol`` or keep two significant digits (``0.1`` alone rounds too many numbers
    to prove anything).

    Parameters
    ----------
    candidates : list of Candidate
    wrong : set of (int, int)
    s_values, e_values : ndarray, shape (K, rows, cols)
        Student's and expected matrix at the sample points.
    tol : float
    student : sympy.Matrix, optional
        The student's answer, for the rounded numbers; without it only ``tol`` counts.

    Returns
    -------
    list of Explanation
        In the order of ``candidates``.

    Examples
    --------
    >>> expected = np.array([[[1.0, 2.0], [3.0, 4.0]]])
    >>> swapped = Candidate("row_swap", "Rows 1 and 2 are swapped.", expected[:, ::-1, :])
    >>> found = match([swapped], {(0, 0), (0, 1), (1, 0), (1, 1)}, swapped.values, expected, 1e-3)
    >>> found[0].code, found[0].full
    ('row_swap', True)
    """
    found = []
    for order, candidate in enumerate(candidates):
        if candidate.values.shape != e_values.shape:
            continue
        changed = {tuple(x) for x in np.argwhere(~close(candidate.values, e_values, tol))}
        if not changed:
            continue
        exact = {tuple(x) for x in np.argwhere(close(s_values, candidate.values, tol))}
        rounded: set[tuple[int, int]] = set()
        strong = exact
        if student is not None:
            rounded = coarse_roundings(student, (wrong & changed) - exact, candidate.values)
            strong = exact | coarse_roundings(student, rounded, candidate.values, True)
        matches = exact | rounded
        explained = wrong & changed & matches
        if not explained & strong:  # resting on one-digit numbers alone is chance
            continue
        full = explained == wrong and changed <= matches
        fair = changed <= wrong and 2 * len(explained) >= len(changed) and len(explained) >= 2
        if not (full or fair):
            continue
        residual = 1.0 if rounded & explained else 0.0
        if explained - rounded:
            rows, cols = zip(*(explained - rounded), strict=True)
            s, c = s_values[:, rows, cols], candidate.values[:, rows, cols]
            with np.errstate(invalid="ignore", divide="ignore"):
                gap = np.abs(s - c) / (tol * np.maximum(SCALE_FLOOR, np.abs(c)))
            if np.isfinite(gap).any():
                residual = max(residual, float(np.nanmax(np.where(np.isfinite(gap), gap, 0))))
        found.append(
            Explanation(
                candidate.code,
                candidate.message,
                frozenset(explained),  # type: ignore[arg-type]
                full,
                candidate.tier,
                residual,
                order,
                candidate.reading,
                candidate.values,
            )
        )
    return found


def rank(explanations: list[Explanation]) -> list[Explanation]:
    """The explanations best first (see the module's docstring for the order).

    >>> a = Explanation("sign_error", "", frozenset({(0, 0)}), True, 4)
    >>> b = Explanation("rotation_direction", "…", frozenset({(0, 0)}), True, 1)
    >>> [e.code for e in rank([a, b])]
    ['rotation_direction', 'sign_error']
    """
    return sorted(explanations, key=Explanation.key)


def equivalent(ranked: list[Explanation], tol: float) -> Explanation | None:
    """Another reading of the same numbers as the first explanation, if there is one.

    Only full explanations with a reading and another code count, and only when their
    numbers agree with the first one's everywhere.

    Parameters
    ----------
    ranked : list of Explanation
        Best first.
    tol : float

    Returns
    -------
    Explanation or None
    """
    first = ranked[0] if ranked else None
    if first is None or not first.full or first.values is None:
        return None
    first_values = first.values
    for other in ranked[1:]:
        reading = other.full and other.reading and other.code != first.code
        same = other.values is not None and np.all(close(other.values, first_values, 2 * tol))
        if reading and same:
            return other
    return None


def sentence(primary: Explanation, other: Explanation | None) -> str:
    """The primary diagnosis, with an equivalent reading mentioned in the same sentence.

    >>> first = Explanation("rotation_direction", "A2 turns the wrong way.", frozenset(), True, 1)
    >>> other = Explanation("transposed_rotation", "", frozenset(), True, 3, reading="a transpose")
    >>> sentence(first, other)
    'A2 turns the wrong way; here that gives the same numbers as a transpose.'
    """
    if other is None:
        return primary.message
    return f"{primary.message.rstrip('.')}; here that gives the same numbers as {other.reading}."
