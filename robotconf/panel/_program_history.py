"""Undo and redo for the Program tab: its own ↶ ↷ over the drafts it showed.

The panel's header undo (``_history.py``) steps through robots and reads each entry's
coordinate count, so a program edit (which leaves the robot alone) gets its own list:
every draft the table showed, newest last, one entry per edit (a typed number is sent
once, when the box is left or Enter pressed, so there is no drag to merge). The oldest
go beyond :data:`~robotconf.panel._history.HISTORY_LIMIT`.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Generic, TypeVar

import ipywidgets as widgets

from ._callbacks import on_click
from ._errors_display import ErrorLabel
from ._history import HISTORY_LIMIT

__all__ = ["Timeline", "TimelineButtons"]

T = TypeVar("T")


class Timeline(Generic[T]):
    """Values for undo and redo, newest last; equal values are not recorded twice.

    Examples
    --------
    >>> timeline = Timeline("a")
    >>> timeline.record("b"), timeline.record("b"), timeline.record("c")
    (True, False, True)
    >>> timeline.undo(), timeline.undo(), timeline.undo(), timeline.redo()
    ('b', 'a', None, 'b')
    >>> timeline.record("d"); timeline.can_redo  # a new edit forgets what was undone
    True
    False
    """

    def __init__(self, first: T, limit: int = HISTORY_LIMIT):
        self.limit = max(int(limit), 2)
        self._values: list[T] = [first]
        self._index = 0

    def __len__(self) -> int:
        return len(self._values)

    @property
    def current(self) -> T:
        """The value the timeline is at."""
        return self._values[self._index]

    @property
    def can_undo(self) -> bool:
        """Whether there is a value before the current one."""
        return self._index > 0

    @property
    def can_redo(self) -> bool:
        """Whether an undo can be redone."""
        return self._index < len(self._values) - 1

    def record(self, value: T) -> bool:
        """Make ``value`` the current entry; ``False`` when it is the current one already."""
        if value == self.current:
            return False
        del self._values[self._index + 1 :]
        self._values.append(value)
        if len(self._values) > self.limit:
            del self._values[0]
        self._index = len(self._values) - 1
        return True

    def undo(self) -> T | None:
        """The value before the current one (and go there), or ``None`` at the start."""
        if not self.can_undo:
            return None
        self._index -= 1
        return self.current

    def redo(self) -> T | None:
        """The value the last undo left (and go there), or ``None``."""
        if not self.can_redo:
            return None
        self._index += 1
        return self.current


class TimelineButtons(Generic[T]):
    """↶ and ↷ buttons over a :class:`Timeline`.

    Parameters
    ----------
    first : object
        The first value.
    on_restore : callable
        ``on_restore(value)`` shows a value from the timeline without recording it.
    what : str
        What is undone, for the tooltips (``"the last change of the program"``).

    Examples
    --------
    >>> shown = []
    >>> buttons = TimelineButtons(1, shown.append, "the last change")
    >>> buttons.record(2); buttons.undo_button.click(); shown, buttons.redo_button.disabled
    ([1], False)
    """

    def __init__(self, first: T, on_restore: Callable[[T], None], what: str):
        self.timeline: Timeline[T] = Timeline(first)
        self._on_restore = on_restore
        layout = widgets.Layout(width="36px")
        self.undo_button = widgets.Button(
            description="↶", tooltip=f"undo {what} (up to {HISTORY_LIMIT} are kept)", layout=layout
        )
        self.redo_button = widgets.Button(
            description="↷", tooltip="redo the change just undone", layout=layout
        )
        self.error = ErrorLabel()
        on_click(self.undo_button, self.error, self.undo)
        on_click(self.redo_button, self.error, self.redo)
        self.widget = widgets.HBox([self.undo_button, self.redo_button, self.error.widget])
        self._refresh()

    def reset(self, value: T) -> None:
        """Start again from ``value``, with nothing to undo."""
        self.timeline = Timeline(value, self.timeline.limit)
        self._refresh()

    def record(self, value: T) -> None:
        """Note that ``value`` is shown now."""
        if self.timeline.record(value):
            self._refresh()

    def undo(self) -> None:
        """Show the value before the current one, if any."""
        self._go(self.timeline.undo, self.timeline.redo)

    def redo(self) -> None:
        """Show the value the last undo left, if any."""
        self._go(self.timeline.redo, self.timeline.undo)

    def _go(self, step: Callable[[], T | None], back: Callable[[], T | None]) -> None:
        value = step()
        if value is None:
            return
        try:
            self._on_restore(value)
        except BaseException:
            back()  # the tab kept its value: so does the timeline
            raise
        finally:
            self._refresh()

    def _refresh(self) -> None:
        self.undo_button.disabled = not self.timeline.can_undo
        self.redo_button.disabled = not self.timeline.can_redo
