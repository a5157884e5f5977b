"""The first three joints of an elbow arm: a turning column, then a shoulder and an elbow.

Axes 2 and 3 are parallel, so the arm's links move in a plane across them that the
column (axis 1) turns. Turns about axes 2 and 3 keep every point's height along ``w₂``,
measured from a point of axis 1: for the point ``x₀`` that must reach ``x_t``,

.. math::

    (x_t - p_1) \\cdot R(w_1, q_1)\\, w_2 = w_2 \\cdot (x_0 - p_1),

an equation ``a cos q₁ + b sin q₁ = c`` with two roots (the shoulder on either side), one
(the point on the offset's circle) or none (closer to axis 1 than the shoulder offset
allows). Turning the target back by ``−q₁`` leaves the two-link problem of axes 2 and 3
(:func:`._planar.place_in_plane`): up to 2 × 2 = 4 solutions. The PUMA's
``d₃`` and the UR's ``d₄`` are such offsets; for the paper's R_zR_yR_y it is 0.
"""

from __future__ import annotations

import numpy as np

from ..geometry._chain_axes import ChainAxes
from ..geometry._subproblems import cross, perp, turn_to_level, unit
from ._planar import PlanePlacement, place_in_plane
from ._solutions import Candidates

__all__ = [
    "shoulder_turns",
    "elbow_turns",
    "offset_reason",
    "shoulder_label",
    "elbow_label",
    "solve_elbow",
]


def shoulder_turns(
    chain: ChainAxes, start: np.ndarray, target: np.ndarray, what: str, out: Candidates
) -> list[tuple[float, bool]]:
    """The column angles ``q₁`` that bring ``target`` into the arm's plane.

    Parameters
    ----------
    chain : ChainAxes
    start, target : ndarray, shape (3,)
        The point at q = 0 (moved by joints 1-3 only) and where it must go.
    what : str
        Its name, for the message when it cannot.
    out : Candidates
        Receives the reason (none) or the note (``q₁`` free: the target is on axis 1).

    Returns
    -------
    list of (float, bool)
        ``(q₁, free)`` pairs; ``free`` when ``q₁`` is the joint's current value because any
        value would do.
    """
    column, arm = chain.joints[0], chain.joints[1]
    offset = float(arm.direction @ (start - column.point))
    reach = target - column.point
    roots = turn_to_level(column.direction, arm.direction, reach, offset, chain.scale)
    if roots.kind == "free":
        out.note(
            f"{what} is on axis 1, so q{column.column + 1} is free: shown at its current value"
        )
        return [(chain.current(0), True)]
    if roots.kind == "none":
        across = float(np.linalg.norm(perp(column.direction, reach)))
        out.reason = offset_reason(what, across, offset)
        return []
    return [(angle, False) for angle in roots.angles]


def offset_reason(what: str, across: float, offset: float) -> str:
    """Why the column cannot bring a point ``across`` from axis 1 into the arm's plane."""
    return (
        f"{what} is {across:.6g} from axis 1, closer than the shoulder offset "
        f"{abs(offset):.6g} allows"
    )


def elbow_turns(
    chain: ChainAxes, q1: float, start: np.ndarray, target: np.ndarray, what: str, out: Candidates
) -> list[PlanePlacement]:
    """Shoulder and elbow angles that put ``start`` on ``target`` once the column is at ``q₁``."""
    back = chain.joints[0].move(-q1, target)
    found, reason = place_in_plane(
        chain.joints[1], chain.joints[2], start, back, chain.current(1), what, "axis 2"
    )
    if reason and not out.reason:
        out.reason = reason
    for placement in found:
        if placement.free:
            out.note(
                f"{what} is on axis 2, so q{chain.joints[1].column + 1} is free: shown at its "
                "current value"
            )
    return found


def _forward(chain: ChainAxes, q1: float, start: np.ndarray) -> np.ndarray:
    """The column's forward direction at ``q₁``: where the arm reaches at q = 0, level."""
    column, arm = chain.joints[0], chain.joints[1]
    ahead = perp(arm.direction, perp(column.direction, start - column.point))
    if np.linalg.norm(ahead) <= 1e-9 * chain.scale:
        ahead = cross(arm.direction, column.direction)
    return column.turn(q1) @ unit(ahead)


def shoulder_label(
    chain: ChainAxes, q1: float, free: bool, start: np.ndarray, target: np.ndarray
) -> str:
    """``shoulder left/right`` (arms with a shoulder offset) or ``front/back`` (without).

    Standing on axis 1 (pointing up) and facing ``target``: *right* when the arm's plane
    lies to the right of axis 1; without an offset, *front* when the target lies ahead of
    the column, the way the arm reaches at q = 0, and *back* when the arm reaches over.
    """
    if free:
        return "shoulder free"
    column, arm = chain.joints[0], chain.joints[1]
    offset = float(arm.direction @ (start - column.point))
    reach = perp(column.direction, target - column.point)
    if abs(offset) > 1e-9 * chain.scale:
        side = offset * (column.turn(q1) @ arm.direction)
        right = float(side @ cross(reach, column.direction)) > 0
        return "shoulder right" if right else "shoulder left"
    ahead = float(_forward(chain, q1, start) @ reach) >= 0
    return "shoulder front" if ahead else "shoulder back"


def elbow_label(
    chain: ChainAxes, q1: float, placement: PlanePlacement, start: np.ndarray, target: np.ndarray
) -> str:
    """``elbow up/down``: the elbow above or below the line from the shoulder to ``target``.

    "Above" is along axis 1 (when that line is vertical: ahead, the way the arm reaches at
    q = 0). ``elbow straight`` / ``elbow folded`` when the elbow is on the line.
    """
    if placement.shape in ("straight", "folded"):
        return f"elbow {placement.shape}"
    column = chain.joints[0]
    normal = column.turn(q1) @ chain.joints[1].direction
    shoulder = column.move(q1, chain.joints[1].point)
    elbow = chain.move([q1, placement.first], chain.joints[2].point)
    line = perp(normal, target - shoulder)
    line = line / max(float(np.linalg.norm(line)), 1e-300)
    up = perp(line, perp(normal, column.direction))
    if np.linalg.norm(up) < 1e-9:
        up = perp(line, perp(normal, _forward(chain, q1, start)))
    return "elbow up" if float(up @ (elbow - shoulder)) > 0 else "elbow down"


def solve_elbow(
    chain: ChainAxes, point: np.ndarray, rotation: np.ndarray | None, family: str
) -> Candidates:
    """Every solution for a 3R elbow arm (position only): up to four.

    >>> import robotconf as rc
    >>> from robotconf.inverse_kinematics.geometry._chain_axes import chain_axes
    >>> found = solve_elbow(chain_axes(rc.preset("paper")), np.array([0, 70, 20.0]), None, "")
    >>> [label for _, label in found.rows]
    ['shoulder front, elbow straight', 'shoulder back, elbow straight']
    """
    out = Candidates()
    start = chain.home[:3, 3]
    what = "the target"
    for q1, free in shoulder_turns(chain, start, point, what, out):
        for placement in elbow_turns(chain, q1, start, point, what, out):
            label = (
                f"{shoulder_label(chain, q1, free, start, point)}, "
                f"{elbow_label(chain, q1, placement, start, point)}"
            )
            out.rows.append(([q1, placement.first, placement.second], label))
    return out
