"""How many points an exercise is worth, and how many numbers of an answer are right.

**Points.** Set per exercise by the course's weighting table (``course/kit/weights.md``,
read by the release); a course without one gets one point per exercise and two for a
4×4 matrix (a transfer or pose matrix, 16 entries to derive).

**The numbers that count** (:func:`credit_counts`, read by the rubric in
:mod:`._rubric`): a matrix's graded entries, a vector's or interval's components, the
solutions of a set, a profile answer's numbers, a DH table's joint axes and its
end-effector. Entries that are 0, equal to the identity's entry, or the homogeneous
``(0, …, 0, 1)`` last row are scaffolding: counting them would give an identity or zero
matrix most of the points (10 of 16 for the transfer matrix of a z rotation). They still
count as wrong when a student gets them wrong. For a set, ``graded`` is the number of
solutions and ``wrong`` the missing ones plus the extra elements. A single number or
angle, one IK solution, a wrong shape and a missing answer have no numbers to count.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

__all__ = [
    "PARTIAL_KINDS",
    "POINTS_PER_EXERCISE",
    "POINTS_PER_MATRIX",
    "SCAFFOLD_TOLERANCE",
    "credit_counts",
    "graded_entries",
    "points_for",
]

#: Points of an exercise whose answer is not a 4×4 matrix.
POINTS_PER_EXERCISE = 1
#: Points of an exercise whose answer is a 4×4 matrix.
POINTS_PER_MATRIX = 2
#: A numeric entry within this (absolute) distance of 0 or 1 counts as that number.
SCAFFOLD_TOLERANCE = 1e-9
#: The kinds of answers of several numbers besides matrices and DH tables.
PARTIAL_KINDS = ("vector", "interval", "set", "angle", "profile", "ik_solutions")


def points_for(kind: str | None, shape: Sequence[int] | None) -> int:
    """Points of an exercise from the kind and shape of its expected value.

    Parameters
    ----------
    kind : str or None
        The checker's kind (``"matrix"``, ``"vector"``, ...); ``None`` when unknown.
    shape : (rows, cols) or None
        ``None`` when the check did not say (the exercise gets the default).

    Returns
    -------
    int
        :data:`POINTS_PER_MATRIX` for a 4×4 matrix, else :data:`POINTS_PER_EXERCISE`.

    Examples
    --------
    >>> points_for("matrix", (4, 4)), points_for("matrix", (4, 1)), points_for(None, None)
    (2, 1, 1)
    >>> points_for("dh_table", (4, 4))  # a table is not a matrix to multiply out
    1
    """
    if kind == "matrix" and shape is not None and tuple(shape) == (4, 4):
        return POINTS_PER_MATRIX
    return POINTS_PER_EXERCISE


def _constant(entry: Any) -> float | None:
    """The value of an entry that is a plain number, else ``None``."""
    try:
        if getattr(entry, "free_symbols", None):
            return None
        value = complex(entry)
    except (TypeError, ValueError):
        return None
    return value.real if value.imag == 0 else None


def graded_entries(matrix: Any) -> np.ndarray:
    """Which entries of an expected matrix earn credit: the ones a blank guess gets wrong.

    Parameters
    ----------
    matrix : sympy.Matrix or array-like, shape (rows, cols)
        The expected value.

    Returns
    -------
    ndarray of bool, shape (rows, cols)
        False for scaffolding: an entry that is 0, equals the identity's entry
        (``eye(rows, cols)``), or lies in a last row ``(0, …, 0, 1)`` of a 4-row matrix
        (homogeneous coordinates).

    Examples
    --------
    >>> import sympy
    >>> q1 = sympy.Symbol("q1")
    >>> rz = sympy.Matrix([[sympy.cos(q1), -sympy.sin(q1), 0, 30],
    ...                    [sympy.sin(q1), sympy.cos(q1), 0, 0],
    ...                    [0, 0, 1, 20], [0, 0, 0, 1]])
    >>> int(graded_entries(rz).sum())  # the four sines and cosines, 30 and 20
    6
    >>> graded_entries([[30], [40], [20], [1]]).ravel().tolist()
    [True, True, True, False]
    """
    rows_list = matrix.tolist() if hasattr(matrix, "tolist") else [list(r) for r in matrix]
    rows, cols = len(rows_list), len(rows_list[0])
    identity = np.eye(rows, cols)
    values = [[_constant(entry) for entry in row] for row in rows_list]
    graded = np.ones((rows, cols), dtype=bool)
    for r in range(rows):
        for c in range(cols):
            value = values[r][c]
            if value is not None and (
                abs(value) <= SCAFFOLD_TOLERANCE
                or abs(value - identity[r, c]) <= SCAFFOLD_TOLERANCE
            ):
                graded[r, c] = False
    last = values[-1]
    homogeneous = [0.0] * (cols - 1) + [1.0]
    if rows == 4 and all(
        v is not None and abs(v - h) <= SCAFFOLD_TOLERANCE
        for v, h in zip(last, homogeneous, strict=True)
    ):
        graded[-1, :] = False
    return graded


def credit_counts(result: Any) -> tuple[int, int] | None:
    """How many of a wrong answer's numbers that count are wrong, and how many count.

    Parameters
    ----------
    result : MatrixCheck, AnswerCheck, IKCheck or DHTableCheck
        A verdict that is not ok; its ``kind`` says which check made it.

    Returns
    -------
    (wrong, graded) or None
        ``None`` when there are no numbers to count: no answer, a wrong shape, no graded
        entry, or a kind that is one number (a value, one angle, one IK solution).

    Examples
    --------
    >>> from robotconf import check_set, check_vector
    >>> credit_counts(check_vector([0, 35, 40], [0, 35, -40]))
    (1, 2)
    >>> credit_counts(check_set([0, 3], [0, np.pi]))  # 3 where π belongs: one of two
    (1, 2)
    >>> credit_counts(check_set([0, 3, 5], [0, np.pi]))  # and 5 too many
    (2, 2)
    """
    kind = getattr(result, "kind", None)
    if kind == "matrix":
        student, expected = result.student, result.expected.matrix
        if student is None or tuple(student.shape) != tuple(expected.shape):
            return None
        graded = int(graded_entries(expected).sum())
        wrong = len(set(result.wrong_entries) | set(result.unchecked_entries))
    elif kind == "dh_table":
        joints = len(result.rows)
        if not joints or result.diagnosis in ("no_answer", "row_count", "joint_type"):
            return None
        graded = joints + 1  # every joint's axis, and the end-effector
        wrong = len(result.wrong_joints) + (0 if result.end_effector_ok else 1)
    elif kind in PARTIAL_KINDS:
        if result.student is None or result.diagnosis in ("shape", "no_answer"):
            return None
        expected = np.asarray(result.expected, dtype=float)
        if kind == "set":
            graded = len(expected)
        elif kind == "ik_solutions":  # the solutions found plus the missing ones
            graded = len(result.student) - len(result.extra) + len(result.wrong)
        elif kind == "profile":
            if expected.size < 2 or np.shape(result.student) != expected.shape:
                return None
            graded = expected.size
        else:
            if expected.size < 2:
                return None
            graded = int((np.abs(expected.ravel()) > SCAFFOLD_TOLERANCE).sum())
        wrong = len(result.wrong) + len(result.extra)
        if kind in ("set", "ik_solutions"):  # a wrong element in a missing one's place
            wrong = len(result.wrong) + max(0, len(result.extra) - len(result.wrong))
    else:
        return None
    return (min(wrong, graded), graded) if graded else None
