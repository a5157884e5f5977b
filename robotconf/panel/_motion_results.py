"""What a Run shows: the DVA table (with CSV download), statistics and plots of one point
or of every point, in the panel's units, the plot optionally over the other method's."""

from __future__ import annotations

import html
import io
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any

import ipywidgets as widgets

from ..motion import METHODS, SimulationSettings, simulate
from ._callbacks import observe, on_click
from ._errors_display import ErrorLabel
from ._images import download_link, figure_png, responsive_image
from ._result_tables import dva_table_html, stats_table_html
from ._units import Units

if TYPE_CHECKING:
    import pandas as pd
    from matplotlib.figure import Figure

    from ..motion import Motion

__all__ = ["MotionResults", "MAX_TABLE_ROWS"]

#: Rows shown in the on-screen table; the CSV always holds every sample.
MAX_TABLE_ROWS = 500
_ALL = "all points"
#: Where every sample is, in a notebook; the app (no cells) names only the CSV.
_BOTH_HOLD = "the CSV and <code>panel.motion.table</code> hold"
#: Index of the plot among the result tabs.
_PLOT_TAB = 2
#: Figure size (inches) and resolution: 1000 × 650 pixels, shown at most that wide and
#: narrower when the column is (the picture scales, nothing is cut off).
FIGSIZE, DPI = (10.0, 6.5), 100


