"""How a move made in the Reach tab reaches the rest of the panel: q controls and undo.

A solved target changes only the coordinates, so the editors keep their rows and just
show the new q (rebuilding every row on each step of a drag would be slow), and the panel
accepts the robot through its usual path (scene, p_EE, matrices, bound file).

Undo: the panel's history coalesces a burst of edits to *one* field, but a solved target
moves several joints at once. :class:`GestureHistory` makes one undo step of one drag of
one target control anyway: while the same control keeps changing (steps less than
:data:`~robotconf.panel._history.COALESCE_SECONDS` apart, nothing else recorded in
between), each new robot replaces the drag's previous one in the history.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Hashable, Iterable
from typing import Any

import numpy as np

from ..kinematics import Robot
from ._history import COALESCE_SECONDS
from ._undo_buttons import UndoButtons

__all__ = ["show_coordinates", "GestureHistory"]


def show_coordinates(editors: Iterable[Any], q: np.ndarray) -> None:
    """Show coordinates ``q`` (n,) in the q control of every editor row (no callbacks).

    ``editors`` are row lists (the module list, the DH table) whose ``rows`` each have a
    ``q`` control; an editor holding another number of rows shows another robot (the DH
    table of an earlier one) and is left alone.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.panel._module_list import ModuleList
    >>> editor = ModuleList(lambda reason, order: None)
    >>> editor.load([rc.Module("Rz"), rc.Module("Ry")], scale=1.0)
    >>> show_coordinates([editor], np.array([0.5, -0.25]))
    >>> [link.q for link in editor.links()]
    [0.5, -0.25]
    """
    for editor in editors:
        rows = editor.rows
        if len(rows) == len(q):
            for row, value in zip(rows, q, strict=True):
                row.q.set_core_value(float(value))


class GestureHistory:
    """Records the robots of Reach-tab moves: one undo step per drag of one control.

    Parameters
    ----------
    buttons : UndoButtons
        The panel's ↶ ↷ buttons and their history.
    window : float
        Seconds within which steps of the same control are one gesture.
    clock : callable
        Returns the time in seconds (a test sets its own: ``moves.clock = …``).

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.Robot([rc.Module("Rz"), rc.Module("Ry")])
    >>> buttons = UndoButtons(arm, lambda robot, order: None)
    >>> moves = GestureHistory(buttons)
    >>> for step in (0.1, 0.2, 0.3):  # a drag of x moves both joints each step
    ...     moves.record(arm.with_q([step, -step]), "x")
    >>> len(buttons.history), buttons.history.current.q
    (2, array([ 0.3, -0.3]))
    >>> moves.record(arm.with_q([1.0, 1.0]), None)  # a solution button: its own step
    >>> len(buttons.history)
    3
    """

    def __init__(
        self,
        buttons: UndoButtons,
        window: float = COALESCE_SECONDS,
        clock: Callable[[], float] = time.monotonic,
    ):
        self._buttons = buttons
        self.window = window
        self.clock = clock
        # The control of the drag going on, when it last moved, and the robot it recorded.
        self._last: tuple[Hashable, float, Robot] | None = None

    def record(self, robot: Robot, gesture: Hashable | None) -> None:
        """Note that the panel now shows ``robot``, moved by control ``gesture`` (``None``:
        a move of its own, such as a click)."""
        history = self._buttons.history
        now = self.clock()
        last = self._last
        same = (
            gesture is not None
            and last is not None
            and last[0] == gesture
            and now - last[1] <= self.window
            and history.current is last[2]
            and history.can_undo
        )
        if same:
            history.undo()  # the drag's previous robot goes; this one takes its place
        self._buttons.record(robot, coalesce=False)
        # A drag back to where it started leaves nothing to undo: the buttons say so.
        self._buttons.undo_button.disabled = not history.can_undo
        self._buttons.redo_button.disabled = not history.can_redo
        self._last = None if gesture is None else (gesture, now, history.current)
