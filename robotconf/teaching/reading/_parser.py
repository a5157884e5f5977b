"""A whitelist parser for matrices and expressions typed by students.

Student text is hostile input. It is never handed to Python or to sympy's own text
parsers (both evaluate Python). Instead the text is checked character by character,
parsed into a Python syntax tree with :func:`ast.parse` (which only *reads* code), and
every node of that tree is checked against a short whitelist while the sympy expression
is built by hand:

- numbers (integers and decimals; no complex numbers, no booleans, no strings),
- the allowed symbols (by default ``q1 … q12`` and ``l1 … l12``) and ``pi``,
- ``+ - * / **``, unary minus and plus, parentheses,
- calls of ``sin``, ``cos``, ``tan``, ``sqrt`` with exactly one argument,
- list brackets for a matrix: ``[[row], [row], …]`` (``Matrix([[…]])`` as printed by
  sympy is accepted too), or ``[a, b, c]`` for a column.

Input length, nesting depth, the number of digits in a literal (as typed, and as a value:
a hexadecimal ``0xfff…`` counts too), the size of exponents and of every number the
formula builds (:data:`MAX_NUMBER_BITS`) are capped, so ``9**9**9``, ``1e300*1e300*…`` or
a megabyte of text is refused at once. Every refusal is an
:class:`~robotconf.InvalidInputError` quoting the offending part. Sums and products are
built in one sympy call each and ``sin``/``cos``/``tan`` of a formula are kept as typed
(not rewritten), so even the longest allowed text parses in a fraction of a second.
"""

from __future__ import annotations

import ast
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from ._builder import Builder
from ._text import (
    DEFAULT_SYMBOL_NAMES,
    MAX_NUMBER_BITS,
    ParserLimits,
    allowed_text,
    check_text,
    symbol_table,
    syntax_tree,
)
from ._wrapper import answer_check

if TYPE_CHECKING:  # pragma: no cover
    import sympy

__all__ = [
    "DEFAULT_SYMBOL_NAMES",
    "MAX_NUMBER_BITS",
    "ParserLimits",
    "parse_expression",
    "parse_matrix",
]


def _prepare(
    text: Any, symbols: Iterable[Any] | None, limits: ParserLimits | None
) -> tuple[Builder, ast.AST]:
    limits = limits or ParserLimits()
    names = symbol_table(symbols)
    allowed = allowed_text(names)
    text = check_text(text, limits, allowed)
    tree = syntax_tree(text, limits, allowed)
    assert isinstance(tree, ast.Expression)
    return Builder(text.strip(), names, limits), tree.body


@answer_check
def parse_expression(
    text: str, symbols: Iterable[Any] | None = None, limits: ParserLimits | None = None
) -> sympy.Expr:
    """Parse one scalar formula typed by a student.

    Parameters
    ----------
    text : str
        E.g. ``"l2*cos(q1)*cos(q2)"``. ``^`` is refused with a hint to write ``**``.
    symbols : iterable of str or sympy.Symbol, optional
        Names the student may use; default ``q1 … q12`` and ``l1 … l12`` (real symbols).
    limits : ParserLimits, optional

    Returns
    -------
    sympy.Expr

    Raises
    ------
    InvalidInputError
        For anything outside the whitelist, quoting the offending part.

    Examples
    --------
    >>> parse_expression("-sin(q1) * (l1 + 2.5)")
    -(l1 + 5/2)*sin(q1)
    >>> parse_expression("__import__('os')")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: student: character "'" is not allowed, in "__import__('os')"; ...
    """
    builder, body = _prepare(text, symbols, limits)
    return builder.expression(body)


@answer_check
def parse_matrix(
    text: str, symbols: Iterable[Any] | None = None, limits: ParserLimits | None = None
) -> sympy.Matrix:
    """Parse a matrix typed by a student.

    Parameters
    ----------
    text : str
        Rows in brackets, ``"[[cos(q1), -sin(q1), 0, 0], …]"``; ``Matrix([[…]])`` as sympy
        prints it is accepted; a flat ``"[x, y, z]"`` is a column, shape (3, 1).
    symbols : iterable of str or sympy.Symbol, optional
        Names the student may use; default ``q1 … q12`` and ``l1 … l12`` (real symbols).
    limits : ParserLimits, optional

    Returns
    -------
    sympy.Matrix, shape (rows, cols)

    Raises
    ------
    InvalidInputError
        For anything outside the whitelist, ragged rows, or input over the limits.

    Examples
    --------
    >>> parse_matrix("[[cos(q1), -sin(q1)], [sin(q1), cos(q1)]]")
    Matrix([
    [cos(q1), -sin(q1)],
    [sin(q1),  cos(q1)]])
    >>> parse_matrix("[[1, 2], [3]]")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: student: rows must all have 2 entries; this one has 1: '[3]'; ...
    """
    builder, body = _prepare(text, symbols, limits)
    return builder.matrix(body)