class MotionResults:
    """Table, statistics and plot tabs of the last simulation.

    Parameters
    ----------
    animate : callable
        Called with the motion when the user presses "animate in 3D".
    app : bool
        The panel runs without cells around it (Voilà): no hint to type code in a cell.
    units : Units, optional
        Length unit named in headers and axes; angular velocities in deg/s in degree
        mode (default: the core's units).

    Examples
    --------
    >>> import robotconf as rc
    >>> results = MotionResults(lambda motion: None, units=Units("mm"))
    >>> results.show(rc.simulate(rc.preset("paper"), {}, t_end=0.5, dt=0.5))
    >>> "position [mm]" in results.table.value
    True
    >>> results.point.value = "all points"; results.tabs.selected_index = 2
    >>> [line.get_label() for line in results.figure().axes[0].lines]
    ['M1', 'M2', 'M3', 'EE']
    """

    def __init__(
        self,
        animate: Callable[[Motion], None],
        *,
        app: bool = False,
        units: Units | None = None,
    ):
        self._animate = animate
        self.app = app
        self.units = units or Units(degrees=False)
        self.motion: Motion | None = None
        self._settings: SimulationSettings | None = None
        self._other: Motion | None = None  # the run with the other method, for the overlay
        self.point = widgets.Dropdown(
            options=["EE"],
            value="EE",
            description="point",
            layout=widgets.Layout(width="190px"),
            style={"description_width": "40px"},
        )
        self.displacement = widgets.Checkbox(
            value=False,
            description="plot displacement",
            indent=False,
            layout=widgets.Layout(width="auto"),
        )
        self.overlay = widgets.Checkbox(
            value=False,
            description="overlay the other method",
            indent=False,
            tooltip="draw the other method's derivatives dashed over this run's",
            layout=widgets.Layout(width="auto"),
        )
        self.table = widgets.HTML()
        self.table_note = widgets.HTML()
        self.csv_button = widgets.Button(description="CSV download link", icon="download")
        self.csv_link = widgets.HTML()
        self.csv_error = ErrorLabel()
        self.error = ErrorLabel()
        self.stats = widgets.HTML()
        self.stats_note = widgets.HTML()
        self.plot = responsive_image()
        self.plot_note = widgets.HTML()
        self.animate_button = widgets.Button(
            description="animate in 3D", icon="play", disabled=True
        )
        # Browser tests and the screenshot script find the parts by these classes.
        for widget, name in (
            (self.point, "point"),
            (self.overlay, "overlay"),
            (self.plot, "plot"),
            (self.table, "table"),
            (self.stats, "stats"),
        ):
            widget.add_class(f"robotconf-results-{name}")
        self.tabs = widgets.Tab(
            children=[
                widgets.VBox(
                    [
                        self.table_note,
                        self.table,
                        widgets.HBox([self.csv_button, self.csv_link, self.csv_error.widget]),
                    ]
                ),
                widgets.VBox([self.stats_note, self.stats]),
                widgets.VBox([self.plot_note, self.plot]),
            ],
            titles=("DVA table", "statistics", "plot"),
        )
        self.widget = widgets.VBox(
            [
                widgets.HBox(
                    [
                        self.point,
                        self.displacement,
                        self.overlay,
                        self.animate_button,
                        self.error.widget,
                    ],
                    layout=widgets.Layout(flex_flow="row wrap", align_items="center"),
                ),
                self.tabs,
            ],
            layout=widgets.Layout(display="none"),
        )
        on_click(self.csv_button, self.csv_error, self.make_csv_link)
        on_click(self.animate_button, self.error, self._animate_motion)
        self._point_handler = observe(self.point, self.error, lambda _: self.render())
        observe(self.displacement, self.error, lambda _: self._render_plot())
        observe(self.overlay, self.error, lambda _: self._render_plot())
        observe(self.tabs, self.error, lambda _: self._render_plot(), "selected_index")
        self._plotted: Any = None

    def _animate_motion(self) -> None:
        if self.motion is not None:
            self._animate(self.motion)

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)``: ``results`` and ``csv``."""
        yield "results", self.error
        yield "csv", self.csv_error

    def set_units(self, units: Units) -> None:
        """Show tables and plot in ``units``."""
        self.units = units
        self._plotted = None
        self.render()

    def show(self, motion: Motion, settings: SimulationSettings | None = None) -> None:
        """Show a new motion; ``settings`` (those it ran with) allow the overlay."""
        self.motion = motion
        self._settings = settings
        self._other = None
        self.overlay.disabled = settings is None
        other = self._other_method(motion)
        self.overlay.description = f"overlay {other}"
        self.overlay.tooltip = f"draw the {other} derivatives dashed over the {motion.method} ones"
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

    @staticmethod
    def _other_method(motion: Motion) -> str:
        return next(m for m in METHODS if m != motion.method)

    def _code(self, text: str, lead: str = "Numbers") -> str:
        """A note naming the core call that gives these numbers (not in the app)."""
        return "" if self.app else f"<small>{lead}: <code>{text}</code></small>"

    def render(self) -> None:
        """Redraw table and statistics for the chosen point (and the plot if showing)."""
        motion = self.motion
        if motion is None:
            return
        table = motion.table
        step = max(1, -(-len(table) // MAX_TABLE_ROWS))
        shown = self._columns(table).iloc[::step]
        degrees = self.units.scale("rad") != 1.0
        # The core (and the CSV) keeps rad/s; say where the shown deg/s differ from it.
        if not degrees:
            converted = ""
        elif self.app:
            converted = " Angular velocity in deg/s (in the CSV: rad/s)."
        else:
            converted = " (angular velocity there in rad/s, here in deg/s)"
        self.table_note.value = (
            f"<small>{len(shown)} of {len(table)} samples shown (one in {step}); "
            f"{'the CSV holds' if self.app else _BOTH_HOLD} all.</small>"
            if step > 1
            else f"<small>{len(table)} samples</small>"
        ) + (" " + self._code("panel.motion.table") + f"<small>{converted}</small>")
        self.table.value = dva_table_html(shown, self.units)
        stats = motion.stats()
        if self.point.value != _ALL:
            stats = stats.loc[[self.point.value]]
        self.stats_note.value = self._code("panel.motion.stats()") + f"<small>{converted}</small>"
        self.stats.value = stats_table_html(stats, self.units)
        self._render_plot()

    def _plotted_point(self) -> str:
        return "all" if self.point.value == _ALL else str(self.point.value)

    def figure(self) -> Figure | None:
        """The plot as the tab shows it (``None`` before a run): the chosen point or all,
        lengths labelled in the panel's unit, the other method dashed if ticked."""
        motion = self.motion
        if motion is None:
            return None
        return motion.plot(
            self._plotted_point(),
            displacement=self.displacement.value,
            length_unit=self.units.length,
            figsize=FIGSIZE,
            compare=self._comparison(),
        )

    def _comparison(self) -> Motion | None:
        """The same run with the other method, simulated once per run when asked for."""
        motion = self.motion
        if motion is None or not self.overlay.value or self._settings is None:
            return None
        if self._other is None:
            settings = {**self._settings.to_dict(), "method": self._other_method(motion)}
            self._other = simulate(motion.robot, dict(motion.signals), **settings)  # type: ignore[arg-type]
        return self._other

    def _render_plot(self) -> None:
        motion = self.motion
        # Drawing costs ~0.2 s: only when the plot tab shows and something changed.
        if motion is None or self.tabs.selected_index != _PLOT_TAB:
            return
        key = (
            id(motion),
            self._plotted_point(),
            self.displacement.value,
            self.overlay.value,
            self.units,
        )
        if key == self._plotted:
            return
        figure = self.figure()
        if figure is None:
            return
        self.plot.value = figure_png(figure, dpi=DPI)
        self._plotted = key
        self.plot_note.value = self._code(self._plot_call(), "Drawn by")

    def _plot_call(self) -> str:
        """The core call that draws the figure shown, as text."""
        motion = self.motion
        assert motion is not None
        arguments = [repr(self._plotted_point())]
        if self.displacement.value:
            arguments.append("displacement=True")
        arguments.append(f"length_unit={self.units.length!r}")
        if self.overlay.value and self._settings is not None:
            settings = {**self._settings.to_dict(), "method": self._other_method(motion)}
            if settings.get("t0") == 0.0:
                del settings["t0"]  # simulate's default: shorter to read
            keywords = ", ".join(f"{k}={v!r}" for k, v in settings.items())
            arguments.append(
                f"compare=rc.simulate(panel.motion.robot, panel.motion.signals, {keywords})"
            )
        return html.escape(f"panel.motion.plot({', '.join(arguments)})")

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
