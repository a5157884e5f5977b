"""Kinematics: modules and DH links, robots, the vectorized kernel, Jacobians, workspaces.

This folder is the numpy core. Everything here imports numpy only. Its map, one concept
per subfolder (lower rows import only rows above them, but for type hints and calls made
when a method runs):

===============  =======================================================================
``conventions``  conventions as data; bounds, names and rigid poses every input obeys
``kernel``       one link as ``P·Screw(q)·Q``; chains composed over samples in blocks
``links``        the paper's modules, DH rows, their matrices and joint ranges
``robot``        the robot (immutable chain plus end effector) and its one-pass snapshot
``quantities``   Jacobians, joint axes, labelled points, rotation vectors, the workspace
``dh``           DH rows ⇄ modules, standard ⇄ modified DH
===============  =======================================================================

Robots and links
    :class:`Robot`, :class:`RobotSnapshot` (``robot.at(q)``: one pass, every frame),
    :class:`Module`, :class:`DHLink`, :class:`Link`, :func:`transfer_matrix`, :func:`dh_matrix`,
    :func:`kind_name`, :func:`check_convention`, :func:`characteristic_length`
Bounds and names (no chain overflows, no two modules share a name)
    :data:`MAX_PARAMETER` (1e150), :data:`MAX_MODULES` (64), :data:`MAX_NAME_CHARS` (200),
    :func:`check_parameter`, :func:`check_name`, :func:`check_module_names`
Conventions (data, see docs/conventions.md)
    :data:`MODULE_KINDS`, :data:`MODULE_CODES`, :data:`JOINT_TYPES`, :data:`AXIS_NAMES`,
    :data:`DH_CONVENTIONS`, :data:`DH_FACTORS`, :func:`dh_formula`, …
Points, axes and Jacobians
    :func:`robot_points`, :func:`format_point`, :func:`joint_axes`, :func:`jacobian`
Rotations as three numbers
    :func:`rotation_vector`, :func:`rotation_matrix` (log and exp maps),
    :func:`rpy_from_matrix`, :func:`matrix_from_rpy` (URDF's roll, pitch, yaw)
DH ⇄ modules, workspace
    :func:`dh_to_modules`, :func:`modules_to_dh`, :func:`workspace`, :class:`Workspace`
Standard ⇄ modified DH
    :func:`convert_dh` (the same robot), :func:`reinterpret_dh` (the same numbers)
Building blocks (the kernel and the component-major helpers the motion layer uses)
    :class:`LinkGeometry`, :func:`chain_poses`, :func:`chain_origins`, :func:`chain_point`,
    :func:`link_matrices`, :func:`joint_screws`, :func:`pose_components`, …

>>> from robotconf.kinematics import Module, Robot
>>> Robot([Module("Rz"), Module("Tx", a=(0, 0, 1))]).end_effector([0.0, 2.0])
array([2., 0., 1.])
"""

from .conventions import (
    AXIS_NAMES,
    DH_CONVENTIONS,
    DH_FACTORS,
    DH_JOINT_PARAMETER,
    DH_LENGTHS,
    DH_PARAMETERS,
    DH_SYMBOLS,
    JOINT_LETTERS,
    JOINT_OF_LETTER,
    JOINT_TYPES,
    JOINT_UNITS,
    KIND_ALIASES,
    MAX_MODULES,
    MAX_NAME_CHARS,
    MAX_PARAMETER,
    MODULE_CODES,
    MODULE_KINDS,
    MODULE_OFFSETS,
    POSE_ALLOWED,
    POSE_TOLERANCE,
    ROTATION_KINDS,
    TRANSLATION_KINDS,
    check_module_names,
    check_name,
    check_parameter,
    check_parameter_vector,
    check_rigid_pose,
    dh_formula,
    kind_axis,
    kind_joint_type,
    kind_label,
)
from .dh import convert_dh, dh_to_modules, modules_to_dh, reinterpret_dh
from .kernel import (
    BLOCK_SIZE,
    LinkGeometry,
    chain_origins,
    chain_point,
    chain_point_pose,
    chain_poses,
    cos_sin,
    kernel_bytes,
    link_matrices,
)
from .links import (
    DHLink,
    Link,
    Module,
    chain_length,
    chain_limits,
    check_convention,
    check_limits,
    default_limits,
    dh_link_from_row,
    dh_matrix,
    kind_name,
    transfer_matrix,
)
from .quantities import (
    MAX_WORKSPACE_SAMPLES,
    WORKSPACE_METHODS,
    JointScrew,
    Workspace,
    cross_components,
    ee_position,
    grid_size,
    jacobian,
    joint_axes,
    joint_screws,
    matrix_from_rpy,
    point_names,
    pose_components,
    robot_points,
    rotate_components,
    rotation_matrix,
    rotation_vector,
    rpy_from_matrix,
    workspace,
    workspace_bytes,
)
from .robot import (
    END_EFFECTOR_LABEL,
    JointAxes,
    Robot,
    RobotPoint,
    RobotSnapshot,
    characteristic_length,
    format_point,
)

__all__ = [
    # robots and links
    "Robot",
    "RobotSnapshot",
    "Module",
    "DHLink",
    "Link",
    "transfer_matrix",
    "dh_matrix",
    "kind_name",
    "check_convention",
    "dh_link_from_row",
    "characteristic_length",
    "check_limits",
    "chain_length",
    "chain_limits",
    "default_limits",
    # bounds and names (docs: robotconf.kinematics.conventions)
    "MAX_PARAMETER",
    "POSE_TOLERANCE",
    "POSE_ALLOWED",
    "check_rigid_pose",
    "MAX_MODULES",
    "MAX_NAME_CHARS",
    "check_parameter",
    "check_parameter_vector",
    "check_name",
    "check_module_names",
    # conventions
    "MODULE_KINDS",
    "MODULE_CODES",
    "KIND_ALIASES",
    "ROTATION_KINDS",
    "TRANSLATION_KINDS",
    "AXIS_NAMES",
    "JOINT_TYPES",
    "JOINT_LETTERS",
    "JOINT_OF_LETTER",
    "JOINT_UNITS",
    "DH_CONVENTIONS",
    "DH_PARAMETERS",
    "DH_FACTORS",
    "DH_SYMBOLS",
    "DH_LENGTHS",
    "DH_JOINT_PARAMETER",
    "MODULE_OFFSETS",
    "kind_joint_type",
    "kind_axis",
    "kind_label",
    "dh_formula",
    # points, axes, Jacobians
    "RobotPoint",
    "robot_points",
    "format_point",
    "END_EFFECTOR_LABEL",
    "point_names",
    "JointAxes",
    "joint_axes",
    "rotation_vector",
    "rotation_matrix",
    "rpy_from_matrix",
    "matrix_from_rpy",
    "jacobian",
    # DH ⇄ modules, workspace
    "dh_to_modules",
    "modules_to_dh",
    "convert_dh",
    "reinterpret_dh",
    "workspace",
    "Workspace",
    "WORKSPACE_METHODS",
    "MAX_WORKSPACE_SAMPLES",
    "grid_size",
    "workspace_bytes",
    # building blocks
    "LinkGeometry",
    "BLOCK_SIZE",
    "cos_sin",
    "chain_poses",
    "chain_origins",
    "chain_point",
    "chain_point_pose",
    "link_matrices",
    "kernel_bytes",
    "JointScrew",
    "joint_screws",
    "pose_components",
    "ee_position",
    "cross_components",
    "rotate_components",
]
