"""The closest configuration: a second-order descent of the error, for targets not met.

Damped least squares (:mod:`robotconf.inverse_kinematics.numeric._lm`) models the error as linear
in the joints. That is exact enough on the way to a solution, where the error goes to
zero, but not where it cannot: the closest configuration to a target out of reach is a
singular one (the arm stretched towards it, or folded), where the first-order model
misses the curvature that decides the minimum. There it crawls (the paper arm stops
0.6 short of its best from some starts), and a start that sits on a saddle (the arm
pointing straight away from the target: every joint motion is orthogonal to the error)
does not move at all.

So a run that did not meet its target continues here, with the true curvature of
``E = ½‖e‖²`` in the solver's units (:mod:`robotconf.inverse_kinematics.model._problem`):
the gradient is ``g = −Jᵀe`` and the Hessian ``H = JᵀJ − Σ_k e_k ∇²e_k`` comes from
central differences of the gradient (steps of 1e-6 rad or robot sizes: one chain pass
for all 2m neighbours of all runs at once). Each step is Newton's, taken in the
eigenvectors of ``H`` with ``|λ|`` for ``λ`` (so it descends across a saddle, Dauphin et
al. 2014), plus a turn along the most negative curvature when there is one, inside a
trust radius that doubles after a full step that lowers ``E`` and shrinks fourfold after
one that does not. Joints pressed against a limit by the gradient are held, as in the
least-squares steps.

A run ends when it meets the tolerances (converged), when the gradient over the free
joints is at float64 rounding and no direction curves down (a local minimum of the
distance), when the trust radius falls below 1e-13 (nothing lowers ``E`` any more), or
after ``max_iterations`` steps. The answer says whether its end is a local minimum: a
gradient at most 1e-6 of ``‖J‖‖e‖`` and no negative curvature.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model._problem import Problem
from ._lm import CONVERGED, ITERATION_LIMIT, STALLED, STATIONARY, blocked_joints

__all__ = ["Closest", "descend", "LOCAL_MINIMUM_RATIO", "CHUNK"]

#: ``‖g‖ / (‖J‖ ‖e‖)`` at most this (and no negative curvature): a local minimum.
LOCAL_MINIMUM_RATIO = 1e-6
#: The same ratio at float64 rounding: the descent is done.
ROUNDING_RATIO = 1e-13
#: Central-difference step of the gradient (rad, or robot sizes).
HESSIAN_STEP = 1e-6
#: Eigenvalues within this fraction of the largest are flat, not curved.
CURVATURE_FLOOR = 1e-9
#: Trust radius (rad, or robot sizes): at the start, the largest, and the end.
RADIUS_START, RADIUS_MAX, RADIUS_MIN = 0.5, 2.0, 1e-13


@dataclass
class Closest:
    """Where each run ended: ``q`` (B, n), ``error`` (B, r), ``status`` (B,)
    (:data:`CONVERGED`, :data:`STATIONARY` at a local minimum, :data:`STALLED` or
    :data:`ITERATION_LIMIT`), ``minimum`` (B,) whether the end is a local minimum of the
    distance, and ``iterations`` (B,)."""

    q: np.ndarray
    error: np.ndarray
    status: np.ndarray
    minimum: np.ndarray
    iterations: np.ndarray


class _Curvature:
    """Gradient, Hessian and the free joints at moving coordinates x (B, m)."""

    def __init__(
        self,
        problem: Problem,
        positions: np.ndarray,
        rotations: np.ndarray | None,
        x: np.ndarray,
        limits: np.ndarray,
    ):
        count, m = x.shape
        scale = problem.column_scale[problem.joints]
        # The point and its 2m neighbours, all runs in one pass of the chain.
        offsets = np.concatenate([np.zeros((1, m)), np.eye(m), -np.eye(m)]) * HESSIAN_STEP
        points = (x[np.newaxis] + (offsets * scale)[:, np.newaxis, :]).reshape(-1, m)
        tiled = np.tile(positions, (2 * m + 1, 1))
        turned = None if rotations is None else np.tile(rotations, (1, 1, 2 * m + 1))
        error, jacobian = problem.evaluate(tiled, turned, points)
        assert jacobian is not None
        scaled = error * problem.row_scale
        gradient = -(jacobian.transpose(0, 2, 1) @ scaled[:, :, np.newaxis])[:, :, 0]
        gradient = gradient.reshape(2 * m + 1, count, m)
        self.error = error[:count]
        self.scaled = scaled[:count]
        self.jacobian = jacobian[:count]
        self.gradient = gradient[0]
        hessian = (gradient[1 : m + 1] - gradient[m + 1 :]).transpose(1, 2, 0)
        hessian /= 2.0 * HESSIAN_STEP
        hessian = 0.5 * (hessian + hessian.transpose(0, 2, 1))
        lower, upper = problem.lower[problem.joints], problem.upper[problem.joints]
        clipped = ~problem.wraps[problem.joints]
        blocked = blocked_joints(lower, upper, clipped, x, -self.gradient)
        self.free = ~(blocked & limits[:, np.newaxis])
        pair = self.free[:, :, np.newaxis] & self.free[:, np.newaxis, :]
        hessian = np.where(pair, hessian, 0.0)
        self.free_gradient = self.gradient * self.free
        self.values, self.vectors = np.linalg.eigh(hessian)
        top = np.max(np.abs(self.values), axis=1, keepdims=True)
        self.floor = CURVATURE_FLOOR * top + 1e-300
        # Held joints' rows are zero: their eigenvalue 0 is no curvature to follow.
        self.negative = np.any(self.values < -self.floor, axis=1)

    def ratio(self) -> np.ndarray:
        """``‖g_free‖ / (‖J‖_F ‖e‖)`` per run (0 where the error is zero)."""
        norm = np.sqrt(np.sum(self.free_gradient**2, axis=1))
        size = np.sqrt(np.sum(self.jacobian**2, axis=(1, 2)) * np.sum(self.scaled**2, axis=1))
        return np.divide(norm, size, out=np.zeros_like(norm), where=size > 0)

    def step(self, radius: np.ndarray) -> np.ndarray:
        """Newton's step with |λ|, plus the turn along a negative curvature, within
        ``radius`` (B,): (B, m) in the solver's units."""
        coefficients = (self.vectors.transpose(0, 2, 1) @ self.free_gradient[:, :, np.newaxis])[
            :, :, 0
        ]
        curvature = np.maximum(np.abs(self.values), self.floor)
        step = -(self.vectors @ (coefficients / curvature)[:, :, np.newaxis])[:, :, 0]
        down = self.vectors[:, :, 0]  # eigh sorts ascending: the most negative first
        sign = np.where(np.sum(down * self.free_gradient, axis=1) > 0.0, -1.0, 1.0)
        step += np.where(self.negative, sign * radius, 0.0)[:, np.newaxis] * down
        step *= self.free
        length = np.sqrt(np.sum(step**2, axis=1))
        shrink = np.minimum(1.0, radius / np.maximum(length, 1e-300))
        return step * shrink[:, np.newaxis]


