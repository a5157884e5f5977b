"""The Save / Load tab: the setup as JSON (a download link, a file upload) and the
exports (report, figures, the 3D scene, URDF, the LaTeX of one matrix).

Everything is made from the state when its button is pressed; a link is never left
pointing to an older state, and a refused export says why beside its button.
"""

from __future__ import annotations

import html
from collections.abc import Callable
from typing import Any

import ipywidgets as widgets
import numpy as np

from ..._errors import InvalidInputError
from ...io import to_urdf
from ...kinematics import Robot
from ...report import BadInput
from ...teaching import Derivation, derivation, symbolic_fits
from .. import actions as act
from ..form import Form, FormEvent, button, check, field, link, message, row, select, text, toggle
from ..header import preset_of
from ..state import PanelState
from ..support import code_hint, observe
from ..support._errors_display import ErrorLabel
from ._export_files import (
    FIGURE_FORMATS,
    figure_file,
    file_stem,
    report_zip,
    robot_figure,
    scene_page,
    step_latex,
)
from ._images import data_uri

__all__ = ["FilesView", "EXPORTS", "size_text", "robot_stem"]

#: The exports, in the order they are listed: key, button label, tooltip.
EXPORTS = (
    ("report", "report (zip)", "what `robotconf report` writes for this setup"),
    ("robot_figure", "robot figure", "the robot with its labelled points (the paper's Figure 14)"),
    ("dva_figure", "DVA figure", "the Motion tab's plot, as it shows it"),
    ("scene_html", "3D scene (HTML)", "one page that opens offline, animated with the last run"),
    ("urdf", "URDF", "the robot for ROS and other tools, lengths in metres"),
)
#: What an export makes: the content, the file name and its MIME type.
Download = tuple[bytes | str, str, str]
#: URDF lengths are metres: what one length unit of the panel is in metres.
METRES = {"mm": 1e-3, "cm": 1e-2, "m": 1.0, "in": 0.0254}


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


def robot_stem(robot: Robot) -> str:
    """A file-name stem for ``robot``: its preset's name, else its own name made safe.

    >>> import robotconf as rc
    >>> robot_stem(rc.preset("paper")), robot_stem(rc.Robot([rc.Module("Rz")], name="my arm"))
    ('paper', 'my_arm')
    """
    return preset_of(robot) or file_stem(robot.name)


