"""Six revolute joints with a spherical wrist (PUMA-like): up to eight solutions.

Axes 4, 5 and 6 meet at the wrist centre ``c``, which the wrist's turns leave in place,
so ``c`` is fixed in the end-effector frame: ``c_t = R_t R₀ᵀ (c₀ − p₀) + p_t``. The first
three joints place it (:mod:`._elbow`: shoulder × elbow, up to four ways); the wrist then
has to make up the rotation ``R_rel = (R₁R₂R₃)ᵀ R_t R₀ᵀ = R₄R₅R₆``:

- ``q₅`` bends axis 6 to the angle that ``R_rel w₆`` makes with axis 4 (turns about axis
  4 keep that angle; :func:`..geometry._subproblems.bend_angles`): two roots, mirror images about
  the position where axis 6 lines up with axis 4 (the wrist flip);
- ``q₄`` turns ``R₅ w₆`` onto ``R_rel w₆`` about axis 4;
- ``q₆`` is what remains, a turn about axis 6.

When axis 6 lines up with axis 4 (the wrist singularity, ``q₅ = 0`` for the PUMA), ``q₄``
and ``q₆`` turn about the same line and only their combination is fixed: the solution
keeps ``q₄`` at its current value.
"""

from __future__ import annotations

import numpy as np

from ..geometry._chain_axes import ChainAxes, common_point
from ..geometry._subproblems import Roots, angle_about, bend_angles, rotate, rotation
from ._elbow import elbow_label, elbow_turns, shoulder_label, shoulder_turns
from ._planar import any_perpendicular
from ._solutions import Candidates

__all__ = [
    "solve_spherical_wrist",
    "wrist_label",
    "rest_angle",
    "singular_note",
    "WRIST_CANNOT_BEND",
]

#: Why a wrist branch has no solution.
WRIST_CANNOT_BEND = (
    "the wrist cannot point axis 6 that way: the angle it must make with axis 4 is outside "
    "what axis 5 can bend"
)


def wrist_label(roots: Roots, q5: float) -> str:
    """``wrist no flip`` / ``wrist flip`` / ``wrist singular``.

    The two wrist solutions mirror each other about the position where axis 6 lines up
    with axis 4; *no flip* is the one turned positively (about axis 5) from it, which is
    ``q₅ > 0`` for the PUMA 560 and UR tables.
    """
    if roots.kind == "tangent":
        return "wrist singular"
    return "wrist no flip" if q5 == max(roots.angles) else "wrist flip"


def rest_angle(axis: np.ndarray, rest: np.ndarray) -> float:
    """The angle of ``rest``, a rotation about the unit ``axis``, shape (3, 3)."""
    x = any_perpendicular(axis)
    angle = angle_about(axis, x, rest @ x, 0.0)
    return 0.0 if angle is None else angle


def singular_note(chain: ChainAxes, first: int, second: int, free: int) -> str:
    """The note for a wrist singularity: which axes are in line and which joint is kept."""
    joints = chain.joints
    return (
        f"wrist singularity: axes {first + 1} and {second + 1} are in line, so only the "
        f"combined turn of q{joints[first].column + 1} and q{joints[second].column + 1} is "
        f"fixed; q{joints[free].column + 1} is shown at its current value"
    )


def solve_spherical_wrist(
    chain: ChainAxes, point: np.ndarray, rotation_t: np.ndarray | None, family: str
) -> Candidates:
    """Every solution for a spherical-wrist 6R arm and a target pose (up to eight).

    Parameters
    ----------
    chain : ChainAxes
    point : ndarray, shape (3,)
    rotation_t : ndarray, shape (3, 3)
        The target orientation (required).
    family : str

    Returns
    -------
    Candidates

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.inverse_kinematics.geometry._chain_axes import chain_axes
    >>> puma = rc.preset("puma560")
    >>> pose = puma.end_effector_pose([0.1, 0.2, -0.3, 0.4, 0.5, 0.6])
    >>> len(solve_spherical_wrist(chain_axes(puma), pose[:3, 3], pose[:3, :3], "").rows)
    8
    """
    assert rotation_t is not None
    out = Candidates()
    w4, w5, w6 = (joint.direction for joint in chain.joints[3:])
    p0, r0 = chain.home[:3, 3], chain.home[:3, :3]
    turn = rotation_t @ r0.T
    centre, _ = common_point(chain.joints[3:])
    goal = point + turn @ (centre - p0)
    what = "the wrist centre"
    for q1, free in shoulder_turns(chain, centre, goal, what, out):
        shoulder = shoulder_label(chain, q1, free, centre, goal)
        for placement in elbow_turns(chain, q1, centre, goal, what, out):
            arm = [q1, placement.first, placement.second]
            elbow = elbow_label(chain, q1, placement, centre, goal)
            relative = chain.turn(arm).T @ turn
            aim = relative @ w6
            roots = bend_angles(w4, w5, w6, aim)
            if roots.kind == "none":
                out.reason = out.reason or WRIST_CANNOT_BEND
                continue
            for q5 in roots.angles:
                q4 = angle_about(w4, rotate(w5, q5, w6), aim, 1e-13)
                if roots.kind == "tangent" or q4 is None:
                    q4 = chain.current(3)
                    out.note(singular_note(chain, 3, 5, 3))
                rest = (rotation(w4, q4) @ rotation(w5, q5)).T @ relative
                q6 = rest_angle(w6, rest)
                label = f"{shoulder}, {elbow}, {wrist_label(roots, q5)}"
                out.rows.append(([*arm, q4, q5, q6], label))
    return out
