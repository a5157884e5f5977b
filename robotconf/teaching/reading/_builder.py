"""Building the sympy expression from a checked syntax tree, node by node.

The second half of the whitelist parser (:mod:`._parser`): every node of the tree is
checked against a short whitelist while the expression is built by hand — numbers,
the allowed symbols and ``pi``, ``+ - * / **``, calls of ``sin``, ``cos``, ``tan``,
``sqrt``, ``asin``, ``acos``, ``atan`` with one argument and ``atan2(y, x)`` with two,
and list brackets for a matrix. Every number the formula
builds is capped (:data:`~._text.MAX_NUMBER_BITS`).
"""

from __future__ import annotations

import ast
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ..._errors import InvalidInputError
from ._slips import find_slip, slip_error
from ._text import (
    FUNCTION_WORDS,
    FUNCTIONS,
    MAX_NUMBER_BITS,
    NODE_WORDS,
    OPERATORS,
    ParserLimits,
    allowed_text,
    quote,
)

if TYPE_CHECKING:  # pragma: no cover
    import sympy

__all__ = ["Builder"]


class Builder:
    """Check a syntax tree against the whitelist and build the sympy expression."""

    def __init__(self, text: str, names: dict[str, Any], limits: ParserLimits) -> None:
        import sympy

        self.sympy = sympy
        self.text = text
        self.names = names
        self.limits = limits
        self.allowed = allowed_text(names)
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
        return InvalidInputError("student", quote(self.text, node), self.allowed, problem=problem)

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
            word = NODE_WORDS.get(type(node).__name__)
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
            if node.id in FUNCTIONS:
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
        word = NODE_WORDS.get(type(node).__name__, type(node).__name__)
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
        if op not in OPERATORS:
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
        if not isinstance(node.func, ast.Name) or node.func.id not in FUNCTIONS:
            raise self.fail(node, f"only {FUNCTION_WORDS} may be called:")
        name = node.func.id
        count = 2 if name == "atan2" else 1
        if (
            len(node.args) != count
            or node.keywords
            or any(isinstance(a, ast.Starred) for a in node.args)
        ):
            words = "two arguments, atan2(y, x)" if count == 2 else "exactly one argument"
            raise self.fail(node, f"{name} takes {words}:")
        arguments = [self.expression(a) for a in node.args]
        if name == "atan2":
            y, x = arguments
            if y.is_number and x.is_number and y.is_zero and x.is_zero:
                raise self.fail(node, "atan2(0, 0) has no angle:")
            return self.finite(node, sympy.atan2(y, x))
        argument = arguments[0]
        if name == "sqrt":
            return self.finite(node, sympy.sqrt(argument))
        if name in ("asin", "acos") and argument.is_number and abs(argument) > 1:
            raise self.fail(node, f"{name} takes a number from -1 to 1:")
        function = {
            "sin": sympy.sin,
            "cos": sympy.cos,
            "tan": sympy.tan,
            "asin": sympy.asin,
            "acos": sympy.acos,
            "atan": sympy.atan,
        }[name]
        if argument.is_number:  # exact values: sin(pi/6) is 1/2, tan(pi/2) infinite
            return self.finite(node, function(argument))
        # Of a formula, kept as typed: sympy's own simplification of the argument (looking
        # for multiples of pi, a minus sign) costs about a millisecond per call, seconds
        # over a long answer, and the checker compares values anyway.
        return function(argument, evaluate=False)
