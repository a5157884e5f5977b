"""Closed forms for parallel revolute axes: planar 2R and 3R arms and SCARAs.

All revolute axes point along ``w`` (the first axis); a prismatic joint, if any, slides
along ``w`` as well. A slide along ``w`` commutes with every turn about a line parallel to
``w``, so it only sets the height along ``w``: ``q_P = w·(x_t − x₀) / (w·w_P)``. What is
left is the two-link problem in the plane (:func:`place_in_plane`): with the first two
axes at ``a₁``, ``a₂`` and the point at ``x₀`` (all seen along ``w``), the elbow angle
keeps the distance ``r = |x_t − a₁|``,

.. math::

    |a_2 + R(q_2)(x_0 - a_2) - a_1| = r
    \\iff (a_1 - a_2)\\cdot R(q_2)(x_0 - a_2) = \\tfrac12(l_1^2 + l_2^2 - r^2),

(law of cosines, ``l₁ = |a₂ − a₁|``, ``l₂ = |x₀ − a₂|``), two angles or none, and the first
joint turns the result onto the target. A third revolute joint (planar 3R, SCARA RRPR)
turns about its own axis: the point ``x₀`` is taken on that axis, which the target pose
places, and the joint takes the rest of the turn about ``w``.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..geometry._chain_axes import AxisJoint, ChainAxes
from ..geometry._subproblems import angle_about, cross, perp, turn_to_level
from ._solutions import Candidates

__all__ = [
    "ELBOW_WORDS",
    "PlanePlacement",
    "place_in_plane",
    "plane_reason",
    "tilted_reason",
    "off_plane_reason",
    "free_first_note",
    "free_last_note",
    "solve_planar",
    "level_point",
    "any_perpendicular",
]

#: The labels of the two elbow branches: the elbow on the clockwise or counterclockwise
#: side of the line from the first axis to the target, seen with the first axis pointing
#: at the viewer.
ELBOW_WORDS = {
    "planar": {"clockwise": "elbow down", "counterclockwise": "elbow up"},
    "SCARA": {"clockwise": "elbow right", "counterclockwise": "elbow left"},
}


class PlanePlacement(NamedTuple):
    """One solution of the two-link problem in a plane.

    ``shape`` is ``"clockwise"`` or ``"counterclockwise"`` (the elbow's side of the line
    from the first axis to the target, seen with the first axis pointing at the viewer),
    ``"straight"`` or ``"folded"`` (on that line: the two branches coincide). ``free``:
    the target is on the first axis, so the first angle is the joint's current value.
    """

    first: float
    second: float
    shape: str
    free: bool


def any_perpendicular(w: np.ndarray) -> np.ndarray:
    """A unit vector perpendicular to the unit vector ``w``.

    >>> any_perpendicular(np.array([0.0, 0.0, 1.0]))
    array([1., 0., 0.])
    """
    basis = np.eye(3)[int(np.argmin(np.abs(w)))]
    v = perp(w, basis)
    return v / float(np.linalg.norm(v))


def place_in_plane(
    first: AxisJoint,
    second: AxisJoint,
    start: np.ndarray,
    target: np.ndarray,
    current: float,
    what: str,
    from_axis: str,
) -> tuple[list[PlanePlacement], str]:
    """Turn two parallel revolute joints so that the point ``start`` lands on ``target``.

    Parameters
    ----------
    first, second : AxisJoint
        Parallel revolute joints, in chain order.
    start : ndarray, shape (3,)
        The point at the joints' zero (moved by both).
    target : ndarray, shape (3,)
        Where it must go; only its part across the axes counts.
    current : float
        The first joint's value to keep when the target lies on its axis.
    what, from_axis : str
        Words for the message when it cannot: ``"the target"``, ``"axis 1"``.

    Returns
    -------
    placements : list of PlanePlacement
        Two, one (straight or folded elbow) or none.
    reason : str
        Why there is none (the distance beyond the reach or inside the inner limit).

    Examples
    --------
    >>> z = np.array([0.0, 0.0, 1.0])
    >>> a = AxisJoint(0, "R", np.zeros(3), z)
    >>> b = AxisJoint(1, "R", np.array([1.0, 0.0, 0.0]), z)
    >>> found, _ = place_in_plane(a, b, np.array([2.0, 0, 0]), np.array([1.0, 1, 0]), 0, "", "")
    >>> [(round(p.first, 6), round(p.second, 6), p.shape) for p in found]
    [(0.0, 1.570796, 'clockwise'), (1.570796, -1.570796, 'counterclockwise')]
    """
    w = first.direction
    u = perp(w, first.point - second.point)
    v = perp(w, start - second.point)
    aim = perp(w, target - first.point)
    l1, l2, r = (float(np.linalg.norm(x)) for x in (u, v, aim))
    size = l1 + l2 + r
    roots = turn_to_level(second.direction, v, u, (l1 * l1 + l2 * l2 - r * r) / 2, l1 * l2)
    if roots.kind in ("none", "free"):
        return [], plane_reason(what, from_axis, r, l1, l2)
    found = []
    for angle in sorted(roots.angles, key=lambda x: -math.sin(x)):
        moved = second.move(angle, start)
        turn = angle_about(w, moved - first.point, aim, 1e-12 * size)
        free = turn is None
        first_angle = current if turn is None else turn
        elbow = first.move(first_angle, second.point)
        if roots.kind == "tangent":
            shape = "folded" if roots.ratio > 0 else "straight"
        else:
            side = float(w @ cross(elbow - first.point, target - first.point))
            shape = "clockwise" if side > 0 else "counterclockwise"
        found.append(PlanePlacement(first_angle, angle, shape, free))
    return found, ""


def plane_reason(what: str, from_axis: str, r: float, l1: float, l2: float) -> str:
    """Why two links of lengths ``l1``, ``l2`` cannot span the distance ``r``.

    >>> plane_reason("the target", "the first axis", 74.2, 40.0, 30.0)
    'the target is 4.2 beyond the reach: it is 74.2 from the first axis, and the arm reaches 70'
    """
    reach, inner = l1 + l2, abs(l1 - l2)
    if r > reach:
        return (
            f"{what} is {r - reach:.6g} beyond the reach: it is {r:.6g} from {from_axis}, "
            f"and the arm reaches {reach:.6g}"
        )
    return (
        f"{what} is {inner - r:.6g} too close: it is {r:.6g} from {from_axis}, and the "
        f"arm reaches no closer than {inner:.6g}"
    )


def tilted_reason(tilt: float) -> str:
    """Why a planar arm cannot take a target orientation tilted ``tilt`` rad out of plane."""
    return (
        f"the target orientation is tilted {math.degrees(tilt):.6g}° out of the "
        "arm's plane: the arm turns only about its parallel axes"
    )


def off_plane_reason(height: float) -> str:
    """Why a planar arm cannot reach a target ``height`` off its plane."""
    return (
        f"the target is {abs(height):.6g} off the plane the arm moves in (measured along its axes)"
    )


def free_first_note(column: int) -> str:
    """The note for a target on the first axis (its joint ``q{column + 1}`` is free)."""
    return f"the target is on the first axis, so q{column + 1} is free: shown at its current value"


def free_last_note(column: int) -> str:
    """The note for a point target when the end-effector lies on the last axis."""
    return (
        f"the end-effector lies on the last axis, so a point leaves q{column + 1} "
        "free: shown at its current value (give angle= or a (4, 4) pose to set it)"
    )


def level_point(chain: ChainAxes, last: AxisJoint) -> np.ndarray:
    """The point of the last revolute axis at the height of the end-effector."""
    p0 = chain.home[:3, 3]
    return last.point + last.direction * float(last.direction @ (p0 - last.point))


def solve_planar(
    chain: ChainAxes, point: np.ndarray, rotation: np.ndarray | None, family: str
) -> Candidates:
    """Every solution for a planar 2R/3R arm or a SCARA (see the module docstring).

    Parameters
    ----------
    chain : ChainAxes
    point : ndarray, shape (3,)
        The end-effector target.
    rotation : ndarray, shape (3, 3), or None
        The target orientation; ``None`` for a point (with three revolute joints only
        when the end-effector lies on the last axis, which is then free).
    family : str
        ``"planar 2R"``, ``"planar 3R"`` or ``"SCARA"`` (for the labels).

    Returns
    -------
    Candidates
    """
    out = Candidates()
    joints = chain.joints
    revolute = [k for k, joint in enumerate(joints) if joint.kind == "R"]
    slides = [k for k, joint in enumerate(joints) if joint.kind == "P"]
    first, second = joints[revolute[0]], joints[revolute[1]]
    last = joints[revolute[2]] if len(revolute) == 3 else None
    w = first.direction
    p0, r0 = chain.home[:3, 3], chain.home[:3, :3]
    size = max(chain.scale, float(np.linalg.norm(point)))
    start, goal, turn = p0, point, None
    if last is not None:
        start = level_point(chain, last)
        if rotation is None:
            goal = point + (start - p0)
        else:
            turn = rotation @ r0.T
            tilt = math.atan2(float(np.linalg.norm(cross(w, turn @ w))), float(w @ turn @ w))
            if tilt > 1e-9:
                out.reason = tilted_reason(tilt)
                return out
            goal = point + turn @ (start - p0)
    height = float(w @ (goal - start))
    slide = 0.0
    if slides:
        direction = joints[slides[0]].direction
        slide = height / float(w @ direction)
        goal = goal - slide * direction
    elif abs(height) > 1e-9 * size:
        out.reason = off_plane_reason(height)
        return out
    what = "the target" if last is None else "the point of the last axis"
    found, out.reason = place_in_plane(
        first, second, start, goal, chain.current(revolute[0]), what, "the first axis"
    )
    words = ELBOW_WORDS["SCARA" if family == "SCARA" else "planar"]
    for placement in found:
        values = [0.0] * len(joints)
        values[revolute[0]], values[revolute[1]] = placement.first, placement.second
        if slides:
            values[slides[0]] = slide
        label = words.get(placement.shape, f"elbow {placement.shape}")
        if placement.free:
            out.note(free_first_note(first.column))
            label += ", first joint free"
        if last is not None:
            values[revolute[2]] = _last_angle(chain, last, values, turn, out)
        out.rows.append((values, label))
    return out


def _last_angle(
    chain: ChainAxes,
    last: AxisJoint,
    values: list[float],
    turn: np.ndarray | None,
    out: Candidates,
) -> float:
    """The third revolute joint: the rest of the turn about the axes (or its own value)."""
    k = chain.joints.index(last)
    if turn is None:
        out.note(free_last_note(last.column))
        return chain.current(k)
    rest = chain.turn(values[:k]).T @ turn
    x = any_perpendicular(last.direction)
    angle = angle_about(last.direction, x, rest @ x, 0.0)
    return 0.0 if angle is None else angle
