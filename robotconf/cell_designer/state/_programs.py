"""A robot's program as the designer edits it: moves as typed, and the program's options.

The moves are the core's own (:class:`~robotconf.programs.PTP`, ``LIN``, ``CIRC``,
``Wait``), and a target may be a cell frame by name (``LIN(frame="table/pick")``), which
only the cell resolves. Nothing is planned while the student types: ``Run`` hands the
moves to :meth:`Cell.program <robotconf.Cell.program>` and the core's refusal names the
move and the field. The cell file keeps the moves as they are here.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import Any

from ...programs import CIRC, LIN, PTP, Move

__all__ = ["RobotProgram", "MOVE_KINDS", "OPTION_NAMES", "target_of", "renamed_frames"]

#: The move types a row can take, in the menu's order.
MOVE_KINDS = ("PTP", "LIN", "CIRC", "Wait")
#: The options the designer shows (a file's other options are kept as they are).
OPTION_NAMES = ("joint_speed", "cartesian_speed")


@dataclass(frozen=True)
class RobotProgram:
    """The moves of one robot and the program's options (``None`` ones left out).

    Examples
    --------
    >>> program = RobotProgram((PTP(q=(0.0, 0.3, -0.5)),)).with_option("joint_speed", 2.0)
    >>> program.options, len(program)
    ({'joint_speed': 2.0}, 1)
    """

    moves: tuple[Move, ...] = ()
    settings: tuple[tuple[str, Any], ...] = ()

    def __len__(self) -> int:
        return len(self.moves)

    @property
    def options(self) -> dict[str, Any]:
        """The options as :meth:`Cell.program <robotconf.Cell.program>` takes them."""
        return dict(self.settings)

    @classmethod
    def of(cls, moves: Any, options: Mapping[str, Any] | None = None) -> RobotProgram:
        """A program from moves and options (a file's ``(moves, options)``)."""
        kept = tuple((k, v) for k, v in (options or {}).items() if v is not None)
        return cls(tuple(moves), kept)

    def with_moves(self, moves: Any) -> RobotProgram:
        """The same options with other moves."""
        return replace(self, moves=tuple(moves))

    def with_option(self, name: str, value: Any) -> RobotProgram:
        """One option set (``None``: the core's default)."""
        options = {**self.options, name: value}
        return RobotProgram.of(self.moves, options)


def target_of(move: Move) -> str:
    """What a move's target is: ``"q"``, ``"point"``, ``"pose"``, ``"frame"`` or ``""``
    (a Wait).

    >>> from robotconf.programs import Wait
    >>> target_of(LIN(frame="table/pick")), target_of(PTP(q=(0.0,))), target_of(Wait(1.0))
    ('frame', 'q', '')
    """
    if getattr(move, "frame", None) is not None:
        return "frame"
    if isinstance(move, PTP):
        if move.q is not None:
            return "q"
        return "pose" if move.pose is not None else "point"
    if isinstance(move, LIN):
        return "pose" if move.pose is not None else "point"
    if isinstance(move, CIRC):
        return "pose" if move.end is not None and len(move.end) == 4 else "point"
    return ""


def renamed_frames(program: RobotProgram, renames: Mapping[str, str]) -> RobotProgram:
    """The program with every move's frame renamed as the cell renamed it.

    >>> from robotconf.programs import Wait
    >>> program = RobotProgram((LIN(frame="table/pick"), Wait(1.0)))
    >>> renamed_frames(program, {"table/pick": "bench/pick"}).moves[0].frame
    'bench/pick'
    """
    moves = []
    for move in program.moves:
        frame = getattr(move, "frame", None)
        if isinstance(move, (PTP, LIN, CIRC)) and isinstance(frame, str) and frame in renames:
            move = replace(move, frame=renames[frame])
        moves.append(move)
    return program.with_moves(moves)
