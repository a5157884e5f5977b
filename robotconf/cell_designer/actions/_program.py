"""Editing each robot's program, and Run: every program planned and checked in the cell.

Every edit is checked move by move as the cell file will be read (a frame stands for a
pose), so the bound file always reads back; whether a target is reachable, a LIN goes
somewhere or a CIRC's points lie on a line is the core's answer at **Run**
(:meth:`Cell.program <robotconf.Cell.program>`, :meth:`Cell.run <robotconf.Cell.run>`),
whose refusal names ``programs['arm'].moves[1].…``.
"""

from __future__ import annotations

from collections.abc import Hashable
from dataclasses import dataclass, replace
from typing import Any

from ..._errors import InvalidInputError
from ..._validation import check_finite_number
from ...programs import CIRC, LIN, PTP, Move, Program, Wait
from ..state import MOVE_KINDS, OPTION_NAMES, DesignerState, RunOutcome
from ._base import Action
from ._moves import checked, converted, new_move, retargeted, robot_item, tcp_point

__all__ = [
    "AddMove",
    "SetMoveKind",
    "SetMoveTarget",
    "SetMoveNumber",
    "SetMoveProfile",
    "TeachMove",
    "MoveRow",
    "RemoveMove",
    "SetProgramOption",
    "SetRunDt",
    "Run",
    "MOVE_FIELDS",
]

#: Number fields of a move row: a PTP's ``q``, a LIN's or CIRC's end ``point`` (or a
#: PTP's), a CIRC's ``via`` (each with a component), and ``speed`` and ``seconds``.
MOVE_FIELDS = ("q", "point", "via", "speed", "seconds")


def _moves(state: DesignerState, robot: str) -> list[Move]:
    robot_item(state, robot)
    return list(state.document.program(robot).moves)


def _with_moves(state: DesignerState, robot: str, moves: list[Move]) -> DesignerState:
    program = state.document.program(robot).with_moves(moves)
    return state.with_document(state.document.with_program(robot, program))


def _row(moves: list[Move], index: int) -> int:
    if not isinstance(index, int) or not 0 <= index < len(moves):
        raise InvalidInputError("move", index, f"a move from 0 to {len(moves) - 1}")
    return index


def _set(state: DesignerState, robot: str, index: int, move: Move) -> DesignerState:
    moves = _moves(state, robot)
    moves[_row(moves, index)] = checked(state, robot, move)
    return _with_moves(state, robot, moves)


@dataclass(frozen=True)
class AddMove(Action):
    """Append a PTP (to the robot's q), a LIN or CIRC (to the first frame) or a Wait."""

    robot: str
    kind: str = "PTP"

    def apply(self, state: DesignerState) -> DesignerState:
        moves = _moves(state, self.robot)
        moves.append(checked(state, self.robot, new_move(state, self.robot, self.kind)))
        return _with_moves(state, self.robot, moves)


@dataclass(frozen=True)
class SetMoveKind(Action):
    """Change a move's type, keeping where it ends (and the frame it goes to)."""

    robot: str
    index: int
    kind: str

    def apply(self, state: DesignerState) -> DesignerState:
        if self.kind not in MOVE_KINDS:
            raise InvalidInputError("kind", self.kind, " or ".join(MOVE_KINDS))
        moves = _moves(state, self.robot)
        move = moves[_row(moves, self.index)]
        return _set(state, self.robot, self.index, converted(state, self.robot, move, self.kind))


@dataclass(frozen=True)
class SetMoveTarget(Action):
    """Send a move to a cell frame (its name), to a point, or (a PTP) to coordinates."""

    robot: str
    index: int
    target: str

    def apply(self, state: DesignerState) -> DesignerState:
        moves = _moves(state, self.robot)
        move = moves[_row(moves, self.index)]
        changed = retargeted(state, self.robot, move, self.target)
        return _set(state, self.robot, self.index, changed)


def _edited(move: Move, field: str, value: float, component: int | None) -> Move:
    if field in ("speed", "seconds"):
        if not hasattr(move, field):
            raise InvalidInputError("field", field, f"a field of a {move.kind}")
        return replace(move, **{field: value})  # type: ignore[type-var]
    name = field
    if field == "point":
        name = "end" if isinstance(move, CIRC) else "position"
    current = getattr(move, name, None)
    if current is None or component not in range(len(current)):
        raise InvalidInputError("field", f"{field}[{component}]", f"a number of this {move.kind}")
    values = list(current)
    values[component] = value  # type: ignore[index]
    return replace(move, **{name: tuple(values)})  # type: ignore[type-var]


