"""Reading a student's answer: a whitelist parser, and numbers within a budget.

Student text is hostile input: it is never evaluated. It is checked character by
character, read into a Python syntax tree and built into sympy node by node against a
whitelist; every entry is then evaluated by a numpy walk of its tree at seeded sample
points, and algebra runs only within a documented budget. A typing slip gets one line of
advice with a caret under the spot.

The parser
    :func:`parse_expression`, :func:`parse_matrix`, :class:`ParserLimits`,
    :data:`DEFAULT_SYMBOL_NAMES`
Typing slips and short tracebacks
    :func:`find_slip`, :func:`short_traceback`
Numbers as hints quote them
    :func:`format_decimal`, :func:`number_text`, :func:`show_entry`, :func:`show_expected`

>>> parse_expression("2*cos(q1)")
2*cos(q1)
"""

from ._parser import DEFAULT_SYMBOL_NAMES, ParserLimits, parse_expression, parse_matrix
from ._shown import format_decimal, number_text, show_entry, show_expected
from ._slips import find_slip
from ._tolerance import ROUNDING_RULE
from ._wrapper import short_traceback

__all__ = [
    "parse_expression",
    "parse_matrix",
    "ParserLimits",
    "DEFAULT_SYMBOL_NAMES",
    "find_slip",
    "short_traceback",
    "format_decimal",
    "number_text",
    "show_entry",
    "show_expected",
    "ROUNDING_RULE",
]
