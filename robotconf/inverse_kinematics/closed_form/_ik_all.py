"""``ik_all``: every closed-form inverse-kinematics solution of the classic arms.

The robot's family is read from its joint axes (:mod:`._recognize`); the family's solver
(:mod:`._planar`, :mod:`._elbow`, :mod:`._spherical_wrist`, :mod:`._ur`) lists its
branches; here every branch is written in the robot's coordinates, wrapped, checked by
forward kinematics, freed of duplicates and compared with the joint limits.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import as_float_array, check_finite_number, one_line
from ..geometry._chain_axes import ChainAxes
from ..geometry._subproblems import perp, rotation
from ._elbow import solve_elbow
from ._planar import solve_planar
from ._recognize import GAP_TOL, NotClosedForm, closed_form_structure, refuse
from ._solutions import Candidates, IKSolutions
from ._spherical_wrist import solve_spherical_wrist
from ._ur import solve_ur

__all__ = [
    "ik_all",
    "VERIFY_TOL",
    "SAME_TOL",
    "wrap_angles",
    "within_limits",
    "orientation_error",
    "failed_reason",
    "other_turn_note",
    "joint_kinds",
]

#: A solution's end-effector must match the target within this fraction of the robot's
#: size (and its orientation within this many radians).
VERIFY_TOL = 1e-9

#: Rows closer than this (radians, or a fraction of the size for slides) are one solution.
SAME_TOL = 1e-9

Solver = Callable[[ChainAxes, np.ndarray, np.ndarray | None, str], Candidates]

SOLVERS: dict[str, Solver] = {
    "planar 2R": solve_planar,
    "planar 3R": solve_planar,
    "SCARA": solve_planar,
    "3R elbow": solve_elbow,
    "spherical-wrist 6R": solve_spherical_wrist,
    "UR": solve_ur,
}

_TARGET = "a point (x, y, z), shape (3,), or a pose, a (4, 4) homogeneous matrix"


def _pose(value: Any, array: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Check a (4, 4) pose and return its point and (re-orthonormalized) rotation."""
    if not np.allclose(array[3], (0.0, 0.0, 0.0, 1.0), rtol=0.0, atol=1e-9):
        raise InvalidInputError(
            "target", one_line(value), _TARGET, problem="the last row of a pose is not 0 0 0 1:"
        )
    turn = array[:3, :3]
    if np.abs(turn.T @ turn - np.eye(3)).max() > 1e-6 or np.linalg.det(turn) < 0:
        raise InvalidInputError(
            "target",
            one_line(value),
            _TARGET + " whose 3×3 block is a rotation (orthonormal within 1e-6, det +1)",
            problem="not a rotation:",
        )
    u, _, vt = np.linalg.svd(turn)  # the nearest rotation, so round-off in a typed pose is forgiven
    return array[:3, 3].copy(), u @ vt


def _read_target(
    value: Any, angle: Any, chain: ChainAxes, family: str
) -> tuple[np.ndarray, np.ndarray | None]:
    array = as_float_array(value, "target", _TARGET)
    if array.shape not in ((3,), (4, 4)):
        raise InvalidInputError(
            "target",
            one_line(value),
            _TARGET,
            problem=f"expected shape (3,) or (4, 4), got {array.shape}:",
        )
    if not np.all(np.isfinite(array)):
        raise InvalidInputError("target", one_line(value), _TARGET, problem="not finite:")
    point, turn = (array.copy(), None) if array.shape == (3,) else _pose(value, array)
    revolute = [joint for joint in chain.joints if joint.kind == "R"]
    angled = family in ("planar 3R", "SCARA") and len(revolute) == 3
    if angle is not None:
        if not angled:
            raise InvalidInputError(
                "angle",
                one_line(angle),
                f"None for a {family} arm",
                problem="only planar 3R arms and 3-revolute SCARAs take an angle, got",
            )
        if turn is not None:
            raise InvalidInputError(
                "angle",
                one_line(angle),
                "None with a (4, 4) pose (its rotation is the angle)",
                problem="a pose already fixes the angle:",
            )
        phi = check_finite_number(angle, "angle")
        turn = rotation(revolute[0].direction, phi) @ chain.home[:3, :3]
    if turn is None and family in ("spherical-wrist 6R", "UR"):
        raise InvalidInputError(
            "target",
            one_line(value),
            f"a (4, 4) pose for a {family} arm",
            problem="a point leaves the orientation open:",
        )
    if turn is None and angled:
        last = revolute[2]
        off = float(np.linalg.norm(perp(last.direction, chain.home[:3, 3] - last.point)))
        if off > GAP_TOL * chain.scale:
            raise InvalidInputError(
                "target",
                one_line(value),
                f"a (4, 4) pose, or a point with angle=φ (the turn about the axes from q = 0) "
                f"for a {family} arm",
                problem="a point leaves the end-effector's angle open:",
            )
    return point, turn


