"""Planar 2R/3R arms and SCARAs over T targets (:mod:`..closed_form._planar`).

:func:`place_in_plane_many` is the two-link problem of two parallel axes, which the elbow
arms reuse for their shoulder and elbow; :func:`solve_planar_many` is the planar family.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import NamedTuple

import numpy as np

from ..closed_form._planar import (
    ELBOW_WORDS,
    any_perpendicular,
    free_last_note,
    level_point,
    off_plane_reason,
    plane_reason,
    tilted_reason,
)
from ..geometry._chain_axes import AxisJoint, ChainAxes
from ..geometry._subproblems import cross as cross_one
from ..geometry._subproblems import perp as perp_one
from ._branches import Branches, FirstReason
from ._vectors import (
    FREE,
    NONE,
    TANGENT,
    TWO,
    angle_about,
    cross,
    dot,
    norm,
    perp,
    rotate,
    rotations,
    solve_cos_sin,
    turn_vectors,
)

__all__ = ["PlaneMany", "place_in_plane_many", "plane_words", "solve_planar_many"]


class PlaneMany(NamedTuple):
    """The two-link problem for T targets.

    ``first``, ``second`` (T, 2): the joints' angles, both branches in the one-target
    order; ``clockwise`` (T, 2) the elbow's side; ``solved`` (T,) both branches found;
    ``failed`` (T,) none (``plane_reason`` with ``r`` (T,), ``l1``, ``l2`` says why);
    ``degenerate`` (T,) a double root or a target on the first axis.
    """

    first: np.ndarray
    second: np.ndarray
    clockwise: np.ndarray
    solved: np.ndarray
    failed: np.ndarray
    degenerate: np.ndarray
    r: np.ndarray
    l1: float
    l2: float


def plane_words(plane: PlaneMany, what: str, from_axis: str) -> Callable[[int], str]:
    """Why target ``t`` has no placement: :func:`plane_reason` with its distance."""

    def words(t: int) -> str:
        return plane_reason(what, from_axis, float(plane.r[t]), plane.l1, plane.l2)

    return words


def place_in_plane_many(
    first: AxisJoint, second: AxisJoint, start: np.ndarray, target: np.ndarray
) -> PlaneMany:
    """:func:`~robotconf.inverse_kinematics.closed_form._planar.place_in_plane` for targets (T, 3).

    >>> z = np.array([0.0, 0.0, 1.0])
    >>> a = AxisJoint(0, "R", np.zeros(3), z)
    >>> b = AxisJoint(1, "R", np.array([1.0, 0.0, 0.0]), z)
    >>> found = place_in_plane_many(a, b, np.array([2.0, 0, 0]), np.array([[1.0, 1, 0]]))
    >>> found.first.round(6) + 0.0, found.second.round(6), found.clockwise
    (array([[0.      , 1.570796]]), array([[ 1.570796, -1.570796]]), array([[ True, False]]))
    """
    w, w2 = first.direction, second.direction
    u = perp_one(w, first.point - second.point)
    v = perp_one(w, start - second.point)
    aim = perp(w, target - first.point)
    l1, l2 = float(np.linalg.norm(u)), float(np.linalg.norm(v))
    r = norm(aim)
    size = l1 + l2 + r
    along = float(u @ w2) * float(w2 @ v)
    level = (l1 * l1 + l2 * l2 - r * r) / 2
    roots = solve_cos_sin(float(u @ v) - along, float(u @ cross_one(w2, v)), level - along, l1 * l2)
    keys = -np.sin(roots.angles)
    angles = np.where((keys[:, 1] < keys[:, 0])[:, np.newaxis], roots.angles[:, ::-1], roots.angles)
    turns = np.empty_like(angles)
    clockwise = np.empty(angles.shape, dtype=bool)
    fixed = np.ones(len(target), dtype=bool)
    for j in range(2):
        moved = second.point + rotate(w2, angles[:, j], start - second.point)
        turns[:, j], ok = angle_about(w, moved - first.point, aim, 1e-12 * size)
        fixed &= ok
        elbow = first.point + rotate(w, turns[:, j], second.point - first.point)
        clockwise[:, j] = dot(w, cross(elbow - first.point, target - first.point)) > 0
    two = roots.kind == TWO
    return PlaneMany(
        first=turns,
        second=angles,
        clockwise=clockwise,
        solved=two & fixed,
        failed=(roots.kind == NONE) | (roots.kind == FREE),
        degenerate=(roots.kind == TANGENT) | (two & ~fixed),
        r=r,
        l1=l1,
        l2=l2,
    )


def solve_planar_many(
    chain: ChainAxes, points: np.ndarray, rotation: np.ndarray | None, family: str
) -> Branches:
    """:func:`~robotconf.inverse_kinematics.closed_form._planar.solve_planar` for T targets: points
    (T, 3) and rotations (T, 3, 3) or None; two branches per target."""
    count = len(points)
    joints = chain.joints
    revolute = [k for k, joint in enumerate(joints) if joint.kind == "R"]
    slides = [k for k, joint in enumerate(joints) if joint.kind == "P"]
    first, second = joints[revolute[0]], joints[revolute[1]]
    last = joints[revolute[2]] if len(revolute) == 3 else None
    w = first.direction
    p0, r0 = chain.home[:3, 3], chain.home[:3, :3]
    size = np.maximum(chain.scale, norm(points))
    reasons = FirstReason(count)
    start, goal, turn = p0, points, None
    if last is not None:
        start = level_point(chain, last)
        if rotation is None:
            goal = points + (start - p0)
        else:
            turn = rotation @ r0.T
            tw = turn_vectors(turn, w)
            tilt = np.arctan2(norm(cross(w, tw)), dot(w, tw))
            reasons.offer(tilt > 1e-9, lambda t: tilted_reason(float(tilt[t])))
            goal = points + turn_vectors(turn, start - p0)
    height = dot(w, goal - start)
    slide = np.zeros(count)
    if slides:
        direction = joints[slides[0]].direction
        slide = height / float(w @ direction)
        goal = goal - slide[:, np.newaxis] * direction
    else:
        off = np.abs(height) > 1e-9 * size
        reasons.offer(off, lambda t: off_plane_reason(float(height[t])))
    blocked = reasons.given.copy()
    what = "the target" if last is None else "the point of the last axis"
    plane = place_in_plane_many(first, second, start, goal)
    reasons.offer(plane.failed, plane_words(plane, what, "the first axis"))
    values = np.zeros((count, 2, len(joints)))
    values[:, :, revolute[0]] = plane.first
    values[:, :, revolute[1]] = plane.second
    if slides:
        values[:, :, slides[0]] = slide[:, np.newaxis]
    valid = np.repeat((plane.solved & ~blocked)[:, np.newaxis], 2, axis=1)
    words = ELBOW_WORDS["SCARA" if family == "SCARA" else "planar"]
    table = np.array([words["counterclockwise"], words["clockwise"]], dtype=object)
    notes: list[tuple[str, ...]] = [()] * count
    if last is not None:
        k = joints.index(last)
        if turn is None:
            values[:, :, k] = chain.current(k)
            note = (free_last_note(last.column),)
            notes = [note if ok else () for ok in valid[:, 0].tolist()]
        else:
            for j in range(2):
                values[:, j, k] = _last_angles(chain, last, k, values[:, j], turn)
    return Branches(
        values, valid, table[plane.clockwise.astype(int)], reasons.text, notes,
        plane.degenerate & ~blocked,
    )  # fmt: skip


def _last_angles(
    chain: ChainAxes, last: AxisJoint, k: int, values: np.ndarray, turn: np.ndarray
) -> np.ndarray:
    """The third revolute joint: the rest of the turn about the axes, (T,)."""
    rest = np.broadcast_to(np.eye(3), turn.shape).copy()
    for i, joint in enumerate(chain.joints[:k]):
        if joint.kind == "R":
            rest = rest @ rotations(joint.direction, values[:, i])
    rest = rest.transpose(0, 2, 1) @ turn
    x = any_perpendicular(last.direction)
    angle, fixed = angle_about(last.direction, x, turn_vectors(rest, x), 0.0)
    return np.where(fixed, angle, 0.0)
