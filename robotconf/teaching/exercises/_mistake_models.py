"""The typical single slips of an exercise, as the answers they give.

An exercise's numbers must make every typical mistake visible: the checker refuses the
answer the slip gives. These builders rebuild the slips from the same models the
checkers diagnose with:

- a robot at a configuration (a pose matrix, a transfer matrix, the end-effector): the
  configuration slips — every joint at 0 (the parking pose), one joint left out, two
  exchanged, one turned the wrong way, a joint angle taken as absolute where it is
  relative to the previous parallel joint, degrees fed to sin and cos, a calculator in
  degree mode — and the matrix checker's own candidates (a module turned the other way,
  an offset after the rotation or missing, a transposed rotation, the wrong order, …);
- a number or a vector: the sign, degrees for radians, a factor of 1000 or 100 for a
  length, half a turn for an angle;
- a DH table: each row with one of the usual repairs undone (α's sign, a and d swapped,
  a θ offset forgotten, …).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ...kinematics import Robot, jacobian, joint_axes
from ..checks._dh_table_text import parse_dh_rows
from ..derivation._expected import ExpectedMatrix, sample_points
from ..diagnosis._mistakes import context_candidates, generic_candidates

__all__ = [
    "component_slips",
    "configuration_hints",
    "configuration_slips",
    "dh_table_slips",
    "matrix_at",
    "matrix_slips",
]


def matrix_at(robot: Robot, step: str, q: Any) -> np.ndarray:
    """The numbers of step ``A<i>``, ``M<i>``, ``p_EE`` (as ``[x, y, z]``) at ``q``, or of
    the linear Jacobian ``J`` (rows x, y, z) or ``J2`` (rows x, y)."""
    if step == "p_EE":
        return np.asarray(robot.end_effector(q), dtype=float)
    if step.startswith("J"):
        rows = int(step[1:] or 3)
        return np.asarray(jacobian(robot, q)[:rows], dtype=float)
    index = int(step[1:]) - 1
    if step[0] == "A":
        return np.asarray(robot.transfer_matrices(q)[index], dtype=float)
    return np.asarray(robot.frame_poses(q)[index], dtype=float)


def _parallel_to_previous(robot: Robot) -> list[tuple[int, int]]:
    """(j, i): revolute joint j whose axis is parallel to the previous revolute joint i."""
    axes = joint_axes(robot, np.zeros(robot.n)).direction
    revolute = [j for j, kind in enumerate(robot.joint_types) if kind == "revolute"]
    pairs = []
    for i, j in zip(revolute, revolute[1:], strict=False):
        if abs(abs(float(axes[i] @ axes[j])) - 1.0) < 1e-9:
            pairs.append((j, i))
    return pairs


def configuration_slips(
    robot: Robot, q: Sequence[float], free: Sequence[int] | None = None
) -> dict[str, np.ndarray]:
    """The configurations the usual slips put in place of ``q``.

    ``free`` lists the 0-based joints the exercise sets (default: every joint); the
    others stand where the task puts them (a PUMA link asked at q = (0, q2, 0, …)), so
    no slip concerns them.

    Returns
    -------
    dict of str to ndarray, shape (n,)
        ``"parking_pose"``, ``"joint_left_out[q2]"``, ``"sign_error[q2]"``,
        ``"swapped_joints[q1,q2]"``, ``"absolute_angle[q3]"``, ``"degrees_as_radians"``
        and ``"radians_as_degrees"`` (the last two for revolute joints only).

    Examples
    --------
    >>> from robotconf.kinematics import Module
    >>> arm = Robot([Module("Rz"), Module("Rz", a=(1, 0, 0))], end_effector=(1, 0, 0))
    >>> slips = configuration_slips(arm, [0.5, 0.25])
    >>> slips["absolute_angle[q2]"].tolist()  # q2 read as the second link's own angle
    [0.5, -0.25]
    """
    at = np.asarray(q, dtype=float)
    names = robot.coordinate_names
    types = robot.joint_types
    moving = [j for j in range(robot.active) if types[j] in ("revolute", "prismatic")]
    if free is not None:
        moving = [j for j in moving if j in free]
    found: dict[str, np.ndarray] = {"parking_pose": np.zeros_like(at)}
    for j in moving:
        left_out = at.copy()
        left_out[j] = 0.0
        found[f"joint_left_out[{names[j]}]"] = left_out
        turned = at.copy()
        turned[j] = -at[j]
        found[f"sign_error[{names[j]}]"] = turned
    for a, i in enumerate(moving):
        for j in moving[a + 1 :]:
            if types[i] == types[j]:
                swapped = at.copy()
                swapped[[i, j]] = at[[j, i]]
                found[f"swapped_joints[{names[i]},{names[j]}]"] = swapped
    for j, i in _parallel_to_previous(robot):
        if j not in moving or i not in moving:
            continue
        absolute = at.copy()
        absolute[j] = at[j] - at[i]
        found[f"absolute_angle[{names[j]}]"] = absolute
    revolute = np.array([t == "revolute" and j in moving for j, t in enumerate(types)])
    if revolute.any():
        found["degrees_as_radians"] = np.where(revolute, np.degrees(at), at)
        found["radians_as_degrees"] = np.where(revolute, np.radians(at), at)
    return found


def matrix_slips(
    robot: Robot, step: str, q: Sequence[float], free: Sequence[int] | None = None
) -> dict[str, np.ndarray]:
    """The answers the usual slips give for step ``step`` of ``robot`` at ``q``.

    The configuration slips (:func:`configuration_slips`, for the ``free`` joints) and
    the matrix checker's own candidate mistakes for the step (a module turned the other
    way, Rot·Trans, a missing offset or end-effector point, a transposed rotation, the
    product in the wrong order, …), each as the numbers the student would write
    (``[x, y, z]`` for ``p_EE``). A slip that gives the right answer whatever the free
    joints (turning a module the task holds at 0) is no slip of this exercise: it is
    left out, judged at a generic value of the free joints.

    Examples
    --------
    >>> import robotconf as rc
    >>> slips = matrix_slips(rc.preset("paper"), "p_EE", [0.5, 0.0, -0.5])
    >>> "absolute_angle[q3]" in slips and "missing_offset" in slips
    True
    """
    at = [float(x) for x in q]
    generic = list(at)
    for k, j in enumerate(range(robot.n) if free is None else free):
        generic[j] = _GENERIC[k % len(_GENERIC)] * (
            1.0 if robot.joint_types[j] == "revolute" else 7.0
        )
    found = _slips_at(robot, step, at, free)
    key = (repr(robot), step, None if free is None else tuple(free))
    if key not in _APPLICABLE:
        usual = _slips_at(robot, step, generic, free)
        right = matrix_at(robot, step, generic)
        _APPLICABLE[key] = {
            code for code, values in usual.items() if not np.allclose(values, right, rtol=1e-6)
        }
    return {code: values for code, values in found.items() if code in _APPLICABLE[key]}


#: The slips that change the answer of a robot's step, by robot, step and free joints.
_APPLICABLE: dict[tuple[str, str, tuple[int, ...] | None], set[str]] = {}


#: Generic values of the free joints (no multiple of 90°, no two alike).
_GENERIC = (0.7, -1.1, 0.4, 1.3, -0.6, 0.9)


def _slips_at(
    robot: Robot, step: str, q: list[float], free: Sequence[int] | None
) -> dict[str, np.ndarray]:
    configurations = configuration_slips(robot, q, free)
    codes = list(configurations)
    if step == "p_EE" and codes:  # one batched forward kinematics for every slip
        points = np.asarray(robot.end_effector(np.array([configurations[c] for c in codes])))
        found = dict(zip(codes, points, strict=True))
    else:
        found = {code: matrix_at(robot, step, configurations[code]) for code in codes}
    names = list(robot.coordinate_names)
    env = sample_points(names, 1, 0)
    if step.startswith("J"):  # a bare matrix: the context-free candidates only
        expected = matrix_at(robot, step, q)[None]
        candidates = generic_candidates(expected)
    else:
        # The candidates read the robot, the step and the pose only: no sympy matrix.
        reference = ExpectedMatrix(None, step, robot, tuple(float(x) for x in q))
        values = matrix_at(robot, step, q)
        if step == "p_EE":
            values = np.append(values, 1.0).reshape(4, 1)
        expected = values[None]
        candidates = context_candidates(reference, env, 1) + generic_candidates(expected)
    for candidate in candidates:
        values = np.asarray(candidate.values, dtype=float)[0]
        if step == "p_EE":
            if candidate.code == "row_swap" and "and 4" in candidate.reading:
                continue  # the point's homogeneous 1 is no row of a typed [x, y, z]
            values = values.reshape(-1)[:3]
        found.setdefault(candidate.code, values)
        if not np.allclose(values, found[candidate.code]):
            found[f"{candidate.code}[{candidate.reading or len(found)}]"] = values
    return found


def component_slips(
    expected: Any, *, angle: bool = False, length: bool = True
) -> dict[str, np.ndarray]:
    """The answers the usual slips of a number or a vector give.

    ``"sign_error"`` (the whole answer, and each component alone for a vector),
    ``"degrees_as_radians"`` for an angle, ``"unit_factor×1000"`` and its reciprocal
    for a length, ``"half_turn"`` for an angle.

    >>> sorted(component_slips(2.0, angle=True))
    ['degrees_as_radians', 'half_turn', 'sign_error']
    """
    value = np.asarray(expected, dtype=float)
    found: dict[str, np.ndarray] = {"sign_error": -value}
    if value.ndim == 1 and value.size > 1:
        for k in range(value.size):
            if value[k] != 0:
                one = value.copy()
                one[k] = -one[k]
                found[f"sign_error[{k + 1}]"] = one
    if angle:
        found["degrees_as_radians"] = np.degrees(value)
        found["half_turn"] = value + math.pi
    elif length:
        for factor in (1000, 100):
            found[f"unit_factor×{factor}"] = value * factor
            found[f"unit_factor÷{factor}"] = value / factor
    return found


def dh_table_slips(rows: Any) -> dict[str, list[tuple[Any, ...]]]:
    """The tables the usual single-row slips give, from a right table ``rows``.

    ``rows`` is read as :func:`~robotconf.teaching.parse_dh_rows` reads an answer; each
    slip is a table of ``(θ offset, d offset, a, α, joint)`` rows with one row changed:
    α's sign, a and d swapped, the sign of a or d, the θ offset forgotten, a constant of
    d or a forgotten (a height, a slide's start, a link length). A slip that leaves the
    row as it was is not listed.

    >>> slips = dh_table_slips([("q1", 0, 30, 0), ("q2", 0, 20, 0)])
    >>> slips["swapped_a_d[1]"][0]
    (0.0, 30.0, 0.0, 0.0, 'R')
    """
    parsed = parse_dh_rows(rows).rows
    found: dict[str, list[tuple[Any, ...]]] = {}
    for r, (theta, d, a, alpha, joint) in enumerate(parsed):
        changes = {
            "alpha_sign": (theta, d, a, -alpha),
            "swapped_a_d": (theta, a, d, alpha),
            "a_sign": (theta, d, -a, alpha),
            "d_sign": (theta, -d, a, alpha),
            "theta_offset": (0.0, d, a, alpha),
            "d_value": (theta, 0.0, a, alpha),
            "a_value": (theta, d, 0.0, alpha),
        }
        for code, row in changes.items():
            new = (*(float(x) + 0.0 for x in row), joint)
            if new != parsed[r]:
                found[f"{code}[{r + 1}]"] = [
                    new if k == r else parsed[k] for k in range(len(parsed))
                ]
    return found


def _show(values: Any) -> str:
    return "(" + ", ".join(f"{float(v):.4g}" for v in np.asarray(values).reshape(-1)) + ")"


def configuration_hints(
    robot: Robot, q: Sequence[float], free: Sequence[int] | None = None
) -> dict[str, tuple[np.ndarray, str]]:
    """The configuration slips at ``q`` with the hint that names each, by slip name.

    The keys are :func:`configuration_slips`' (``"joint_left_out[q2]"``); the code before
    the bracket is the matrix checker's (a joint turned the wrong way is
    ``rotation_direction``). A matrix exercise names these when the checker's own
    candidates do not explain the answer (a bare Jacobian has none of them).

    >>> import robotconf as rc
    >>> hints = configuration_hints(rc.preset("paper"), [0.5, 0.2, -0.4])
    >>> hints["joint_left_out[q2]"][1][:44]
    'Your numbers are what you get with q2 = 0: j'
    """
    names = robot.coordinate_names
    at = np.asarray(q, dtype=float)
    found: dict[str, tuple[np.ndarray, str]] = {}
    for key, values in configuration_slips(robot, q, free).items():
        code, _, inside = key.partition("[")
        joints = inside.rstrip("]").split(",") if inside else []
        if code == "parking_pose":
            hint = (
                "Your numbers are those of the parking pose q = 0 (every joint at 0), but "
                f"this exercise asks for q = {_show(at)}: put the joint values in."
            )
        elif code == "joint_left_out":
            j = names.index(joints[0])
            hint = (
                f"Your numbers are what you get with {joints[0]} = 0: joint {j + 1} was left "
                f"out — here it stands at {joints[0]} = {at[j]:.4g}."
            )
        elif code == "sign_error":
            code = "rotation_direction"
            hint = (
                f"Your numbers are what you get with −{joints[0]}: joint "
                f"{names.index(joints[0]) + 1} turned the wrong way — a positive "
                f"{joints[0]} turns it counterclockwise about its axis."
            )
        elif code == "swapped_joints":
            hint = (
                f"{joints[0]} and {joints[1]} are exchanged: your numbers are what you get "
                "with the two joint values swapped."
            )
        elif code == "absolute_angle":
            hint = (
                f"{joints[0]} is used as an absolute angle: the joint turns relative to the "
                "link before it (their axes are parallel), so the angles add up along the "
                "chain."
            )
        elif code == "degrees_as_radians":
            hint = (
                "Your numbers are what you get with angles in degrees fed to sin and cos as "
                "if they were radians: convert first, radians = degrees × π/180."
            )
        else:  # radians_as_degrees
            hint = (
                "Your numbers are what you get with a calculator in degree mode: the angles "
                "here are in radians, so switch it to radian mode."
            )
        found[key] = (values, hint)
    return found
