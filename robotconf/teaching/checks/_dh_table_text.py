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

Writing: the hint sentences of :func:`~robotconf.teaching.check_dh_table`. They name the
row and the parameter to look at and say what it measures, never the right value
(unless the check reveals). Parameter names follow the convention: a standard row i
holds ``a_i, α_i``, a modified row i holds ``a_{i-1}, α_{i-1}``.
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

__all__ = [
    "DHRow",
    "ParsedTable",
    "parse_dh_rows",
    "joint_symbol",
    "NO_ANSWER",
    "convention_hint",
    "degrees_hint",
    "exchanged_hint",
    "generic_hint",
    "joint_type_hint",
    "repair_hint",
    "row_count_hint",
    "swapped_columns_hint",
]

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
        raise InvalidInputError(where, str(expr)[:60], "numbers, pi, sin, cos, tan, sqrt") from None
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


# -- hints ------------------------------------------------------------------------------

NO_ANSWER = "No answer yet: replace None with your DH table, one row per joint."
_JOINT_WORDS = {"R": "revolute", "P": "prismatic"}
_FORMULAS = {"standard": "Rz(θ)·Tz(d)·Tx(a)·Rx(α)", "modified": "Rx(α)·Tx(a)·Rz(θ)·Tz(d)"}


@dataclass(frozen=True)
class _Names:
    """What row i's parameters are called, and the axes they are measured along."""

    theta: str
    d: str
    a: str
    alpha: str
    z_from: str  # α turns this z axis …
    z_to: str  # … onto this one, which is joint `joint`'s axis
    x_about: str  # α is measured about, a along this x axis
    z_d: str  # d is measured along this z axis
    joint: int


def _names(r: int, convention: str) -> _Names:
    i = r + 1
    if convention == "standard":
        return _Names(
            f"θ{i}", f"d{i}", f"a{i}", f"α{i}", f"z{i - 1}", f"z{i}", f"x{i}", f"z{i - 1}", i + 1
        )
    return _Names(
        f"θ{i}", f"d{i}", f"a{i - 1}", f"α{i - 1}", f"z{i - 1}", f"z{i}", f"x{i - 1}", f"z{i}", i
    )


def _number(value: float) -> str:
    for k, text in ((0.5, "pi/2"), (-0.5, "-pi/2"), (1.0, "pi"), (-1.0, "-pi")):
        if np.isclose(value, k * np.pi, rtol=0, atol=1e-12):
            return text
    return f"{value:.6g}"


def repair_hint(
    code: str,
    r: int,
    convention: str,
    repaired: DHRow | None = None,
    *,
    written: float | None = None,
) -> str:
    """The hint for a single-row mistake (``code`` as in ``DHTableCheck.diagnosis``);
    ``written``: for ``d_value``/``a_value``, the length the row holds where another
    belongs (None: the row has 0 there, a constant left out).

    >>> print(repair_hint("alpha_sign", 0, "standard"))  # doctest: +ELLIPSIS
    Row 1: check the sign of α1. With it, z1 points the wrong way, so joint 2 turns ...
    """
    n = _names(r, convention)
    i = r + 1
    texts = {
        "alpha_sign": (
            f"Row {i}: check the sign of {n.alpha}. With it, {n.z_to} points the wrong way, "
            f"so joint {n.joint} turns backwards. {n.alpha} is the angle from {n.z_from} to "
            f"{n.z_to}, measured about {n.x_about} by the right-hand rule."
        ),
        "swapped_a_d": (
            f"Row {i}: {n.a} and {n.d} look swapped. {n.d} is the distance along {n.z_d} "
            f"(between x{i - 1} and x{i}); {n.a} is the distance along {n.x_about} "
            f"(between {n.z_from} and {n.z_to})."
        ),
        "theta_offset": (
            f"Row {i}: at q{i} = 0 your frame {i} is turned about {n.z_d} against the "
            f"robot's zero position (the joint's zero moved): check the constant in "
            f"{n.theta}, the angle from x{i - 1} to x{i} when q{i} = 0."
        ),
        "twist": (
            f"Row {i}: {n.alpha} does not turn {n.z_from} onto joint {n.joint}'s axis: "
            f"{n.z_to} must lie along that axis, pointing the way the joint turns."
        ),
        "a_sign": (
            f"Row {i}: check the sign of {n.a}: it is measured along {n.x_about}, "
            f"from {n.z_from} to {n.z_to}."
        ),
        "d_sign": (
            f"Row {i}: check the sign of {n.d}: it is measured along {n.z_d}, "
            f"from x{i - 1} to x{i}."
        ),
        "d_value": (
            f"Row {i}: {n.d} misses a constant: the distance along {n.z_d} from x{i - 1} to "
            f"x{i} at q = 0 (a height, or where a slide starts) belongs in {n.d}, besides "
            "the joint variable of a slide."
        ),
        "a_value": (
            f"Row {i}: {n.a} misses a constant: the distance along {n.x_about} from "
            f"{n.z_from} to {n.z_to} (a link's length) belongs in {n.a}."
        ),
    }
    text = texts[code]
    if written is not None and code in ("d_value", "a_value"):
        field, along = (
            (n.d, f"{n.z_d} from x{i - 1} to x{i}")
            if code == "d_value"
            else (
                n.a,
                f"{n.x_about} from {n.z_from} to {n.z_to}",
            )
        )
        text = (
            f"Row {i}: {field} = {_number(written)} is not the robot's: {field} is the "
            f"distance along {along} at q = 0 — check which length of the drawing goes "
            "there (another link's length, or one measured from another joint?)."
        )
    if repaired is not None:
        theta, d, a, alpha, joint = repaired
        text += (
            f" A right row {i}: θ = {_number(theta)}, d = {_number(d)}, a = {_number(a)}, "
            f"α = {_number(alpha)} ({joint}; q{i} added to {'θ' if joint == 'R' else 'd'})."
        )
    return text


