"""A target pose as the Reach tab types it: x, y, z and roll, pitch, yaw.

Roll, pitch and yaw are turns about the base frame's fixed x, y and z axes, in that
order (URDF's ``rpy``): ``R = Rz(yaw) · Ry(pitch) · Rx(roll)``. The panel converts
between these six numbers and the 4 × 4 homogeneous pose the core's inverse kinematics
takes; nothing else here.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

__all__ = ["pose_from_xyz_rpy", "xyz_rpy_from_pose", "rotation_from_rpy"]

#: Below this ``|cos(pitch)|`` roll and yaw turn about the same axis (gimbal lock): the
#: whole turn is given to yaw.
_GIMBAL = 1e-9


def rotation_from_rpy(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """``Rz(yaw) · Ry(pitch) · Rx(roll)``, shape (3, 3); angles in radians.

    >>> rotation_from_rpy(0.0, 0.0, math.pi / 2).round(12) + 0.0
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])
    """
    cr, sr = math.cos(roll), math.sin(roll)
    cp, sp = math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    return np.array(
        [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ]
    )


def pose_from_xyz_rpy(xyz: Sequence[float], rpy: Sequence[float]) -> np.ndarray:
    """The homogeneous pose (4, 4) at point ``xyz`` (length units) turned by ``rpy`` (rad).

    >>> pose_from_xyz_rpy((1.0, 2.0, 3.0), (0.0, 0.0, 0.0))[:3, 3]
    array([1., 2., 3.])
    """
    pose = np.eye(4)
    pose[:3, :3] = rotation_from_rpy(*rpy)
    pose[:3, 3] = xyz
    return pose


def xyz_rpy_from_pose(pose: np.ndarray) -> tuple[np.ndarray, tuple[float, float, float]]:
    """The point and the roll, pitch, yaw (rad) of a pose: the inverse of
    :func:`pose_from_xyz_rpy`, with pitch in [−π/2, π/2] and roll, yaw in (−π, π].

    Examples
    --------
    >>> point, rpy = xyz_rpy_from_pose(pose_from_xyz_rpy((1, 2, 3), (0.1, -0.2, 0.3)))
    >>> point, np.round(rpy, 12)
    (array([1., 2., 3.]), array([ 0.1, -0.2,  0.3]))
    """
    rotation = np.asarray(pose, dtype=float)[:3, :3]
    pitch = math.atan2(-rotation[2, 0], math.hypot(rotation[0, 0], rotation[1, 0]))
    if abs(math.cos(pitch)) > _GIMBAL:
        roll = math.atan2(rotation[2, 1], rotation[2, 2])
        yaw = math.atan2(rotation[1, 0], rotation[0, 0])
    else:  # roll and yaw turn about the same axis: give the whole turn to yaw
        roll = 0.0
        yaw = math.atan2(-rotation[0, 1], rotation[1, 1])
    return np.array(pose, dtype=float)[:3, 3].copy(), (roll, pitch, yaw)
