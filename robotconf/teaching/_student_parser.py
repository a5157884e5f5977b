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
from dataclasses import dataclass, fields
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from .._errors import InvalidInputError
from .._validation import check_integer
from ._slips import find_slip, power_slip, short_traceback, slip_error

if TYPE_CHECKING:  # pragma: no cover
    import sympy

__all__ = [
    "DEFAULT_SYMBOL_NAMES",
    "MAX_NUMBER_BITS",
    "ParserLimits",
    "parse_expression",
    "parse_matrix",
]

#: Symbols a student may use when no robot says otherwise.
DEFAULT_SYMBOL_NAMES = tuple(f"q{i}" for i in range(1, 13)) + tuple(f"l{i}" for i in range(1, 13))
_FUNCTIONS = ("sin", "cos", "tan", "sqrt")
_RESERVED = (*_FUNCTIONS, "pi", "Matrix")
_ASCII_ALLOWED = frozenset(
    "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_ \t\r\n+-*/().,[]^"
)
_UNICODE_SUBSTITUTES = {"−": "-", "·": "*", "×": "*", "π": "pi", "⋅": "*"}
_NODE_WORDS = {
    "Attribute": "attribute access (a dot after a name)",
    "Lambda": "a lambda",
    "ListComp": "a comprehension",
    "SetComp": "a comprehension",
    "DictComp": "a comprehension",
    "GeneratorExp": "a comprehension",
    "Subscript": "indexing with [ ] after a value",
    "Compare": "a comparison",
    "BoolOp": "'and'/'or'",
    "IfExp": "an if-expression",
    "Dict": "a dictionary",
    "Set": "a set",
    "Starred": "a * unpacking",
    "NamedExpr": "an assignment (:=)",
    "Await": "await",
    "Yield": "yield",
    "JoinedStr": "a string",
    "Slice": "a slice",
}
_OPERATORS = {"Add": "+", "Sub": "-", "Mult": "*", "Div": "/", "Pow": "**"}
#: Largest size (bits of numerator or denominator) of any number in a formula, about 1233
#: decimal digits (Python itself refuses to print an integer of over 4300 digits).
MAX_NUMBER_BITS = 4096


@dataclass(frozen=True)
class ParserLimits:
    """Caps that keep parsing fast whatever the input.

    Parameters
    ----------
    max_length : int
        Characters in the whole text.
    max_depth : int
        Nesting depth of brackets and of the syntax tree.
    max_exponent : int
        Largest absolute value of a numeric exponent (``q1**2`` is fine, ``2**99`` not).
    max_digits : int
        Digits in one number literal.
    max_entries : int
        Entries in a matrix.

    Raises
    ------
    InvalidInputError
        For a cap that is not an integer ≥ 1.

    Examples
    --------
    >>> ParserLimits(max_depth=10).max_depth
    10
    >>> ParserLimits(max_length=0)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: max_length: out of range: 0; allowed: an integer ≥ 1
    """

    max_length: int = 20_000
    max_depth: int = 40
    max_exponent: int = 64
    max_digits: int = 40
    max_entries: int = 400

    def __post_init__(self) -> None:
        for cap in fields(self):
            object.__setattr__(self, cap.name, check_integer(getattr(self, cap.name), cap.name, 1))


def _quote(text: str, node: ast.AST | None = None, limit: int = 60) -> str:
    part = ast.get_source_segment(text, node) if node is not None else text
    part = text if part is None else part
    return part if len(part) <= limit else part[: limit - 3] + "..."


def _allowed_text(names: Iterable[str]) -> str:
    shown = list(names)
    symbols = ", ".join(shown[:6]) + (", …" if len(shown) > 6 else "")
    return (
        f"numbers, the symbols {symbols}, pi, + - * / **, parentheses, "
        "sin cos tan sqrt, and [[…], …] for a matrix"
    )


