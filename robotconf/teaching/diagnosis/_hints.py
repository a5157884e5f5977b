"""Hints of the homework checker for the entries no candidate mistake explains.

Such entries are sorted into groups a sentence can name (rounded too coarsely, a sign
error on a sine or on the whole entry, a zero in the translation column) and the rest,
which is named entry by entry. Helpers of :mod:`robotconf.teaching.checks._matrix`; the
candidate mistakes come from :mod:`robotconf.teaching.diagnosis._mistakes` and are ranked by
:mod:`robotconf.teaching.diagnosis._ranking`.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..reading._shown import show_entry, show_expected
from ..reading._tolerance import SCALE_FLOOR
from ._generic import is_rotation_like
from ._rounding import coarse_roundings

__all__ = [
    "EntryGroup",
    "NO_ANSWER",
    "close",
    "entries_text",
    "entry_groups",
    "entry_hints",
    "shape_hint",
]

#: The hint for an exercise still holding its ``None`` placeholder.
NO_ANSWER = "No answer yet: replace None with your matrix."


def close(a: np.ndarray, b: np.ndarray, tol: float) -> np.ndarray:
    """Entry-wise ``|a − b| ≤ tol·max(0.2, |b|)`` at every sample point (axis 0).

    Parameters
    ----------
    a, b : ndarray, shape (K, ...)
    tol : float

    Returns
    -------
    ndarray of bool, shape (...)
    """
    with np.errstate(invalid="ignore"):
        ok = np.abs(a - b) <= tol * np.maximum(SCALE_FLOOR, np.abs(b))
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


def _quote(entries: set, student: Any, expected: Any, reveal: bool) -> list[str]:
    return [
        f"entry {_entry_text(r, c)}: expected {show_expected(expected[r, c])}, you wrote "
        f"{show_entry(student[r, c])}"
        if reveal
        else f"entry {_entry_text(r, c)}"
        for r, c in sorted(entries)
    ]


@dataclass(frozen=True)
class EntryGroup:
    """Wrong entries one sentence can name.

    Attributes
    ----------
    kind : str
        ``"rounded"``, ``"rotation_sine"``, ``"sine"``, ``"negated"`` or ``"zero_translation"``.
    code : str
        The mistake code: ``"coarse_rounding"``, ``"sign_error"`` or ``"missing_offset"``.
    entries : frozenset of (int, int)
    tier : int
        0 for a coarse rounding, 4 for the others
        (see :mod:`robotconf.teaching.diagnosis._ranking`).
    """

    kind: str
    code: str
    entries: frozenset[tuple[int, int]]
    tier: int


_KINDS = ("rounded", "rotation_sine", "sine", "negated", "zero_translation")


def entry_groups(
    entries: set,
    student: Any,
    expected: Any,
    s_values: np.ndarray,
    e_values: np.ndarray,
    tol: float,
) -> list[EntryGroup]:
    """Sort wrong entries into the groups a sentence can name, largest group first.

    Parameters
    ----------
    entries : set of (int, int)
    student, expected : sympy.Matrix
    s_values, e_values : ndarray, shape (K, rows, cols)
    tol : float

    Returns
    -------
    list of EntryGroup
        Non-empty groups, by size (then rounding first, then the order of ``kind``);
        entries in none of them are left out.

    Examples
    --------
    >>> import sympy
    >>> q1 = sympy.Symbol("q1", real=True)
    >>> expected = sympy.Matrix([[sympy.sin(q1), 0.5]])
    >>> student = sympy.Matrix([[-sympy.sin(q1), sympy.Rational(1, 2) + 1]])
    >>> e = np.array([[[np.sin(0.3), 0.5]]])
    >>> s = np.array([[[-np.sin(0.3), 1.5]]])
    >>> groups = entry_groups({(0, 0), (0, 1)}, student, expected, s, e, 1e-3)
    >>> [(g.kind, sorted(g.entries)) for g in groups]
    [('sine', [(0, 0)])]
    """
    import sympy

    zeros = np.zeros(e_values.shape[0])
    rounded = coarse_roundings(student, entries, e_values)
    negated = {
        (r, c)
        for r, c in entries - rounded
        if close(s_values[:, r, c], -e_values[:, r, c], tol)
        and not close(e_values[:, r, c], zeros, tol)
    }
    homogeneous = is_rotation_like(e_values)
    sine = {(r, c) for r, c in negated if expected[r, c].has(sympy.sin)}
    rotation_sine = {(r, c) for r, c in sine if homogeneous and r < 3 and c < 3}
    rest = entries - negated - rounded
    zero_translation = {
        (r, c)
        for r, c in rest
        if homogeneous
        and expected.shape == (4, 4)
        and c == 3
        and r < 3
        and close(s_values[:, r, c], zeros, tol)
    }
    found = {
        "rounded": ("coarse_rounding", rounded),
        "rotation_sine": ("sign_error", rotation_sine),
        "sine": ("sign_error", sine - rotation_sine),
        "negated": ("sign_error", negated - sine),
        "zero_translation": ("missing_offset", zero_translation),
    }
    groups = [
        EntryGroup(kind, code, frozenset(group), 0 if kind == "rounded" else 4)
        for kind, (code, group) in found.items()
        if group
    ]
    return sorted(groups, key=lambda g: (-len(g.entries), g.tier, _KINDS.index(g.kind)))


def _group_hint(group: EntryGroup, student: Any, expected: Any, reveal: bool) -> str:
    entries = set(group.entries)
    if group.kind == "rounded":
        one = len(entries) == 1
        where = (
            "; ".join(_quote(entries, student, expected, True)) + " —"
            if reveal
            else f"{'Entry' if one else 'Entries'} {entries_text(entries)} {'is' if one else 'are'}"
        )
        return (
            f"{where} rounded too coarsely: keep 3 significant digits (to the "
            f"digits you kept, {'it is' if one else 'they are'} right)."
        )
    if group.kind == "rotation_sine":
        return (
            "; ".join(_quote(entries, student, expected, reveal))
            + " — a sign error on a sine term: the rotation goes the wrong way. A positive "
            "rotation about x has −sin in (2,3), about y +sin in (1,3), about z −sin in (1,2)."
        )
    if group.kind == "sine":
        return (
            "; ".join(_quote(entries, student, expected, reveal))
            + " — a sign error: the whole entry has the opposite sign."
        )
    if group.kind == "negated":  # the course's tests read this wording, one entry or more
        return f"Entries {entries_text(entries)} have the wrong sign."
    one = len(entries) == 1
    return (
        f"{'Entry' if one else 'Entries'} {entries_text(entries)} of the translation column "
        f"{'is' if one else 'are'} 0 where the answer is not: an offset (a translation) "
        "seems to be missing."
    )


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
        One per group of :func:`entry_groups` (largest first), then one per remaining
        entry (at most 8).
    codes : list of str
        The groups' codes, in the same order.
    """
    groups = entry_groups(entries, student, expected, s_values, e_values, tol)
    hints = [_group_hint(group, student, expected, reveal) for group in groups]
    codes = [group.code for group in groups]
    rest = set(entries).difference(*(group.entries for group in groups))
    for r, c in sorted(rest)[:8]:
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