#: Runs descended at once: the Hessian's pass holds 2m + 1 configurations per run.
CHUNK = 512


def descend(
    problem: Problem, index: np.ndarray, q: np.ndarray, limits: bool, max_iterations: int
) -> Closest:
    """Second-order descent from ``q`` (B, n) for targets ``index`` (see the module notes),
    :data:`CHUNK` runs at a time (each run on its own: the chunks change no answer).

    Parameters
    ----------
    problem : Problem
    index : ndarray of int, shape (B,)
        The target of each run.
    q : ndarray, shape (B, n)
        Where each run starts (the end of its least-squares run).
    limits : bool
        Keep the joints within their ranges.
    max_iterations : int
        Most steps per run.

    Returns
    -------
    Closest
    """
    if not problem.joints.size:
        return _still(problem, index, q)
    if len(index) <= CHUNK:
        return _descend(problem, index, q, limits, max_iterations)
    parts = [
        _descend(problem, index[k : k + CHUNK], q[k : k + CHUNK], limits, max_iterations)
        for k in range(0, len(index), CHUNK)
    ]
    return Closest(
        *(np.concatenate([getattr(p, f) for p in parts]) for f in Closest.__dataclass_fields__)
    )


def _still(problem: Problem, index: np.ndarray, q: np.ndarray) -> Closest:
    """A robot without a moving joint cannot move: where it stands is its closest
    configuration, a minimum of the distance with nothing to descend."""
    count = len(index)
    error = problem.evaluate(
        problem.positions[index], problem.rotations_of(index), q[:, :0], jacobian=False
    )[0]
    status = np.where(problem.converged(error), CONVERGED, STATIONARY)
    return Closest(q.copy(), error, status, np.ones(count, dtype=bool), np.zeros(count, dtype=int))


