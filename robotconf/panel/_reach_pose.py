"""A target pose as the Reach tab types it: x, y, z and roll, pitch, yaw.

Roll, pitch and yaw are turns about the base frame's fixed x, y and z axes, in that
order (URDF's ``rpy``): ``R = Rz(yaw) · Ry(pitch) · Rx(roll)``. The panel converts
between these six numbers and the 4 × 4 homogeneous pose the core's inverse kinematics
takes, with the kinematics' :func:`~robotconf.kinematics.matrix_from_rpy` and
:func:`~robotconf.kinematics.rpy_from_matrix`.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..kinematics import matrix_from_rpy, rpy_from_matrix

__all__ = ["pose_from_xyz_rpy", "xyz_rpy_from_pose"]


def pose_from_xyz_rpy(xyz: Sequence[float], rpy: Sequence[float]) -> np.ndarray:
    """The homogeneous pose (4, 4) at point ``xyz`` (length units) turned by ``rpy`` (rad).

    >>> pose_from_xyz_rpy((1.0, 2.0, 3.0), (0.0, 0.0, 0.0))[:3, 3]
    array([1., 2., 3.])
    """
    pose = np.eye(4)
    pose[:3, :3] = matrix_from_rpy(*rpy)
    pose[:3, 3] = xyz
    return pose


def xyz_rpy_from_pose(pose: np.ndarray) -> tuple[np.ndarray, tuple[float, float, float]]:
    """The point and the roll, pitch, yaw (rad) of a pose: the inverse of
    :func:`pose_from_xyz_rpy`, with pitch in [−π/2, π/2] and roll, yaw in (−π, π] (at
    gimbal lock yaw is 0).

    Examples
    --------
    >>> point, rpy = xyz_rpy_from_pose(pose_from_xyz_rpy((1, 2, 3), (0.1, -0.2, 0.3)))
    >>> point, np.round(rpy, 12)
    (array([1., 2., 3.]), array([ 0.1, -0.2,  0.3]))
    """
    roll, pitch, yaw = rpy_from_matrix(np.asarray(pose, dtype=float)[:3, :3])
    return np.array(pose, dtype=float)[:3, 3].copy(), (roll, pitch, yaw)