def exchanged_hint(code: str, rows: tuple[int, int], convention: str) -> str:
    """Two rows' a (or d) exchanged: each row holds the other's length (rows 0-based).

    >>> exchanged_hint("a_value", (0, 1), "standard")  # doctest: +ELLIPSIS
    'Rows 1 and 2: a1 and a2 look exchanged: ...'
    """
    first, second = (_names(r, convention) for r in rows)
    if code == "d_value":
        names, what = (first.d, second.d), "d is the distance along the joint's z axis"
    else:
        names, what = (first.a, second.a), "a is the length of the link along its x axis"
    return (
        f"Rows {rows[0] + 1} and {rows[1] + 1}: {names[0]} and {names[1]} look exchanged: "
        f"{what}, so each row takes the length of its own link (which link comes after "
        "which joint?)."
    )


def swapped_columns_hint(rows: list[int], convention: str) -> str:
    """a and d swapped in several rows: the table's columns mixed up.

    >>> swapped_columns_hint([1, 2], "standard")  # doctest: +ELLIPSIS
    'In rows 1 and 2, a and d look swapped: ...'
    """
    listed = ", ".join(str(r) for r in rows[:-1]) + f" and {rows[-1]}"
    along = "z_(i-1)" if convention == "standard" else "z_i"
    return (
        f"In rows {listed}, a and d look swapped: the columns are (θ, d, a, α) — d is the "
        f"distance along {along} (between the x axes), a the distance along the common "
        "normal x (between the z axes)."
    )


def convention_hint(asked: str, other: str, whole: bool) -> str:
    """The table fits the robot when read in the other convention."""
    fits = "describe the robot" if whole else "put every joint axis in the right place"
    return (
        f"Your rows {fits} when read as a {other} DH table, but this exercise asks for the "
        f"{asked} convention, {_FORMULAS[asked]}. In a standard table row i holds a_i and "
        f"α_i of the link after joint i; in a modified table row i holds a_(i-1) and "
        f"α_(i-1) of the link before it, and the last link's length goes into the tool "
        f"point."
    )


def degrees_hint() -> str:
    """The angles were typed in degrees."""
    return (
        "Your angles look like degrees: a DH table takes radians (write -pi/2, not -90; "
        "pi/6, not 30)."
    )


def row_count_hint(rows: int, joints: int) -> str:
    """The table has too few or too many rows."""
    plural = "s" if rows != 1 else ""
    text = (
        f"Your table has {rows} row{plural}, but the robot has {joints} joints: one row per joint."
    )
    if rows < joints:
        return text + " A row is missing."
    return text + (
        " A constant offset between two joints goes into d or a of a neighbouring row, "
        "not into a row of its own."
    )


def joint_type_hint(r: int, letter: str) -> str:
    """Row r's joint has the wrong type."""
    i = r + 1
    place = "θ" if letter == "R" else "d"
    return (
        f"Row {i}: joint {i} is {_JOINT_WORDS[letter]}, so its variable q{i} belongs in "
        f"{place} (a revolute joint moves θ, a prismatic joint moves d)."
    )


def generic_hint(
    first_wrong: int | None, reversed_axis: bool, convention: str, rows: int, tool: bool
) -> tuple[str, str]:
    """(code, hint) when no single repair explains the table.

    ``first_wrong``: 0-based first joint whose axis is wrong (None: all right, the
    end-effector is not); ``reversed_axis``: that axis is the right line, pointing the
    other way; ``tool``: the exercise gives a tool point.
    """
    if first_wrong is None:
        if convention == "standard":
            where = f"check the constants of the last row (d{rows} and a{rows})" + (
                " and the tool point" if tool else f": the tool sits at the origin of frame {rows}"
            )
        else:
            where = (
                f"check d{rows} and the tool point: in a modified table the last link's "
                "length goes into the tool point"
            )
        return "end_effector", f"Every joint axis is right, but the end-effector is not: {where}."
    j = first_wrong + 1
    z = f"z{j - 1}" if convention == "standard" else f"z{j}"
    last = j - 1 if convention == "standard" else j
    rows_text = "row 1" if last == 1 else f"rows 1-{last}"
    if reversed_axis:
        return "reversed_axis", (
            f"Joint {j}: your {z} lies along the right line but points the other way, so a "
            f"positive q{j} turns the robot backwards (look at the twists α in {rows_text})."
        )
    if convention == "standard" and j == 1:
        return "axis", "Joint 1's axis must be z0, the base frame's z axis."
    start = "" if last == 1 else f"; start with row {last}"
    return "axis", (
        f"Joint {j}'s axis is not where your table puts {z}: {z} must lie along joint "
        f"{j}'s axis. It is placed by {rows_text}{start}."
    )
