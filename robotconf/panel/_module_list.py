"""The list editor: module rows with add, remove and move up/down."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import Any

import ipywidgets as widgets

from .._errors import InvalidInputError
from ..kinematics import Link, Module, Robot
from ._drag_relay import DragRelay
from ._errors_display import ErrorLabel
from ._module_row import ModuleRow
from ._row_list import ChangeCallback, RowList

__all__ = ["ModuleList"]


class ModuleList(RowList):
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
        button = widgets.Button(
            description="add module", icon="plus", tooltip="append a module at the tool end"
        )
        super().__init__(on_change, button)
        # The q sliders' drags reach the kernel without waiting for each round trip.
        self.drag_relay = DragRelay()
        self.widget = widgets.VBox(
            [
                self._rows_box,
                widgets.HBox([self.add_button, self.error.widget]),
                self.drag_relay,
            ]
        )

    def _refresh(self) -> None:
        super()._refresh()
        self.drag_relay.track(row.q for row in self.rows)

    def _row(self, link: Link, limits: Any = None) -> ModuleRow:
        return ModuleRow(link, self._scale, self.degrees, limits, self._row_changed, self._action)

    def _new_link(self) -> Module:
        return Module("Rz")  # a rotation about z at the tool end

    def _last_row_message(self) -> str:
        # The core's own rule and message: a robot keeps at least one module.
        try:
            Robot([Module("none")]).with_removed(0)
        except InvalidInputError as error:
            return str(error)
        return "a robot keeps at least one module"  # pragma: no cover - the core refuses

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
        self._load_rows(links, scale, degrees, limits)

    def links(self) -> list[Link] | None:
        """The links of all rows, or ``None`` if any row is invalid (its message shown)."""
        links = [row.link() for row in self.rows]
        if any(link is None for link in links):
            return None
        self.error.clear()  # a refused add/remove is old news once the list is valid
        return links  # type: ignore[return-value]

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)`` pairs: ``modules`` and ``modules[i].<field>``."""
        yield "modules", self.error
        for i, row in enumerate(self.rows):
            yield from row.error_items(f"modules[{i}]")

    def _row_changed(self, row: ModuleRow, reason: str) -> None:
        self._on_change(reason, None)
