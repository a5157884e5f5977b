"""The Program tab: PTP, LIN, CIRC and Wait moves taught, edited and run.

A row per move (:func:`move_rows`); **teach** takes where the robot is now, **add move**
appends a PTP to the current coordinates; the header's and this tab's ↶ ↷ undo any edit.
Every edit is checked by :class:`robotconf.programs.Program` for the panel's robot.
**Run** checks and simulates the program: the violations show under their moves, the run
becomes the panel's last simulation (the Motion tab's tables and plot) and plays in the
3D view with the end effector's trace. While the tab shows, the 3D view marks where each
move ends (P1, P2, …) and each CIRC's via point.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

from ..._errors import InvalidInputError
from ...programs import Program, ProgramReport
from .. import actions as act
from .._feedback import Feedback
from ..form import Form, FormEvent, button, message, number, row, text
from ..state import PanelState, Units, in_units
from ..state._program_draft import build
from ..support._app_mode import code_hint
from ..viewport import Extras
from ._limits import LIMIT_FIELDS, default_limits, limit_controls, limit_value
from ._rows import BOX_UNITS, move_rows

__all__ = ["ProgramView", "violations_by_move", "run_summary"]

_FIELD = re.compile(r"^program\.moves\[(\d+)\]\.(\w+?)(\d*)$")
_MOVE_FIELD = re.compile(r"moves\[(\d+)\]")
INTRO = (
    "Moves run in order from where the robot is now, each ending at rest: PTP moves every "
    "joint at once (synchronized), LIN the end effector on a straight line, CIRC on an arc "
    "through a via point; Wait holds. teach takes the robot's current pose."
)


def violations_by_move(report: ProgramReport, moves: int, units: Units) -> list[list[str]]:
    """The core's message of every violation (in the panel's units), listed under the
    move that causes it."""
    found: list[list[str]] = [[] for _ in range(moves)]
    for violation in report:
        if 0 <= violation.move < moves:
            found[violation.move].append(in_units(violation.message, units))
    return found


def run_summary(run: Any, app: bool) -> tuple[str, str]:
    """The status line after a Run and its tone: duration, samples, violations."""
    motion, report = run.motion, run.report
    dt = float(motion.t[1] - motion.t[0]) if motion.t.size > 1 else float("nan")
    head = f"{motion.program.duration:.6g} s, {motion.t.size} samples (dt = {dt:.6g} s)"
    hint = code_hint("; numbers: panel.program.check(dt), panel.motion", app)
    if report.ok:
        return f"✓ {head}: no violations{hint}", "ok"
    where = ", ".join(f"P{m}" for m in sorted({v.move + 1 for v in report}))
    return (
        f"⚠ {head}: {len(report)} violation(s), at {where} (each under its move){hint}",
        "warning",
    )


class ProgramView:
    """The move table, the limits, Run, and the taught points in the 3D view.

    Parameters
    ----------
    dispatch : callable
        ``dispatch(action, key, typed=None)``.
    undo, redo : callable
        The panel's undo and redo (one history for every edit).
    history : callable
        ``history()`` → ``(can_undo, can_redo)``.
    app : bool
        No notebook around the panel: no hints to type code.
    """

    def __init__(
        self,
        dispatch: Callable[..., None],
        undo: Callable[[], None],
        redo: Callable[[], None],
        history: Callable[[], tuple[bool, bool]],
        app: bool = False,
    ) -> None:
        self._dispatch = dispatch
        self._undo, self._redo, self._history = undo, redo, history
        self.app = app
        self._state: PanelState | None = None
        self._built: tuple[Any, Any, Program | InvalidInputError | None] | None = None
        self.form = Form(self._event, css_class="robotconf-program-tab")
        self.widget = self.form

    def program(self, state: PanelState) -> Program | None:
        """The program the table makes for the robot (``None`` while empty or refused)."""
        built = self._build(state)
        return None if isinstance(built, InvalidInputError) else built

    def refusal(self, state: PanelState) -> tuple[str, str] | None:
        """``(control key, message)`` of the core's refusal of the table, if any: a move's
        (``program.moves[1]``), a limit's (``program.joint_accel``) or the table's."""
        built = self._build(state)
        if not isinstance(built, InvalidInputError):
            return None
        message = in_units(str(built.within("program")), state.units)  # as Run says it
        match = _MOVE_FIELD.search(built.field)
        if match is not None:
            return f"program.moves[{match.group(1)}]", message
        name = built.field.split(".")[0].split("[")[0]
        if name in {setting for _, setting, _, _ in LIMIT_FIELDS}:
            return f"program.{name}", message
        return "program", message

    def _build(self, state: PanelState) -> Program | InvalidInputError | None:
        draft, robot = state.document.program, state.robot
        cached = self._built
        if cached is None or cached[0] is not draft or cached[1] is not robot:
            try:
                result: Program | InvalidInputError | None = build(draft, robot)
            except InvalidInputError as error:
                result = error
            self._built = cached = (draft, robot, result)
        return cached[2]

    # -- drawing ------------------------------------------------------------------------

    def render(self, state: PanelState, feedback: Feedback, rev: str, visible: bool) -> None:
        """Show the table (only while the tab shows)."""
        self._state = state
        if not visible:
            return
        robot, units, draft = state.robot, state.units, state.document.program
        built = self._build(state)
        refusal = None
        top_note = feedback.message("program")
        refused = self.refusal(state)
        if refused is not None:
            match = _MOVE_FIELD.search(refused[0])
            if match is not None:
                refusal = (int(match.group(1)), refused[1])
            elif refused[0] == "program":
                top_note = top_note or refused[1]
        run = state.program_run
        current = (
            run is not None and not isinstance(built, InvalidInputError) and built == run.program
        )
        moves = draft.moves
        violations = (
            violations_by_move(run.report, len(moves), state.units) if current and run else []
        )
        speed = draft.settings.get("cartesian_speed") or default_limits(robot).cartesian_speed
        can_undo, can_redo = self._history()
        rows = [
            row("program.intro", [text("Program", tone="title"), text(INTRO, tone="note")]),
            row(
                "program",
                [
                    button(
                        "program.undo",
                        "↶",
                        title="undo the last change",
                        disabled=not can_undo,
                        css_class="robotconf-program-undo",
                    ),
                    button(
                        "program.redo",
                        "↷",
                        title="redo the change just undone",
                        disabled=not can_redo,
                        css_class="robotconf-program-redo",
                    ),
                    button(
                        "program.add",
                        "+ add move",
                        title="add a PTP move to the robot's current coordinates",
                        css_class="robotconf-program-add",
                    ),
                    button(
                        "program.clear",
                        "✕ clear",
                        title="delete every move (↶ brings them back)",
                        disabled=not moves,
                    ),
                ],
                note=message(top_note),
            ),
            *move_rows(moves, robot, units, float(speed), feedback, rev, violations, refusal),
            row(
                "program.limits",
                [text("Limits", tone="title")],
                limit_controls(robot, draft.settings, units, feedback, rev, refused),
            ),
            self._run_row(state, feedback, rev, run, current),
        ]
        self.form.show(rows)

    def _run_row(
        self, state: PanelState, feedback: Feedback, rev: str, run: Any, current: bool
    ) -> dict[str, Any]:
        dt = state.program_dt
        error = feedback.message("program.dt")
        if run is None:
            status, tone = "Run checks and simulates the program.", "note"
        else:
            status, tone = run_summary(run, self.app)
            if not current:
                status += " — the program or the robot changed since this run: press Run"
        return row(
            "program.run",
            [
                number(
                    "program.dt",
                    dt,
                    0.0,
                    0.0,
                    0.001,
                    label="dt [s]",
                    slider=False,
                    rev=rev,
                    width="80px",
                    text=feedback.typed("program.dt") if error else None,
                    note=message(error),
                ),
                button("program.run", "▶ Run", style="primary", css_class="robotconf-program-run"),
                button("program.motion", "tables and plots: Motion tab", disabled=run is None),
            ],
            [text(status, tone=tone, css_class="robotconf-program-status")],
            note=message(feedback.message("program.run")),
        )

    def scene_extras(self, state: PanelState) -> Extras:
        """Where each move ends (P1, P2 …) and the CIRC via points, for the 3D view."""
        draft, robot = state.document.program, state.robot
        key = ("program", draft, robot)
        points, labels, via, via_labels = act.taught_markers(draft, robot)
        if not len(points) and not len(via):
            return Extras(key, (("clear_taught_points", (), {}),))
        call = ("show_taught_points", (points, labels), {"via": via, "via_labels": via_labels})
        return Extras(key, (call,))

    # -- input --------------------------------------------------------------------------

    def _event(self, event: FormEvent) -> None:
        state = self._state
        if state is None:
            return
        key = event.key
        if key == "program.undo":
            self._undo()
            return
        if key == "program.redo":
            self._redo()
            return
        typed = event.text if event.event == "type" else None
        try:
            action, target = self._action(state, event)
        except InvalidInputError as error:
            self._dispatch(error, key, typed)
            return
        self._dispatch(action, target, typed)

    def _action(self, state: PanelState, event: FormEvent) -> tuple[Any, str]:
        key = event.key
        if key == "program.add":
            return act.AddMove(), "program"
        if key == "program.clear":
            return act.ClearProgram(), "program"
        if key == "program.run":
            return act.RunProgram(), "program.run"
        if key == "program.motion":
            return act.SelectTab("motion"), "program.run"
        if key == "program.dt":
            return act.SetProgramDt(_value(event, "dt")), key
        if key.startswith("program.") and key[8:] in {f[0] for f in LIMIT_FIELDS}:
            settings = state.document.program.settings
            setting, value = limit_value(
                state.robot, settings, key[8:], _value(event, key[8:]), state.units
            )
            return act.SetProgramSetting(setting, value), key
        match = _FIELD.match(key)
        if match is None:
            return None, key
        index, name, component = int(match.group(1)), match.group(2), match.group(3)
        row_key = f"program.moves[{index}]"
        if name in ("teach", "up", "down", "delete"):
            return act.MoveRow(index, name), row_key
        if name == "via" and not component and event.event == "click":
            return act.MoveRow(index, "teach via"), row_key
        if name in ("kind", "profile"):
            return act.EditMove(index, name, str(event.value)), row_key
        k = int(component) if component else None
        unit = state.robot.modules[k or 0].unit if name == "q" else BOX_UNITS.get(name, "")
        value = state.units.to_core(_value(event, name), unit)
        return act.EditMove(index, name, value, k), key


def _value(event: FormEvent, field: str) -> float:
    from ..form import parse_number

    if event.event == "drag":
        return float(event.value)
    return parse_number(event.text or "", field)
