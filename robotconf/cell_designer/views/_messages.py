"""What the designer says beside a control: the core's refusal, and the text refused.

A refusal is about a keystroke, not about the cell, so it is not part of the state: it is
kept here by control key until that control is used successfully or the document is
replaced (undo, redo, a load). Messages are shown in the designer's units (the core's
radians in degrees, ``length`` named).
"""

from __future__ import annotations

from collections.abc import Iterator

from ...panel.state import Units, in_units

__all__ = ["Messages"]


class Messages:
    """Messages beside controls, keyed by the control (``"entry[2].pose0"``).

    Examples
    --------
    >>> messages = Messages()
    >>> messages.refused("entry[0].size0", "size[0]: out of range: -1.0; …", typed="-1")
    >>> messages.text("entry[0].size0"), messages.typed("entry[0].size0")
    ('size[0]: out of range: -1.0; …', '-1')
    >>> messages.accepted("entry[0].size0"); messages.text("entry[0].size0")
    ''
    """

    def __init__(self) -> None:
        self._messages: dict[str, tuple[str, str | None]] = {}
        self.units = Units()

    def refused(self, key: str, message: str, typed: str | None = None) -> None:
        """Show ``message`` beside ``key`` (and keep ``typed`` in its box)."""
        self._messages[key] = (message, typed)

    def accepted(self, key: str) -> None:
        """``key`` was used successfully: its message goes."""
        self._messages.pop(key, None)

    def clear(self) -> None:
        """Every message goes (the document was replaced)."""
        self._messages.clear()

    def text(self, key: str) -> str:
        """The message beside ``key`` in the designer's units (``""``: none)."""
        found = self._messages.get(key)
        return in_units(found[0], self.units) if found else ""

    def typed(self, key: str) -> str | None:
        """What was typed into ``key`` and refused, if anything."""
        found = self._messages.get(key)
        return found[1] if found else None

    def items(self) -> Iterator[tuple[str, str]]:
        """``(key, message)`` of every message shown."""
        for key in list(self._messages):
            yield key, self.text(key)
