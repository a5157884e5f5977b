"""Starts for the numeric solver from the closed forms of a recognized arm.

A target whose first start (``q0``) fails tries the other starts in turn. For a robot
with a closed form (:func:`~robotconf.inverse_kinematics.recognize` names its family)
every closed-form solution is already an exact solution, whatever rows the mask keeps,
so those come first, nearest ``q0`` first: the run from one of them converges at once
(it starts within the tolerances) and the target needs no random start. The random
starts fill the rest of the ``seeds``.
"""

from __future__ import annotations

import numpy as np

from ..._errors import InvalidInputError
from ..batch._many import ik_all_many
from ..closed_form._ik_all import wrap_angles
from ..closed_form._recognize import closed_form_structure
from ..model._problem import Problem
from ._reasons import fit_into_limits

__all__ = ["closed_form_starts", "MOST_BRANCHES"]

#: The most closed-form solutions a target has (a 6R arm's eight).
MOST_BRANCHES = 8


def _solutions(problem: Problem, index: np.ndarray):
    """``ik_all_many`` of the targets ``index`` (None when there is no closed form for
    them: another family, or a point for an arm that needs a pose)."""
    chain, family, _ = closed_form_structure(problem.robot)
    if family is None:
        return None
    positions = problem.positions[index]
    if problem.rotations is None:
        targets = positions
    else:
        targets = np.broadcast_to(np.eye(4), (len(index), 4, 4)).copy()
        targets[:, :3, :3] = problem.rotations[index]
        targets[:, :3, 3] = positions
    try:
        return ik_all_many(problem.robot, targets)
    except InvalidInputError:
        return None


def closed_form_starts(
    problem: Problem, index: np.ndarray, first: np.ndarray, limits: bool, most: int
) -> tuple[np.ndarray, np.ndarray]:
    """The closed-form solutions of targets ``index`` (k,) as starts, nearest first.

    Parameters
    ----------
    problem : Problem
    index : ndarray of int, shape (k,)
    first : ndarray, shape (k, n)
        Each target's first start: the others are ranked by their distance to it
        (angles modulo a turn, slides in robot sizes).
    limits : bool
        Keep only solutions within the joint ranges, turned by whole turns into them.
    most : int
        Starts per target at most.

    Returns
    -------
    starts : ndarray, shape (k, E, n)
        ``E = min(most, 8)``; row ``j < counts[i]`` of target ``i`` is a start.
    counts : ndarray of int, shape (k,)

    Examples
    --------
    >>> from robotconf.presets import preset
    >>> from robotconf.inverse_kinematics.model._problem import make_problem
    >>> from robotconf.inverse_kinematics.model._targets import check_targets
    >>> arm = preset("planar_2r", l1=1, l2=1)
    >>> problem = make_problem(arm, check_targets([1, 1, 0], "position"),
    ...                        np.array([1.0, 1, 1, 0, 0, 0]), 1e-9, 1e-9)
    >>> starts, counts = closed_form_starts(problem, np.array([0]), np.zeros((1, 2)), True, 4)
    >>> counts, starts[0, : counts[0]].round(6) + 0.0
    (array([2]), array([[ 0.      ,  1.570796],
           [ 1.570796, -1.570796]]))
    """
    width = min(most, MOST_BRANCHES)
    starts = np.zeros((len(index), width, problem.robot.n))
    counts = np.zeros(len(index), dtype=int)
    sets = None if width <= 0 or not len(index) else _solutions(problem, index)
    if sets is None or not len(sets.q):
        return starts, counts
    rows, owner = sets.q, sets.target
    if limits:
        rows, outside = fit_into_limits(problem, rows[sets.within_limits])
        owner = owner[sets.within_limits]
        inside = ~outside.any(axis=1)
        rows, owner = rows[inside], owner[inside]
    revolute = problem.moving & np.array([t == "revolute" for t in problem.robot.joint_types])
    gap = rows - first[owner]
    gap = np.where(revolute, wrap_angles(gap), gap)
    scale = np.where(problem.moving, problem.column_scale, 1.0)
    distance = np.sum((gap * problem.moving / scale) ** 2, axis=1)
    order = np.lexsort((distance, owner))  # per target, nearest first (ties in branch order)
    owner, rows = owner[order], rows[order]
    rank = np.arange(len(owner)) - np.searchsorted(owner, owner)
    kept = rank < width
    starts[owner[kept], rank[kept]] = rows[kept]
    counts[:] = np.bincount(owner[kept], minlength=len(index))
    return starts, counts
