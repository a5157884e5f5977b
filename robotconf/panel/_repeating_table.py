"""Simulink's Repeating Sequence as an editable table of times and values, with a preview."""

from __future__ import annotations

import html
from collections.abc import Callable, Sequence

import ipywidgets as widgets
import numpy as np

from .._errors import InvalidInputError
from ..signals import RepeatingSequence
from ._callbacks import observe, on_click
from ._errors_display import ErrorLabel
from ._images import figure_png
from ._unit_box import UnitBox
from ._units import Units

__all__ = ["RepeatingTable"]


class RepeatingTable:
    """Rows of (time, value); the core's :class:`~robotconf.signals.RepeatingSequence`
    checks them (first time 0, strictly increasing, finite) and draws the preview.

    Values are typed in the panel's units (degrees for an angle in degree mode) and reach
    the core in its own (radians); times are seconds.

    Parameters
    ----------
    on_change : callable, optional
        Called after every edit.
    preview : bool
        Draw the small matplotlib preview (two periods) after valid edits.
    unit : str
        Core unit of the values: ``"rad"``, ``"length"`` or ``""``.
    units : Units, optional
        The panel's units (default: the core's).

    Examples
    --------
    >>> table = RepeatingTable(preview=False)
    >>> table.build()  # Simulink's default 0 → 2 sawtooth
    RepeatingSequence(times=(0.0, 2.0), values=(0.0, 2.0))
    >>> table.times[1].value = 0.0
    >>> table.build() is None, table.error.message.startswith("times:")
    (True, True)
    >>> table = RepeatingTable(preview=False, unit="rad", units=Units(degrees=True))
    >>> table.values[1].value = 90.0  # degrees, as the header says
    >>> table.build().values, table.header()
    ((0.0, 1.5707963267948966), ('time [s]', 'value [deg]'))
    """

    def __init__(
        self,
        on_change: Callable[[], None] | None = None,
        preview: bool = True,
        *,
        unit: str = "",
        units: Units | None = None,
    ):
        self._on_change = on_change
        self.preview_enabled = preview
        self.unit = unit
        self.units = units or Units(degrees=False)
        self._quiet = False
        self.times: list[UnitBox] = []
        self.values: list[UnitBox] = []
        self.error = ErrorLabel()
        self.add_button = widgets.Button(description="row", icon="plus", tooltip="add a row")
        self.remove_button = widgets.Button(
            description="row", icon="minus", tooltip="remove the last row"
        )
        on_click(self.add_button, self.error, self._add_row)
        on_click(self.remove_button, self.error, self._remove_row)
        self.preview = widgets.Image(format="png", layout=widgets.Layout(width="320px"))
        self._grid = widgets.GridBox(
            layout=widgets.Layout(grid_template_columns="80px 100px", grid_gap="2px 4px")
        )
        self.widget = widgets.HBox(
            [
                widgets.VBox(
                    [
                        self._grid,
                        widgets.HBox([self.add_button, self.remove_button]),
                        self.error.widget,
                    ]
                ),
                self.preview,
            ]
        )
        default = RepeatingSequence()
        self.load(default.times, default.values)

    def load(self, times: Sequence[float], values: Sequence[float]) -> None:
        """Show a table (no change callback)."""
        self.times = [self._box(t, "") for t in times]
        self.values = [self._box(v, self.unit) for v in values]
        self._layout()
        self._draw(self.build())

    def _box(self, value: float, unit: str) -> UnitBox:
        box = UnitBox(float(value), unit, self.units, layout=widgets.Layout(width="78px"))
        observe(box, self.error, lambda _: self._changed())
        return box

    def header(self) -> tuple[str, str]:
        """The column headings, with units."""
        unit = self.units.coordinate(self.unit)
        return "time [s]", f"value [{unit}]" if unit else "value"

    def set_units(self, units: Units, unit: str | None = None) -> None:
        """Show the same sequence in other units (``unit``: the coordinate's new core
        unit, when it changed type); no change callback."""
        self.units = units
        self.unit = self.unit if unit is None else unit
        self._quiet = True  # the sequence stays the same: no edit to report
        try:
            for box in self.values:
                box.set_units(units, self.unit)
        finally:
            self._quiet = False
        self._layout()
        self._draw(self.build())

    def _layout(self) -> None:
        header = [
            widgets.HTML(f"<b style='white-space:nowrap'>{html.escape(text)}</b>")
            for text in self.header()
        ]
        cells = [w for pair in zip(self.times, self.values, strict=True) for w in pair]
        self._grid.children = tuple(header + cells)

    def _add_row(self) -> None:
        last_t = self.times[-1].core_value if self.times else 0.0
        last_v = self.values[-1].core_value if self.values else 0.0
        step = np.diff([b.core_value for b in self.times[-2:]])
        self.times.append(self._box(last_t + (float(step[0]) if step.size else 1.0), ""))
        self.values.append(self._box(last_v, self.unit))
        self._layout()
        self._changed()

    def _remove_row(self) -> None:
        if self.times:
            self.times.pop()
            self.values.pop()
            self._layout()
            self._changed()

    def build(self) -> RepeatingSequence | None:
        """The sequence, or ``None`` after showing the core's message."""
        try:
            signal = RepeatingSequence(
                times=tuple(b.core_value for b in self.times),
                values=tuple(b.core_value for b in self.values),
            )
        except InvalidInputError as error:
            self.error.show(str(error))
            return None
        self.error.clear()
        return signal

    def _changed(self) -> None:
        if self._quiet:
            return
        self._draw(self.build())
        if self._on_change is not None:
            self._on_change()

    def _draw(self, signal: RepeatingSequence | None) -> None:
        if signal is None or not self.preview_enabled:
            return
        from matplotlib.figure import Figure

        t = np.linspace(0.0, 2.0 * signal.period, 400)
        figure = Figure(figsize=(4.0, 1.6), layout="constrained")
        axes = figure.subplots()
        # Drawn in the units the table shows (the core's numbers times 180/π in degrees).
        axes.plot(t, signal.value(t) * self.units.scale(self.unit), lw=1.2)
        axes.set_xlabel("time [s]", fontsize=8)
        axes.set_ylabel(self.header()[1], fontsize=8)
        axes.tick_params(labelsize=7)
        axes.grid(True, alpha=0.3)
        self.preview.value = figure_png(figure)
