"""What the answer checks read: a student's answer as numbers, the reference, the options.

A student's answer goes through :func:`~robotconf.teaching.check_matrix` first, so the
same whitelist parser (text is never evaluated), the same size limits, the refusal of
imaginary entries and of robotconf's own results, and the same one-line advice for typing
slips apply; its numeric judge screens every entry. Only then are the entries turned into
floats here, in the checker's own numpy walk.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_finite_number, check_flag
from ..diagnosis._components import Setting
from ..reading._numeric_eval import NotEvaluable, TooLarge, complex_values
from ..reading._parser import ParserLimits
from ..reading._shown import number_text, show_entry
from ._matrix import check_matrix

__all__ = [
    "NO_ANSWER",
    "Options",
    "read_options",
    "Parsed",
    "check_options",
    "check_text",
    "expected_numbers",
    "parse_answer",
]

#: The hint for an exercise still holding its ``None`` placeholder.
NO_ANSWER = "No answer yet: replace None with your answer."


@dataclass(frozen=True)
class Parsed:
    """A student's answer as understood: a matrix of numbers, or why there are none.

    Attributes
    ----------
    values : ndarray, shape (rows, cols), or None
        ``None`` when an entry holds symbols or is too large to evaluate.
    entries : list of str
        Each entry as the student wrote it (row by row), for quoting in hints.
    symbols : list of str
        Names left in the answer (``q1``), sorted.
    too_complicated : bool
        An entry has more parts than the checker evaluates.
    """

    values: np.ndarray | None
    entries: list[str]
    symbols: list[str]
    too_complicated: bool = False


def _entry_text(entry: Any) -> str:
    """An entry as hints quote it: numbers and the numbers inside a formula as decimals
    (``50000*sin(2.198)``, not the exact fraction the parser keeps)."""
    if entry.is_Number:
        value = float(entry)
        return number_text(value) if np.isfinite(value) else str(entry.evalf(4))
    return show_entry(entry, limit=40)


def check_text(value: Any, field: str) -> str | None:
    """``value`` if it is text or ``None``; anything else is refused."""
    if value is not None and not isinstance(value, str):
        raise InvalidInputError(field, value, "text or None")
    return value


def check_options(tol: Any, rel: Any) -> tuple[float, float]:
    """The absolute and relative tolerances, checked: ``tol ≥ 0``, ``0 ≤ rel < 1``."""
    tol = check_finite_number(tol, "tol")
    rel = check_finite_number(rel, "rel")
    if tol < 0:
        raise InvalidInputError("tol", tol, "a number ≥ 0 (absolute tolerance)")
    if not 0 <= rel < 1:
        raise InvalidInputError("rel", rel, "a number from 0 to 1 (relative tolerance)")
    return tol, rel


@dataclass(frozen=True)
class Options:
    """The options every answer check takes, checked once.

    Attributes
    ----------
    setting : Setting
        The tolerances, the period of angles, the unit and ``reveal``.
    name : str
        What the messages call the answer.
    hint : str or None
        The exercise's own advice.
    """

    setting: Setting
    name: str
    hint: str | None


def read_options(
    name: Any,
    default_name: str,
    *,
    tol: Any,
    rel: Any,
    unit: Any = None,
    reveal: Any = False,
    hint: Any = None,
    period: float | None = None,
    degrees: bool = False,
) -> Options:
    """Check the options an answer check was called with.

    Raises
    ------
    InvalidInputError
        For a tolerance out of range (``tol < 0``, ``rel`` outside 0 … 1), a name, unit
        or hint that is not text, or a ``reveal`` that is not a boolean.

    >>> options = read_options(None, "the value", tol=1e-3, rel=5e-3, unit="mm")
    >>> options.name, options.setting.show(2.5)
    ('the value', '2.5 mm')
    """
    tol, rel = check_options(tol, rel)
    setting = Setting(
        tol, rel, period, degrees, check_text(unit, "unit"), check_flag(reveal, "reveal")
    )
    return Options(setting, check_text(name, "name") or default_name, check_text(hint, "hint"))


def expected_numbers(expected: Any, field: str = "expected") -> np.ndarray:
    """The teacher's reference as a float array; every entry a finite real number.

    Numbers, numpy arrays, nested lists, sympy numbers (``sympy.pi``) and sympy matrices
    without symbols are read; text, booleans, complex numbers, symbols and non-finite
    values are refused.

    >>> expected_numbers([0, np.pi]).tolist()
    [0.0, 3.141592653589793]
    """
    if hasattr(expected, "tolist") and not isinstance(expected, np.ndarray):
        expected = expected.tolist()  # a sympy Matrix
    array = np.asarray(expected, dtype=object)
    allowed_text = "finite real numbers (for formulas in q1, q2, … use check_matrix)"
    if array.size == 0 or array.size > 10_000:
        raise InvalidInputError(field, expected, allowed_text, problem="empty or too large:")
    values = np.empty(array.shape)
    for index, item in np.ndenumerate(array):
        if isinstance(item, (str, bytes, bool, np.bool_, complex, np.complexfloating)):
            raise InvalidInputError(field, expected, allowed_text)
        try:
            values[index] = float(item)
        except (TypeError, ValueError):
            raise InvalidInputError(field, expected, allowed_text) from None
    if not np.isfinite(values).all():
        raise InvalidInputError(field, expected, allowed_text, problem="not finite:")
    return values


def _is_scalar(answer: Any) -> bool:
    """A single number or formula, not a list: parse it as a 1×1 matrix."""
    if isinstance(answer, str):
        return "," not in answer
    if isinstance(answer, (list, tuple)):
        return False
    if hasattr(answer, "shape"):  # arrays, numpy numbers (shape ()), sympy matrices
        return np.shape(answer) == ()
    return True  # numbers and sympy expressions; anything else is refused by check_matrix


def _complex_entries(matrix: Any) -> tuple[np.ndarray, bool]:
    """Each entry's value (0 where it cannot be evaluated) and whether one is too large."""
    values = np.zeros(matrix.shape, dtype=complex)
    too_large = False
    for r in range(matrix.rows):
        for c in range(matrix.cols):
            try:
                values[r, c] = complex_values(matrix[r, c], {}, 1, strict=True)[0]
            except TooLarge:
                too_large = True
            except NotEvaluable:  # the judge names it, with its own message
                pass
    return values, too_large


