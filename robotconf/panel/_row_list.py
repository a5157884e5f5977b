"""What the module list and the DH table share: a column of rows with add, remove, move.

A subclass builds its rows (:meth:`RowList._row`), says what a new row holds
(:meth:`RowList._new_link`) and why the last row cannot go
(:meth:`RowList._last_row_message`); the bookkeeping lives here once.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import ipywidgets as widgets

from ._callbacks import on_click
from ._errors_display import ErrorLabel

__all__ = ["RowList", "ChangeCallback"]

#: Called with a reason (``"q"``, ``"link"`` or ``"structure"``) and, for structure
#: changes, the old index of each new row (``None`` for a new row).
ChangeCallback = Callable[[str, "list[int | None] | None"], None]


class RowList:
    """Rows of link editors in a VBox, an add button and an error line.

    Parameters
    ----------
    on_change : callable
        ``on_change(reason, order)`` after every user edit.
    add_button : ipywidgets.Button
        Appends a row when clicked.
    """

    def __init__(self, on_change: ChangeCallback, add_button: widgets.Button) -> None:
        self._on_change = on_change
        self.rows: list[Any] = []
        self._scale = 1.0
        self.degrees = True
        self.add_button = add_button
        self.error = ErrorLabel()
        on_click(self.add_button, self.error, self.add)
        self._rows_box = widgets.VBox()

    def _row(self, link: Any, limits: Any = None) -> Any:  # pragma: no cover - abstract
        raise NotImplementedError

    def _new_link(self) -> Any:  # pragma: no cover - abstract
        raise NotImplementedError

    def _last_row_message(self) -> str:  # pragma: no cover - abstract
        raise NotImplementedError

    def _load_rows(
        self, links: Sequence[Any], scale: float, degrees: bool | None, limits: Any
    ) -> None:
        self._scale = scale
        if degrees is not None:
            self.degrees = degrees
        self.rows = [
            self._row(link, None if limits is None else limits[i]) for i, link in enumerate(links)
        ]
        self.error.clear()  # a message about the old rows is stale now
        self._refresh()

    def _refresh(self) -> None:
        for i, row in enumerate(self.rows):
            row.set_title(i, len(self.rows))
        self._rows_box.children = tuple(row.widget for row in self.rows)

    def set_degrees(self, degrees: bool) -> None:
        """Show angles in degrees or radians (no change to the robot)."""
        self.degrees = degrees
        for row in self.rows:
            row.set_degrees(degrees)

    def add(self, link: Any = None) -> None:
        """Append a row holding ``link`` (default: the subclass's new link)."""
        order: list[int | None] = [*range(len(self.rows)), None]
        self.rows.append(self._row(link or self._new_link()))
        self.error.clear()
        self._refresh()
        self._on_change("structure", order)

    def _action(self, row: Any, action: str) -> None:
        i = self.rows.index(row)
        order: list[int | None] = list(range(len(self.rows)))
        if action == "remove":
            if len(self.rows) == 1:
                self.error.show(self._last_row_message())
                return
            del self.rows[i]
            del order[i]
        else:
            j = i - 1 if action == "up" else i + 1
            if not 0 <= j < len(self.rows):
                return
            self.rows[i], self.rows[j] = self.rows[j], self.rows[i]
            order[i], order[j] = order[j], order[i]
        self.error.clear()
        self._refresh()
        self._on_change("structure", order)
