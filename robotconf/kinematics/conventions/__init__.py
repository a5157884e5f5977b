"""Conventions and bounds: the rules every module, DH row and robot obeys, as data.

The tables docs/conventions.md describes (module kinds, joint letters and units, DH
conventions and their factors), and the checks that keep a chain's numbers and names
sane before anything is computed: bounded parameters, unique display names, rigid poses.

Conventions (data)
    :data:`MODULE_KINDS`, :data:`MODULE_CODES`, :data:`JOINT_TYPES`, :data:`AXIS_NAMES`,
    :data:`DH_CONVENTIONS`, :data:`DH_FACTORS`, :func:`dh_formula`, …
Bounds (no chain overflows)
    :data:`MAX_PARAMETER` (1e150), :data:`MAX_MODULES` (64), :func:`check_parameter`,
    :func:`check_parameter_vector`
Names (no two modules share a name)
    :data:`MAX_NAME_CHARS` (200), :func:`check_name`, :func:`check_module_names`
Rigid poses
    :func:`check_rigid_pose`, :data:`POSE_TOLERANCE`, :data:`POSE_ALLOWED`

>>> MAX_MODULES, dh_formula("standard")
(64, 'Rz(θ)·Tz(d)·Tx(a)·Rx(α)')
"""

from ._bounds import MAX_MODULES, MAX_PARAMETER, check_parameter, check_parameter_vector
from ._conventions import (
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
    MODULE_CODES,
    MODULE_KINDS,
    MODULE_OFFSETS,
    ROTATION_KINDS,
    TRANSLATION_KINDS,
    dh_formula,
    kind_axis,
    kind_joint_type,
    kind_label,
)
from ._names import MAX_NAME_CHARS, check_module_names, check_name
from ._pose_check import POSE_ALLOWED, POSE_TOLERANCE, check_rigid_pose

__all__ = [
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
    "MAX_PARAMETER",
    "MAX_MODULES",
    "check_parameter",
    "check_parameter_vector",
    "MAX_NAME_CHARS",
    "check_name",
    "check_module_names",
    "POSE_TOLERANCE",
    "POSE_ALLOWED",
    "check_rigid_pose",
]
