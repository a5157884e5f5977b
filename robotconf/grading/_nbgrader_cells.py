"""Course cells as nbgrader cells: autograded answers, autograder tests, read-only cells.

nbgrader keeps its cell types in ``metadata.nbgrader`` (schema version 3):
``{grade, solution, locked, points, grade_id, schema_version}``. An autograded answer
is ``solution`` (editable); ``nbgrader generate_assignment`` replaces the lines between
``### BEGIN SOLUTION`` and ``### END SOLUTION`` with its code stub and keeps the others.
An autograder test is ``grade`` and ``locked``, worth ``points``; the lines between
``### BEGIN HIDDEN TESTS`` and ``### END HIDDEN TESTS`` are removed from the students'
copy and put back by ``nbgrader autograde``. A read-only cell is only ``locked``.
"""

from __future__ import annotations

import ast
import re
import textwrap
from typing import Any

from .._errors import InvalidInputError
from .rubric._rubric import DEFAULT_CAP, DEFAULT_SHARE, Rubric

__all__ = [
    "BEGIN_HIDDEN",
    "BEGIN_SOLUTION",
    "CODE_STUB",
    "END_HIDDEN",
    "END_SOLUTION",
    "SCHEMA_VERSION",
    "answer_source",
    "grade_id",
    "nbgrader_metadata",
    "autograder_source",
    "credit_arguments",
]

SCHEMA_VERSION = 3
BEGIN_SOLUTION = "### BEGIN SOLUTION"
END_SOLUTION = "### END SOLUTION"
BEGIN_HIDDEN = "### BEGIN HIDDEN TESTS"
END_HIDDEN = "### END HIDDEN TESTS"
#: What ``nbgrader generate_assignment`` writes where a solution was (nbgrader_config.py
#: sets it): the student keeps the stub line ``answer_k = None`` above it. nbgrader's own
#: default stub would add ``raise NotImplementedError()``.
CODE_STUB = "# Replace None above with your answer, then run the check cell below."
_MARKERS = ("BEGIN SOLUTION", "END SOLUTION", "BEGIN HIDDEN TESTS", "END HIDDEN TESTS")
_NOT_ID = re.compile(r"[^A-Za-z0-9_-]")


def grade_id(text: str) -> str:
    """``text`` as an nbgrader grade id (letters, digits, ``_`` and ``-`` only).

    >>> grade_id("answer_1"), grade_id("réponse 2")
    ('answer_1', 'r_ponse_2')
    """
    return _NOT_ID.sub("_", text) or "cell"


def nbgrader_metadata(
    grade_id: str,
    *,
    grade: bool = False,
    solution: bool = False,
    locked: bool = False,
    points: float | None = None,
) -> dict[str, Any]:
    """A cell's ``metadata.nbgrader``.

    Examples
    --------
    >>> meta = nbgrader_metadata("test_answer_1", grade=True, locked=True, points=2)
    >>> meta["grade"], meta["locked"], meta["solution"], meta["points"], meta["schema_version"]
    (True, True, False, 2, 3)
    """
    meta: dict[str, Any] = {
        "grade": grade,
        "grade_id": grade_id,
        "locked": locked,
        "schema_version": SCHEMA_VERSION,
        "solution": solution,
    }
    if grade:
        meta["points"] = points if points is not None else 0
    return meta


def _refuse_markers(source: str, where: str) -> None:
    for marker in _MARKERS:
        if marker in source:
            raise InvalidInputError(where, marker, "course cells without nbgrader markers")


def answer_source(stub: str, solution: str, where: str = "answer cell") -> str:
    """An answer cell for nbgrader: the student's stub line, then the marked solution.

    Examples
    --------
    >>> print(answer_source("answer_1 = None  # your matrix", "answer_1 = [[1, 0], [0, 1]]"))
    answer_1 = None  # your matrix
    ### BEGIN SOLUTION
    answer_1 = [[1, 0], [0, 1]]
    ### END SOLUTION
    """
    _refuse_markers(stub + solution, where)
    return "\n".join([stub.rstrip(), BEGIN_SOLUTION, solution.strip("\n"), END_SOLUTION])


