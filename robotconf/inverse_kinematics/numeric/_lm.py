"""Damped least squares (Levenberg–Marquardt) for a batch of runs at once.

One step for every run still going, with ``J`` and ``e`` in the solver's units
(:mod:`robotconf.inverse_kinematics.model._problem`) and ``E = ½‖e‖²``:

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

A run stops when it meets both tolerances (**converged**), when ``μ`` passes ``10⁸``
without an accepted step or ``E`` has not halved over 5 steps (**stalled**: crawling
along a limit, at a saddle where no step helps, at rounding level, or on its way to a
solution outside the ranges — another start is cheaper than following it), or after
``max_iterations`` steps. (:data:`STATIONARY` is the second-order descent's word for a
local minimum, :mod:`robotconf.inverse_kinematics.numeric._closest`.)
Runs of one target may be ordered (its starts, tried in turn): a run is dropped
(**superseded**) as soon as a run of the same target ordered before it has converged,
since only the first converged run counts.

Only the runs still going are computed: the state is kept compact (one row per running
run) and shrinks as runs stop, and each step evaluates the error and the Jacobian of the
trial point together from one pass of the chain. Every operation acts on each run alone
(elementwise, or one small matrix per run), so a run's result does not depend on which
other runs share the batch.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model._chain import Workspace
from ..model._problem import FULL_TURN, Problem

__all__ = [
    "RUNNING",
    "CONVERGED",
    "STATIONARY",
    "STALLED",
    "ITERATION_LIMIT",
    "SUPERSEDED",
    "Run",
    "solve",
    "blocked_joints",
    "gradient_ratio",
]

RUNNING, CONVERGED, STATIONARY, STALLED, ITERATION_LIMIT, SUPERSEDED = range(6)

#: Sugihara's bias w̄, in the solver's dimension-free units.
BIAS = 1e-4
#: Limits and factors of the trust multiplier μ.
MU_START, MU_MIN, MU_MAX = 1.0, 1e-6, 1e8
MU_DOWN, MU_UP = 0.25, 4.0
#: A run whose ``E`` has not fallen below this factor of itself over this many steps is
#: crawling and stops as stalled: converging runs halve it many times over in that time.
PROGRESS_WINDOW, PROGRESS_FACTOR = 5, 0.5


@dataclass
class Run:
    """Where each run of a batch ended: ``q`` (B, n), ``error`` (B, r) unscaled,
    ``status`` (B,) one of the codes above, ``iterations`` (B,) steps tried."""

    q: np.ndarray
    error: np.ndarray
    status: np.ndarray
    iterations: np.ndarray


def blocked_joints(
    lower: np.ndarray, upper: np.ndarray, clipped: np.ndarray, x: np.ndarray, direction: np.ndarray
) -> np.ndarray:
    """Joints (B, k) sitting at a clipped limit that ``direction`` (B, k) would push past.

    ``lower``, ``upper`` and ``clipped`` (k,) describe the joints; ``clipped`` is False
    for joints that wrap or do not move.
    """
    margin = 1e-12 * np.maximum(upper - lower, 1.0)
    at_lower = (x <= lower + margin) & (direction < 0)
    at_upper = (x >= upper - margin) & (direction > 0)
    return clipped & (at_lower | at_upper)


def gradient_ratio(jacobian: np.ndarray, error: np.ndarray) -> np.ndarray:
    """``‖Jᵀe‖ / (‖J‖_F ‖e‖)`` per run: 0 when no joint motion changes the error."""
    gradient = (jacobian.transpose(0, 2, 1) @ error[:, :, np.newaxis])[:, :, 0]
    scale = np.sqrt(np.sum(jacobian**2, axis=(1, 2)) * np.sum(error**2, axis=-1))
    norm = np.sqrt(np.sum(gradient**2, axis=-1))
    return np.divide(norm, scale, out=np.zeros_like(norm), where=scale > 0)


@dataclass
class _Joints:
    """The moving joints' ranges, as the loop uses them (all (m,))."""

    lower: np.ndarray
    upper: np.ndarray
    wraps: np.ndarray
    clipped: np.ndarray
    scale: np.ndarray

    def __post_init__(self) -> None:
        margin = 1e-12 * np.maximum(self.upper - self.lower, 1.0)
        # A joint within the margin of a clipped limit sits at it (see blocked_joints).
        self.low_edge = np.where(self.clipped, self.lower + margin, -np.inf)
        self.high_edge = np.where(self.clipped, self.upper - margin, np.inf)
        self.any_wraps = bool(self.wraps.any())
        self.any_clipped = bool(self.clipped.any())

    @classmethod
    def of(cls, problem: Problem) -> _Joints:
        j = problem.joints
        wraps = problem.wraps[j]
        return cls(problem.lower[j], problem.upper[j], wraps, ~wraps, problem.column_scale[j])

    def project(self, x: np.ndarray, limits: np.ndarray) -> np.ndarray:
        """``x`` (B, m) wrapped or clipped into the ranges where ``limits`` (B,) says so."""
        inside = x
        if self.any_wraps:
            outside = self.wraps & ((x < self.lower) | (x > self.upper))
            wrapped = self.lower + np.mod(x - self.lower, FULL_TURN)
            inside = np.where(outside, wrapped, x)
        inside = np.clip(inside, self.lower, self.upper)
        if limits.all():
            return inside
        return np.where(limits[:, np.newaxis], inside, x)

    def blocked(self, x: np.ndarray, direction: np.ndarray, limits: np.ndarray) -> np.ndarray:
        """Joints (B, m) at a clipped limit that ``direction`` pushes past, where ``limits``."""
        low = (x <= self.low_edge) & (direction < 0)
        blocked = low | ((x >= self.high_edge) & (direction > 0))
        return blocked if limits.all() else blocked & limits[:, np.newaxis]


