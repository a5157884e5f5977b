"""The branches of T targets written as the robot's coordinates and checked, as
:func:`robotconf.inverse_kinematics.closed_form._ik_all._finish` does for one target: wrapped,
verified by forward kinematics (all branches of all targets in one call), freed of
duplicates, compared with the joint limits, and each target's reason worded.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..closed_form._ik_all import (
    SAME_TOL,
    VERIFY_TOL,
    failed_reason,
    joint_kinds,
    orientation_error,
    other_turn_note,
    within_limits,
    wrap_angles,
)
from ..geometry._chain_axes import ChainAxes
from ._branches import Branches
from ._vectors import norm

__all__ = ["Finished", "finish_many"]


@dataclass
class Finished:
    """Verified solutions of T targets: ``q`` (R, n), ``labels`` (R,) object,
    ``within`` (R,) bool, ``target`` (R,) the target of each row (ascending), and
    ``reasons`` (T,) as :class:`~robotconf.inverse_kinematics.IKSolutions` words them."""

    q: np.ndarray
    labels: np.ndarray
    within: np.ndarray
    target: np.ndarray
    reasons: list[str]


def _distinct(rows: np.ndarray, keep: np.ndarray, revolute: np.ndarray, scale: np.ndarray):
    """Each target's kept rows (T, B) after dropping the later of two within SAME_TOL."""
    chosen = np.zeros(keep.shape, dtype=bool)
    for i in range(keep.shape[1]):
        ok = keep[:, i].copy()
        for j in range(i):
            gap = rows[:, i] - rows[:, j]
            gap = np.abs(np.where(revolute, wrap_angles(gap), gap)) / scale
            ok &= ~chosen[:, j] | (gap.max(axis=1) > SAME_TOL)
        chosen[:, i] = ok
    return chosen


def finish_many(
    chain: ChainAxes,
    family: str,
    points: np.ndarray,
    turns: np.ndarray | None,
    found: Branches,
) -> Finished:
    """Verify and word the branches of T targets (the degenerate ones are left out: the
    caller asks the one-target solver about them)."""
    robot = chain.robot
    count, width, _ = found.values.shape
    revolute, solved = joint_kinds(chain)
    columns = [joint.column for joint in chain.joints]
    rows = np.broadcast_to(chain.reference, (count, width, robot.n)).copy()
    rows[:, :, columns] = found.values
    rows[:, :, revolute] = wrap_angles(rows[:, :, revolute])
    size = np.maximum(chain.scale, norm(points))
    valid = found.valid & ~found.degenerate[:, np.newaxis]
    owner, branch = np.nonzero(valid)
    poses = robot.end_effector_pose(rows[owner, branch]) if owner.size else np.zeros((0, 4, 4))
    near = norm(poses[:, :3, 3] - points[owner]) <= VERIFY_TOL * size[owner]
    turned = np.zeros(len(owner))
    if turns is not None and owner.size:
        turned = orientation_error(poses[:, :3, :3], turns[owner])
    passed = near & (turned <= VERIFY_TOL)
    keep = np.zeros(valid.shape, dtype=bool)
    keep[owner, branch] = passed
    other_turn = np.bincount(owner[near & ~passed], minlength=count)
    scale = np.where(revolute, 1.0, size[:, np.newaxis])
    chosen = _distinct(rows, keep, revolute, scale)
    reasons = list(found.reasons)
    has_rows = chosen.any(axis=1)
    failed = valid.any(axis=1) & ~keep.any(axis=1)
    starts = np.searchsorted(owner, np.arange(count + 1))
    for t in np.flatnonzero(failed | has_rows).tolist():
        if failed[t]:
            mine = slice(starts[t], starts[t + 1])
            reasons[t] = failed_reason(family, near[mine], turned[mine], poses[mine], points[t])
            continue
        missing = [f"some branches have no solution: {reasons[t]}"] if reasons[t] else []
        if other_turn[t]:
            missing.append(other_turn_note(int(other_turn[t]), family))
        reasons[t] = "; ".join([*found.notes[t], *missing])
    target, branch = np.nonzero(chosen)
    q = rows[target, branch]
    within = within_limits(q, robot.joint_limits(), revolute, solved)
    return Finished(q, found.labels[target, branch], within, target, reasons)
