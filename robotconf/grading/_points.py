"""How many points an exercise is worth, and how much of them a partly right answer earns.

**Points.** One point per exercise; a 4×4 matrix (a transfer or pose matrix, 16 entries
to derive) is worth two. The shape is the one the check compares against.

**Partial credit per entry** (matrices, vectors, sets, intervals). A wrong answer of the
right shape earns ``points × max(0, 1 − wrong / graded)``: ``wrong`` counts the entries
the checker marked wrong (or too complicated to check) and ``graded`` the entries a
blank guess would not already get right. Entries that are 0, equal to the identity's
entry, or the homogeneous ``(0, …, 0, 1)`` last row are scaffolding: counting them would
give an identity or zero matrix most of the points (10 of 16 for the transfer matrix of a
z rotation). They still count as wrong when a student gets them wrong. For a set,
``graded`` is the number of solutions and ``wrong`` the missing ones plus the extra
elements. A wrong shape, a missing answer or an answer without graded entries earns
nothing; so does a single number or angle, and a DH table (a wrong row moves every frame
after it, so its rows are not separately right or wrong).
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
    "answer_credit",
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
#: The checkers' kinds whose answers can earn partial credit.
PARTIAL_KINDS = ("matrix", "vector", "interval", "set")


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


def credit_counts(kind: str, result: Any) -> tuple[int, int] | None:
    """How many graded entries a wrong answer has wrong, and how many there are.

    Parameters
    ----------
    kind : str
        The checker's kind: ``"matrix"``, ``"vector"``, ``"interval"``, ``"set"``,
        ``"value"``, ``"angle"`` or ``"dh_table"``.
    result : MatrixCheck, AnswerCheck or DHTableCheck
        A verdict that is not ok.

    Returns
    -------
    (wrong, graded) or None
        ``None`` when no partial credit applies: no answer, a wrong shape, no graded
        entry, or a kind graded as a whole (value, angle, DH table).

    Examples
    --------
    >>> from robotconf import check_vector
    >>> credit_counts("vector", check_vector([0, 35, 40], [0, 35, -40]))
    (1, 2)
    """
    if kind == "matrix":
        student, expected = result.student, result.expected.matrix
        if student is None or tuple(student.shape) != tuple(expected.shape):
            return None
        graded = int(graded_entries(expected).sum())
        wrong = len(set(result.wrong_entries) | set(result.unchecked_entries))
    elif kind in PARTIAL_KINDS:
        if result.student is None or result.diagnosis == "shape":
            return None
        expected = np.asarray(result.expected, dtype=float)
        if kind == "set":
            graded = len(expected)
        else:
            graded = int((np.abs(expected.ravel()) > SCAFFOLD_TOLERANCE).sum())
        wrong = len(result.wrong) + len(result.extra)
    else:
        return None
    return (wrong, graded) if graded else None


def answer_credit(kind: str, result: Any) -> float:
    """The fraction of the points a checked answer earns, from 0 to 1.

    Parameters
    ----------
    kind : str
        The checker's kind (see :func:`credit_counts`).
    result : MatrixCheck, AnswerCheck or DHTableCheck

    Returns
    -------
    float
        1 when right; ``max(0, 1 − wrong / graded)`` from :func:`credit_counts`; 0 when
        no partial credit applies.

    Examples
    --------
    >>> from robotconf import Module, Robot, check_matrix, check_set, expected_matrix
    >>> robot = Robot([Module("Rz", a=(30, 0, 20))])
    >>> a1 = expected_matrix(robot, "A1")
    >>> one_sign = "[[cos(q1), sin(q1), 0, 30], [sin(q1), cos(q1), 0, 0], [0, 0, 1, 20], "
    >>> one_sign += "[0, 0, 0, 1]]"  # the sine in (2,1) should be -sin(q1)
    >>> answer_credit("matrix", check_matrix(one_sign, a1))  # 1 of the 6 graded entries
    0.8333333333333334
    >>> answer_credit("matrix", check_matrix(np.eye(4), a1))  # a blank guess
    0.0
    >>> answer_credit("set", check_set([0], [0, np.pi]))  # π missing
    0.5
    >>> answer_credit("set", check_set([0, 3], [0, np.pi]))  # π missing, 3 extra
    0.0
    """
    if result.ok:
        return 1.0
    counts = credit_counts(kind, result)
    if counts is None:
        return 0.0
    wrong, graded = counts
    return max(0.0, 1.0 - wrong / graded)
