"""Run the corpus through the checker and tabulate the outcomes per family."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import robotconf as rc

from .case import Case
from .references import reference

__all__ = ["Outcome", "family_table", "format_table", "judge", "primary_rate"]


@dataclass(frozen=True)
class Outcome:
    """What the checker made of one case.

    Attributes
    ----------
    case : Case
    ok : bool
        The checker's verdict.
    diagnosis : str or None
        Its primary diagnosis.
    hints : tuple of str
    grade : str
        ``"right"`` (the verdict and, for a wrong answer, the primary diagnosis are the
        expected ones), ``"vague"`` (no diagnosis where one was expected), ``"wrong"`` (a
        diagnosis other than the expected one), ``"false accept"`` or ``"false reject"``.
    """

    case: Case
    ok: bool
    diagnosis: str | None
    hints: tuple[str, ...]
    grade: str


def judge(case: Case) -> Outcome:
    """Check one case's answer and grade the result."""
    result = rc.check_matrix(case.answer, reference(case.reference), **case.options)
    if result.ok != case.ok:
        grade = "false accept" if result.ok else "false reject"
    elif case.ok or result.diagnosis == case.diagnosis:
        grade = "right"
    elif result.diagnosis is None:
        grade = "vague"
    else:
        grade = "wrong"
    return Outcome(case, result.ok, result.diagnosis, tuple(result.hints), grade)


def primary_rate(outcomes: Iterable[Outcome]) -> float:
    """The share of wrong answers whose primary diagnosis is the expected one."""
    graded = [o for o in outcomes if not o.case.ok]
    return sum(o.grade == "right" for o in graded) / len(graded) if graded else 1.0


def family_table(outcomes: Iterable[Outcome]) -> list[tuple[str, int, int, int, int]]:
    """Per family: ``(family, count, right primary, vague, wrong)``, plus a total row.

    A right answer counts as "right" when accepted; a false accept or reject counts as
    "wrong".
    """
    rows: dict[str, list[int]] = {}
    for outcome in outcomes:
        row = rows.setdefault(outcome.case.family, [0, 0, 0, 0])
        row[0] += 1
        if outcome.grade == "right":
            row[1] += 1
        elif outcome.grade == "vague":
            row[2] += 1
        else:
            row[3] += 1
    table = [(family, *counts) for family, counts in sorted(rows.items())]
    total = [sum(row[i] for row in table) for i in range(1, 5)]
    return [*table, ("total", *total)]  # type: ignore[list-item]


def format_table(rows: list[tuple[str, int, int, int, int]]) -> str:
    """The table as Markdown, ready to paste into a note."""
    lines = [
        "| family | count | right primary | vague | wrong |",
        "|---|---:|---:|---:|---:|",
    ]
    lines += [f"| {f} | {n} | {r} | {v} | {w} |" for f, n, r, v, w in rows]
    return "\n".join(lines)
