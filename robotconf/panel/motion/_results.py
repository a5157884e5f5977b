"""What a run shows: the DVA table (with a CSV download), statistics and the plot of one
point or of every point, in the panel's units; the plot optionally over the other
derivative method's. Drawn from ``state.motion`` and the view options."""

from __future__ import annotations

import html
import io
from typing import TYPE_CHECKING, Any

import ipywidgets as widgets

from ...kinematics import characteristic_length
from ...motion import METHODS, simulate
from ..files import download_link, figure_png, responsive_image
from ..form import Form, button, check, message, row, select, toggle
from ..state import RESULT_VIEWS, PanelState, Units
from ._tables import dva_table_html, stats_table_html

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ...motion import Motion, SimulationSettings

__all__ = ["ResultsView", "MAX_TABLE_ROWS", "ALL_POINTS"]

#: Rows shown in the on-screen table; the CSV always holds every sample.
MAX_TABLE_ROWS = 500
#: The point choice that shows every point.
ALL_POINTS = "all"
#: Figure size (inches) and resolution: 1000 × 650 pixels, scaled down to the column.
FIGSIZE, DPI = (10.0, 6.5), 100
_VIEW_LABELS = {"table": "DVA table", "statistics": "statistics", "plot": "plot"}


def other_method(motion: Motion) -> str:
    """The derivative method the overlay draws: the first one the run did not use."""
    return next(m for m in METHODS if m != motion.method)


def _other_settings(settings: SimulationSettings, motion: Motion) -> dict[str, Any]:
    return {**settings.to_dict(), "method": other_method(motion)}


