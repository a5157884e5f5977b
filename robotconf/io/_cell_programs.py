"""A robot's program inside a cell file: the ``"program"`` of a robot entry.

It is the program schema's object (:mod:`._program_schema`: the options, ``null`` for a
default, and the moves as :meth:`Move.to_dict <robotconf.programs.Move.to_dict>` writes
them), except that a move may name a cell entry by its ``frame``
(``{"type": "LIN", "frame": "table/pick", …}``), which only the cell resolves. So reading
keeps the moves as written and checks each against the robot with the frame standing
for a pose; whether a target is reachable is a question for :meth:`Cell.run
<robotconf.Cell.run>`, not for the file.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._json_fields import check_json_object
from .._validation import one_line
from ..kinematics import Robot
from ..programs import MAX_MOVES, Move, Program, Wait
from ._program_schema import _PROGRAM_KEYS, _move, _plain, _value

__all__ = ["CellProgram", "program_parts", "program_out", "program_in"]

#: A robot's program in a cell: its moves (a move's ``frame`` names a cell entry) and the
#: options :meth:`Cell.program <robotconf.Cell.program>` takes (``None`` ones left out).
CellProgram = tuple[tuple[Move, ...], dict[str, Any]]


def program_parts(value: Any, path: str) -> CellProgram:
    """``(moves, options)`` of a :class:`~robotconf.programs.Program`, a list of moves,
    or such a pair.

    >>> from robotconf.programs import LIN
    >>> moves, options = program_parts([LIN(frame="pick")], "programs['arm']")
    >>> moves[0].frame, options
    ('pick', {})
    """
    if isinstance(value, Program):
        return value.moves, {k: v for k, v in value.settings.items() if v is not None}
    if isinstance(value, tuple) and len(value) == 2 and isinstance(value[1], Mapping):
        moves, options = value
    else:
        moves, options = value, {}
    if not isinstance(moves, (list, tuple)) or not all(isinstance(m, Move) for m in moves):
        raise InvalidInputError(
            path, one_line(value), "a Program, a list of moves, or (moves, options)"
        )
    return tuple(moves), {k: v for k, v in options.items() if v is not None}


def program_out(value: Any, path: str) -> dict[str, Any] | None:
    """The ``"program"`` object of a robot entry, or ``None`` for no program (no moves).

    >>> from robotconf.programs import Wait
    >>> program_out(([Wait(1.0)], {"joint_speed": 2.0}), "p")["joint_speed"]
    2.0
    """
    if value is None:
        return None
    moves, options = program_parts(value, path)
    if not moves:
        return None
    data = {key: _plain(options.get(key)) for key in _PROGRAM_KEYS if key != "moves"}
    data["moves"] = [move.to_dict() for move in moves]
    return data


def program_in(value: Any, path: str, robot: Robot, names: set[str]) -> CellProgram:
    """A robot entry's ``"program"`` read and checked.

    Parameters
    ----------
    value : object
        The parsed JSON.
    path : str
        Its JSON path, named by every error (``robots[0].program.moves[1].frame``).
    robot : Robot
        The entry's robot: every move is checked against it (a frame stands for a pose).
    names : set of str
        The full names of the file's entries: a move's ``frame`` must be one of them.

    Examples
    --------
    >>> import robotconf as rc
    >>> data = {"moves": [{"type": "LIN", "frame": "pick", "speed": 5}]}
    >>> moves, options = program_in(data, "program", rc.preset("paper"), {"pick"})
    >>> moves[0].frame, options
    ('pick', {})
    >>> program_in(data, "program", rc.preset("paper"), {"table"})
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: program.moves[0].frame: no such frame: 'pick'; ...
    """
    check_json_object(value, path, _PROGRAM_KEYS)
    moves = value["moves"]
    if not isinstance(moves, list) or not 1 <= len(moves) <= MAX_MOVES:
        shown = one_line(moves) if not isinstance(moves, list) else f"<{len(moves)} moves>"
        raise InvalidInputError(f"{path}.moves", shown, f"a list of 1 to {MAX_MOVES} moves")
    built = tuple(_move(move, f"{path}.moves[{i}]") for i, move in enumerate(moves))
    for i, move in enumerate(built):
        frame = getattr(move, "frame", None)
        if frame is not None and frame not in names:
            raise InvalidInputError(
                f"{path}.moves[{i}].frame", frame, "a frame of the cell", "no such frame:"
            )
        try:
            move.resolved(lambda _name: np.eye(4)).checked(robot.n, robot.coordinate_names)
        except InvalidInputError as error:
            raise error.within(f"{path}.moves[{i}]") from None
    keys = [key for key in _PROGRAM_KEYS if key != "moves"]
    options = {key: _value(value.get(key), f"{path}.{key}") for key in keys}
    options = {key: option for key, option in options.items() if option is not None}
    try:
        Program(robot, [Wait(0.0)], **options)  # the options, checked as a program's
    except InvalidInputError as error:
        raise error.within(path) from None
    return built, options
