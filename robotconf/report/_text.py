"""Text from untrusted files, made safe for a report: Markdown that shows exactly the
text, and one-line terminal messages."""

from __future__ import annotations

import unicodedata

__all__ = ["markdown_text", "one_line", "MAX_MESSAGE_CHARS"]

#: Longest error message printed (characters); the rest is cut, it stays one line.
MAX_MESSAGE_CHARS = 1000

# Bidirectional-text controls reorder what a reader sees; shown as their code instead.
_BIDI_CONTROLS = frozenset(
    "\u061c\u200e\u200f\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069"
)
_MARKDOWN_ENTITIES = {"&": "&amp;", "<": "&lt;", ">": "&gt;"}
# What means something inline in CommonMark or GitHub Markdown (code, emphasis, links and
# images, tables, strikethrough, $ math, attribute and superscript extensions) gets a
# backslash, which CommonMark allows before any ASCII punctuation. User text never starts
# a line, so list and heading markers need nothing; "(" only matters after "]".
_MARKDOWN_PUNCTUATION = frozenset("\\`*_{}[]#|$~^")


def _visible(text: str) -> str:
    """``text`` on one line: control characters become spaces, bidi controls ``\\u202e``."""
    out = []
    for char in text:
        if char in _BIDI_CONTROLS:
            out.append(f"\\u{ord(char):04x}")
        elif unicodedata.category(char) in ("Cc", "Zl", "Zp"):
            out.append(" ")
        else:
            out.append(char)
    return "".join(out)


def markdown_text(text: object) -> str:
    r"""User text as Markdown that shows exactly that text, on one line, with no markup.

    Parameters
    ----------
    text : object
        A name, label, unit or file name (``str()`` of anything else).

    Returns
    -------
    str
        ``<``, ``>`` and ``&`` as HTML entities, Markdown punctuation backslash-escaped,
        line breaks and other control characters as spaces.

    Examples
    --------
    >>> print(markdown_text("<img src=x onerror=alert(1)> *$x$* | [a](b)\n# h"))
    &lt;img src=x onerror=alert(1)&gt; \*\$x\$\* \| \[a\](b) \# h
    """
    escaped = []
    for char in _visible(str(text)):
        if char in _MARKDOWN_ENTITIES:
            escaped.append(_MARKDOWN_ENTITIES[char])
        elif char in _MARKDOWN_PUNCTUATION:
            escaped.append("\\" + char)
        else:
            escaped.append(char)
    return "".join(escaped)


def one_line(text: object) -> str:
    """A message for the terminal: one line, no control characters, bounded length.

    >>> one_line("a\\n  b\\x1b[31m")
    'a b [31m'
    """
    line = " ".join(_visible(str(text)).split())
    if len(line) > MAX_MESSAGE_CHARS:
        line = line[: MAX_MESSAGE_CHARS - 1] + "…"
    return line
