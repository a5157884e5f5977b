"""What the panel says beside a control: the core's refusal, and the text that was refused.

When the student types ``abc`` into q2's box, or a value the core refuses, the state does
not change; the box keeps showing what they typed and the message beside it says why.
That message is not part of the state (it is about a keystroke, not about the robot); it
lives here, keyed by the control, until the same control is used again successfully or
the document is replaced (undo, redo, a load).
"""

from __future__ import annotations

from collections.abc import Iterator

from .state import Units, in_units
from .support import LOGGER, Refusal, failure_message

__all__ = ["Feedback", "Refusal", "failure_message", "LOGGER"]


class Feedback:
    """Messages beside controls, keyed by the control (``"modules[1].q"``).

    Examples
    --------
    >>> feedback = Feedback()
    >>> feedback.refused("modules[1].q", "q2: not a number: 'abc'", typed="abc")
    >>> feedback.message("modules[1].q"), feedback.typed("modules[1].q")
    ("q2: not a number: 'abc'", 'abc')
    >>> feedback.accepted("modules[1].q"); feedback.message("modules[1].q")
    ''
    """

    def __init__(self) -> None:
        self._messages: dict[str, tuple[str, str | None]] = {}
        #: Bumped at every change, so a view can tell whether to draw again.
        self.version = 0
        #: The panel's units: messages speak them (:func:`~.state.in_units`).
        self.units = Units()

    def show_in(self, units: Units) -> None:
        """Say every message in ``units`` from now on (the student switched units)."""
        if units != self.units:
            self.units = units
            self.version += 1

    def refused(self, key: str, message: str, typed: str | None = None) -> None:
        """Show ``message`` beside control ``key`` (and keep ``typed`` in its box)."""
        self._messages[key] = (message, typed)
        self.version += 1

    def accepted(self, key: str) -> None:
        """Control ``key`` was used successfully: its message goes."""
        if self._messages.pop(key, None) is not None:
            self.version += 1

    def clear(self) -> None:
        """Every message goes (the document was replaced: undo, redo, a load)."""
        if self._messages:
            self._messages.clear()
            self.version += 1

    def message(self, key: str) -> str:
        """The message beside ``key`` (``""`` for none)."""
        found = self._messages.get(key)
        return in_units(found[0], self.units) if found else ""

    def typed(self, key: str) -> str | None:
        """What the student typed into ``key`` that was refused, if anything."""
        found = self._messages.get(key)
        return found[1] if found else None

    def items(self) -> Iterator[tuple[str, str]]:
        """``(key, message)`` of every message shown."""
        for key, (message, _) in self._messages.items():
            yield key, in_units(message, self.units)

    def under(self, prefix: str) -> Iterator[tuple[str, str]]:
        """``(key, message)`` of the messages of controls whose key starts with ``prefix``."""
        for key, message in self.items():
            if key.startswith(prefix):
                yield key, message
