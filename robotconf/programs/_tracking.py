"""Following a Cartesian path in joint space: knots when planning, seeds when sampling.

Planning a LIN or CIRC move walks its path in ``K`` equal steps of ``u`` (a knot every
5 % of the robot's size and every 0.1 rad of turn, 8 … 128 knots). Each knot starts from
the previous one and takes two damped Gauss–Newton steps towards its pose, so the walk
stays on the branch it started on; the last knot is then solved exactly by ``rc.ik``
seeded from it, which also tells why when the end cannot be reached. The knots carry
``dq/du = J⁺ p'(u)``.

Sampling solves every sample with one batched ``rc.ik`` call, each sample seeded from
the cubic Hermite interpolation of its two neighbouring knots (values and ``dq/du``):
a seed a few steps of Newton's method from the sample's own solution, on the same
branch. Where the path passes a singularity the knots may jump; ``Program.check``
reports it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._chain import Chain, kinematics, pose_error, solve
from ._paths import CartesianPath

__all__ = ["Knots", "knot_count", "track", "make_knots", "hermite"]

#: Steps of Gauss–Newton per knot, and their damping (scaled units).
KNOT_STEPS = 2
KNOT_DAMPING = 1e-4
MIN_KNOTS, MAX_KNOTS = 8, 128
#: A walk has kept to the path when every knot comes this close (scaled: relative to the
#: robot's size, and rad) before its last step; Newton's method then leaves about its
#: square after it. A walk that lost the path (through the workspace's hole, or where the
#: branch flips) stays far off.
KNOT_RESIDUAL = 0.05


@dataclass(frozen=True, eq=False)
class Knots:
    """Joint values along a path: ``q`` (K+1, n) and ``dq/du`` (K+1, n) at ``u`` (K+1,)."""

    u: np.ndarray
    q: np.ndarray
    slope: np.ndarray


def knot_count(path: CartesianPath, length: float) -> int:
    """Knots for a path: one per 5 % of the robot's size ``length`` and per 0.1 rad.

    >>> from robotconf.programs._paths import line_path
    >>> knot_count(line_path(np.zeros(3), np.array([1.0, 0, 0]), np.eye(3), np.eye(3)), 1.0)
    20
    """
    wanted = max(path.length / (0.05 * length), path.angle / 0.1)
    return int(np.clip(np.ceil(wanted), MIN_KNOTS, MAX_KNOTS))


def track(
    chain: Chain, path: CartesianPath, q_start: np.ndarray, u: np.ndarray
) -> tuple[np.ndarray, bool]:
    """Walk ``path`` from ``q_start`` through the knots at ``u`` (see the module notes).

    Returns
    -------
    q : ndarray, shape (K+1, n)
        ``q[0]`` is ``q_start``; ``q[-1]`` is the walk's end, to be solved exactly.
    kept : bool
        Whether every knot came within :data:`KNOT_RESIDUAL` (scaled) of its pose.
    """
    count = u.size - 1
    targets, _, _ = path.evaluate(u, np.zeros_like(u), np.zeros_like(u))
    q = np.empty((count + 1, chain.robot.n))
    q[0] = q_start
    current = q_start[np.newaxis].copy()
    worst = 0.0
    for k in range(1, count + 1):
        for _ in range(KNOT_STEPS):
            pose, jac = kinematics(chain, current)
            error = pose_error(chain, targets[k : k + 1], pose)
            step, _ = solve(chain, jac, error, damping=KNOT_DAMPING)
            current = current + step
        q[k] = current[0]
        # The residual before the last step bounds the one after it (Newton converges).
        worst = max(worst, float(np.linalg.norm(error[0, chain.rows] * chain.row_scale)))
    return q, worst <= KNOT_RESIDUAL


def make_knots(chain: Chain, path: CartesianPath, u: np.ndarray, q: np.ndarray) -> Knots:
    """The knots ``q`` at ``u`` with their slopes ``dq/du = J⁺ x'(u)``."""
    _, tangent, _ = path.evaluate(u, np.ones_like(u), np.zeros_like(u))
    _, jac = kinematics(chain, q)
    slope, _ = solve(chain, jac, tangent, damping=KNOT_DAMPING)
    return Knots(u, q, slope)


def hermite(knots: Knots, u: np.ndarray) -> np.ndarray:
    """Cubic Hermite interpolation of the knots at ``u`` (T,), shape (T, n).

    >>> knots = Knots(np.array([0.0, 1.0]), np.array([[0.0], [1.0]]), np.array([[0.0], [0.0]]))
    >>> hermite(knots, np.array([0.5]))  # smoothstep
    array([[0.5]])
    """
    k = np.clip(np.searchsorted(knots.u, u, side="right") - 1, 0, knots.u.size - 2)
    h = knots.u[k + 1] - knots.u[k]
    s = ((u - knots.u[k]) / h)[:, np.newaxis]
    s2, s3 = s * s, s * s * s
    h00, h10 = 2 * s3 - 3 * s2 + 1, s3 - 2 * s2 + s
    h01, h11 = -2 * s3 + 3 * s2, s3 - s2
    hh = h[:, np.newaxis]
    return (
        h00 * knots.q[k]
        + h10 * hh * knots.slope[k]
        + h01 * knots.q[k + 1]
        + h11 * hh * knots.slope[k + 1]
    )
