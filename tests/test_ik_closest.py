"""Targets out of reach: an honest reason and distance, and the closest configuration.

Every distance here is checked against an independent computation: the planar 2R arm's
reachable set is the annulus ``|l1 − l2| ≤ ρ ≤ l1 + l2`` in its plane (closed form), and
the paper robot's is sampled densely in its two arm joints (the base turn is solved by
hand) and refined by a pattern search, with its joint ranges.
"""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.inverse_kinematics import ik

# -- the planar 2R arm: reason and distance ---------------------------------------------


def annulus_distance(targets: np.ndarray, inner: float, outer: float) -> np.ndarray:
    """Distance from points to the annulus inner ≤ ρ ≤ outer in the plane z = 0."""
    rho = np.hypot(targets[:, 0], targets[:, 1])
    across = np.maximum(0.0, np.maximum(rho - outer, inner - rho))
    return np.hypot(targets[:, 2], across)


def test_the_minimal_case_off_the_plane_above_the_hole():
    # ρ = 0.5 is 0.5 inside the hole (radius 1), and 2 above the plane: √(0.25 + 4).
    result = ik(rc.preset("planar_2r", l1=2, l2=1), [0.5, 0.0, 2.0])
    assert result.reason == "unreachable"
    assert result.distance_to_reach == pytest.approx(np.sqrt(4.25), abs=1e-12)
    assert result.position_error == pytest.approx(np.sqrt(4.25), abs=1e-12)
    assert "2.062 out of reach" in result.message


def test_every_target_off_the_plane_or_in_the_hole_is_unreachable_with_its_true_distance():
    robot = rc.preset("planar_2r", l1=2, l2=1)
    radii = [0.0, 0.2, 0.4, 0.6, 0.8, 0.95]
    heights = [-2.0, -1.0, -0.5, 0.5, 1.0, 2.0, 3.0]
    angles = np.linspace(0.0, 2 * np.pi, len(radii) * len(heights), endpoint=False)
    targets = np.array(
        [
            [r * np.cos(a), r * np.sin(a), z]
            for (r, z), a in zip([(r, z) for r in radii for z in heights], angles, strict=True)
        ]
    )
    result = ik(robot, targets)
    truth = annulus_distance(targets, 1.0, 3.0)
    assert len(targets) == 42 and result.reason == ("unreachable",) * 42
    np.testing.assert_allclose(result.distance_to_reach, truth, rtol=0, atol=1e-12)
    # The configuration returned reaches that closest point.
    np.testing.assert_allclose(result.position_error, truth, rtol=0, atol=1e-9)
    # Inside the plane, outside the annulus, too.
    flat = np.array([[0.3, 0.4, 0.0], [3.2, -1.0, 0.0], [-4.0, 0.0, 0.0]])
    np.testing.assert_allclose(ik(robot, flat).distance_to_reach, annulus_distance(flat, 1, 3))


# -- the paper robot: the closest configuration -----------------------------------------

L2, L3, SHOULDER = 30.0, 40.0, 20.0
Q2_RANGE, Q3_RANGE = np.pi / 2, 3 * np.pi / 4