def wrap_angles(values: np.ndarray) -> np.ndarray:
    """Angles wrapped to (−π, π].

    >>> wrap_angles(np.array([np.pi, -np.pi, 4.0])).round(6)
    array([ 3.141593,  3.141593, -2.283185])
    """
    return np.pi - np.mod(np.pi - values, 2 * np.pi)


def within_limits(
    q: np.ndarray, limits: np.ndarray, revolute: np.ndarray, solved: np.ndarray
) -> np.ndarray:
    """Whether each row of ``q`` (k, n) lies within ``limits`` (n, 2), a revolute angle
    counting as within when it or a whole turn away from it is; only ``solved`` columns
    count. Returns (k,) bool."""
    lo, hi = limits[:, 0], limits[:, 1]
    eps = 1e-12 * (1.0 + np.abs(limits).max(axis=1))
    turns = np.where(revolute, np.ceil((lo - eps - q) / (2 * np.pi)), 0.0)
    shifted = q + 2 * np.pi * turns
    ok = (shifted >= lo - eps) & (shifted <= hi + eps)
    return np.all(ok | ~solved, axis=-1)


def joint_kinds(chain: ChainAxes) -> tuple[np.ndarray, np.ndarray]:
    """Which of the robot's n coordinates are revolute joints of the chain, and which are
    solved (moving) at all: two (n,) bool arrays."""
    revolute = np.zeros(chain.robot.n, dtype=bool)
    solved = np.zeros(chain.robot.n, dtype=bool)
    for joint in chain.joints:
        solved[joint.column] = True
        revolute[joint.column] = joint.kind == "R"
    return revolute, solved


