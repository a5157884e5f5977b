"""The export buttons of the Save / Load tab: each makes a download link in the page.

Report folder (zip), robot and DVA figures (PNG or SVG), the 3D scene as one HTML page,
the robot as URDF, and one matrix of the derivation as LaTeX text to copy. The content
comes from :mod:`robotconf.panel._export_files` (the core's own exporters); this module
only wires buttons, links and error labels. A refused export (a run over the memory
budget, no Run yet) says why beside its button and leaves no link to an older state.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import ipywidgets as widgets
import numpy as np

from .._errors import InvalidInputError
from ..io import to_urdf
from ..kinematics import Robot
from ..report import BadInput
from ..teaching import Derivation, derivation, symbolic_fits
from ._app_mode import code_hint
from ._callbacks import Guarded, observe, on_click
from ._errors_display import ErrorLabel
from ._export_files import (
    FIGURE_FORMATS,
    figure_file,
    file_stem,
    report_zip,
    robot_figure,
    scene_page,
    step_latex,
)
from ._images import download_link

if TYPE_CHECKING:
    from ._motion_section import MotionSection

__all__ = ["ExportsSection", "size_text"]

#: What a producer returns: the content, the file name and its MIME type.
Download = tuple[bytes | str, str, str]


def size_text(size: int) -> str:
    """``"12 kB"``, ``"1.3 MB"``: the size shown in a link.

    >>> size_text(900), size_text(12_345), size_text(1_250_000)
    ('900 B', '12 kB', '1.2 MB')
    """
    if size < 1000:
        return f"{size} B"
    if size < 1_000_000:
        return f"{size / 1e3:.0f} kB"
    return f"{size / 1e6:.2g} MB"


@dataclass
class _Export:
    """One export: its button, the link it makes and the label for its errors."""

    button: widgets.Button
    link: widgets.HTML
    error: ErrorLabel

    def row(self) -> widgets.HBox:
        """Button, link and error label side by side."""
        return widgets.HBox(
            [self.button, self.link, self.error.widget],
            layout=widgets.Layout(align_items="center"),
        )


class ExportsSection:
    """Export buttons and the LaTeX of one matrix.

    Parameters
    ----------
    robot : callable
        Returns the panel's current valid robot.
    motion_section : MotionSection
        Signals and time settings (for the report), the last motion and its chosen
        point (for the DVA figure).
    source : callable
        Where the robot came from, named in the report (the bound file, or the panel).
    app : bool
        The panel runs without cells around it (Voilà): no hint that names code.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.panel._motion_section import MotionSection
    >>> robot = rc.Robot([rc.Module("Tz", q=2.0)], end_effector=(1, 0, 0))
    >>> motion = MotionSection(lambda: robot, lambda m: None)
    >>> exports = ExportsSection(lambda: robot, motion, source=lambda: "doctest")
    >>> exports.make("urdf").startswith("<a download=")
    True
    >>> exports.make("dva_figure"), exports.errors["dva_figure"][:24]
    ('', 'motion: nothing to plot:')
    """

    def __init__(
        self,
        robot: Callable[[], Robot],
        motion_section: MotionSection,
        *,
        source: Callable[[], str],
        app: bool = False,
    ):
        self._robot = robot
        self._motion = motion_section
        self._source = source
        self.figure_format = widgets.ToggleButtons(
            options=[(fmt.upper(), fmt) for fmt in FIGURE_FORMATS],
            value="png",
            tooltips=["picture (pixels)", "vector drawing, for print"],
            style={"button_width": "48px"},
        )
        producers: dict[str, tuple[str, str, Callable[[], Download]]] = {
            "report": ("report (zip)", "file-archive-o", self._report),
            "robot_figure": ("robot figure", "image", self._robot_figure),
            "dva_figure": ("DVA figure", "line-chart", self._dva_figure),
            "scene_html": ("3D scene (HTML)", "cube", self._scene_html),
            "urdf": ("URDF", "code", self._urdf),
        }
        self.exports: dict[str, _Export] = {}
        for key, (label, icon, produce) in producers.items():
            export = _Export(
                widgets.Button(description=label, icon=icon, layout=widgets.Layout(width="170px")),
                widgets.HTML(),
                ErrorLabel(),
            )
            export.button.add_class(f"robotconf-export-{key.replace('_', '-')}")
            self.exports[key] = export
            on_click(export.button, export.error, self._maker(key, produce))
        self.latex = _LatexView()
        self.widget = widgets.VBox(
            [
                widgets.HTML(
                    "<b>Export</b> the current robot, its signals and time settings"
                    + code_hint(" (the report is what <code>robotconf report</code> writes)", app)
                    + ":"
                ),
                self.exports["report"].row(),
                widgets.HBox(
                    [widgets.HTML("figures as"), self.figure_format],
                    layout=widgets.Layout(align_items="center"),
                ),
                self.exports["robot_figure"].row(),
                self.exports["dva_figure"].row(),
                self.exports["scene_html"].row(),
                self.exports["urdf"].row(),
                self.latex.widget,
            ]
        )

    @property
    def errors(self) -> dict[str, str]:
        """``{export key: message}`` of the exports refused last time."""
        return {key: label.message for key, label in self.error_items() if label.message}

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)``: ``report``, ``robot_figure``, ``dva_figure``, ``scene_html``,
        ``urdf``, ``latex``."""
        for key, export in self.exports.items():
            yield key, export.error
        yield "latex", self.latex.error

    def make(self, key: str) -> str:
        """Click export ``key``; returns the link's HTML (``""`` when refused)."""
        self.exports[key].button.click()
        return str(self.exports[key].link.value)

    def show(self, robot: Robot) -> None:
        """The robot changed: the LaTeX view follows (when its tab shows)."""
        self.latex.show(robot)

    def set_visible(self, visible: bool) -> None:
        """Whether the tab shows (the LaTeX view waits until it does)."""
        self.latex.set_visible(visible)

    # -- producers ----------------------------------------------------------------------

    def _maker(self, key: str, produce: Callable[[], Download]) -> Callable[[], None]:
        export = self.exports[key]

        def make() -> None:
            export.error.clear()
            # Never a link to an older state, whatever fails below.
            export.link.value = "<small>preparing…</small>"
            try:
                content, name, mime = produce()
            except BadInput as error:  # the report's results overflow: the user's to change
                export.link.value = ""
                export.error.show(str(error))
                return
            except Exception:
                export.link.value = ""
                raise  # the guard shows it beside the button
            size = size_text(len(content.encode() if isinstance(content, str) else content))
            export.link.value = download_link(content, name, mime, f"{name} ({size})")

        return make

    def _stem(self) -> str:
        return file_stem(self._robot().name)

    def _report(self) -> Download:
        signals = self._motion.signals()
        if signals is None:
            raise InvalidInputError(
                "signals", "invalid", "valid signals: fix the one marked in red first"
            )
        settings = self._motion.simulation_settings()
        data = report_zip(self._robot(), signals, settings, source=self._source())
        return data, f"{self._stem()}_report.zip", "application/zip"

    def _figure(self, figure: Any, name: str) -> Download:
        fmt = self.figure_format.value
        return figure_file(figure, fmt), f"{name}.{fmt}", FIGURE_FORMATS[fmt]

    def _robot_figure(self) -> Download:
        return self._figure(robot_figure(self._robot()), f"{self._stem()}_robot")

    def _dva_figure(self) -> Download:
        results = self._motion.results
        motion = results.motion
        if motion is None:
            raise InvalidInputError(
                "motion", None, "a motion: press Run on the Motion tab first", "nothing to plot:"
            )
        # The figure the plot tab shows: its point (or all), units and overlay.
        point = results.point.value if results.point.value in motion.points else "all"
        figure = results.figure()
        return self._figure(figure, f"{file_stem(motion.robot.name)}_dva_{file_stem(point)}")

    def _scene_html(self) -> Download:
        page = scene_page(self._robot(), self._motion.motion)
        return page, f"{self._stem()}_scene.html", "text/html"

    def _urdf(self) -> Download:
        return to_urdf(self._robot()), f"{self._stem()}.urdf", "application/xml"


