"""The course's rubric: credit for the right method, read off the checker's diagnosis.

A wrong answer earns the larger of two shares of an exercise's points:

- **a named slip of a right method** — the checker's primary diagnosis names one known
  slip and explains the whole answer (``complete``: nothing else is wrong): the rotation
  turned the wrong way, ``atan`` for ``atan2``, ``2v/a`` for the acceleration time, a
  forgotten synchronization, a θ offset missing in one DH row, …: the slip's share, by
  default **half** (:data:`DEFAULT_SHARE`), set per exercise and per slip by the teacher
  (``course/kit/weights.md``);
- **the numbers that are right**, for an answer of several numbers (a matrix's graded
  entries, a vector's components, the solutions of a set, a profile's numbers, a DH
  table's joint axes and end-effector), at most three quarters (:data:`DEFAULT_CAP`):
  a wrong answer never earns what a right one does.

A right answer earns the points; no answer, a wrong shape, an answer that still holds
symbols and a wrong single number without a recognised slip earn nothing. The
explanation a student reads in the feedback says which of these decided.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from ..._errors import InvalidInputError
from ...teaching import (
    DH_DIAGNOSES,
    DIAGNOSES,
    IK_DIAGNOSES,
    MATRIX_DIAGNOSES,
    PROFILE_DIAGNOSES,
)
from ...teaching.exercises import EXERCISE_SLIPS
from ._points import credit_counts

__all__ = [
    "DEFAULT_CAP",
    "DEFAULT_SHARE",
    "SLIP_WORDS",
    "UNEXPLAINED",
    "WORDS_BY_KIND",
    "Award",
    "Rubric",
    "award",
    "names_a_slip",
]

#: The share of the points a named slip earns unless the rubric says otherwise.
DEFAULT_SHARE = 0.5
#: The most a wrong answer earns by the numbers it has right.
DEFAULT_CAP = 0.75

#: Diagnosis codes that name no slip of a right method: nothing, the wrong shape, no
#: numbers, or a wrong answer the checker cannot explain.
UNEXPLAINED = frozenset(
    {
        "no_answer",
        "not_a_number",
        "too_complicated",
        "shape",
        "wrong",
        "missing",
        "duplicate",
        "extra",
        "distance_not_covered",
        "axis",
        "reversed_axis",
        "end_effector",
    }
)

#: What each diagnosis code means, for each kind of answer (a code such as
#: ``sign_error`` says something else of a matrix than of an IK solution).
WORDS_BY_KIND: dict[str, dict[str, str]] = {
    "matrix": MATRIX_DIAGNOSES,
    "dh_table": DH_DIAGNOSES,
    "ik_solution": IK_DIAGNOSES,
    "ik_solutions": IK_DIAGNOSES,
    "profile": {**DIAGNOSES, **PROFILE_DIAGNOSES},
    **{kind: DIAGNOSES for kind in ("value", "vector", "angle", "set", "interval")},
}
#: Every diagnosis code of the checkers with what it means (the rubric's words), and the
#: course exercises' own slips (the largest move sets the time, q3 = A before the drop, …).
SLIP_WORDS: dict[str, str] = {
    code: words
    for table in (
        EXERCISE_SLIPS,
        DH_DIAGNOSES,
        PROFILE_DIAGNOSES,
        IK_DIAGNOSES,
        MATRIX_DIAGNOSES,
        DIAGNOSES,
    )
    for code, words in table.items()
}


def names_a_slip(code: str | None) -> bool:
    """Whether a diagnosis code names a known slip of a right method.

    >>> names_a_slip("atan_quadrant"), names_a_slip("wrong"), names_a_slip(None)
    (True, False, False)
    """
    return code is not None and code in SLIP_WORDS and code not in UNEXPLAINED


def _share(value: Any, field: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not 0 <= value <= 1:
        raise InvalidInputError(field, value, "a share of the points from 0 to 1")
    return float(value)


@dataclass(frozen=True)
class Rubric:
    """How one exercise is graded.

    Parameters
    ----------
    points : float
        What the exercise is worth.
    share : float
        The share a named slip earns (default 0.5).
    slips : mapping of str to float
        Shares for particular slips (diagnosis codes), e.g. ``{"too_rounded": 0.75}``.
    cap : float
        The most a wrong answer earns by its right numbers (default 0.75).
    per_number : bool
        Whether the right numbers of a wrong answer count at all (``False`` for a check
        with several parts, where one part's numbers say little about the whole).

    Raises
    ------
    InvalidInputError
        For points that are not a number ≥ 0, a share or cap outside 0 … 1, or a slip
        code the checkers do not have (or one that names no slip).

    Examples
    --------
    >>> Rubric(2, slips={"atan_quadrant": 0.25}).share_of("atan_quadrant")
    0.25
    >>> Rubric(2).share_of("sign_error"), Rubric(2).share_of("wrong")
    (0.5, 0.0)
    """

    points: float
    share: float = DEFAULT_SHARE
    slips: Mapping[str, float] = field(default_factory=dict)
    cap: float = DEFAULT_CAP
    per_number: bool = True

    def __post_init__(self) -> None:
        points = self.points
        if isinstance(points, bool) or not isinstance(points, (int, float)) or not points >= 0:
            raise InvalidInputError("points", points, "a finite number ≥ 0")
        if points == float("inf"):
            raise InvalidInputError("points", points, "a finite number ≥ 0")
        object.__setattr__(self, "points", float(points))
        object.__setattr__(self, "share", _share(self.share, "share"))
        object.__setattr__(self, "cap", _share(self.cap, "cap"))
        slips = dict(self.slips)
        for code, value in slips.items():
            if not names_a_slip(code):
                raise InvalidInputError(
                    "slips", code, "a diagnosis code that names a slip (robotconf course rubric)"
                )
            slips[code] = _share(value, f"slips[{code!r}]")
        object.__setattr__(self, "slips", slips)

    def share_of(self, code: str | None) -> float:
        """The share a primary diagnosis ``code`` earns by itself (0 if it names no slip)."""
        if not names_a_slip(code):
            return 0.0
        assert code is not None
        return self.slips.get(code, self.share)


@dataclass(frozen=True)
class Award:
    """What one checked answer earns, and why.

    Attributes
    ----------
    score : float
        Points, rounded to 0.01.
    points : float
        What the exercise is worth.
    slip : str or None
        The named slip that earned its share, if that decided.
    counts : (int, int) or None
        ``(wrong, graded)`` numbers of an answer of several numbers.
    reason : str
        One sentence for the student: what cost the points.
    """

    score: float
    points: float
    slip: str | None
    counts: tuple[int, int] | None
    reason: str


def _points_text(value: float) -> str:
    return f"{value:g} point{'' if value == 1 else 's'}"


def award(result: Any, rubric: Rubric) -> Award:
    """The points a checker's verdict earns under ``rubric``.

    Parameters
    ----------
    result : MatrixCheck, AnswerCheck, IKCheck or DHTableCheck
        A verdict (its ``kind`` says which check made it).
    rubric : Rubric

    Returns
    -------
    Award

    Examples
    --------
    >>> import numpy as np
    >>> from robotconf import check_ik_solution, check_vector, preset
    >>> arm = preset("planar_2r", l1=1, l2=1)
    >>> slip = award(check_ik_solution([0, np.pi / 2], arm, [-1, -1, 0]), Rubric(2))
    >>> slip.score, slip.slip
    (1.0, 'atan_quadrant')
    >>> award(check_vector([0, 35, 40], [0, 35, -40]), Rubric(1)).score  # 1 of 2 numbers
    0.5
    """
    points = rubric.points
    if result.ok:
        return Award(points, points, None, None, "right")
    code = result.diagnosis
    counts = credit_counts(result) if rubric.per_number else None
    # A slip earns its share when it explains the whole answer: one slip, nothing else.
    by_slip = rubric.share_of(code) if getattr(result, "complete", False) else 0.0
    by_numbers = 0.0
    if counts is not None:
        wrong, graded = counts
        by_numbers = min(rubric.cap, max(0.0, 1.0 - wrong / graded))
    fraction = max(by_slip, by_numbers)
    score = round(points * fraction, 2)
    if fraction == 0.0:
        if code == "no_answer":
            why = "no answer yet: no points."
        elif counts is None:
            why = "the checker recognises no slip of the method here: no points."
        else:
            why = "none of the numbers that count is right: no points."
        return Award(0.0, points, None, counts, why)
    if by_slip >= by_numbers:
        assert code is not None
        words = WORDS_BY_KIND.get(getattr(result, "kind", ""), SLIP_WORDS).get(code)
        why = (
            f"{_points_text(score)} of {_points_text(points)}: the checker names one slip "
            f"of a right method ({words or SLIP_WORDS[code]}), which earns {by_slip:.0%} of "
            "the points."
        )
        return Award(score, points, code, counts, why)
    assert counts is not None
    wrong, graded = counts
    capped = f" (a wrong answer earns at most {rubric.cap:.0%})"
    why = (
        f"{_points_text(score)} of {_points_text(points)}: {graded - wrong} of the {graded} "
        f"numbers that count are right{capped if by_numbers == rubric.cap else ''}."
    )
    return Award(score, points, None, counts, why)
