"""Closed-form inverse kinematics: ``ik_all`` lists every solution, ``recognize`` the family.

Round trips: a configuration q within the joint ranges gives a target by forward
kinematics; every solution must reproduce that target and one of them must be q (up to
whole turns). Counts, labels, reasons and refusals are checked against hand-derived
values, and the solution sets against an independent Newton search.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import robotconf as rc
from robotconf import InvalidInputError
from robotconf.inverse_kinematics import IKSolutions, ik_all, recognize

PI = math.pi
RNG_SEED = 20240611


def _revolute(robot: rc.Robot) -> np.ndarray:
    return np.array([kind == "revolute" for kind in robot.joint_types])


def _gap(a: np.ndarray, b: np.ndarray, revolute: np.ndarray) -> float:
    """Largest difference of two configurations, angles compared modulo 2π."""
    diff = a - b
    diff = np.where(revolute, np.abs(np.remainder(diff + PI, 2 * PI) - PI), np.abs(diff))
    return float(diff.max())


def _check(
    robot: rc.Robot, q: np.ndarray, pose: bool, count: int | None = None, **options
) -> IKSolutions:
    """FK(q) → ik_all: every row reproduces the target and one row is q."""
    target = robot.end_effector_pose(q)
    sols = ik_all(robot, target if pose else target[:3, 3], **options)
    size = max(rc.characteristic_length(robot), float(np.linalg.norm(target[:3, 3])))
    assert sols.q.shape == (len(sols), robot.n) and len(sols.labels) == len(sols)
    assert len(sols) >= 1, sols.reason
    reached = robot.end_effector_pose(sols.q)
    assert np.abs(reached[:, :3, 3] - target[:3, 3]).max() <= 1e-9 * size
    if pose:
        assert np.abs(reached[:, :3, :3] - target[:3, :3]).max() <= 1e-9
    revolute = _revolute(robot)
    assert min(_gap(row, q, revolute) for row in sols.q) < 1e-7, (q, sols)
    angles = sols.q[:, revolute]
    assert np.all(angles > -PI) and np.all(angles <= PI)
    if count is not None:
        assert len(sols) == count, sols
        assert len(set(sols.labels)) == count
    return sols


def _random_q(robot: rc.Robot, rng: np.random.Generator) -> np.ndarray:
    limits = robot.joint_limits()
    return rng.uniform(limits[:, 0], limits[:, 1])


# -- the presets ---------------------------------------------------------------------------

PRESET_CASES = [
    ("planar_2r", "planar 2R", False, 2),
    ("planar_3r", "planar 3R", True, 2),
    ("scara", "SCARA", True, 2),
    ("paper", "3R elbow", False, 4),
    ("articulated", "3R elbow", False, 4),
    ("puma560", "spherical-wrist 6R", True, 8),
    ("ur5", "UR", True, None),  # UR: 8 only where every branch reaches (see below)
]


@pytest.mark.parametrize(("name", "family", "pose", "count"), PRESET_CASES)
def test_presets_round_trip(name, family, pose, count):
    robot = rc.preset(name)
    assert recognize(robot) == family
    rng = np.random.default_rng(RNG_SEED)
    for _ in range(25):
        sols = _check(robot, _random_q(robot, rng), pose, count)
        assert sols.family == family


def test_ur5_has_eight_solutions_inside_its_workspace():
    ur5 = rc.preset("ur5")
    configurations = [
        [0.1, -1.2, 1.3, 0.4, 0.5, 0.6],
        [2.0, -1.8, 1.0, -0.5, -1.2, 2.5],
        [-1.0, -1.0, 1.6, 1.0, 2.0, -0.3],
    ]
    for q in configurations:
        sols = _check(ur5, np.array(q), True, 8)
        words = {tuple(label.split(", ")) for label in sols.labels}
        expected = {
            (s, e, w)
            for s in ("shoulder left", "shoulder right")
            for e in ("elbow up", "elbow down")
            for w in ("wrist flip", "wrist no flip")
        }
        assert words == expected


def test_puma_labels_are_the_eight_arm_configurations():
    puma = rc.preset("puma560")
    # Corke's nominal pose qn: a right arm, elbow above the shoulder-wrist line, q5 > 0.
    qn = np.array([0, PI / 4, PI, 0, PI / 4, 0])
    sols = _check(puma, qn, True, 8)
    mine = min(range(8), key=lambda i: _gap(sols.q[i], qn, np.ones(6, bool)))
    assert sols.labels[mine] == "shoulder right, elbow up, wrist no flip"
    for row, label in zip(sols.q, sols.labels, strict=True):
        frames = puma.frame_poses(row)
        # In the arm's plane (across axis 2 = frame 1's z): the shoulder at the origin, the
        # elbow on axis 3 (frame 2's origin), the wrist centre (frame 4's origin).
        across = np.cross(frames[0, :3, 2], [0, 0, 1.0])
        elbow, wrist = frames[1, :3, 3], frames[3, :3, 3]
        (he, hw), (ze, zw) = (elbow @ across, wrist @ across), (elbow[2], wrist[2])
        turn = hw * ze - zw * he  # > 0: the elbow counterclockwise from the wrist
        assert ("elbow up" in label) == (turn * np.sign(hw) > 0)
        assert ("no flip" in label) == (row[4] > 0)


# -- random members of each family ---------------------------------------------------------


def _random_planar(rng, joints: str, convention: str) -> rc.Robot:
    rows = []
    for letter in joints:
        theta, length = rng.uniform(-PI, PI), rng.uniform(0.3, 2.0)
        if letter == "R":
            rows.append((theta, rng.uniform(-0.5, 0.5), length, 0.0, "R"))
        else:  # a slide along the axes (its twist π points it down, as in Spong's SCARA)
            rows.append((0.0, 0.2, 0.0, PI if rng.random() < 0.5 else 0.0, "P"))
    return rc.Robot.from_dh(rows, convention, end_effector=(rng.uniform(0.2, 1), 0, 0.1))


@pytest.mark.parametrize(
    ("joints", "family", "pose", "count"),
    [
        ("RR", "planar 2R", False, 2),
        ("RRR", "planar 3R", True, 2),
        ("RRPR", "SCARA", True, 2),
        ("RPRR", "SCARA", True, 2),
        ("RRP", "SCARA", False, 2),
    ],
)
@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_random_planar_and_scara(joints, family, pose, count, convention):
    rng = np.random.default_rng(RNG_SEED + len(joints))
    for _ in range(6):
        robot = _random_planar(rng, joints, convention)
        assert recognize(robot) == family
        for _ in range(4):
            _check(robot, _random_q(robot, rng), pose, count)


def _random_puma(rng, shoulder: float = 0.0) -> rc.Robot:
    lengths = rng.uniform(0.05, 0.6, size=6)
    twist = PI / 2 * rng.choice([-1, 1])
    rows = [
        (rng.uniform(-PI, PI), lengths[0], shoulder, twist, "R"),
        (rng.uniform(-PI, PI), 0.0, lengths[1], 0.0, "R"),
        (rng.uniform(-PI, PI), lengths[2], lengths[3], -PI / 2, "R"),
        (rng.uniform(-PI, PI), lengths[4], 0.0, PI / 2, "R"),
        (rng.uniform(-PI, PI), 0.0, 0.0, -PI / 2, "R"),
        (rng.uniform(-PI, PI), lengths[5], 0.0, 0.0, "R"),
    ]
    return rc.Robot.from_dh(rows, end_effector=(0.0, 0.05, 0.1))


def _random_ur(rng) -> rc.Robot:
    d1, a2, a3, d4, d5, d6 = rng.uniform(0.05, 0.6, size=6) * rng.choice([-1, 1], size=6)
    alphas = (PI / 2, 0.0, 0.0, PI / 2, -PI / 2, 0.0)
    lengths = [(d1, 0.0), (0.0, a2), (0.0, a3), (d4, 0.0), (d5, 0.0), (d6, 0.0)]
    rows = [
        (rng.uniform(-PI, PI), d, a, alpha, "R")
        for (d, a), alpha in zip(lengths, alphas, strict=True)
    ]
    return rc.Robot.from_dh(rows)


def test_random_spherical_wrist_arms_have_eight_solutions():
    rng = np.random.default_rng(RNG_SEED)
    for k in range(6):
        robot = _random_puma(rng)
        if k % 2:
            robot = rc.convert_dh(robot, "modified")
        assert recognize(robot) == "spherical-wrist 6R"
        for _ in range(4):
            _check(robot, rng.uniform(-PI, PI, 6), True, 8)


def test_random_arms_with_a_shoulder_offset_and_ur_arms():
    rng = np.random.default_rng(RNG_SEED + 1)
    for _ in range(5):
        kuka = _random_puma(rng, shoulder=rng.uniform(0.05, 0.3))
        ur = _random_ur(rng)
        assert (recognize(kuka), recognize(ur)) == ("spherical-wrist 6R", "UR")
        for _ in range(4):
            _check(kuka, rng.uniform(-PI, PI, 6), True)
            _check(ur, rng.uniform(-PI, PI, 6), True)


def test_random_elbow_arms_with_offsets():
    rng = np.random.default_rng(RNG_SEED + 2)
    for _ in range(6):
        a1, d2, a2, a3 = rng.uniform(0.1, 1.0, size=4)
        rows = [(0.0, 0.5, a1, PI / 2, "R"), (0.3, d2, a2, 0.0, "R"), (-0.2, 0.0, a3, 0.0, "R")]
        robot = rc.Robot.from_dh(rows, end_effector=(0.1, 0.2, 0.0))
        assert recognize(robot) == "3R elbow"
        for _ in range(4):
            sols = _check(robot, rng.uniform(-PI, PI, 3), False)
            assert len(sols) in (2, 4)


# -- robots built from modules -------------------------------------------------------------


def test_module_robots_are_recognized_and_solved():
    m = rc.Module
    rng = np.random.default_rng(RNG_SEED + 3)
    planar = rc.Robot([m("Rz"), m("Rz", a=(40, 0, 0))], end_effector=(30, 0, 5))
    wrist_arm = rc.Robot(
        [
            m("Rz"),
            m("Ry", a=(0, 0, 20)),
            m("Ry", a=(30, 0, 0)),
            m("Rx", a=(25, 0, 0)),
            m("Ry"),
            m("Rx"),
        ],
        end_effector=(5, 0, 2),
    )
    ur_like = rc.Robot(
        [
            m("Rz"),
            m("Ry", a=(0, 0, 9)),
            m("Ry", a=(-42, 0, 0)),
            m("Ry", a=(-39, 0, 0)),
            m("Rz", a=(0, -11, 0)),
            m("Ry", a=(0, 0, -9)),
        ],
        end_effector=(0, -8, 0),
    )
    for robot, family, pose, count in (
        (planar, "planar 2R", False, 2),
        (wrist_arm, "spherical-wrist 6R", True, 8),
        (ur_like, "UR", True, None),
    ):
        assert recognize(robot) == family
        for _ in range(8):
            _check(robot, rng.uniform(-PI, PI, robot.n), pose, count)


def test_dh_rows_written_as_modules_with_held_constants():
    puma = rc.preset("puma560")
    modules = [
        module
        for i, link in enumerate(puma.modules)
        for module in rc.dh_to_modules(link.with_name(f"J{i + 1}"))
    ]
    robot = rc.Robot(modules)
    held = [i for i, module in enumerate(modules) if "(constant)" in (module.name or "")]
    assert recognize(robot) == "spherical-wrist 6R"  # "(constant)" modules are held
    q = robot.q.copy()
    q[[i for i in range(robot.n) if i not in held]] = [0.3, 0.2, -0.4, 0.5, 0.6, 0.7]
    sols = _check(robot, q, True, 8)
    assert np.all(sols.q[:, held] == robot.q[held])  # the constants stay where they are
    # Renamed, the held twists count as joints, unless passed as constant=.
    renamed = rc.Robot([m.with_name(None) if i in held else m for i, m in enumerate(modules)])
    assert recognize(renamed) is None
    assert recognize(renamed, constant=held) == "spherical-wrist 6R"
    _check(renamed, q, True, 8, constant=held)


# -- hand-derived answers ------------------------------------------------------------------


def test_planar_2r_unit_links_target_1_1():
    # l1 = l2 = 1 to (1, 1): law of cosines, cos q2 = (2 − 1 − 1) / 2 = 0, so q2 = ±π/2;
    # q2 = +π/2 has q1 = 0 (elbow at (1, 0), below the line: "elbow down"), q2 = −π/2
    # has q1 = π/2 (elbow at (0, 1), above it: "elbow up").
    sols = ik_all(rc.preset("planar_2r", l1=1, l2=1), [1, 1, 0])
    assert sols.family == "planar 2R" and sols.reason == ""
    np.testing.assert_allclose(sols.q, [[0, PI / 2], [PI / 2, -PI / 2]], atol=1e-12)
    assert sols.labels == ("elbow down", "elbow up")
    assert sols.within_limits.tolist() == [True, True]


def test_planar_3r_with_an_angle():
    # Wrist point = (1, 2) − 1·(cos φ, sin φ) = (1, 1) for φ = π/2: the 2R answer above,
    # and q3 = φ − q1 − q2.
    arm = rc.preset("planar_3r", l1=1, l2=1, l3=1)
    sols = ik_all(arm, [1, 2, 0], angle=PI / 2)
    np.testing.assert_allclose(sols.q, [[0, PI / 2, 0], [PI / 2, -PI / 2, PI / 2]], atol=1e-12)
    assert sols.labels == ("elbow down", "elbow up")


def test_scara_point_leaves_the_tool_turn_at_its_current_value():
    scara = rc.preset("scara").with_q([0, 0, 0, 0.7])
    sols = ik_all(scara, [30, 40, 25])  # the docstring's point: q = (π/2, −π/2, 5, q4)
    assert len(sols) == 2 and "a point leaves q4 free" in sols.reason
    np.testing.assert_allclose(sols.q[:, 3], 0.7)
    np.testing.assert_allclose(sols.q[1], [PI / 2, -PI / 2, 5, 0.7], atol=1e-12)
    assert sols.labels == ("elbow right", "elbow left")


# -- unreachable targets and degenerate ones -----------------------------------------------


def test_unreachable_targets_say_how_far():
    arm = rc.preset("planar_2r")  # 40 + 30: reaches 70, no closer than 10
    far = ik_all(arm, [74.2 * math.cos(1.0), 74.2 * math.sin(1.0), 0])
    assert len(far) == 0 and far.q.shape == (0, 2)
    assert far.reason.startswith("the target is 4.2 beyond the reach")
    assert "too close" in ik_all(arm, [5, 0, 0]).reason
    assert ik_all(arm, [5, 0, 0]).reason.startswith("the target is 5 too close")
    assert ik_all(arm, [50, 0, 3]).reason.startswith("the target is 3 off the plane")
    # The paper's arm: the shoulder is at (0, 0, 20), the arm 30 + 40 long.
    assert (
        "30 beyond the reach: it is 100 from axis 2"
        in ik_all(rc.preset("paper"), [0, 0, 120]).reason
    )


def test_puma_unreachable_wrist_centre():
    puma = rc.preset("puma560")
    pose = np.eye(4)
    pose[:3, 3] = (1.5, 0.0, 0.0)  # no tool: the wrist centre is the target point
    d3, a2, a3, d4 = 0.15005, 0.4318, 0.0203, 0.4318
    across = math.sqrt(1.5**2 - d3**2)  # from axis 2, in the arm's plane
    beyond = across - (a2 + math.hypot(a3, d4))
    sols = ik_all(puma, pose)
    assert len(sols) == 0
    assert sols.reason.startswith(f"the wrist centre is {beyond:.6g} beyond the reach")
    pose[:3, 3] = (0.0, 0.0, 0.3)  # on axis 1: inside the shoulder offset d3
    inside = ik_all(puma, pose)
    assert len(inside) == 0 and "closer than the shoulder offset 0.15005" in inside.reason


def test_elbow_straight_and_target_on_the_first_axis():
    straight = ik_all(rc.preset("planar_2r"), [70, 0, 0])
    assert straight.labels == ("elbow straight",)
    np.testing.assert_allclose(straight.q, [[0, 0]], atol=1e-12)
    folded = ik_all(rc.preset("planar_2r", l1=1, l2=1).with_q([0.4, 0]), [0, 0, 0])
    np.testing.assert_allclose(folded.q, [[0.4, PI]], atol=1e-12)
    assert "q1 is free" in folded.reason


def test_wrist_singularity_keeps_q4_and_the_sum():
    puma = rc.preset("puma560").with_q([0, 0, 0, 0.7, 0, 0])
    q = np.array([0.3, 0.4, -0.5, 0.2, 0.0, 0.9])  # q5 = 0: axes 4 and 6 in line
    sols = ik_all(puma, puma.end_effector_pose(q))
    singular = [i for i, label in enumerate(sols.labels) if "wrist singular" in label]
    assert singular and "wrist singularity" in sols.reason
    np.testing.assert_allclose(sols.q[singular, 3], 0.7)
    mine = min(singular, key=lambda i: _gap(sols.q[i, :3], q[:3], np.ones(3, bool)))
    assert _gap(sols.q[mine, :3], q[:3], np.ones(3, bool)) < 1e-9
    # At the PUMA's q5 = 0 axes 4 and 6 point the same way: only q4 + q6 counts.
    assert abs(math.remainder(sols.q[mine, 3] + sols.q[mine, 5] - (0.2 + 0.9), 2 * PI)) < 1e-9
    reached = puma.end_effector_pose(sols.q)
    assert np.abs(reached - puma.end_effector_pose(q)).max() < 1e-9


def test_ur_wrist_singularity_keeps_q6():
    ur5 = rc.preset("ur5").with_q([0, 0, 0, 0, 0, -0.4])
    q = np.array([0.5, -1.2, 1.4, 0.3, 0.0, 0.8])
    sols = ik_all(ur5, ur5.end_effector_pose(q))
    singular = [i for i, label in enumerate(sols.labels) if "wrist singular" in label]
    assert singular and "q6 is shown at its current value" in sols.reason
    np.testing.assert_allclose(sols.q[singular, 5], -0.4)
    assert np.abs(ur5.end_effector_pose(sols.q) - ur5.end_effector_pose(q)).max() < 1e-9


def test_within_limits_counts_whole_turns():
    puma = rc.preset("puma560")  # q2 may go from −45° to 225°
    q = np.array([0.2, 3.5, -0.6, 0.3, 0.5, 0.1])  # q2 = 200°: wrapped, −160°
    sols = _check(puma, q, True, 8)
    mine = min(range(8), key=lambda i: _gap(sols.q[i], q, np.ones(6, bool)))
    assert sols.q[mine, 1] == pytest.approx(3.5 - 2 * PI)
    assert sols.within_limits[mine]
    tight = rc.preset("planar_2r", l1=1, l2=1).with_limits("q1", (-0.5, 0.5))
    assert ik_all(tight, [1, 1, 0]).within_limits.tolist() == [True, False]


def test_a_pose_for_a_position_arm_keeps_the_matching_branch():
    arm = rc.preset("planar_2r")
    sols = ik_all(arm, arm.end_effector_pose([0.3, 0.5]))
    np.testing.assert_allclose(sols.q, [[0.3, 0.5]], atol=1e-12)
    assert "1 more branch reaches the point with another orientation" in sols.reason
    turned = arm.end_effector_pose([0.3, 0.5])
    turned[:3, :3] = turned[:3, :3] @ np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1.0]])
    assert "cannot also give the target's orientation" in ik_all(arm, turned).reason


# -- recognition ---------------------------------------------------------------------------


def test_recognition_reads_geometry_not_names():
    assert recognize(rc.preset("planar_2r").with_name("PUMA 560")) == "planar 2R"
    assert recognize(rc.preset("puma560").with_name("planar 2R")) == "spherical-wrist 6R"
    for name in ("cartesian", "cylindrical", "spherical", "stanford"):
        assert recognize(rc.preset(name)) is None


def test_perturbed_puma_is_refused_with_the_measured_offset():
    rows = [link.row() for link in rc.preset("puma560").modules]
    theta, d, _, alpha, joint = rows[3]
    rows[3] = (theta, d, 0.0125, alpha, joint)  # a wrist offset a4 = 12.5 mm
    robot = rc.Robot.from_dh(rows, name="PUMA with an offset wrist")
    assert recognize(robot) is None
    with pytest.raises(InvalidInputError) as caught:
        ik_all(robot, np.eye(4))
    message = str(caught.value)
    assert caught.value.field == "robot"
    assert "the last three axes do not intersect (axes 4 and 5: closest approach 0.0125)" in message
    assert "not a spherical-wrist arm" in message and "rc.ik(robot, target)" in message


def test_bad_targets_are_refused():
    with pytest.raises(InvalidInputError, match="a point leaves the orientation open") as caught:
        ik_all(rc.preset("puma560"), [0.3, 0.1, 0.2])
    assert caught.value.field == "target"
    with pytest.raises(InvalidInputError, match="leaves the end-effector's angle open"):
        ik_all(rc.preset("planar_3r"), [30, 10, 0])
    with pytest.raises(InvalidInputError) as caught:
        ik_all(rc.preset("planar_2r"), [30, 10, 0], angle=1.0)
    assert caught.value.field == "angle"
    with pytest.raises(InvalidInputError, match="not a rotation"):
        ik_all(rc.preset("puma560"), np.diag([2.0, 1, 1, 1]))
    with pytest.raises(InvalidInputError, match="expected shape"):
        ik_all(rc.preset("planar_2r"), [1, 2])


# -- an independent check: a Newton search finds nothing the closed form missed ------------


def _newton_solutions(robot: rc.Robot, target: np.ndarray, starts: int, seed: int) -> list:
    rng = np.random.default_rng(seed)
    found = []
    for _ in range(starts):
        q = rng.uniform(-PI, PI, robot.n)
        for _ in range(60):
            pose = robot.end_effector_pose(q)
            turn = target[:3, :3] @ pose[:3, :3].T
            error = np.concatenate(
                [target[:3, 3] - pose[:3, 3], 0.5 * (turn - turn.T)[[2, 0, 1], [1, 2, 0]]]
            )
            if np.abs(error).max() < 1e-12:
                break
            q = q + np.linalg.lstsq(robot.jacobian(q), error, rcond=None)[0]
        if np.abs(robot.end_effector_pose(q) - target).max() < 1e-9:
            found.append(q)
    return found


@pytest.mark.parametrize(
    ("name", "q", "count"),
    [
        ("puma560", [0.3, 0.2, -0.4, 0.5, 0.6, 0.7], 8),
        ("ur5", [0.1, -1.2, 1.3, 0.4, 0.5, 0.6], 8),
        ("ur5", [1.1, -2.6, 0.3, -1.4, 2.3, -2.6], 4),  # the other wrist branch is too far
    ],
)
def test_no_solution_is_missed(name, q, count):
    robot = rc.preset(name)
    target = robot.end_effector_pose(q)
    sols = ik_all(robot, target)
    assert len(sols) == count
    newton = _newton_solutions(robot, target, starts=40, seed=RNG_SEED)
    assert len(newton) >= 10  # the search did find solutions
    revolute = np.ones(6, bool)
    for x in newton:
        assert min(_gap(row, x, revolute) for row in sols.q) < 1e-6
    hit = {min(range(len(sols)), key=lambda i: _gap(sols.q[i], x, revolute)) for x in newton}
    assert len(hit) >= min(len(sols), 3)  # and not just one branch


def test_solutions_print_as_a_table():
    text = str(ik_all(rc.preset("planar_2r", l1=1, l2=1), [1, 1, 0]))
    assert text.splitlines()[0] == "planar 2R: 2 solutions"
    assert "elbow up: q = [ 1.570796, -1.570796]" in text
