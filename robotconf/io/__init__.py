"""Files: robotconf's versioned JSON format, and URDF export.

Reading is defensive (size, nesting, duplicate keys, NaN, the schema); nothing read is
ever evaluated. docs/file-format.md describes the format.

Files
    :class:`Setup`, :func:`load`, :func:`load_setup`, :data:`FORMAT`, :data:`VERSION`,
    :data:`MAX_BYTES`, :data:`MAX_LINKS`, :func:`robot_to_dict`, :func:`robot_from_dict`
Programs
    :func:`program_to_json`, :func:`load_program`, :func:`program_to_dict`,
    :func:`program_from_dict` (the ``"program"`` section)
Cells
    :func:`load_cell`, :func:`save_cell`, :func:`cell_to_json`, :func:`cell_to_dict`,
    :func:`cell_from_dict`, :data:`CELL_FORMAT`, :data:`CELL_VERSION`
URDF
    :func:`to_urdf`, :func:`rpy_from_matrix`

>>> from robotconf.kinematics import Module, Robot
>>> robot = Robot([Module("Rz")], end_effector=(1, 0, 0))
>>> Setup.from_json(Setup(robot).to_json()).robot == robot
True
"""

from ._cell_files import cell_to_json, load_cell, save_cell
from ._cell_schema import CELL_FORMAT, CELL_VERSION, cell_from_dict, cell_to_dict
from ._files import MAX_BYTES, Setup, load, load_program, load_setup, parse_json, program_to_json
from ._program_schema import program_from_dict, program_to_dict
from ._schema import FORMAT, MAX_LINKS, MAX_NAME_CHARS, VERSION, robot_from_dict, robot_to_dict
from ._urdf import PLACEHOLDER_EFFORT, PLACEHOLDER_VELOCITY, rpy_from_matrix, to_urdf

__all__ = [
    # files
    "Setup",
    "load",
    "load_setup",
    "parse_json",
    "robot_to_dict",
    "robot_from_dict",
    "FORMAT",
    "VERSION",
    "MAX_BYTES",
    "MAX_LINKS",
    "MAX_NAME_CHARS",
    # programs
    "program_to_json",
    "load_program",
    "program_to_dict",
    "program_from_dict",
    # cells
    "load_cell",
    "save_cell",
    "cell_to_json",
    "cell_to_dict",
    "cell_from_dict",
    "CELL_FORMAT",
    "CELL_VERSION",
    # URDF
    "to_urdf",
    "rpy_from_matrix",
    "PLACEHOLDER_EFFORT",
    "PLACEHOLDER_VELOCITY",
]
