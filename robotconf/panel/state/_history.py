"""Undo and redo: the documents the panel showed, newest last.

Documents are immutable, so the history is a list of them and undoing is going back to
the one before. One gesture makes one entry even when its control fires many times: an
action names its gesture (the same field of the same module, the same end-effector
component, the same signal parameter, the same Reach slider …), and a document that
comes from the same gesture as the entry on top, less than :data:`COALESCE_SECONDS`
after it, replaces that entry instead of adding one. So a slider drag or a burst of
typing in one box is undone at once. Structure changes, loads and conversions have no
gesture and always make their own entry. The oldest entries go beyond
:data:`HISTORY_LIMIT`.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Hashable
from typing import Generic, TypeVar

__all__ = ["History", "HISTORY_LIMIT", "COALESCE_SECONDS"]

#: Entries kept (the current one included): enough for a session, small in memory.
HISTORY_LIMIT = 200
#: Edits of the same gesture closer together than this are one entry (s).
COALESCE_SECONDS = 1.5

T = TypeVar("T")


class History(Generic[T]):
    """Documents for undo and redo, with one entry per gesture.

    Parameters
    ----------
    first : object
        The first entry (nothing to undo before it).
    limit : int
        Entries kept at most (the oldest go first).
    window : float
        Seconds within which edits of the same gesture are one entry.
    clock : callable
        Returns the time in seconds (a test passes its own).

    Examples
    --------
    >>> history = History("a")
    >>> for text in ("ab", "abc", "abcd"):  # typing in one box: one entry
    ...     _ = history.record(text, gesture="box")
    >>> history.record("x", gesture=None)
    True
    >>> len(history), history.undo(), history.undo(), history.can_undo
    (3, 'abcd', 'a', False)
    >>> history.redo()
    'abcd'
    """

    def __init__(
        self,
        first: T,
        limit: int = HISTORY_LIMIT,
        window: float = COALESCE_SECONDS,
        clock: Callable[[], float] = time.monotonic,
    ):
        self.limit = max(int(limit), 2)
        self.window = window
        self._clock = clock
        self._entries: list[T] = [first]
        self._index = 0
        # The gesture of the top entry and when, while it may still absorb the same gesture.
        self._last: tuple[Hashable, float] | None = None

    def __len__(self) -> int:
        return len(self._entries)

    @property
    def current(self) -> T:
        """The entry the history is at."""
        return self._entries[self._index]

    @property
    def can_undo(self) -> bool:
        """Whether there is an entry before the current one."""
        return self._index > 0

    @property
    def can_redo(self) -> bool:
        """Whether an undo can be redone."""
        return self._index < len(self._entries) - 1

    def record(self, entry: T, gesture: Hashable | None = None) -> bool:
        """Make ``entry`` the current one; ``False`` when it equals the current entry.

        Parameters
        ----------
        entry : object
            The document the panel now shows.
        gesture : hashable or None
            What the edit changed (``("q", 1)``); an edit of the same gesture shortly
            after the entry on top replaces it. ``None``: always its own entry.

        Returns
        -------
        bool
            Whether the history changed.
        """
        if entry == self.current:
            return False
        del self._entries[self._index + 1 :]  # a new edit forgets what was undone
        now = self._clock()
        same_gesture = (
            gesture is not None
            and self._last is not None
            and self._last[0] == gesture
            and now - self._last[1] <= self.window
            and self._index > 0
        )
        if same_gesture:
            self._entries[self._index] = entry
            if entry == self._entries[self._index - 1]:  # back where the gesture started
                self._entries.pop()
                self._index -= 1
                gesture = None
        else:
            self._entries.append(entry)
            self._index += 1
            if len(self._entries) > self.limit:
                del self._entries[0]
                self._index -= 1
        self._last = None if gesture is None else (gesture, now)
        return True

    def undo(self) -> T | None:
        """The entry before the current one (and go there), or ``None`` at the start."""
        if not self.can_undo:
            return None
        self._index -= 1
        self._last = None  # the next edit starts a new entry
        return self.current

    def redo(self) -> T | None:
        """The entry an undo left (and go there), or ``None`` when there is none."""
        if not self.can_redo:
            return None
        self._index += 1
        self._last = None
        return self.current
