"""The error for input a user can fix, as the report and the command line raise it."""

from __future__ import annotations

__all__ = ["BadInput"]


class BadInput(Exception):
    """Raised for input the user can fix; ``main`` prints it on one line, the panel shows it
    beside its report button."""
