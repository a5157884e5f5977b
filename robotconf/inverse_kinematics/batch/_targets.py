"""The checks of :func:`~robotconf.inverse_kinematics.ik_all`'s target, over T targets.

Each target is checked as the one-target function checks it (a finite point, or a pose
whose last row is 0 0 0 1 and whose 3×3 block is a rotation within 1e-6, re-made
orthonormal); the first bad one is refused naming ``targets[i]``.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import as_float_array, one_line
from ..closed_form._recognize import GAP_TOL
from ..geometry._chain_axes import ChainAxes
from ..geometry._subproblems import perp
from ._vectors import rotations

__all__ = ["TargetsMany", "read_targets_many"]

_TARGETS = "points (T, 3) or poses (T, 4, 4) (homogeneous matrices), T ≥ 1"
_ONE = "a point (x, y, z) or a pose, a (4, 4) homogeneous matrix"


class TargetsMany:
    """T checked targets: ``points`` (T, 3), ``turns`` (T, 3, 3) or None, and the
    ``angle`` each one was given with (T,) or None."""

    def __init__(self, points: np.ndarray, turns: np.ndarray | None, angles: np.ndarray | None):
        self.points, self.turns, self.angles = points, turns, angles


def _rotations(array: np.ndarray) -> np.ndarray:
    """Refuse the first pose that is not one; the nearest rotations (T, 3, 3)."""
    rows = ~np.all(np.abs(array[:, 3] - (0.0, 0.0, 0.0, 1.0)) <= 1e-9, axis=1)
    turn = array[:, :3, :3]
    drift = np.abs(turn.transpose(0, 2, 1) @ turn - np.eye(3)).max(axis=(1, 2))
    bad = rows | (drift > 1e-6) | (np.linalg.det(turn) < 0)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        if rows[i]:
            problem, allowed = "the last row of a pose is not 0 0 0 1:", _ONE
        else:
            problem = "not a rotation:"
            allowed = _ONE + " whose 3×3 block is a rotation (orthonormal within 1e-6, det +1)"
        raise InvalidInputError(f"targets[{i}]", one_line(array[i]), allowed, problem=problem)
    u, _, vt = np.linalg.svd(turn)  # the nearest rotations: round-off in typed poses is forgiven
    return u @ vt


def _angles(angle: Any, count: int) -> np.ndarray:
    allowed = "a finite number (radians), or T of them"
    values = as_float_array(angle, "angle", allowed)
    if values.shape not in ((), (count,)):
        raise InvalidInputError(
            "angle", one_line(angle), allowed, problem=f"{values.shape} for {count} targets:"
        )
    if not np.all(np.isfinite(values)):
        raise InvalidInputError("angle", one_line(angle), allowed, problem="not finite:")
    return np.broadcast_to(values, (count,)).astype(float)


def read_targets_many(value: Any, angle: Any, chain: ChainAxes, family: str) -> TargetsMany:
    """Check T targets for a robot of ``family`` (see ``ik_all_many``)."""
    array = as_float_array(value, "targets", _TARGETS)
    if not (array.ndim == 2 and array.shape[1] == 3 or array.shape[1:] == (4, 4)):
        raise InvalidInputError(
            "targets", one_line(value), _TARGETS, problem=f"shape {array.shape}:"
        )
    if len(array) == 0:
        raise InvalidInputError("targets", one_line(value), _TARGETS, problem="no targets:")
    finite = np.isfinite(array.reshape(len(array), -1)).all(axis=1)
    if not finite.all():
        i = int(np.flatnonzero(~finite)[0])
        raise InvalidInputError(f"targets[{i}]", one_line(array[i]), _ONE, problem="not finite:")
    count = len(array)
    poses = array.ndim == 3
    points = np.ascontiguousarray(array[:, :3, 3] if poses else array)
    turns = _rotations(array) if poses else None
    revolute = [joint for joint in chain.joints if joint.kind == "R"]
    angled = family in ("planar 3R", "SCARA") and len(revolute) == 3
    angles = None
    if angle is not None:
        if not angled:
            raise InvalidInputError(
                "angle",
                one_line(angle),
                f"None for a {family} arm",
                problem="only planar 3R arms and 3-revolute SCARAs take an angle, got",
            )
        if turns is not None:
            raise InvalidInputError(
                "angle",
                one_line(angle),
                "None with (4, 4) poses (their rotations are the angles)",
                problem="poses already fix the angle:",
            )
        angles = _angles(angle, count)
        turns = rotations(revolute[0].direction, angles) @ chain.home[:3, :3]
    if turns is None and family in ("spherical-wrist 6R", "UR"):
        raise InvalidInputError(
            "targets",
            one_line(value),
            f"poses (T, 4, 4) for a {family} arm",
            problem="a point leaves the orientation open:",
        )
    if turns is None and angled:
        last = revolute[2]
        off = float(np.linalg.norm(perp(last.direction, chain.home[:3, 3] - last.point)))
        if off > GAP_TOL * chain.scale:
            raise InvalidInputError(
                "targets",
                one_line(value),
                f"poses (T, 4, 4), or points with angle=φ (the turn about the axes from "
                f"q = 0) for a {family} arm",
                problem="a point leaves the end-effector's angle open:",
            )
    return TargetsMany(points, turns, angles)
