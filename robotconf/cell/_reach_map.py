"""``cell.reach_map`` and ``cell.place``: reach on a voxel grid, and where a base should go.

A reach map asks :func:`~robotconf.cell._reach.reach` at every voxel centre of a box
region (points for arms that reach points; for 6-joint arms, poses with one orientation
of the TCP). Placement moves the robot's base over a grid of positions (its orientation
kept) and asks whether every target is reachable from each; the best base has the
largest least clearance over the targets (each target taking its best branch), ties going
to the larger least manipulability.

Time: ``rc.ik_all`` runs once per voxel (or per base and target); everything after it —
joint limits, the clearance of every branch, manipulability — is one vectorized pass.
"""

from __future__ import annotations

import copy
from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_finite_number, check_vector3, one_line
from ..inverse_kinematics import recognize
from ._answers import Placement, ReachMap
from ._entries import planning_robot
from ._limits import MAX_BASES, MAX_VOXELS
from ._pose import check_pose
from ._reach import POSE_FAMILIES, evaluate_targets, read_targets

if TYPE_CHECKING:
    from ._cell import Cell

__all__ = ["reach_map", "place", "grid_points"]


def grid_points(
    region: Any, step: Any, limit: int, field: str = "region"
) -> tuple[np.ndarray, tuple[int, int, int]]:
    """Voxel centres of a box region ``(low corner, high corner)`` every ``step``.

    >>> points, shape = grid_points([(0, 0, 0), (2, 1, 0)], 1.0, 100)
    >>> shape, points[:2].tolist()
    ((3, 2, 1), [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
    """
    allowed = "(low corner, high corner): two points (x, y, z), low ≤ high"
    if not isinstance(region, (list, tuple, np.ndarray)) or len(region) != 2:
        raise InvalidInputError(field, one_line(region), allowed, problem="not:")
    low = np.array(check_vector3(region[0], f"{field}[0]"))
    high = np.array(check_vector3(region[1], f"{field}[1]"))
    if np.any(high < low):
        raise InvalidInputError(
            field, one_line(region), allowed, problem="a high corner below the low one:"
        )
    spacing = check_finite_number(step, "step")
    if not spacing > 0.0:
        raise InvalidInputError("step", spacing, "a length > 0", problem="must be > 0, got")
    counts = np.floor((high - low) / spacing + 1e-9).astype(float) + 1.0
    if np.prod(counts) > limit:
        raise InvalidInputError(
            "step",
            spacing,
            f"at most {limit} grid points (a larger step or a smaller region)",
            problem=f"{int(np.prod(counts))} grid points with",
        )
    shape = tuple(int(c) for c in counts)
    axes = [low[k] + spacing * np.arange(shape[k]) for k in range(3)]
    points = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    return points, shape  # type: ignore[return-value]


def _orientation(cell: Cell, entry: Any, orientation: Any) -> np.ndarray:
    if orientation is not None:
        array = np.asarray(orientation, dtype=float) if not isinstance(orientation, str) else None
        if array is not None and array.shape == (3, 3):
            padded = np.eye(4)
            padded[:3, :3] = array
            orientation = padded
        return check_pose(orientation, "orientation")[:3, :3]
    robot = planning_robot(entry)
    return (cell.pose_of(entry.name) @ robot.end_effector_pose())[:3, :3]