class _Builder:
    """Check a syntax tree against the whitelist and build the sympy expression."""

    def __init__(self, text: str, names: dict[str, Any], limits: ParserLimits) -> None:
        import sympy

        self.sympy = sympy
        self.text = text
        self.names = names
        self.limits = limits
        self.allowed = _allowed_text(names)
        # Where each line starts, so a literal's text is a slice: ast.get_source_segment
        # re-splits the whole text on every call, quadratic over a long answer.
        starts = [0]
        for line in text.splitlines(keepends=True):
            starts.append(starts[-1] + len(line))
        self.line_starts = starts

    def segment(self, node: ast.AST) -> str:
        """The source text of ``node`` (the text is ASCII: columns are characters)."""
        line, end_line = getattr(node, "lineno", None), getattr(node, "end_lineno", None)
        column, end_column = (
            getattr(node, "col_offset", None),
            getattr(node, "end_col_offset", None),
        )
        if line is None or end_line is None or column is None or end_column is None:
            return ""
        return self.text[
            self.line_starts[line - 1] + column : self.line_starts[end_line - 1] + end_column
        ]

    def fail(self, node: ast.AST | None, problem: str) -> InvalidInputError:
        if isinstance(node, ast.Subscript) and isinstance(node.value, (ast.List, ast.Tuple)):
            slip = find_slip(self.text)  # "[1, 2] [3, 4]": a comma missing between rows
            if slip is not None:
                return slip_error("student", self.text, *slip, self.allowed)
        return InvalidInputError("student", _quote(self.text, node), self.allowed, problem=problem)

    # -- matrices -------------------------------------------------------------------

    def matrix(self, node: ast.AST) -> sympy.Matrix:
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Name)
            and node.func.id == "Matrix"
            and len(node.args) == 1
            and not node.keywords
        ):
            node = node.args[0]
        if not isinstance(node, (ast.List, ast.Tuple)):
            word = _NODE_WORDS.get(type(node).__name__)
            if word is not None:
                raise self.fail(node, f"{word} is not allowed:")
            raise self.fail(node, "expected a matrix written as [[…], […], …], got")
        if not node.elts:
            raise self.fail(node, "empty matrix:")
        if all(isinstance(e, (ast.List, ast.Tuple)) for e in node.elts):
            rows = [self.row(e) for e in node.elts]  # type: ignore[arg-type]
            width = len(rows[0])
            for e, row in zip(node.elts, rows, strict=True):
                if len(row) != width:
                    raise self.fail(
                        e, f"rows must all have {width} entries; this one has {len(row)}:"
                    )
        elif any(isinstance(e, (ast.List, ast.Tuple)) for e in node.elts):
            raise self.fail(node, "mixes rows in brackets and single entries:")
        else:
            rows = [[entry] for entry in self.row(node)]
        if len(rows) * len(rows[0]) > self.limits.max_entries:
            raise self.fail(node, f"more than {self.limits.max_entries} entries:")
        return self.sympy.Matrix(rows)

    def row(self, node: ast.List | ast.Tuple) -> list[Any]:
        if not node.elts:
            raise self.fail(node, "empty row:")
        for e in node.elts:
            if isinstance(e, (ast.List, ast.Tuple)):
                raise self.fail(e, "brackets nested too deep for a matrix:")
        return [self.expression(e) for e in node.elts]

    # -- scalars ----------------------------------------------------------------------

    def expression(self, node: ast.AST) -> Any:
        sympy = self.sympy
        if isinstance(node, ast.Constant):
            return self.constant(node)
        if isinstance(node, ast.Name):
            if node.id in self.names:
                return self.names[node.id]
            if node.id == "pi":
                return sympy.pi
            if node.id in _FUNCTIONS:
                raise self.fail(
                    node, f"{node.id} needs an argument in parentheses, e.g. {node.id}(q1):"
                )
            raise self.fail(node, "unknown name")
        if isinstance(node, ast.UnaryOp):
            if isinstance(node.op, ast.USub):
                return -self.expression(node.operand)
            if isinstance(node.op, ast.UAdd):
                return self.expression(node.operand)
            raise self.fail(node, "only - and + may stand before a value:")
        if isinstance(node, ast.BinOp):
            return self.binary(node)
        if isinstance(node, ast.Call):
            return self.call(node)
        if isinstance(node, (ast.List, ast.Tuple)):
            raise self.fail(node, "brackets inside a matrix entry:")
        word = _NODE_WORDS.get(type(node).__name__, type(node).__name__)
        raise self.fail(node, f"{word} is not allowed:")

    def constant(self, node: ast.Constant) -> Any:
        value = node.value
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            kind = "a string" if isinstance(value, (str, bytes)) else type(value).__name__
            raise self.fail(node, f"{kind} is not a number:")
        cap = self.limits.max_digits
        digits = sum(ch.isdigit() for ch in self.segment(node))
        # The value too: a hexadecimal literal has few decimal digits as typed, and
        # turning a huge integer into text fails in Python itself (over 4300 digits).
        if digits > cap or (isinstance(value, int) and abs(value) >= 10**cap):
            raise self.fail(node, f"a number with more than {cap} digits:")
        if isinstance(value, int):
            return self.sympy.Integer(value)
        if value != value or value in (float("inf"), float("-inf")):
            raise self.fail(node, "not a finite number:")
        fraction = Fraction(repr(value))  # the decimal the student typed, exactly
        return self.sympy.Rational(fraction.numerator, fraction.denominator)

    def binary(self, node: ast.BinOp) -> Any:
        op = type(node.op).__name__
        if op not in _OPERATORS:
            if op == "BitXor":
                raise self.fail(node, "^ is not a power in Python; write ** (q1**2):")
            raise self.fail(node, "only + - * / ** are allowed:")
        if op == "Pow":
            result = self.power(node, self.expression(node.left), self.expression(node.right))
        elif op in ("Add", "Sub"):
            terms = [
                self.expression(leaf) * sign for leaf, sign in self.chain(node, ("Add", "Sub"))
            ]
            result = self.sympy.Add(*terms)
        else:
            factors = []
            for leaf, sign in self.chain(node, ("Mult", "Div")):
                factor = self.expression(leaf)
                if sign < 0:
                    if factor == 0:
                        raise self.fail(leaf, "division by zero:")
                    factor = self.sympy.Pow(factor, -1)
                factors.append(factor)
            result = self.sympy.Mul(*factors)
        return self.finite(node, self.small_numbers(node, result))

    def chain(self, node: ast.BinOp, ops: tuple[str, str]) -> list[tuple[ast.AST, int]]:
        """The operands of ``a + b - c …`` (or ``a * b / c …``) with their signs, in order.

        A whole sum (product) is built by one sympy call: adding term by term would
        re-collect the terms at every step, quadratic over a long answer. The second op
        (``-``, ``/``) flips the sign of its right operand.
        """
        leaves: list[tuple[ast.AST, int]] = []
        stack: list[tuple[ast.AST, int]] = [(node, 1)]
        while stack:
            current, sign = stack.pop()
            name = type(current.op).__name__ if isinstance(current, ast.BinOp) else ""
            if name in ops:
                assert isinstance(current, ast.BinOp)
                flip = -1 if name == ops[1] else 1
                stack.append((current.right, sign * flip))  # popped after the left side
                stack.append((current.left, sign))
            else:
                leaves.append((current, sign))
        return leaves

    def small_numbers(self, node: ast.AST, value: Any) -> Any:
        """Refuse a result holding a number over :data:`MAX_NUMBER_BITS` bits.

        Products of allowed literals (``1e300*1e300*…``) would otherwise grow numbers
        without limit; printing one over 4300 digits even fails in Python itself.
        """
        if value.is_Atom and not value.is_Rational:
            return value
        numbers = [value] if value.is_Rational else value.atoms(self.sympy.Rational)
        for number in numbers:
            if max(int(number.p).bit_length(), int(number.q).bit_length()) > MAX_NUMBER_BITS:
                raise self.fail(node, "number too large:")
        return value

    def power(self, node: ast.BinOp, base: Any, exponent: Any) -> Any:
        sympy = self.sympy
        cap = self.limits.max_exponent
        if not exponent.is_Rational:
            raise self.fail(node, "exponents must be plain numbers such as 2 or 1/2:")
        if abs(exponent) > cap:
            raise self.fail(node, f"exponent larger than {cap}:")
        if base == 0 and exponent < 0:
            raise self.fail(node, "division by zero:")
        if base.is_Rational:
            bits = max(int(base.p).bit_length(), int(base.q).bit_length())
            if bits * abs(exponent) > MAX_NUMBER_BITS:
                raise self.fail(node, "number too large:")
        result = sympy.Pow(base, exponent)
        for power in result.atoms(sympy.Pow):
            if power.exp.is_Rational and abs(power.exp) > cap:
                raise self.fail(node, f"exponent larger than {cap} after combining powers:")
        return result

    def finite(self, node: ast.AST, value: Any) -> Any:
        sympy = self.sympy
        if value.has(sympy.zoo, sympy.nan, sympy.oo, -sympy.oo):
            raise self.fail(node, "division by zero or an infinite value:")
        return value

    def call(self, node: ast.Call) -> Any:
        sympy = self.sympy
        if not isinstance(node.func, ast.Name) or node.func.id not in _FUNCTIONS:
            raise self.fail(node, "only sin, cos, tan and sqrt may be called:")
        if len(node.args) != 1 or node.keywords or isinstance(node.args[0], ast.Starred):
            raise self.fail(node, f"{node.func.id} takes exactly one argument:")
        argument = self.expression(node.args[0])
        name = node.func.id
        if name == "sqrt":
            return self.finite(node, sympy.sqrt(argument))
        function = {"sin": sympy.sin, "cos": sympy.cos, "tan": sympy.tan}[name]
        if argument.is_number:  # exact values: sin(pi/6) is 1/2, tan(pi/2) infinite
            return self.finite(node, function(argument))
        # Of a formula, kept as typed: sympy's own simplification of the argument (looking
        # for multiples of pi, a minus sign) costs about a millisecond per call, seconds
        # over a long answer, and the checker compares values anyway.
        return function(argument, evaluate=False)


