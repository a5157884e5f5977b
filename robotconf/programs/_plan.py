"""Planning a program: each move's start and end configuration, path and time law.

Planning does not depend on the sampling step: it fixes every move's duration and end
configuration (solving targets with ``rc.ik``), so that ``Program.simulate(dt)`` at any
``dt`` samples the same motion.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from .._errors import InvalidInputError
from .._validation import one_line
from ..inverse_kinematics import IKResult, ik
from ._chain import Chain, kinematics
from ._inputs import check_duration
from ._limits import Limits
from ._moves import CIRC, LIN, PTP, Move, Wait
from ._paths import CartesianPath, arc_path, line_path
from ._profiles import Profile, quintic, still, trapezoidal
from ._tracking import Knots, knot_count, make_knots, track

__all__ = ["Segment", "plan", "PATH_TOL", "check_held"]

#: Tolerance of ``rc.ik`` along LIN/CIRC paths: relative to the robot's size, and rad.
PATH_TOL = 1e-12

#: A LIN shorter than this (relative to the robot's size) and turning less (rad) goes
#: nowhere.
ZERO_PATH = 1e-12


@dataclass(frozen=True, eq=False)
class Segment:
    """One planned move of a program.

    Attributes
    ----------
    index : int
        The move's position in the program.
    kind : str
        ``"PTP"``, ``"LIN"``, ``"CIRC"`` or ``"Wait"``.
    start, duration : float
        When the move starts and how long it takes (s).
    q_start, q_end : ndarray, shape (n,)
        Coordinates at both ends.
    point_start, point_end : ndarray, shape (3,)
        End-effector positions at both ends (length): the taught points.
    profile : Profile
        The time law of the move's path parameter ``u``.
    path : CartesianPath or None
        The end-effector path of a LIN or CIRC move.
    via : ndarray, shape (3,), or None
        The via point of a CIRC move.
    knots : Knots or None
        LIN/CIRC: the joint values planning walked the path through (seeds for sampling).

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.programs import PTP, Program, Wait
    >>> prog = Program(rc.preset("paper"), [PTP(q=[0, 0.3, -0.5]), Wait(0.5)])
    >>> prog.segments[1]
    Segment(1, 'Wait', t = 1 … 1.5 s, profile='still')
    """

    index: int
    kind: str
    start: float
    duration: float
    q_start: np.ndarray
    q_end: np.ndarray
    point_start: np.ndarray
    point_end: np.ndarray
    profile: Profile
    path: CartesianPath | None = None
    via: np.ndarray | None = None
    knots: Knots | None = None

    @property
    def end(self) -> float:
        """When the move ends (s)."""
        return self.start + self.duration

    @property
    def corners(self) -> tuple[float, ...]:
        """Times (s) inside the move where the accelerations jump (trapezoid corners)."""
        return tuple(self.start + c for c in self.profile.corners)

    def __repr__(self) -> str:
        return (
            f"Segment({self.index}, {self.kind!r}, t = {self.start:.6g} … {self.end:.6g} s, "
            f"profile={self.profile.kind!r})"
        )


def check_held(chain: Chain, q: np.ndarray, field: str) -> None:
    """Coordinates of joints a program does not move must keep the robot's own values."""
    robot = chain.robot
    differ = ~chain.moving & (q != robot.q)
    if np.any(differ):
        j = int(np.flatnonzero(differ)[0])
        raise InvalidInputError(
            field,
            float(q[j]),
            f"{robot.coordinate_names[j]} = {robot.q[j]!r}, the robot's own value",
            problem=f"{robot.coordinate_names[j]} is not a moving joint (module "
            f"{robot.module_names[j]!r}) and must keep its value, got",
        )


def _ee(chain: Chain, q: np.ndarray) -> np.ndarray:
    pose, _ = kinematics(chain, q[np.newaxis])
    return pose[0]


def _nearest_twin(chain: Chain, q: np.ndarray, near: np.ndarray) -> np.ndarray:
    """Revolute angles turned by whole turns to lie nearest ``near``, within the ranges."""
    robot = chain.robot
    limits = robot.joint_limits()
    revolute = np.array([t == "revolute" for t in robot.joint_types]) & chain.moving
    turns = np.round((near - q) / (2.0 * np.pi))
    twin = q + 2.0 * np.pi * turns
    inside = (twin >= limits[:, 0]) & (twin <= limits[:, 1])
    return np.where(revolute & inside, twin, q)


