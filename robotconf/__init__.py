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

from . import signals
from ._check_result import MatrixCheck
from ._checking import assert_matrix, check_matrix
from ._derivation import Derivation, DerivationStep, derivation
from ._dh import DH_CONVENTIONS, DHLink, dh_matrix
from ._errors import InvalidInputError
from ._expected import ExpectedMatrix, expected_matrix
from ._geometry import LinkGeometry
from ._jacobian import jacobian
from ._link import JOINT_TYPES, Link
from ._module import MODULE_KINDS, Module, kind_name, transfer_matrix
from ._motion_table import compare_motions
from ._robot import Robot
from ._simulation import Motion, simulate
from ._student_parser import ParserLimits, parse_expression, parse_matrix
from ._symbolic import SymbolicChain, symbolic_chain
from ._validation import check_finite_number, check_joint_values, check_vector3

__version__ = "0.1.0"

__all__ = [
    "DH_CONVENTIONS",
    "JOINT_TYPES",
    "MODULE_KINDS",
    "assert_matrix",
    "check_finite_number",
    "check_joint_values",
    "check_matrix",
    "check_vector3",
    "compare_motions",
    "derivation",
    "Derivation",
    "DerivationStep",
    "dh_matrix",
    "DHLink",
    "expected_matrix",
    "ExpectedMatrix",
    "InvalidInputError",
    "jacobian",
    "kind_name",
    "Link",
    "LinkGeometry",
    "MatrixCheck",
    "Module",
    "Motion",
    "parse_expression",
    "parse_matrix",
    "ParserLimits",
    "Robot",
    "signals",
    "simulate",
    "symbolic_chain",
    "SymbolicChain",
    "transfer_matrix",
]
