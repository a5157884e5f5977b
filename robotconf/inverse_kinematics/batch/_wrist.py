"""The 6R arms over T targets: spherical wrist (:mod:`..closed_form._spherical_wrist`) and
UR (:mod:`..closed_form._ur`).

Eight branches per target, in the one-target solvers' loop order: shoulder × elbow ×
wrist for the spherical wrist, shoulder × wrist × elbow for the UR.
"""

from __future__ import annotations

import numpy as np

from ..closed_form._elbow import offset_reason
from ..closed_form._planar import any_perpendicular
from ..closed_form._spherical_wrist import WRIST_CANNOT_BEND
from ..closed_form._ur import closest_on
from ..geometry._chain_axes import ChainAxes, common_point
from ._arm import ELBOW_UP_DOWN, SHOULDER_WORDS, elbow_turns_many, elbow_up, shoulder_turns_many
from ._branches import Branches, FirstReason, label_table
from ._plane import plane_words
from ._vectors import NONE, TANGENT, TWO, angle_about, bend_angles, rotate, rotations, turn_vectors

__all__ = ["solve_spherical_wrist_many", "solve_ur_many", "WRIST_WORDS"]

#: Wrist words by code: 0 for the root that is not the larger one.
WRIST_WORDS = ("wrist flip", "wrist no flip")

_MEET = "the point where axes 5 and 6 meet"
_WRIST = "the wrist point (on axis 4, nearest axis 5)"


def _transpose(matrices: np.ndarray) -> np.ndarray:
    return matrices.transpose(0, 2, 1)


def _arm_turn(chain: ChainAxes, q1: np.ndarray, q2: np.ndarray, q3: np.ndarray) -> np.ndarray:
    """``R₁ R₂ R₃`` of the first three joints, (T, 3, 3)."""
    a, b, c = chain.joints[:3]
    return rotations(a.direction, q1) @ rotations(b.direction, q2) @ rotations(c.direction, q3)


def _rest_angle(axis: np.ndarray, rest: np.ndarray) -> np.ndarray:
    """The angle of each ``rest`` (T, 3, 3), a rotation about the unit ``axis``."""
    x = any_perpendicular(axis)
    angle, fixed = angle_about(axis, x, turn_vectors(rest, x), 0.0)
    return np.where(fixed, angle, 0.0)


def _wrist_codes(roots_angles: np.ndarray) -> np.ndarray:
    """1 ("no flip") for the larger of the two roots, per target and root (T, 2)."""
    larger = np.max(roots_angles, axis=1, keepdims=True)
    return (roots_angles == larger).astype(int)


def solve_spherical_wrist_many(
    chain: ChainAxes, points: np.ndarray, rotation: np.ndarray | None, family: str
) -> Branches:
    """Every branch of a spherical-wrist 6R arm for target poses (T, 3) and (T, 3, 3)."""
    assert rotation is not None
    count = len(points)
    w4, w5, w6 = (joint.direction for joint in chain.joints[3:])
    p0, r0 = chain.home[:3, 3], chain.home[:3, :3]
    turn = rotation @ r0.T
    centre, _ = common_point(chain.joints[3:])
    goal = points + turn_vectors(turn, centre - p0)
    what = "the wrist centre"
    reasons = FirstReason(count)
    shoulders = shoulder_turns_many(chain, centre, goal)
    reasons.offer(
        shoulders.failed,
        lambda t: offset_reason(what, float(shoulders.across[t]), shoulders.offset),
    )
    values = np.zeros((count, 8, 6))
    valid = np.zeros((count, 8), dtype=bool)
    codes = np.zeros((count, 8), dtype=int)
    degenerate = shoulders.degenerate.copy()
    for i in range(2):
        q1 = shoulders.q1[:, i]
        plane = elbow_turns_many(chain, q1, centre, goal)
        reasons.offer(shoulders.solved & plane.failed, plane_words(plane, what, "axis 2"))
        placed = shoulders.solved & plane.solved
        degenerate |= shoulders.solved & plane.degenerate
        for j in range(2):
            q2, q3 = plane.first[:, j], plane.second[:, j]
            up = elbow_up(chain, q1, q2, centre, goal)
            relative = _transpose(_arm_turn(chain, q1, q2, q3)) @ turn
            aim = turn_vectors(relative, w6)
            roots = bend_angles(w4, w5, w6, aim)
            reasons.offer(placed & (roots.kind == NONE), lambda t: WRIST_CANNOT_BEND)
            bent = placed & (roots.kind == TWO)
            degenerate |= placed & (roots.kind == TANGENT)
            wrist = _wrist_codes(roots.angles)
            for k in range(2):
                q5 = roots.angles[:, k]
                q4, fixed = angle_about(w4, rotate(w5, q5, w6), aim, 1e-13)
                degenerate |= bent & ~fixed
                rest = _transpose(rotations(w4, q4) @ rotations(w5, q5)) @ relative
                b = 4 * i + 2 * j + k
                values[:, b] = np.stack([q1, q2, q3, q4, q5, _rest_angle(w6, rest)], axis=1)
                valid[:, b] = bent
                codes[:, b] = (shoulders.words[:, i] * 2 + up) * 2 + wrist[:, k]
    table = label_table(SHOULDER_WORDS, ELBOW_UP_DOWN, WRIST_WORDS)
    return Branches(values, valid, table[codes], reasons.text, [()] * count, degenerate)