class _LatexView:
    """One matrix of the derivation (numeric at the robot's q, or symbolic) as LaTeX text."""

    def __init__(self) -> None:
        self.step = widgets.Dropdown(description="matrix", layout=widgets.Layout(width="180px"))
        self.symbolic = widgets.Checkbox(value=False, description="symbolic", indent=False)
        self.lengths = widgets.Checkbox(
            value=False, description="lengths as l1, l2, …", indent=False
        )
        self.text = widgets.Textarea(
            layout=widgets.Layout(width="100%", height="150px"),
            placeholder="the LaTeX of the chosen matrix",
        )
        self.text.add_class("robotconf-latex-export")
        self.error = ErrorLabel()
        self.widget = widgets.VBox(
            [
                widgets.HTML("<b>LaTeX</b> of one matrix, to copy into a document:"),
                widgets.HBox(
                    [self.step, self.symbolic, self.lengths, self.error.widget],
                    layout=widgets.Layout(flex_flow="row wrap", align_items="center"),
                ),
                self.text,
            ]
        )
        self.visible = False
        self._robot: Robot | None = None
        self._shown: Any = None
        self._symbolic_cache: dict[Any, Derivation] = {}
        self._step_handler: Guarded = observe(self.step, self.error, lambda _: self.render())
        observe(self.symbolic, self.error, lambda _: self.render())
        observe(self.lengths, self.error, lambda _: self.render())

    def show(self, robot: Robot) -> None:
        self._robot = robot
        self.render()  # nothing while hidden: a q slider's tick costs nothing here

    def set_visible(self, visible: bool) -> None:
        self.visible = visible
        self.render()

    def render(self) -> None:
        robot = self._robot
        if robot is None or not self.visible:
            return
        self.symbolic.disabled = self.lengths.disabled = not symbolic_fits(robot)
        symbolic = self.symbolic.value and not self.symbolic.disabled
        key = (robot, symbolic, bool(self.lengths.value), self.step.value)
        if key == self._shown:
            return
        steps = self._symbolic(robot) if symbolic else derivation(robot)
        names = [step.name for step in steps]
        if list(self.step.options) != names:
            keep = self.step.value if self.step.value in names else names[-1]
            with self._step_handler.paused():
                self.step.options = names
                self.step.value = keep
        self.text.value = step_latex(steps, self.step.value)
        self._shown = (robot, symbolic, bool(self.lengths.value), self.step.value)

    def _symbolic(self, robot: Robot) -> Derivation:
        # The symbolic matrices do not depend on q: one computation per structure.
        key = (robot.with_q(np.zeros(robot.n)), bool(self.lengths.value))
        steps = self._symbolic_cache.get(key)
        if steps is None:
            steps = derivation(robot, symbolic=True, lengths=bool(self.lengths.value))
            self._symbolic_cache = {key: steps}  # one structure at a time: bounded memory
        return steps
