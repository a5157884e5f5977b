"""``cell.reach``: can a robot reach each target, with how many branches, and why not.

For every target (a cell frame, a point or a pose of the TCP in the cell's frame) the
closed forms list every branch in the robot's base frame (``rc.ik_all_many``, all
targets in one vectorized call); a branch counts when it lies within the joint limits
(``within_limits``) and its clearance (``cell.clearance``, all branches of all targets in
one call) is at least ``margin``.
The best branch has the largest manipulability, Yoshikawa's ``√det(J Jᵀ)`` of the
steered rows of the TCP's Jacobian (the linear rows for a point, all six for a pose);
of branches within 1e-9 of it (mirror images often tie) the first.

A 6-joint arm (spherical wrist, UR) needs poses; the 3R elbow arm and planar 2R reach
points, and a pose's orientation is left aside for them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np

from .._errors import InvalidInputError
from .._validation import as_float_array, check_finite_number, one_line
from ..inverse_kinematics import IKSolutionSets, ik_all, ik_all_many, recognize
from ._answers import Reach, format_length
from ._entries import RobotEntry, planning_robot
from ._limits import MAX_TARGETS
from ._pose import check_pose

if TYPE_CHECKING:
    from ._cell import Cell

__all__ = [
    "reach",
    "evaluate_targets",
    "read_targets",
    "solve_targets",
    "targets_in_base",
    "branch_clearances",
    "summarize",
    "Summary",
    "POSE_FAMILIES",
    "POINT_FAMILIES",
]

#: Families whose closed forms need a pose target.
POSE_FAMILIES = ("spherical-wrist 6R", "UR")

#: Families that reach points only (a pose gives its point).
POINT_FAMILIES = ("3R elbow", "planar 2R")

#: Manipulabilities within this fraction of the largest count as equal (the first
#: branch of equals is the best).
TIE = 1e-9

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


def targets_in_base(entry: RobotEntry, base_world: np.ndarray, poses: np.ndarray) -> np.ndarray:
    """:func:`~robotconf.cell._entries.target_in_base` for poses (K, 4, 4) at once, seen
    from one base (4, 4) or from each of B bases (B, 4, 4): (K, 4, 4) or (B·K, 4, 4),
    base slowest."""
    turn = np.swapaxes(base_world[..., :3, :3], -1, -2)
    inverse = np.zeros(base_world.shape)
    inverse[..., :3, :3] = turn
    inverse[..., :3, 3] = -(turn @ base_world[..., :3, 3, np.newaxis])[..., 0]
    inverse[..., 3, 3] = 1.0
    local = (inverse[..., np.newaxis, :, :] @ poses).reshape(-1, 4, 4)
    if entry.tool is not None:
        local[:, :3, :3] = local[:, :3, :3] @ entry.tool.tcp[:3, :3].T
    return local


def _solve_kinds(robot: Any, local: np.ndarray, wants_pose: np.ndarray) -> IKSolutionSets:
    """``rc.ik_all_many`` of poses where ``wants_pose``, of their points elsewhere."""
    if wants_pose.all() or not wants_pose.any():
        return ik_all_many(robot, local if wants_pose.all() else local[:, :3, 3])
    poses, points = np.flatnonzero(wants_pose), np.flatnonzero(~wants_pose)
    parts = [
        (poses, ik_all_many(robot, local[poses])),
        (points, ik_all_many(robot, local[points, :3, 3])),
    ]
    target = np.concatenate([index[sets.target] for index, sets in parts])
    order = np.argsort(target, kind="stable")
    reasons = [""] * len(local)
    for index, sets in parts:
        for k, text in zip(index.tolist(), sets.reasons, strict=True):
            reasons[k] = text
    labels = np.array([label for _, sets in parts for label in sets.labels], dtype=object)
    return IKSolutionSets(
        q=np.concatenate([sets.q for _, sets in parts])[order],
        labels=tuple(labels[order].tolist()),
        within_limits=np.concatenate([sets.within_limits for _, sets in parts])[order],
        target=target[order],
        counts=np.bincount(target, minlength=len(local)),
        reasons=tuple(reasons),
        family=parts[0][1].family,
    )


def _within_targets(error: InvalidInputError, count: int) -> InvalidInputError:
    """A batch's error about ``targets[i]`` (of ``count`` targets, repeated per base)
    named as the cell's target, as a one-target call's error reads there."""
    if not error.field.startswith("targets["):
        return error
    i = int(error.field[len("targets[") : error.field.index("]")]) % count
    return InvalidInputError(f"targets[{i}].target", error.value, error.allowed, error.problem)


def solve_targets(
    entry: RobotEntry, base_world: np.ndarray, poses: np.ndarray, is_pose: np.ndarray
) -> tuple[Any, str | None, IKSolutionSets]:
    """Every closed-form branch of every target (poses (K, 4, 4) in the cell's frame) in
    the robot's base frame, in one vectorized call (``rc.ik_all_many``); ``base_world``
    (B, 4, 4) solves them from B bases at once (target ``b·K + k`` of the answer)."""
    robot = planning_robot(entry)
    family = recognize(robot)
    local = targets_in_base(entry, base_world, poses)
    if family is None:
        try:  # the one-target call says why there is no closed form
            ik_all(robot, local[0])
        except InvalidInputError as error:
            raise error.within("targets[0]") from None
    if family in POSE_FAMILIES and not is_pose.all():
        k = int(np.flatnonzero(~is_pose)[0])
        raise InvalidInputError(
            f"targets[{k}]",
            one_line(poses[k][:3, 3]),
            f"a pose or a frame for a {family} arm",
            problem="a point leaves the orientation open:",
        )
    wants_pose = np.tile(is_pose & (family not in POINT_FAMILIES), len(local) // len(poses))
    try:
        sets = _solve_kinds(robot, local, wants_pose)
    except InvalidInputError as error:
        raise _within_targets(error, len(poses)) from None
    return robot, family, sets


def _manipulability(robot: Any, q: np.ndarray, full: np.ndarray) -> np.ndarray:
    if not len(q):
        return np.zeros(0)
    jac = robot.jacobian(q)
    linear = np.linalg.det(jac[:, :3] @ np.swapaxes(jac[:, :3], 1, 2))
    whole = np.linalg.det(jac @ np.swapaxes(jac, 1, 2))
    return np.sqrt(np.maximum(np.where(full, whole, linear), 0.0))


def _why_not(
    reason: str,
    labels: tuple[str, ...],
    ok_limits: np.ndarray,
    gaps: np.ndarray,
    hits: list[str],
    unit: str | None,
) -> str:
    if len(labels) == 0:
        return reason or "no closed-form solution"
    if not ok_limits.any():
        return f"every branch leaves the joint limits ({', '.join(labels)})"
    parts = [
        f"the {label}, which hits {other} ({format_length(-gap, unit)} deep)"
        if gap < 0
        else f"the {label}, which comes within {format_length(gap, unit)} of {other}"
        for label, gap, other, ok in zip(labels, gaps, hits, ok_limits, strict=True)
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


def branch_clearances(cell: Cell, name: str, q: np.ndarray, within: np.ndarray):
    """Each branch's clearance (``inf`` outside the limits, not measured) and what it is
    nearest, one ``cell.clearance`` call for all the branches within the limits."""
    gaps = np.full(len(q), np.inf)
    hits = [""] * len(q)
    if within.any():
        found = cell.clearance(name, q[within])
        gaps[within] = found.distance
        for i, other in zip(np.flatnonzero(within).tolist(), found.other, strict=True):
            hits[i] = f"'{other}'"
    return gaps, hits


class Summary(NamedTuple):
    """Per target (K,): usable branches and the best one; per branch (R,): usable."""

    free: np.ndarray
    collision_free: np.ndarray
    manipulability: np.ndarray
    q: np.ndarray
    clearance: np.ndarray


def summarize(
    plan: Any,
    family: str | None,
    sets: IKSolutionSets,
    is_pose: np.ndarray,
    gaps: np.ndarray,
    margin: float,
) -> Summary:
    """Which branches count (within the limits, clearance ≥ ``margin``) and each target's
    best: the largest manipulability (the first branch within :data:`TIE` of it), and
    the target's largest clearance."""
    rows, owner, size = sets.q, sets.target, len(sets)
    free = sets.within_limits & (gaps >= margin)
    manip = np.full(len(rows), np.nan)
    full = is_pose[owner] & (family not in POINT_FAMILIES)
    manip[free] = _manipulability(plan, rows[free], full[free])
    best_q = np.full((size, plan.n), np.nan)
    best_m = np.full(size, np.nan)
    best_gap = np.full(size, np.nan)
    usable = np.flatnonzero(free)
    if usable.size:
        most = np.full(size, -np.inf)
        np.maximum.at(most, owner[usable], manip[usable])
        # Mirror branches (elbow up and down) often have the same manipulability: the
        # first branch within round-off of the largest wins, not the round-off.
        close = usable[manip[usable] >= most[owner[usable]] * (1.0 - TIE)]
        first = close[np.r_[True, owner[close][1:] != owner[close][:-1]]]
        best_q[owner[first]], best_m[owner[first]] = rows[first], manip[first]
        widest = np.full(size, -np.inf)
        np.maximum.at(widest, owner[usable], gaps[usable])
        best_gap[owner[first]] = widest[owner[first]]
    counted = np.bincount(owner, free, size).astype(int) if len(owner) else np.zeros(size, int)
    return Summary(free, counted, best_m, best_q, best_gap)


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
    plan, family, sets = solve_targets(entry, base_world, poses, is_pose)
    gaps, hits = branch_clearances(cell, entry.name, sets.q, sets.within_limits)
    best = summarize(plan, family, sets, is_pose, gaps, margin)
    size, owner = len(sets), sets.target
    starts = np.concatenate([[0], np.cumsum(sets.counts)]).tolist()
    reasons, names = [], []
    for k in range(size):
        mine = slice(starts[k], starts[k + 1])
        ok = best.free[mine]
        branch = sets.labels[mine]
        names.append(tuple(label for label, good in zip(branch, ok.tolist(), strict=True) if good))
        if best.collision_free[k]:
            reasons.append("")
            continue
        reasons.append(
            _why_not(
                sets.reasons[k], branch, sets.within_limits[mine], gaps[mine], hits[mine], cell.unit
            )
        )
    within = sets.within_limits
    return Reach(
        tuple(labels),
        best.collision_free > 0,
        sets.counts.copy(),
        np.bincount(owner, within, size).astype(int) if len(owner) else np.zeros(size, int),
        best.collision_free,
        best.manipulability,
        best.q,
        best.clearance,
        tuple(names),
        tuple(reasons),
    )
