"""robotconf: serial-robot kinematics for teaching, from modules or Denavit–Hartenberg rows.

The core (this package's top level) needs only numpy; tables, plots, symbolic algebra and
the 3D view import their libraries when they are used.

>>> import robotconf as rc
>>> robot = rc.Robot(
...     [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
...     end_effector=(40, 0, 0),
... )
>>> robot.end_effector([0, 0, 0])
array([70.,  0., 20.])
"""

from typing import Any

from . import presets, signals
from ._check_result import MatrixCheck
from ._checking import assert_matrix, check_matrix
from ._derivation import Derivation, DerivationStep, derivation
from ._dh import DH_CONVENTIONS, DHLink, dh_matrix
from ._dh_conversion import dh_to_modules, modules_to_dh
from ._errors import InvalidInputError
from ._expected import ExpectedMatrix, expected_matrix
from ._files import Setup, load, load_setup
from ._geometry import LinkGeometry
from ._jacobian import jacobian
from ._joint_axes import JointAxes, joint_axes
from ._limits import characteristic_length
from ._link import JOINT_TYPES, Link
from ._module import MODULE_KINDS, Module, kind_name, transfer_matrix
from ._motion_table import compare_motions
from ._robot import Robot
from ._robot_plot import plot_robot
from ._robot_points import RobotPoint, format_point, robot_points
from ._simulation import Motion, simulate
from ._student_parser import ParserLimits, parse_expression, parse_matrix
from ._symbolic import SymbolicChain, symbolic_chain
from ._urdf import to_urdf
from ._validation import check_finite_number, check_joint_values, check_vector3
from ._workspace import Workspace, workspace
from .presets import preset, preset_names

__version__ = "0.1.0"

__all__ = [
    "DH_CONVENTIONS",
    "JOINT_TYPES",
    "MODULE_KINDS",
    "assert_matrix",
    "characteristic_length",
    "check_finite_number",
    "check_joint_values",
    "check_matrix",
    "check_vector3",
    "compare_motions",
    "configurator",
    "Configurator",
    "derivation",
    "Derivation",
    "DerivationStep",
    "dh_matrix",
    "dh_to_modules",
    "DHLink",
    "expected_matrix",
    "ExpectedMatrix",
    "InvalidInputError",
    "jacobian",
    "joint_axes",
    "JointAxes",
    "format_point",
    "kind_name",
    "load",
    "load_setup",
    "Link",
    "LinkGeometry",
    "MatrixCheck",
    "modules_to_dh",
    "Module",
    "Motion",
    "parse_expression",
    "parse_matrix",
    "ParserLimits",
    "preset",
    "preset_names",
    "presets",
    "plot_robot",
    "Robot",
    "robot_points",
    "RobotPoint",
    "Scene",
    "Setup",
    "signals",
    "simulate",
    "symbolic_chain",
    "SymbolicChain",
    "to_urdf",
    "transfer_matrix",
    "view",
    "workspace",
    "Workspace",
]

# Presentation layers import ipywidgets (and more) on first use, never at `import robotconf`.
_LAZY = {
    "configurator": "panel",
    "Configurator": "panel",
    "Scene": "scene",
    "view": "scene",
}


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(f".{_LAZY[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
