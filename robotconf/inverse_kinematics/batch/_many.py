"""``ik_all_many``: every closed-form solution of many targets, vectorized over them.

The robot's joint lines and family are read once (and kept, per robot geometry); the
family's branches are then computed for all targets at once, a chunk at a time, and
checked by one forward-kinematics call per chunk. A target that meets a degenerate case
(a double root, a joint left free on its axis, a wrist singularity: a set of measure
zero, but a grid may hit it) is answered by the one-target :func:`ik_all`, which words
those cases.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from ..._budget import check_memory
from ..closed_form._ik_all import ik_all
from ..closed_form._recognize import NotClosedForm, closed_form_structure, refuse
from ..geometry._chain_axes import ChainAxes
from ._arm import solve_elbow_many
from ._branches import Branches
from ._finish import Finished, finish_many
from ._plane import solve_planar_many
from ._sets import IKSolutionSets
from ._targets import TargetsMany, read_targets_many
from ._wrist import solve_spherical_wrist_many, solve_ur_many

__all__ = ["ik_all_many", "CHUNK", "ik_all_many_bytes"]

#: Targets solved together: enough to amortize numpy's per-call cost, few enough that the
#: working arrays (about 3 kB per target) stay small.
CHUNK = 2048

SolverMany = Callable[[ChainAxes, np.ndarray, np.ndarray | None, str], Branches]

SOLVERS_MANY: dict[str, SolverMany] = {
    "planar 2R": solve_planar_many,
    "planar 3R": solve_planar_many,
    "SCARA": solve_planar_many,
    "3R elbow": solve_elbow_many,
    "spherical-wrist 6R": solve_spherical_wrist_many,
    "UR": solve_ur_many,
}


def ik_all_many_bytes(targets: int, n: int) -> float:
    """Peak bytes of :func:`ik_all_many` for ``targets`` targets of an ``n``-joint robot.

    An upper estimate: up to 8 rows per target, each held about three times while the
    chunks' answers are joined and sorted, plus one chunk's working arrays. Measured
    peaks with ``tracemalloc``: 1.6 kB per target for 20 000 PUMA 560 poses, 0.5 kB for
    20 000 points of the paper robot.

    >>> ik_all_many_bytes(8000, 6) / 1e6
    20.8
    """
    per_target = 8 * (24 * n + 60) + 200
    return targets * per_target + CHUNK * 3000.0


def _solve_chunk(
    chain: ChainAxes, family: str, targets: TargetsMany, part: slice
) -> tuple[Finished, np.ndarray]:
    """One chunk's answer, and the targets (indices into all) the one-target solver answers."""
    points = targets.points[part]
    turns = None if targets.turns is None else targets.turns[part]
    found = SOLVERS_MANY[family](chain, points, turns, family)
    finished = finish_many(chain, family, points, turns, found)
    finished.target += part.start
    return finished, np.flatnonzero(found.degenerate) + part.start


def ik_all_many(
    robot: Any, targets: Any, *, angle: Any = None, constant: Any = ()
) -> IKSolutionSets:
    """Every closed-form solution of each of T targets, computed together.

    What :func:`~robotconf.inverse_kinematics.ik_all` does for one target, vectorized
    over many: the same families, branches, labels, checks and reasons.

    Parameters
    ----------
    robot : Robot
        A robot with a closed form (:func:`~robotconf.inverse_kinematics.recognize`).
    targets : array-like, shape (T, 3) or (T, 4, 4)
        Points or poses (base frame), as ``ik_all``'s ``target``.
    angle : float or array-like of shape (T,), optional
        Planar 3R arms and 3-revolute SCARAs with point targets: the end-effector's turn.
    constant : int, str or iterable of them
        As for ``ik_all``.

    Returns
    -------
    IKSolutionSets
        ``sets[k]`` equals ``ik_all(robot, targets[k])`` to round-off (same rows in the
        same order, labels, flags and reason).

    Raises
    ------
    InvalidInputError
        ``robot`` without a closed form; ``targets`` (or ``targets[i]``, the first bad
        one) or ``angle`` for input of the wrong shape or kind; ``targets`` when the
        answer would not fit the memory budget.

    Examples
    --------
    >>> import robotconf as rc
    >>> puma = rc.preset("puma560")
    >>> poses = puma.end_effector_pose([[0.3, 0.2, -0.4, 0.5, 0.6, 0.7], [0.1] * 6])
    >>> sets = ik_all_many(puma, poses)
    >>> sets.counts, sets[0].labels[0]
    (array([8, 8]), 'shoulder left, elbow up, wrist no flip')
    """
    chain, family, why = closed_form_structure(robot, constant)
    if family is None:
        raise refuse(chain, NotClosedForm(why)) from None
    read = read_targets_many(targets, angle, chain, family)
    count = len(read.points)
    check_memory(
        "targets",
        f"<{count} targets>",
        ik_all_many_bytes(count, robot.n),
        "fewer targets per call (split them into chunks), or a larger memory budget",
    )
    solved = [
        _solve_chunk(chain, family, read, slice(s, s + CHUNK)) for s in range(0, count, CHUNK)
    ]
    parts = [part for part, _ in solved]
    reasons = [text for part in parts for text in part.reasons]
    q = [part.q for part in parts]
    labels = [part.labels for part in parts]
    within = [part.within for part in parts]
    owner = [part.target for part in parts]
    degenerate = np.concatenate([aside for _, aside in solved])
    if degenerate.size:
        given = np.asarray(targets, dtype=float)
        for t in degenerate.tolist():
            one = ik_all(
                robot,
                given[t],
                angle=None if read.angles is None else float(read.angles[t]),
                constant=constant,
            )
            q.append(one.q)
            labels.append(np.array(one.labels, dtype=object))
            within.append(one.within_limits)
            owner.append(np.full(len(one), t))
            reasons[t] = one.reason
    target = np.concatenate(owner)
    order = np.argsort(target, kind="stable")
    return IKSolutionSets(
        q=np.concatenate(q)[order],
        labels=tuple(np.concatenate(labels)[order].tolist()),
        within_limits=np.concatenate(within)[order],
        target=target[order],
        counts=np.bincount(target, minlength=count),
        reasons=tuple(reasons),
        family=family,
    )
