"""Hints of the homework checker: which candidate mistakes explain the wrong entries, and
sentences for the entries no candidate explains (sign errors, a missing offset, the rest).

Helpers of :mod:`robotconf.teaching._checker`; the candidates themselves come from
:mod:`robotconf.teaching._mistakes`.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

from ._check_result import show_entry, show_expected
from ._mistakes import Candidate, is_rotation_like

__all__ = ["close", "entries_text", "entry_hints", "explain", "shape_hint", "NO_ANSWER"]

#: The hint for an exercise still holding its ``None`` placeholder.
NO_ANSWER = "No answer yet: replace None with your matrix."


def close(a: np.ndarray, b: np.ndarray, tol: float) -> np.ndarray:
    """Entry-wise ``|a − b| ≤ tol·max(1, |b|)`` at every sample point (axis 0).

    Parameters
    ----------
    a, b : ndarray, shape (K, ...)
    tol : float

    Returns
    -------
    ndarray of bool, shape (...)
    """
    with np.errstate(invalid="ignore"):
        ok = np.abs(a - b) <= tol * np.maximum(1.0, np.abs(b))
    return np.all(ok, axis=0)


def _entry_text(r: int, c: int) -> str:
    return f"({r + 1},{c + 1})"


def entries_text(entries: Iterable[tuple[int, int]]) -> str:
    """1-based entries as the hints write them: ``"(1,3), (2,1)"``."""
    return ", ".join(_entry_text(r, c) for r, c in sorted(entries))


def shape_hint(student_shape: tuple[int, int], expected: Any, transposed_wrong: Any) -> str:
    """The hint for an answer of the wrong shape.

    Parameters
    ----------
    student_shape : (int, int)
    expected : sympy.Matrix
    transposed_wrong : set of (int, int) or None
        For an answer with the transposed shape: the entries still wrong once it is
        transposed back (empty: it is exactly the transpose); ``None`` otherwise.

    Returns
    -------
    str
    """
    rows, cols = expected.shape
    text = f"Expected a {rows}×{cols} matrix, you gave {student_shape[0]}×{student_shape[1]}."
    if transposed_wrong is not None:
        count = rows * cols
        shapes = (
            f"expected {rows}×{cols} ({rows} rows of {cols} entries), you gave "
            f"{student_shape[0]}×{student_shape[1]} — write each row as a row, not as a column."
        )
        if not transposed_wrong:
            text = f"Your matrix is the transpose of the expected one: {shapes}"
        elif len(transposed_wrong) <= 6:
            text = (
                f"Your matrix looks transposed: {shapes} Transposed back, entries "
                f"{entries_text(transposed_wrong)} (numbered as in the expected matrix) are "
                "still wrong."
            )
        else:
            text = (
                f"Your matrix looks transposed: {shapes} Transposed back, "
                f"{len(transposed_wrong)} of its {count} entries are still wrong."
            )
    elif expected.shape == (4, 4) and student_shape == (3, 3):
        text += " That looks like the rotation part only: add the translation column and "
        text += "the bottom row (0, 0, 0, 1)."
    return text


def explain(
    candidates: list[Candidate], wrong: set, s_values: np.ndarray, e_values: np.ndarray, tol: float
) -> tuple[list[Candidate], list[tuple[Candidate, set]]]:
    """Candidates that explain all wrong entries, and those that explain some of them.

    A full explanation: the student's answer equals the candidate wherever the mistake
    changes anything, and every wrong entry is such a place. A partial one: the mistake
    explains at least half of the entries it changes, and none of them is right (a right
    entry there would contradict the mistake); the rest is another error. (Fewer would
    be a coincidence of numbers rather than the mistake.)

    Parameters
    ----------
    candidates : list of Candidate
    wrong : set of (int, int)
    s_values, e_values : ndarray, shape (K, rows, cols)
        Student's and expected matrix at the sample points.
    tol : float

    Returns
    -------
    full : list of Candidate
    partial : list of (Candidate, set of (int, int))
        Best first.
    """
    full, partial = [], []
    for candidate in candidates:
        if candidate.values.shape != e_values.shape:
            continue
        changed = {tuple(x) for x in np.argwhere(~close(candidate.values, e_values, tol))}
        if not changed:
            continue
        matches = {tuple(x) for x in np.argwhere(close(s_values, candidate.values, tol))}
        explained = wrong & changed & matches
        if explained == wrong and changed <= matches:
            full.append(candidate)
        elif explained and changed <= wrong and 2 * len(explained) >= len(changed):
            partial.append((candidate, explained))
    partial.sort(key=lambda item: -len(item[1]))
    return full, partial


def _quote(entries: set, student: Any, expected: Any, reveal: bool) -> list[str]:
    return [
        f"entry {_entry_text(r, c)}: expected {show_expected(expected[r, c])}, you wrote "
        f"{show_entry(student[r, c])}"
        if reveal
        else f"entry {_entry_text(r, c)}"
        for r, c in sorted(entries)
    ]


def entry_hints(
    entries: set,
    student: Any,
    expected: Any,
    s_values: np.ndarray,
    e_values: np.ndarray,
    tol: float,
    reveal: bool,
) -> tuple[list[str], list[str]]:
    """Hints for wrong entries that no candidate mistake explains.

    Parameters
    ----------
    entries : set of (int, int)
    student, expected : sympy.Matrix
    s_values, e_values : ndarray, shape (K, rows, cols)
    tol : float
    reveal : bool
        Whether the hints may quote the expected entries.

    Returns
    -------
    hints : list of str
    codes : list of str
    """
    import sympy

    hints, codes = [], []
    zeros = np.zeros(e_values.shape[0])
    negated = {
        (r, c)
        for r, c in entries
        if close(s_values[:, r, c], -e_values[:, r, c], tol)
        and not close(e_values[:, r, c], zeros, tol)
    }
    homogeneous = is_rotation_like(e_values)
    sine = {(r, c) for r, c in negated if expected[r, c].has(sympy.sin)}
    rotation_sine = {(r, c) for r, c in sine if homogeneous and r < 3 and c < 3}
    if rotation_sine:
        codes.append("sign_error")
        hints.append(
            "; ".join(_quote(rotation_sine, student, expected, reveal))
            + " — a sign error on a sine term: the rotation goes the wrong way. A positive "
            "rotation about x has −sin in (2,3), about y +sin in (1,3), about z −sin in (1,2)."
        )
    if sine - rotation_sine:
        codes.append("sign_error")
        hints.append(
            "; ".join(_quote(sine - rotation_sine, student, expected, reveal))
            + " — a sign error: the whole entry has the opposite sign."
        )
    if negated - sine:
        codes.append("sign_error")
        hints.append(f"Entries {entries_text(negated - sine)} have the wrong sign.")
    rest = entries - negated
    missing = {
        (r, c)
        for r, c in rest
        if homogeneous
        and expected.shape == (4, 4)
        and c == 3
        and r < 3
        and close(s_values[:, r, c], zeros, tol)
    }
    if missing:
        codes.append("missing_offset")
        hints.append(
            f"Entries {entries_text(missing)} of the translation column are 0 where the "
            "answer is not: an offset (a translation) seems to be missing."
        )
    for r, c in sorted(rest - missing)[:8]:
        if reveal:
            hints.append(
                f"entry {_entry_text(r, c)}: expected {show_expected(expected[r, c])}, "
                f"you wrote {show_entry(student[r, c])}."
            )
        else:
            hints.append(
                f"entry {_entry_text(r, c)} is wrong (you wrote {show_entry(student[r, c])})."
            )
    return hints, codes
