"""Formulas and numbers as hints quote them: decimals, cut when long, simplified if cheap."""

from __future__ import annotations

from typing import Any

__all__ = ["format_decimal", "number_text", "sentence", "show_entry", "show_expected"]


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


def number_text(value: float) -> str:
    """A number as hints quote it: at most 4 significant digits, no float noise.

    >>> number_text(3.141592653589793), number_text(-99.0), number_text(1e-7), number_text(123456.0)
    ('3.142', '-99', '1e-07', '1.235e+05')
    """
    x = float(value)
    if x == 0:
        return "0"
    return f"{x:.4g}"


def sentence(text: str) -> str:
    """``text`` with a capital first letter when it starts with an article (not ``q3``)."""
    if text.startswith(("the ", "a ", "an ")):
        return text[0].upper() + text[1:]
    return text
