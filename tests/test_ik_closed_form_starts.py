"""``rc.ik`` on an arm with a closed form: after ``q0``, the closed-form solutions nearest it.

The PUMA 560's own ``q = 0`` is a wrist singularity, and from it about a third of random
reachable poses are not met. Such a target's next start is the closed-form solution
nearest ``q0`` (within the ranges): it starts within the tolerances, so the answer is that
solution, found without a random start. A target met from ``q0`` keeps ``q0``'s answer.
"""

from __future__ import annotations

import numpy as np

import robotconf as rc
from robotconf.inverse_kinematics import ik, ik_all

PI = np.pi


def _wrapped(q: np.ndarray) -> np.ndarray:
    return np.remainder(q + PI, 2 * PI) - PI


def _targets(robot: rc.Robot, count: int, seed: int) -> np.ndarray:
    limits = robot.joint_limits()
    rng = np.random.default_rng(seed)
    return robot.end_effector_pose(rng.uniform(limits[:, 0], limits[:, 1], (count, robot.n)))


def test_a_target_not_met_from_q0_ends_at_the_nearest_closed_form_solution():
    puma = rc.preset("puma560")
    goals = _targets(puma, 60, seed=11)
    alone = ik(puma, goals, mode="pose", seeds=1, respect_limits=False)
    both = ik(puma, goals, mode="pose", seeds=2, respect_limits=False)
    assert alone.success.all() and both.success.all()
    # Met from q0, a target keeps that answer bit for bit; one that q0's run missed (the
    # descent then took it somewhere) now ends at the closed-form solution nearest q0.
    changed = [k for k in range(len(goals)) if not np.array_equal(alone.q[k], both.q[k])]
    assert len(changed) >= 5
    for k in changed:
        sols = ik_all(puma, goals[k])
        nearest = sols.q[np.argmin(np.sum(_wrapped(sols.q - puma.q) ** 2, axis=1))]
        assert np.abs(_wrapped(both.q[k] - nearest)).max() < 1e-8
        # q0's run and no step more (the closed-form start is already a solution), where
        # seeds=1 went on with the second-order descent.
        assert both.iterations[k] < alone.iterations[k]


def test_within_the_ranges_the_nearest_solution_inside_them():
    puma = rc.preset("puma560")
    goals = _targets(puma, 60, seed=12)
    found = ik(puma, goals, mode="pose")
    assert found.success.all()
    limits = puma.joint_limits()
    assert np.all((found.q >= limits[:, 0] - 1e-12) & (found.q <= limits[:, 1] + 1e-12))
    for k in range(len(goals)):
        sols = ik_all(puma, goals[k])
        gaps = np.abs(_wrapped(sols.q - found.q[k])).max(axis=1)
        assert gaps.min() < 1e-6  # every answer is one of the closed-form solutions


def test_a_target_met_from_q0_keeps_that_answer():
    ur5 = rc.preset("ur5")
    limits = ur5.joint_limits()
    rng = np.random.default_rng(13)
    q = rng.uniform(limits[:, 0], limits[:, 1], (20, 6))
    moved = ur5.end_effector_pose(q + rng.normal(scale=0.02, size=q.shape))
    near = ik(ur5, moved, q0=q, mode="pose")
    first_only = ik(ur5, moved, q0=q, mode="pose", seeds=1)
    assert near.success.all() and first_only.success.all()
    assert np.array_equal(near.q, first_only.q)
    assert np.array_equal(near.iterations, first_only.iterations)


def test_arms_without_a_closed_form_and_masks_are_unchanged_in_kind():
    # A robot without a closed form takes its random starts as before; a mask that
    # leaves the turn about the tool free still takes exact closed-form solutions.
    stanford = rc.preset("stanford")
    goals = _targets(stanford, 20, seed=14)
    assert ik(stanford, goals, mode="pose").success.all()
    puma = rc.preset("puma560")
    goals = _targets(puma, 30, seed=15)
    free_turn = ik(puma, goals, mode="pose", mask=[1, 1, 1, 1, 1, 0])
    assert free_turn.success.all()