def solve_ur_many(
    chain: ChainAxes, points: np.ndarray, rotation: np.ndarray | None, family: str
) -> Branches:
    """Every branch of a UR-type arm for target poses (T, 3) and (T, 3, 3)."""
    assert rotation is not None
    count = len(points)
    joints = chain.joints
    w4, w5, w6 = (joint.direction for joint in joints[3:])
    p0, r0 = chain.home[:3, 3], chain.home[:3, :3]
    turn = rotation @ r0.T
    meet, _ = common_point(joints[4:])
    meet_goal = points + turn_vectors(turn, meet - p0)
    wrist = closest_on(chain, 3, 4)
    reasons = FirstReason(count)
    shoulders = shoulder_turns_many(chain, meet, meet_goal)
    reasons.offer(
        shoulders.failed,
        lambda t: offset_reason(_MEET, float(shoulders.across[t]), shoulders.offset),
    )
    values = np.zeros((count, 8, 6))
    valid = np.zeros((count, 8), dtype=bool)
    codes = np.zeros((count, 8), dtype=int)
    degenerate = shoulders.degenerate.copy()
    for i in range(2):
        q1 = shoulders.q1[:, i]
        relative = _transpose(rotations(joints[0].direction, q1)) @ turn
        roots = bend_angles(w4, w5, w6, turn_vectors(relative, w6))
        bent = shoulders.solved & (roots.kind == TWO)
        degenerate |= shoulders.solved & (roots.kind == TANGENT)
        flips = _wrist_codes(roots.angles)
        for k in range(2):
            q5 = roots.angles[:, k]
            q6, fixed = angle_about(
                w6, turn_vectors(_transpose(relative), w4), rotate(w5, -q5, w4), 1e-13
            )
            degenerate |= bent & ~fixed
            tilted = joints[4].point + rotate(w5, -q5, wrist - joints[4].point)
            back = joints[5].point + rotate(w6, -q6, tilted - joints[5].point)
            goal = points + turn_vectors(turn, back - p0)
            plane = elbow_turns_many(chain, q1, wrist, goal)
            reasons.offer(bent & plane.failed, plane_words(plane, _WRIST, "axis 2"))
            degenerate |= bent & plane.degenerate
            wrist_turn = _transpose(rotations(w5, q5) @ rotations(w6, q6))
            for j in range(2):
                q2, q3 = plane.first[:, j], plane.second[:, j]
                rest = _transpose(_arm_turn(chain, q1, q2, q3)) @ turn @ wrist_turn
                b = 4 * i + 2 * k + j
                values[:, b] = np.stack([q1, q2, q3, _rest_angle(w4, rest), q5, q6], axis=1)
                valid[:, b] = bent & plane.solved
                up = elbow_up(chain, q1, q2, wrist, goal)
                codes[:, b] = (shoulders.words[:, i] * 2 + up) * 2 + flips[:, k]
    table = label_table(SHOULDER_WORDS, ELBOW_UP_DOWN, WRIST_WORDS)
    return Branches(values, valid, table[codes], reasons.text, [()] * count, degenerate)
