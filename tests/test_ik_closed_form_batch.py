"""``ik_all_many``: the closed forms over many targets agree with ``ik_all`` one by one.

For every family — the presets, random members in both DH conventions, module chains,
held constants — random reachable targets are mixed with unreachable ones and with the
degenerate cases the one-target solver words itself (a target on the first axis, a
stretched or folded elbow, a wrist singularity): each target's rows, labels, limit flags
and reason must be those of ``ik_all`` on that target alone, rows to round-off.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import robotconf as rc
from robotconf import InvalidInputError
from robotconf.inverse_kinematics import IKSolutionSets, ik_all, ik_all_many
from robotconf.inverse_kinematics.closed_form._recognize import closed_form_structure

from .test_ik_closed_form import _random_planar, _random_puma, _random_ur

PI = math.pi


def _assert_same(robot: rc.Robot, targets: np.ndarray, **options) -> IKSolutionSets:
    """Batched == one by one, target by target."""
    angle = options.pop("angle", None)
    sets = ik_all_many(robot, targets, angle=angle, **options)
    assert len(sets) == len(targets) and sets.counts.sum() == len(sets.q)
    assert np.all(np.diff(sets.target) >= 0)
    revolute = np.array([kind == "revolute" for kind in robot.joint_types])
    size = max(1.0, rc.characteristic_length(robot))
    for k, target in enumerate(targets):
        own = None if angle is None else float(np.broadcast_to(angle, (len(targets),))[k])
        one = ik_all(robot, target, angle=own, **options)
        many = sets[k]
        assert many.labels == one.labels, (k, one, many)
        assert many.within_limits.tolist() == one.within_limits.tolist(), k
        assert many.reason == one.reason, k
        assert many.family == one.family and many.q.shape == one.q.shape, k
        gap = many.q - one.q
        gap = np.where(revolute, np.remainder(gap + PI, 2 * PI) - PI, gap / size)
        assert np.abs(gap).max(initial=0.0) < 1e-9, (k, one, many)
    return sets


def _reachable(robot: rc.Robot, count: int, rng: np.random.Generator, pose: bool) -> np.ndarray:
    limits = np.clip(robot.joint_limits(), -PI, PI)
    poses = robot.end_effector_pose(rng.uniform(limits[:, 0], limits[:, 1], (count, robot.n)))
    return poses if pose else poses[:, :3, 3]


def _mixed(robot: rc.Robot, rng: np.random.Generator, pose: bool, count: int = 60) -> np.ndarray:
    """Reachable targets, a sixth of them pushed out of reach (three robot sizes away)."""
    targets = _reachable(robot, count, rng, pose)
    far = 3.0 * rc.characteristic_length(robot)
    points = targets[:, :3, 3] if pose else targets
    points[: count // 6] *= far / np.linalg.norm(points[: count // 6], axis=1, keepdims=True)
    return targets


PRESETS = [
    ("planar_2r", False),
    ("planar_3r", True),
    ("scara", True),
    ("scara", False),  # Spong's SCARA: a point leaves q4 at its own value (a note)
    ("paper", False),
    ("articulated", False),
    ("puma560", True),
    ("ur5", True),
]


@pytest.mark.parametrize(("name", "pose"), PRESETS)
def test_presets_batched_equal_one_by_one(name, pose):
    robot = rc.preset(name)
    robot = robot.with_q(np.clip(0.3 * np.ones(robot.n), *robot.joint_limits().T))
    sets = _assert_same(robot, _mixed(robot, np.random.default_rng(7), pose))
    assert 0 < np.count_nonzero(sets.counts) < len(sets)


@pytest.mark.parametrize("joints", ["RR", "RRR", "RRPR", "RPRR", "RRP"])
@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_random_planar_arms_and_scaras(joints, convention):
    rng = np.random.default_rng(31 + len(joints))
    for _ in range(3):
        robot = _random_planar(rng, joints, convention)
        _assert_same(robot, _mixed(robot, rng, joints.count("R") == 3, 30))


def test_random_six_joint_arms():
    rng = np.random.default_rng(32)
    for k in range(3):
        puma = _random_puma(rng, shoulder=rng.uniform(0.05, 0.3) if k else 0.0)
        if k == 2:
            puma = rc.convert_dh(puma, "modified")
        for robot in (puma, _random_ur(rng)):
            _assert_same(robot, _mixed(robot, rng, True, 30))


def test_random_elbow_arms_and_module_chains():
    rng = np.random.default_rng(33)
    a1, d2, a2, a3 = rng.uniform(0.1, 1.0, size=4)
    rows = [(0.0, 0.5, a1, PI / 2, "R"), (0.3, d2, a2, 0.0, "R"), (-0.2, 0.0, a3, 0.0, "R")]
    offset_elbow = rc.Robot.from_dh(rows, end_effector=(0.1, 0.2, 0.0))
    m = rc.Module
    wrist_arm = rc.Robot(
        [m("Rz"), m("Ry", a=(0, 0, 20)), m("Ry", a=(30, 0, 0)), m("Rx", a=(25, 0, 0)), m("Ry")]
        + [m("Rx")],
        end_effector=(5, 0, 2),
    )
    _assert_same(offset_elbow, _mixed(offset_elbow, rng, False))
    _assert_same(wrist_arm, _mixed(wrist_arm, rng, True))


def test_held_constants():
    puma = rc.preset("puma560")
    modules = [m for link in puma.modules for m in rc.dh_to_modules(link)]
    held = [i for i, module in enumerate(modules) if "(constant)" in (module.name or "")]
    renamed = rc.Robot([m.with_name(None) if i in held else m for i, m in enumerate(modules)])
    rng = np.random.default_rng(34)
    _assert_same(renamed, _mixed(renamed, rng, True, 20), constant=held)


def test_degenerate_targets_among_regular_ones():
    # Each of these takes the one-target path (a double root, a free joint, a singular
    # wrist), in the middle of a batch.
    rng = np.random.default_rng(35)
    two = rc.preset("planar_2r", l1=1, l2=1).with_q([0.4, 0.0])
    points = np.concatenate([_reachable(two, 5, rng, False), [[2, 0, 0], [0, 0, 0], [1, 1, 0]]])
    _assert_same(two, points)
    paper = rc.preset("paper").with_q([0.25, 0, 0])
    axis = [[0, 0, 50], [0, 0, 20 + 70], [70, 0, 20], [0, 0, -30]]  # on axis 1, stretched
    _assert_same(paper, np.concatenate([_reachable(paper, 5, rng, False), axis]))
    puma = rc.preset("puma560").with_q([0, 0, 0, 0.7, 0, 0])
    singular = puma.end_effector_pose([[0.3, 0.4, -0.5, 0.2, 0.0, 0.9], [0.1, 0.2, 0.3, 0, 0, 0]])
    sets = _assert_same(puma, np.concatenate([_reachable(puma, 5, rng, True), singular]))
    assert "wrist singularity" in sets[5].reason
    ur5 = rc.preset("ur5").with_q([0, 0, 0, 0, 0, -0.4])
    flat = ur5.end_effector_pose([[0.5, -1.2, 1.4, 0.3, 0.0, 0.8]])
    _assert_same(ur5, np.concatenate([flat, _reachable(ur5, 5, rng, True)]))


def test_poses_for_arms_that_set_a_point():
    arm = rc.preset("planar_2r")
    poses = arm.end_effector_pose([[0.3, 0.5], [1.0, -0.4], [2.0, 1.0]])
    poses[1, :3, :3] = poses[1, :3, :3] @ np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1.0]])
    sets = _assert_same(arm, poses)
    assert "1 more branch reaches the point with another orientation" in sets[0].reason
    assert "cannot also give the target's orientation" in sets[1].reason


def test_planar_3r_points_with_angles():
    arm = rc.preset("planar_3r", l1=1, l2=1, l3=1)
    points = np.array([[1.0, 2.0, 0.0], [1.0, 2.0, 0.0], [0.5, 0.5, 0.0], [9.0, 0.0, 0.0]])
    angles = np.array([PI / 2, 0.3, -1.0, 0.0])
    sets = _assert_same(arm, points, angle=angles)
    np.testing.assert_allclose(sets[0].q, [[0, PI / 2, 0], [PI / 2, -PI / 2, PI / 2]], atol=1e-12)
    _assert_same(arm, points, angle=PI / 2)  # one angle for all


def test_the_answer_table():
    arm = rc.preset("planar_2r", l1=1, l2=1)
    sets = ik_all_many(arm, [[1, 1, 0], [3, 0, 0], [0, 1.5, 0]])
    assert sets.counts.tolist() == [2, 0, 2] and sets.target.tolist() == [0, 0, 2, 2]
    assert len(sets.labels) == len(sets.q) == len(sets.within_limits) == 4
    assert [len(s) for s in sets] == [2, 0, 2] and len(sets[-1]) == 2
    assert sets[1].reason.startswith("the target is 1 beyond the reach")
    with pytest.raises(IndexError):
        sets[3]
    with pytest.raises(ValueError):
        sets.q[0, 0] = 1.0  # read-only, as IKSolutions
    assert str(sets) == (
        "planar 2R: 3 targets, 4 solutions (2 targets with at least one, 4 solutions within "
        "the limits)"
    )


def test_the_robots_structure_is_read_once_per_geometry():
    scara = rc.preset("scara")
    chain, family, why = closed_form_structure(scara)
    assert family == "SCARA" and why == ""
    for q4 in (0.7, -0.2):
        moved = scara.with_q([0, 0, 0, q4])
        again, _, _ = closed_form_structure(moved)
        assert again.joints is chain.joints and again.robot is moved
        # The free tool turn keeps each copy's own q4, alone and in a batch.
        np.testing.assert_allclose(ik_all(moved, [30, 40, 25]).q[:, 3], q4)
        np.testing.assert_allclose(ik_all_many(moved, [[30, 40, 25]]).q[:, 3], q4)
    assert closed_form_structure(scara.with_end_effector([1.0, 0, 0]))[0] is not chain


@pytest.mark.parametrize(
    ("robot", "targets", "options", "field"),
    [
        ("paper", [1.0, 2.0, 3.0], {}, "targets"),  # one point: use ik_all
        ("paper", np.zeros((0, 3)), {}, "targets"),
        ("paper", [[1.0, 2.0, 3.0], [np.nan, 0, 0]], {}, "targets[1]"),
        ("puma560", [np.eye(4), np.diag([1.0, 1.0, -1.0, 1.0])], {}, "targets[1]"),
        ("puma560", [[0.5, 0.0, 0.4]], {}, "targets"),  # a point for a 6R arm
        ("stanford", [np.eye(4)], {}, "robot"),
        ("paper", [[1.0, 2.0, 3.0]], {"angle": 0.3}, "angle"),
        ("planar_3r", [[1.0, 2.0, 0.0]] * 3, {"angle": [0.1, 0.2]}, "angle"),
    ],
)
def test_bad_input_names_the_field(robot, targets, options, field):
    with pytest.raises(InvalidInputError) as caught:
        ik_all_many(rc.preset(robot), targets, **options)
    assert caught.value.field == field


def test_memory_budget_is_checked_first():
    rc.set_memory_budget(1)
    try:
        with pytest.raises(InvalidInputError) as caught:
            ik_all_many(rc.preset("paper"), np.zeros((100_000, 3)))
        assert caught.value.field == "targets"
    finally:
        rc.set_memory_budget(None)
