"""Point clouds in the scene (e.g. a sampled workspace), as three.js points.

:class:`PointClouds` is the part of :class:`~robotconf.scene.Scene` that draws them under
``/meshcat/robotconf/clouds/<name>`` and remembers each cloud's bounding box, so the view
can be fitted to hold them.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import as_float_array
from ._commands import ROOT, Op, Outbox, set_object_op
from ._three import point_cloud

__all__ = ["PointClouds", "point_cloud_op", "MAX_POINTS"]

#: Points drawn at most (a browser handles this many smoothly).
MAX_POINTS = 2_000_000


def point_cloud_op(path: str, points: Any, color: Any, size: float) -> Op:
    """A packed meshcat ``set_object`` command for a point cloud.

    Parameters
    ----------
    path : str
    points : array-like, shape (N, 3)
        Positions (length units).
    color : array-like, shape (3,) or (N, 3)
        RGB in 0…1.
    size : float
        Point size (length units).
    """
    xyz = as_float_array(points, "points", "an (N, 3) array of positions")
    if xyz.ndim != 2 or xyz.shape[1] != 3 or not 0 < len(xyz) <= MAX_POINTS:
        raise InvalidInputError(
            "points", f"shape {xyz.shape}", f"shape (N, 3) with 1 ≤ N ≤ {MAX_POINTS}"
        )
    rgb = as_float_array(color, "color", "RGB values in 0…1")
    if rgb.shape == (3,):
        rgb = np.broadcast_to(rgb, xyz.shape)
    if rgb.shape != xyz.shape or np.any((rgb < 0) | (rgb > 1)):
        raise InvalidInputError("color", color, "RGB values in 0…1, shape (3,) or (N, 3)")
    return set_object_op(path, point_cloud(xyz, rgb, size))


class PointClouds:
    """Named point clouds beside the robot.

    Examples
    --------
    >>> from robotconf.scene import RecordingChannel
    >>> clouds = PointClouds(Outbox(RecordingChannel()))
    >>> clouds.add("workspace", [[0, 0, 0], [1, 2, 3]], (0.2, 0.4, 0.9), 0.1)
    >>> clouds.extent().min(axis=0).tolist(), clouds.extent().max(axis=0).tolist()
    ([0.0, 0.0, 0.0], [1.0, 2.0, 3.0])
    """

    def __init__(self, outbox: Outbox) -> None:
        self._outbox = outbox
        self._corners: dict[str, np.ndarray] = {}

    def add(self, name: str, points: Any, color: Any, size: float) -> None:
        """Draw ``points`` (N, 3) as cloud ``name``, replacing one of that name."""
        path = f"{ROOT}/clouds/{_clean_name(name)}"
        self._outbox.send([point_cloud_op(path, points, color, size)])
        xyz = np.asarray(points, dtype=float)
        low, high = xyz.min(axis=0), xyz.max(axis=0)
        # The bounding box's 8 corners: the view that holds them holds the cloud.
        self._corners[name] = np.array(
            [[(low, high)[b >> k & 1][k] for k in range(3)] for b in range(8)]
        )

    def extent(self) -> np.ndarray:
        """The corners of every cloud's bounding box, shape (8 × clouds, 3)."""
        return np.vstack([np.zeros((0, 3)), *self._corners.values()])


def _clean_name(name: Any) -> str:
    if not isinstance(name, str) or not name or not all(c.isalnum() or c in "_-" for c in name):
        raise InvalidInputError("name", name, "letters, digits, '_' or '-'")
    return name
