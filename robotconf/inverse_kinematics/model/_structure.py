"""What a robot can move at all: the generic rank of its Jacobian and over-constraint.

Two numbers, measured on a few random configurations within the joint ranges (a fixed
generator, so every call agrees):

- the **generic rank** ``r``: how many independent directions the constrained rows can
  move in at a typical configuration; a configuration whose rank is lower is singular;
- the **span** ``D``: how many directions they ever move in, over all configurations.

A planar 2R arm asked for a point moves in D = 2 directions (x, y) with r = 2: the z row
is never moved, so a target either has the right z or is out of reach, and the problem is
well posed. Asked for a full pose it moves in D = 3 directions (x, y, turn about z) but
only r = 2 at a time: most targets then have no solution, and :func:`ik` warns.
"""

from __future__ import annotations

import warnings
from functools import lru_cache

import numpy as np

from ...kinematics import Robot
from ._problem import Problem, make_problem
from ._targets import Targets

__all__ = ["generic_rank", "cached_rank", "rank", "warn_if_overconstrained", "ROW_NAMES"]

#: Names of the six rows of the error, for messages.
ROW_NAMES = ("x", "y", "z", "turn about x", "turn about y", "turn about z")

_SAMPLES = 4
_GENERATOR_SEED = 20240611
_RANK_TOL = 1e-9


def rank(matrices: np.ndarray, tol: float = _RANK_TOL) -> np.ndarray:
    """Numerical rank of each matrix (B, m, k): singular values above ``tol·σ_max``."""
    if matrices.shape[-1] == 0 or matrices.shape[-2] == 0:
        return np.zeros(len(matrices), dtype=int)
    values = np.linalg.svd(matrices, compute_uv=False)
    top = values[:, :1]
    return np.sum((values > tol * top) & (top > 0), axis=-1)


def _sample_jacobians(problem: Problem) -> np.ndarray:
    rng = np.random.default_rng(_GENERATOR_SEED)
    draws = problem.lower + (problem.upper - problem.lower) * rng.random(
        (_SAMPLES, problem.robot.n)
    )
    q = problem.project(draws, limits=True)
    full = problem.robot.jacobian(q)
    # Turns are measured about the target's axes, which are the tool's at a solution.
    tool = problem.robot.end_effector_pose(q)[:, :3, :3]
    full[:, 3:] = np.einsum("bji,bjk->bik", tool, full[:, 3:])
    weighted = full[:, problem.rows] * problem.row_scale[:, np.newaxis]
    return weighted[:, :, problem.moving] * problem.column_scale[problem.moving]


def generic_rank(problem: Problem) -> tuple[int, int]:
    """``(r, D)``: the rank at a typical configuration and the span over all of them.

    Returns
    -------
    tuple of int
        ``r`` ≤ ``D`` ≤ the number of constrained rows.
    """
    jacobians = _sample_jacobians(problem)
    typical = int(np.max(rank(jacobians)))
    span = int(rank(np.concatenate(list(jacobians), axis=1)[np.newaxis])[0])
    return typical, span


@lru_cache(maxsize=64)
def cached_rank(robot: Robot, weights: tuple[float, ...]) -> tuple[int, int]:
    """:func:`generic_rank` for a robot and the six mask weights, computed once.

    >>> from robotconf.presets import preset
    >>> cached_rank(preset("planar_2r"), (1.0, 1.0, 1.0, 1.0, 1.0, 1.0))
    (2, 3)
    """
    # Only the robot and the rows matter, not the targets.
    nowhere = Targets(np.zeros((1, 3)), None, False)
    return generic_rank(make_problem(robot, nowhere, np.array(weights), 1.0, 1.0))


def warn_if_overconstrained(problem: Problem, typical: int, span: int) -> None:
    """Warn when the rows ask for more directions than the joints can set at once.

    The solver still runs (least squares): targets off the reachable set end
    ``"unreachable"`` at the closest configuration found.
    """
    if span <= typical:
        return
    rows = ", ".join(ROW_NAMES[r] for r in problem.rows)
    warnings.warn(
        f"mask: the target constrains {rows}; the robot moves its end effector in {span} "
        f"of these directions but only {typical} at a time, so most such targets have no "
        "exact solution and end 'unreachable' at the closest configuration found. "
        "Constrain fewer directions (mask=...) for an exact answer.",
        UserWarning,
        stacklevel=3,
    )
