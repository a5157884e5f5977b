"""The result of a homework check: verdict, wrong entries, hints, and an HTML table."""

from __future__ import annotations

import html
from dataclasses import dataclass, field
from typing import Any

from ._expected import ExpectedMatrix

__all__ = ["MatrixCheck", "format_decimal", "show_entry", "show_expected"]


@dataclass(frozen=True, eq=False)
class MatrixCheck:
    """The verdict on one student matrix.

    Attributes
    ----------
    ok : bool
        Every entry right (and the shape).
    wrong_entries : list of (int, int)
        0-based ``(row, col)`` of wrong entries, as numpy indexes them. Hints count from
        1 as textbooks do: entry (1,3) is ``wrong_entries`` item ``(0, 2)``.
    hints : list of str
        What the mistake most likely is, in sentences a student can act on.
    mistakes : list of str
        Codes of the hints, in their order (the primary diagnosis first, then the
        entry-level ones): ``"wrong_order"``, ``"transposed_rotation"``,
        ``"transposed_matrix"``, ``"rotation_direction"``, ``"sign_error"``,
        ``"offset_after_rotation"``, ``"missing_offset"``, ``"dh_convention"``,
        ``"degrees_as_radians"``, ``"radians_as_degrees"``, ``"row_swap"``,
        ``"column_swap"``, ``"swapped_d_a"``, ``"homogeneous_coordinate"``,
        ``"parking_pose"``, ``"joint_left_out"``, ``"swapped_joints"``, ``"unit_slip"``,
        ``"coarse_rounding"``, the same slip in every module of a kind
        ``"<code>_all"`` (``"rotation_direction_all"``, ``"missing_offset_all"``,
        ``"offset_after_rotation_all"``, ``"sign_error_all"``, ``"swapped_d_a_all"``),
        ``"shape"``, ``"no_answer"``, ``"too_complicated"``.
    student : sympy.Matrix or None
        The student's matrix as understood; ``None`` when there is no answer yet.
    expected : ExpectedMatrix
    unchecked_entries : list of (int, int)
        0-based entries too complicated to check within the checker's budget (neither
        right nor known to be wrong; ``ok`` is False while there are any).
    diagnoses : tuple of str
        Every explanation that fits the wrong entries, ranked best first, each code once
        (see :mod:`robotconf.teaching._ranking`); empty when the answer is right or
        nothing fits. ``("no_answer",)``, ``("shape",)`` or ``("transposed_matrix",)``
        when there is no answer or it has another shape.

    Examples
    --------
    >>> import numpy as np
    >>> from robotconf.teaching import check_matrix
    >>> result = check_matrix([[3, 4], [1, 2]], np.array([[1, 2], [3, 4]]))
    >>> result.diagnosis, result.diagnoses
    ('row_swap', ('row_swap',))
    >>> check_matrix([[1, 2], [3, 4]], np.array([[1, 2], [3, 4]])).diagnosis is None
    True
    """

    ok: bool
    wrong_entries: list[tuple[int, int]]
    hints: list[str]
    mistakes: list[str]
    student: Any
    expected: ExpectedMatrix
    reveal: bool = field(default=False, repr=False)
    unchecked_entries: list[tuple[int, int]] = field(default_factory=list)
    diagnoses: tuple[str, ...] = ()

    @property
    def diagnosis(self) -> str | None:
        """The primary diagnosis: the best-ranked mistake code, or ``None``."""
        return self.diagnoses[0] if self.diagnoses else None

    def __bool__(self) -> bool:
        return self.ok

    def __str__(self) -> str:
        name = self.expected.name or "the matrix"
        if self.ok:
            return f"{name}: correct."
        count = len(self.wrong_entries)
        head = f"{name}: {count} wrong entr{'y' if count == 1 else 'ies'}." if count else f"{name}:"
        if self.unchecked_entries:
            unchecked = len(self.unchecked_entries)
            head += f" {unchecked} entr{'y' if unchecked == 1 else 'ies'} too complicated to check."
        return "\n".join([head, *(f"- {hint}" for hint in self.hints)])

    def __repr__(self) -> str:
        return f"<MatrixCheck ok={self.ok} wrong_entries={self.wrong_entries}>"

    def _repr_html_(self) -> str:
        rows = []
        wrong = set(self.wrong_entries)
        unchecked = set(self.unchecked_entries)
        student = self.student
        if student is not None:
            for r in range(student.rows):
                cells = []
                for c in range(student.cols):
                    text = html.escape(show_entry(student[r, c]))
                    if (r, c) in wrong:
                        tip = f"entry ({r + 1},{c + 1}) is wrong"
                        if self.reveal and self.expected.matrix.shape == student.shape:
                            tip += ": expected " + show_expected(self.expected.matrix[r, c])
                        cells.append(
                            f'<td style="background:#fdd;border:2px solid #c00" '
                            f'title="{html.escape(tip)}">✗ {text}</td>'
                        )
                    elif (r, c) in unchecked:
                        tip = f"entry ({r + 1},{c + 1}) is too complicated to check"
                        cells.append(
                            f'<td style="background:#ffe9b3;border:2px solid #b80" '
                            f'title="{html.escape(tip)}">? {text}</td>'
                        )
                    else:
                        cells.append(f'<td style="background:#efe">{text}</td>')
                rows.append("<tr>" + "".join(cells) + "</tr>")
        verdict = "✔ correct" if self.ok else html.escape(str(self).split("\n")[0])
        hints = "".join(f"<li>{html.escape(h)}</li>" for h in self.hints)
        return (
            f"<div><b>{verdict}</b>"
            f'<table style="font-family:monospace;border-collapse:collapse">{"".join(rows)}</table>'
            + (f"<ul>{hints}</ul>" if hints else "")
            + "</div>"
        )