def arm_plane(q2: np.ndarray, q3: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The paper robot's end effector in the plane its base turn sets: horizontal reach x
    (signed) and height z. Written out from the modules Ry(q2) then Ry(q3)."""
    x = L2 * np.cos(q2) + L3 * np.cos(q2 + q3)
    z = SHOULDER - L2 * np.sin(q2) - L3 * np.sin(q2 + q3)
    return x, z


def paper_distance(target: np.ndarray) -> float:
    """The true closest distance, within the joint ranges. The base turns a full turn, so
    a target at horizontal distance ρ is met by |x| = ρ (turning to it, or away for
    x < 0): distance² = (|x| − ρ)² + (z − z_t)². A 401² grid of (q2, q3), then a pattern
    search from the best node down to steps of 1e-12 rad."""
    rho, height = float(np.hypot(target[0], target[1])), float(target[2])

    def squared(a: float, b: float) -> float:
        x, z = arm_plane(np.array(a), np.array(b))
        return float((abs(x) - rho) ** 2 + (z - height) ** 2)

    q2 = np.linspace(-Q2_RANGE, Q2_RANGE, 401)
    q3 = np.linspace(-Q3_RANGE, Q3_RANGE, 401)
    grid2, grid3 = np.meshgrid(q2, q3, indexing="ij")
    x, z = arm_plane(grid2, grid3)
    k = int(np.argmin((np.abs(x) - rho) ** 2 + (z - height) ** 2))
    a, b = float(grid2.ravel()[k]), float(grid3.ravel()[k])
    best, step = squared(a, b), float(q2[1] - q2[0])
    moves = [(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1), (1, -1), (-1, 1)]
    while step > 1e-12:
        for da, db in moves:
            na = float(np.clip(a + da * step, -Q2_RANGE, Q2_RANGE))
            nb = float(np.clip(b + db * step, -Q3_RANGE, Q3_RANGE))
            value = squared(na, nb)
            if value < best:
                a, b, best = na, nb, value
                break
        else:
            step /= 2
    return float(np.sqrt(best))


def test_behind_the_robot_from_q0_the_arm_turns_round_to_the_closest_configuration():
    # From q = 0 the arm points along +x, straight away from (−100, 0, 20): every joint
    # motion is orthogonal to the error there (a saddle of the distance), and the answer
    # used to stay at q = 0, 170 away. Turned round it is 100 − 70 = 30 away.
    robot = rc.preset("paper")
    result = ik(robot, [-100.0, 0.0, 20.0], q0=[0.0, 0.0, 0.0])
    assert result.reason == "unreachable" and result.distance_to_reach == 30.0
    assert result.position_error == pytest.approx(30.0, abs=1e-9)
    np.testing.assert_allclose(robot.end_effector(result.q), [-70.0, 0.0, 20.0], atol=1e-7)


def test_targets_out_of_reach_get_the_closest_configuration():
    # Beyond the reach (the bound 70 is met) and inside the joint ranges' hole (a fold of
    # at most 135° leaves √(30² + 40² − 2·30·40·cos 45°) = 28.3 from the shoulder, while
    # the proved hole is only 10): both end at the true closest distance.
    rng = np.random.default_rng(0)
    directions = rng.normal(size=(40, 3))
    directions /= np.linalg.norm(directions, axis=1, keepdims=True)
    radius = np.concatenate([rng.uniform(71, 170, 24), rng.uniform(0, 28, 16)])
    targets = np.array([0.0, 0.0, SHOULDER]) + directions * radius[:, np.newaxis]
    result = ik(rc.preset("paper"), targets)
    truth = np.array([paper_distance(t) for t in targets])
    assert not np.any(result.success)
    np.testing.assert_allclose(result.position_error, truth, rtol=0, atol=1e-7)
    # Where the bound is the truth it is the reported distance; the hole's bound is lower.
    beyond = radius > 70
    np.testing.assert_allclose(result.distance_to_reach[beyond], truth[beyond], atol=1e-12)
    assert np.all(result.distance_to_reach <= truth + 1e-12)


def test_a_descent_stopped_at_a_joint_limit_tries_the_other_starts():
    # With the base limited to ±90°, the descent from this q0 stops against a joint limit
    # 92.8 from the target, short of the proved 51: the other starts are tried, and the
    # closest configuration of all is kept (no sampled configuration is closer).
    robot = rc.preset("paper").with_limits(0, (-np.pi / 2, np.pi / 2))
    target = np.array([-49.2, -104.9, -14.9])
    q0 = [0.89, -0.81, -1.34]
    alone = ik(robot, target, q0=q0, seeds=1)
    result = ik(robot, target, q0=q0)
    assert result.reason == alone.reason == "unreachable"
    assert alone.position_error > result.position_error + 20
    samples = np.stack(
        np.meshgrid(
            np.linspace(-np.pi / 2, np.pi / 2, 61),
            np.linspace(-Q2_RANGE, Q2_RANGE, 61),
            np.linspace(-Q3_RANGE, Q3_RANGE, 61),
            indexing="ij",
        ),
        axis=-1,
    ).reshape(-1, 3)
    sampled = np.min(np.linalg.norm(robot.end_effector(samples) - target, axis=1))
    assert result.position_error <= sampled + 1e-9
    assert sampled - result.position_error < 1.0  # the 3° grid misses it by little
    assert "the closest configuration found misses it by 63.76" in result.message


def test_a_robot_without_a_moving_joint_stands_where_it_is():
    # One "none" module: the end effector is fixed at (1, 0, 0); every other point is
    # missed by exactly its distance to it, and the robot's own point is met.
    robot = rc.Robot([rc.Module("none", (1, 0, 0))], end_effector=(1, 0, 0))
    targets = np.array([[1.0, 2.0, 3.0], [2.0, 0.0, 0.0], [1.0, 0.0, 0.0]])
    result = ik(robot, targets)
    np.testing.assert_array_equal(result.q, np.zeros((3, 1)))
    assert list(result.success) == [False, False, True]
    assert list(result.reason[:2]) == ["unreachable", "unreachable"]
    np.testing.assert_allclose(result.position_error, [np.sqrt(13.0), 1.0, 0.0], atol=1e-12)


def test_a_line_move_of_a_robot_without_a_moving_joint_is_refused_by_name():
    from robotconf.programs import LIN, Program

    robot = rc.Robot([rc.Module("none", (1, 0, 0))], end_effector=(1, 0, 0))
    with pytest.raises(rc.InvalidInputError, match=r"moves\[0\]\.position: unreachable"):
        Program(robot, [LIN(position=[2, 0, 0], speed=1)])