@dataclass(frozen=True)
class SetMoveNumber(Action):
    """One number of a move (:data:`MOVE_FIELDS`): radians or length units, a path speed
    (length/s), seconds."""

    robot: str
    index: int
    field: str
    value: float
    component: int | None = None

    def apply(self, state: DesignerState) -> DesignerState:
        moves = _moves(state, self.robot)
        move = moves[_row(moves, self.index)]
        value = check_finite_number(self.value, self.field)
        changed = _edited(move, self.field, value, self.component)
        return _set(state, self.robot, self.index, changed)

    @property
    def gesture(self) -> Hashable | None:
        return ("move", self.robot, self.index, self.field, self.component)


@dataclass(frozen=True)
class SetMoveProfile(Action):
    """A PTP's time law: ``"trapezoidal"`` or ``"quintic"``."""

    robot: str
    index: int
    profile: str

    def apply(self, state: DesignerState) -> DesignerState:
        moves = _moves(state, self.robot)
        move = moves[_row(moves, self.index)]
        if not isinstance(move, PTP):
            raise InvalidInputError("profile", self.profile, "a PTP's profile")
        return _set(state, self.robot, self.index, replace(move, profile=self.profile))


@dataclass(frozen=True)
class TeachMove(Action):
    """A PTP's target becomes the robot's q; a LIN's or CIRC's point (``via``: the CIRC's
    via point) where the TCP is now."""

    robot: str
    index: int
    via: bool = False

    def apply(self, state: DesignerState) -> DesignerState:
        moves = _moves(state, self.robot)
        move = moves[_row(moves, self.index)]
        point = tcp_point(state, self.robot)
        if isinstance(move, PTP):
            changed: Move = retargeted(state, self.robot, move, "q")
        elif isinstance(move, CIRC) and self.via:
            changed = replace(move, via=point)
        elif isinstance(move, LIN):
            changed = replace(move, position=point, pose=None, frame=None)
        elif isinstance(move, CIRC):
            changed = replace(move, end=point, frame=None)
        else:
            raise InvalidInputError("move", self.index, "a PTP, LIN or CIRC (a Wait has no target)")
        return _set(state, self.robot, self.index, changed)


@dataclass(frozen=True)
class MoveRow(Action):
    """Move a row up (``-1``) or down (``+1``)."""

    robot: str
    index: int
    delta: int

    def apply(self, state: DesignerState) -> DesignerState:
        moves = _moves(state, self.robot)
        i = _row(moves, self.index)
        j = i + (1 if self.delta > 0 else -1)
        if not 0 <= j < len(moves):
            return state
        moves[i], moves[j] = moves[j], moves[i]
        return _with_moves(state, self.robot, moves)


@dataclass(frozen=True)
class RemoveMove(Action):
    """Delete a row (undo brings it back)."""

    robot: str
    index: int

    def apply(self, state: DesignerState) -> DesignerState:
        moves = _moves(state, self.robot)
        del moves[_row(moves, self.index)]
        return _with_moves(state, self.robot, moves)


@dataclass(frozen=True)
class SetProgramOption(Action):
    """A program option (:data:`~..state.OPTION_NAMES`: ``joint_speed`` in rad/s,
    ``cartesian_speed`` in length/s); ``None`` for the core's default."""

    robot: str
    name: str
    value: float | None

    def apply(self, state: DesignerState) -> DesignerState:
        if self.name not in OPTION_NAMES:
            raise InvalidInputError("option", self.name, " or ".join(OPTION_NAMES))
        item = robot_item(state, self.robot)
        value = None if self.value is None else check_finite_number(self.value, self.name)
        program = state.document.program(self.robot).with_option(self.name, value)
        if not program.moves:
            raise InvalidInputError(self.name, value, "a program with moves: add a move first")
        Program(item.robot, [Wait(0.0)], **program.options)  # the core's check of the options
        return state.with_document(state.document.with_program(self.robot, program))

    @property
    def gesture(self) -> Hashable | None:
        return ("option", self.robot, self.name)


@dataclass(frozen=True)
class SetRunDt(Action):
    """Run's sampling step (s), > 0."""

    dt: float

    def apply(self, state: DesignerState) -> DesignerState:
        dt = check_finite_number(self.dt, "dt")
        if not dt > 0.0:
            raise InvalidInputError("dt", dt, "a time step > 0 (s)", "must be positive,")
        return state.replace(run_dt=dt)


@dataclass(frozen=True)
class Run(Action):
    """Plan every robot's program in the cell and run them side by side (``cell.run``):
    the cycle time, each program's violations and every contact, move by move."""

    def apply(self, state: DesignerState) -> DesignerState:
        document = state.document
        if not document.programs:
            raise InvalidInputError("programs", None, "a robot with moves: add a move first")
        cell = document.cell.cell
        built: dict[str, Any] = {}
        for robot, program in document.programs:
            try:
                built[robot] = cell.program(robot, list(program.moves), **program.options)
            except InvalidInputError as error:
                raise error.within(f"programs[{robot!r}]") from None
        run = cell.run(built, dt=state.run_dt)
        return state.replace(run=RunOutcome(run, document, state.run_dt))
