"""The numeric inverse-kinematics solver: starts, retries and an honest reason for each.

:func:`ik` validates, then runs the batched damped least squares of
:mod:`._lm` from up to ``seeds`` starts per target — ``q0`` first, then (an arm with a
closed form) the closed-form solutions nearest ``q0`` (:mod:`._starts`), then the same
random configurations for every target — and keeps the first converged run (or the
closest one). Each start runs within the joint ranges; where all of them fail and some
joint is clipped (not a full-turn revolute), the starts run again without the ranges, and
a solution whose revolute joints fit the ranges after whole turns counts as converged
(:mod:`robotconf.inverse_kinematics.numeric._search` runs them in waves).

Targets that still fail are diagnosed, in this order:

1. **unreachable**: outside the reach shell (:mod:`..model._reach`), a proof;
2. **joint limit**: a run without the ranges converged, but no whole-turn twin of its
   solution fits them; the joints past their limits are named;
3. **singular**: the Jacobian at the final configuration lost rank against the robot's
   generic rank; the joints in its new null space are named;
4. **unreachable**: the error is orthogonal to every allowed joint motion at the closest
   configuration found (a local minimum of the distance, not a proof);
5. **iteration limit**: none of the above (the message says when the error left is
   already float64 rounding).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..._budget import check_memory
from ..._errors import InvalidInputError
from ..._validation import one_line
from ...kinematics import Robot
from ..model._problem import Problem, make_problem, robot_model
from ..model._reach import Reach
from ..model._structure import cached_rank, rank, warn_if_overconstrained
from ..model._targets import check_mask, check_mode, check_options, check_start, check_targets
from ._closest import descend
from ._lm import CONVERGED, STALLED, solve
from ._reasons import (
    SINGULAR_TOL,
    beyond_reach_message,
    closest_message,
    converged_message,
    dependent_joints,
    iteration_message,
    joint_limit_message,
    singular_message,
)
from ._result import IKResult, single_or_batch
from ._search import WAVE_RUNS, Search, search
from ._starts import closed_form_starts

__all__ = ["ik", "ik_bytes"]

#: Errors below this (relative to the robot's size, or in rad) are float64 rounding.
ROUNDING = 1e3 * np.finfo(float).eps

#: A target proved out of reach whose descent from q0 stops short of the proved distance
#: tries the other starts this many at a time, each a least-squares run of at most
#: EXTRA_ITERATIONS steps (it only has to find a basin: the descent then goes down it).
EXTRA_STARTS, EXTRA_ITERATIONS = 4, 20


def ik_bytes(targets: int, n: int) -> float:
    """Peak bytes of :func:`ik` for ``targets`` targets of an ``n``-joint robot.

    An upper estimate: the runs going at once (at most ``max(T, 128)``, each with its
    pose, Jacobian, the step's n×n systems and their copies for LAPACK), plus the targets
    and the search state; the closest-point descent works in chunks of at most 512
    targets. Measured peaks with ``tracemalloc``: 4.4 kB per target for 20 000
    PUMA 560 pose targets (n = 6) and 1.7 kB for 20 000 points of the paper robot
    (n = 3), 1.4 and 2 times below the estimate.

    >>> ik_bytes(1000, 6) / 1e6
    7.304
    """
    per_run = 8.0 * (8 * n * n + 50 * n + 200)
    return max(targets, WAVE_RUNS) * per_run + 1e6


def ik(
    robot: Robot,
    target: Any,
    q0: Any = None,
    mode: str = "position",
    mask: Any = None,
    *,
    tol: float = 1e-9,
    orientation_tol: float = 1e-9,
    max_iterations: int = 100,
    seeds: int = 32,
    seed: int = 0,
    respect_limits: bool = True,
) -> IKResult:
    """Joint values that put the end effector on a target point or pose (numerically).

    Damped least squares (Levenberg–Marquardt with Sugihara's damping) on the geometric
    Jacobian, for one target or many at once, with several starts per target and a
    reason for every outcome. See docs/ik.md, "Numeric solver".

    Parameters
    ----------
    robot : Robot
    target : array-like, shape (3,), (4, 4), (T, 3) or (T, 4, 4)
        Point(s) (length units) or homogeneous pose(s) in the base frame. A pose's
        rotation must be orthonormal with det +1 (within 1e-6), its last row [0, 0, 0, 1].
    q0 : array-like, shape (n,) or (T, n), optional
        First start (default: the robot's own ``q``), moved into the ranges first.
    mode : {"position", "pose"}
        ``"position"``: the end-effector point only (3 rows); ``"pose"``: point and
        orientation (6 rows; the orientation error is the rotation vector of
        ``R_target·Rᵀ``).
    mask : array-like of 6 booleans or weights ≥ 0, optional
        Which rows count, and how much: x, y, z in the base frame, then turns about the
        target's x, y, z axes (the tool's at a solution). ``[1, 1, 1, 1, 1, 0]`` asks for
        the point and the tool's z axis, leaving the turn about it free.
    tol : float
        Position tolerance relative to the robot's size: the end effector must come
        within ``tol · L`` of the target, ``L`` = :func:`~robotconf.characteristic_length`.
    orientation_tol : float
        Orientation tolerance (rad).
    max_iterations : int
        Most steps per run (a start within the ranges, or without them), 1 … 10 000.
    seeds : int
        Starts per target, 1 … 64: ``q0``, then, on an arm with a closed form
        (:func:`~robotconf.inverse_kinematics.recognize`), the closed-form solutions of
        the target within the ranges, nearest ``q0`` first (they are solutions already),
        then random configurations within the ranges from
        ``numpy.random.default_rng(seed)``, the same for every target (so a target gets
        the same answer alone or among others): ``seeds`` in all. A target proved out of
        reach gets ``q0`` only; a solved one stops at its first success. Failed starts
        cost time only for the targets that need them.
    seed : int
        Seed of those random starts (≥ 0).
    respect_limits : bool
        Keep every joint within :meth:`Robot.joint_limits`.

    Returns
    -------
    IKResult
        ``q``, ``success``, ``position_error``, ``orientation_error``, ``iterations``,
        ``reason``, ``message``, ``distance_to_reach``; arrays over T for T targets.

    Raises
    ------
    InvalidInputError
        Naming the field: ``robot``, ``target`` (or ``target[i]``), ``mode``, ``mask``,
        ``q0``, ``tol``, ``orientation_tol``, ``max_iterations``, ``seeds``, ``seed``,
        ``respect_limits``; ``target`` also when T targets would not fit the memory budget.

    Warns
    -----
    UserWarning
        When the constrained rows ask for more directions than the joints can set at
        once (a planar arm asked for a full pose): most targets then end "unreachable".

    Examples
    --------
    The paper robot reaching a point it can reach, and one 30 beyond its reach:

    >>> from robotconf.presets import preset
    >>> robot = preset("paper")
    >>> point = robot.end_effector([0.3, 0.4, -0.5])
    >>> result = ik(robot, point)
    >>> result.reason, bool(np.allclose(robot.end_effector(result.q), point))
    ('converged', True)
    >>> far = ik(robot, [100, 0, 20])
    >>> far.reason, far.distance_to_reach
    ('unreachable', 30.0)
    >>> far.message
    "the target is 30 beyond the reach (reach sphere radius 70 about (0, 0, 20) on joint 1's axis)"
    """
    if not isinstance(robot, Robot):
        raise InvalidInputError("robot", one_line(robot), "a Robot", problem="not a robot:")
    mode = check_mode(mode)
    targets = check_targets(target, mode)
    weights = check_mask(mask, mode)
    options = check_options(tol, orientation_tol, max_iterations, seeds, seed, respect_limits)
    count = targets.count
    check_memory(
        "target",
        f"<{count} targets>",
        ik_bytes(count, robot.n),
        "fewer targets per call (split them into chunks), or a larger memory budget",
    )
    first = check_start(q0, robot.q, count, robot.coordinate_names)
    problem = make_problem(robot, targets, weights, options.tol, options.orientation_tol)
    typical, span = cached_rank(robot, tuple(weights.tolist()))
    warn_if_overconstrained(problem, typical, span)
    limits = options.respect_limits

    reach = robot_model(robot).reach
    position_rows = int(np.sum(problem.rows < 3))
    beyond = reach.distance(problem.positions) if position_rows == 3 else np.zeros(count)
    proved = beyond > problem.position_tol

    rng = np.random.default_rng(options.seed)
    draws = problem.lower + (problem.upper - problem.lower) * rng.random(
        (options.seeds - 1, robot.n)
    )
    found = search(
        problem,
        first,
        draws,
        proved,
        options.max_iterations,
        limits,
        own=lambda index: closed_form_starts(problem, index, first[index], limits, len(draws)),
    )
    _verify(problem, found)
    minimum = _approach(problem, found, proved, beyond, draws, options.max_iterations, limits)
    _verify(problem, found)
    return _diagnose(
        problem,
        targets.batched,
        reach,
        beyond,
        proved,
        minimum,
        typical,
        options.max_iterations,
        found,
    )


def _verify(problem: Problem, found: Search) -> None:
    """Measure the answers again with the robot's own kinematics, which is what a caller
    checks them by; a solution that meets the tolerances only by the solver's chain (a
    rounding apart) does not count as one."""
    pose = problem.robot.end_effector_pose(found.q)
    error = problem.errors_from_pose(np.arange(len(found.q)), pose)
    found.error = error
    found.status[(found.status == CONVERGED) & ~problem.converged(error)] = STALLED


def _closer(problem: Problem, error: np.ndarray, than: np.ndarray) -> np.ndarray:
    """Whether errors (B, r) are closer than errors ``than`` (B, r) by more than the
    position tolerance (in the solver's units): a later start must be clearly better to
    replace an earlier one, so ties keep the configuration nearest ``q0``."""
    margin = problem.position_tol / problem.length
    return np.sqrt(2.0 * problem.energy(error)) < np.sqrt(2.0 * problem.energy(than)) - margin


def _approach(
    problem: Problem,
    found: Search,
    proved: np.ndarray,
    beyond: np.ndarray,
    draws: np.ndarray,
    max_iterations: int,
    limits: bool,
) -> np.ndarray:
    """Take every target not met to the closest configuration (:mod:`._closest`).

    Its best run (a target proved out of reach: its first start) continues by a
    second-order descent. A proved target whose descent from ``q0`` stops short of the
    proved distance (against a joint limit, say) then tries the other starts, a few at
    a time (:data:`EXTRA_STARTS`, each a short least-squares run, the closest of them
    descending in turn) until one reaches the proved distance, and keeps the closest
    clearly closer than the one from ``q0``. Returns which targets end at a local
    minimum of the distance.
    """
    count = len(found.q)
    minimum = np.zeros(count, dtype=bool)
    found.starts[proved] = 1
    failed = np.flatnonzero(found.status != CONVERGED)
    if not failed.size:
        return minimum
    end = descend(problem, failed, found.q[failed], limits, max_iterations)
    found.q[failed], found.error[failed] = end.q, end.error
    found.status[failed] = np.where(end.status == CONVERGED, CONVERGED, found.status[failed])
    found.iterations[failed] += end.iterations
    minimum[failed] = end.minimum
    short = failed[proved[failed] & _short(problem, found.error[failed], beyond[failed])]
    # At most max(T, 128) runs at once, as in the search.
    per_wave = max(1, min(EXTRA_STARTS, max(count, WAVE_RUNS) // max(len(short), 1)))
    for first in range(0, len(draws), per_wave):
        if not short.size:
            break
        chunk = draws[first : first + per_wave]
        index = np.repeat(short, len(chunk))
        steps = min(max_iterations, EXTRA_ITERATIONS)
        run = solve(problem, index, np.tile(chunk, (len(short), 1)), steps, limits)
        energy = problem.energy(run.error).reshape(len(short), len(chunk))
        best = np.arange(len(short)) * len(chunk) + np.argmin(energy, axis=1)
        other = descend(problem, short, run.q[best], limits, max_iterations)
        spent = run.iterations.reshape(len(short), len(chunk)).sum(axis=1)
        found.iterations[short] += spent + other.iterations
        found.starts[short] += len(chunk)
        closer = _closer(problem, other.error, found.error[short])
        chosen = short[closer]
        found.q[chosen], found.error[chosen] = other.q[closer], other.error[closer]
        minimum[chosen] = other.minimum[closer]
        short = short[_short(problem, found.error[short], beyond[short])]
    return minimum


def _short(problem: Problem, error: np.ndarray, beyond: np.ndarray) -> np.ndarray:
    """Whether errors (B, r) miss by more than the proved distance ``beyond`` (B,)."""
    position, _ = problem.error_norms(error)
    return position > beyond + problem.position_tol


def _diagnose(
    problem: Problem,
    batched: bool,
    reach: Reach,
    beyond: np.ndarray,
    proved: np.ndarray,
    minimum: np.ndarray,
    typical: int,
    max_iterations: int,
    search: Search,
) -> IKResult:
    q, error, status, starts = search.q, search.error, search.status, search.starts
    count = len(q)
    reason = ["converged"] * count
    message = [""] * count
    distance = np.zeros(count)
    failed = np.flatnonzero(status != CONVERGED)
    missed, _ = _norms(problem, error)
    for i in failed[proved[failed]]:
        reason[i] = "unreachable"
        distance[i] = beyond[i]
        # Say how far the closest configuration stays when the bound is not reached.
        farther = missed[i] > beyond[i] + problem.position_tol
        closest = float(missed[i]) if farther else None
        message[i] = beyond_reach_message(reach, problem.positions[i], float(beyond[i]), closest)
    open_ = failed[~proved[failed]]
    past = search.outside[open_].any(axis=1)
    for i in open_[past]:
        reason[i] = "joint limit"
        message[i] = joint_limit_message(problem, search.outside_q[i], search.outside[i])
    open_ = open_[~past]

    if open_.size:
        jacobian = problem.expand(problem.jacobian_at(open_, q[open_]))
        found = rank(jacobian[:, :, problem.moving], SINGULAR_TOL)
        full = problem.robot.jacobian(q[open_])
        position, orientation = _norms(problem, error[open_])
        rounding = ~(position > ROUNDING * problem.length) & ~(orientation > ROUNDING)
        for k, i in enumerate(open_):
            lost = dependent_joints(problem, jacobian[k], full[k]) if found[k] < typical else None
            if minimum[i]:
                reason[i] = "unreachable"
                distance[i] = np.nan_to_num(position[k])
                message[i] = closest_message(int(starts[i]), position[k], orientation[k])
            elif lost is not None:
                reason[i] = "singular"
                message[i] = singular_message(*lost)
            else:
                reason[i] = "iteration limit"
                message[i] = iteration_message(
                    max_iterations, int(starts[i]), position[k], orientation[k], rounding[k]
                )

    position, orientation = _norms(problem, error)
    success = status == CONVERGED
    iterations = search.iterations
    for i in np.flatnonzero(success):
        message[i] = converged_message(int(iterations[i]), position[i], orientation[i])
    return single_or_batch(
        batched,
        q=q,
        success=success,
        position_error=position,
        orientation_error=orientation,
        iterations=iterations,
        reason=reason,
        message=message,
        distance_to_reach=distance,
    )


def _norms(problem: Problem, error: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Position and orientation errors; NaN for a kind of row the mask leaves out."""
    position, orientation = problem.error_norms(error)
    if not problem.position_rows.any():
        position = np.full(len(error), np.nan)
    if problem.position_rows.all():
        orientation = np.full(len(error), np.nan)
    return position, orientation
