"""Controls shared by every editing mode: number of active modules and end-effector point."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

import ipywidgets as widgets

from .._errors import InvalidInputError
from .._validation import check_finite_number
from ._callbacks import observe
from ._errors_display import ErrorLabel
from ._number_control import NumberControl
from ._ranges import length_step

__all__ = ["RobotExtras"]


class RobotExtras:
    """Active-module count (paper §2.3.3) and end-effector ``P = (Px, Py, Pz)``.

    Examples
    --------
    >>> extras = RobotExtras(lambda: None)
    >>> extras.load(n=3, active=3, point=(40, 0, 0), scale=100.0)
    >>> extras.active.value = 2
    >>> extras.values()
    (2, (40.0, 0.0, 0.0))
    """

    def __init__(self, on_change: Callable[[], None]):
        self._on_change = on_change
        self._quiet = False
        self.active = widgets.BoundedIntText(
            value=1,
            min=1,
            max=1,
            description="active modules",
            style={"description_width": "initial"},
            layout=widgets.Layout(width="190px"),
        )
        self.active_error = ErrorLabel()
        self.point = tuple(
            NumberControl(name, 0.0, -1.0, 1.0, on_change=lambda _: self._changed())
            for name in ("Px", "Py", "Pz")
        )
        observe(self.active, self.active_error, lambda _: self._changed())
        self.widget = widgets.VBox(
            [
                widgets.HBox([self.active, self.active_error.widget]),
                widgets.HTML("<b>End-effector</b> P in the last module's frame"),
                *(c.widget for c in self.point),
            ]
        )

    def load(self, n: int, active: int, point: Any, scale: float) -> None:
        """Show a robot's values (no change callback)."""
        self._quiet = True
        try:
            self.set_count(n, keep_all=False)
            self.active.value = active
            for control, value in zip(self.point, point, strict=True):
                control.set_length_step(length_step(scale))
                control.set_range(-scale, scale)
                control.set_core_value(float(value))
        finally:
            self._quiet = False

    def set_count(self, n: int, keep_all: bool = True) -> None:
        """Adapt to ``n`` modules; "all active" stays all active."""
        self._quiet, quiet = True, self._quiet
        try:
            all_active = self.active.value == self.active.max
            self.active.max = max(n, 1)
            if keep_all and all_active:
                self.active.value = self.active.max
        finally:
            self._quiet = quiet

    def values(self) -> tuple[int, tuple[float, float, float]] | None:
        """``(active, (Px, Py, Pz))``, or ``None`` after showing why a value is invalid."""
        valid = True
        for name, control in zip(("Px", "Py", "Pz"), self.point, strict=True):
            try:
                check_finite_number(control.core_value, name)
                control.error.clear()
            except InvalidInputError as error:
                control.error.show(str(error))
                valid = False
        if not valid:
            return None
        point = tuple(c.core_value for c in self.point)
        return int(self.active.value), point  # type: ignore[return-value]

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)`` pairs: ``active`` and ``end_effector.Px`` …"""
        yield "active", self.active_error
        for name, control in zip(("Px", "Py", "Pz"), self.point, strict=True):
            yield f"end_effector.{name}", control.error

    def _changed(self) -> None:
        if not self._quiet:
            self._on_change()
