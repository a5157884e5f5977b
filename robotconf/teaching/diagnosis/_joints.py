"""The right matrix at the wrong configuration: q = 0, one joint left out, two exchanged.

An answer worked out at the parking pose q = 0, one joint's angle forgotten (as if the
joint stood at 0), the values of two joints exchanged, or — for a DH table at numeric q
— degrees fed to sin and cos for the joint angles only (or for the table's constant
angles only), while the rest is right. These are rebuilt by changing the configuration
(or the angles' units) of an otherwise right derivation.
"""

from __future__ import annotations

from itertools import combinations

import numpy as np

from ...kinematics import DHLink, joint_axes
from ._candidate import Candidate, fmt, vector
from ._context import MistakeContext

__all__ = ["joint_candidates"]


def _joint_words(context: MistakeContext, j: int) -> str:
    link = context.robot.modules[j]
    kind = f"DH row, joint {link.joint}" if isinstance(link, DHLink) else getattr(link, "kind", "")
    return f"joint {j + 1} (module M{j + 1}, {kind})"


def _moving(context: MistakeContext, joints: list[int]) -> list[int]:
    """The joints whose value matters: not held at 0 by the exercise."""
    if not context.numeric_q:
        return joints
    return [j for j in joints if np.any(context.q[:, j] != 0)]


def _parking(context: MistakeContext, moving: list[int]) -> Candidate:
    names = [context.robot.coordinate_names[j] for j in moving]
    if context.numeric_q:
        message = (
            "Your numbers are those of the parking pose q = 0 (every joint at 0), but this "
            f"exercise asks for q = {vector(context.q[0])}: put the joint values in."
        )
    else:
        message = (
            "Your answer is the matrix at the parking pose q = 0 (every joint at 0): keep "
            f"{', '.join(names)} as symbols — the exercise asks for the matrix at any q."
        )
    q = context.q.copy()
    q[:, moving] = 0.0
    return Candidate(
        "parking_pose", message, context.value(q=q), "working at the parking pose q = 0"
    )


def _left_out(context: MistakeContext, j: int) -> Candidate:
    name = context.robot.coordinate_names[j]
    if context.numeric_q:
        message = (
            f"Your numbers are what you get with {name} = 0: {_joint_words(context, j)} was "
            f"left out — here it stands at {name} = {fmt(context.q[0, j])}."
        )
    else:
        message = (
            f"{name} is missing from your answer: it is what you get with {name} = 0, as if "
            f"{_joint_words(context, j)} did not move — each joint's coordinate enters every "
            "matrix from its own module on."
        )
    q = context.q.copy()
    q[:, j] = 0.0
    return Candidate("joint_left_out", message, context.value(q=q), f"leaving {name} out")


def _exchanged(context: MistakeContext, i: int, j: int) -> Candidate:
    first, second = context.robot.coordinate_names[i], context.robot.coordinate_names[j]
    message = (
        f"{first} and {second} are exchanged: your answer is what you get with the two joint "
        f"values swapped — module M{i + 1} moves by {first}, module M{j + 1} by {second}."
    )
    q = context.q.copy()
    q[:, [i, j]] = q[:, [j, i]]
    reading = f"exchanging {first} and {second}"
    return Candidate("swapped_joints", message, context.value(q=q), reading)


def _absolute(context: MistakeContext, moving: list[int]) -> list[Candidate]:
    """A joint angle used as the link's angle against the base, where it is relative to
    the previous joint about a parallel axis (q3 read as the forearm's own angle)."""
    robot = context.robot
    axes = joint_axes(robot, np.zeros(robot.n)).direction
    revolute = [j for j in moving if robot.joint_types[j] == "revolute"]
    found = []
    for i, j in zip(revolute, revolute[1:], strict=False):
        if abs(abs(float(axes[i] @ axes[j])) - 1.0) > 1e-9:
            continue
        names = robot.coordinate_names
        message = (
            f"{names[j]} is used as an absolute angle: joint {j + 1} turns relative to "
            f"link {i + 1} (their axes are parallel), so the link after it points at "
            f"{names[i]} + {names[j]} — the angles add up along the chain."
        )
        q = context.q.copy()
        q[:, j] = context.q[:, j] - context.q[:, i]
        reading = f"taking {names[j]} as the link's angle against the base"
        found.append(Candidate("absolute_angle", message, context.value(q=q), reading))
    return found


def _dh_degrees(context: MistakeContext, moving: list[int]) -> list[Candidate]:
    """Degrees for the joint angles only, or for the table's angles only (numeric q)."""
    robot = context.robot
    rows = [link for j in context.modules if isinstance(link := robot.modules[j], DHLink)]
    revolute = [j for j in moving if robot.modules[j].joint_type == "revolute"]
    constants = any(row.theta != 0 or row.alpha != 0 for row in rows)
    if not (context.numeric_q and revolute and constants):
        return []
    joints = (
        "Your numbers are what you get with the joint angles in degrees fed to sin and cos as "
        "if they were radians (the table's own angles are right). Convert first: "
        "radians = degrees × π/180."
    )
    table = (
        "Your numbers are what you get with the table's angles θ and α in degrees fed to sin "
        "and cos as if they were radians (the joint angles are right). Convert first: "
        "radians = degrees × π/180."
    )
    return [
        Candidate(
            "degrees_as_radians",
            joints,
            context.value(units="degrees", angles="joints"),
            "feeding the joint angles in degrees to sin and cos",
        ),
        Candidate(
            "degrees_as_radians",
            table,
            context.value(units="degrees", angles="constants"),
            "feeding the table's angles in degrees to sin and cos",
        ),
    ]


def joint_candidates(context: MistakeContext) -> list[Candidate]:
    """Wrong configurations: q = 0, one joint at 0, two joints exchanged; DH degrees.

    Parameters
    ----------
    context : MistakeContext

    Returns
    -------
    list of Candidate
        Codes ``"parking_pose"``, ``"joint_left_out"`` (only where it differs from the
        parking pose: two or more joints move), ``"swapped_joints"`` (two joints of one
        type with different values) and ``"degrees_as_radians"``.

    Examples
    --------
    >>> from robotconf.kinematics import Module, Robot
    >>> from robotconf.teaching import expected_matrix, sample_points
    >>> robot = Robot([Module("Rz"), Module("Ry", a=(0, 0, 20))], end_effector=(40, 0, 0))
    >>> reference = expected_matrix(robot, "p_EE", q=[0.5, 0.0])
    >>> context = MistakeContext(reference, sample_points(["q1", "q2"], 2, 0), 2)
    >>> [c.code for c in joint_candidates(context)]  # q2 = 0 already: no joint_left_out
    ['parking_pose', 'swapped_joints']
    """
    moving = _moving(context, context.joints())
    if not moving:
        return []
    candidates = [_parking(context, moving)]
    if len(moving) >= 2:
        candidates += [_left_out(context, j) for j in moving]
    types = context.robot.joint_types
    for i, j in combinations(context.joints(), 2):
        if types[i] != types[j]:  # radians are no lengths
            continue
        if not context.numeric_q or np.any(context.q[:, i] != context.q[:, j]):
            candidates.append(_exchanged(context, i, j))
    if context.numeric_q:
        candidates += _absolute(context, moving)
    return candidates + _dh_degrees(context, moving)
