"""What a robot gives besides its frames: Jacobians, joint axes, points, rotations, workspace.

Each takes a :class:`~robotconf.kinematics.Robot` (and coordinates) and derives one
quantity from the kernel's poses.

Jacobians and joint screws
    :func:`jacobian`, :class:`JointScrew`, :func:`joint_screws`, :func:`pose_components`,
    :func:`ee_position`, :func:`cross_components`, :func:`rotate_components`,
    :func:`point_names`
Joint axes (for the scene) and labelled points
    :func:`joint_axes`, :func:`robot_points`
Rotations as three numbers
    :func:`rotation_vector`, :func:`rotation_matrix` (log and exp maps),
    :func:`rpy_from_matrix`, :func:`matrix_from_rpy` (URDF's roll, pitch, yaw)
Reachable points
    :func:`workspace`, :class:`Workspace`, :data:`WORKSPACE_METHODS`,
    :data:`MAX_WORKSPACE_SAMPLES`, :func:`grid_size`, :func:`workspace_bytes`

>>> rotation_vector(matrix_from_rpy(0.0, 0.0, 0.5)).round(12) + 0.0
array([0. , 0. , 0.5])
"""

from ._jacobian import (
    JointScrew,
    cross_components,
    ee_position,
    jacobian,
    joint_screws,
    point_names,
    pose_components,
    rotate_components,
)
from ._joint_axes import joint_axes
from ._points import robot_points
from ._rotations import matrix_from_rpy, rotation_matrix, rotation_vector, rpy_from_matrix
from ._workspace import (
    MAX_WORKSPACE_SAMPLES,
    WORKSPACE_METHODS,
    Workspace,
    grid_size,
    workspace,
    workspace_bytes,
)

__all__ = [
    "jacobian",
    "JointScrew",
    "joint_screws",
    "pose_components",
    "ee_position",
    "cross_components",
    "rotate_components",
    "point_names",
    "joint_axes",
    "robot_points",
    "rotation_vector",
    "rotation_matrix",
    "rpy_from_matrix",
    "matrix_from_rpy",
    "workspace",
    "Workspace",
    "WORKSPACE_METHODS",
    "MAX_WORKSPACE_SAMPLES",
    "grid_size",
    "workspace_bytes",
]