def _same_code(original: str, wrapped: str) -> bool:
    """Whether the ``with`` block of ``wrapped`` runs exactly ``original``."""
    try:
        inside = ast.parse(wrapped).body[-2]
        before = ast.parse(original)
    except (SyntaxError, IndexError):
        return False
    if not isinstance(inside, ast.With):
        return False
    return ast.dump(ast.Module(body=inside.body, type_ignores=[])) == ast.dump(before)


def _assert_calls(check: str) -> int:
    """How many ``assert_*`` checker calls the code holds (``rc.assert_matrix(...)``)."""
    count = 0
    for node in ast.walk(ast.parse(check)):
        if isinstance(node, ast.Call):
            name = getattr(node.func, "attr", None) or getattr(node.func, "id", "")
            count += str(name).startswith("assert_")
    return count


def credit_arguments(rubric: Rubric, several: bool) -> str:
    """The arguments of ``Credit(…)`` for one exercise's rubric (defaults left out).

    >>> credit_arguments(Rubric(2, slips={"too_rounded": 0.75}), several=False)
    "2, slips={'too_rounded': 0.75}"
    >>> credit_arguments(Rubric(1.5, share=0.4), several=True)
    '1.5, share=0.4, several=True'
    """
    parts = [f"{rubric.points:g}"]
    if rubric.share != DEFAULT_SHARE:
        parts.append(f"share={rubric.share:g}")
    if rubric.slips:
        parts.append(f"slips={dict(sorted(rubric.slips.items()))!r}")
    if rubric.cap != DEFAULT_CAP:
        parts.append(f"cap={rubric.cap:g}")
    if several:
        parts.append("several=True")
    return ", ".join(parts)


def autograder_source(
    check: str,
    rubric: Rubric,
    *,
    variable: str,
    recheck: bool,
    where: str = "check cell",
) -> tuple[str, bool]:
    """A check cell as an nbgrader autograder test cell of a graded copy.

    The whole check is a hidden test: the students' copy keeps one line that shows their
    answer back, so the expected values (and the code that computes them) are not in it; ``nbgrader
    autograde`` puts the check back. It runs inside ``with Credit(…) as credit:``
    (:class:`~robotconf.grading.Credit`, with the exercise's rubric), first flagging an
    answer cell that asks robotconf for its answer (``credit.own_work``), and the cell
    ends with ``credit.score``, the number nbgrader reads. ``recheck`` adds
    ``credit.recheck()`` (a symbolic answer at 32 other values of its symbols). A check
    that cannot be indented without changing it (a multi-line string, IPython syntax) is
    hidden as it is: whole points.

    Returns
    -------
    (str, bool)
        The source, and whether the rubric's credit applies.

    Examples
    --------
    >>> check = "rc.assert_matrix(answer_1, expected_1)"
    >>> source, credit = autograder_source(check, Rubric(2), variable="answer_1", recheck=False)
    >>> print(source)
    answer_1  # your answer, worth 2 points: checked when your notebook is graded
    ### BEGIN HIDDEN TESTS
    from robotconf.grading import Credit
    <BLANKLINE>
    with Credit(2) as credit:
        credit.own_work('answer_1')
        rc.assert_matrix(answer_1, expected_1)
    credit.score
    ### END HIDDEN TESTS
    """
    _refuse_markers(check, where)
    check = check.strip("\n")
    points = rubric.points
    # The students' copy keeps one line: their answer, shown back to them.
    comment = (
        f"{variable}  # your answer, worth {points:g} point{'' if points == 1 else 's'}: "
        "checked when your notebook is graded"
    )
    try:
        several = _assert_calls(check) != 1
    except SyntaxError:
        return "\n".join([comment, BEGIN_HIDDEN, check, END_HIDDEN]), False
    opening = f"with Credit({credit_arguments(rubric, several)}) as credit:"
    body = textwrap.indent(check, "    ")
    inner = ["from robotconf.grading import Credit", "", opening, body]
    if recheck:
        inner.append("    credit.recheck()  # the same check at 32 other values of the symbols")
    inner.append("credit.score")
    if not _same_code(check, "\n".join([*inner[:4], inner[-1]])):
        return "\n".join([comment, BEGIN_HIDDEN, check, END_HIDDEN]), False
    inner.insert(3, f"    credit.own_work({variable!r})")
    return "\n".join([comment, BEGIN_HIDDEN, *inner, END_HIDDEN]), True