#: Entries with more nodes than this print unsorted (sorting a huge sum is slow).
_SORTED_PRINT_NODES = 200
#: Entries with more nodes than this are not printed at all, only described.
_PRINTED_NODES = 2000
#: Fractions with a larger denominator print as decimals (``cos(q1)/2`` stays exact,
#: ``13859/100`` is the student's 138.59).
_EXACT_DENOMINATOR = 12
#: Expected entries of at most this many nodes are shown trigonometrically simplified;
#: ``trigsimp`` of a tree this small takes milliseconds, of a large one it may not end.
_SIMPLIFIED_NODES = 40


def format_decimal(value: float) -> str:
    """A number as feedback shows it: 4–6 significant digits, no float noise.

    Four decimals at most for numbers of 1 and over (six significant digits at most),
    four significant digits below 1; trailing zeros are dropped.

    >>> format_decimal(-0.81725), format_decimal(138.59), format_decimal(20.0)
    ('-0.8173', '138.59', '20')
    >>> format_decimal(1 / 3), format_decimal(123456.789), format_decimal(0.000123456)
    ('0.3333', '123457', '0.0001235')
    """
    import math

    x = float(value)
    if not math.isfinite(x):
        return str(x)
    if x == 0:
        return "0"
    if abs(x) >= 1e6 or abs(x) < 1e-4:
        text = f"{x:.4g}"
    elif abs(x) >= 1:
        digits = int(math.floor(math.log10(abs(x)))) + 1
        text = f"{x:.{min(4, max(0, 6 - digits))}f}"
    else:
        text = f"{x:.4g}"
    if "." in text and "e" not in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _node_count(entry: Any, cap: int) -> int:
    """Nodes of ``entry``'s tree, counting stops past ``cap`` (a walk, no recursion)."""
    count, stack = 0, [entry]
    while stack and count <= cap:
        count += 1
        stack.extend(stack.pop().args)
    return count


def show_entry(entry: Any, limit: int = 300) -> str:
    """An entry as hints quote it: numbers as decimals, long formulas cut at ``limit``.

    Fractions a student typed as decimals show as decimals again (``-0.81725``, parsed
    exactly as -3269/4000, shows as ``-0.8173``); small fractions inside a formula
    (``cos(q1)/2``) stay exact.

    >>> import sympy
    >>> show_entry(sympy.Float(0.70710678)), show_entry(sympy.Symbol("q1") * 2)
    ('0.7071', '2*q1')
    >>> show_entry(sympy.Rational(-3269, 4000)), show_entry(sympy.Rational(13859, 100))
    ('-0.8173', '138.59')
    >>> show_entry(sympy.Rational(13859, 100) * sympy.cos(sympy.Symbol("q1")))
    '138.59*cos(q1)'
    """
    import sympy
    from sympy.printing.str import StrPrinter

    class _DecimalPrinter(StrPrinter):
        def _print_Float(self, expr: Any) -> str:
            return format_decimal(float(expr))

    if entry.is_Number:
        if entry.is_Integer:
            return str(entry)
        return format_decimal(float(entry))
    count = _node_count(entry, _PRINTED_NODES)
    if count > _PRINTED_NODES:
        return f"a formula of over {_PRINTED_NODES} parts"
    decimals = {
        number: sympy.Float(number, 17)
        for number in entry.atoms(sympy.Rational)
        if number.q > _EXACT_DENOMINATOR
    }
    if decimals:
        entry = entry.xreplace(decimals)
    printer = _DecimalPrinter({"order": "none" if count > _SORTED_PRINT_NODES else None})
    text = printer.doprint(entry)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def show_expected(entry: Any, limit: int = 300) -> str:
    """An expected entry as a revealing hint quotes it: simplified when that is cheap.

    The expected side is trusted, but a hint must not cost seconds: only an entry of at
    most 40 nodes holding ``sin``/``cos`` is passed through ``trigsimp``, and only when
    that makes it shorter. A constant (``sqrt(3)/2``, ``cos(pi/6)``) shows as a decimal,
    like the numbers a student types.

    >>> import sympy
    >>> a, b = sympy.symbols("q1 q2")
    >>> show_expected(sympy.cos(a) * sympy.cos(b) - sympy.sin(a) * sympy.sin(b))
    'cos(q1 + q2)'
    >>> show_expected(sympy.sqrt(3) / 2), show_expected(20 * sympy.cos(sympy.pi / 6))
    ('0.866', '17.3205')
    """
    import sympy

    small = _node_count(entry, _SIMPLIFIED_NODES) <= _SIMPLIFIED_NODES
    if not entry.free_symbols and not entry.is_Integer and small:
        value = complex(entry.evalf(17))
        if value.imag == 0:
            return format_decimal(value.real)
    if (
        not entry.is_Number
        and entry.has(sympy.sin, sympy.cos)
        and _node_count(entry, _SIMPLIFIED_NODES) <= _SIMPLIFIED_NODES
    ):
        simpler = sympy.trigsimp(entry)
        if sympy.count_ops(simpler) < sympy.count_ops(entry):
            entry = simpler
    return show_entry(entry, limit)
