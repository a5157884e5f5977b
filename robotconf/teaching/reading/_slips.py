"""Typing slips in a student's formula, told in one line with a caret under the spot.

Python's own syntax errors talk about Python ("invalid syntax. Perhaps you forgot a
comma?") and come with a traceback through the checker. A student who typed ``cos q2``
needs "write cos(q2)" and where. :func:`find_slip` reads the text as a plain list of
tokens (no evaluation, linear in its length) and names the first slip it recognises;
:func:`slip_error` turns it into an :class:`~robotconf.InvalidInputError` whose message
is the quoted text with the advice, and a second line with a caret under the spot.
:func:`~._wrapper.short_traceback` makes such an error show as its message alone in
IPython.
"""

from __future__ import annotations

import re
from typing import Any

from ..._errors import InvalidInputError

__all__ = ["find_slip", "power_slip", "slip_error", "slip_in_entry"]

_FUNCTIONS = ("sin", "cos", "tan", "sqrt")
_OPENERS = {"(": ")", "[": "]"}
_CLOSERS = {")": "(", "]": "["}
#: Characters of the quoted text shown around the slip (long answers are cut around it).
_WINDOW = 60
_TOKEN = re.compile(
    r"(?P<number>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)"
    r"|(?P<name>[A-Za-z_]\w*)"
    r"|(?P<op>\*\*|[-+*/^])"
    r"|(?P<bracket>[()\[\]])"
    r"|(?P<comma>,)"
    r"|(?P<space>\s+)"
    r"|(?P<other>.)",
    re.DOTALL,
)


def _tokens(text: str) -> list[tuple[str, str, int]]:
    """``(kind, text, position)`` of every token but whitespace."""
    found = []
    for match in _TOKEN.finditer(text):
        kind = match.lastgroup or "other"
        if kind != "space":
            found.append((kind, match.group(), match.start()))
    return found


def _is_value(kind: str, word: str) -> bool:
    return kind == "number" or (kind == "name" and word not in (*_FUNCTIONS, "Matrix"))


def power_slip(text: str, position: int) -> str:
    """The advice for a ``^`` at ``position``: Python writes powers as ``**``.

    >>> power_slip("q1^2", 2)
    'use ** for powers: q1**2'
    """
    left = re.search(r"[\w.)\]]+$", text[:position].rstrip())
    right = re.match(r"[\w.(]+", text[position + 1 :].lstrip())
    if left and right:
        return f"use ** for powers: {left.group()}**{right.group()}"
    return "use ** for powers"


def find_slip(text: str) -> tuple[int, str] | None:
    """The first typing slip in ``text``: its position and what to write instead.

    Only called on text Python cannot read (or reads as something else, such as
    ``[1, 2] [3, 4]``), so every finding is a real mistake.

    Parameters
    ----------
    text : str
        ASCII text of a formula or matrix.

    Returns
    -------
    (int, str) or None
        0-based position of the slip and the advice; ``None`` if none is recognised.

    Examples
    --------
    >>> find_slip("cos q2")
    (4, 'write cos(q2)')
    >>> find_slip("sin(q1")
    (3, 'this ( is never closed: add )')
    """
    tokens = _tokens(text)
    stack: list[tuple[str, int]] = []
    previous: tuple[str, str, int] | None = None
    for index, (kind, word, position) in enumerate(tokens):
        if word == "^":
            return position, power_slip(text, position)
        if kind == "other":
            return position, f"{word!r} cannot stand here"
        if previous is not None:
            slip = _pair_slip(previous, (kind, word, position), tokens[index + 1 :], stack)
            if slip is not None:
                return slip
        elif kind == "op" and word in ("*", "/", "**"):
            return position, f"something is missing before {word}"
        elif kind == "comma":
            return position, "something is missing before the comma"
        if kind == "bracket":
            if word in _OPENERS:
                stack.append((word, position))
            elif not stack:
                return position, f"this {word} has no matching {_CLOSERS[word]}"
            elif stack[-1][0] != _CLOSERS[word]:
                return position, f"a {_OPENERS[stack[-1][0]]} is missing before this {word}"
            else:
                stack.pop()
        previous = (kind, word, position)
    if previous is not None and previous[0] == "op":
        return previous[2], f"something is missing after {previous[1]}"
    if stack:
        opener, position = stack[-1]
        return position, f"this {opener} is never closed: add {_OPENERS[opener]}"
    return None