def reach_map(
    cell: Cell, robot: Any, region: Any, step: Any, *, orientation: Any = None, margin: Any = 0.0
) -> ReachMap:
    """Reach at every voxel of a region.

    Parameters
    ----------
    cell : Cell
    robot : str or None
    region : (low, high)
        Opposite corners of a box in the cell's frame.
    step : float
        Voxel size (length units); at most :data:`~robotconf.cell.MAX_VOXELS` voxels.
    orientation : array-like, optional
        For 6-joint arms: the TCP's orientation at every voxel (3×3 or a pose); default
        its orientation at the robot's own ``q``.
    margin : float
        Clearance a branch needs.

    Examples
    --------
    >>> import robotconf as rc
    >>> cell = rc.Cell()
    >>> cell.add_robot("arm", rc.preset("paper"))
    >>> rmap = cell.reach_map("arm", [(0, 0, 20), (80, 0, 20)], 20)
    >>> rmap.points[:, 0].tolist(), rmap.branches.tolist()
    ([0.0, 20.0, 40.0, 60.0, 80.0], [0, 0, 2, 2, 0])
    """
    entry = cell.robot_entry(robot)
    points, shape = grid_points(region, step, MAX_VOXELS)
    limit = check_finite_number(margin, "margin")
    six = recognize(planning_robot(entry)) in POSE_FAMILIES
    poses = np.broadcast_to(np.eye(4), (len(points), 4, 4)).copy()
    poses[:, :3, 3] = points
    if six:
        poses[:, :3, :3] = _orientation(cell, entry, orientation)
    labels = [f"voxel {k}" for k in range(len(points))]
    result = evaluate_targets(cell, entry, labels, poses, np.full(len(points), six), limit)
    return ReachMap(points, shape, result.collision_free, result.manipulability, result)


def place(
    cell: Cell, robot: Any, targets: Any, region: Any, *, step: Any = None, margin: Any = 0.0
) -> Placement:
    """Where to put a robot's base so that every target is reachable, with most margin.

    Parameters
    ----------
    cell : Cell
    robot : str or None
    targets : frames, points or poses (as for ``cell.reach``)
    region : (low, high)
        Box of base origins to try (cell frame); the base keeps its orientation.
    step : float, optional
        Grid spacing; default a tenth of the region's largest side.
    margin : float
        Clearance each target's branch needs.

    Examples
    --------
    >>> import robotconf as rc
    >>> cell = rc.Cell()
    >>> cell.add_robot("arm", rc.preset("paper"))
    >>> plan = cell.place("arm", [[100, 0, 20], [100, 30, 20]], [(0, 0, 0), (80, 0, 0)], step=20)
    >>> plan.feasible.tolist(), plan.positions[plan.best].tolist()
    ([False, False, True, True, False], [40.0, 0.0, 0.0])
    """
    entry = cell.robot_entry(robot)
    labels, poses, is_pose = read_targets(cell, targets)
    limit = check_finite_number(margin, "margin")
    if step is None:
        sides = (
            np.ptp(np.array([check_vector3(c, "region") for c in region]), axis=0)
            if isinstance(region, (list, tuple)) and len(region) == 2
            else np.ones(3)
        )
        step = max(float(sides.max()) / 10.0, 1e-9) if sides.max() > 0 else 1.0
    positions, shape = grid_points(region, step, MAX_BASES // max(len(labels), 1))
    trial = copy.deepcopy(cell)
    base = cell.pose_of(entry.name)
    parent = cell.parent_of(entry.name)
    up = np.linalg.inv(cell.pose_of(parent)) if parent is not None else np.eye(4)
    count = len(positions)
    feasible = np.zeros(count, dtype=bool)
    reached = np.zeros(count, dtype=int)
    gaps = np.full(count, np.nan)
    manip = np.full(count, np.nan)
    for b, position in enumerate(positions):
        world = base.copy()
        world[:3, 3] = position
        trial.set_pose(entry.name, up @ world)
        result = evaluate_targets(
            trial, trial.robot_entry(entry.name), labels, poses, is_pose, limit
        )
        reached[b] = int(result.reachable.sum())
        if result.all_reachable:
            feasible[b] = True
            gaps[b] = float(np.min(result.clearance))
            manip[b] = float(np.min(result.manipulability))
    best = None
    if feasible.any():
        order = np.lexsort((np.where(feasible, -manip, np.inf), np.where(feasible, -gaps, np.inf)))
        best = int(order[0])
    best_pose = None
    if best is not None:
        best_pose = base.copy()
        best_pose[:3, 3] = positions[best]
    return Placement(positions, shape, feasible, reached, gaps, manip, best, best_pose, cell.unit)
