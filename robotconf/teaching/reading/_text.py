"""Student text before it is parsed: the caps, the characters allowed, the syntax tree.

The first half of the whitelist parser (:mod:`._parser`): the text is checked character
by character and against the caps of :class:`ParserLimits`, then read into a Python
syntax tree with :func:`ast.parse` (which only *reads* code), its depth checked
iteratively. A typing slip Python cannot read gets one line of advice
(:mod:`._slips`).
"""

from __future__ import annotations

import ast
from collections.abc import Iterable
from dataclasses import dataclass, fields
from typing import Any

from ..._errors import InvalidInputError
from ..._validation import check_integer
from ._slips import find_slip, power_slip, slip_error

__all__ = [
    "DEFAULT_SYMBOL_NAMES",
    "FUNCTIONS",
    "FUNCTION_WORDS",
    "MAX_NUMBER_BITS",
    "NODE_WORDS",
    "OPERATORS",
    "ParserLimits",
    "allowed_text",
    "check_text",
    "quote",
    "symbol_table",
    "syntax_tree",
]

#: Symbols a student may use when no robot says otherwise.
DEFAULT_SYMBOL_NAMES = tuple(f"q{i}" for i in range(1, 13)) + tuple(f"l{i}" for i in range(1, 13))
#: The functions a student may call (``atan2(y, x)`` takes two arguments, the rest one):
#: what a hand derivation uses, inverse kinematics' angles included.
FUNCTIONS = ("sin", "cos", "tan", "sqrt", "asin", "acos", "atan", "atan2")
#: The same, in words, for the messages.
FUNCTION_WORDS = ", ".join(FUNCTIONS[:-1]) + f" and {FUNCTIONS[-1]}"
RESERVED = (*FUNCTIONS, "pi", "Matrix")
_ASCII_ALLOWED = frozenset(
    "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_ \t\r\n+-*/().,[]^"
)
_UNICODE_SUBSTITUTES = {"−": "-", "·": "*", "×": "*", "π": "pi", "⋅": "*"}
NODE_WORDS = {
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
OPERATORS = {"Add": "+", "Sub": "-", "Mult": "*", "Div": "/", "Pow": "**"}
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


def quote(text: str, node: ast.AST | None = None, limit: int = 60) -> str:
    part = ast.get_source_segment(text, node) if node is not None else text
    part = text if part is None else part
    return part if len(part) <= limit else part[: limit - 3] + "..."


def allowed_text(names: Iterable[str]) -> str:
    shown = list(names)
    symbols = ", ".join(shown[:6]) + (", …" if len(shown) > 6 else "")
    return (
        f"numbers, the symbols {symbols}, pi, + - * / **, parentheses, "
        f"{' '.join(FUNCTIONS)}, and [[…], …] for a matrix"
    )


#: Symbol tables already built, by their names (making sympy symbols is not free, and a
#: DH table parses a dozen entries with the same names).
_TABLES: dict[tuple[str, ...], dict[str, Any]] = {}


def symbol_table(symbols: Iterable[Any] | None) -> dict[str, Any]:

    names = DEFAULT_SYMBOL_NAMES if symbols is None else symbols
    if isinstance(names, (str, bytes)):
        raise InvalidInputError("symbols", names, "a list of names such as ['q1', 'q2']")
    key = tuple(names) if isinstance(names, (tuple, list)) else None
    if key is not None and all(isinstance(x, str) for x in key):
        if key not in _TABLES:
            if len(_TABLES) >= 256:
                _TABLES.clear()
            _TABLES[key] = _build(key)
        return dict(_TABLES[key])
    return _build(names)


def _build(names: Iterable[Any]) -> dict[str, Any]:
    import sympy

    table = {}
    for item in names:
        name = item.name if isinstance(item, sympy.Symbol) else item
        if not isinstance(name, str) or not name.isidentifier() or not name.isascii():
            raise InvalidInputError("symbols", item, "names made of letters, digits and _")
        if name in RESERVED:
            raise InvalidInputError("symbols", name, f"names other than {FUNCTION_WORDS}, pi")
        table[name] = item if isinstance(item, sympy.Symbol) else sympy.Symbol(name, real=True)
    return table


def check_text(text: Any, limits: ParserLimits, allowed: str) -> str:
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


def syntax_tree(text: str, limits: ParserLimits, allowed: str) -> ast.AST:
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
