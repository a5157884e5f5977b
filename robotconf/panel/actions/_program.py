"""The Program tab: moves added, edited, taught, reordered, deleted; limits; Run.

Every edit gives a new :class:`~robotconf.panel.state.ProgramDraft`. A value a move itself
refuses (a speed that is no positive number) is refused at once, beside its box. A draft
the core refuses as a whole for this robot (a LIN that goes nowhere yet, a CIRC whose
points lie on one line, a target out of reach) is kept, like code being typed: the tab
names the move and why, ``panel.program`` is ``None`` and the bound file keeps its last
valid setup until the draft is fixed. (Turning a PTP into a LIN that ends where it
starts, to edit its end next, must be possible.)
"""

from __future__ import annotations

import warnings
from collections.abc import Hashable
from dataclasses import dataclass, replace
from typing import Any

from ..._errors import InvalidInputError
from ..._validation import check_finite_number
from ...programs import PTP
from ..state import PanelState, Playback, ProgramDraft, ProgramRun
from ..state._program_draft import build
from ._base import Action
from ._program_edits import edit_move, row_action

__all__ = [
    "AddMove",
    "ClearProgram",
    "EditMove",
    "MoveRow",
    "SetProgramSetting",
    "SetProgramDt",
    "RunProgram",
    "ROW_ACTIONS",
    "run_program",
]

#: What a row's buttons do.
ROW_ACTIONS = ("teach", "teach via", "up", "down", "delete")


def _checked(state: PanelState, draft: ProgramDraft) -> PanelState:
    """``state`` with ``draft`` as its program (the tab shows what the core says of it)."""
    return state.with_document(program=draft)


def _move_index(state: PanelState, index: int) -> int:
    count = len(state.document.program.moves)
    if not isinstance(index, int) or not 0 <= index < count:
        raise InvalidInputError("move", index, f"a move number from 0 to {count - 1}")
    return index


def run_program(program: Any, dt: Any) -> tuple[Any, Any]:
    """``program.check(dt)`` and ``program.simulate(dt)``: the report and the motion.

    The simulation's warning about violations is not raised: the tab lists every
    violation under its move instead.

    >>> import robotconf as rc
    >>> from robotconf.programs import Program
    >>> report, motion = run_program(Program(rc.preset("paper"), [PTP(q=[0, 0, 0.5])]), 0.1)
    >>> report.ok, motion.t.size
    (True, 11)
    """
    report = program.check(dt)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        motion = program.simulate(dt)
    return report, motion


@dataclass(frozen=True)
class AddMove(Action):
    """Append a PTP to the robot's current coordinates.

    >>> import robotconf as rc
    >>> state = AddMove().apply(PanelState.start(rc.preset("paper")))
    >>> state.document.program.moves
    (PTP(q=(0.0, 0.0, 0.0), pose=None, position=None, profile='trapezoidal'),)
    """

    def apply(self, state: PanelState) -> PanelState:
        program = state.document.program
        move = PTP(q=tuple(float(v) for v in state.robot.q))
        return _checked(state, program.with_moves([*program.moves, move]))


@dataclass(frozen=True)
class ClearProgram(Action):
    """Delete every move (undo brings them back)."""

    def apply(self, state: PanelState) -> PanelState:
        return state.with_document(program=state.document.program.with_moves([]))


@dataclass(frozen=True)
class EditMove(Action):
    """Set field ``name`` of move ``index`` (or one ``component`` of it) to ``value`` in
    core units; ``name="kind"`` changes the move's type, keeping where it ends."""

    index: int
    name: str
    value: Any
    component: int | None = None

    def apply(self, state: PanelState) -> PanelState:
        i = _move_index(state, self.index)
        try:
            draft = edit_move(
                state.document.program, state.robot, i, self.name, self.value, self.component
            )
        except InvalidInputError as error:  # a move refuses an out-of-bounds number itself
            raise error.within(f"program.moves[{i}]") from None
        return _checked(state, draft)

    @property
    def gesture(self) -> Hashable | None:
        if self.name == "kind":
            return None
        return ("move", self.index, self.name, self.component)


@dataclass(frozen=True)
class MoveRow(Action):
    """A row's button: ``"teach"`` (where the robot is now), ``"teach via"`` (a CIRC's
    via point), ``"up"``, ``"down"`` or ``"delete"``."""

    index: int
    action: str

    def apply(self, state: PanelState) -> PanelState:
        if self.action not in ROW_ACTIONS:
            raise InvalidInputError("action", self.action, ", ".join(ROW_ACTIONS))
        i = _move_index(state, self.index)
        draft = row_action(state.document.program, state.robot, i, self.action)
        return _checked(state, draft)


@dataclass(frozen=True)
class SetProgramSetting(Action):
    """Set a limit of the program (``joint_speed``, ``cartesian_speed`` …; ``None``: the
    core's default for this robot)."""

    name: str
    value: Any

    def apply(self, state: PanelState) -> PanelState:
        return _checked(state, state.document.program.with_setting(self.name, self.value))

    @property
    def gesture(self) -> Hashable:
        return ("program setting", self.name)


@dataclass(frozen=True)
class SetProgramDt(Action):
    """The sampling step of the Program tab's Run (s, > 0)."""

    dt: float

    def apply(self, state: PanelState) -> PanelState:
        dt = check_finite_number(self.dt, "dt")
        if dt <= 0:
            raise InvalidInputError("dt", dt, "a time step > 0 (s)", problem="must be positive,")
        return state.replace(program_dt=dt)


@dataclass(frozen=True)
class RunProgram(Action):
    """Check and simulate the program (``program.check(dt)``, ``program.simulate(dt)``):
    the run is the panel's last simulation and plays in the 3D view with the trace."""

    def apply(self, state: PanelState) -> PanelState:
        try:
            program = build(state.document.program, state.robot)
        except InvalidInputError as error:
            raise error.within("program") from None
        if program is None:
            from ...programs import Program

            Program(state.robot, [])  # the core says what an empty program lacks
        report, motion = run_program(program, state.program_dt)
        return state.replace(
            program_run=ProgramRun(program, motion, report),
            motion=motion,
            run_settings=None,
            playback=Playback(source="program", playing=True, speed=state.playback.speed),
            view=replace(state.view, trace=True),
        )
