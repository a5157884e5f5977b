"""What a Run shows: the DVA table (with CSV download), statistics and plots of one point."""

from __future__ import annotations

import io
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any

import ipywidgets as widgets

from ._callbacks import observe, on_click
from ._errors_display import ErrorLabel
from ._images import download_link, figure_png

if TYPE_CHECKING:
    import pandas as pd

    from ..motion import Motion

__all__ = ["MotionResults", "MAX_TABLE_ROWS"]

#: Rows shown in the on-screen table; the CSV always holds every sample.
MAX_TABLE_ROWS = 500
_ALL = "all points"
#: Where every sample is, in a notebook; the app (no cells) names only the CSV.
_BOTH_HOLD = "the CSV and <code>panel.motion.table</code> hold"


def _html_table(frame: pd.DataFrame) -> str:
    # Column headers are point names, which come from files: pandas escapes them.
    table = frame.to_html(float_format=lambda v: f"{v:.6g}", border=0, escape=True)
    return (
        '<div style="max-height:320px;overflow:auto;font-size:0.8em;'
        f'border:1px solid #ddd">{table}</div>'
    )


class MotionResults:
    """Table, statistics and plot tabs of the last simulation.

    Parameters
    ----------
    animate : callable
        Called with the motion when the user presses "animate in 3D".
    app : bool
        The panel runs without cells around it (Voilà): no hint to type code in a cell.
    """

    def __init__(self, animate: Callable[[Motion], None], *, app: bool = False):
        self._animate = animate
        self.app = app
        self.motion: Motion | None = None
        self.point = widgets.Dropdown(options=["EE"], value="EE", description="point")
        self.displacement = widgets.Checkbox(
            value=False, description="plot displacement", indent=False
        )
        self.table = widgets.HTML()
        self.table_note = widgets.HTML()
        self.csv_button = widgets.Button(description="CSV download link", icon="download")
        self.csv_link = widgets.HTML()
        self.csv_error = ErrorLabel()
        self.error = ErrorLabel()
        self.stats = widgets.HTML()
        self.plot = widgets.Image(format="png", layout=widgets.Layout(max_width="900px"))
        self.animate_button = widgets.Button(
            description="animate in 3D", icon="play", disabled=True
        )
        self.tabs = widgets.Tab(
            children=[
                widgets.VBox(
                    [
                        self.table_note,
                        self.table,
                        widgets.HBox([self.csv_button, self.csv_link, self.csv_error.widget]),
                    ]
                ),
                self.stats,
                self.plot,
            ],
            titles=("DVA table", "statistics", "plot"),
        )
        self.widget = widgets.VBox(
            [
                widgets.HBox(
                    [self.point, self.displacement, self.animate_button, self.error.widget]
                ),
                self.tabs,
            ],
            layout=widgets.Layout(display="none"),
        )
        on_click(self.csv_button, self.csv_error, self.make_csv_link)
        on_click(self.animate_button, self.error, self._animate_motion)
        self._point_handler = observe(self.point, self.error, lambda _: self.render())
        observe(self.displacement, self.error, lambda _: self._render_plot())
        observe(self.tabs, self.error, lambda _: self._render_plot(), "selected_index")
        self._plotted: Any = None

    def _animate_motion(self) -> None:
        if self.motion is not None:
            self._animate(self.motion)

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)``: ``results`` and ``csv``."""
        yield "results", self.error
        yield "csv", self.csv_error

    def show(self, motion: Motion) -> None:
        """Show a new motion."""
        self.motion = motion
        self.widget.layout.display = None
        self.animate_button.disabled = False
        self.csv_link.value = ""
        self.csv_error.clear()
        # Dropdown labels are rendered as text by ipywidgets, so point names stay raw here.
        points = [*reversed(motion.points), _ALL]  # EE first: what students look at
        keep = self.point.value if self.point.value in points else "EE"
        with self._point_handler.paused():
            self.point.options = points
            self.point.value = keep
        self._plotted = None
        self.render()

    def _columns(self, frame: pd.DataFrame) -> pd.DataFrame:
        point = self.point.value
        return frame if point == _ALL else frame.loc[:, [point]]

    def render(self) -> None:
        """Redraw table and statistics for the chosen point (and the plot if showing)."""
        motion = self.motion
        if motion is None:
            return
        table = motion.table
        step = max(1, -(-len(table) // MAX_TABLE_ROWS))
        shown = self._columns(table).iloc[::step]
        self.table_note.value = (
            f"<small>{len(shown)} of {len(table)} samples shown (every {step}th); "
            f"{'the CSV holds' if self.app else _BOTH_HOLD} all.</small>"
            if step > 1
            else f"<small>{len(table)} samples</small>"
        )
        self.table.value = _html_table(shown)
        stats = motion.stats()
        if self.point.value != _ALL:
            stats = stats.loc[[self.point.value]]
        self.stats.value = _html_table(stats)
        self._render_plot()

    def _render_plot(self) -> None:
        motion = self.motion
        # Drawing costs ~0.2 s: only when the plot tab shows and something changed.
        if motion is None or self.tabs.selected_index != 2:
            return
        point = "EE" if self.point.value == _ALL else self.point.value
        key = (id(motion), point, self.displacement.value)
        if key == self._plotted:
            return
        figure = motion.plot(point, displacement=self.displacement.value, figsize=(10.0, 6.5))
        self.plot.value = figure_png(figure)
        self._plotted = key

    def make_csv_link(self) -> str:
        """Build the CSV of the whole table as a ``data:`` link; returns its HTML."""
        self.csv_link.value = ""  # never a link to an older motion, whatever fails below
        if self.motion is None:
            return ""
        buffer = io.StringIO()
        self.motion.to_csv(buffer)  # the core's export, with its memory check
        text = buffer.getvalue()
        # The robot's name is the user's; download_link escapes it in the attribute and text.
        name = f"{self.motion.robot.name or 'robot'}_motion.csv".replace(" ", "_")
        self.csv_link.value = download_link(
            text, name, "text/csv", f"{name} ({len(text) / 1e6:.2g} MB)"
        )
        return self.csv_link.value
