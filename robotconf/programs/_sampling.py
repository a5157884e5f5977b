"""Sampling a planned program: joint values, velocities and accelerations on a time grid.

PTP and Wait moves are closed forms: ``q = q0 + Δ·u(t)``, ``q̇ = Δ·u̇``, ``q̈ = Δ·ü``.
LIN and CIRC samples are solved by one batched ``rc.ik`` call (seeded from the knots,
see :mod:`robotconf.programs._tracking`); then, with the Jacobian ``J`` at each sample,

    q̇ = J⁺ ẋ,      q̈ = J⁺ (ẍ − J̇ q̇)

(``J⁺`` the pseudo-inverse over the generic rank, ``J̇ q̇`` exact, see
:mod:`robotconf.programs._chain`), so the motion's DVA needs no differencing.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from .._budget import check_memory
from .._errors import InvalidInputError
from ..inverse_kinematics import ik
from ..motion import SimulationSettings
from ._chain import Chain, bias, kinematics, solve
from ._plan import PATH_TOL, Segment
from ._tracking import hermite

__all__ = ["Samples", "sample", "bytes_per_sample"]


def bytes_per_sample(n: int) -> float:
    """Peak bytes per time sample for an ``n``-joint robot (an upper estimate).

    It adds ``rc.ik``'s per-target memory, the Jacobians and their SVDs, two outward
    recursions (``J̇ q̇`` and the motion's DVA) and the coordinate arrays.

    >>> bytes_per_sample(6)
    10976.0
    """
    return 8.0 * (7 * n * n + 120 * n + 400)


@dataclass(frozen=True, eq=False)
class Samples:
    """A program sampled on a time grid.

    Attributes
    ----------
    t : ndarray, shape (T,)
    q, qd, qdd : ndarray, shape (T, n)
    move : ndarray of int, shape (T,)
        The move each sample belongs to.
    cartesian : ndarray of bool, shape (T,)
        Samples of LIN and CIRC moves.
    solved : ndarray of bool, shape (T,)
        Whether ``rc.ik`` met its tolerances (True outside LIN/CIRC moves).
    sigma : ndarray, shape (T,)
        Smallest generic singular value of the scaled Jacobian (NaN outside LIN/CIRC).
    error : ndarray, shape (T,)
        ``rc.ik``'s position error (length; 0 outside LIN/CIRC).
    failures : dict
        Sample index → (reason, message) of ``rc.ik`` where it failed.
    """

    t: np.ndarray
    q: np.ndarray
    qd: np.ndarray
    qdd: np.ndarray
    move: np.ndarray
    cartesian: np.ndarray
    solved: np.ndarray
    sigma: np.ndarray
    error: np.ndarray
    failures: dict[int, tuple[str, str]] = field(default_factory=dict)


def time_grid(total: float, dt: float, n: int) -> np.ndarray:
    """``0, dt, 2dt, …`` up to the program's end, which is always the last sample."""
    if not total > 0.0:
        raise InvalidInputError(
            "moves",
            "<a program of duration 0>",
            "a program that moves or waits",
            problem="nothing to sample:",
        )
    settings = SimulationSettings(t_end=total, dt=dt)
    count = settings.check_samples(n + 1)
    check_memory(
        "dt",
        settings.dt,
        (count + 1) * bytes_per_sample(n),
        "a larger dt (or a shorter program), or a larger memory budget",
    )
    t = settings.time_grid(n + 1)
    if total - t[-1] > 1e-9 * settings.dt:
        t = np.append(t, total)
    return t


def _owner(t: np.ndarray, segments: Sequence[Segment]) -> tuple[np.ndarray, list[Segment]]:
    timed = [s for s in segments if s.duration > 0.0]
    starts = np.array([s.start for s in timed])
    index = np.clip(np.searchsorted(starts, t, side="right") - 1, 0, len(timed) - 1)
    return index, timed


def sample(chain: Chain, segments: Sequence[Segment], dt: float) -> Samples:
    """Sample the planned ``segments`` every ``dt`` seconds (see the module notes)."""
    n = chain.robot.n
    t = time_grid(segments[-1].end, dt, n)
    count = t.size
    q, qd, qdd = np.empty((count, n)), np.zeros((count, n)), np.zeros((count, n))
    move = np.empty(count, dtype=int)
    cartesian = np.zeros(count, dtype=bool)
    owner, timed = _owner(t, segments)
    parts = []
    for k, segment in enumerate(timed):
        rows = np.flatnonzero(owner == k)
        if not rows.size:
            continue
        move[rows] = segment.index
        u, ud, udd = segment.profile.evaluate(t[rows] - segment.start)
        if segment.path is None or segment.knots is None:
            delta = segment.q_end - segment.q_start
            q[rows] = segment.q_start + u[:, np.newaxis] * delta
            qd[rows] = ud[:, np.newaxis] * delta
            qdd[rows] = udd[:, np.newaxis] * delta
            continue
        cartesian[rows] = True
        pose, twist, rate = segment.path.evaluate(u, ud, udd)
        parts.append((rows, u, pose, twist, rate, hermite(segment.knots, u), segment))
    solved = np.ones(count, dtype=bool)
    sigma = np.full(count, np.nan)
    error = np.zeros(count)
    failures: dict[int, tuple[str, str]] = {}
    if parts:
        rows = np.concatenate([p[0] for p in parts])
        pose = np.concatenate([p[2] for p in parts])
        twist = np.concatenate([p[3] for p in parts])
        rate = np.concatenate([p[4] for p in parts])
        seeds = np.concatenate([p[5] for p in parts])
        result = ik(
            chain.robot,
            pose if chain.mode == "pose" else pose[:, :3, 3],
            q0=seeds,
            mode=chain.mode,
            seeds=1,
            respect_limits=False,
            tol=PATH_TOL,
            orientation_tol=PATH_TOL,
        )
        solution = result.q
        offset = 0
        for part_rows, u, *_, segment in parts:
            block = solution[offset : offset + part_rows.size]
            block[u <= 0.0] = segment.q_start
            block[u >= 1.0] = segment.q_end
            offset += part_rows.size
        q[rows] = solution
        solved[rows] = result.success
        error[rows] = result.position_error
        for bad in np.flatnonzero(~result.success).tolist():
            failures[int(rows[bad])] = (result.reason[bad], result.message[bad])
        _, jac = kinematics(chain, solution)
        velocity, sigma[rows] = solve(chain, jac, twist)
        qd[rows] = velocity
        qdd[rows], _ = solve(chain, jac, rate - bias(chain, solution, velocity, jac))
    return Samples(t, q, qd, qdd, move, cartesian, solved, sigma, error, failures)