def _reach(
    chain: Chain, target: np.ndarray, q0: np.ndarray, field: str, shown: object = None
) -> np.ndarray:
    """``rc.ik`` for a PTP target (or a path end that the walk missed), refusing a miss."""
    mode = chain.mode if target.shape == (4, 4) else "position"
    result = ik(chain.robot, target, q0=q0, mode=mode)
    if not result.success:
        raise InvalidInputError(
            field,
            one_line(target if shown is None else shown),
            "a target the robot reaches within its joint ranges",
            problem=f"unreachable target ({result.reason}: {result.message}):",
        )
    return _nearest_twin(chain, result.q, q0)


def _joint_profile(delta: np.ndarray, limits: Limits, kind: str) -> Profile:
    moves = np.abs(delta) > 0.0
    if not moves.any():
        return still(0.0)
    # A step of 1e-300 at a speed of 1e150 overflows: _check_time refuses that time law.
    with np.errstate(over="ignore"):
        speed = float(np.min(limits.joint_speed[moves] / np.abs(delta[moves])))
        accel = float(np.min(limits.joint_accel[moves] / np.abs(delta[moves])))
    return quintic(speed, accel) if kind == "quintic" else trapezoidal(speed, accel)


def _ptp(chain: Chain, move: PTP, q0: np.ndarray, limits: Limits) -> tuple[np.ndarray, Profile]:
    if move.q is not None:
        target = np.array(move.q, dtype=float)
        check_held(chain, target, "q")
    elif move.pose is not None:
        target = _reach(chain, np.array(move.pose), q0, "pose")
    else:
        target = _reach(chain, np.array(move.position), q0, "position")
    return target, _joint_profile(target - q0, limits, move.profile)


def _path(chain: Chain, move: LIN | CIRC, q0: np.ndarray) -> tuple[CartesianPath, str, np.ndarray]:
    """The move's path from the end-effector pose at ``q0``, the target's field and value."""
    start = _ee(chain, q0)
    p0, r0 = start[:3, 3], start[:3, :3]
    field = "end" if isinstance(move, CIRC) else ("pose" if move.pose is not None else "position")
    if isinstance(move, CIRC):
        goal = move.end
    else:
        goal = move.pose if move.pose is not None else move.position
    goal_array = np.array(goal, dtype=float)
    if goal_array.shape == (4, 4):
        p1 = goal_array[:3, 3]
        turns = move.orientation == "slerp" and chain.mode == "pose"
        r1 = goal_array[:3, :3] if turns else r0
    else:
        p1, r1 = goal_array, r0
    if isinstance(move, LIN):
        path = line_path(p0, p1, r0, r1)
        if path.length <= ZERO_PATH * chain.length and path.angle <= ZERO_PATH:
            raise InvalidInputError(
                field,
                tuple(float(v) for v in p1),  # the point, also for a pose target
                "a target away from the start (for no motion use Wait)",
                problem="the LIN goes nowhere: the end effector is already at",
            )
        return path, field, goal_array
    arc = arc_path(p0, np.array(move.via), p1, r0, r1)
    if arc is None:
        raise InvalidInputError(
            "via",
            move.via,
            "a via point off the line through the start and the end (three distinct points)",
            problem=f"start {tuple(np.round(p0, 9).tolist())}, via and end lie on one line:",
        )
    return arc, field, goal_array


def _path_profile(path: CartesianPath, move: LIN | CIRC, chain: Chain, limits: Limits) -> Profile:
    speed = limits.cartesian_speed if move.speed is None else move.speed
    accel = limits.cartesian_accel if move.accel is None else move.accel
    caps_v, caps_a = [], []
    if path.length > ZERO_PATH * chain.length:
        caps_v.append(speed / path.length)
        caps_a.append(accel / path.length)
    if path.angle > ZERO_PATH:
        caps_v.append(limits.angular_speed / path.angle)
        caps_a.append(limits.angular_accel / path.angle)
    return trapezoidal(min(caps_v), min(caps_a))


