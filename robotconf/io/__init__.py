"""Files: robotconf's versioned JSON format, and URDF export.

Reading is defensive (size, nesting, duplicate keys, NaN, the schema); nothing read is
ever evaluated. docs/file-format.md describes the format.

Files
    :class:`Setup`, :func:`load`, :func:`load_setup`, :data:`FORMAT`, :data:`VERSION`,
    :data:`MAX_BYTES`, :data:`MAX_LINKS`, :func:`robot_to_dict`, :func:`robot_from_dict`
URDF
    :func:`to_urdf`, :func:`rpy_from_matrix`

>>> from robotconf.kinematics import Module, Robot
>>> robot = Robot([Module("Rz")], end_effector=(1, 0, 0))
>>> Setup.from_json(Setup(robot).to_json()).robot == robot
True
"""

from ._files import MAX_BYTES, Setup, load, load_setup, parse_json
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
    # URDF
    "to_urdf",
    "rpy_from_matrix",
    "PLACEHOLDER_EFFORT",
    "PLACEHOLDER_VELOCITY",
]
