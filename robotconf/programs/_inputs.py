"""Validators for the fields of moves and programs; each error names its field."""

from __future__ import annotations

from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import as_float_array, check_finite_number, check_vector3, one_line
from ..motion import MAX_TIME

__all__ = [
    "POSE_TOLERANCE",
    "positive",
    "seconds",
    "point",
    "pose",
    "choice",
    "rates",
]

#: A pose's rotation must be orthonormal with det +1 within this (as for ``rc.ik``).
POSE_TOLERANCE = 1e-6

_POSE = "a 4×4 homogeneous pose: orthonormal rotation (det +1), last row [0, 0, 0, 1]"


def positive(value: Any, field: str, what: str) -> float:
    """A finite number > 0 (a speed or an acceleration).

    >>> positive(20, "speed", "a speed (length/s)")
    20.0
    >>> positive(-1, "speed", "a speed (length/s)")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: speed: must be > 0, got -1.0; allowed: a speed (length/s) > 0
    """
    number = check_finite_number(value, field)
    if not number > 0.0:
        raise InvalidInputError(field, number, f"{what} > 0", problem="must be > 0, got")
    return number


def seconds(value: Any, field: str) -> float:
    """A duration of at least 0 and at most ``MAX_TIME`` seconds.

    >>> seconds(0.5, "seconds")
    0.5
    """
    number = check_finite_number(value, field)
    if not 0.0 <= number <= MAX_TIME:
        raise InvalidInputError(
            field, number, f"a duration from 0 to {MAX_TIME:g} s", problem="out of range:"
        )
    return number


def point(value: Any, field: str) -> tuple[float, float, float]:
    """Three finite coordinates (length).

    >>> point([60, 10, 30], "position")
    (60.0, 10.0, 30.0)
    """
    return check_vector3(value, field)


def pose(value: Any, field: str) -> tuple[tuple[float, ...], ...]:
    """A homogeneous 4×4 pose as nested tuples, checked like ``rc.ik`` checks targets.

    >>> pose(np.eye(4), "pose")[3]
    (0.0, 0.0, 0.0, 1.0)
    >>> pose(np.diag([1.0, 1.0, -1.0, 1.0]), "pose")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: pose: the rotation is a reflection (det −1): ...
    """
    array = as_float_array(value, field, _POSE)
    if array.shape != (4, 4):
        raise InvalidInputError(
            field, one_line(value), _POSE, problem=f"expected shape (4, 4), got {array.shape}:"
        )
    if not np.all(np.isfinite(array)):
        raise InvalidInputError(field, one_line(array), _POSE, problem="entries must be finite:")
    if np.max(np.abs(array[3] - (0.0, 0.0, 0.0, 1.0))) > 1e-12:
        raise InvalidInputError(
            field, one_line(array[3]), _POSE, problem="the last row is not [0, 0, 0, 1]:"
        )
    rotation = array[:3, :3]
    drift = float(np.max(np.abs(rotation.T @ rotation - np.eye(3))))
    det = float(np.linalg.det(rotation))
    if drift > POSE_TOLERANCE or abs(det - 1.0) > POSE_TOLERANCE:
        what = "a reflection (det −1)" if det < 0 else f"not orthonormal (RᵀR − I ≤ {drift:.2g})"
        problem = f"the rotation is {what}:"
        raise InvalidInputError(field, one_line(rotation), _POSE, problem=problem)
    return tuple(tuple(float(x) for x in row) for row in array)


def choice(value: Any, field: str, choices: tuple[str, ...]) -> str:
    """One of ``choices`` (any case).

    >>> choice("Quintic", "profile", ("trapezoidal", "quintic"))
    'quintic'
    """
    allowed = " or ".join(repr(c) for c in choices)
    if not isinstance(value, str):
        raise InvalidInputError(field, one_line(value), allowed, problem="expected text, got")
    name = value.strip().lower()
    if name not in choices:
        raise InvalidInputError(field, value, allowed, problem="unknown value")
    return name


def rates(value: Any, n: int, field: str, what: str) -> float | tuple[float, ...]:
    """One limit for every joint, or one per joint: each finite and > 0.

    >>> rates([1, 2], 2, "joint_speed", "a joint speed")
    (1.0, 2.0)
    """
    array = as_float_array(value, field, f"{what} > 0, or {n} of them (one per joint)")
    if array.shape == ():
        return positive(float(array), field, what)
    if array.shape != (n,):
        raise InvalidInputError(
            field,
            one_line(value),
            f"one number, or {n} (one per joint)",
            problem=f"expected shape () or ({n},), got {array.shape}:",
        )
    return tuple(positive(x, f"{field}[{j}]", what) for j, x in enumerate(array.tolist()))
