"""Run the corpus through the checker and tabulate the outcomes per family."""

from __future__ import annotations

import functools
import re
from collections.abc import Iterable
from dataclasses import dataclass

import robotconf as rc
from robotconf.grading.rubric._rubric import UNEXPLAINED

from .case import Case
from .references import reference

#: Lessons whose exercises check with per-student numbers (rc.Assignment).
ASSIGNED = {
    "L7": "07_velocity_acceleration",
    "L9": "09_dh_frame_assignment",
    "L10": "10_paper_lab",
    "L11": "11_inverse_kinematics",
    "L12": "12_trajectories",
}
_EXERCISE = re.compile(r"(L\d+)\.ex(\d+)")
#: Codes that name no mistake: the checker saw the answer is wrong, and no more.
GENERIC = {"wrong", "axis", "reversed_axis", "end_effector"}
#: Codes that name no slip of a right method (the rubric's own list): a case labelled
#: None ("no single slip explains it") is right to get one of them, and a case labelled
#: with one (a solution missing from a set) is right to get that one.
NO_SLIP = UNEXPLAINED
#: One mistake, two codes: a matrix check says ``unit_slip`` where a number check says
#: ``unit_factor`` (a length in mm for m). A label matches either.
SAME_MISTAKE = {"unit_factor": "unit_slip"}


def _code(code: str | None) -> str | None:
    return SAME_MISTAKE.get(code, code) if code is not None else None


@functools.cache
def assignment(lesson: str, student: str) -> rc.Assignment:
    """A lesson's exercises with one student's numbers (drawn once)."""
    return rc.Assignment(lesson, student)


def verdict(case: Case) -> object:
    """The check a notebook runs on the case's answer."""
    found = _EXERCISE.fullmatch(case.reference)
    if found and found.group(1) in ASSIGNED and not case.reference.startswith("L7.ex1"):
        task = assignment(ASSIGNED[found.group(1)], case.student)
        return task.check(int(found.group(2)), case.answer)
    return rc.check_matrix(case.answer, reference(case.reference), **case.options)


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


def _named(found: str | None, label: str | None) -> bool:
    """Whether the checker's primary diagnosis is the one the case expects."""
    if label is None and found in NO_SLIP:
        return True
    return _code(found) == _code(label)


def judge(case: Case) -> Outcome:
    """Check one case's answer and grade the result."""
    result = verdict(case)
    diagnosis = result.diagnosis if result.diagnosis not in GENERIC else None  # type: ignore[attr-defined]
    if result.ok != case.ok:  # type: ignore[attr-defined]
        grade = "false accept" if result.ok else "false reject"  # type: ignore[attr-defined]
    elif case.ok or _named(diagnosis, case.diagnosis):
        grade = "right"
    elif diagnosis is None:
        grade = "vague"
    else:
        grade = "wrong"
    return Outcome(case, result.ok, diagnosis, tuple(result.hints), grade)  # type: ignore[attr-defined]


def primary_rate(outcomes: Iterable[Outcome]) -> float:
    """The share of wrong answers whose primary diagnosis is the expected one."""
    graded = [o for o in outcomes if not o.case.ok]
    return sum(o.grade == "right" for o in graded) / len(graded) if graded else 1.0


def lesson_group(case: Case) -> str:
    """``"lessons 1–8"`` or ``"lessons 9–12"``, by the case's reference."""
    number = int(re.match(r"L(\d+)", case.reference).group(1))  # type: ignore[union-attr]
    return "lessons 9–12" if number >= 9 else "lessons 1–8"


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
