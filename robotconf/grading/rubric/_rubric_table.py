"""``robotconf course rubric LESSON``: a lesson's rubric as the teacher reads it.

For every exercise: its points and the share a named slip earns (from the weighting
table, ``course/kit/weights.md``), the kind of answer its check judges, whether its
right numbers count, and every slip the checker names for that kind of answer with the
share it earns. Read from the notebooks' cells (the check's ``assert_*`` call), without
running them; an exercise with per-student numbers (``task.assert_answer(k, …)``) is
read from its registered exercise, whose typical slips are run through its check with
the demo student's numbers and listed first.
"""

from __future__ import annotations

import ast
import os

from ...teaching import (
    DH_DIAGNOSES,
    DIAGNOSES,
    IK_DIAGNOSES,
    MATRIX_DIAGNOSES,
    PROFILE_DIAGNOSES,
)
from ...teaching.exercises import Assignment, registered
from .._course import find_course, select_lessons, solutions_notebook
from .._notebook_cells import cell_source, find_exercises, read_notebook
from ._points import POINTS_PER_EXERCISE, POINTS_PER_MATRIX
from ._rubric import UNEXPLAINED, Rubric, names_a_slip
from ._weights import WEIGHTS_FILE, find_weights

__all__ = ["check_kinds", "rubric_text"]

#: The codes each kind of answer may be diagnosed with.
_CODES = {
    "matrix": MATRIX_DIAGNOSES,
    "value": DIAGNOSES,
    "vector": DIAGNOSES,
    "angle": DIAGNOSES,
    "set": DIAGNOSES,
    "interval": DIAGNOSES,
    "ik_solution": IK_DIAGNOSES,
    "ik_solutions": IK_DIAGNOSES,
    "profile": {**PROFILE_DIAGNOSES, **DIAGNOSES},
    "dh_table": DH_DIAGNOSES,
}
#: The codes the rubric's head already says earn nothing (no answer, wrong shape, symbols).
_SAID = frozenset({"no_answer", "not_a_number", "too_complicated", "shape"})
_NUMBERS = {
    "matrix": "per graded entry",
    "vector": "per component",
    "angle": "per angle (of several)",
    "set": "per solution",
    "interval": "per end",
    "ik_solutions": "per solution",
    "profile": "per number (of several)",
    "dh_table": "per joint axis and the end-effector",
}


def check_kinds(source: str) -> list[str]:
    """The kinds of answer a check cell's ``assert_*`` calls judge, in order.

    >>> check_kinds("rc.assert_ik_solutions(answer_2, arm, target, name='both')")
    ['ik_solutions']
    """
    try:
        tree = ast.parse(source)
    except SyntaxError:
        return []
    kinds = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            name = str(getattr(node.func, "attr", None) or getattr(node.func, "id", ""))
            if name.startswith("assert_") and name[7:] in _CODES:
                kinds.append(name[7:])
    return kinds


def _assignment_exercise(source: str) -> int | None:
    """``k`` of a check cell's ``task.assert_answer(k, answer_k)``, if it has one."""
    try:
        tree = ast.parse(source)
    except SyntaxError:
        return None
    for node in ast.walk(tree):
        if (
            isinstance(node, ast.Call)
            and getattr(node.func, "attr", None) == "assert_answer"
            and node.args
            and isinstance(node.args[0], ast.Constant)
            and isinstance(node.args[0].value, int)
        ):
            return node.args[0].value
    return None


def _typical(lesson: str, number: int) -> tuple[str, list[str]]:
    """The kind of answer of a course exercise with drawn numbers, and the codes its
    typical slips get from its check (with the demo student's numbers)."""
    task = Assignment(lesson, "demo")
    kind = str(getattr(task.check(number, task.answer(number)), "kind", "?"))
    codes: list[str] = []
    for answer in task.exercise(number).slips(task.numbers).values():
        typed = answer.tolist() if hasattr(answer, "tolist") else answer
        code = task.check(number, typed).diagnosis
        if names_a_slip(code) and code not in codes:
            codes.append(code)
    return kind, codes


