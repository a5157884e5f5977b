"""The moves of a robot program: PTP, LIN, CIRC and Wait (docs/programs.md).

A move records what was asked. Making one checks that its numbers are numbers within the
program bounds (finite, ``|x| ≤ 1e150``, rates from 1e-150 to 1e150, see
:mod:`robotconf.programs._inputs`), so an error names the field at once;
:class:`~robotconf.programs.Program` checks it again against the robot (so an error names
``moves[i].field``) and keeps the checked copy, whose numbers are plain floats and tuples.
``to_dict`` gives the JSON form of a move.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, fields, replace
from typing import Any, ClassVar

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_configuration, one_line
from ._inputs import check_move_numbers, choice, point, pose, positive, seconds
from ._profiles import PROFILES

__all__ = ["Move", "PTP", "LIN", "CIRC", "Wait", "ORIENTATIONS", "MOVE_TYPES"]

#: How a LIN or CIRC move turns the tool: ``"slerp"`` from the start orientation to the
#: target's, or ``"hold"`` the start orientation throughout.
ORIENTATIONS = ("slerp", "hold")


def _frozen(value: Any) -> Any:
    """A hashable, comparable stand-in for a field's value (arrays become tuples)."""
    if isinstance(value, np.ndarray):
        return ("array", value.shape, tuple(value.ravel().tolist()))
    if isinstance(value, (list, tuple)):
        return tuple(_frozen(v) for v in value)
    return value


def _plain(value: Any) -> Any:
    """A checked field as JSON data: tuples become lists."""
    if isinstance(value, tuple):
        return [_plain(v) for v in value]
    return value


@dataclass(frozen=True, eq=False)
class Move:
    """Base of the four moves: comparison, JSON data and the checked copy.

    Two moves are equal when they are of one type with equal fields (arrays compared by
    value), so a program read back from JSON equals the original.

    >>> Wait(1.0) == Wait(1.0), PTP(q=(0.0, 1.0)) == PTP(q=[0.0, 1.0])
    (True, True)
    """

    kind: ClassVar[str] = ""

    def __post_init__(self) -> None:
        check_move_numbers(self)

    def _key(self) -> tuple[Any, ...]:
        return tuple(_frozen(getattr(self, f.name)) for f in fields(self))

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        assert isinstance(other, Move)
        return self._key() == other._key()

    def __hash__(self) -> int:
        return hash((self.kind, *self._key()))

    def to_dict(self) -> dict[str, Any]:
        """The move as JSON data: ``{"type": "LIN", field: value, …}`` (every field; a
        cell ``frame`` only when the move names one)."""
        data: dict[str, Any] = {"type": self.kind}
        for f in fields(self):
            if f.name != "frame" or getattr(self, f.name) is not None:
                data[f.name] = _plain(getattr(self, f.name))
        return data

    def resolved(self, lookup: Callable[[str], Any]) -> Move:
        """The move with its cell frame replaced by the pose ``lookup(frame)`` gives.

        A cell (``cell.program``, ``cell.run``) calls this with each frame's pose in the
        robot's base frame; a move without a frame comes back unchanged.

        >>> import numpy as np
        >>> LIN(frame="table/pick").resolved(lambda name: np.eye(4)).pose[3]
        (0.0, 0.0, 0.0, 1.0)
        """
        frame = getattr(self, "frame", None)
        if frame is None:
            return self
        if not isinstance(frame, str):
            raise InvalidInputError("frame", one_line(frame), _FRAME)
        target = pose(lookup(frame), "frame")
        key = "end" if isinstance(self, CIRC) else "pose"
        changes: dict[str, Any] = {"frame": None, key: target}
        return replace(self, **changes)

    def checked(self, n: int, names: Sequence[str]) -> Move:
        """A copy with every field validated and normalized (errors name the field)."""
        raise NotImplementedError


#: What a move's ``frame`` names.
_FRAME = "the name of a frame of a work cell ('table/pick'), resolved by the cell"


def _unresolved(frame: Any) -> InvalidInputError:
    """A move that names a cell frame, checked outside a cell."""
    return InvalidInputError(
        "frame",
        one_line(frame),
        "a point or pose target here; a frame target in cell.program(…) or cell.run(…)",
        problem="a cell frame outside a cell:",
    )


def _one_target(move: Move, names: tuple[str, ...]) -> str:
    given = [name for name in names if getattr(move, name) is not None]
    allowed = "exactly one target: " + " or ".join(names)
    if not given:
        raise InvalidInputError(names[0], None, allowed, problem="no target given:")
    if len(given) > 1:
        raise InvalidInputError(given[1], tuple(given), allowed, problem="more than one target:")
    return given[0]


def _optional(value: Any, field: str, what: str) -> float | None:
    return None if value is None else positive(value, field, what)


@dataclass(frozen=True, eq=False)
class PTP(Move):
    """Point to point: every joint moves at once and all arrive together (joint space).

    Parameters
    ----------
    q : array-like, shape (n,), optional
        Target coordinates (rad, length).
    pose : array-like, shape (4, 4), optional
        Target end-effector pose, solved by ``rc.ik`` from the previous move's end.
    position : array-like, shape (3,), optional
        Target end-effector point, solved likewise. Give exactly one target.
    frame : str, optional
        A work cell's frame (``"table/pick"``), resolved to a pose by the cell.
    profile : {"trapezoidal", "quintic"}
        Time law; both respect the program's joint speed and acceleration limits.

    Examples
    --------
    >>> PTP(q=[0, 0.3, -0.5]).to_dict()
    {'type': 'PTP', 'q': [0, 0.3, -0.5], 'pose': None, 'position': None, 'profile': 'trapezoidal'}
    """

    kind: ClassVar[str] = "PTP"
    q: Any = None
    pose: Any = None
    position: Any = None
    profile: str = "trapezoidal"
    frame: Any = field(default=None, repr=False)

    def checked(self, n: int, names: Sequence[str]) -> PTP:
        target = _one_target(self, ("q", "pose", "position", "frame"))
        if target == "frame":
            raise _unresolved(self.frame)
        profile = choice(self.profile, "profile", PROFILES)
        if target == "q":
            values = check_configuration(self.q, n, names, "q")
            return PTP(q=tuple(values.tolist()), profile=profile)
        if target == "pose":
            return PTP(pose=pose(self.pose, "pose"), profile=profile)
        return PTP(position=point(self.position, "position"), profile=profile)


