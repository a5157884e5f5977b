"""Fitting the view: the sphere that holds the drawn robot at one configuration.

The scene centres this sphere at the viewer's origin (where the camera orbits) and puts
the camera at the distance where the sphere just fills the pane. Points come from the
core only: the base, every frame origin, every joint axis point and the end-effector.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..kinematics import joint_axes
from ._drawing import SPHERE_RADIUS, RobotDrawing

__all__ = ["view_sphere"]


def view_sphere(drawing: RobotDrawing, q: Any) -> tuple[np.ndarray, float]:
    """Centre (3,) and radius of a sphere around everything drawn at ``q`` (n,).

    The centre is the middle of the points' bounding box; the radius reaches the farthest
    point plus a sphere's size, so the end-effector ball is inside too.

    Examples
    --------
    >>> import robotconf as rc
    >>> robot = rc.Robot([rc.Module("Ry", a=(0, 0, 20))], end_effector=(40, 0, 0))
    >>> centre, radius = view_sphere(RobotDrawing(robot, 60.0), [0.0])
    >>> centre.tolist(), round(radius, 2)
    ([20.0, 0.0, 10.0], 24.88)
    """
    robot = drawing.robot
    axes = joint_axes(robot, q)
    points = np.vstack(
        [
            np.zeros((1, 3)),
            robot.frame_origins(q),
            axes.point[~np.isnan(axes.point).any(axis=1)],
            robot.end_effector(q)[None],
        ]
    )
    centre = 0.5 * (points.min(axis=0) + points.max(axis=0))
    reach = float(np.linalg.norm(points - centre, axis=1).max())
    margin = 1.2 * SPHERE_RADIUS * drawing.size
    return centre, reach + margin
