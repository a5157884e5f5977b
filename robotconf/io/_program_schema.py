"""A program as JSON data (the ``"program"`` section of a robotconf file) and back.

Every field is written, ``null`` for a default, and every float as Python writes it
(its shortest exact form), so ``program_from_dict(program_to_dict(p), robot) == p`` bit
for bit. Reading checks the JSON types here (numbers, lists, text, ``null``; booleans,
NaN and infinities refused) and leaves the rest to :class:`Program`, naming
``program.moves[i].field``.
"""

from __future__ import annotations

from dataclasses import fields
from typing import TYPE_CHECKING, Any

from .._errors import InvalidInputError
from .._json_fields import check_json_number, check_json_object
from .._validation import one_line
from ..programs import LIMIT_NAMES, MAX_MOVES, MOVE_TYPES, Program

if TYPE_CHECKING:
    from ..kinematics import Robot

__all__ = ["program_to_dict", "program_from_dict"]

_PROGRAM_KEYS = {"moves": True, "start": False, **{name: False for name in LIMIT_NAMES}}
_DEPTH = 3


def _plain(value: Any) -> Any:
    if isinstance(value, tuple):
        return [_plain(v) for v in value]
    return value


def program_to_dict(program: Program) -> dict[str, Any]:
    """``{"start": …, "joint_speed": …, …, "moves": [...]}`` (see the module notes).

    >>> import robotconf as rc
    >>> from robotconf.programs import Wait
    >>> program_to_dict(Program(rc.preset("paper"), [Wait(1)]))["moves"]
    [{'type': 'Wait', 'seconds': 1.0}]
    """
    data = {key: _plain(value) for key, value in program.settings.items()}
    data["moves"] = [move.to_dict() for move in program.moves]
    return data


def _value(value: Any, path: str, depth: int = 0) -> Any:
    """A JSON field: ``null``, text, a number, or lists of numbers (at most 3 deep)."""
    if value is None or isinstance(value, str):
        return value
    if isinstance(value, list):
        if depth >= _DEPTH:
            raise InvalidInputError(path, one_line(value), "numbers, or lists of them", "too deep:")
        return [_value(v, f"{path}[{i}]", depth + 1) for i, v in enumerate(value)]
    return check_json_number(value, path)


def _move(value: Any, path: str) -> Any:
    kind = value.get("type") if isinstance(value, dict) else None
    if kind not in MOVE_TYPES:
        raise InvalidInputError(
            f"{path}.type" if isinstance(value, dict) else path,
            one_line(kind if isinstance(value, dict) else value),
            'an object with "type": "PTP", "LIN", "CIRC" or "Wait"',
            problem="unknown move type",
        )
    cls = MOVE_TYPES[kind]
    names = [f.name for f in fields(cls)]
    check_json_object(value, path, {"type": True, **{name: False for name in names}})
    given = {name: _value(value[name], f"{path}.{name}") for name in names if name in value}
    try:
        return cls(**given)
    except InvalidInputError as error:
        raise error.within(path) from None


def program_from_dict(value: Any, robot: Robot, path: str = "program") -> Program:
    """The ``"program"`` object of a file as a :class:`Program` for ``robot``.

    >>> import robotconf as rc
    >>> data = {"moves": [{"type": "PTP", "q": [0, 0.3, -0.5]}], "joint_speed": 2}
    >>> program_from_dict(data, rc.preset("paper")).limits.joint_speed
    array([2., 2., 2.])
    """
    check_json_object(value, path, _PROGRAM_KEYS)
    moves = value["moves"]
    if not isinstance(moves, list) or len(moves) > MAX_MOVES:
        raise InvalidInputError(
            f"{path}.moves",
            one_line(moves) if not isinstance(moves, list) else f"<{len(moves)} moves>",
            f"a list of 1 to {MAX_MOVES} moves",
            problem="not a list of moves:",
        )
    built = [_move(move, f"{path}.moves[{i}]") for i, move in enumerate(moves)]
    keys = [key for key in _PROGRAM_KEYS if key != "moves"]
    options = {key: _value(value.get(key), f"{path}.{key}") for key in keys}
    try:
        return Program(robot, built, **options)
    except InvalidInputError as error:
        raise error.within(path) from None