def _pair_slip(
    previous: tuple[str, str, int],
    current: tuple[str, str, int],
    rest: list[tuple[str, str, int]],
    stack: list[tuple[str, int]],
) -> tuple[int, str] | None:
    """A slip made by two neighbouring tokens, e.g. ``cos q2``, ``2 q1``, ``] [``."""
    p_kind, p_word, p_position = previous
    kind, word, position = current
    ends_value = _is_value(p_kind, p_word) or p_word in (")", "]")
    starts_value = _is_value(kind, word) or word in ("(", "[") or kind == "name"
    if p_kind == "name" and p_word in _FUNCTIONS and word != "(":
        if _is_value(kind, word):
            after = rest[0][1] if rest else ""
            if after in ("(", "[", "*", "/", "**", "^"):
                return position, f"put the argument of {p_word} in parentheses: {p_word}(…)"
            return position, f"write {p_word}({word})"
        return position, f"{p_word} needs its argument in parentheses, e.g. {p_word}(q1)"
    if ends_value and starts_value:
        if p_word == "]" and word == "[":
            return position, "a comma is missing between ] and ["
        if p_kind == kind == "number" and stack and stack[-1][0] == "[":
            return position, f"a comma is missing between entries: {p_word}, {word}"
        if _is_value(p_kind, p_word) and _is_value(kind, word):
            return position, f"multiplication needs *: write {p_word}*{word}"
        if _is_value(p_kind, p_word) and word in _FUNCTIONS:
            return position, f"multiplication needs *: write {p_word}*{word}(…)"
        return position, f"multiplication needs *: put * between {p_word} and {word}"
    if p_kind == "op":
        if kind == "op" and word in ("*", "/", "**"):
            return position, f"two operators in a row: {p_word} {word}"
        if word in (")", "]") or kind == "comma":
            return p_position, f"something is missing after {p_word}"
    if p_word in ("(", "[") or p_kind == "comma":
        if kind == "op" and word in ("*", "/", "**"):
            return position, f"something is missing before {word}"
        if kind == "comma":
            return position, "an entry is missing before this comma"
        if p_word == "(" and word == ")":
            return position, "empty parentheses: something is missing inside"
    return None


def _shown(text: str, position: int) -> tuple[str, int]:
    """The line of ``text`` holding ``position``, cut to a window; the column in it."""
    start = text.rfind("\n", 0, position) + 1
    end = text.find("\n", position)
    line = text[start : len(text) if end < 0 else end].rstrip()
    column = position - start
    if len(line) > _WINDOW:  # keep the slip in view, with some text on both sides
        left = max(0, min(column - _WINDOW // 2, len(line) - _WINDOW))
        cut = line[left : left + _WINDOW]
        prefix = "..." if left else ""
        suffix = "..." if left + _WINDOW < len(line) else ""
        line, column = prefix + cut + suffix, column - left + len(prefix)
    return line, min(column, max(len(line) - 1, 0))


def slip_error(field: str, text: str, position: int, advice: str, allowed: str) -> Any:
    """An :class:`~robotconf.InvalidInputError`: the text and advice, then a caret line.

    Like every such error, the message starts with the field.

    Parameters
    ----------
    field : str
        ``"student"`` or ``"student[r][c]"``.
    text : str
        The student's text.
    position : int
        0-based position of the slip in ``text``.
    advice : str
        What to write instead.
    allowed : str
        What the parser accepts (kept on the error, not in the message).

    Returns
    -------
    InvalidInputError

    Examples
    --------
    >>> print(slip_error("student", "2 q1", 2, "multiplication needs *: write 2*q1", ""))
    student: `2 q1`: multiplication needs *: write 2*q1
                ^
    """
    line, column = _shown(text, position)
    error = InvalidInputError(field, line, allowed, problem=advice)
    # One line a student reads, the caret under the spot (the backtick takes a column).
    head = f"{field}: `"
    error.args = (f"{head}{line}`: {advice}\n{' ' * (len(head) + column)}^",)
    return error


def slip_in_entry(error: InvalidInputError, field: str) -> InvalidInputError:
    """The same error for one entry of a list answer, named by ``field``.

    >>> error = slip_in_entry(slip_error("student", "cos q2", 4, "write cos(q2)", ""),
    ...                       "student[0][1]")
    >>> print(error)
    student[0][1]: `cos q2`: write cos(q2)
                         ^
    """
    moved = InvalidInputError(field, error.value, error.allowed, error.problem)
    lines = str(error).split("\n")
    old = f"{error.field}: "
    if len(lines) == 2 and lines[1].strip() == "^" and lines[0].startswith(old):
        shift = len(field) - len(error.field)  # a slip: move the caret with the text
        moved.args = (f"{field}: {lines[0][len(old) :]}\n{' ' * shift}{lines[1]}",)
    return moved