def parse_answer(answer: Any, limits: ParserLimits | None) -> Parsed:
    """Read a student's answer through :func:`check_matrix` and evaluate its entries.

    Parameters
    ----------
    answer : number, text, list, ndarray or sympy object (not None)
    limits : ParserLimits or None

    Returns
    -------
    Parsed
        The answer as a matrix of numbers, of whatever shape the student wrote: one number
        (1, 1), a list (n, 1) or (1, n), nested lists (rows, cols).

    Raises
    ------
    InvalidInputError
        As :func:`check_matrix` does for malformed, imaginary, non-finite or hostile
        input, and for an entry whose value overflows the float range (``"1e200**2"``).
    """
    if isinstance(answer, (complex, np.complexfloating)):
        raise InvalidInputError("student", answer, "real numbers", problem="a complex number:")
    if _is_scalar(answer):  # a bare number or formula parses as a 1×1 matrix
        probe = np.zeros((1, 1))
    else:  # a shape no answer has: check_matrix parses the answer and stops there
        probe = np.zeros((1, (limits or ParserLimits()).max_entries + 1))
    result = check_matrix(answer, probe, samples=1, limits=limits)
    matrix = result.student
    entries = [_entry_text(matrix[r, c]) for r in range(matrix.rows) for c in range(matrix.cols)]
    symbols = sorted({s.name for s in matrix.free_symbols})
    if symbols:
        return Parsed(None, entries, symbols)
    values, too_large = _complex_entries(matrix)
    if "shape" in result.mistakes:
        # Parsed only: the numeric judge now screens every entry (I, huge numbers, values
        # that are not real, functions it cannot evaluate) against the answer's own real
        # values, so right entries agree and nothing is left to explain.
        finite = np.isfinite(values)
        reference = np.where(finite, values.real, 0.0)
        check_matrix(matrix, reference, samples=1, limits=limits)
    if too_large:
        return Parsed(None, entries, [], too_complicated=True)
    for (r, c), value in np.ndenumerate(values):
        if not np.isfinite(value):
            raise InvalidInputError(
                f"student[{r}][{c}]",
                entries[r * matrix.cols + c],
                "numbers within ±1.8e308",
                problem=f"entry ({r + 1},{c + 1}) is too large to check:",
            )
    return Parsed(values.real, entries, [])


def component_names(names: Sequence[str] | None, n: int, default: str) -> list[str]:
    """Names of n components: given, or x, y, z (n ≤ 3), or ``f"{default} {i}"``."""
    if names is not None:
        names = list(names)
        if len(names) != n or not all(isinstance(x, str) for x in names):
            raise InvalidInputError("components", names, f"{n} names (text)")
        return names
    if default == "component" and n <= 3:
        return ["x", "y", "z"][:n]
    return [f"{default} {i + 1}" for i in range(n)]
