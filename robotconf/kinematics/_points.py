"""The labelled points of a robot picture: module frame origins and the end-effector.

The paper's Figure 14 draws a green sphere at each module and a red one at the
end-effector, each labelled with its position (``M2 (0.0, 0.0, 20.0)``). The static plot,
the 3D scene and the report all label the same points, so they come from here.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_configuration, check_integer, check_vector3, one_line

if TYPE_CHECKING:  # pragma: no cover
    from ._robot import Robot

__all__ = ["RobotPoint", "robot_points", "format_point", "END_EFFECTOR_LABEL"]

#: Name of the end-effector point (as in :class:`~robotconf.Motion`'s points).
END_EFFECTOR_LABEL = "EE"


class RobotPoint(NamedTuple):
    """A named point: unpacks as ``name, position``.

    Attributes
    ----------
    name : str
        A module name (``"M1"`` or the module's own) or ``"EE"``.
    position : ndarray, shape (3,)
        Base-frame position (length units).
    """

    name: str
    position: np.ndarray

    def __str__(self) -> str:
        return format_point(self.name, self.position)


def robot_points(robot: Robot, q: Any = None) -> list[RobotPoint]:
    """Module frame origins and the end-effector, named, at one configuration.

    Parameters
    ----------
    robot : Robot
    q : array-like, shape (n,), optional
        Coordinates (radians / length); default: the modules' own ``q``.

    Returns
    -------
    list of RobotPoint, length n + 1
        ``(name, position)`` for ``M1 … Mn`` (:meth:`Robot.frame_origins`), then ``EE``
        (:meth:`Robot.end_effector`) — always last.

    Raises
    ------
    InvalidInputError
        For a bad ``q`` or a trajectory instead of one configuration.

    Examples
    --------
    The paper's Figure 14 (parking position):

    >>> import robotconf as rc
    >>> robot = rc.Robot(
    ...     [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
    ...     end_effector=(40, 0, 0),
    ... )
    >>> [str(point) for point in robot_points(robot)]
    ['M1 (0.0, 0.0, 0.0)', 'M2 (0.0, 0.0, 20.0)', 'M3 (30.0, 0.0, 20.0)', 'EE (70.0, 0.0, 20.0)']
    >>> name, xyz = robot_points(robot)[-1]
    >>> name, xyz
    ('EE', array([70.,  0., 20.]))
    """
    from ._robot import Robot

    if not isinstance(robot, Robot):
        raise InvalidInputError("robot", robot, "a robotconf Robot", problem="not a robot:")
    if q is not None:
        q = check_configuration(q, robot.n, robot.coordinate_names)
    origins = robot.frame_origins(q)
    points = [RobotPoint(name, origins[i]) for i, name in enumerate(robot.module_names)]
    points.append(RobotPoint(END_EFFECTOR_LABEL, robot.end_effector(q)))
    return points


def format_point(name: str, xyz: Any, digits: int = 1) -> str:
    """A point's label as the paper prints it: ``"EE (70.0, 0.0, 20.0)"``.

    Parameters
    ----------
    name : str
    xyz : array-like, shape (3,)
        Position (length units).
    digits : int
        Decimals, 0 to 15. Values that round to zero print as ``0.0``, never ``-0.0``.

    Returns
    -------
    str

    Examples
    --------
    >>> format_point("EE", [70, -1e-17, 20])
    'EE (70.0, 0.0, 20.0)'
    >>> format_point("M3", [29.99996, 0, 20], digits=3)
    'M3 (30.000, 0.000, 20.000)'
    """
    if not isinstance(name, str):
        raise InvalidInputError("name", one_line(name), "text", problem="not text:")
    digits = check_integer(digits, "digits", 0, 15)
    values = check_vector3(xyz, "xyz")
    # round() first, then + 0.0: a tiny negative would otherwise print as "-0.0".
    shown = ", ".join(f"{round(v, digits) + 0.0:.{digits}f}" for v in values)
    return f"{name} ({shown})"
