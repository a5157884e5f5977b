"""The column, shoulder and elbow of an elbow arm over T targets (:mod:`..closed_form._elbow`).

The 3R elbow arm is solved here; the 6R arms (:mod:`._wrist`) place their wrist with the
same three functions.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..closed_form._elbow import offset_reason
from ..geometry._chain_axes import ChainAxes
from ..geometry._subproblems import cross as cross_one
from ..geometry._subproblems import perp as perp_one
from ..geometry._subproblems import unit
from ._branches import Branches, FirstReason, label_table
from ._plane import PlaneMany, place_in_plane_many, plane_words
from ._vectors import FREE, NONE, TANGENT, TWO, cross, dot, norm, perp, rotate, solve_cos_sin

__all__ = [
    "Shoulders",
    "SHOULDER_WORDS",
    "ELBOW_UP_DOWN",
    "shoulder_turns_many",
    "elbow_turns_many",
    "elbow_up",
    "solve_elbow_many",
]

#: Shoulder words by code (:func:`shoulder_turns_many`), elbow words by ``elbow_up``.
SHOULDER_WORDS = ("shoulder left", "shoulder right", "shoulder back", "shoulder front")
ELBOW_UP_DOWN = ("elbow down", "elbow up")


class Shoulders(NamedTuple):
    """The column angles ``q₁`` (T, 2), their shoulder word codes (T, 2), which targets
    have both (``solved``), none (``failed``: ``offset_reason`` with ``across``) or a
    degenerate case (``degenerate``: a double root, or the point on axis 1)."""

    q1: np.ndarray
    words: np.ndarray
    solved: np.ndarray
    failed: np.ndarray
    degenerate: np.ndarray
    across: np.ndarray
    offset: float


def _forward(chain: ChainAxes, q1: np.ndarray, start: np.ndarray) -> np.ndarray:
    """The column's forward direction at each ``q₁`` (see the one-target twin)."""
    column, arm = chain.joints[0], chain.joints[1]
    ahead = perp_one(arm.direction, perp_one(column.direction, start - column.point))
    if np.linalg.norm(ahead) <= 1e-9 * chain.scale:
        ahead = cross_one(arm.direction, column.direction)
    return rotate(column.direction, q1, unit(ahead))


def shoulder_turns_many(chain: ChainAxes, start: np.ndarray, targets: np.ndarray) -> Shoulders:
    """The column angles that bring each target into the arm's plane, and their labels."""
    column, arm = chain.joints[0], chain.joints[1]
    w, x = column.direction, arm.direction
    offset = float(x @ (start - column.point))
    reach = targets - column.point
    along = dot(reach, w) * float(w @ x)
    roots = solve_cos_sin(
        dot(reach, x) - along, dot(reach, cross_one(w, x)), offset - along, chain.scale
    )
    flat = perp(w, reach)
    words = np.empty(roots.angles.shape, dtype=int)
    for i in range(2):
        q1 = roots.angles[:, i]
        if abs(offset) > 1e-9 * chain.scale:
            side = offset * rotate(w, q1, x)
            words[:, i] = (dot(side, cross(flat, w)) > 0).astype(int)
        else:
            words[:, i] = 2 + (dot(_forward(chain, q1, start), flat) >= 0).astype(int)
    return Shoulders(
        q1=roots.angles,
        words=words,
        solved=roots.kind == TWO,
        failed=roots.kind == NONE,
        degenerate=(roots.kind == TANGENT) | (roots.kind == FREE),
        across=norm(flat),
        offset=offset,
    )


def elbow_turns_many(
    chain: ChainAxes, q1: np.ndarray, start: np.ndarray, targets: np.ndarray
) -> PlaneMany:
    """Shoulder and elbow angles once the column is at ``q₁`` (T,)."""
    column = chain.joints[0]
    back = column.point + rotate(column.direction, -q1, targets - column.point)
    return place_in_plane_many(chain.joints[1], chain.joints[2], start, back)


def elbow_up(
    chain: ChainAxes, q1: np.ndarray, shoulder: np.ndarray, start: np.ndarray, targets: np.ndarray
) -> np.ndarray:
    """Whether the elbow is above the line from the shoulder to the target (T,) bool;
    ``shoulder`` is joint 2's angle (see the one-target ``elbow_label``)."""
    column, second, third = chain.joints[:3]
    normal = rotate(column.direction, q1, second.direction)
    pivot = column.point + rotate(column.direction, q1, second.point - column.point)
    bent = second.point + rotate(second.direction, shoulder, third.point - second.point)
    elbow = column.point + rotate(column.direction, q1, bent - column.point)
    line = perp(normal, targets - pivot)
    line = line / np.maximum(norm(line), 1e-300)[:, np.newaxis]
    up = perp(line, perp(normal, column.direction))
    small = norm(up) < 1e-9
    if small.any():
        ahead = _forward(chain, q1[small], start)
        up[small] = perp(line[small], perp(normal[small], ahead))
    return dot(up, elbow - pivot) > 0


def solve_elbow_many(
    chain: ChainAxes, points: np.ndarray, rotation: np.ndarray | None, family: str
) -> Branches:
    """:func:`~robotconf.inverse_kinematics.closed_form._elbow.solve_elbow` for T targets (points
    (T, 3)): four branches, shoulder slowest."""
    count = len(points)
    start = chain.home[:3, 3]
    what = "the target"
    reasons = FirstReason(count)
    shoulders = shoulder_turns_many(chain, start, points)
    reasons.offer(
        shoulders.failed,
        lambda t: offset_reason(what, float(shoulders.across[t]), shoulders.offset),
    )
    values = np.zeros((count, 4, 3))
    valid = np.zeros((count, 4), dtype=bool)
    codes = np.zeros((count, 4), dtype=int)
    degenerate = shoulders.degenerate.copy()
    for i in range(2):
        q1 = shoulders.q1[:, i]
        plane = elbow_turns_many(chain, q1, start, points)
        failed = shoulders.solved & plane.failed
        reasons.offer(failed, plane_words(plane, what, "axis 2"))
        degenerate |= shoulders.solved & plane.degenerate
        for j in range(2):
            b = 2 * i + j
            values[:, b] = np.stack([q1, plane.first[:, j], plane.second[:, j]], axis=1)
            valid[:, b] = shoulders.solved & plane.solved
            up = elbow_up(chain, q1, plane.first[:, j], start, points)
            codes[:, b] = shoulders.words[:, i] * 2 + up
    table = label_table(SHOULDER_WORDS, ELBOW_UP_DOWN)
    return Branches(values, valid, table[codes], reasons.text, [()] * count, degenerate)
