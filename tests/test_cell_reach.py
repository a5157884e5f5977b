"""``cell.reach`` against rc.ik_all + joint limits + cell.clearance; placement by brute force."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc


def _paper_cell():
    cell = rc.Cell(unit="mm")
    cell.add_robot("arm", rc.preset("paper"), base=rc.pose([0, 0, 5]), mount="table")
    cell.add(rc.Box([200, 200, 10], pose=rc.pose([0, 0, 0]), name="table"))
    cell.add(rc.Box([15, 15, 30], pose=rc.pose([40, 30, 20]), name="fixture"))
    cell.add(rc.Cylinder(4, 40, pose=rc.pose([-30, 20, 25]), name="post"))
    return cell


def _by_hand(cell, robot, world_point):
    """Branches, within limits, collision-free: from the three public calls alone."""
    base = cell.pose_of(robot)
    local = np.linalg.solve(base, np.append(world_point, 1.0))[:3]
    solutions = rc.ik_all(cell.robot(robot), local)
    free = 0
    for q, ok in zip(solutions.q, solutions.within_limits, strict=True):
        if ok and cell.clearance(robot, q).distance >= 0.0:
            free += 1
    return len(solutions), int(solutions.within_limits.sum()), free


def test_reach_agrees_with_ik_all_limits_and_clearance_on_every_target():
    cell = _paper_cell()
    rng = np.random.default_rng(3)
    targets = rng.uniform([-80, -80, 5], [80, 80, 90], (150, 3))
    result = cell.reach("arm", targets)
    assert 0 < result.reachable.sum() < len(targets)
    assert np.any((result.within_limits > 0) & ~result.reachable)  # some only collide
    for k, point in enumerate(targets):
        expected = _by_hand(cell, "arm", point)
        got = (result.branches[k], result.within_limits[k], result.collision_free[k])
        assert got == expected, (k, point)
        assert result.reachable[k] == (expected[2] > 0)
        if result.reachable[k]:
            q = result.q[k]
            jac = cell.robot("arm").jacobian(q)[:3]
            assert result.manipulability[k] == pytest.approx(abs(np.linalg.det(jac)), rel=1e-9)
            assert np.allclose(cell.robot("arm").end_effector(q) + [0, 0, 5], point, atol=1e-9)
        else:
            assert result.reasons[k]


def test_reasons_name_the_distance_the_limits_and_the_collision():
    cell = _paper_cell()
    result = cell.reach("arm", [[120, 0, 25], [60, 0, 8]])
    assert result.reasons[0].startswith("the target is 50 beyond the reach")
    # Low over the table: every branch within the limits has its forearm in the table.
    assert result.reasons[1].startswith("only with the shoulder front, elbow")
    assert "which hits 'table'" in result.reasons[1]


def test_reach_of_frames_and_poses_for_a_six_joint_arm():
    cell = rc.Cell()
    puma = rc.preset("puma560")
    cell.add_robot("puma", puma, base=rc.pose([0.2, 0.1, 0.0], [0, 0, 0.3]))
    goal = cell.pose_of("puma") @ puma.end_effector_pose([0.3, 0.2, -0.4, 0.5, 0.6, 0.7])
    cell.add_frame("pick", goal)
    result = cell.reach("puma", "pick")
    assert result.reachable[0] and result.branches[0] == 8
    with pytest.raises(rc.InvalidInputError) as caught:
        cell.reach("puma", [0.5, 0.0, 0.4])
    assert caught.value.field == "targets[0]"


def test_a_tool_moves_the_reach_to_its_tcp():
    cell = rc.Cell()
    cell.add_robot("arm", rc.preset("paper"), tool=rc.Tool(tcp=rc.pose([10, 0, 0])))
    stretched = cell.reach("arm", [[80, 0, 20], [81, 0, 20]])
    assert stretched.branches.tolist() == [2, 0]  # the TCP is 10 beyond the flange
    segments, radii = cell.link_capsules("arm", [0, 0, 0])
    assert segments[-1].tolist() == [[70.0, 0.0, 20.0], [80.0, 0.0, 20.0]]
    assert cell.link_names("arm") == ("link 1", "link 2", "link 3", "tool")


def test_place_finds_a_base_whenever_one_exists_on_the_grid():
    cell = rc.Cell(unit="mm")
    cell.add_robot("arm", rc.preset("paper"))
    cell.add(rc.Box([20, 20, 40], pose=rc.pose([60, 45, 20]), name="fixture"))
    targets = [[90, 0, 30], [80, 25, 30], [70, -20, 40]]
    region = [(0, -40, 0), (60, 40, 0)]
    plan = cell.place("arm", targets, region, step=20)
    brute = []
    for position in plan.positions:
        trial = rc.Cell(unit="mm")
        trial.add_robot("arm", rc.preset("paper"), base=rc.pose(position))
        trial.add(rc.Box([20, 20, 40], pose=rc.pose([60, 45, 20]), name="fixture"))
        brute.append(trial.reach("arm", targets).all_reachable)
    assert plan.feasible.tolist() == brute
    assert any(brute) and plan.best is not None and brute[plan.best]
    assert plan.margin[plan.best] == np.nanmax(plan.margin)
    assert "base positions reach every target; best at" in str(plan)
    nowhere = cell.place("arm", [[500, 0, 0]], region, step=20)
    assert nowhere.best is None and not nowhere.feasible.any()


def test_reach_map_matches_reach_at_every_voxel():
    cell = _paper_cell()
    rmap = cell.reach_map("arm", [(-60, -60, 20), (60, 60, 60)], 20)
    assert rmap.shape == (7, 7, 3) and rmap.grid().shape == (7, 7, 3)
    again = cell.reach("arm", rmap.points)
    assert np.array_equal(rmap.branches, again.collision_free)
    assert np.array_equal(np.isnan(rmap.manipulability), ~again.reachable)
    with pytest.raises(rc.InvalidInputError) as caught:
        cell.reach_map("arm", [(-1e6, -1e6, 0), (1e6, 1e6, 1e6)], 1)
    assert caught.value.field == "step"