class FilesView:
    """Save, load and export.

    Parameters
    ----------
    dispatch : callable
        ``dispatch(action, key, typed=None)``.
    save_text : callable
        The setup's JSON text (raises while it cannot be saved).
    source : callable
        Where the robot came from, named in the report (the bound file, or the panel).
    figure : callable
        ``figure(state)``: the Motion tab's plot as it shows it, or ``None``.
    app : bool
        No notebook around the panel: no hints to type code.
    """

    def __init__(
        self,
        dispatch: Callable[..., None],
        save_text: Callable[[], str],
        source: Callable[[], str],
        figure: Callable[[PanelState], Any],
        app: bool = False,
    ) -> None:
        self._dispatch = dispatch
        self._save_text = save_text
        self._source = source
        self._figure = figure
        self.app = app
        self._state: PanelState | None = None
        self._feedback: Any = None
        self._rev = ""
        self.filename = "robot.json"
        self.figure_format = "png"
        self.latex_step = ""
        self.latex_symbolic = False
        self.latex_lengths = False
        self._links: dict[str, tuple[Any, dict[str, Any]]] = {}  # key → (state, link spec)
        self._latex: tuple[Any, str] | None = None
        self._symbolic: tuple[Any, Derivation] | None = None
        self.form = Form(self._event, css_class="robotconf-files")
        self.upload = widgets.FileUpload(accept=".json,application/json", multiple=False)
        self.upload_error = ErrorLabel()
        observe(self.upload, self.upload_error, self._uploaded)
        self.latex = widgets.Textarea(
            layout=widgets.Layout(width="100%", height="150px"),
            placeholder="the LaTeX of the chosen matrix",
        )
        self.latex.add_class("robotconf-latex-export")
        self._load_intro = widgets.HTML(
            "<b>Load</b> a robotconf JSON file"
            + code_hint(" (or <code>panel.load(path)</code>)", app)
            + ":"
        )
        self.load_status = widgets.HTML()
        self.widget = widgets.VBox(
            [
                self._load_intro,
                widgets.HBox([self.upload, self.load_status, self.upload_error.widget]),
                self.form,
                self.latex,
            ]
        )
        self.widget.add_class("robotconf-files-tab")

    # -- drawing ------------------------------------------------------------------------

    def render(self, state: PanelState, feedback: Any, rev: str, visible: bool) -> None:
        """Show the buttons and the links made for this very state (only while visible)."""
        self._state = state
        self._feedback, self._rev = feedback, rev
        if not visible:
            return
        note = feedback.message
        save_hint = code_hint(" (or panel.save(path) in a cell)", self.app)
        rows = [
            row(
                "save",
                [
                    text(
                        "Save the robot, its signals, time settings and program as JSON"
                        + save_hint
                        + ":",
                        tone="title",
                    )
                ],
                [
                    field("save.name", self.filename, label="file name", width="200px", rev=rev),
                    button("save.make", "Save (download link)", css_class="robotconf-save"),
                    *self._link("save", state),
                ],
                note=message(note("save")),
            ),
            row(
                "export",
                [
                    text(
                        "Export the current robot, its signals and time settings"
                        + code_hint(" (the report is what robotconf report writes)", self.app)
                        + ":",
                        tone="title",
                    )
                ],
                [
                    text("figures as"),
                    toggle(
                        "export.format",
                        self.figure_format,
                        [(fmt.upper(), fmt) for fmt in FIGURE_FORMATS],
                        rev=rev,
                    ),
                ],
            ),
        ]
        for key, label, tip in EXPORTS:
            rows.append(
                row(
                    f"export.{key}",
                    [
                        button(
                            f"export.{key}",
                            label,
                            title=tip,
                            css_class=f"robotconf-export-{key.replace('_', '-')}",
                        ),
                        *self._link(key, state),
                    ],
                    note=message(note(f"export.{key}")),
                )
            )
        rows.append(self._latex_row(state, note))
        self.form.show(rows)

    def _link(self, key: str, state: PanelState) -> list[dict[str, Any]]:
        made = self._links.get(key)
        if made is None or made[0] is not state.document:
            return []
        return [made[1]]

    def _latex_row(self, state: PanelState, note: Callable[[str], str]) -> dict[str, Any]:
        robot = state.robot
        fits = symbolic_fits(robot)
        symbolic = self.latex_symbolic and fits
        steps = self._steps(robot, symbolic)
        names = [step.name for step in steps] if steps is not None else []
        chosen = self.latex_step if self.latex_step in names else (names[-1] if names else "")
        key = (robot, symbolic, self.latex_lengths, chosen)
        if steps is not None and (self._latex is None or self._latex[0] != key):
            self.latex.value = step_latex(steps, chosen)
            self._latex = (key, chosen)
        return row(
            "latex",
            [text("LaTeX of one matrix, to copy into a document:", tone="title")],
            [
                select("latex.step", chosen, [(n, n) for n in names], label="matrix", width="90px"),
                check("latex.symbolic", self.latex_symbolic, "symbolic", disabled=not fits),
                check(
                    "latex.lengths",
                    self.latex_lengths,
                    "lengths as l1, l2, …",
                    disabled=not fits or not self.latex_symbolic,
                ),
            ],
            note=message(note("latex")),
        )

    def _steps(self, robot: Robot, symbolic: bool) -> Derivation | None:
        if not symbolic:
            return derivation(robot)
        key = (robot.with_q(np.zeros(robot.n)), self.latex_lengths)
        if self._symbolic is None or self._symbolic[0] != key:
            try:
                steps = derivation(robot, symbolic=True, lengths=self.latex_lengths)
            except InvalidInputError as error:
                self._dispatch(error, "latex")
                return None
            self._symbolic = (key, steps)  # one structure at a time: bounded memory
        return self._symbolic[1]

    # -- input --------------------------------------------------------------------------

    def _event(self, event: FormEvent) -> None:
        key = event.key
        if key == "save.name":
            self.filename = (event.text or "").strip() or "robot.json"
        elif key == "save.make":
            self._make("save", self._save)
            return
        elif key == "export.format":
            self.figure_format = str(event.value)
        elif key.startswith("export."):
            name = key.split(".", 1)[1]
            self._make(name, getattr(self, f"_{name}"), progress=name == "report")
            return
        elif key == "latex.step":
            self.latex_step = str(event.value)
        elif key == "latex.symbolic":
            self.latex_symbolic = bool(event.value)
        elif key == "latex.lengths":
            self.latex_lengths = bool(event.value)
        self._dispatch(None, key)  # a choice of this tab: draw it again

    def _make(self, key: str, produce: Callable[[], Download], progress: bool = False) -> None:
        """Make export ``key`` for the current state; its link, or why not, beside it."""
        state = self._state
        if state is None:
            return
        self._links.pop(key, None)  # never a link to an older state, whatever fails below
        label = "save" if key == "save" else f"export.{key}"
        if progress:
            self._progress(key, "preparing…")
        try:
            content, name, mime = produce()
        except (InvalidInputError, BadInput) as error:
            self._links.pop(key, None)  # no "preparing…" left behind
            self._dispatch(error, label)
            return
        raw = content.encode("utf-8") if isinstance(content, str) else content
        spec = link(
            data_uri(raw, mime),
            name,
            f"{name} ({size_text(len(raw))})",
            key=f"{key}.link",
            css_class="robotconf-download",
        )
        self._links[key] = (state.document, spec)
        if self._feedback is not None:
            self._feedback.accepted(label)  # it worked: an old refusal goes
        self._dispatch(None, label)

    def _progress(self, key: str, what: str) -> None:
        state = self._state
        if state is None:
            return
        self._links[key] = (state.document, text(what, tone="note", key=f"{key}.link"))
        self.render(state, self._feedback, self._rev, True)  # shown while the work goes on

    # -- producers ----------------------------------------------------------------------

    def _save(self) -> Download:
        name = self.filename if self.filename.endswith(".json") else self.filename + ".json"
        return self._save_text(), name, "application/json"

    def _report(self) -> Download:
        state = self._state
        assert state is not None
        motion = state.document.motion
        signals = motion.driven(state.robot.coordinate_names)
        stem = robot_stem(state.robot)

        def step(done: int, total: int, what: str) -> None:
            self._progress("report", f"preparing… {done}/{total}: {what}")

        data = report_zip(
            state.robot, signals, motion.settings, source=self._source(), stem=stem, progress=step
        )
        return data, f"{stem}_report.zip", "application/zip"

    def _figure_download(self, figure: Any, name: str) -> Download:
        fmt = self.figure_format
        return figure_file(figure, fmt), f"{name}.{fmt}", FIGURE_FORMATS[fmt]

    def _robot_figure(self) -> Download:
        state = self._state
        assert state is not None
        figure = robot_figure(state.robot, length_unit=state.units.length)
        return self._figure_download(figure, f"{robot_stem(state.robot)}_robot")

    def _dva_figure(self) -> Download:
        state = self._state
        assert state is not None
        motion = state.motion
        if motion is None:
            raise InvalidInputError(
                "motion", None, "a motion: press Run on the Motion tab first", "nothing to plot:"
            )
        point = state.view.result_point if state.view.result_point in motion.points else "all"
        figure = self._figure(state)
        stem = robot_stem(motion.robot)
        return self._figure_download(figure, f"{stem}_dva_{file_stem(point)}")

    def _scene_html(self) -> Download:
        state = self._state
        assert state is not None
        title = preset_of(state.robot) or state.robot.name or "robot"
        page = scene_page(state.robot, state.motion, title=title)
        return page, f"{robot_stem(state.robot)}_scene.html", "text/html"

    def _urdf(self) -> Download:
        state = self._state
        assert state is not None
        scale = METRES.get(state.units.length, 1.0)
        urdf = to_urdf(state.robot, scale=scale)
        return urdf, f"{robot_stem(state.robot)}.urdf", "application/xml"

    def _uploaded(self, change: dict[str, Any]) -> None:
        files = change["new"]
        if not files:
            return
        upload = files[0]
        self.load_status.value = ""
        from ._setup_io import setup_parts

        try:
            robot, signals, simulation, program = setup_parts(bytes(upload["content"]))
        except InvalidInputError as error:
            self.upload_error.show(str(error))
            return
        self.upload_error.clear()
        self._dispatch(act.LoadSetup(robot, signals, simulation, program), "load")
        # The file name is the user's: text, never markup.
        self.load_status.value = f"<small>loaded {html.escape(str(upload['name']))}</small>"
