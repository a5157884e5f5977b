"""A robot program as the Program tab edits it: moves and settings before the core checks them.

The table shows a :class:`ProgramDraft`, and every edit (a typed field, teach, add,
delete, reorder, a type change) makes a new draft; :func:`build` hands it to
:class:`robotconf.programs.Program`, whose :class:`~robotconf.InvalidInputError` names the
move and the field (``moves[2].speed``). Drafts are immutable, so the tab's undo keeps a
list of them. Where a move ends (the taught points in the 3D pane) is read off the draft
without planning: a PTP's coordinates through forward kinematics, a LIN's or CIRC's
target as typed.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ...kinematics import Robot
from ...programs import CIRC, LIN, PTP, Move, Program, Wait, moving_joints

__all__ = [
    "ProgramDraft",
    "MOVE_KINDS",
    "WAIT_SECONDS",
    "build",
    "draft_of",
    "converted",
    "edited",
    "taught",
    "remapped",
    "held",
    "end_points",
    "point_of",
]

#: The move types a row can take, in the order the type menu lists them.
MOVE_KINDS = ("PTP", "LIN", "CIRC", "Wait")
#: A new Wait row holds this long (s).
WAIT_SECONDS = 1.0
#: How far (relative to the robot's size) a new CIRC's via point lies off its chord when
#: start and end coincide, so that the arc is a proper one to edit from.
VIA_OFFSET = 0.1

Point = tuple[float, float, float]


@dataclass(frozen=True)
class ProgramDraft:
    """The moves of the table and the program's settings, as typed.

    Attributes
    ----------
    moves : tuple of Move
        Core moves with plain tuples of core numbers (radians, length units).
    settings : dict
        ``start`` and the limits as :class:`~robotconf.programs.Program` takes them,
        ``None`` (or absent) for the core's default.

    Examples
    --------
    >>> draft = ProgramDraft((PTP(q=(0.0, 0.3, -0.5)),), {"cartesian_speed": 20.0})
    >>> draft == ProgramDraft((PTP(q=(0.0, 0.3, -0.5)),), {"cartesian_speed": 20.0})
    True
    """

    moves: tuple[Move, ...] = ()
    settings: Mapping[str, Any] = field(default_factory=dict)

    def with_moves(self, moves: Sequence[Move]) -> ProgramDraft:
        """The same settings with other moves."""
        return replace(self, moves=tuple(moves))

    def with_setting(self, name: str, value: Any) -> ProgramDraft:
        """The same moves with one setting changed (``None``: the core's default)."""
        return replace(self, settings={**self.settings, name: value})


def build(draft: ProgramDraft, robot: Robot) -> Program | None:
    """The core's program for ``robot``, or ``None`` when the draft has no moves.

    Raises
    ------
    InvalidInputError
        The core's own, naming the move and field (``moves[1].via``) or the setting.

    Examples
    --------
    >>> import robotconf as rc
    >>> build(ProgramDraft((Wait(2.0),)), rc.preset("paper")).duration
    2.0
    >>> build(ProgramDraft(), rc.preset("paper")) is None
    True
    """
    if not draft.moves:
        return None
    options = {key: value for key, value in draft.settings.items() if value is not None}
    return Program(robot, list(draft.moves), **options)


def draft_of(program: Program | None) -> ProgramDraft:
    """The draft that builds ``program`` again (empty for ``None``).

    >>> import robotconf as rc
    >>> program = Program(rc.preset("paper"), [Wait(1.0)], joint_speed=2.0)
    >>> build(draft_of(program), program.robot) == program
    True
    """
    if program is None:
        return ProgramDraft()
    settings = {key: value for key, value in program.settings.items() if value is not None}
    return ProgramDraft(tuple(program.moves), settings)


def point_of(move: Move) -> Point | None:
    """The end-effector point a LIN, CIRC or PTP ``position``/``pose`` target names.

    ``None`` for a PTP given by coordinates and for a Wait (see :func:`end_points`).

    >>> point_of(LIN(position=(60.0, 10.0, 30.0))), point_of(Wait(1.0)) is None
    ((60.0, 10.0, 30.0), True)
    """
    target: Any = None
    if isinstance(move, (PTP, LIN)):
        target = move.position if move.position is not None else move.pose
    elif isinstance(move, CIRC):
        target = move.end
    if target is None:
        return None
    array = np.asarray(target, dtype=float)
    values = array[:3, 3] if array.shape == (4, 4) else array.reshape(-1)[:3]
    return (float(values[0]), float(values[1]), float(values[2]))


def end_points(draft: ProgramDraft, robot: Robot) -> list[np.ndarray | None]:
    """Where each move leaves the end effector, from the draft alone (no planning).

    A PTP's coordinates go through ``robot.end_effector``; a Wait stays where the move
    before it ended (the robot's current end effector at the start). ``None`` where a
    move cannot say (coordinates that do not fit the robot).

    >>> import robotconf as rc
    >>> moves = (PTP(q=(0.0, 0.0, 0.0)), Wait(1.0), LIN(position=(60.0, 10.0, 30.0)))
    >>> [p.tolist() for p in end_points(ProgramDraft(moves), rc.preset("paper"))]
    [[70.0, 0.0, 20.0], [70.0, 0.0, 20.0], [60.0, 10.0, 30.0]]
    """
    points: list[np.ndarray | None] = []
    before: np.ndarray | None = robot.at().end_effector
    for move in draft.moves:
        point: np.ndarray | None
        if isinstance(move, Wait):
            point = before
        elif isinstance(move, PTP) and move.q is not None:
            try:
                point = robot.end_effector(move.q)
            except InvalidInputError:
                point = None
        else:
            named = point_of(move)
            point = None if named is None else np.array(named)
        if point is not None and not np.isfinite(point).all():
            point = None
        points.append(point)
        before = point
    return points


def taught(move: Move, robot: Robot, via: bool = False) -> Move:
    """``move`` with its target set to where the robot is now.

    A PTP takes the current coordinates, a LIN its end-effector point (its pose, when
    the target is a pose), a CIRC the same as its end (``via=True``: as its via point).

    >>> import robotconf as rc
    >>> robot = rc.preset("paper")
    >>> taught(LIN(position=(1.0, 2.0, 3.0), speed=5.0), robot)
    LIN(position=(70.0, 0.0, 20.0), pose=None, speed=5.0, accel=None, orientation='slerp')
    """
    point = tuple(float(v) for v in robot.at().end_effector)
    pose = tuple(tuple(float(v) for v in row) for row in robot.end_effector_pose())
    if isinstance(move, PTP):
        return PTP(q=tuple(float(v) for v in robot.q), profile=move.profile)
    if isinstance(move, LIN):
        if move.pose is not None:
            return replace(move, pose=pose, position=None)
        return replace(move, position=point, pose=None)
    if isinstance(move, CIRC):
        if via:
            return replace(move, via=point)
        return replace(move, end=pose if np.shape(move.end) == (4, 4) else point)
    return move


def converted(move: Move, kind: str, robot: Robot, before: Any, after: Any) -> Move:
    """``move`` as a move of type ``kind``, keeping the point it ends at.

    Parameters
    ----------
    move : Move
    kind : {"PTP", "LIN", "CIRC", "Wait"}
    robot : Robot
        The panel's robot (a Wait becoming a PTP takes its coordinates).
    before, after : array-like of 3 or None
        Where the move starts and where it ends now (:func:`end_points`); a CIRC gets a
        via point halfway along, off to the side by half the chord.

    Examples
    --------
    >>> import robotconf as rc
    >>> arc = converted(LIN(position=(40.0, 0.0, 20.0)), "CIRC", rc.preset("paper"),
    ...                 (70.0, 0.0, 20.0), (40.0, 0.0, 20.0))
    >>> arc.via, arc.end
    ((55.0, 15.0, 20.0), (40.0, 0.0, 20.0))
    """
    if kind == move.kind:
        return move
    end = robot.at().end_effector if after is None else np.asarray(after, dtype=float)
    point = tuple(float(v) for v in end)
    speed = getattr(move, "speed", None)
    if kind == "Wait":
        return Wait(WAIT_SECONDS)
    if kind == "PTP":
        if isinstance(move, Wait) or after is None:
            return PTP(q=tuple(float(v) for v in robot.q))
        return PTP(position=point)
    if kind == "LIN":
        return LIN(position=point, speed=speed)
    start = robot.at().end_effector if before is None else np.asarray(before, dtype=float)
    return CIRC(via=_via(start, end, robot), end=point, speed=speed)


def _via(start: np.ndarray, end: np.ndarray, robot: Robot) -> Point:
    """Halfway along the chord, pushed sideways (level if it can) by half its length."""
    from ...kinematics import characteristic_length

    chord = end - start
    length = float(np.linalg.norm(chord))
    side = np.cross(chord, (0.0, 0.0, 1.0))  # level, when the chord is not vertical
    if np.linalg.norm(side) <= 1e-9 * length:
        side = np.cross(chord, (1.0, 0.0, 0.0)) if length > 0 else np.array([1.0, 0.0, 0.0])
    side = side / np.linalg.norm(side)
    offset = 0.5 * length if length > 0 else VIA_OFFSET * characteristic_length(robot)
    via = 0.5 * (start + end) + offset * side
    return (float(via[0]) + 0.0, float(via[1]) + 0.0, float(via[2]) + 0.0)


def edited(move: Move, name: str, value: Any, component: int | None = None) -> Move:
    """``move`` with field ``name`` (or one ``component`` of it) set to ``value``.

    ``name`` is a move's field, or ``"point"`` for a LIN's target or a CIRC's end, the
    point in either a ``position`` or a ``pose`` (whose translation is set).

    >>> edited(PTP(q=(0.0, 0.0)), "q", 0.5, component=1).q
    (0.0, 0.5)
    >>> edited(LIN(position=(1.0, 2.0, 3.0)), "point", 9.0, component=2).position
    (1.0, 2.0, 9.0)
    """
    if component is None:
        return replace(move, **{name: value})
    if name == "point":
        attribute = "end" if isinstance(move, CIRC) else "position"
        if getattr(move, attribute) is None:
            attribute = "pose"
        target = getattr(move, attribute)
        if np.shape(target) == (4, 4):
            rows = [list(row) for row in target]
            rows[component][3] = value
            return replace(move, **{attribute: tuple(tuple(row) for row in rows)})
        name = attribute
    values = list(getattr(move, name))
    values[component] = value
    return replace(move, **{name: tuple(values)})


def held(draft: ProgramDraft, robot: Robot) -> ProgramDraft:
    """The draft with every PTP's coordinates of joints a program does not move (a module
    set to none or fixed, an inactive one) at the robot's own values: the program cannot
    move them, and the core refuses a PTP that asks it to. The same draft when nothing
    changes.

    >>> import robotconf as rc
    >>> arm = rc.Robot([rc.Module("Rz"), rc.Module("none", (1, 0, 0), q=0.0)])
    >>> held(ProgramDraft((PTP(q=(0.5, 0.7)),)), arm).moves[0].q
    (0.5, 0.0)
    """
    still = ~moving_joints(robot)
    if not still.any():
        return draft
    own = robot.q
    moves, changed = [], False
    for move in draft.moves:
        if isinstance(move, PTP) and move.q is not None and len(move.q) == robot.n:
            q = tuple(float(own[i]) if still[i] else move.q[i] for i in range(robot.n))
            if q != tuple(move.q):
                move, changed = replace(move, q=q), True
        moves.append(move)
    return draft.with_moves(moves) if changed else draft


def remapped(draft: ProgramDraft, robot: Robot, order: Sequence[int | None] | None) -> ProgramDraft:
    """The draft with every PTP's coordinates following the robot's (a module added,
    removed or moved): coordinate i takes old coordinate ``order[i]``, or the robot's own
    value when it is new (``order`` ``None``: by position).

    >>> import robotconf as rc
    >>> draft = ProgramDraft((PTP(q=(0.1, 0.2, 0.3)),))
    >>> two = rc.preset("planar_2r")
    >>> remapped(draft, two, [None, 2]).moves[0].q
    (0.0, 0.3)
    """
    n = robot.n
    source = list(order) if order is not None else list(range(n))
    moves = []
    for move in draft.moves:
        if isinstance(move, PTP) and move.q is not None:
            old = list(move.q)
            new = []
            for i in range(n):
                j = source[i] if i < len(source) else None
                ok = j is not None and 0 <= j < len(old) and math.isfinite(old[j])
                new.append(float(old[j]) if ok and j is not None else float(robot.q[i]))
            move = replace(move, q=tuple(new))
        moves.append(move)
    return draft.with_moves(moves)
