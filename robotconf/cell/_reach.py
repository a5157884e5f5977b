"""``cell.reach``: can a robot reach each target, with how many branches, and why not.

For every target (a cell frame, a point or a pose of the TCP in the cell's frame) the
closed forms ``rc.ik_all`` list every branch in the robot's base frame; a branch counts
when it lies within the joint limits (``IKSolutions.within_limits``) and its clearance
(``cell.clearance``, all branches of all targets in one call) is at least ``margin``.
The best branch has the largest manipulability, Yoshikawa's ``√det(J Jᵀ)`` of the
steered rows of the TCP's Jacobian (the linear rows for a point, all six for a pose).

A 6-joint arm (spherical wrist, UR) needs poses; the 3R elbow arm and planar 2R reach
points, and a pose's orientation is left aside for them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import as_float_array, check_finite_number, one_line
from ..inverse_kinematics import ik_all, recognize
from ._answers import Reach, format_length
from ._entries import RobotEntry, planning_robot, target_in_base
from ._limits import MAX_TARGETS
from ._pose import check_pose

if TYPE_CHECKING:
    from ._cell import Cell

__all__ = ["reach", "evaluate_targets", "read_targets", "POSE_FAMILIES", "POINT_FAMILIES"]

#: Families whose closed forms need a pose target.
POSE_FAMILIES = ("spherical-wrist 6R", "UR")

#: Families that reach points only (a pose gives its point).
POINT_FAMILIES = ("3R elbow", "planar 2R")

_TARGETS = "a frame name, a point (3,), a pose (4, 4), or a list of them"


def read_targets(cell: Cell, targets: Any) -> tuple[list[str], np.ndarray, np.ndarray]:
    """Labels, poses in the cell's frame (K, 4, 4) and whether each is a pose (K,)."""
    if isinstance(targets, str):
        targets = [targets]
    elif not isinstance(targets, (list, tuple)):
        array = as_float_array(targets, "targets", _TARGETS)
        if array.shape in ((3,), (4, 4)):
            targets = [array]
        elif array.ndim in (2, 3) and array.shape[1:] in ((3,), (4, 4)):
            targets = list(array)
        else:
            raise InvalidInputError(
                "targets", one_line(targets), _TARGETS, problem=f"shape {array.shape}:"
            )
    if not 1 <= len(targets) <= MAX_TARGETS:
        raise InvalidInputError(
            "targets", f"<{len(targets)} targets>", f"1 to {MAX_TARGETS} targets"
        )
    labels, poses, is_pose = [], [], []
    for i, item in enumerate(targets):
        field = f"targets[{i}]"
        if isinstance(item, str):
            poses.append(cell.pose_of(item) if item in cell.entries else cell._entry(item, field))
            labels.append(item)
            is_pose.append(True)
            continue
        array = as_float_array(item, field, _TARGETS)
        if array.shape == (3,):
            if not np.all(np.isfinite(array)):
                raise InvalidInputError(field, one_line(item), "finite coordinates")
            pose = np.eye(4)
            pose[:3, 3] = array
            poses.append(pose)
            labels.append("(" + ", ".join(f"{v:.4g}" for v in array) + ")")
            is_pose.append(False)
        else:
            pose = check_pose(array, field)
            poses.append(pose)
            labels.append("pose at (" + ", ".join(f"{v:.4g}" for v in pose[:3, 3]) + ")")
            is_pose.append(True)
    return labels, np.array(poses), np.array(is_pose, dtype=bool)


def solve_targets(
    entry: RobotEntry, base_world: np.ndarray, poses: np.ndarray, is_pose: np.ndarray
):
    """``rc.ik_all`` of every target in the robot's base frame: a list of IKSolutions."""
    robot = planning_robot(entry)
    family = recognize(robot)
    solutions = []
    for k in range(len(poses)):
        local = target_in_base(entry, base_world, poses[k])
        if family in POSE_FAMILIES and not is_pose[k]:
            raise InvalidInputError(
                f"targets[{k}]",
                one_line(poses[k][:3, 3]),
                f"a pose or a frame for a {family} arm",
                problem="a point leaves the orientation open:",
            )
        wants_pose = is_pose[k] and family not in POINT_FAMILIES
        try:
            solutions.append(ik_all(robot, local if wants_pose else local[:3, 3]))
        except InvalidInputError as error:
            raise error.within(f"targets[{k}]") from None
    return robot, family, solutions


def _manipulability(robot: Any, q: np.ndarray, full: np.ndarray) -> np.ndarray:
    if not len(q):
        return np.zeros(0)
    jac = robot.jacobian(q)
    linear = np.linalg.det(jac[:, :3] @ np.swapaxes(jac[:, :3], 1, 2))
    whole = np.linalg.det(jac @ np.swapaxes(jac, 1, 2))
    return np.sqrt(np.maximum(np.where(full, whole, linear), 0.0))


