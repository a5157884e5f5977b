"""A reach map in the scene: every voxel a point, coloured by what reaches it.

:class:`ReachMapLayer` draws a :class:`~robotconf.cell.ReachMap` (``cell.reach_map``) as
two point clouds under ``…/cell/reach``: the voxels no branch reaches, faint grey, and
the others coloured from light to dark green by how many collision-free branches within
the joint limits reach them (or, ``color_by="manipulability"``, from yellow to purple by
the best branch's manipulability). A legend label above the region says what the
colours mean. Points are half a voxel across.
"""

from __future__ import annotations

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import one_line
from ...cell import ReachMap
from .._commands import Op, Outbox, labels_op, set_object_op, transform_command
from .._ghosts import faint
from .._three import label_anchor, point_cloud
from ._paths import REACH

__all__ = ["ReachMapLayer", "reach_colors", "COLOR_BY", "UNREACHED_RGB", "voxel_step"]

#: What the reachable voxels' colours show.
COLOR_BY = ("branches", "manipulability")
#: The unreachable voxels: grey, at this opacity.
UNREACHED_RGB = (0.62, 0.62, 0.62)
UNREACHED_OPACITY = 0.25
#: Colour ramps, from the least to the most: light to dark green (branches), yellow to
#: purple (manipulability, viridis's ends).
RAMPS = {
    "branches": (np.array([0.74, 0.93, 0.66]), np.array([0.0, 0.42, 0.13])),
    "manipulability": (np.array([0.99, 0.91, 0.14]), np.array([0.27, 0.0, 0.33])),
}
#: Words of the ramps' ends in the legend.
RAMP_WORDS = {"branches": ("light green", "dark green"), "manipulability": ("yellow", "purple")}


def reach_colors(values: np.ndarray, color_by: str) -> np.ndarray:
    """RGB (V, 3) of reachable voxels' ``values`` (branches ≥ 1, or manipulability ≥ 0):
    the ramp's start at the least value, its end at the most (all at the end when they
    are equal).

    >>> reach_colors(np.array([1, 2, 3]), "branches")[[0, 2]].round(2).tolist()
    [[0.74, 0.93, 0.66], [0.0, 0.42, 0.13]]
    """
    low_color, high_color = RAMPS[color_by]
    values = np.asarray(values, dtype=float)
    least, most = float(values.min()), float(values.max())
    share = np.ones_like(values) if most <= least else (values - least) / (most - least)
    return low_color + share[:, None] * (high_color - low_color)


def voxel_step(reach_map: ReachMap) -> float:
    """The grid's spacing: the least gap between neighbouring voxel centres (0 for a
    grid of one voxel).

    >>> import robotconf as rc
    >>> cell = rc.Cell(); cell.add_robot("arm", rc.preset("paper"))
    >>> voxel_step(cell.reach_map("arm", [(0, 0, 20), (80, 0, 20)], 20))
    20.0
    """
    grid = reach_map.points.reshape(*reach_map.shape, 3)
    gaps = []
    for axis in range(3):
        if reach_map.shape[axis] > 1:
            step = np.diff(np.take(grid, [0, 1], axis=axis), axis=axis)
            gaps.append(float(np.linalg.norm(step.reshape(-1, 3)[0])))
    return min(gaps, default=0.0)


class ReachMapLayer:
    """A reach map's voxels as coloured points, with a legend.

    Parameters
    ----------
    outbox : Outbox

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import RecordingChannel
    >>> cell = rc.Cell(unit="mm"); cell.add_robot("arm", rc.preset("paper"))
    >>> layer = ReachMapLayer(Outbox(RecordingChannel()))
    >>> layer.show(cell.reach_map("arm", [(0, 0, 20), (80, 0, 20)], 20), "branches", 1.0)
    >>> layer.legend
    'reach map: 2 of 5 voxels reachable; branches 2 (light green) … 2 (dark green); grey: none'
    """

    def __init__(self, outbox: Outbox) -> None:
        self._outbox = outbox
        self.shown = False
        self.legend = ""
        self._corners = np.zeros((0, 3))

    def show(self, reach_map: ReachMap, color_by: str, fallback_size: float) -> None:
        """Draw ``reach_map`` (replacing one shown); ``fallback_size`` is the point size
        (length units) of a map of one voxel."""
        if not isinstance(reach_map, ReachMap):
            raise InvalidInputError(
                "reach_map", one_line(reach_map), "a ReachMap from cell.reach_map(...)"
            )
        if color_by not in COLOR_BY:
            raise InvalidInputError(
                "color_by", one_line(color_by), "'branches' or 'manipulability'"
            )
        self.clear()
        points = reach_map.points
        step = voxel_step(reach_map) or fallback_size
        reached = reach_map.branches > 0
        ops: list[Op] = []
        if (~reached).any():
            grey = np.broadcast_to(UNREACHED_RGB, (int((~reached).sum()), 3))
            cloud = faint(point_cloud(points[~reached], grey, 0.3 * step), UNREACHED_OPACITY)
            ops.append(set_object_op(f"{REACH}/unreached", cloud))
        values = (
            reach_map.branches[reached]
            if color_by == "branches"
            else np.nan_to_num(reach_map.manipulability[reached])
        )
        if reached.any():
            colors = reach_colors(values, color_by)
            ops.append(
                set_object_op(f"{REACH}/reached", point_cloud(points[reached], colors, 0.5 * step))
            )
        self.legend = _legend(int(reached.sum()), len(points), values, color_by)
        anchor = f"{REACH}/legend"
        top = points.max(axis=0)
        low = points.min(axis=0)
        where = np.array([0.5 * (low[0] + top[0]), 0.5 * (low[1] + top[1]), top[2] + step])
        ops.append(set_object_op(anchor, label_anchor(0.5 * step)))
        matrix = np.eye(4)
        matrix[:3, 3] = where
        ops += [transform_command(anchor, matrix), labels_op([anchor], [self.legend])]
        self._outbox.send(ops)
        self.shown = True
        self._corners = np.vstack([low, top, where])

    def clear(self) -> None:
        """Remove the reach map."""
        if self.shown:
            self._outbox.delete(REACH)
        self.shown = False
        self.legend = ""
        self._corners = np.zeros((0, 3))

    def extent(self) -> np.ndarray:
        """The map's lowest and highest corners and its legend's point, (k, 3)."""
        return self._corners


def _legend(reached: int, total: int, values: np.ndarray, color_by: str) -> str:
    head = f"reach map: {reached} of {total} voxels reachable"
    if not reached:
        return head + "; grey: none"
    low_word, high_word = RAMP_WORDS[color_by]
    if color_by == "branches":
        low, high = f"{int(values.min())}", f"{int(values.max())}"
    else:
        low, high = f"{values.min():.3g}", f"{values.max():.3g}"
    return f"{head}; {color_by} {low} ({low_word}) … {high} ({high_word}); grey: none"