def _descend(
    problem: Problem, index: np.ndarray, q: np.ndarray, limits: bool, max_iterations: int
) -> Closest:
    count = len(index)
    joints = problem.joints
    scale = problem.column_scale[joints]
    lower, upper, wraps = problem.lower[joints], problem.upper[joints], problem.wraps[joints]
    bounded = np.full(count, limits)
    x = problem.project(q, limits)[:, joints]
    positions = problem.positions[index]
    rotations = problem.rotations_of(index)
    status = np.full(count, ITERATION_LIMIT)
    iterations = np.zeros(count, dtype=int)
    radius = np.full(count, RADIUS_START)
    energy = problem.energy(problem.evaluate(positions, rotations, x, jacobian=False)[0])
    running = np.arange(count)
    for _ in range(max_iterations):
        if not running.size:
            break
        rotations_now = None if rotations is None else rotations[:, :, running]
        here = _Curvature(problem, positions[running], rotations_now, x[running], bounded[running])
        met = problem.converged(here.error)
        flat = (here.ratio() <= ROUNDING_RATIO) & ~here.negative
        small = radius[running] < RADIUS_MIN
        stop = met | flat | small
        status[running[met]] = CONVERGED
        status[running[flat & ~met]] = STATIONARY
        status[running[small & ~met & ~flat]] = STALLED
        here_step = here.step(radius[running])[~stop]
        running = running[~stop]
        if not running.size:
            break
        step = here_step * scale
        trial = x[running] + step
        outside = wraps & ((trial < lower) | (trial > upper))
        wrapped = lower + np.mod(trial - lower, 2.0 * np.pi)
        trial = np.where(outside & bounded[running, np.newaxis], wrapped, trial)
        trial = np.where(bounded[running, np.newaxis], np.clip(trial, lower, upper), trial)
        rotations_now = None if rotations is None else rotations[:, :, running]
        trial_error = problem.evaluate(positions[running], rotations_now, trial, jacobian=False)[0]
        trial_energy = problem.energy(trial_error)
        better = trial_energy < energy[running]
        iterations[running] += 1
        taken = np.sqrt(np.sum(here_step**2, axis=1))
        full = taken >= 0.99 * radius[running]
        accepted = running[better]
        x[accepted] = trial[better]
        energy[accepted] = trial_energy[better]
        grow = np.where(full, np.minimum(2.0 * radius[running], RADIUS_MAX), radius[running])
        radius[running] = np.where(better, grow, 0.25 * np.minimum(radius[running], taken))
    error = problem.evaluate(positions, rotations, x, jacobian=False)[0]
    minimum = np.zeros(count, dtype=bool)
    if count:
        end = _Curvature(problem, positions, rotations, x, bounded)
        minimum = (end.ratio() <= LOCAL_MINIMUM_RATIO) & ~end.negative
    return Closest(problem.full_q(x), error, status, minimum, iterations)
