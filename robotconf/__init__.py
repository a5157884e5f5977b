"""robotconf: serial-robot kinematics for teaching, from modules or Denavit–Hartenberg rows.

``import robotconf as rc`` gives the names a notebook needs, grouped by concept below. Each
lives in a folder of its own (docs/architecture.md): :mod:`robotconf.kinematics`,
:mod:`robotconf.signals`, :mod:`robotconf.motion`, :mod:`robotconf.inverse_kinematics`
(``rc.ik``, ``rc.ik_all``), :mod:`robotconf.calibration` (``rc.locate_frame``,
``rc.calibrate``), :mod:`robotconf.programs`, :mod:`robotconf.cell` (``rc.Cell``),
:mod:`robotconf.teaching`, :mod:`robotconf.io`, :mod:`robotconf.presets`,
:mod:`robotconf.plots`, and the presentation layers :mod:`robotconf.scene`,
:mod:`robotconf.panel` and :mod:`robotconf.grading`. Importing the
package loads numpy only; tables, plots, symbolic algebra, the 3D view and the panel
import their libraries when they are used.

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
from ._budget import memory_budget, set_memory_budget
from ._errors import InvalidInputError
from ._validation import check_finite_number, check_joint_values, check_vector3
from .calibration import Calibration, FrameFit, calibrate, locate_frame
from .cell import Box, Cell, Cylinder, Mesh, Sphere, Tool, pose
from .inverse_kinematics import IKResult, IKSolutions, ik, ik_all
from .io import Setup, load, load_cell, load_program, load_setup, to_urdf
from .kinematics import (
    DH_CONVENTIONS,
    JOINT_TYPES,
    MODULE_KINDS,
    DHLink,
    JointAxes,
    Link,
    LinkGeometry,
    Module,
    Robot,
    RobotPoint,
    Workspace,
    characteristic_length,
    convert_dh,
    dh_matrix,
    dh_to_modules,
    format_point,
    jacobian,
    joint_axes,
    kind_name,
    modules_to_dh,
    reinterpret_dh,
    robot_points,
    transfer_matrix,
    workspace,
)
from .motion import Motion, SimulationSettings, compare_motions, simulate
from .plots import plot_coordinates, plot_motion, plot_robot, plot_workspace
from .presets import preset, preset_names
from .programs import (
    CIRC,
    LIN,
    PTP,
    Program,
    ProgramMotion,
    ProgramReport,
    Violation,
    Wait,
)
from .teaching import (
    AnswerCheck,
    Derivation,
    DerivationStep,
    DHTableCheck,
    ExpectedMatrix,
    IKCheck,
    MatrixCheck,
    ParserLimits,
    ProfileTask,
    SymbolicChain,
    Variant,
    assert_angle,
    assert_dh_table,
    assert_ik_solution,
    assert_ik_solutions,
    assert_interval,
    assert_matrix,
    assert_profile,
    assert_set,
    assert_value,
    assert_vector,
    check_angle,
    check_dh_table,
    check_ik_solution,
    check_ik_solutions,
    check_interval,
    check_matrix,
    check_profile,
    check_set,
    check_value,
    check_vector,
    derivation,
    expected_matrix,
    parse_expression,
    parse_matrix,
    symbolic_chain,
)

__version__ = "0.1.0"

# What a notebook needs; the rest (validators, kernel descriptions, parser pieces) stays
# reachable as rc.NAME and from its folder.
__all__ = [
    # robots
    "Robot",
    "Module",
    "DHLink",
    "MODULE_KINDS",
    "DH_CONVENTIONS",
    "transfer_matrix",
    "dh_matrix",
    "InvalidInputError",
    "memory_budget",
    "set_memory_budget",
    # kinematics
    "robot_points",
    "jacobian",
    "joint_axes",
    "dh_to_modules",
    "modules_to_dh",
    "convert_dh",
    "reinterpret_dh",
    "workspace",
    "Workspace",
    # motion
    "signals",
    "simulate",
    "Motion",
    "SimulationSettings",
    "compare_motions",
    # teaching
    "derivation",
    "symbolic_chain",
    "expected_matrix",
    "check_matrix",
    "assert_matrix",
    "MatrixCheck",
    "check_value",
    "check_vector",
    "check_angle",
    "check_set",
    "check_interval",
    "assert_value",
    "assert_vector",
    "assert_angle",
    "assert_set",
    "assert_interval",
    "AnswerCheck",
    "check_ik_solution",
    "check_ik_solutions",
    "assert_ik_solution",
    "assert_ik_solutions",
    "IKCheck",
    "check_profile",
    "assert_profile",
    "ProfileTask",
    "check_dh_table",
    "assert_dh_table",
    "DHTableCheck",
    "Variant",
    # inverse kinematics
    "ik",
    "ik_all",
    "IKResult",
    "IKSolutions",
    # calibration
    "locate_frame",
    "FrameFit",
    "calibrate",
    "Calibration",
    # robot programs
    "Program",
    "PTP",
    "LIN",
    "CIRC",
    "Wait",
    "ProgramMotion",
    "ProgramReport",
    "Violation",
    # the work cell
    "Cell",
    "pose",
    "Box",
    "Cylinder",
    "Sphere",
    "Mesh",
    "Tool",
    "load_cell",
    # files and presets
    "load",
    "load_setup",
    "load_program",
    "Setup",
    "to_urdf",
    "preset",
    "preset_names",
    "presets",
    # pictures
    "plot_robot",
    "plot_motion",
    "plot_coordinates",
    "plot_workspace",
    "view",
    "Scene",
    "configurator",
    "Configurator",
]

# Kept importable under their old top-level names; not part of the notebook surface.
_ALSO_PUBLIC = (
    check_finite_number,
    check_joint_values,
    check_vector3,
    characteristic_length,
    format_point,
    kind_name,
    JOINT_TYPES,
    JointAxes,
    Link,
    LinkGeometry,
    RobotPoint,
    Derivation,
    DerivationStep,
    ExpectedMatrix,
    ParserLimits,
    SymbolicChain,
    parse_expression,
    parse_matrix,
)

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


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))
