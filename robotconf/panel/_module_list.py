"""The list editor: module rows with add, remove and move up/down."""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from typing import Any

import ipywidgets as widgets

from .._errors import InvalidInputError
from .._link import Link
from .._module import Module
from .._robot import Robot
from ._errors_display import ErrorLabel
from ._module_row import ModuleRow

__all__ = ["ModuleList"]

#: Called with a reason (``"q"``, ``"link"`` or ``"structure"``) and, for structure
#: changes, the old index of each new row (``None`` for a new row).
ChangeCallback = Callable[[str, "list[int | None] | None"], None]


class ModuleList:
    """Editable list of module rows (the paper's Figure 7/8 block dialog, as a list).

    Parameters
    ----------
    on_change : callable
        ``on_change(reason, order)`` after every user edit.

    Examples
    --------
    >>> import robotconf as rc
    >>> editor = ModuleList(lambda reason, order: None)
    >>> editor.load([rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20))], scale=100.0)
    >>> editor.add_button.click()
    >>> [link.kind for link in editor.links()]
    ['Rz', 'Ry', 'Rz']
    """

    def __init__(self, on_change: ChangeCallback):
        self._on_change = on_change
        self.rows: list[ModuleRow] = []
        self._scale = 1.0
        self.degrees = True
        self._limits: Any = None
        self.add_button = widgets.Button(
            description="add module", icon="plus", tooltip="append a module at the tool end"
        )
        self.add_button.on_click(lambda _: self.add())
        self.error = ErrorLabel()
        self._rows_box = widgets.VBox()
        self.widget = widgets.VBox(
            [self._rows_box, widgets.HBox([self.add_button, self.error.widget])]
        )

    # -- building -----------------------------------------------------------------------

    def _row(self, link: Link, limits: Any = None) -> ModuleRow:
        return ModuleRow(link, self._scale, self.degrees, limits, self._row_changed, self._action)

    def load(
        self,
        links: Sequence[Link],
        scale: float,
        degrees: bool | None = None,
        limits: Any = None,
    ) -> None:
        """Replace all rows by ``links`` (no change callback).

        ``limits`` is an (n, 2) array of joint limits in core units, or ``None``.
        """
        self._scale = scale
        if degrees is not None:
            self.degrees = degrees
        self.rows = [
            self._row(link, None if limits is None else limits[i]) for i, link in enumerate(links)
        ]
        self._refresh()

    def _refresh(self) -> None:
        for i, row in enumerate(self.rows):
            row.set_title(i, len(self.rows))
        self._rows_box.children = tuple(row.widget for row in self.rows)

    def links(self) -> list[Link] | None:
        """The links of all rows, or ``None`` if any row is invalid (its message shown)."""
        links = [row.link() for row in self.rows]
        if any(link is None for link in links):
            return None
        return links  # type: ignore[return-value]

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)`` pairs: ``modules`` and ``modules[i].<field>``."""
        yield "modules", self.error
        for i, row in enumerate(self.rows):
            yield from row.error_items(f"modules[{i}]")

    def set_degrees(self, degrees: bool) -> None:
        """Show angle coordinates in degrees or radians (no change to the robot)."""
        self.degrees = degrees
        for row in self.rows:
            row.set_degrees(degrees)

    # -- user actions -------------------------------------------------------------------

    def add(self, module: Module | None = None) -> None:
        """Append a module (default: a rotation about z) at the tool end."""
        order: list[int | None] = [*range(len(self.rows)), None]
        self.rows.append(self._row(module or Module("Rz")))
        self.error.clear()
        self._refresh()
        self._on_change("structure", order)

    def _action(self, row: ModuleRow, action: str) -> None:
        i = self.rows.index(row)
        order: list[int | None] = list(range(len(self.rows)))
        if action == "remove":
            if len(self.rows) == 1:
                # The core's own rule and message: a robot keeps at least one module.
                try:
                    Robot([Module("none")]).with_removed(0)
                except InvalidInputError as error:
                    self.error.show(str(error))
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

    def _row_changed(self, row: ModuleRow, reason: str) -> None:
        self._on_change(reason, None)