def _dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row-wise dot products of (B, k) arrays, (B,)."""
    return (a[:, np.newaxis, :] @ b[:, :, np.newaxis])[:, 0, 0]


def _step(
    normal: np.ndarray,
    gradient: np.ndarray,
    damping: np.ndarray,
    joints: _Joints,
    x: np.ndarray,
    limits: np.ndarray | None,
) -> np.ndarray:
    """Solve ``(JᵀJ + λI) Δ = Jᵀe``, again without the joints it would push past a limit
    (``limits`` (B,): where the ranges hold; None: nowhere). ``normal`` is overwritten."""
    m = normal.shape[-1]
    diagonal = normal.reshape(len(normal), m * m)[:, :: m + 1]
    diagonal += damping[:, np.newaxis]
    step = np.linalg.solve(normal, gradient[:, :, np.newaxis])[:, :, 0]
    if limits is not None:
        blocked = joints.blocked(x, step, limits)
        again = np.flatnonzero(blocked.any(axis=1))
        if again.size:
            # Freezing joints zeroes their Jacobian columns: JᵀJ loses their rows and
            # columns, Jᵀe their entries (the damping keeps the system regular).
            free = ~blocked[again]
            system = normal[again] * (free[:, :, np.newaxis] & free[:, np.newaxis, :])
            system.reshape(len(again), m * m)[:, :: m + 1] += damping[again, np.newaxis] * ~free
            free_gradient = (gradient[again] * free)[:, :, np.newaxis]
            step[again] = np.linalg.solve(system, free_gradient)[:, :, 0]
    return step * joints.scale


def solve(
    problem: Problem,
    index: np.ndarray,
    start: np.ndarray,
    max_iterations: int,
    limits: bool | np.ndarray,
    order: np.ndarray | None = None,
    decisive: np.ndarray | None = None,
) -> Run:
    """Iterate runs for targets ``index`` from ``start`` (B, n) until each one stops.

    Parameters
    ----------
    problem : Problem
    index : ndarray of int, shape (B,)
        The target of each run (a target may have several runs).
    start : ndarray, shape (B, n)
        Start coordinates (projected into the ranges first where ``limits``).
    max_iterations : int
        Most steps per run.
    limits : bool or ndarray of bool, shape (B,)
        Keep the joints within their ranges (for every run, or per run).
    order : ndarray of int, shape (B,), optional
        The rank of each run among the runs of its target: once one converges, the runs
        of the same target with a higher rank stop as :data:`SUPERSEDED` (their results
        are not meaningful). Default: every run stands alone.
    decisive : ndarray of bool, shape (B,), optional
        Which runs end the race when they converge (default: all).

    Returns
    -------
    Run
    """
    count = len(index)
    limits = np.broadcast_to(np.asarray(limits, dtype=bool), (count,))
    joints = _Joints.of(problem)
    x = joints.project(problem.project(start, False)[:, problem.joints], limits)
    positions = problem.positions[index]
    rotations = problem.rotations_of(index)
    error, jacobian = problem.evaluate(positions, rotations, x)
    assert jacobian is not None
    status = np.where(problem.converged(error), CONVERGED, RUNNING)
    iterations = np.zeros(count, dtype=int)
    race = None if order is None else _Race(index, order, decisive, status)
    out_x, out_error = x.copy(), error.copy()

    # The compact state of the running runs; ``ids`` maps its rows to the batch's.
    keep = status == RUNNING
    ids = np.flatnonzero(keep)
    state = _State(
        x[keep], error[keep], jacobian[keep], positions[keep],
        None if rotations is None else rotations[:, :, keep], limits[keep],
    )  # fmt: skip
    mu = np.full(ids.size, MU_START)
    checkpoint = np.full(ids.size, np.inf)
    energy = problem.energy(state.error)
    m = len(problem.joints)
    workspace = Workspace()
    for iteration in range(max_iterations):
        if not ids.size:
            break
        stop = None if race is None else race.lost(ids)
        if iteration % PROGRESS_WINDOW == 0:
            # Crawling: E fell by less than the factor since the last check.
            stalled = np.where(energy > PROGRESS_FACTOR * checkpoint, STALLED, 0)
            stop = stalled if stop is None else np.where(stop == 0, stalled, stop)
            checkpoint = energy
        if stop is not None and stop.any():
            going = stop == 0
            finished = ~going
            status[ids[finished]] = stop[finished]
            out_x[ids[finished]] = state.x[finished]
            out_error[ids[finished]] = state.error[finished]
            ids, mu, checkpoint, energy = ids[going], mu[going], checkpoint[going], energy[going]
            state = state.take(going)
            if not ids.size:
                break
        scaled = state.error * problem.row_scale
        jt = state.jacobian.transpose(0, 2, 1)
        gradient = (jt @ scaled[:, :, np.newaxis])[:, :, 0]
        # Into a buffer kept across steps: arrays this size (above glibc's mmap threshold)
        # would otherwise be fresh pages, page-faulted in at every step.
        normal = np.matmul(jt, state.jacobian, out=workspace.get("normal", (len(ids), m, m)))
        bounded = state.limits if joints.any_clipped and state.limits.any() else None
        step = _step(normal, gradient, mu * (energy + BIAS), joints, state.x, bounded)
        trial = joints.project(state.x + step, state.limits)
        trial_error, trial_jacobian = problem.evaluate(
            state.positions, state.rotations, trial, workspace=workspace
        )
        assert trial_jacobian is not None
        trial_energy = problem.energy(trial_error)
        better = trial_energy < energy
        iterations[ids] += 1
        np.copyto(state.x, trial, where=better[:, np.newaxis])
        np.copyto(state.error, trial_error, where=better[:, np.newaxis])
        np.copyto(state.jacobian, trial_jacobian, where=better[:, np.newaxis, np.newaxis])
        energy = np.where(better, trial_energy, energy)
        mu = np.where(better, np.maximum(mu * MU_DOWN, MU_MIN), mu * MU_UP)
        done = np.where(better & problem.converged(state.error), CONVERGED, 0)
        done[~better & (mu > MU_MAX)] = STALLED
        if race is not None:
            race.won(ids[done == CONVERGED])
        if done.any():
            going = done == 0
            finished = ~going
            status[ids[finished]] = done[finished]
            out_x[ids[finished]] = state.x[finished]
            out_error[ids[finished]] = state.error[finished]
            ids, mu, checkpoint, energy = ids[going], mu[going], checkpoint[going], energy[going]
            state = state.take(going)
    status[ids] = ITERATION_LIMIT
    out_x[ids] = state.x
    out_error[ids] = state.error
    return Run(problem.full_q(out_x), out_error, status, iterations)


class _Race:
    """The lowest rank of a converged run, per target, to drop the runs behind it."""

    def __init__(
        self, index: np.ndarray, order: np.ndarray, decisive: np.ndarray | None, status: np.ndarray
    ):
        self.index, self.order = index, order
        self.decisive = np.ones(len(index), bool) if decisive is None else decisive
        self.best = np.full(int(index.max(initial=-1)) + 1, np.iinfo(int).max)
        self.won(np.flatnonzero(status == CONVERGED))

    def won(self, runs: np.ndarray) -> None:
        runs = runs[self.decisive[runs]]
        np.minimum.at(self.best, self.index[runs], self.order[runs])

    def lost(self, runs: np.ndarray) -> np.ndarray:
        """SUPERSEDED for the runs (B,) behind a converged one, else 0."""
        behind = self.order[runs] > self.best[self.index[runs]]
        return np.where(behind, SUPERSEDED, 0)


@dataclass
class _State:
    """The running runs' coordinates (B, m), errors (B, r), Jacobians (B, r, m), targets
    (points (B, 3), rotations (3, 3, B)) and range flags (B,)."""

    x: np.ndarray
    error: np.ndarray
    jacobian: np.ndarray
    positions: np.ndarray
    rotations: np.ndarray | None
    limits: np.ndarray

    def take(self, rows: np.ndarray) -> _State:
        return _State(
            self.x[rows],
            self.error[rows],
            self.jacobian[rows],
            self.positions[rows],
            None if self.rotations is None else self.rotations[:, :, rows],
            self.limits[rows],
        )
