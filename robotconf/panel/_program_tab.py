"""The "Program" tab: a robot program (PTP, LIN, CIRC and Wait moves) taught and run in
the panel.

A table holds one row per move (:mod:`robotconf.panel._program_row`); **teach** records
where the robot is now, **add move** appends a PTP to the current coordinates, and the
rows move up, down or go (the tab's own ↶ ↷ undo every edit). Every edit hands the
moves to :class:`robotconf.programs.Program`, whose refusal (an unreachable target, a LIN
that goes nowhere, three points of a CIRC on one line, a negative speed) shows beside the
move while the last valid program stays. **Run** checks and simulates the program: the
violations show under the moves that cause them, the motion becomes the panel's last
simulation (the Motion tab's tables, statistics and plot) and plays in the 3D view with
the end effector's trace. While the tab shows, the 3D view marks where each move ends
(P1, P2, …). The program is saved with the panel's setup (docs/file-format.md).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator, Sequence
from typing import Any

import ipywidgets as widgets
import numpy as np

from .._errors import InvalidInputError
from ..kinematics import Robot
from ..programs import LIMIT_NAMES, PTP, Program, ProgramMotion, ProgramReport
from ._callbacks import on_click
from ._errors_display import ErrorLabel
from ._program_draft import ProgramDraft, build, draft_of, remapped
from ._program_edits import edit_move, row_action, taught_markers
from ._program_history import TimelineButtons
from ._program_limits import LimitControls
from ._program_row import MoveRow, RowContext
from ._program_run import run_program, run_summary, violations_by_move
from ._ranges import length_scale, length_step
from ._units import Units

__all__ = ["ProgramTab"]

_MOVE_FIELD = re.compile(r"moves\[(\d+)\]")
_INTRO = (
    "<b>Program</b> <small>Moves run in order from where the robot is now, each ending "
    "at rest: <b>PTP</b> moves every joint at once (synchronized), <b>LIN</b> the end "
    "effector on a straight line, <b>CIRC</b> on an arc through a via point; <b>Wait</b> "
    "holds. <b>teach</b> takes the robot's current pose.</small>"
)


class ProgramTab:
    """The move table, the program's limits, Run, and the taught points in the 3D view.

    Parameters
    ----------
    robot : callable
        Returns the panel's current robot.
    scene : object
        The panel's 3D scene; ``show_taught_points``/``clear_taught_points`` are used
        when it has them.
    units : Units
        The panel's units.
    show_motion : callable
        ``show_motion(motion)`` shows a run as the panel's last simulation and plays it.
    open_motion : callable, optional
        Brings the Motion tab to the front (its button is hidden without one).
    on_change : callable, optional
        Called after every edit of the program (the bound file saves).
    dt : float
        The sampling step Run starts with (s).
    app : bool
        The panel runs without cells around it: no hints to type code.

    Attributes
    ----------
    draft : ProgramDraft
        The moves and settings the table shows.
    program : Program or None
        The last valid program (``None`` while the table is empty).
    motion : ProgramMotion or None
        The last Run's motion; ``report`` its violations.

    Examples
    --------
    >>> import robotconf as rc
    >>> robot = rc.preset("paper")
    >>> tab = ProgramTab(lambda: robot, None, Units(), show_motion=lambda motion: None)
    >>> tab.add_button.click()  # a PTP to where the robot is
    >>> tab.rows[0].kind.value = "LIN"  # a line to the same point: refused, with the reason
    >>> tab.rows[0].error.message[:39]
    'moves[0].position: the LIN goes nowhere'
    >>> tab.history.undo_button.click()  # the PTP again
    >>> tab.rows[0].boxes["q"][2].value = 90.0  # degrees
    >>> tab.run_button.click()
    >>> tab.program.moves[0].q == (0.0, 0.0, np.pi / 2), tab.report.ok
    (True, True)
    >>> round(tab.program.duration, 4)  # π/2 at 1 rad/s, 2 rad/s²: π/2 / 1 + 1 / 2
    2.0708
    """

    def __init__(
        self,
        robot: Callable[[], Robot],
        scene: Any,
        units: Units,
        *,
        show_motion: Callable[[ProgramMotion], None],
        open_motion: Callable[[], None] | None = None,
        on_change: Callable[[], None] | None = None,
        dt: float = 0.01,
        app: bool = False,
    ):
        self._robot = robot
        self._scene = scene
        self.units = units
        self.app = app
        self._show_motion = show_motion
        self._on_change = on_change or (lambda: None)
        self.draft = ProgramDraft()
        self.program: Program | None = None
        self.motion: ProgramMotion | None = None
        self.report: ProgramReport | None = None
        self.rows: list[MoveRow] = []
        self._built: tuple[Robot, ProgramDraft, Program | InvalidInputError | None] | None = None
        self._structure: Robot | None = None  # the robot at q = 0 the table was shown for
        self._visible = False
        self._edited = False  # the program changed since the last Run
        self.history = TimelineButtons(self.draft, self._restore, "the last change of the program")
        self.history.widget.add_class("robotconf-program-history")
        self.limits = LimitControls(self._limit_typed)
        self.dt = widgets.FloatText(
            value=dt, description="dt [s]", layout=widgets.Layout(width="170px")
        )
        self.dt_error = ErrorLabel()
        self.add_button = widgets.Button(
            description="add move",
            icon="plus",
            tooltip="add a PTP move to the robot's current coordinates",
            layout=widgets.Layout(width="auto"),
        )
        self.clear_button = widgets.Button(
            description="clear",
            icon="trash",
            tooltip="delete every move (↶ brings them back)",
            layout=widgets.Layout(width="auto"),
        )
        self.run_button = widgets.Button(description="Run", icon="play", button_style="primary")
        self.motion_button = widgets.Button(
            description="tables and plots: Motion tab",
            icon="table",
            disabled=True,
            layout=widgets.Layout(width="auto", display=None if open_motion else "none"),
        )
        self.error = ErrorLabel()
        self.run_error = ErrorLabel()
        self.status = widgets.HTML()
        for widget, name in (
            (self.add_button, "add"),
            (self.run_button, "run"),
            (self.status, "status"),
        ):
            widget.add_class(f"robotconf-program-{name}")
        self._rows_box = widgets.VBox()
        self.widget = widgets.VBox(
            [
                widgets.HTML(_INTRO),
                widgets.HBox(
                    [self.history.widget, self.add_button, self.clear_button, self.error.widget],
                    layout=widgets.Layout(flex_flow="row wrap", align_items="center"),
                ),
                self._rows_box,
                widgets.HTML("<b>Limits</b> <small>(typed, or the core's defaults)</small>"),
                self.limits.widget,
                widgets.HBox(
                    [self.dt, self.run_button, self.motion_button, self.dt_error.widget],
                    layout=widgets.Layout(flex_flow="row wrap", align_items="center"),
                ),
                self.run_error.widget,
                self.status,
            ]
        )
        self.widget.add_class("robotconf-program-tab")
        on_click(self.add_button, self.error, self.add_move)
        on_click(self.clear_button, self.error, lambda: self._set_moves([]))
        on_click(self.run_button, self.run_error, self.run)
        if open_motion is not None:
            on_click(self.motion_button, self.run_error, open_motion)
        self._render()

    # -- what the panel calls -----------------------------------------------------------

    def show(self, robot: Robot, order: Sequence[int | None] | None = None) -> None:
        """The panel's robot changed: PTP coordinates follow added, removed or moved
        modules (``order``, as for the motion signals); a new geometry is checked again."""
        if self.draft.moves and (order is not None or self._misfits(robot)):
            self._set_draft(remapped(self.draft, robot, order))
            return
        if self.draft.moves or self._visible:
            structure = robot.with_q(np.zeros(robot.n))
            if structure != self._structure:
                self._structure = structure
                self._refresh()
        self._show_status()

    def set_visible(self, visible: bool) -> None:
        """Mark the taught points while the tab shows; take them away when not."""
        self._visible = bool(visible)
        if self._visible:
            self._refresh()
        else:
            self._call("clear_taught_points")

    def set_units(self, units: Units) -> None:
        """Show every number in ``units``; the program itself stays."""
        self.units = units
        self._render()

    def load(self, program: Program | None) -> None:
        """Show a loaded program (``None``: an empty table), as one undoable step; the
        first program of a table never edited is where its undo starts."""
        draft = draft_of(program)
        if program is not None:
            self._built = (program.robot, draft, program)
        fresh = not self.draft.moves and not self.history.timeline.can_undo
        self._set_draft(draft, record=not fresh)
        if fresh:
            self.history.reset(draft)

    def saved_program(self, robot: Robot) -> Program | None:
        """The program to save with ``robot``: the table's, built for it.

        Raises
        ------
        InvalidInputError
            While the core refuses the table (named ``program.moves[i]…``): the panel's
            file keeps its last valid setup.
        """
        try:
            return self._build(robot)
        except InvalidInputError as error:
            raise error.within("program") from None

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)`` of every error label of the tab."""
        yield "program", self.error
        yield "program.history", self.history.error
        yield "program.run", self.run_error
        yield "program.dt", self.dt_error
        yield from self.limits.error_items()
        for row in self.rows:
            yield from row.error_items()

    # -- editing ------------------------------------------------------------------------

    def add_move(self) -> None:
        """Append a PTP to the robot's current coordinates."""
        robot = self._robot()
        self._set_moves([*self.draft.moves, PTP(q=tuple(float(v) for v in robot.q))])

    def _edit(self, index: int, name: str, value: Any, component: int | None) -> None:
        self._set_draft(edit_move(self.draft, self._robot(), index, name, value, component))

    def _action(self, index: int, action: str) -> None:
        self._set_draft(row_action(self.draft, self._robot(), index, action))

    def _limit_typed(self, setting: str, value: Any) -> None:
        self._set_draft(self.draft.with_setting(setting, value))

    def _set_moves(self, moves: Sequence[Any]) -> None:
        self._set_draft(self.draft.with_moves(moves))

    def _restore(self, draft: ProgramDraft) -> None:
        self._set_draft(draft, record=False)

    def _set_draft(self, draft: ProgramDraft, record: bool = True) -> None:
        """Show ``draft``, check it with the core, and save; ``record`` for undo."""
        changed = draft != self.draft
        self.draft = draft
        if record:
            self.history.record(draft)
        if changed:
            self._edited = True
            for row in self.rows:
                row.show_violations([])  # they belong to the moves of the last Run
        self._refresh()
        self._show_status()
        if changed:
            self._on_change()

    # -- checking -----------------------------------------------------------------------

    def _build(self, robot: Robot) -> Program | None:
        """The table's program for ``robot`` (cached per robot and draft)."""
        built = self._built
        if built is None or built[1] != self.draft or built[0] != robot:
            try:
                result: Program | InvalidInputError | None = build(self.draft, robot)
            except InvalidInputError as error:
                result = error
            built = self._built = (robot, self.draft, result)
        if isinstance(built[2], InvalidInputError):
            raise built[2].with_traceback(None)  # cached: no tracebacks piled up on it
        return built[2]

    def _check(self) -> None:
        """Show the core's verdict on the table: its message beside the move or limit it
        names, or none (the program becomes the last valid one)."""
        labels = [self.error, *self.limits.errors.values(), *(row.error for row in self.rows)]
        for label in labels:
            label.clear()
        try:
            program = self._build(self._robot())
        except InvalidInputError as error:
            self._label_for(error.field).show(str(error))
            return
        self.program = program  # an empty table is valid too: no program

    def _label_for(self, field: str) -> ErrorLabel:
        match = _MOVE_FIELD.match(field)
        if match is not None and int(match.group(1)) < len(self.rows):
            return self.rows[int(match.group(1))].error
        name = field.split(".")[0].split("[")[0]
        if name in LIMIT_NAMES and name in self.limits.errors:
            return self.limits.errors[name]
        return self.dt_error if name == "dt" else self.error

    # -- running ------------------------------------------------------------------------

    def run(self) -> ProgramMotion | None:
        """Check and simulate the table's program; on bad input keep the last run."""
        for label in (self.run_error, self.dt_error):
            label.clear()
        robot = self._robot()
        try:
            program = self._build(robot)
            if program is None:
                Program(robot, [])  # the core says what an empty program lacks
                return None
            report, motion = run_program(program, self.dt.value)
        except InvalidInputError as error:
            label = self._label_for(error.field)
            (self.run_error if label is self.error else label).show(str(error))
            return None
        self.program, self.motion, self.report, self._edited = program, motion, report, False
        for row, messages in zip(
            self.rows, violations_by_move(report, len(self.rows)), strict=True
        ):
            row.show_violations(messages)
        self.motion_button.disabled = False
        self._show_status()
        self._show_motion(motion)
        return motion

    # -- showing ------------------------------------------------------------------------

    def _refresh(self) -> None:
        self._render()
        self._check()
        self._draw()

    def _render(self) -> None:
        """The rows and the limits as the draft has them, in the panel's units."""
        robot = self._robot()
        moves = self.draft.moves
        while len(self.rows) > len(moves):
            self.rows.pop().close()
        while len(self.rows) < len(moves):
            self.rows.append(MoveRow(len(self.rows), self._edit, self._action))
        self._rows_box.children = tuple(row.widget for row in self.rows)
        limits = self.limits.defaults(robot)
        speed = self.draft.settings.get("cartesian_speed") or limits.cartesian_speed
        context = RowContext(
            robot, self.units, length_step(length_scale(robot)), float(speed), len(moves)
        )
        for row, move in zip(self.rows, moves, strict=True):
            row.show(move, context)
        self.limits.show(robot, self.draft.settings, limits, self.units)

    def _draw(self) -> None:
        """Mark where each move ends (P1, P2, …) and the CIRC via points in the 3D view."""
        if not self._visible:
            return
        points, labels, via, via_labels = taught_markers(self.draft, self._robot())
        if not len(points) and not len(via):
            self._call("clear_taught_points")
        else:
            self._call("show_taught_points", points, labels, via=via, via_labels=via_labels)

    def _show_status(self) -> None:
        motion, report = self.motion, self.report
        if motion is None or report is None:
            self.status.value = "<small>Run checks and simulates the program.</small>"
            return
        text = run_summary(motion, report, app=self.app)
        if self._edited:
            text += "<br><small>the program changed since this run: press Run</small>"
        elif motion.robot != self._robot():
            text += "<br><small>the robot changed since this run: press Run</small>"
        self.status.value = text

    def _misfits(self, robot: Robot) -> bool:
        return any(
            isinstance(move, PTP) and move.q is not None and len(move.q) != robot.n
            for move in self.draft.moves
        )

    def _call(self, name: str, *args: Any, **kwargs: Any) -> None:
        method = getattr(self._scene, name, None)
        if method is not None:
            method(*args, **kwargs)
