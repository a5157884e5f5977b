"""Fitting the view: the sphere that holds everything drawn.

The scene centres this sphere at the viewer's origin (where the camera orbits) and puts
the camera at the distance where the sphere just fills the pane. The points come from the
scene's parts: the robot (base, frame origins, joint axes' points, end effector), the
ghosts, the target marker and the taught points; so a target out of reach or a program's
far point is never outside the picture.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ._commands import Op, command_op

__all__ = ["view_sphere", "inside", "camera_op", "CENTRED"]

#: What centring moves: everything meshcat draws for us, and its grid and world axes.
CENTRED = ("/meshcat", "/Grid", "/Axes")


def view_sphere(parts: Sequence[np.ndarray], margin: float) -> tuple[np.ndarray, float]:
    """Centre (3,) and radius of a sphere around every point of ``parts`` (each (k, 3)).

    The centre is the middle of the points' bounding box; the radius reaches the farthest
    point plus ``margin`` (a sphere's size, so the end-effector ball is inside too).

    Examples
    --------
    >>> robot = np.array([[0.0, 0, 0], [0, 0, 20], [40, 0, 20]])
    >>> centre, radius = view_sphere([robot], margin=2.0)
    >>> centre.tolist(), round(radius, 2)
    ([20.0, 0.0, 10.0], 24.36)
    >>> view_sphere([robot, np.array([[100.0, 0, 0]])], margin=2.0)[0].tolist()
    [50.0, 0.0, 10.0]
    """
    points = np.vstack([np.zeros((1, 3)), *parts])
    centre = 0.5 * (points.min(axis=0) + points.max(axis=0))
    reach = float(np.linalg.norm(points - centre, axis=1).max())
    return centre, reach + margin


def inside(points: np.ndarray, centre: np.ndarray, radius: float) -> bool:
    """Whether every point (k, 3) lies within the sphere.

    >>> points = np.array([[1.0, 0, 0], [3.0, 0, 0]])
    >>> inside(points[:1], np.zeros(3), 2.0), inside(points, np.zeros(3), 2.0)
    (True, False)
    """
    if not len(points):
        return True
    return bool((np.linalg.norm(points - centre, axis=1) <= radius).all())


def camera_op() -> Op:
    """Look at the scene from the front right, slightly above (the fit sets the distance
    and keeps this direction).

    >>> camera_op().content["command"]["value"]
    [0.9, 0.6, 0.9]
    """
    return command_op(
        {
            "type": "set_property",
            "path": "/Cameras/default/rotated/<object>",
            "property": "position",
            "value": [0.9, 0.6, 0.9],
        }
    )
