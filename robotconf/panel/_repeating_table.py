"""Simulink's Repeating Sequence as an editable table of times and values, with a preview."""

from __future__ import annotations

from collections.abc import Callable, Sequence

import ipywidgets as widgets
import numpy as np

from .._errors import InvalidInputError
from ..signals import RepeatingSequence
from ._callbacks import observe, on_click
from ._errors_display import ErrorLabel
from ._images import figure_png

__all__ = ["RepeatingTable"]


class RepeatingTable:
    """Rows of (time, value); the core's :class:`~robotconf.signals.RepeatingSequence`
    checks them (first time 0, strictly increasing, finite) and draws the preview.

    Parameters
    ----------
    on_change : callable, optional
        Called after every edit.
    preview : bool
        Draw the small matplotlib preview (two periods) after valid edits.

    Examples
    --------
    >>> table = RepeatingTable(preview=False)
    >>> table.build()  # Simulink's default 0 → 2 sawtooth
    RepeatingSequence(times=(0.0, 2.0), values=(0.0, 2.0))
    >>> table.times[1].value = 0.0
    >>> table.build() is None, table.error.message.startswith("times:")
    (True, True)
    """

    def __init__(self, on_change: Callable[[], None] | None = None, preview: bool = True):
        self._on_change = on_change
        self.preview_enabled = preview
        self.times: list[widgets.FloatText] = []
        self.values: list[widgets.FloatText] = []
        self.error = ErrorLabel()
        self.add_button = widgets.Button(description="row", icon="plus", tooltip="add a row")
        self.remove_button = widgets.Button(
            description="row", icon="minus", tooltip="remove the last row"
        )
        on_click(self.add_button, self.error, self._add_row)
        on_click(self.remove_button, self.error, self._remove_row)
        self.preview = widgets.Image(format="png", layout=widgets.Layout(width="320px"))
        self._grid = widgets.GridBox(
            layout=widgets.Layout(grid_template_columns="80px 80px", grid_gap="2px 4px")
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
        self.times = [self._box(t) for t in times]
        self.values = [self._box(v) for v in values]
        self._layout()
        self._draw(self.build())

    def _box(self, value: float) -> widgets.FloatText:
        box = widgets.FloatText(value=float(value), layout=widgets.Layout(width="78px"))
        observe(box, self.error, lambda _: self._changed())
        return box

    def _layout(self) -> None:
        header = [widgets.HTML("<b>time (s)</b>"), widgets.HTML("<b>value</b>")]
        cells = [w for pair in zip(self.times, self.values, strict=True) for w in pair]
        self._grid.children = tuple(header + cells)

    def _add_row(self) -> None:
        last_t = self.times[-1].value if self.times else 0.0
        last_v = self.values[-1].value if self.values else 0.0
        step = np.diff([b.value for b in self.times[-2:]])
        self.times.append(self._box(last_t + (float(step[0]) if step.size else 1.0)))
        self.values.append(self._box(last_v))
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
                times=tuple(b.value for b in self.times), values=tuple(b.value for b in self.values)
            )
        except InvalidInputError as error:
            self.error.show(str(error))
            return None
        self.error.clear()
        return signal

    def _changed(self) -> None:
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
        axes.plot(t, signal.value(t), lw=1.2)
        axes.set_xlabel("time (s)", fontsize=8)
        axes.tick_params(labelsize=7)
        axes.grid(True, alpha=0.3)
        self.preview.value = figure_png(figure)
