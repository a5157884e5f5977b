"""Where a robot's moves go, read off the cell: the TCP now, a frame's point, a new move.

Points a move is given directly stay in the robot's base frame, as in any program
(docs/cell.md, "Programs in the cell"); a frame is the cell's, resolved by the cell. These
helpers turn one into the other so that a move keeps its place when its target or its
type changes.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ...programs import CIRC, LIN, PTP, Move, Wait
from ..state import DesignerState, RobotItem, target_of

__all__ = [
    "Point",
    "robot_item",
    "tcp_point",
    "frame_point",
    "end_point",
    "new_move",
    "converted",
    "retargeted",
    "checked",
]

Point = tuple[float, float, float]
#: A new Wait row holds this long (s).
WAIT_SECONDS = 1.0


def robot_item(state: DesignerState, name: str) -> RobotItem:
    """The robot ``name`` of the cell (refused for an object or a frame)."""
    item = state.cell.item(name)
    if not isinstance(item, RobotItem):
        raise InvalidInputError("robot", name, f"one of {list(state.cell.robots)}")
    return item


def _point(values: Any) -> Point:
    x, y, z = (float(v) + 0.0 for v in np.asarray(values, dtype=float)[:3])
    return (x, y, z)


def tcp_point(state: DesignerState, robot: str, q: Any = None) -> Point:
    """Where the robot's TCP is (at ``q``, default its own), in its base frame."""
    planner = state.cell.cell.program(robot, [Wait(0.0)]).robot  # the TCP's robot
    return _point(planner.end_effector(planner.q if q is None else q))


def frame_point(state: DesignerState, robot: str, frame: str) -> Point:
    """Where a cell entry's origin is, in the robot's base frame."""
    built = state.cell.cell
    local = np.linalg.solve(built.pose_of(robot), built.pose_of(frame))
    return _point(local[:3, 3])


def end_point(state: DesignerState, robot: str, move: Move) -> Point | None:
    """Where a move ends (base frame); ``None`` for a Wait."""
    target = target_of(move)
    if target == "frame":
        return frame_point(state, robot, move.frame)  # type: ignore[attr-defined]
    if target == "q":
        return tcp_point(state, robot, move.q)  # type: ignore[attr-defined]
    if target in ("point", "pose"):
        value = getattr(move, "end" if isinstance(move, CIRC) else "position", None)
        if value is None:
            value = move.pose  # type: ignore[attr-defined]
        array = np.asarray(value, dtype=float)
        return _point(array[:3, 3] if array.shape == (4, 4) else array)
    return None


def _via(start: Point, end: Point, size: float) -> Point:
    """Halfway along the chord, pushed sideways (level if it can) by half its length."""
    a, b = np.array(start), np.array(end)
    chord = b - a
    length = float(np.linalg.norm(chord))
    side = np.cross(chord, (0.0, 0.0, 1.0))
    if np.linalg.norm(side) <= 1e-9 * max(length, 1.0):
        side = np.cross(chord, (1.0, 0.0, 0.0)) if length > 0 else np.array([1.0, 0.0, 0.0])
    side /= np.linalg.norm(side)
    return _point(0.5 * (a + b) + (0.5 * length if length > 0 else 0.1 * size) * side)


def new_move(state: DesignerState, robot: str, kind: str) -> Move:
    """A new move for the end of the program: a PTP to the robot's q, a LIN or CIRC to the
    cell's first frame (else where the TCP is), a Wait of a second.

    >>> from robotconf.cell_designer.actions import AddRobot
    >>> state = AddRobot("paper").apply(DesignerState())
    >>> new_move(state, "paper", "PTP")
    PTP(q=(0.0, 0.0, 0.0), pose=None, position=None, profile='trapezoidal')
    """
    item = robot_item(state, robot)
    if kind == "PTP":
        return PTP(q=tuple(float(v) for v in item.robot.q))
    if kind == "Wait":
        return Wait(WAIT_SECONDS)
    frames = state.cell.frames
    if kind == "LIN":
        return LIN(frame=frames[0]) if frames else LIN(position=tcp_point(state, robot))
    if kind == "CIRC":
        start = tcp_point(state, robot)
        end = frame_point(state, robot, frames[0]) if frames else start
        via = _via(start, end, float(np.linalg.norm(start)) or 1.0)
        return CIRC(via=via, frame=frames[0]) if frames else CIRC(via=via, end=end)
    raise InvalidInputError("kind", kind, "'PTP', 'LIN', 'CIRC' or 'Wait'")


def converted(state: DesignerState, robot: str, move: Move, kind: str) -> Move:
    """``move`` as a move of type ``kind`` that ends where it ends (its frame kept)."""
    if kind == move.kind:
        return move
    if kind == "Wait":
        return Wait(WAIT_SECONDS)
    frame = getattr(move, "frame", None)
    end = end_point(state, robot, move)
    speed = getattr(move, "speed", None)
    if kind == "PTP":
        if frame is not None:
            return PTP(frame=frame)
        return PTP(position=end) if end is not None else new_move(state, robot, "PTP")
    if end is None:
        return new_move(state, robot, kind)
    if kind == "LIN":
        return LIN(frame=frame, speed=speed) if frame else LIN(position=end, speed=speed)
    via = _via(tcp_point(state, robot), end, float(np.linalg.norm(end)) or 1.0)
    if frame is not None:
        return CIRC(via=via, frame=frame, speed=speed)
    return CIRC(via=via, end=end, speed=speed)


def retargeted(state: DesignerState, robot: str, move: Move, target: str) -> Move:
    """``move`` going to ``target``: a cell entry's name, ``"point"`` (where it ends now,
    in the base frame) or ``"q"`` (a PTP: the robot's coordinates now)."""
    if isinstance(move, Wait):
        raise InvalidInputError("target", target, "none: a Wait has no target")
    if target == "q":
        if not isinstance(move, PTP):
            raise InvalidInputError("target", target, "a point or a frame (q is a PTP's)")
        return PTP(
            q=tuple(float(v) for v in robot_item(state, robot).robot.q), profile=move.profile
        )
    if target == "point":
        end = end_point(state, robot, move) or tcp_point(state, robot)
        if isinstance(move, PTP):
            return PTP(position=end, profile=move.profile)
        if isinstance(move, LIN):
            return replace(move, position=end, pose=None, frame=None)
        assert isinstance(move, CIRC)
        return replace(move, end=end, frame=None)
    state.cell.item(target)
    if isinstance(move, PTP):
        return PTP(frame=target, profile=move.profile)
    if isinstance(move, LIN):
        return replace(move, position=None, pose=None, frame=target)
    assert isinstance(move, CIRC)
    return replace(move, end=None, frame=target)


def checked(state: DesignerState, robot: str, move: Move) -> Move:
    """``move`` if the robot's program can hold it (a frame stands for a pose), else the
    core's refusal; a cell file can always be read back."""
    item = robot_item(state, robot)
    eye = np.eye(4)
    move.resolved(lambda _name: eye).checked(item.robot.n, item.robot.coordinate_names)
    return move