def _symbol_table(symbols: Iterable[Any] | None) -> dict[str, Any]:
    import sympy

    names = DEFAULT_SYMBOL_NAMES if symbols is None else symbols
    if isinstance(names, (str, bytes)):
        raise InvalidInputError("symbols", names, "a list of names such as ['q1', 'q2']")
    table = {}
    for item in names:
        name = item.name if isinstance(item, sympy.Symbol) else item
        if not isinstance(name, str) or not name.isidentifier() or not name.isascii():
            raise InvalidInputError("symbols", item, "names made of letters, digits and _")
        if name in _RESERVED:
            raise InvalidInputError("symbols", name, "names other than sin, cos, tan, sqrt, pi")
        table[name] = item if isinstance(item, sympy.Symbol) else sympy.Symbol(name, real=True)
    return table


def _check_text(text: Any, limits: ParserLimits, allowed: str) -> str:
    if not isinstance(text, str):
        raise InvalidInputError("student", text, allowed, problem="expected text, got")
    if len(text) > limits.max_length:
        raise InvalidInputError(
            "student",
            text[:40] + "...",
            allowed,
            problem=f"text too long ({len(text)} characters, at most {limits.max_length}):",
        )
    for bad, good in _UNICODE_SUBSTITUTES.items():
        text = text.replace(bad, good)
    for position, ch in enumerate(text):
        if ch not in _ASCII_ALLOWED:
            around = text[max(0, position - 15) : position + 15]
            raise InvalidInputError(
                "student", around, allowed, problem=f"character {ch!r} is not allowed, in"
            )
    run = 0
    for position, ch in enumerate(text):
        run = run + 1 if ch.isdigit() else 0
        if run > limits.max_digits:
            raise InvalidInputError(
                "student",
                text[max(0, position - 20) : position + 5] + "...",
                allowed,
                problem=f"a number with more than {limits.max_digits} digits:",
            )
    depth = deepest = 0
    for ch in text:
        if ch in "([":
            depth += 1
            deepest = max(deepest, depth)
        elif ch in ")]":
            depth -= 1
    if deepest > limits.max_depth:
        raise InvalidInputError(
            "student",
            text[:40] + ("..." if len(text) > 40 else ""),
            allowed,
            problem=f"brackets nested deeper than {limits.max_depth}:",
        )
    if not text.strip():
        raise InvalidInputError("student", text, allowed, problem="empty input:")
    return text