@dataclass(frozen=True, eq=False)
class LIN(Move):
    """A straight line of the end-effector point, at a trapezoidal speed along it.

    Parameters
    ----------
    position : array-like, shape (3,), optional
        Target point (length); the orientation is held.
    pose : array-like, shape (4, 4), optional
        Target pose; the orientation turns from the start's to the pose's (slerp).
    frame : str, optional
        A work cell's frame (``"table/pick"``): its pose, resolved by the cell.
    speed : float, optional
        Path speed (length/s), > 0; default the program's ``cartesian_speed``.
    accel : float, optional
        Path acceleration (length/s²), > 0; default the program's ``cartesian_accel``.
    orientation : {"slerp", "hold"}
        ``"hold"`` keeps the start orientation even for a pose target.

    Examples
    --------
    >>> LIN(position=[60, 10, 30], speed=20).speed
    20
    """

    kind: ClassVar[str] = "LIN"
    position: Any = None
    pose: Any = None
    speed: Any = None
    accel: Any = None
    orientation: str = "slerp"
    frame: Any = field(default=None, repr=False)

    def checked(self, n: int, names: Sequence[str]) -> LIN:
        target = _one_target(self, ("position", "pose", "frame"))
        if target == "frame":
            raise _unresolved(self.frame)
        speed = _optional(self.speed, "speed", "a path speed (length/s)")
        accel = _optional(self.accel, "accel", "a path acceleration (length/s²)")
        orientation = choice(self.orientation, "orientation", ORIENTATIONS)
        if target == "pose":
            return LIN(
                pose=pose(self.pose, "pose"), speed=speed, accel=accel, orientation=orientation
            )
        return LIN(
            position=point(self.position, "position"),
            speed=speed,
            accel=accel,
            orientation=orientation,
        )


@dataclass(frozen=True, eq=False)
class CIRC(Move):
    """A circular arc of the end-effector point from where it is, through ``via``, to ``end``.

    Parameters
    ----------
    via : array-like, shape (3,)
        A point of the arc (length); with the start and ``end`` it fixes the circle.
    end : array-like, shape (3,) or (4, 4)
        The end point, or the end pose (its orientation is reached by slerp).
    frame : str, optional
        Instead of ``end``: a work cell's frame, resolved to the end pose by the cell.
    speed, accel, orientation
        As for :class:`LIN`.

    Examples
    --------
    >>> CIRC(via=[50, 20, 30], end=[40, 10, 30]).kind
    'CIRC'
    """

    kind: ClassVar[str] = "CIRC"
    via: Any = None
    end: Any = None
    speed: Any = None
    accel: Any = None
    orientation: str = "slerp"
    frame: Any = field(default=None, repr=False)

    def checked(self, n: int, names: Sequence[str]) -> CIRC:
        if self.frame is not None:
            if self.end is not None:
                raise InvalidInputError(
                    "frame", self.frame, "end or frame, not both", "both given:"
                )
            raise _unresolved(self.frame)
        if self.via is None or self.end is None:
            missing = "via" if self.via is None else "end"
            raise InvalidInputError(missing, None, "a point (3 numbers)", problem="missing:")
        shape = np.shape(self.end) if not isinstance(self.end, (str, bytes)) else ()
        end = pose(self.end, "end") if shape == (4, 4) else point(self.end, "end")
        return CIRC(
            via=point(self.via, "via"),
            end=end,
            speed=_optional(self.speed, "speed", "a path speed (length/s)"),
            accel=_optional(self.accel, "accel", "a path acceleration (length/s²)"),
            orientation=choice(self.orientation, "orientation", ORIENTATIONS),
        )


@dataclass(frozen=True, eq=False)
class Wait(Move):
    """Hold still for ``seconds`` (≥ 0).

    >>> Wait(0.5).to_dict()
    {'type': 'Wait', 'seconds': 0.5}
    """

    kind: ClassVar[str] = "Wait"
    seconds: Any = 0.0

    def checked(self, n: int, names: Sequence[str]) -> Wait:
        return replace(self, seconds=seconds(self.seconds, "seconds"))


def _shows_frame(cls: type[Move]) -> None:
    """A move's repr names its cell frame only when it has one (as ``to_dict`` writes it)."""
    plain = cls.__repr__

    def __repr__(self: Move) -> str:
        text = plain(self)
        frame = getattr(self, "frame", None)
        return text if frame is None else f"{text[:-1]}, frame={frame!r})"

    cls.__repr__ = __repr__  # type: ignore[method-assign,assignment]


for _cls in (PTP, LIN, CIRC):
    _shows_frame(_cls)


#: Move type name (the JSON ``"type"``) → class.
MOVE_TYPES: dict[str, type[Move]] = {"PTP": PTP, "LIN": LIN, "CIRC": CIRC, "Wait": Wait}
