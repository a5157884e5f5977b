"""Every input check of the numeric solver: targets, mode, mask, start, options.

Each check raises :class:`~robotconf.InvalidInputError` naming the field, the value and
what is allowed, before any work starts.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import (
    as_float_array,
    check_finite_number,
    check_flag,
    check_integer,
    check_joint_values,
    one_line,
)

__all__ = [
    "MODES",
    "MAX_ITERATIONS",
    "MAX_SEEDS",
    "ROTATION_TOLERANCE",
    "Targets",
    "check_targets",
    "check_mode",
    "check_mask",
    "check_start",
    "check_options",
    "Options",
]

#: The solver's modes and the mask each one means: x y z (base frame), then the turns
#: about the target frame's x y z axes.
MODES = {"position": (1.0, 1.0, 1.0, 0.0, 0.0, 0.0), "pose": (1.0,) * 6}

#: Most iterations one start may take.
MAX_ITERATIONS = 10_000

#: Most starts per target (q0 plus random ones).
MAX_SEEDS = 64

#: How far a target's rotation may be from orthonormal with det +1 (largest entry of
#: ``RᵀR − I``, and ``|det R − 1|``).
ROTATION_TOLERANCE = 1e-6

_TARGET = (
    "a point (3,), a pose (4, 4) with an orthonormal rotation (det +1) and last row "
    "[0, 0, 0, 1], or T of them: (T, 3) or (T, 4, 4)"
)


@dataclass(frozen=True)
class Targets:
    """Validated targets: ``positions`` (T, 3), ``rotations`` (T, 3, 3) or None (points),
    and whether the input had a leading T axis."""

    positions: np.ndarray
    rotations: np.ndarray | None
    batched: bool

    @property
    def count(self) -> int:
        """The number of targets T."""
        return int(self.positions.shape[0])


def check_mode(mode: Any) -> str:
    """``"position"`` or ``"pose"`` (any case).

    >>> check_mode("Pose")
    'pose'
    """
    allowed = "'position' (the end-effector point) or 'pose' (point and orientation)"
    if not isinstance(mode, str):
        raise InvalidInputError("mode", one_line(mode), allowed, problem="not text:")
    name = mode.strip().lower()
    if name not in MODES:
        raise InvalidInputError("mode", mode, allowed, problem="unknown mode")
    return name


def _check_poses(poses: np.ndarray, batched: bool) -> None:
    """Refuse the first of poses (T, 4, 4) with a bad last row or rotation."""
    rows = np.max(np.abs(poses[:, 3] - (0.0, 0.0, 0.0, 1.0)), axis=1) > 1e-12
    rotation = poses[:, :3, :3]
    drift = np.max(np.abs(rotation.transpose(0, 2, 1) @ rotation - np.eye(3)), axis=(1, 2))
    det = np.linalg.det(rotation)
    bad = rows | ~(drift <= ROTATION_TOLERANCE) | ~(np.abs(det - 1.0) <= ROTATION_TOLERANCE)
    if not bad.any():
        return
    i = int(np.flatnonzero(bad)[0])
    field = f"target[{i}]" if batched else "target"
    if rows[i]:
        raise InvalidInputError(
            field, one_line(poses[i, 3]), _TARGET, problem="the last row is not [0, 0, 0, 1]:"
        )
    what = (
        "a reflection (det −1)" if det[i] < 0 else f"not orthonormal (RᵀR − I up to {drift[i]:.2g})"
    )
    raise InvalidInputError(
        field, one_line(rotation[i]), _TARGET, problem=f"the rotation is {what}:"
    )


def check_targets(target: Any, mode: str) -> Targets:
    """Validate one target or T targets.

    Parameters
    ----------
    target : array-like, shape (3,), (4, 4), (T, 3) or (T, 4, 4)
        Points (length) or homogeneous poses in the base frame. A pose's rotation must be
        orthonormal with determinant +1 within :data:`ROTATION_TOLERANCE`.
    mode : {"position", "pose"}
        ``"pose"`` needs poses; ``"position"`` takes either (a pose's point is used).

    Returns
    -------
    Targets

    Raises
    ------
    InvalidInputError
        ``target`` (or ``target[i]`` for the i-th of T) on a wrong shape, NaN or infinity,
        a bad rotation or last row, or a point in mode ``"pose"``.

    Examples
    --------
    >>> check_targets([1, 2, 3], "position").positions
    array([[1., 2., 3.]])
    >>> check_targets([[1, 2, 3], [4, 5, 6]], "position").batched
    True
    """
    array = as_float_array(target, "target", _TARGET)
    if array.shape in ((3,), (4, 4)):
        batched, array = False, array[np.newaxis]
    elif array.ndim in (2, 3) and array.shape[1:] in ((3,), (4, 4)) and array.shape[0] >= 1:
        batched = True
    else:
        raise InvalidInputError(
            "target", one_line(target), _TARGET, problem=f"wrong shape {array.shape}:"
        )
    finite = np.isfinite(array.reshape(len(array), -1)).all(axis=1)
    if not finite.all():
        i = int(np.flatnonzero(~finite)[0])
        field = f"target[{i}]" if batched else "target"
        raise InvalidInputError(field, one_line(array[i]), _TARGET, problem="NaN or infinity in")
    if array.ndim == 2:
        if mode == "pose":
            raise InvalidInputError(
                "target",
                one_line(target),
                "a pose (4, 4) or poses (T, 4, 4) in mode 'pose', or mode='position'",
                problem="a point has no orientation:",
            )
        return Targets(np.ascontiguousarray(array), None, batched)
    _check_poses(array, batched)
    rotations = np.ascontiguousarray(array[:, :3, :3]) if mode == "pose" else None
    return Targets(np.ascontiguousarray(array[:, :3, 3]), rotations, batched)


def check_mask(mask: Any, mode: str) -> np.ndarray:
    """The six row weights: x, y, z in the base frame, turns about the target's x, y, z.

    Parameters
    ----------
    mask : None or array-like, shape (6,)
        Booleans or weights ≥ 0 (finite, at least one > 0); ``None``: the mode's rows.
        Mode ``"position"`` has no orientation, so its last three entries must be 0.
    mode : {"position", "pose"}

    Returns
    -------
    ndarray, shape (6,)

    Raises
    ------
    InvalidInputError
        ``mask`` on a wrong length, a negative or non-finite weight, all zeros, or an
        orientation weight in mode ``"position"``.

    Examples
    --------
    Position and the tool's z axis (any turn about it is fine):

    >>> check_mask([1, 1, 1, 1, 1, 0], "pose")
    array([1., 1., 1., 1., 1., 0.])
    """
    if mask is None:
        return np.array(MODES[mode])
    allowed = (
        "6 booleans or weights ≥ 0 (x, y, z, then turns about the target's x, y, z), "
        "at least one > 0"
    )
    values = np.asarray(mask)
    if values.dtype.kind == "b":
        values = values.astype(float)
    else:
        values = as_float_array(mask, "mask", allowed)
    if values.shape != (6,):
        raise InvalidInputError(
            "mask",
            one_line(mask),
            allowed,
            problem=f"expected 6 entries, got shape {values.shape}:",
        )
    if not np.isfinite(values).all() or (values < 0).any():
        raise InvalidInputError("mask", one_line(mask), allowed, problem="negative or not finite:")
    if not (values > 0).any():
        raise InvalidInputError("mask", one_line(mask), allowed, problem="constrains nothing:")
    if mode == "position" and (values[3:] > 0).any():
        raise InvalidInputError(
            "mask",
            one_line(mask),
            "zeros in the last three entries for mode='position' (or mode='pose')",
            problem="orientation weights without an orientation target:",
        )
    return values


def check_start(q0: Any, robot_q: np.ndarray, count: int, names: tuple[str, ...]) -> np.ndarray:
    """The first start of every target, shape (T, n).

    Parameters
    ----------
    q0 : None or array-like, shape (n,) or (T, n)
        ``None``: the robot's own coordinates.
    robot_q : ndarray, shape (n,)
    count : int
        The number of targets T.
    names : tuple of str
        Coordinate names, for the message.

    Raises
    ------
    InvalidInputError
        ``q0`` on a wrong shape, NaN or infinity, or T rows that do not match the targets.
    """
    n = len(robot_q)
    if q0 is None:
        return np.tile(robot_q, (count, 1))
    values, batched = check_joint_values(q0, n, names, "q0")
    if batched and values.shape[0] != count:
        raise InvalidInputError(
            "q0",
            one_line(q0),
            f"shape ({n},), or ({count}, {n}): one start per target",
            problem=f"{values.shape[0]} rows for {count} targets:",
        )
    return np.array(np.broadcast_to(values, (count, n)))


@dataclass(frozen=True)
class Options:
    """The solver's numeric options, validated."""

    tol: float
    orientation_tol: float
    max_iterations: int
    seeds: int
    seed: int
    respect_limits: bool


def _positive(value: Any, field: str) -> float:
    number = check_finite_number(value, field)
    if number <= 0:
        raise InvalidInputError(field, value, "a finite number > 0", problem="must be > 0, got")
    return number


def check_options(
    tol: Any,
    orientation_tol: Any,
    max_iterations: Any,
    seeds: Any,
    seed: Any,
    respect_limits: Any,
) -> Options:
    """Validate the numeric options of :func:`~robotconf.ik`.

    >>> check_options(1e-9, 1e-9, 200, 8, 0, True).seeds
    8
    """
    return Options(
        tol=_positive(tol, "tol"),
        orientation_tol=_positive(orientation_tol, "orientation_tol"),
        max_iterations=check_integer(max_iterations, "max_iterations", 1, MAX_ITERATIONS),
        seeds=check_integer(seeds, "seeds", 1, MAX_SEEDS),
        seed=check_integer(seed, "seed", 0),
        respect_limits=check_flag(respect_limits, "respect_limits"),
    )
