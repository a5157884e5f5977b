"""Poses (4×4 homogeneous matrices) and names: how the cell reads every placement.

``pose(xyz, rpy)`` is the one helper for writing a pose anywhere in robotconf (a robot's
base, a box, a frame, a tool's TCP, a program's target): a translation and URDF's roll,
pitch, yaw (``R = Rz(yaw)·Ry(pitch)·Rx(roll)``, from
:func:`robotconf.kinematics.matrix_from_rpy`).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_vector3, one_line
from ..kinematics import (
    MAX_NAME_CHARS,
    MAX_PARAMETER,
    check_rigid_pose,
    matrix_from_rpy,
)

__all__ = ["pose", "check_pose", "check_cell_name", "NAME_SEPARATOR"]

#: Joins a frame's parent and its own name: ``"table/pick"``.
NAME_SEPARATOR = "/"

_POSE = (
    "a 4×4 homogeneous pose (orthonormal rotation, det +1, last row 0 0 0 1, "
    f"|translation| ≤ {MAX_PARAMETER:g}), e.g. rc.pose(xyz, rpy)"
)


def pose(xyz: Any = (0.0, 0.0, 0.0), rpy: Any = (0.0, 0.0, 0.0)) -> np.ndarray:
    """A pose from a translation and roll, pitch, yaw angles.

    Parameters
    ----------
    xyz : array-like, shape (3,)
        Translation (length units).
    rpy : array-like, shape (3,)
        Roll, pitch, yaw (rad): turns about the fixed x, y and z axes in that order,
        ``R = Rz(yaw)·Ry(pitch)·Rx(roll)`` (URDF's ``rpy``).

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    InvalidInputError
        ``xyz`` or ``rpy`` not three finite numbers, or a translation beyond ±1e150.

    Examples
    --------
    >>> import robotconf as rc
    >>> rc.pose([1, 2, 3], [0, 0, np.pi / 2]).round(12) + 0.0
    array([[ 0., -1.,  0.,  1.],
           [ 1.,  0.,  0.,  2.],
           [ 0.,  0.,  1.,  3.],
           [ 0.,  0.,  0.,  1.]])
    """
    x = check_vector3(xyz, "xyz")
    angles = check_vector3(rpy, "rpy")
    if max(abs(v) for v in x) > MAX_PARAMETER:
        raise InvalidInputError("xyz", x, _POSE, problem="too large:")
    out = np.eye(4)
    out[:3, :3] = matrix_from_rpy(*angles)
    out[:3, 3] = x
    return out


def check_pose(value: Any, field: str) -> np.ndarray:
    """A rigid 4×4 pose as a float array; ``None`` is the identity.

    A rotation off by more than round-off (up to 1e-6) is replaced by the nearest
    rotation, so a typed pose is forgiven and every pose the cell keeps is rigid.

    >>> check_pose(None, "pose")[0]
    array([1., 0., 0., 0.])
    >>> check_pose(np.diag([1.0, 1.0, -1.0, 1.0]), "box.pose")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: box.pose: the rotation is a reflection (det −1): ...
    """
    if value is None:
        return np.eye(4)
    array = check_rigid_pose(value, field, _POSE)
    rotation = array[:3, :3]
    drift = float(np.max(np.abs(rotation.T @ rotation - np.eye(3))))
    out = np.array(array, dtype=float)
    if drift > 1e-12:  # a rotation exact to round-off is kept bit for bit
        u, _, vt = np.linalg.svd(rotation)
        out[:3, :3] = u @ vt
    out[3] = (0.0, 0.0, 0.0, 1.0)
    return out


def check_cell_name(value: Any, field: str) -> str:
    """A name in the cell: non-empty text without ``/`` (it joins frame names).

    >>> check_cell_name("table", "name")
    'table'
    >>> check_cell_name("a/b", "name")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: name: contains '/': 'a/b'; allowed: ...
    """
    allowed = f"non-empty text of at most {MAX_NAME_CHARS} characters without '{NAME_SEPARATOR}'"
    if not isinstance(value, str) or not value.strip():
        raise InvalidInputError(field, one_line(value), allowed, problem="not a name:")
    if len(value) > MAX_NAME_CHARS:
        raise InvalidInputError(field, value, allowed, problem="too long:")
    if NAME_SEPARATOR in value:
        raise InvalidInputError(field, value, allowed, problem=f"contains '{NAME_SEPARATOR}':")
    return value
