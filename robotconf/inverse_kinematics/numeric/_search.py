"""The starts of :func:`~robotconf.ik`, tried in turn per target but run in waves.

Each target has a sequence of **runs**: one within the joint ranges from each start
(``q0``, then the target's own starts if the caller gives some — the closed-form
solutions of a recognized arm — then the random ones, nearest first:
:func:`nearest_first`), and, on a robot with clipped joints, the same starts once more
without the ranges (a solution then turned by whole turns to fit them). The answer
is the first run in this order that converges, or the closest of all when none does;
``iterations`` adds up the steps of every run up to it.

Running one run per target at a time would leave a batch of few stragglers iterating
for many steps, start after start. So the runs still needed are run together in
**waves**. The first wave is every target's first start; each later one gives each open
target its next few runs at once (as many as fit in about ``max(T, 128)`` runs: one each
while many targets are open, all the rest for a few), the runs of a target racing in
order — once one converges, the ones behind it stop (:func:`._lm.solve`).
The outcomes are then read in the order above, exactly as if the runs had been tried one
after the other, so a target gets the same answer alone or among others, and whatever
the waves were.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..model._problem import Problem
from ._lm import CONVERGED, STALLED, Run, solve
from ._reasons import fit_into_limits

__all__ = ["Search", "search", "nearest_first", "WAVE_RUNS", "OwnStarts"]

#: A wave holds up to max(T, this) runs.
WAVE_RUNS = 128

#: Targets' own starts (see :func:`search`): index (k,) → starts (k, E, n), counts (k,).
OwnStarts = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]


@dataclass
class Search:
    """The best run of each target so far, over the runs read."""

    problem: Problem
    q: np.ndarray  # (T, n)
    error: np.ndarray  # (T, r)
    energy: np.ndarray  # (T,)
    status: np.ndarray  # (T,)
    iterations: np.ndarray  # (T,) summed over runs
    starts: np.ndarray  # (T,)
    # A solution found without the ranges that no whole-turn twin fits into them:
    # (T, n) coordinates and (T, n) joints outside, the first one found per target.
    outside_q: np.ndarray
    outside: np.ndarray

    @classmethod
    def begin(cls, problem: Problem, first: np.ndarray, limits: bool) -> Search:
        count, n = first.shape
        return cls(
            problem,
            q=problem.project(first, limits),
            error=np.zeros((count, len(problem.rows))),
            energy=np.full(count, np.inf),
            status=np.zeros(count, dtype=int),
            iterations=np.zeros(count, dtype=int),
            starts=np.zeros(count, dtype=int),
            outside_q=np.zeros((count, n)),
            outside=np.zeros((count, n), dtype=bool),
        )

    def keep(self, index: np.ndarray, run: Run) -> None:
        """Keep the runs that converged or came closer than the best so far."""
        energy = self.problem.energy(run.error)
        better = (run.status == CONVERGED) | (energy < self.energy[index])
        chosen = index[better]
        self.q[chosen] = run.q[better]
        self.error[chosen] = run.error[better]
        self.energy[chosen] = energy[better]
        self.status[chosen] = run.status[better]

    def read_limited(self, index: np.ndarray, run: Run) -> None:
        """A run from a new start, within the ranges (or without, when they are off)."""
        self.iterations[index] += run.iterations
        self.starts[index] += 1
        self.keep(index, run)

    def read_free(self, index: np.ndarray, run: Run) -> None:
        """The same start again without the ranges: its solution counts when a whole-turn
        twin of it fits them, and is remembered for the message when none does."""
        self.iterations[index] += run.iterations
        solved = run.status == CONVERGED
        fitted, outside = fit_into_limits(self.problem, run.q[solved])
        inside = ~outside.any(axis=1)
        fits = index[solved][inside]
        if fits.size:
            twins = fitted[inside]
            error = self.problem.errors_at(fits, twins)
            status = np.where(self.problem.converged(error), CONVERGED, STALLED)
            self.keep(fits, Run(twins, error, status, run.iterations[solved][inside]))
        found = index[solved][~inside]
        new = ~self.outside[found].any(axis=1)
        self.outside_q[found[new]] = fitted[~inside][new]
        self.outside[found[new]] = outside[~inside][new]


def search(
    problem: Problem,
    first: np.ndarray,
    draws: np.ndarray,
    proved: np.ndarray,
    max_iterations: int,
    limits: bool,
    own: OwnStarts | None = None,
) -> Search:
    """Try the starts of every target (see the module notes).

    Parameters
    ----------
    problem : Problem
    first : ndarray, shape (T, n)
        Each target's first start.
    draws : ndarray, shape (S − 1, n)
        The random starts, the same for every target.
    proved : ndarray of bool, shape (T,)
        Targets proved out of reach: no runs here (they keep their first start).
    max_iterations : int
        Most steps per run.
    limits : bool
        Keep the joints within their ranges.
    own : callable, optional
        ``own(index)`` gives targets ``index`` (k,) their own starts, tried right after
        the first one and in place of as many random starts: ``(starts (k, E, n),
        counts (k,))`` with ``E ≤ S − 1``. Asked once per target, when its first start
        has failed.

    Returns
    -------
    Search
    """
    state = Search.begin(problem, first, limits)
    count = len(first)
    starts = len(draws) + 1
    clipped = bool(np.any(problem.moving & ~problem.wraps))
    retries = limits and clipped
    # Runs per target: the starts within the ranges, then (retries) the same starts
    # without them; a target proved out of reach gets none: the second-order descent
    # (``_closest``) takes it from its first start to the closest configuration.
    length = np.where(proved, 0, starts * (2 if retries else 1))
    done = np.zeros(count, dtype=int)  # runs read so far, per target
    # Each target's random starts, nearest first (ranked once its first start failed).
    ranking = np.zeros((count, len(draws)), dtype=int)
    # Each target's own starts (ahead of the random ones), once its first start failed.
    mine = np.zeros((count, 0, first.shape[1]))
    mine_count = np.zeros(count, dtype=int)
    while True:
        open_ = np.flatnonzero((state.status != CONVERGED) & (done < length))
        if not open_.size:
            return state
        fresh = open_[done[open_] == 1]
        if fresh.size and len(draws):
            ranking[fresh] = nearest_first(problem, fresh, draws)
            if own is not None:
                given, mine_count[fresh] = own(fresh)
                if given.shape[1] > mine.shape[1]:
                    mine = np.concatenate(
                        [mine, np.zeros((count, given.shape[1] - mine.shape[1], mine.shape[2]))],
                        axis=1,
                    )
                mine[fresh, : given.shape[1]] = given
        # The first wave is every target's first start alone: from a q0 near the answer,
        # as when following a moving target, that is all it takes.
        width = max(1, max(count, WAVE_RUNS) // open_.size) if done.any() else 1
        ahead = np.minimum(done[open_] + width, length[open_]) - done[open_]
        target = np.repeat(open_, ahead)
        offset = np.cumsum(ahead) - ahead
        item = np.repeat(done[open_] - offset, ahead) + np.arange(ahead.sum())
        attempt, free = item % starts, item >= starts
        start = first[target]
        later = attempt > 0
        rank = attempt - 1
        own_start = later & (rank < mine_count[target])
        start[own_start] = mine[target[own_start], rank[own_start]]
        drawn = later & ~own_start
        shift = rank[drawn] - mine_count[target[drawn]]
        start[drawn] = draws[ranking[target[drawn], shift]]
        # A run without the ranges decides nothing by converging: its twin may not fit.
        run = solve(
            problem, target, start, max_iterations, limits & ~free, order=item, decisive=~free
        )
        for k in np.unique(item):
            rows = np.flatnonzero((item == k) & (state.status[target] != CONVERGED))
            if not rows.size:
                continue
            part = Run(run.q[rows], run.error[rows], run.status[rows], run.iterations[rows])
            if k >= starts:
                state.read_free(target[rows], part)
            else:
                state.read_limited(target[rows], part)
        done[open_] += ahead


def nearest_first(problem: Problem, index: np.ndarray, draws: np.ndarray) -> np.ndarray:
    """The random starts ranked for each target ``index`` (k,), nearest first: by the
    error (in the solver's units) their end-effector poses leave, ties in draw order.

    Depends on the target and the draws only, so a target ranks them the same alone or
    among others. Returns (k, S − 1) indices into ``draws``.
    """
    count = len(draws)
    pose = problem.robot.end_effector_pose(problem.project(draws, False))
    targets = np.repeat(index, count)
    error = problem.errors_from_pose(targets, np.tile(pose, (len(index), 1, 1)))
    energy = problem.energy(error).reshape(len(index), count)
    return np.argsort(energy, axis=1, kind="stable")
