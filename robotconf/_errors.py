"""The exception raised for every kind of bad input."""

from __future__ import annotations

import re
from typing import Any

__all__ = ["InvalidInputError"]


def _short_repr(value: Any, limit: int = 80) -> str:
    # One line, so a panel label, a CLI error and a log entry stay one line for arrays too.
    try:
        text = re.sub(r"\s*\n\s*", " ", repr(value))
    except ValueError:  # an integer too long for Python to print
        text = f"<{type(value).__name__} too long to show>"
    return text if len(text) <= limit else text[: limit - 3] + "..."


class InvalidInputError(ValueError):
    """Bad input to robotconf: names the field, the value and what is allowed.

    It is a :class:`ValueError`, so ``except ValueError`` catches it. The attributes let a
    widget panel show the message beside the control that caused it.

    Parameters
    ----------
    field : str
        The input that was wrong, e.g. ``"kind"``, ``"a"``, ``"q"`` or ``"modules[2].a"``.
    value : object
        The offending value (shortened in the message when long).
    allowed : str
        What would have been accepted.
    problem : str, optional
        What is wrong with the value, when "invalid" alone would not say it.

    Examples
    --------
    >>> err = InvalidInputError("kind", "Rw", "none, Rx, Ry, Rz, Tx, Ty, Tz, fixed")
    >>> str(err)
    "kind: invalid value 'Rw'; allowed: none, Rx, Ry, Rz, Tx, Ty, Tz, fixed"
    >>> isinstance(err, ValueError)
    True
    """

    def __init__(self, field: str, value: Any, allowed: str, problem: str = "invalid value"):
        self.field = field
        self.value = value
        self.allowed = allowed
        self.problem = problem
        super().__init__(f"{field}: {problem} {_short_repr(value)}; allowed: {allowed}")

    def within(self, prefix: str) -> InvalidInputError:
        """The same error with its field placed inside a container field.

        >>> InvalidInputError("a", (1, 2), "3 numbers").within("modules[1]").field
        'modules[1].a'
        """
        return InvalidInputError(f"{prefix}.{self.field}", self.value, self.allowed, self.problem)


# Tracebacks and doctests show the public name.
InvalidInputError.__module__ = "robotconf"
