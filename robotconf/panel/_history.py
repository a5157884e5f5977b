"""Undo and redo: the robots the panel showed, newest last.

Robots are immutable, so the history is a list of robots and undoing is loading the one
before. One gesture makes one entry even when its control fires many times: a new robot
that changes the *same thing* as the entry on top (the same field of the same module, the
same end-effector component, the same coordinate), less than :data:`COALESCE_SECONDS`
after it, replaces that entry instead of adding one, so a slider drag or a burst of typing
in one box is undone at once. Structure changes, loads and conversions always make their
own entry. The oldest entries go beyond :data:`HISTORY_LIMIT`.

Each entry also keeps where the coordinates of the robot before it went (a row deleted
or moved, a conversion), so after an undo or a redo :attr:`History.last_order` tells the
panel which coordinate each motion signal belongs to now.
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Callable, Hashable

from ..kinematics import Robot

__all__ = ["History", "edit_key", "inverse_order", "Order", "HISTORY_LIMIT", "COALESCE_SECONDS"]

#: For each coordinate of a robot, the index of the coordinate of the robot before it that
#: it continues (``None``: new); ``None`` for the whole list: coordinate i is coordinate i.
Order = list[int | None]

#: Robots kept (the current one included): enough for a session, small in memory.
HISTORY_LIMIT = 200
#: Edits of the same thing closer together than this are one entry.
COALESCE_SECONDS = 1.5


def edit_key(old: Robot, new: Robot) -> Hashable | None:
    """What ``new`` changes in ``old``, when it is one thing; ``None`` otherwise.

    Parameters
    ----------
    old, new : Robot

    Returns
    -------
    hashable or None
        ``("module", i, fields)`` when only module ``i`` changed (``fields``: the names of
        its changed fields), ``("end_effector", axes)`` when only the end-effector point
        changed, ``None`` for anything else (a structure change, several modules).

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.Robot([rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20))])
    >>> edit_key(arm, arm.with_q([0.0, 0.5]))
    ('module', 1, ('q',))
    >>> edit_key(arm, arm.with_end_effector((1, 0, 0)))
    ('end_effector', (0,))
    >>> edit_key(arm, arm.with_removed(1)) is None
    True
    """
    if old.n != new.n or old.active != new.active:
        return None
    changed = [i for i, (a, b) in enumerate(zip(old.modules, new.modules, strict=True)) if a != b]
    axes = tuple(
        k
        for k, (a, b) in enumerate(zip(old.end_effector_point, new.end_effector_point, strict=True))
        if a != b
    )
    if len(changed) == 1 and not axes:
        a, b = old.modules[changed[0]], new.modules[changed[0]]
        if type(a) is not type(b) or not dataclasses.is_dataclass(a):
            return None
        fields = tuple(
            f.name for f in dataclasses.fields(a) if getattr(a, f.name) != getattr(b, f.name)
        )
        return ("module", changed[0], fields)
    if not changed and axes:
        return ("end_effector", axes)
    return None


def inverse_order(order: Order | None, n: int) -> Order | None:
    """The order that goes back: for each of the ``n`` old coordinates, its new index.

    >>> inverse_order([0, 2], 3)  # coordinate 2 (index 1) was deleted
    [0, None, 1]
    >>> inverse_order(None, 2) is None
    True
    """
    if order is None:
        return None
    back: Order = [None] * n
    for new, old in enumerate(order):
        if old is not None and 0 <= old < n:
            back[old] = new
    return back


class History:
    """Robots for undo and redo, with one entry per gesture.

    Parameters
    ----------
    robot : Robot
        The first robot (nothing to undo before it).
    limit : int
        Robots kept at most (the oldest go first).
    window : float
        Seconds within which edits of the same thing are one entry.
    clock : callable
        Returns the time in seconds (a test passes its own).

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.Robot([rc.Module("Rz")])
    >>> history = History(arm)
    >>> for q in (0.1, 0.2, 0.3):  # a slider drag: one entry
    ...     _ = history.record(arm.with_q([q]))
    >>> history.record(arm.with_end_effector((1, 0, 0)))
    True
    >>> len(history), history.undo().q, history.undo() == arm, history.can_undo
    (3, array([0.3]), True, False)
    >>> history.redo().q
    array([0.3])

    A deletion and its undo, with where the coordinates go:

    >>> two = rc.Robot([rc.Module("Rz"), rc.Module("Tz")])
    >>> history = History(two)
    >>> history.record(two.with_removed(0), coalesce=False, order=[1])
    True
    >>> history.undo() == two, history.last_order
    (True, [None, 0])
    """

    def __init__(
        self,
        robot: Robot,
        limit: int = HISTORY_LIMIT,
        window: float = COALESCE_SECONDS,
        clock: Callable[[], float] = time.monotonic,
    ):
        self.limit = max(int(limit), 2)
        self.window = window
        self._clock = clock
        self._robots: list[Robot] = [robot]
        self._orders: list[Order | None] = [None]  # how each robot came from the one before
        self._index = 0
        #: After :meth:`undo` or :meth:`redo`: for each coordinate of the robot returned,
        #: the index of the coordinate it continues in the robot left (``None``: by position).
        self.last_order: Order | None = None
        # What the top entry changed and when, while it may still absorb the same gesture.
        self._last: tuple[Hashable, float] | None = None

    def __len__(self) -> int:
        return len(self._robots)

    @property
    def current(self) -> Robot:
        """The robot the history is at."""
        return self._robots[self._index]

    @property
    def can_undo(self) -> bool:
        """Whether there is a robot before the current one."""
        return self._index > 0

    @property
    def can_redo(self) -> bool:
        """Whether an undo can be redone."""
        return self._index < len(self._robots) - 1

    def record(self, robot: Robot, coalesce: bool = True, order: Order | None = None) -> bool:
        """Make ``robot`` the current entry; ``False`` when it is the current robot already.

        Parameters
        ----------
        robot : Robot
            The robot the panel now shows.
        coalesce : bool
            Whether it may replace the top entry when it changes the same thing shortly
            after (``False`` for loads, conversions and structure changes).
        order : list or None
            For each coordinate of ``robot``, the one of the current robot it continues
            (``None``: coordinate i is coordinate i).

        Returns
        -------
        bool
            Whether the history changed.
        """
        current = self.current
        if robot == current:
            return False
        del self._robots[self._index + 1 :]  # a new edit forgets what was undone
        del self._orders[self._index + 1 :]
        now = self._clock()
        key = edit_key(current, robot) if coalesce else None
        same_gesture = (
            key is not None
            and self._last is not None
            and self._last[0] == key
            and now - self._last[1] <= self.window
            and self._index > 0
        )
        if same_gesture:
            self._robots[self._index] = robot
            if robot == self._robots[self._index - 1]:  # back where the gesture started
                self._robots.pop()
                self._orders.pop()
                self._index -= 1
                key = None
        else:
            self._robots.append(robot)
            self._orders.append(order)
            self._index += 1
            if len(self._robots) > self.limit:
                del self._robots[0]
                del self._orders[0]
                self._index -= 1
        self._last = None if key is None else (key, now)
        return True

    def undo(self) -> Robot | None:
        """The robot before the current one (and go there), or ``None`` at the start."""
        if not self.can_undo:
            return None
        self.last_order = inverse_order(self._orders[self._index], self._robots[self._index - 1].n)
        self._index -= 1
        self._last = None  # the next edit starts a new entry
        return self.current

    def redo(self) -> Robot | None:
        """The robot an undo left (and go there), or ``None`` when there is none."""
        if not self.can_redo:
            return None
        self._index += 1
        self.last_order = self._orders[self._index]
        self._last = None
        return self.current
