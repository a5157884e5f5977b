"""Point clouds in the scene (e.g. a sampled workspace), as three.js points."""

from __future__ import annotations

from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import as_float_array
from ._commands import Op, set_object_op
from ._three import point_cloud

__all__ = ["point_cloud_op", "MAX_POINTS"]

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
