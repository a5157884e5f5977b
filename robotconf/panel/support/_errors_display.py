"""A small red message shown next to the control whose input the core refused.

The panel never invents its own error texts: it shows the message of the core's
:class:`~robotconf.InvalidInputError` (which names the field, the value and what is
allowed) beside the control that caused it, and keeps the last valid robot.
"""

from __future__ import annotations

import html
from collections.abc import Iterable, Iterator

import ipywidgets as widgets

__all__ = ["ErrorLabel", "collect_errors"]

_STYLE = "color:#b00020;font-size:0.85em;line-height:1.2"


class ErrorLabel:
    """An HTML widget that is empty until a message is shown.

    Examples
    --------
    >>> label = ErrorLabel()
    >>> label.show("dt: must be positive, got 0.0; allowed: a time step > 0 (s)")
    >>> label.message
    'dt: must be positive, got 0.0; allowed: a time step > 0 (s)'
    >>> label.clear(); label.message
    ''
    """

    def __init__(self) -> None:
        self.widget = widgets.HTML(value="", layout=widgets.Layout(margin="0 0 0 6px"))
        self._message = ""

    @property
    def message(self) -> str:
        """The message shown, or ``""``."""
        return self._message

    def show(self, message: str) -> None:
        """Show ``message`` (plain text, escaped) in red."""
        if message == self._message:
            return
        self._message = message
        self.widget.value = f'<span style="{_STYLE}">⚠ {html.escape(message)}</span>'

    def clear(self) -> None:
        """Hide the message."""
        if self._message:
            self._message = ""
            self.widget.value = ""


def collect_errors(items: Iterable[tuple[str, ErrorLabel]]) -> Iterator[tuple[str, str]]:
    """The ``(control key, message)`` pairs of the labels that show a message."""
    for key, label in items:
        if label.message:
            yield key, label.message