def _why_not(
    k: int, sols: Any, ok_limits: np.ndarray, gaps: np.ndarray, hits: list[str], unit: str | None
) -> str:
    if len(sols) == 0:
        return sols.reason or "no closed-form solution"
    if not ok_limits.any():
        return f"every branch leaves the joint limits ({', '.join(sols.labels)})"
    parts = [
        f"the {label}, which hits {other} ({format_length(-gap, unit)} deep)"
        if gap < 0
        else f"the {label}, which comes within {format_length(gap, unit)} of {other}"
        for label, gap, other, ok in zip(sols.labels, gaps, hits, ok_limits, strict=True)
        if ok
    ]
    return "only with " + " and ".join(parts)


def reach(cell: Cell, robot: Any, targets: Any, *, margin: Any = 0.0) -> Reach:
    """Which targets a robot reaches within its limits and without collision.

    Parameters
    ----------
    cell : Cell
    robot : str or None
    targets : str, array-like or list
        Frame names, points (3,) or poses (4, 4) of the TCP in the cell's frame.
    margin : float
        The clearance a branch needs (length units).

    Returns
    -------
    Reach

    Examples
    --------
    >>> import robotconf as rc
    >>> cell = rc.Cell(unit="mm")
    >>> cell.add_robot("arm", rc.preset("paper"), mount="table")  # its column stands on it
    >>> cell.add(rc.Box([200, 200, 10], pose=rc.pose([0, 0, -5]), name="table"))
    'table'
    >>> result = cell.reach("arm", [[50, 0, 10], [100, 0, 20]])
    >>> result.reachable, result.branches
    (array([ True, False]), array([4, 0]))
    >>> print(result.reasons[1])
    the target is 30 beyond the reach: ...
    """
    entry = cell.robot_entry(robot)
    labels, poses, is_pose = read_targets(cell, targets)
    return evaluate_targets(
        cell, entry, labels, poses, is_pose, check_finite_number(margin, "margin")
    )


def evaluate_targets(
    cell: Cell,
    entry: RobotEntry,
    labels: list[str],
    poses: np.ndarray,
    is_pose: np.ndarray,
    margin: float,
) -> Reach:
    """:func:`reach` for targets already read (poses in the cell's frame)."""
    base_world = cell.pose_of(entry.name)
    plan, family, solutions = solve_targets(entry, base_world, poses, is_pose)
    counts = np.array([len(s) for s in solutions])
    rows = np.concatenate([s.q for s in solutions]) if counts.sum() else np.zeros((0, plan.n))
    owner = np.repeat(np.arange(len(solutions)), counts)
    within = (
        np.concatenate([s.within_limits for s in solutions]) if counts.sum() else np.zeros(0, bool)
    )
    gaps = np.full(len(rows), np.inf)
    hits = [""] * len(rows)
    if within.any():
        found = cell.clearance(entry.name, rows[within])
        gaps[within] = found.distance
        for i, other in zip(np.flatnonzero(within), found.other, strict=True):
            hits[i] = f"'{other}'"
    free = within & (gaps >= margin)
    manip = np.full(len(rows), np.nan)
    full = is_pose[owner] & (family not in POINT_FAMILIES)
    manip[free] = _manipulability(plan, rows[free], full[free])
    size = len(solutions)
    best_q = np.full((size, plan.n), np.nan)
    best_m = np.full(size, np.nan)
    best_gap = np.full(size, np.nan)
    reasons, names = [], []
    for k, sols in enumerate(solutions):
        mine = owner == k
        ok = free[mine]
        names.append(tuple(label for label, good in zip(sols.labels, ok, strict=True) if good))
        if ok.any():
            pick = np.flatnonzero(mine)[np.nanargmax(np.where(ok, manip[mine], -np.inf))]
            best_q[k], best_m[k] = rows[pick], manip[pick]
            best_gap[k] = np.max(gaps[mine][ok])
            reasons.append("")
        else:
            reasons.append(
                _why_not(
                    k,
                    sols,
                    within[mine],
                    gaps[mine],
                    [hits[i] for i in np.flatnonzero(mine)],
                    cell.unit,
                )
            )
    count = np.bincount
    return Reach(
        tuple(labels),
        np.array([r == "" for r in reasons]),
        counts,
        count(owner, within, size).astype(int) if len(owner) else np.zeros(size, int),
        count(owner, free, size).astype(int) if len(owner) else np.zeros(size, int),
        best_m,
        best_q,
        best_gap,
        tuple(names),
        tuple(reasons),
    )