def _syntax_tree(text: str, limits: ParserLimits, allowed: str) -> ast.AST:
    __tracebackhide__ = True  # noqa: F841 (read by IPython and pytest)
    stripped = text.strip()
    if "^" in stripped:  # Python would read it as xor: it is never what a student means
        position = stripped.index("^")
        raise slip_error("student", stripped, position, power_slip(stripped, position), allowed)
    try:
        tree = ast.parse(stripped, mode="eval")
    except SyntaxError as error:
        # Python's own wording talks about Python ("Perhaps you forgot a comma?").
        slip = find_slip(stripped)
        if slip is None:
            lines = stripped.split("\n")
            row = min(max((error.lineno or 1) - 1, 0), len(lines) - 1)
            column = min(max((error.offset or 1) - 1, 0), len(lines[row]))
            position = sum(len(line) + 1 for line in lines[:row]) + column
            slip = (min(position, max(len(stripped) - 1, 0)), "cannot read the formula here")
        raise slip_error("student", stripped, *slip, allowed) from None
    except (ValueError, RecursionError, MemoryError, OverflowError):
        raise InvalidInputError(
            "student", text[:40], allowed, problem="formula too deeply nested or too large:"
        ) from None
    # Depth of the tree, iteratively (no recursion on hostile input).
    stack: list[tuple[ast.AST, int]] = [(tree, 0)]
    while stack:
        node, depth = stack.pop()
        if depth > limits.max_depth + 2:
            segment = ast.get_source_segment(text.strip(), node) or text[:40]
            raise InvalidInputError(
                "student",
                segment[:60],
                allowed,
                problem=f"formula nested deeper than {limits.max_depth}:",
            )
        stack.extend((child, depth + 1) for child in ast.iter_child_nodes(node))
    return tree


def _prepare(
    text: Any, symbols: Iterable[Any] | None, limits: ParserLimits | None
) -> tuple[_Builder, ast.AST]:
    limits = limits or ParserLimits()
    names = _symbol_table(symbols)
    allowed = _allowed_text(names)
    text = _check_text(text, limits, allowed)
    tree = _syntax_tree(text, limits, allowed)
    assert isinstance(tree, ast.Expression)
    return _Builder(text.strip(), names, limits), tree.body


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
    __tracebackhide__ = True  # noqa: F841 (read by IPython and pytest)
    try:
        builder, body = _prepare(text, symbols, limits)
        return builder.expression(body)
    except InvalidInputError as error:
        raise short_traceback(error) from None


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
    __tracebackhide__ = True  # noqa: F841 (read by IPython and pytest)
    try:
        builder, body = _prepare(text, symbols, limits)
        return builder.matrix(body)
    except InvalidInputError as error:
        raise short_traceback(error) from None
