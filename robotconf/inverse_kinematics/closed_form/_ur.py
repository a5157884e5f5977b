"""Universal Robots-type arms: axes 2 ∥ 3 ∥ 4, axes 5 and 6 meeting; up to eight solutions.

The standard analytic method (K. P. Hawkins, "Analytic Inverse Kinematics for the
Universal Robots UR-5/UR-10 Arms", Georgia Tech 2013), written with the joint lines so it
holds for any such geometry, in the order the unknowns come free:

1. ``q₁``: the point ``s`` where axes 5 and 6 meet is fixed in the end-effector frame and
   moved by joints 1-4 only; turns about the parallel axes 2-4 keep its height along
   ``w₂``, which gives the column angle as for an elbow arm (shoulder left/right).
2. ``q₅``: those turns also keep the angle between axis 6 and ``w₂``, so ``q₅`` must bend
   axis 6 to the angle that the target's axis 6 (turned back by ``−q₁``) makes with
   ``w₂``: two roots, mirror images about the wrist singularity (axis 6 ∥ axes 2-4).
3. ``q₆``: with ``R₁ᵀ R_t R₀ᵀ = R₂₃₄ R₅ R₆`` and ``R₂₃₄`` a turn about ``w₂``,
   ``w₂ᵀ R₁ᵀ R_t R₀ᵀ = w₂ᵀ R₅ R₆`` fixes ``q₆`` (unless at the singularity).
4. ``q₂, q₃``: a point ``o`` on axis 4 is moved by joints 1-3 only, and its target is
   ``T_t M₀⁻¹ e^{−ξ₆q₆} e^{−ξ₅q₅} o``: the two-link problem of axes 2 and 3 (elbow up/down).
5. ``q₄``: the rest of the turn about ``w₄``.
"""

from __future__ import annotations

import numpy as np

from ..geometry._chain_axes import ChainAxes, common_point
from ..geometry._subproblems import angle_about, bend_angles, cross, rotate, rotation
from ._elbow import elbow_label, elbow_turns, shoulder_label, shoulder_turns
from ._solutions import Candidates
from ._spherical_wrist import rest_angle, singular_note, wrist_label

__all__ = ["solve_ur", "closest_on"]

_MEET = "the point where axes 5 and 6 meet"
_WRIST = "the wrist point (on axis 4, nearest axis 5)"


def closest_on(chain: ChainAxes, k: int, other: int) -> np.ndarray:
    """The point of joint line ``k`` closest to joint line ``other``, shape (3,)."""
    a, b = chain.joints[k], chain.joints[other]
    across = cross(a.direction, b.direction)
    # The plane through line b containing the common normal cuts line a at its closest point.
    normal = cross(b.direction, across)
    t = float(normal @ (b.point - a.point)) / float(normal @ a.direction)
    return a.point + t * a.direction


def solve_ur(
    chain: ChainAxes, point: np.ndarray, rotation_t: np.ndarray | None, family: str
) -> Candidates:
    """Every solution for a UR-type arm and a target pose (up to eight).

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
    >>> ur5 = rc.preset("ur5")
    >>> pose = ur5.end_effector_pose([0.1, -1.2, 1.3, 0.4, 0.5, 0.6])
    >>> len(solve_ur(chain_axes(ur5), pose[:3, 3], pose[:3, :3], "").rows)
    8
    """
    assert rotation_t is not None
    out = Candidates()
    joints = chain.joints
    w4, w5, w6 = (joint.direction for joint in joints[3:])
    p0, r0 = chain.home[:3, 3], chain.home[:3, :3]
    turn = rotation_t @ r0.T
    meet, _ = common_point(joints[4:])
    meet_goal = point + turn @ (meet - p0)
    wrist = closest_on(chain, 3, 4)
    for q1, free in shoulder_turns(chain, meet, meet_goal, _MEET, out):
        shoulder = shoulder_label(chain, q1, free, meet, meet_goal)
        relative = joints[0].turn(q1).T @ turn
        roots = bend_angles(w4, w5, w6, relative @ w6)
        for q5 in roots.angles:
            if roots.kind == "tangent":
                q6 = chain.current(5)
                out.note(singular_note(chain, 3, 5, 5))
            else:
                found = angle_about(w6, relative.T @ w4, rotate(w5, -q5, w4), 1e-13)
                q6 = chain.current(5) if found is None else found
            back = joints[5].move(-q6, joints[4].move(-q5, wrist))
            goal = point + turn @ (back - p0)
            for placement in elbow_turns(chain, q1, wrist, goal, _WRIST, out):
                arm = [q1, placement.first, placement.second]
                rest = chain.turn(arm).T @ turn @ (rotation(w5, q5) @ rotation(w6, q6)).T
                q4 = rest_angle(w4, rest)
                elbow = elbow_label(chain, q1, placement, wrist, goal)
                label = f"{shoulder}, {elbow}, {wrist_label(roots, q5)}"
                out.rows.append(([*arm, q4, q5, q6], label))
    return out