def _slip_list(rubric: Rubric, kind: str, typical: list[str] | None = None) -> str:
    codes = [code for code in _CODES.get(kind, {}) if names_a_slip(code)]
    if typical:
        others = [code for code in codes if code not in typical]
        listed = f"its typical slips {_shown(rubric, typical)}; any other: {_shown(rubric, others)}"
    else:
        listed = _shown(rubric, codes)
    return listed + _unnamed(kind)


def _unnamed(kind: str) -> str:
    """The codes of this kind of check that name no slip, with the share they earn (none
    of their own: only the right numbers count), so the listing holds every code."""
    codes = [code for code in _CODES.get(kind, {}) if code in UNEXPLAINED - _SAID]
    if not codes:
        return ""
    shown = ", ".join(f"`{code}`" for code in codes)
    numbers = "only the right numbers count" if kind in _NUMBERS else "nothing"
    return f"; naming no slip (share 0, {numbers}): {shown}"


def _shown(rubric: Rubric, codes: list[str]) -> str:
    shown = []
    for code in codes:
        share = rubric.share_of(code)
        mark = "" if share == rubric.share else f" **{share:g}**"
        shown.append(f"`{code}`{mark}")
    return ", ".join(shown)


def rubric_text(lesson: str, course: str | os.PathLike[str] | None = None) -> str:
    """The rubric of one lesson as Markdown.

    Parameters
    ----------
    lesson : str
        A lesson number (``"9"``, ``"09"``) or folder name.
    course : path-like, optional
        The course folder (default ``./course``, else the repository's).

    Returns
    -------
    str

    Raises
    ------
    InvalidInputError
        For a lesson the course does not have, or a malformed notebook or table.

    Examples
    --------
    >>> text = rubric_text("11")
    >>> print(text.splitlines()[0])
    # Rubric of 11_inverse_kinematics: 9 points
    >>> "| 2 | 1.5 | ik_solutions | 0.75 |" in text
    True
    >>> "`atan_quadrant`" in text.split("**Exercise 1**")[1].split("any other")[0]
    True
    """
    folder = find_course(course)
    name = select_lessons(folder, [lesson])[0]
    weights = find_weights(folder)
    notebook = read_notebook(solutions_notebook(folder, name))
    rows = []
    total = 0.0
    details = []
    drawn = {e.number for e in registered(name)}
    for exercise in find_exercises(notebook, f"{name} solutions"):
        check = cell_source(notebook["cells"][exercise.check_index])
        kinds = check_kinds(check)
        kind = kinds[-1] if kinds else "?"
        number = _assignment_exercise(check)
        typical: list[str] | None = None
        if number in drawn:
            kind, typical = _typical(name, number)
            kinds = [kind]
        points = weights.points_of(name, exercise.number) if weights else None
        if points is None:
            points = float(POINTS_PER_MATRIX if kind == "matrix" else POINTS_PER_EXERCISE)
        rubric = weights.rubric(name, exercise.number, points) if weights else Rubric(points)
        total += points
        several = len(kinds) > 1
        numbers = "—" if several else _NUMBERS.get(kind, "— (one number)")
        slip = round(rubric.share * points, 2)
        rows.append(
            f"| {exercise.number} | {points:g} | {kind} | {slip:g} | {numbers} |"
            + (" several checks: a named slip only |" if several else " |")
        )
        if kind in _CODES or typical:
            listed = _slip_list(rubric, kind, typical)
            details.append(f"- **Exercise {exercise.number}**: {listed}")
    source = weights.source if weights else f"no {WEIGHTS_FILE}: the default points"
    head = [
        f"# Rubric of {name}: {total:g} points",
        "",
        f"Points and shares from {source}. A right answer earns the points; a wrong one "
        "the larger of the share of a named slip of a right method and the share of its "
        "numbers that are right (at most 3/4); no answer, a wrong shape and an "
        "unexplained single number earn nothing. An answer cell that calls robotconf "
        "earns no automatic points (manual grading).",
        "",
        "| exercise | points | answer | a named slip earns | right numbers count | notes |",
        "|---|---:|---|---:|---|---|",
    ]
    tail = [
        "",
        "Slips each check names (a share in bold where the table sets one; "
        "`robotconf course rubric` reads the codes' meanings from the checkers):",
        "",
        *details,
    ]
    return "\n".join(head + rows + tail) + "\n"
