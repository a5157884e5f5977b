"""One check for a rigid pose given by a user: a 4×4 homogeneous matrix.

A robot program's pose target, a work cell's object or frame pose and a base pose are
all read here, so each refuses the same things with the same words: a wrong shape, a
non-finite entry, a last row other than ``[0, 0, 0, 1]``, a translation beyond
:data:`~robotconf.kinematics.MAX_PARAMETER`, and a rotation that is not orthonormal with
det +1 within :data:`POSE_TOLERANCE`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import as_float_array, one_line
from ._bounds import MAX_PARAMETER

__all__ = ["POSE_TOLERANCE", "POSE_ALLOWED", "check_rigid_pose"]

#: A pose's rotation must be orthonormal with det +1 within this (as for ``rc.ik``).
POSE_TOLERANCE = 1e-6

#: What a pose may be, as errors say it.
POSE_ALLOWED = (
    "a 4×4 homogeneous pose: orthonormal rotation (det +1), last row [0, 0, 0, 1], "
    f"|translation| ≤ {MAX_PARAMETER:.0e}"
)


def check_rigid_pose(value: Any, field: str, allowed: str = POSE_ALLOWED) -> np.ndarray:
    """``value`` as a float (4, 4) array once it is a rigid pose within round-off.

    Parameters
    ----------
    value : array-like, shape (4, 4)
    field : str
        The name errors give.
    allowed : str
        What errors say is allowed.

    Returns
    -------
    ndarray, shape (4, 4)
        A new array; its rotation is as given (orthonormal within
        :data:`POSE_TOLERANCE`, not re-orthonormalized).

    Raises
    ------
    InvalidInputError
        Naming ``field`` and what is wrong.

    Examples
    --------
    >>> check_rigid_pose(np.eye(4), "pose")[3]
    array([0., 0., 0., 1.])
    >>> check_rigid_pose(np.diag([1.0, 1.0, -1.0, 1.0]), "pose")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: pose: the rotation is a reflection (det −1): ...
    """
    array = np.array(as_float_array(value, field, allowed), dtype=float)
    if array.shape != (4, 4):
        raise InvalidInputError(
            field, one_line(value), allowed, problem=f"expected shape (4, 4), got {array.shape}:"
        )
    if not np.all(np.isfinite(array)):
        raise InvalidInputError(field, one_line(array), allowed, problem="entries must be finite:")
    if np.max(np.abs(array[3] - (0.0, 0.0, 0.0, 1.0))) > 1e-12:
        raise InvalidInputError(
            field, one_line(array[3]), allowed, problem="the last row is not [0, 0, 0, 1]:"
        )
    if np.max(np.abs(array[:3, 3])) > MAX_PARAMETER:
        raise InvalidInputError(
            field,
            tuple(array[:3, 3].tolist()),
            allowed,
            problem=f"the point is too large (|x| > {MAX_PARAMETER:.0e}):",
        )
    rotation = array[:3, :3]
    drift = float(np.max(np.abs(rotation.T @ rotation - np.eye(3))))
    det = float(np.linalg.det(rotation))
    if drift > POSE_TOLERANCE or abs(det - 1.0) > POSE_TOLERANCE:
        what = "a reflection (det −1)" if det < 0 else f"not orthonormal (RᵀR − I ≤ {drift:.2g})"
        raise InvalidInputError(
            field, one_line(rotation), allowed, problem=f"the rotation is {what}:"
        )
    return array
