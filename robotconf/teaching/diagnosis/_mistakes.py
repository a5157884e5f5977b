"""The usual mistakes in hand-derived kinematics, rebuilt as "wrong answers" to compare with.

Each :class:`Candidate` is what a student would have written after making one specific
mistake, evaluated at the same sample points as the expected matrix, together with the
sentence that explains the mistake. The checker recognises a mistake when the student's
wrong entries agree with a candidate, and ranks the candidates that do
(:mod:`robotconf.teaching.diagnosis._ranking`).

Context-aware candidates need the robot and the matrix name (an
:class:`~robotconf.teaching.ExpectedMatrix` from ``expected_matrix`` or a derivation
step). This file holds the single slips in one named module or step: wrong rotation
direction of one module, offset after the rotation, a missing offset or end-effector
point, the other DH convention, degrees read as radians (and the reverse), multiplication
in the wrong order, and for a DH row the twist α with the wrong sign or d and a swapped.
The other families have files of their own: the same slip in every module of a kind
(``_mistakes_compound``), the wrong configuration (``_mistakes_joints``), lengths in the
wrong unit and the point's homogeneous coordinate (``_mistakes_lengths``), and the
context-free transposes and swaps (``_mistakes_generic``).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ...kinematics import DHLink, dh_formula
from ..derivation._expected import ExpectedMatrix
from ._candidate import ROTATION_PATTERN, Candidate, module_label, vector
from ._compound import compound_candidates
from ._context import LINK_CODES, MistakeContext, link_mistakes
from ._generic import generic_candidates, is_rotation_like
from ._joints import joint_candidates
from ._lengths import point_candidates, unit_candidates

__all__ = [
    "Candidate",
    "context_candidates",
    "generic_candidates",
    "is_rotation_like",
    "link_message",
    "ROTATION_PATTERN",
]


def link_message(code: str, j: int, link: Any) -> tuple[str, str]:
    """The hint for one link mistake of module ``j`` (1-based), and its short reading.

    Parameters
    ----------
    code : str
        One of :func:`~robotconf.teaching.diagnosis._context.link_mistakes`.
    j : int
    link : Module or DHLink

    Returns
    -------
    message, reading : str

    Examples
    --------
    >>> from robotconf.kinematics import Module
    >>> link_message("missing_offset", 2, Module("Ry", a=(0, 0, 20)))[1]
    'leaving out the offset of A2'
    """
    label = module_label(j, link)
    if code == "rotation_direction":
        axis = link.axis
        return (
            f"The sine terms of {label} have the wrong sign, so the joint turns the wrong way: "
            f"a positive rotation about {axis} has {ROTATION_PATTERN[axis]}.",
            f"turning A{j} the other way (its sines flipped)",
        )
    if code == "offset_after_rotation":
        return (
            f"In {label} the offset is applied after the rotation (Rot·Trans) instead of "
            "before it (Trans·Rot): a module first moves its origin by a in the parent frame, "
            "then rotates, so the last column of its matrix is just (ax, ay, az).",
            f"applying the offset of A{j} after its rotation",
        )
    if code == "missing_offset":
        return (
            f"The offset of {label} is missing: every module first translates by its "
            "a = (ax, ay, az) in the parent frame — put it in the last column of its matrix.",
            f"leaving out the offset of A{j}",
        )
    if code == "missing_d":
        return (
            f"The link offset d of {label} is missing: Tz(d) moves along z by d.",
            f"leaving out d of A{j}",
        )
    if code == "alpha_sign":
        return (
            f"The twist α of {label} has the wrong sign: α is the angle from the old z axis "
            "to the new one, measured about x by the right-hand rule, and Rx(α) has −sin α "
            "in entry (2,3) and +sin α in entry (3,2).",
            f"giving the twist α of A{j} the wrong sign",
        )
    if code == "swapped_d_a":
        return (
            f"The link offset d and the link length a of {label} are swapped: d is the "
            "distance along z (Tz(d)), a the distance along x (Tx(a)).",
            f"swapping d and a of A{j}",
        )
    return (
        f"The link length a of {label} is missing: Tx(a) moves along x by a.",
        f"leaving out a of A{j}",
    )


def _named_candidates(context: MistakeContext) -> list[Candidate]:
    """Single slips in one named module, in the order the ranking prefers on a tie."""
    robot, name = context.robot, context.name
    candidates = []
    for j in context.modules:
        link = robot.modules[j]
        for mistake in link_mistakes(link):
            message, reading = link_message(mistake, j + 1, link)
            code = LINK_CODES.get(mistake, mistake)
            values = context.value({j: mistake})
            candidates.append(Candidate(code, message, values, reading))
    dh_links = [j for j in context.modules if isinstance(robot.modules[j], DHLink)]
    if dh_links:
        convention = robot.modules[dh_links[0]].convention  # type: ignore[attr-defined]
        other = "modified" if convention == "standard" else "standard"
        message = (
            f"You used the {other} DH convention ({dh_formula(other)}) but this table is "
            f"{convention} DH ({dh_formula(convention)}); multiply the four factors in that "
            "order."
        )
        values = context.value(dict.fromkeys(dh_links, "convention"))
        reading = f"using the {other} DH convention"
        candidates.append(Candidate("dh_convention", message, values, reading))
    revolute = any(robot.modules[j].joint_type == "revolute" for j in context.modules)
    if revolute and (context.numeric_q or dh_links):
        message = (
            "Your numbers are what you get with angles in degrees fed to sin and cos as if "
            "they were radians (calculator in radian mode). Convert first: "
            "radians = degrees × π/180."
        )
        values = context.value(units="degrees")
        reading = "feeding angles in degrees to sin and cos"
        candidates.append(Candidate("degrees_as_radians", message, values, reading))
    if revolute and context.numeric_q:
        message = (
            "Your numbers are what you get with a calculator in degree mode: the angles here "
            "are in radians, so switch it to radian mode (or convert: degrees = rad × 180/π)."
        )
        values = context.value(units="radians")
        reading = "a calculator in degree mode"
        candidates.append(Candidate("radians_as_degrees", message, values, reading))
    index = context.expected.index or 1
    if name.startswith("M") and index >= 2 or name == "p_EE" and robot.n >= 2:
        count = index if name.startswith("M") else robot.n
        wrong, right = ("A2·A1", "A1·A2") if count == 2 else (f"A{count}·…·A1", f"A1·…·A{count}")
        message = (
            f"You multiplied in the wrong order ({wrong} instead of {right}): "
            "M_i = M_(i-1)·A_i — each new transfer matrix goes on the right, because it is "
            "written in the frame of the module before it."
        )
        values = context.value(reverse=True)
        reading = f"multiplying in the wrong order ({wrong})"
        candidates.append(Candidate("wrong_order", message, values, reading))
    return candidates


def _point_missing(context: MistakeContext) -> list[Candidate]:
    robot = context.robot
    if context.name != "p_EE" or not any(robot.end_effector_point):
        return []
    message = (
        f"The end-effector point P = {vector(robot.end_effector_point)} is "
        f"missing: p_EE = M{robot.n}·[Px, Py, Pz, 1]ᵀ, not the origin of the last frame."
    )
    values = context.value(point=np.zeros(3))
    return [Candidate("missing_offset", message, values, "leaving out the end-effector point P")]


def context_candidates(
    expected: ExpectedMatrix, env: dict[str, np.ndarray], k: int
) -> list[Candidate]:
    """Wrong answers from the mistakes that need to know the robot and the matrix.

    Parameters
    ----------
    expected : ExpectedMatrix
        With robot and name.
    env : dict of str to ndarray, shape (K,)
        Sample values of the symbols.
    k : int
        Number of sample points.

    Returns
    -------
    list of Candidate
        Single slips first (in the order the ranking prefers on a tie), then the same
        slip repeated in several modules; none without context.

    Examples
    --------
    >>> from robotconf.kinematics import Module, Robot
    >>> from robotconf.teaching import expected_matrix, sample_points
    >>> robot = Robot([Module("Rz"), Module("Ry", a=(0, 0, 20))], end_effector=(40, 0, 0))
    >>> env = sample_points(["q1", "q2"], 4, 0)
    >>> codes = [c.code for c in context_candidates(expected_matrix(robot, "A2"), env, 4)]
    >>> codes[:3]
    ['rotation_direction', 'offset_after_rotation', 'missing_offset']
    """
    if not expected.has_context:
        return []
    context = MistakeContext(expected, env, k)
    return [
        *_point_missing(context),
        *point_candidates(context),
        *_named_candidates(context),
        *joint_candidates(context),
        *unit_candidates(context),
        *compound_candidates(context),
    ]
