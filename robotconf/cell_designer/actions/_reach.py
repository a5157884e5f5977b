"""The reach map: on or off, for which robot, over which region, at which step.

The map is :meth:`Cell.reach_map <robotconf.Cell.reach_map>` (one ``rc.ik_all`` per voxel,
about 1–3 ms each), computed when it is switched on, when its controls change and on
**update**; an edit of the cell leaves it drawn and says it is stale, so a drag of a
pose never waits for a map. The designer takes at most :data:`MAX_DESIGNER_VOXELS` voxels
(a few seconds); the count is checked before any work, and a larger grid is refused
beside the step with the count.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_finite_number
from ...kinematics import characteristic_length
from ..state import DesignerState, ReachOutcome, ReachSetup
from ._base import Action, nice
from ._moves import robot_item

__all__ = [
    "MAX_DESIGNER_VOXELS",
    "SetReachMap",
    "SetReachRobot",
    "SetReachCorner",
    "SetReachStep",
    "UpdateReachMap",
    "reach_region",
    "voxel_count",
]

#: The most voxels one map of the designer may have (``cell.reach_map`` in a notebook
#: cell takes up to :data:`robotconf.cell.MAX_VOXELS`).
MAX_DESIGNER_VOXELS = 2000
#: The default grid's most voxels (about a second for a 3-joint arm on a laptop).
DEFAULT_VOXELS = 600
#: Default steps tried, finest first, in multiples of a tenth of the robot's size.
_STEPS = (1.0, 2.0, 2.5, 5.0, 10.0, 20.0, 25.0, 50.0)

Corner = tuple[float, float, float]


def voxel_count(low: Corner, high: Corner, step: float) -> int:
    """Voxels of the grid ``cell.reach_map`` lays over ``(low, high)`` every ``step``.

    >>> voxel_count((0, 0, 0), (80, 80, 40), 20)
    75
    """
    counts = np.floor((np.array(high) - np.array(low)) / step + 1e-9) + 1.0
    return int(np.prod(np.maximum(counts, 0.0)))


def reach_region(state: DesignerState, setup: ReachSetup) -> tuple[str, Corner, Corner, float]:
    """``(robot, low, high, step)`` the map uses: the controls, and for what is not set,
    a box around the robot's base one robot size out (below the base a quarter of it),
    on the finest grid of 1, 2 or 5 × 10^k with at most :data:`DEFAULT_VOXELS` voxels.

    >>> from robotconf.cell_designer.actions import AddRobot
    >>> reach_region(AddRobot("paper").apply(DesignerState()), ReachSetup())
    ('paper', (-100.0, -100.0, -25.0), (100.0, 100.0, 100.0), 25.0)
    """
    robots = state.cell.robots
    robot = setup.robot if setup.robot in robots else (robots[0] if robots else None)
    if robot is None:
        raise InvalidInputError("reach.robot", None, "a robot of the cell: add one first")
    item = robot_item(state, robot)
    size = characteristic_length(item.robot)
    base = state.cell.cell.pose_of(robot)[:3, 3]

    def snapped(values: np.ndarray, rounding: Any, step: float) -> Corner:
        x, y, z = (float(rounding(v / step) * step) + 0.0 for v in values)
        return (x, y, z)

    start = nice(size / 10.0)
    steps = [setup.step] if setup.step is not None else [start * m for m in _STEPS]
    for step in steps:
        low = setup.low or snapped(base - (size, size, 0.25 * size), math.floor, step)
        high = setup.high or snapped(base + (size, size, size), math.ceil, step)
        if voxel_count(low, high, step) <= DEFAULT_VOXELS:
            break
    return robot, low, high, step


def _computed(state: DesignerState, setup: ReachSetup) -> DesignerState:
    """The state with ``setup`` and, when it is on, its map (the count checked first)."""
    if not setup.on:
        return state.replace(reach=setup)
    robot, low, high, step = reach_region(state, setup)
    if any(h < lo for lo, h in zip(low, high, strict=True)):
        raise InvalidInputError(
            "reach.high", high, f"a corner at or above the low one {low}", "below the low corner:"
        )
    count = voxel_count(low, high, step)
    if count > MAX_DESIGNER_VOXELS:
        raise InvalidInputError(
            "reach.step",
            step,
            f"at most {MAX_DESIGNER_VOXELS} voxels here (a larger step or a smaller "
            "region; cell.reach_map in a notebook cell takes more)",
            problem=f"{count} voxels with step",
        )
    result = state.cell.cell.reach_map(robot, [low, high], step)
    return state.replace(reach=setup, reach_map=ReachOutcome(result, state.cell, setup))


@dataclass(frozen=True)
class SetReachMap(Action):
    """Switch the map on (computed now) or off (taken from the view)."""

    on: bool

    def apply(self, state: DesignerState) -> DesignerState:
        return _computed(state, replace(state.reach, on=bool(self.on)))


@dataclass(frozen=True)
class SetReachRobot(Action):
    """The robot whose reach is mapped; the region goes back to the default around it."""

    robot: str

    def apply(self, state: DesignerState) -> DesignerState:
        robot_item(state, self.robot)
        return _computed(state, ReachSetup(state.reach.on, self.robot))


@dataclass(frozen=True)
class SetReachCorner(Action):
    """One coordinate (``axis`` 0, 1, 2) of the low (``corner`` 0) or high (1) corner."""

    corner: int
    axis: int
    value: float

    def apply(self, state: DesignerState) -> DesignerState:
        value = check_finite_number(self.value, "reach." + ("low", "high")[self.corner])
        _, low, high, step = reach_region(state, state.reach)
        point = list((low, high)[self.corner])
        point[self.axis] = value
        corners = [low, high]
        corners[self.corner] = (point[0], point[1], point[2])
        setup = replace(state.reach, low=corners[0], high=corners[1], step=step)
        return _computed(state, setup)


@dataclass(frozen=True)
class SetReachStep(Action):
    """The voxel size (length units, > 0)."""

    step: float

    def apply(self, state: DesignerState) -> DesignerState:
        step = check_finite_number(self.step, "reach.step")
        if not step > 0.0:
            raise InvalidInputError("reach.step", step, "a length > 0", "must be > 0, got")
        _, low, high, _ = reach_region(state, state.reach)
        return _computed(state, replace(state.reach, low=low, high=high, step=step))


@dataclass(frozen=True)
class UpdateReachMap(Action):
    """Compute the map again for the cell as it is now."""

    def apply(self, state: DesignerState) -> DesignerState:
        return _computed(state, replace(state.reach, on=True))
