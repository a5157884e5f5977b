"""The Programs tab: each robot's moves, its speeds, and Run with what it found.

Under each move the last Run's word on it: the core's refusal (a target out of reach, a
LIN that goes nowhere), the program's violations and every contact the move causes,
with its time. The last row has the step, **Run**, the cycle time and each robot's
count; an edit after a Run says the run is stale and takes its marks away.
Keys: the moves' (``robotconf/cell_designer/views/_moves.py``), ``program[j].add_kind``,
``program[j].add``, ``program[j].joint_speed``, ``program[j].cartesian_speed``,
``run.dt``, ``run``.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ...panel.form import Form, FormEvent, button, message, row, select, text
from ...programs import Program, Wait
from .. import actions as act
from ..state import MOVE_KINDS, DesignerState, RobotItem
from ._boxes import ANGLE, LENGTH, box, core_value
from ._messages import Messages
from ._moves import MOVE_CLASS, move_controls
from ._results import move_notes, run_lines
from ._rows import parse_key

__all__ = ["ProgramsView"]


class ProgramsView:
    """Every robot's program, Run, and the run's results."""

    def __init__(self, dispatch: Callable[..., None]) -> None:
        self._dispatch = dispatch
        self._state: DesignerState | None = None
        self._moves: dict[int, tuple[str, int]] = {}
        self._robots: dict[int, str] = {}
        self.add_kind: dict[str, str] = {}
        self.form = Form(self._event, css_class="robotconf-cell-programs")

    def render(self, state: DesignerState, messages: Messages, rev: str, step: float) -> None:
        """Draw the programs of every robot, then Run and its results."""
        self._state = state
        self._moves, self._robots = {}, {}
        rows: list[dict[str, Any]] = []
        robots = [i for i in state.cell.items if isinstance(i, RobotItem)]
        if not robots:
            rows.append(
                row(
                    "none",
                    [text("Add a robot first (Cell tab): each robot has a program.", tone="note")],
                )
            )
        for j, item in enumerate(robots):
            self._robots[j] = item.name
            rows += self._robot_rows(j, item, state, messages, rev, step)
        notes = [messages.text("run"), messages.text("run.dt")]
        rows.append(
            row(
                "run",
                [
                    text("dt [s]", tone="note"),
                    box(
                        "run.dt",
                        state.run_dt,
                        "",
                        state.units,
                        messages,
                        rev,
                        step=0.01,
                        width="58px",
                    ),
                    button(
                        "run",
                        "Run",
                        style="primary",
                        rev=rev,
                        css_class="robotconf-cell-run",
                        disabled=not robots,
                    ),
                ],
                *run_lines(state),
                note=message("; ".join(n for n in notes if n)),
            )
        )
        self.form.show(rows)

    def _robot_rows(
        self,
        j: int,
        item: RobotItem,
        state: DesignerState,
        messages: Messages,
        rev: str,
        step: float,
    ) -> list[dict[str, Any]]:
        units = state.units
        program = state.document.program(item.name)
        limits = Program(item.robot, [Wait(0.0)], **program.options).limits
        prefix = f"program[{j}]"
        rows = [
            row(
                prefix,
                [
                    text(f"{item.name}", tone="title"),
                    text(f"joint speed [{units.angle}/s]", tone="note"),
                    box(
                        f"{prefix}.joint_speed",
                        float(limits.joint_speed.min()),
                        ANGLE,
                        units,
                        messages,
                        rev,
                        step=0.1,
                        width="90px",
                        title="PTP joint speed (the core's default until typed)",
                    ),
                    text(f"path speed [{units.length}/s]", tone="note"),
                    box(
                        f"{prefix}.cartesian_speed",
                        float(limits.cartesian_speed),
                        LENGTH,
                        units,
                        messages,
                        rev,
                        step=step,
                        width="58px",
                        title="LIN and CIRC speed (the core's default until typed)",
                    ),
                ],
                note=message(
                    "; ".join(
                        t
                        for k in ("joint_speed", "cartesian_speed", "add")
                        if (t := messages.text(f"{prefix}.{k}"))
                    )
                ),
                css_class="robotconf-cell-program",
            )
        ]
        count = len(program.moves)
        for i, move in enumerate(program.moves):
            k = len(self._moves)
            self._moves[k] = (item.name, i)
            key = f"move[{k}]"
            controls = move_controls(
                key, i, count, move, item, state, messages, rev, float(limits.cartesian_speed), step
            )
            rows.append(
                row(
                    key,
                    controls,
                    *move_notes(state, item.name, i, key, messages),
                    box=True,
                    css_class=MOVE_CLASS,
                )
            )
        kind = self.add_kind.get(item.name, "PTP")
        rows.append(
            row(
                f"{prefix}.adding",
                [
                    select(
                        f"{prefix}.add_kind",
                        kind,
                        [(k, k) for k in MOVE_KINDS],
                        rev=rev,
                        width="70px",
                    ),
                    button(
                        f"{prefix}.add",
                        "+ move",
                        rev=rev,
                        title="PTP to the robot's q now; LIN and CIRC to the first frame",
                    ),
                ],
            )
        )
        return rows

    def _event(self, event: FormEvent) -> None:
        state = self._state
        if state is None:
            return
        key = event.key
        try:
            action = self._action(state, key, event)
        except Exception as error:  # a number that is no number: said beside the box
            self._dispatch(error, key, event.text)
            return
        self._dispatch(action, key, event.text)

    def _action(self, state: DesignerState, key: str, event: FormEvent) -> Any:
        if key == "run":
            return act.Run()
        if key == "run.dt":
            return act.SetRunDt(core_value(event, "", state.units, "dt"))
        parsed = parse_key(key)
        if parsed is None:
            return None
        table, index, name, part = parsed
        if table == "program" and index in self._robots:
            robot = self._robots[index]
            if name == "add_kind":
                self.add_kind[robot] = str(event.value)
                return None
            if name == "add":
                return act.AddMove(robot, self.add_kind.get(robot, "PTP"))
            unit = ANGLE if name == "joint_speed" else LENGTH
            return act.SetProgramOption(robot, name, core_value(event, unit, state.units, name))
        if table != "move" or index not in self._moves:
            return None
        robot, i = self._moves[index]
        if name == "kind":
            return act.SetMoveKind(robot, i, str(event.value))
        if name == "target":
            return act.SetMoveTarget(robot, i, str(event.value))
        if name == "profile":
            return act.SetMoveProfile(robot, i, str(event.value))
        if name == "teach":
            return act.TeachMove(robot, i)
        if name in ("up", "down"):
            return act.MoveRow(robot, i, -1 if name == "up" else 1)
        if name == "delete":
            return act.RemoveMove(robot, i)
        unit = LENGTH if name in ("point", "via", "speed") else ""
        if name == "q" and part is not None:
            item = state.cell.item(robot)
            assert isinstance(item, RobotItem)
            unit = item.robot.modules[part].unit
        value = core_value(event, unit, state.units, name)
        return act.SetMoveNumber(robot, i, name, value, part)
