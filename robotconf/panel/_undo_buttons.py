"""The ↶ ↷ buttons: undo and redo any change of the robot (see ``_history``)."""

from __future__ import annotations

from collections.abc import Callable

import ipywidgets as widgets

from ..kinematics import Robot
from ._callbacks import on_click
from ._errors_display import ErrorLabel
from ._history import HISTORY_LIMIT, History, Order

__all__ = ["UndoButtons"]


class UndoButtons:
    """Undo and redo buttons over a :class:`~robotconf.panel._history.History`.

    Parameters
    ----------
    robot : Robot
        The first robot.
    on_restore : callable
        ``on_restore(robot, order)`` shows a robot from the history (without recording it
        again); ``order`` says where the coordinates went (see ``History.last_order``).

    Examples
    --------
    >>> import robotconf as rc
    >>> shown = []
    >>> buttons = UndoButtons(rc.Robot([rc.Module("Rz")]), lambda robot, order: shown.append(robot))
    >>> buttons.undo_button.disabled
    True
    >>> buttons.record(rc.Robot([rc.Module("Tz")]), coalesce=False)
    >>> buttons.undo_button.click()
    >>> shown[-1].modules, buttons.redo_button.disabled
    ((Module('Rz'),), False)
    """

    def __init__(self, robot: Robot, on_restore: Callable[[Robot, Order | None], None]):
        self.history = History(robot)
        self._on_restore = on_restore
        layout = widgets.Layout(width="36px")
        self.undo_button = widgets.Button(
            description="↶",
            tooltip=f"undo the last change of the robot (up to {HISTORY_LIMIT} are kept)",
            layout=layout,
        )
        self.redo_button = widgets.Button(
            description="↷", tooltip="redo the change just undone", layout=layout
        )
        # Stable hooks for browser tests and for instructors' custom CSS.
        self.undo_button.add_class("robotconf-undo")
        self.redo_button.add_class("robotconf-redo")
        self.error = ErrorLabel()
        on_click(self.undo_button, self.error, self.undo)
        on_click(self.redo_button, self.error, self.redo)
        self.widget = widgets.HBox([self.undo_button, self.redo_button, self.error.widget])
        self._refresh()

    def record(self, robot: Robot, coalesce: bool = True, order: Order | None = None) -> None:
        """Note that the panel now shows ``robot`` (see :meth:`History.record`)."""
        if self.history.record(robot, coalesce, order):
            self._refresh()

    def undo(self) -> None:
        """Show the robot before the current one, if any."""
        self._go(self.history.undo, self.history.redo)

    def redo(self) -> None:
        """Show the robot the last undo left, if any."""
        self._go(self.history.redo, self.history.undo)

    def _go(self, step: Callable[[], Robot | None], back: Callable[[], Robot | None]) -> None:
        robot = step()
        if robot is None:
            return
        try:
            self._on_restore(robot, self.history.last_order)
        except BaseException:
            back()  # the panel kept its robot: so does the history
            raise
        finally:
            self._refresh()

    def _refresh(self) -> None:
        self.undo_button.disabled = not self.history.can_undo
        self.redo_button.disabled = not self.history.can_redo