def orientation_error(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The angle between rotations, from ``‖A − B‖_F = 2√2 sin(θ/2)``, shape (k,)."""
    gap = np.linalg.norm(a - b, axis=(-2, -1)) / (2 * math.sqrt(2))
    return 2 * np.arcsin(np.clip(gap, 0.0, 1.0))


def _finish(
    chain: ChainAxes,
    family: str,
    point: np.ndarray,
    turn: np.ndarray | None,
    found: Candidates,
) -> IKSolutions:
    robot = chain.robot
    n = robot.n
    revolute, solved = joint_kinds(chain)
    rows = np.tile(chain.reference, (len(found.rows), 1))
    for i, (values, _) in enumerate(found.rows):
        for joint, value in zip(chain.joints, values, strict=True):
            rows[i, joint.column] = value
    rows[:, revolute] = wrap_angles(rows[:, revolute])
    labels = [label for _, label in found.rows]
    size = max(chain.scale, float(np.linalg.norm(point)))
    reason = found.reason
    keep = np.ones(len(rows), dtype=bool)
    other_turn = 0
    if len(rows):
        poses = robot.end_effector_pose(rows)
        near = np.linalg.norm(poses[:, :3, 3] - point, axis=1) <= VERIFY_TOL * size
        turned = np.zeros(len(rows)) if turn is None else orientation_error(poses[:, :3, :3], turn)
        keep = near & (turned <= VERIFY_TOL)
        other_turn = int(np.count_nonzero(near & ~keep))
        if not keep.any():
            reason = failed_reason(family, near, turned, poses, point)
    chosen: list[int] = []
    scale = np.where(revolute, 1.0, size)
    for i in map(int, np.flatnonzero(keep)):
        differ = [
            np.abs(np.where(revolute, wrap_angles(rows[i] - rows[j]), rows[i] - rows[j])) / scale
            for j in chosen
        ]
        if all(d.max() > SAME_TOL for d in differ):
            chosen.append(i)
    q = rows[chosen] if chosen else np.zeros((0, n))
    limits = robot.joint_limits()
    within = within_limits(q, limits, revolute, solved)
    if chosen:
        missing = [f"some branches have no solution: {reason}"] if reason else []
        if other_turn:
            missing.append(other_turn_note(other_turn, family))
        reason = "; ".join([*found.notes, *missing])
    return IKSolutions(q, tuple(labels[i] for i in chosen), within, family, reason)


def other_turn_note(count: int, family: str) -> str:
    """The note for ``count`` branches that reach the point with another orientation."""
    verb = "branches reach" if count > 1 else "branch reaches"
    return (
        f"{count} more {verb} the point with another orientation (a {family} arm does not set both)"
    )


def failed_reason(
    family: str, near: np.ndarray, turned: np.ndarray, poses: np.ndarray, point: np.ndarray
) -> str:
    """Why no branch passed the check: ``near`` (k,) which reach the point, ``turned`` (k,)
    how far their orientations are (rad), ``poses`` (k, 4, 4) where they end."""
    if near.any():
        off = math.degrees(float(turned[near].min()))
        return (
            f"the point is reachable, but a {family} arm cannot also give the target's "
            f"orientation: the nearest solution's orientation is {off:.6g}° away"
        )
    miss = float(np.linalg.norm(poses[:, :3, 3] - point, axis=1).min())
    return f"no branch passed the forward-kinematics check (the closest misses by {miss:.3g})"


def ik_all(robot: Any, target: Any, *, angle: Any = None, constant: Any = ()) -> IKSolutions:
    """Every closed-form inverse-kinematics solution of a classic arm.

    The family is recognized from the robot's joint axes (see :func:`recognize`), so a
    DH table in either convention and a chain of modules are treated alike.

    Parameters
    ----------
    robot : Robot
        A planar 2R/3R arm, a SCARA, a 3R elbow arm, a spherical-wrist 6R arm or a
        UR-type arm (docs/ik.md, "Closed-form solutions").
    target : array-like, shape (3,) or (4, 4)
        A point (length units, base frame) or a pose (homogeneous matrix; its rotation
        must be orthonormal within 1e-6 and is re-orthonormalized). 6R arms need a pose.
        Planar 3R arms and 3-revolute SCARAs need a pose or a point with ``angle`` —
        or just a point when the end-effector lies on the last axis, which is then free.
        The others take a point; a pose is also matched in orientation.
    angle : float, optional
        Planar 3R arms and 3-revolute SCARAs: the end-effector's turn φ about the axes
        from its orientation at q = 0 (radians; for a DH planar 3R, ``q1 + q2 + q3``).
    constant : int, str or iterable of them
        More modules held at their own ``q``; modules named ``"… (constant)"`` (the
        held twists of :func:`robotconf.dh_to_modules`) always are.

    Returns
    -------
    IKSolutions
        ``q`` (k, n) with every verified solution, ``labels``, ``within_limits``,
        ``family`` and ``reason``.

    Raises
    ------
    InvalidInputError
        ``robot`` for a geometry without a closed form here (the message says what
        differs, e.g. the closest approach of the wrist axes); ``target`` / ``angle`` for
        a target of the wrong shape or kind.

    Examples
    --------
    >>> import robotconf as rc
    >>> sols = ik_all(rc.preset("planar_2r", l1=1, l2=1), [1, 1, 0])
    >>> sols.labels, sols.q.round(6) + 0.0
    (('elbow down', 'elbow up'), array([[ 0.      ,  1.570796],
           [ 1.570796, -1.570796]]))
    >>> puma = rc.preset("puma560")
    >>> pose = puma.end_effector_pose([0.3, 0.2, -0.4, 0.5, 0.6, 0.7])
    >>> len(ik_all(puma, pose)), ik_all(puma, pose).family
    (8, 'spherical-wrist 6R')
    >>> ik_all(rc.preset("planar_2r"), [74.2, 0, 0]).reason
    'the target is 4.2 beyond the reach: it is 74.2 from the first axis, and the arm reaches 70'
    """
    chain, family, why = closed_form_structure(robot, constant)
    if family is None:
        raise refuse(chain, NotClosedForm(why)) from None
    point, turn = _read_target(target, angle, chain, family)
    return _finish(chain, family, point, turn, SOLVERS[family](chain, point, turn, family))
