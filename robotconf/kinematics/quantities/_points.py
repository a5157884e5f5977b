"""The labelled points of a robot picture: module frame origins and the end-effector.

The paper's Figure 14 draws a green sphere at each module and a red one at the
end-effector, each labelled with its position (``M2 (0.0, 0.0, 20.0)``). The static plot,
the 3D scene and the report all label the same points, so they come from here.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from ..._errors import InvalidInputError
from ..._validation import check_configuration
from ..robot._named_results import END_EFFECTOR_LABEL, RobotPoint, format_point

if TYPE_CHECKING:  # pragma: no cover
    from ..robot._robot import Robot

__all__ = ["RobotPoint", "robot_points", "format_point", "END_EFFECTOR_LABEL"]


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
    from ..robot._robot import Robot

    if not isinstance(robot, Robot):
        raise InvalidInputError("robot", robot, "a robotconf Robot", problem="not a robot:")
    if q is not None:
        q = check_configuration(q, robot.n, robot.coordinate_names)
    origins = robot.frame_origins(q)
    points = [RobotPoint(name, origins[i]) for i, name in enumerate(robot.module_names)]
    points.append(RobotPoint(END_EFFECTOR_LABEL, robot.end_effector(q)))
    return points
