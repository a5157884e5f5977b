"""A DH table as a student writes it and reads about it: rows into numbers, hints out.

Reading: a table typed by a student becomes numbers, ``(θ, d, a, α, joint)`` per row.

A student writes a table as a textbook does, with the joint variable in its place:
``[("q1", 20, 0, "-pi/2"), ("q2", 0, 30, 0)]``, or as text
``"[[q1, 20, 0, -pi/2], [q2, 0, 30, 0]]"``, or in robotconf's own row format with a joint
letter, ``(0, 20, 0, -pi/2, "R")``. Text goes through the whitelist parser
(:func:`~robotconf.teaching.parse_expression`), never through ``eval``.

Where ``q_i`` stands decides the joint type (θ: revolute, d: prismatic); the rest of the
entry is the constant offset. Mistakes a student makes in *writing* a row (no joint
variable, ``q2`` in row 1, ``-q1``) are reported as issues with a hint, so that the check
fails kindly; only input that is not a table at all raises
:class:`~robotconf.InvalidInputError`.
The hint sentences written back live in :mod:`._dh_hints`.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_finite_number
from ...kinematics import MAX_MODULES
from ..reading._numeric_eval import NotEvaluable, TooLarge, complex_values
from ..reading._parser import parse_expression, parse_matrix
from ..reading._text import FUNCTION_WORDS

__all__ = ["DHRow", "ParsedTable", "joint_symbol", "parse_dh_rows"]

#: One numeric row in robotconf's order: θ offset, d offset, a, α (radians), "R" or "P".
DHRow = tuple[float, float, float, float, str]

_COLUMNS = ("θ", "d", "a", "α")
_LETTERS = {"r": "R", "revolute": "R", "p": "P", "prismatic": "P"}
_ALLOWED = (
    "a list of rows (θ, d, a, α) with the joint variable q_i in θ or d, e.g. "
    "[('q1', 20, 0, '-pi/2'), ...], or rows (θ, d, a, α, 'R'/'P'), "
    "or text '[[q1, 20, 0, -pi/2], ...]'"
)
#: Joint values at which an entry is evaluated to read off its offset and its slope in q_i.
_PROBE = np.array([0.0, 1.0, -0.7])
_MAX_Q = MAX_MODULES


@dataclass(frozen=True)
class ParsedTable:
    """A table as understood.

    Attributes
    ----------
    rows : tuple of DHRow
        One per row; only meaningful when ``issues`` is empty.
    issues : tuple of (str, str)
        ``(code, hint)`` for rows that are not written as DH rows: ``"joint_variable"``
        (no ``q_i``, another row's ``q``, or ``q_i`` in a or α), ``"joint_direction"``
        (``-q_i``), ``"joint_type"`` (the letter contradicts where ``q_i`` stands).
    """

    rows: tuple[DHRow, ...]
    issues: tuple[tuple[str, str], ...]


def joint_symbol(index: int) -> str:
    """The joint variable of 0-based row ``index``: ``joint_symbol(0) == "q1"``."""
    return f"q{index + 1}"


def _values(values: Mapping[str, Any] | None) -> dict[str, float]:
    if values is None:
        return {}
    if not isinstance(values, Mapping):
        raise InvalidInputError("values", values, "a dict of names to numbers, e.g. {'l1': 20}")
    checked = {}
    for name, value in values.items():
        if not isinstance(name, str) or not name.isidentifier() or name.startswith("q"):
            raise InvalidInputError(
                "values", name, "names such as 'l1' (q1, q2, … are the joint variables)"
            )
        checked[name] = check_finite_number(value, f"values[{name!r}]")
    return checked


def _rows_of(answer: Any, symbols: list[str], field: str) -> list[list[Any]]:
    """The answer as a list of rows of entries (text parsed into sympy expressions)."""
    if isinstance(answer, str):
        matrix = parse_matrix(answer, symbols)
        if matrix.cols == 1:  # "[q1, 0, 1, 0]": one row typed flat
            matrix = matrix.T
        return [list(matrix.row(r)) for r in range(matrix.rows)]
    if isinstance(answer, np.ndarray):
        answer = answer.tolist()
    if isinstance(answer, (bytes, Mapping)) or not isinstance(answer, Sequence) or not answer:
        raise InvalidInputError(field, answer, _ALLOWED, problem="not a list of rows:")
    if len(answer) > MAX_MODULES:
        raise InvalidInputError(field, f"{len(answer)} rows", f"at most {MAX_MODULES} rows")
    rows = []
    for r, row in enumerate(answer):
        if isinstance(row, np.ndarray):
            row = row.tolist()
        if isinstance(row, (str, bytes)) or not isinstance(row, Sequence) or len(row) not in (4, 5):
            raise InvalidInputError(
                f"{field}[{r}]", row, _ALLOWED, problem="a row needs 4 entries (θ, d, a, α), got"
            )
        rows.append(list(row))
    return rows


def _entry(value: Any, symbols: list[str], where: str) -> Any:
    import sympy

    if isinstance(value, str):
        return parse_expression(value, symbols)
    if isinstance(value, (bool, np.bool_)):
        raise InvalidInputError(where, value, "a number or a formula", problem="a boolean:")
    if isinstance(value, (int, float, np.integer, np.floating)):
        return sympy.Float(check_finite_number(value, where), 17)
    if isinstance(value, sympy.Expr):
        return value
    raise InvalidInputError(where, value, "a number or a formula such as 'q1 + pi/2'")


def _probe(expr: Any, values: dict[str, float], own: str, where: str) -> np.ndarray:
    """The entry's values at q_own = 0, 1, -0.7 (other names from ``values``)."""
    k = len(_PROBE)
    env = {name: np.full(k, value) for name, value in values.items()}
    env[own] = _PROBE
    try:
        result = complex_values(expr, env, k, strict=True)
    except (NotEvaluable, TooLarge):
        raise InvalidInputError(where, str(expr)[:60], f"numbers, pi, {FUNCTION_WORDS}") from None
    if not np.all(np.isfinite(result)) or np.any(np.abs(result.imag) > 1e-12):
        raise InvalidInputError(where, str(expr)[:60], "a real, finite number")
    return result.real


def _read_row(
    r: int, row: list[Any], values: dict[str, float], symbols: list[str], field: str
) -> tuple[DHRow | None, list[tuple[str, str]]]:
    own = joint_symbol(r)
    i = r + 1
    letter = None
    if len(row) == 5:
        given = row[4]
        if not isinstance(given, str) or given.strip().lower() not in _LETTERS:
            raise InvalidInputError(f"{field}[{r}][4]", given, "'R' (revolute) or 'P' (prismatic)")
        letter = _LETTERS[given.strip().lower()]
    numbers: list[float] = []
    holds: list[int] = []  # columns where q_i stands
    for c, value in enumerate(row[:4]):
        where = f"{field}[{r}][{c}]"
        expr = _entry(value, symbols, where)
        names = {s.name for s in expr.free_symbols}
        others = sorted(n for n in names if n.startswith("q") and n != own)
        if others:
            hint = f"Row {i} uses {', '.join(others)}: the joint variable of row {i} is {own}."
            return None, [("joint_variable", hint)]
        unknown = sorted(names - set(values) - {own})
        if unknown:
            raise InvalidInputError(where, ", ".join(unknown), "q1, q2, … and the given lengths")
        f = _probe(expr, values, own, where)
        slope = f[1] - f[0]
        linear = abs(f[2] - (f[0] - 0.7 * slope)) <= 1e-9 * (1 + abs(f[0]))
        if own in names and linear and abs(slope) <= 1e-12:
            names.discard(own)  # q1 - q1: no joint variable after all
        if own in names:
            if c >= 2:
                hint = (
                    f"Row {i}: {own} stands in {_COLUMNS[c]}, but a joint moves only θ "
                    f"(revolute) or d (prismatic)."
                )
                return None, [("joint_variable", hint)]
            if not linear or abs(abs(slope) - 1) > 1e-9:
                hint = f"Row {i}: write {_COLUMNS[c]} as {own} plus a constant, e.g. {own} + pi/2."
                return None, [("joint_variable", hint)]
            if slope < 0:
                hint = (
                    f"Row {i}: {_COLUMNS[c]} holds -{own}. In a DH table the joint variable "
                    f"is added (+{own}); if the joint turns the other way, let its z axis "
                    f"point the other way."
                )
                return None, [("joint_direction", hint)]
            holds.append(c)
        numbers.append(float(f[0]))
    if len(holds) > 1:
        return None, [("joint_variable", f"Row {i}: {own} may stand in θ or in d, not in both.")]
    if holds:
        placed = "R" if holds[0] == 0 else "P"
        if letter is not None and letter != placed:
            where_q = "θ" if placed == "R" else "d"
            hint = (
                f"Row {i} says '{letter}', but {own} stands in {where_q}: a revolute joint "
                f"moves θ, a prismatic joint moves d."
            )
            return None, [("joint_type", hint)]
        letter = placed
    if letter is None:
        hint = (
            f"Row {i} has no joint variable: write {own} into θ (revolute joint) or into d "
            f"(prismatic joint), e.g. ('{own}', 0, 30, 0)."
        )
        return None, [("joint_variable", hint)]
    theta, d, a, alpha = numbers
    return (theta, d, a, alpha, letter), []


def parse_dh_rows(
    answer: Any, values: Mapping[str, Any] | None = None, field: str = "answer"
) -> ParsedTable:
    """Read a DH table into numbers.

    Parameters
    ----------
    answer : sequence of rows, ndarray, or str
        Rows of 4 entries ``(θ, d, a, α)`` with ``q_i`` in θ or d, or of 5 entries
        ``(θ, d, a, α, joint)``; entries are numbers or formulas as text (numbers,
        ``q1 … q12``, ``pi``, ``sin cos tan sqrt``, and the names in ``values``).
    values : dict of str to float, optional
        Named lengths a student may write, e.g. ``{"l1": 20}``.
    field : str
        Name of the input in error messages.

    Returns
    -------
    ParsedTable
        Rows as ``(θ offset, d offset, a, α, "R"/"P")``, angles in radians as typed.

    Raises
    ------
    InvalidInputError
        For input that is not a table: not a list, a row of another length, text outside
        the whitelist, an entry that is not a real finite number, more than 64 rows.

    Examples
    --------
    >>> parse_dh_rows([("q1", 20, 0, "-pi/2"), ("q2 + pi/2", 0, 30, 0)]).rows[1]
    (1.5707963267948966, 0.0, 30.0, 0.0, 'R')
    >>> parse_dh_rows("[[0, q1 + l1, 0, 0]]", values={"l1": 5}).rows
    ((0.0, 5.0, 0.0, 0.0, 'P'),)
    >>> parse_dh_rows([(0, 20, 0, 0)]).issues[0][0]
    'joint_variable'
    """
    named = _values(values)
    symbols = [f"q{k}" for k in range(1, _MAX_Q + 1)] + list(named)
    rows: list[DHRow] = []
    issues: list[tuple[str, str]] = []
    for r, row in enumerate(_rows_of(answer, symbols, field)):
        parsed, problems = _read_row(r, row, named, symbols, field)
        issues += problems
        if parsed is not None:
            rows.append(parsed)
    return ParsedTable(tuple(rows), tuple(issues))