def _end(
    chain: Chain,
    path: CartesianPath,
    walked: np.ndarray,
    kept: bool,
    field: str,
    shown: object,
) -> np.ndarray:
    """The path's end, solved exactly from the walk's end.

    When the walk lost the path (through the hole of the workspace, say), its end says
    little: the end is then solved afresh within the joint ranges (``rc.ik`` with its
    restarts), and only if that fails is the walk's own solution kept (or the target
    refused). ``Program.check`` reports the broken path.
    """
    pose, _, _ = path.evaluate(np.ones(1), np.zeros(1), np.zeros(1))
    target = pose[0] if chain.mode == "pose" else pose[0, :3, 3]
    seeded = _exact(chain, target, walked)
    if seeded.success and kept:
        return seeded.q
    try:
        fresh = _reach(chain, target, walked, field, shown)
    except InvalidInputError:
        if seeded.success:
            return seeded.q
        raise
    polished = _exact(chain, target, fresh)
    return polished.q if polished.success else fresh


def _exact(chain: Chain, target: np.ndarray, seed: np.ndarray) -> IKResult:
    """``rc.ik`` from one seed to the path tolerance, joint ranges aside."""
    return ik(
        chain.robot,
        target,
        q0=seed,
        mode=chain.mode,
        seeds=1,
        respect_limits=False,
        tol=PATH_TOL,
        orientation_tol=PATH_TOL,
    )


def _cartesian(
    chain: Chain, move: LIN | CIRC, q0: np.ndarray, limits: Limits
) -> tuple[np.ndarray, Profile, CartesianPath, Knots]:
    path, field, goal = _path(chain, move, q0)
    profile = _path_profile(path, move, chain, limits)
    u = np.linspace(0.0, 1.0, knot_count(path, chain.length) + 1)
    q, kept = track(chain, path, q0, u)
    q[-1] = _end(chain, path, q[-1], kept, field, one_line(goal))
    return q[-1].copy(), profile, path, make_knots(chain, path, u, q)


def _check_time(i: int, move: Move, profile: Profile, limits: Limits) -> None:
    """Refuse a move whose time law overflowed or runs past ``MAX_TIME``, naming the
    speed or acceleration that sets it: the move's own (``moves[i].speed``) or the
    program's (``cartesian_speed``, ``joint_speed``, …)."""
    rate = "accel" if 2.0 * profile.blend >= profile.duration > 0.0 else "speed"
    own = isinstance(move, (LIN, CIRC)) and getattr(move, rate) is not None
    if own:
        field, value = rate, getattr(move, rate)
    elif isinstance(move, Wait):
        field, value, own = "seconds", move.seconds, True
    else:
        field = ("joint_" if isinstance(move, PTP) else "cartesian_") + rate
        setting = getattr(limits, field)
        value = tuple(setting.tolist()) if isinstance(setting, np.ndarray) else setting
    what = f"move {i + 1} ({move.kind})"
    try:
        check_duration(profile.duration, (profile.speed, profile.accel), field, value, what)
    except InvalidInputError as error:
        raise (error.within(f"moves[{i}]") if own else error) from None


def plan(chain: Chain, moves: Sequence[Move], start: np.ndarray, limits: Limits) -> list[Segment]:
    """Plan every move in turn from ``start``; errors are named ``moves[i].field``."""
    segments: list[Segment] = []
    q0, t = start, 0.0
    point0 = _ee(chain, q0)[:3, 3]
    for i, move in enumerate(moves):
        path: CartesianPath | None = None
        knots: Knots | None = None
        try:
            if isinstance(move, PTP):
                q1, profile = _ptp(chain, move, q0, limits)
            elif isinstance(move, Wait):
                q1, profile = q0, still(move.seconds)
            elif isinstance(move, (LIN, CIRC)):
                q1, profile, path, knots = _cartesian(chain, move, q0, limits)
            else:  # pragma: no cover - Program checks the types
                raise TypeError(type(move).__name__)
        except InvalidInputError as error:
            raise error.within(f"moves[{i}]") from None
        _check_time(i, move, profile, limits)
        point1 = _ee(chain, q1)[:3, 3]
        via = np.array(move.via) if isinstance(move, CIRC) else None
        ends = (q0, q1, point0, point1)
        segments.append(
            Segment(i, move.kind, t, profile.duration, *ends, profile, path, via, knots)
        )
        q0, t, point0 = q1, t + profile.duration, point1
    check_duration(t, (), "moves", f"<{len(moves)} moves>", "the program")
    return segments