class ResultsView:
    """The result of the last run, in the panel's units.

    Parameters
    ----------
    form_event : callable
        Receives the result controls' events (the Motion tab turns them into actions).
    app : bool
        No notebook around the panel: no hints to type code.
    """

    def __init__(self, form_event: Any, app: bool = False) -> None:
        self.app = app
        self.controls = Form(form_event, css_class="robotconf-results")
        self.table_note = widgets.HTML()
        self.table = widgets.HTML()
        self.table.add_class("robotconf-results-table")
        self.csv_link = widgets.HTML()
        self.stats_note = widgets.HTML()
        self.stats = widgets.HTML()
        self.stats.add_class("robotconf-results-stats")
        self.plot_note = widgets.HTML()
        self.plot = responsive_image()
        self.plot.add_class("robotconf-results-plot")
        self._table_box = widgets.VBox([self.table_note, self.table, self.csv_link])
        self._stats_box = widgets.VBox([self.stats_note, self.stats])
        self._plot_box = widgets.VBox([self.plot_note, self.plot])
        self.widget = widgets.VBox([self.controls], layout=widgets.Layout(display="none"))
        self.motion: Motion | None = None
        self._shown: Any = None
        self._plotted: Any = None
        self._other: tuple[Any, Motion] | None = None
        self._csv_for: Any = None

    def render(self, state: PanelState, feedback: Any, rev: str, visible: bool) -> None:
        """Show ``state.motion`` as the view options say (drawn only while visible)."""
        motion = state.motion
        self.motion = motion
        if motion is None:
            self.widget.layout.display = "none"
            return
        self.widget.layout.display = None
        view = state.view
        points = [*reversed(motion.points), ALL_POINTS]  # EE first: what students look at
        point = view.result_point if view.result_point in points else "EE"
        other = other_method(motion)
        overlay_off = state.run_settings is None  # a program's run: no signals to rerun
        self.controls.show(
            [
                row(
                    "results",
                    [
                        select(
                            "results.point",
                            point,
                            [(p, p) for p in points],
                            label="point",
                            rev=rev,
                            width="110px",
                            css_class="robotconf-results-point",
                        ),
                        toggle(
                            "results.view",
                            view.result_view,
                            [(_VIEW_LABELS[v], v) for v in RESULT_VIEWS],
                            rev=rev,
                            css_class="robotconf-results-view",
                        ),
                        check(
                            "results.displacement", view.displacement, "plot displacement", rev=rev
                        ),
                        check(
                            "results.overlay",
                            view.overlay,
                            f"overlay {other}",
                            rev=rev,
                            disabled=overlay_off,
                            title=f"draw the {other} derivatives dashed over the "
                            f"{motion.method} ones",
                            css_class="robotconf-results-overlay",
                        ),
                        button(
                            "results.animate",
                            "▶ animate in 3D",
                            css_class="robotconf-animate",
                            title="play this run in the 3D view",
                        ),
                        button(
                            "results.csv",
                            "CSV download link",
                            title="the whole table as a CSV file",
                        ),
                    ],
                    note=message(feedback.message("results")),
                )
            ]
        )
        chosen = {"table": self._table_box, "statistics": self._stats_box, "plot": self._plot_box}
        box = chosen.get(view.result_view, self._table_box)
        if self.widget.children != (self.controls, box):
            self.widget.children = (self.controls, box)
        if motion is not self._csv_for:
            self.csv_link.value = ""  # never a link to an older run
        if not visible:
            return
        key = (id(motion), point, state.units, view.result_view)
        if view.result_view in ("table", "statistics") and key != self._shown:
            self._shown = key
            self._render_tables(motion, point, state.units)
        if view.result_view == "plot":
            self._render_plot(state, motion, point)

    # -- tables ------------------------------------------------------------------------

    def _code(self, text: str, lead: str = "Numbers") -> str:
        return "" if self.app else f"<small>{lead}: <code>{text}</code></small>"

    def _render_tables(self, motion: Motion, point: str, units: Units) -> None:
        table = motion.table
        step = max(1, -(-len(table) // MAX_TABLE_ROWS))
        columns = table if point == ALL_POINTS else table.loc[:, [point]]
        shown = columns.iloc[::step]
        degrees = units.scale("rad") != 1.0
        if not degrees:
            converted = ""
        elif self.app:
            converted = " Angular velocity in deg/s (in the CSV: rad/s)."
        else:
            converted = " (angular velocity there in rad/s, here in deg/s)"
        where = "the CSV holds" if self.app else "the CSV and <code>panel.motion.table</code> hold"
        count = (
            f"<small>{len(shown)} of {len(table)} samples shown (one in {step}); "
            f"{where} all.</small>"
            if step > 1
            else f"<small>{len(table)} samples</small>"
        )
        self.table_note.value = (
            count + " " + self._code("panel.motion.table") + f"<small>{converted}</small>"
        )
        size = characteristic_length(motion.robot)
        self.table.value = dva_table_html(shown, units, size)
        stats = motion.stats()
        if point != ALL_POINTS:
            stats = stats.loc[[point]]
        self.stats_note.value = self._code("panel.motion.stats()") + f"<small>{converted}</small>"
        self.stats.value = stats_table_html(stats, units, size)

    # -- plot --------------------------------------------------------------------------

    def figure(self, state: PanelState) -> Figure | None:
        """The plot as the tab shows it (``None`` before a run)."""
        motion = state.motion
        if motion is None:
            return None
        view = state.view
        points = [*motion.points, ALL_POINTS]
        point = view.result_point if view.result_point in points else "EE"
        return motion.plot(
            point,
            displacement=view.displacement,
            length_unit=state.units.length,
            figsize=FIGSIZE,
            compare=self._comparison(state) if view.overlay else None,
        )

    def _comparison(self, state: PanelState) -> Motion | None:
        """The same run with the other method, simulated once per run."""
        motion, settings = state.motion, state.run_settings
        if motion is None or settings is None:
            return None
        if self._other is None or self._other[0] is not motion:
            other = simulate(
                motion.robot,
                dict(motion.signals),  # type: ignore[arg-type]
                **_other_settings(settings, motion),
            )
            self._other = (motion, other)
        return self._other[1]

    def _render_plot(self, state: PanelState, motion: Motion, point: str) -> None:
        view = state.view
        key = (id(motion), point, view.displacement, view.overlay, state.units)
        if key == self._plotted:
            return
        figure = self.figure(state)
        if figure is None:
            return
        self.plot.value = figure_png(figure, dpi=DPI)
        self._plotted = key
        self.plot_note.value = self._code(self._plot_call(state, motion, point), "Drawn by")

    def _plot_call(self, state: PanelState, motion: Motion, point: str) -> str:
        """The core call that draws the figure shown, as text."""
        arguments = [repr(point)]
        if state.view.displacement:
            arguments.append("displacement=True")
        arguments.append(f"length_unit={state.units.length!r}")
        if state.view.overlay and state.run_settings is not None:
            settings = _other_settings(state.run_settings, motion)
            if settings.get("t0") == 0.0:
                del settings["t0"]  # simulate's default: shorter to read
            keywords = ", ".join(f"{k}={v!r}" for k, v in settings.items())
            arguments.append(
                f"compare=rc.simulate(panel.motion.robot, panel.motion.signals, {keywords})"
            )
        return html.escape(f"panel.motion.plot({', '.join(arguments)})")

    def make_csv_link(self) -> str:
        """Build the CSV of the whole table as a ``data:`` link; returns its HTML."""
        self.csv_link.value = ""
        motion = self.motion
        if motion is None:
            return ""
        buffer = io.StringIO()
        motion.to_csv(buffer)  # the core's export, with its memory check
        content = buffer.getvalue()
        # The robot's name is the user's; download_link escapes it in the attribute and text.
        name = f"{motion.robot.name or 'robot'}_motion.csv".replace(" ", "_")
        self.csv_link.value = download_link(
            content, name, "text/csv", f"{name} ({len(content) / 1e6:.2g} MB)"
        )
        self._csv_for = motion
        return self.csv_link.value
