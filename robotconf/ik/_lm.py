"""Damped least squares (Levenberg–Marquardt) for a batch of targets at once.

One step for every target still running, with ``J`` and ``e`` in the solver's units
(:mod:`robotconf.ik._problem`) and ``E = ½‖e‖²``:

.. math::

    (J^T J + \\lambda I)\\,\\Delta q = J^T e, \\qquad \\lambda = \\mu\\,(E + \\bar w)

The damping follows Sugihara (2011): proportional to the remaining error, so far from the
target the steps are cautious gradient steps and near it they become Gauss–Newton steps
with quadratic convergence; the small bias ``w̄`` keeps the matrix invertible at a
singularity. On top, the classic Levenberg–Marquardt trust rule: a step that does not
lower ``E`` is rejected and ``μ`` grows fourfold; an accepted one shrinks it fourfold.

Joint ranges are kept by projection: after each step a joint is clipped to its range (or
wrapped, when the range spans a full turn). A joint already at a limit whose step would
push it further is frozen for that step and the step is solved again without it, so the
other joints still make progress along the limit.

A target stops when it meets both tolerances (**converged**), when its error is
orthogonal to everything the joints can do (**stationary**: ``‖Jᵀe‖ ≤ 10⁻⁹ ‖J‖ ‖e‖``,
a closest point or a singularity), when ``μ`` passes ``10⁸`` without an accepted step or
``E`` falls by less than 1 % over 10 steps (**stalled**: nothing lowers the error any
more, e.g. crawling along a limit, or at rounding level), or after ``max_iterations``
steps. The batch shrinks as targets stop; no Python loop runs over targets.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._problem import Problem

__all__ = [
    "RUNNING",
    "CONVERGED",
    "STATIONARY",
    "STALLED",
    "ITERATION_LIMIT",
    "Run",
    "solve",
    "gradient_ratio",
]

RUNNING, CONVERGED, STATIONARY, STALLED, ITERATION_LIMIT = range(5)

#: Sugihara's bias w̄, in the solver's dimension-free units.
BIAS = 1e-4
#: Limits and factors of the trust multiplier μ.
MU_START, MU_MIN, MU_MAX = 1.0, 1e-6, 1e8
MU_DOWN, MU_UP = 0.25, 4.0
#: A run whose ``E`` fell by less than 1 % over this many steps is crawling (typically
#: along a joint limit) and stops as stalled.
PROGRESS_WINDOW, PROGRESS_FACTOR = 10, 0.99
#: ``‖Jᵀe‖ / (‖J‖ ‖e‖)`` below this: the error is orthogonal to every joint motion.
STATIONARY_RATIO = 1e-9


@dataclass
class Run:
    """Where each target of a batch ended: ``q`` (B, n), ``error`` (B, m) unscaled,
    ``status`` (B,) one of the codes above, ``iterations`` (B,) steps tried."""

    q: np.ndarray
    error: np.ndarray
    status: np.ndarray
    iterations: np.ndarray


def _solve(jacobian: np.ndarray, gradient: np.ndarray, damping: np.ndarray) -> np.ndarray:
    n = jacobian.shape[-1]
    system = jacobian.transpose(0, 2, 1) @ jacobian
    system += damping[:, np.newaxis, np.newaxis] * np.eye(n)
    return np.linalg.solve(system, gradient[..., np.newaxis])[..., 0]


def blocked_joints(problem: Problem, q: np.ndarray, direction: np.ndarray) -> np.ndarray:
    """Joints (B, n) sitting at a clipped limit that ``direction`` would push past."""
    margin = 1e-12 * np.maximum(problem.upper - problem.lower, 1.0)
    clipped = problem.moving & ~problem.wraps
    at_lower = (q <= problem.lower + margin) & (direction < 0)
    at_upper = (q >= problem.upper - margin) & (direction > 0)
    return clipped & (at_lower | at_upper)


def _step(
    problem: Problem,
    jacobian: np.ndarray,
    error: np.ndarray,
    gradient: np.ndarray,
    damping: np.ndarray,
    q: np.ndarray,
    limits: bool,
) -> np.ndarray:
    step = _solve(jacobian, gradient, damping)
    if limits:
        blocked = blocked_joints(problem, q, step)
        again = np.flatnonzero(blocked.any(axis=1))
        if again.size:
            free = jacobian[again] * ~blocked[again][:, np.newaxis, :]
            free_gradient = np.einsum("bmn,bm->bn", free, error[again])
            step[again] = _solve(free, free_gradient, damping[again])
    return step * problem.column_scale


def gradient_ratio(jacobian: np.ndarray, error: np.ndarray) -> np.ndarray:
    """``‖Jᵀe‖ / (‖J‖_F ‖e‖)`` per target: 0 when no joint motion changes the error."""
    gradient = np.einsum("bmn,bm->bn", jacobian, error)
    scale = np.linalg.norm(jacobian, axis=(1, 2)) * np.linalg.norm(error, axis=-1)
    norm = np.linalg.norm(gradient, axis=-1)
    return np.divide(norm, scale, out=np.zeros_like(norm), where=scale > 0)


def solve(
    problem: Problem, index: np.ndarray, start: np.ndarray, max_iterations: int, limits: bool
) -> Run:
    """Iterate targets ``index`` from ``start`` (B, n) until each one stops.

    Parameters
    ----------
    problem : Problem
    index : ndarray of int, shape (B,)
        Which of the problem's targets.
    start : ndarray, shape (B, n)
        Start coordinates (projected into the ranges first when ``limits``).
    max_iterations : int
        Most steps per target.
    limits : bool
        Keep the joints within their ranges.

    Returns
    -------
    Run
    """
    q = problem.project(start, limits)
    error = problem.pose_errors(index, problem.pose(q))
    status = np.where(problem.converged(error), CONVERGED, RUNNING)
    iterations = np.zeros(len(index), dtype=int)
    mu = np.full(len(index), MU_START)
    jacobian = np.zeros((len(index), len(problem.rows), problem.robot.n))
    running = np.flatnonzero(status == RUNNING)
    if running.size:
        jacobian[running] = problem.jacobian(index[running], q[running])
    checkpoint = np.full(len(index), np.inf)
    for iteration in range(max_iterations):
        if iteration % PROGRESS_WINDOW == 0:
            energy_now = problem.energy(error)
            crawling = (status == RUNNING) & (energy_now > PROGRESS_FACTOR * checkpoint)
            status[crawling] = STALLED
            checkpoint = energy_now
        active = np.flatnonzero(status == RUNNING)
        if not active.size:
            break
        scaled = problem.scaled(error[active])
        gradient = np.einsum("bmn,bm->bn", jacobian[active], scaled)
        allowed = jacobian[active]
        if limits:
            # Joints pressed against a limit cannot help: leave them out of the test.
            allowed = allowed * ~blocked_joints(problem, q[active], gradient)[:, np.newaxis]
        flat = gradient_ratio(allowed, scaled) <= STATIONARY_RATIO
        status[active[flat]] = STATIONARY
        active, scaled, gradient = active[~flat], scaled[~flat], gradient[~flat]
        if not active.size:
            break
        energy = problem.energy(error[active])
        damping = mu[active] * (energy + BIAS)
        step = _step(problem, jacobian[active], scaled, gradient, damping, q[active], limits)
        trial = problem.project(q[active] + step, limits)
        trial_error = problem.pose_errors(index[active], problem.pose(trial))
        better = problem.energy(trial_error) < energy
        iterations[active] += 1
        good, bad = active[better], active[~better]
        q[good] = trial[better]
        error[good] = trial_error[better]
        mu[good] = np.maximum(mu[good] * MU_DOWN, MU_MIN)
        mu[bad] *= MU_UP
        status[bad[mu[bad] > MU_MAX]] = STALLED
        done = problem.converged(error[good])
        status[good[done]] = CONVERGED
        refresh = good[~done]
        if refresh.size:
            jacobian[refresh] = problem.jacobian(index[refresh], q[refresh])
    status[status == RUNNING] = ITERATION_LIMIT
    return Run(q, error, status, iterations)
