"""The numeric inverse-kinematics solver: solutions, honest reasons, vectorization, inputs.

Reference values are derived by hand in the comments (reach radii, the 2R closed form,
joint angles) or computed independently here (forward kinematics of the answer, a tiny
Newton iteration on the 2R formulas written out below).
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from robotconf import InvalidInputError, dh_to_modules, set_memory_budget
from robotconf.inverse_kinematics import IKResult, ik
from robotconf.inverse_kinematics.model._problem import Problem, make_problem
from robotconf.inverse_kinematics.model._reach import reach_shell
from robotconf.inverse_kinematics.model._rotation import rotation_vector_last
from robotconf.inverse_kinematics.model._targets import check_mask, check_targets
from robotconf.inverse_kinematics.numeric import _search as search_module
from robotconf.inverse_kinematics.numeric._ik import _verify
from robotconf.inverse_kinematics.numeric._lm import CONVERGED, STALLED, solve
from robotconf.inverse_kinematics.numeric._reasons import fit_into_limits
from robotconf.inverse_kinematics.numeric._search import Search, search
from robotconf.kinematics import (
    Module,
    Robot,
    characteristic_length,
    rotation_matrix,
    rotation_vector,
)
from robotconf.presets import preset

TOL = 1e-9  # the default relative position tolerance
ORIENTATION_TOL = 1e-9


def random_q(robot: Robot, count: int, seed: int) -> np.ndarray:
    limits = robot.joint_limits()
    rng = np.random.default_rng(seed)
    return limits[:, 0] + (limits[:, 1] - limits[:, 0]) * rng.random((count, robot.n))


def turn_angle(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Angle between rotations, from ‖A − B‖_F = 2√2·sin(θ/2) (accurate for tiny θ)."""
    gap = np.linalg.norm(a - b, axis=(-2, -1))
    return 2.0 * np.arcsin(np.minimum(gap / (2.0 * np.sqrt(2.0)), 1.0))


def check_solutions(robot: Robot, result: IKResult, target: np.ndarray, mode: str) -> None:
    """Every success's forward kinematics meets the target within the tolerances."""
    ok = np.asarray(result.success)
    q = np.asarray(result.q)[ok]
    size = characteristic_length(robot)
    if mode == "position":
        reached = robot.end_effector(q)
        gap = np.linalg.norm(reached - target[ok], axis=-1)
    else:
        pose = robot.end_effector_pose(q)
        gap = np.linalg.norm(pose[:, :3, 3] - target[ok][:, :3, 3], axis=-1)
        angle = turn_angle(pose[:, :3, :3], target[ok][:, :3, :3])
        assert np.all(angle <= ORIENTATION_TOL * 1.01)
        assert np.allclose(np.asarray(result.orientation_error)[ok], angle, atol=1e-12)
    assert np.all(gap <= TOL * size)
    assert np.allclose(np.asarray(result.position_error)[ok], gap, rtol=1e-6, atol=1e-15)
    limits = robot.joint_limits()
    moving = np.array([t in ("revolute", "prismatic") for t in robot.joint_types])
    inside = (q >= limits[:, 0] - 1e-12) & (q <= limits[:, 1] + 1e-12)
    assert np.all(inside[:, moving])


# -- solutions ----------------------------------------------------------------------------


@pytest.mark.parametrize(
    "name", ["planar_2r", "planar_3r", "scara", "puma560", "ur5", "paper", "stanford"]
)
@pytest.mark.parametrize("mode", ["position", "pose"])
def test_random_reachable_targets_are_met(name: str, mode: str) -> None:
    robot = preset(name)
    q = random_q(robot, 40, seed=11)
    target = robot.end_effector(q) if mode == "position" else robot.end_effector_pose(q)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # planar arms asked for a pose
        result = ik(robot, target, mode=mode)
    check_solutions(robot, result, target, mode)
    assert np.mean(result.success) >= 0.95
    assert all(r == "converged" for r, s in zip(result.reason, result.success, strict=True) if s)
    assert np.all(result.distance_to_reach[result.success] == 0.0)


@pytest.mark.parametrize("name", ["puma560", "ur5"])
def test_pose_success_rate_with_default_seeds(name: str) -> None:
    # Measured with the defaults (32 starts): 1000/1000 for both robots on four samples
    # of 1000 (8 starts gave the PUMA 991–998/1000: its joint ranges hide solutions).
    robot = preset(name)
    target = robot.end_effector_pose(random_q(robot, 200, seed=5))
    result = ik(robot, target, mode="pose")
    assert np.mean(result.success) >= 0.97
    check_solutions(robot, result, target, "pose")


def test_prismatic_robots_and_held_modules() -> None:
    for name in ("cartesian", "cylindrical", "spherical"):
        robot = preset(name)
        target = robot.end_effector(random_q(robot, 20, seed=2))
        result = ik(robot, target)
        assert result.success.all()
        check_solutions(robot, result, target, "position")
    # A null module and a fixed offset: their coordinates stay the robot's own.
    paper = preset("paper")
    modules = [paper.modules[0], Module("none", q=0.7), *paper.modules[1:], Module("fixed")]
    robot = Robot(modules, end_effector=(40, 0, 0)).with_module(4, Module("fixed", a=(0, 0, 5)))
    q = np.array([0.4, 0.7, -0.3, 0.8, 0.0])
    result = ik(robot, robot.end_effector(q), q0=np.zeros(5))
    assert result.reason == "converged"
    assert result.q[1] == 0.7 and result.q[4] == 0.0
    assert np.linalg.norm(robot.end_effector(result.q) - robot.end_effector(q)) <= TOL * 95


def test_position_and_tool_axis_mask_with_a_held_joint() -> None:
    # PUMA 560 whose last joint is held (a "(constant)" module): 5 joints can still put the
    # point and the tool's z axis anywhere reachable, but not the turn about that axis.
    puma = preset("puma560")
    robot = puma.with_module(5, puma.modules[5].with_name("flange (constant)"))
    q_true = np.array([0.3, 0.6, -0.9, 0.4, 0.7, 0.0])
    target = robot.end_effector_pose(q_true)
    target[:3, :3] = target[:3, :3] @ rotation_matrix(np.array([[0.0, 0.0, 0.7]]))[0]
    result = ik(robot, target, mode="pose", mask=[1, 1, 1, 1, 1, 0], q0=np.zeros(6))
    assert result.reason == "converged"
    assert result.q[5] == 0.0
    pose = robot.end_effector_pose(result.q)
    z_gap = np.arccos(np.clip(pose[:3, 2] @ target[:3, 2], -1.0, 1.0))
    assert z_gap <= 1e-7  # arccos is only good to ~1e-8 near 0
    assert np.linalg.norm(pose[:3, 3] - target[:3, 3]) <= TOL * characteristic_length(robot)
    # The turn about z is left open: here it stays 0.7 rad off (hand: the held joint 6).
    assert turn_angle(pose[:3, :3], target[:3, :3]) == pytest.approx(0.7, abs=1e-7)
    # The full pose asks for 6 directions of 5 joints: a warning, then the least-squares
    # compromise between the two errors, and "unreachable".
    with pytest.warns(UserWarning, match="only 5 at a time"):
        full = ik(robot, target, mode="pose", q0=result.q, seeds=1)
    assert full.reason == "unreachable"
    assert 0.0 < full.orientation_error < 0.7 and full.position_error > 1e-3


# -- the 2R arm against its closed form and a hand-written Newton ---------------------------


def two_r(l1: float = 2.0, l2: float = 1.0) -> Robot:
    return preset("planar_2r", l1=l1, l2=l2)


def closed_form(x: float, y: float, l1: float, l2: float) -> list[np.ndarray]:
    """Both 2R solutions: cos q2 = (r² − l1² − l2²)/(2 l1 l2), q1 = atan2(y, x) − β."""
    c2 = (x * x + y * y - l1 * l1 - l2 * l2) / (2 * l1 * l2)
    out = []
    for q2 in (np.arccos(c2), -np.arccos(c2)):
        q1 = np.arctan2(y, x) - np.arctan2(l2 * np.sin(q2), l1 + l2 * np.cos(q2))
        out.append(np.array([q1, q2]))
    return out


def newton_2r(x: float, y: float, q: np.ndarray, l1: float, l2: float) -> np.ndarray:
    """Plain Newton on the 2R formulas written out (no robotconf involved)."""
    q = q.astype(float).copy()
    for _ in range(50):
        c1, s1 = np.cos(q[0]), np.sin(q[0])
        c12, s12 = np.cos(q[0] + q[1]), np.sin(q[0] + q[1])
        f = np.array([l1 * c1 + l2 * c12 - x, l1 * s1 + l2 * s12 - y])
        jac = np.array([[-l1 * s1 - l2 * s12, -l2 * s12], [l1 * c1 + l2 * c12, l2 * c12]])
        q -= np.linalg.solve(jac, f)
    return q


def wrap(angle: np.ndarray) -> np.ndarray:
    return (angle + np.pi) % (2 * np.pi) - np.pi


def test_2r_matches_closed_form_and_newton() -> None:
    robot = two_r()
    rng = np.random.default_rng(4)
    radius = rng.uniform(1.2, 2.8, 20)
    heading = rng.uniform(-np.pi, np.pi, 20)
    target = np.stack([radius * np.cos(heading), radius * np.sin(heading), np.zeros(20)], 1)
    start = np.array([0.3, 1.2])
    result = ik(robot, target, q0=start)
    assert result.success.all()
    for (x, y, _), q in zip(target, result.q, strict=True):
        gaps = [np.abs(wrap(q - s)).max() for s in closed_form(x, y, 2.0, 1.0)]
        assert min(gaps) <= 1e-8
        newton = newton_2r(x, y, q + 0.05, 2.0, 1.0)  # Newton from near the answer
        assert np.abs(wrap(newton - q)).max() <= 1e-8


# -- unreachable, singular, joint limit, iteration limit --------------------------------------


def test_paper_arm_beyond_its_reach() -> None:
    # Reach sphere about the shoulder (0, 0, 20) on joint 1's axis: l2 + l3 = 30 + 40 = 70.
    robot = preset("paper")
    direction = np.array([0.6, 0.0, 0.8])
    target = np.array([0.0, 0.0, 20.0]) + 100 * direction
    result = ik(robot, target)
    assert result.reason == "unreachable" and not result.success
    assert result.distance_to_reach == pytest.approx(100 - 70, abs=1e-12)
    assert "30 beyond the reach" in result.message and "radius 70" in result.message
    # The arm ends stretched towards the target: 30 short of it, on the same ray.
    assert result.position_error == pytest.approx(30.0, abs=1e-6)
    reached = robot.end_effector(result.q)
    assert np.allclose(reached, [0.0, 0.0, 20.0] + 70 * direction, atol=1e-5)


def test_2r_target_in_the_hole() -> None:
    # l1 = 2, l2 = 1: no point closer than l1 − l2 = 1 to the base; 0.5 is 0.5 inside.
    result = ik(two_r(), [0.5, 0.0, 0.0])
    assert result.reason == "unreachable"
    assert result.distance_to_reach == pytest.approx(0.5, abs=1e-12)
    assert "inside the hole" in result.message


def test_target_off_the_plane_of_a_planar_arm() -> None:
    # (2.5, 0, 1) is inside the reach sphere (|p| = 2.69 < 3), but a planar arm stays in
    # z = 0: the closest point it reaches is (2.5, 0, 0), exactly 1 away — proved by the
    # plane its parallel axes keep it in.
    result = ik(two_r(), [2.5, 0.0, 1.0])
    assert result.reason == "unreachable"
    assert result.distance_to_reach == pytest.approx(1.0, abs=1e-12)
    assert np.allclose(two_r().end_effector(result.q), [2.5, 0.0, 0.0], atol=1e-9)
    assert result.position_error == pytest.approx(1.0, abs=1e-12)
    assert "the target is 1 out of reach" in result.message
    assert "in the plane at height 0 along (0, 0, 1), 1 to 3 from joint 1's axis" in result.message
    assert "(1 off that plane)" in result.message


def test_errors_of_rows_left_out_are_nan() -> None:
    robot = preset("puma560")
    target = robot.end_effector_pose([0.1, 0.2, -0.3, 0.4, 0.5, 0.6])
    turn_only = ik(robot, target, mode="pose", mask=[0, 0, 0, 1, 1, 1])
    assert turn_only.success and np.isnan(turn_only.position_error)
    assert turn_only.orientation_error <= ORIENTATION_TOL
    point_only = ik(robot, target, mode="pose", mask=[True] * 3 + [False] * 3)
    assert point_only.success and np.isnan(point_only.orientation_error)


def test_reach_shell_holds_every_preset() -> None:
    for name in ("paper", "cartesian", "cylindrical", "scara", "stanford", "puma560", "ur5"):
        robot = preset(name)
        moving = np.array([t in ("revolute", "prismatic") for t in robot.joint_types])
        shell = reach_shell(robot, moving, robot.q)
        reached = robot.end_effector(random_q(robot, 5000, 1))
        distance = np.linalg.norm(reached - shell.center, axis=1)
        assert distance.max() <= shell.outer + 1e-9 and distance.min() >= shell.inner - 1e-9
    # The 2R shell by hand: 1 ≤ r ≤ 3 about the base.
    shell = reach_shell(two_r(), np.ones(2, bool), np.zeros(2))
    assert (shell.inner, shell.outer) == (1.0, 3.0)


def test_a_start_on_a_singular_saddle_is_left_along_its_negative_curvature() -> None:
    # Straight out (q = 0) the EE is at (3, 0, 0); (2.5, 0, 0) is along the arm, and both
    # Jacobian columns point along y there: no least-squares step moves along x. Folding
    # the elbow brings the end closer, a direction of negative curvature of the error,
    # which the second-order descent follows: one start suffices.
    robot = two_r()
    found = ik(robot, [2.5, 0.0, 0.0], q0=[0.0, 0.0], seeds=1)
    assert found.reason == "converged"
    # 2.5² = 2² + 1² + 2·2·1·cos q2: cos q2 = 1.25 / 4.
    assert abs(found.q[1]) == pytest.approx(np.arccos(1.25 / 4), abs=1e-9)


def test_singular_configurations_name_their_joints() -> None:
    # The words behind the reason "singular" (what remains when the descent runs out of
    # steps at a singular configuration that is not a closest one).
    from robotconf.inverse_kinematics.numeric._reasons import dependent_joints, singular_message

    stretched = two_r()
    problem = make_problem(
        stretched,
        check_targets([2.5, 0.0, 0.0], "position"),
        np.ones(6) * [1, 1, 1, 0, 0, 0],
        TOL,
        1.0,
    )
    q = np.zeros((1, 2))
    jacobian = problem.expand(problem.jacobian_at(np.arange(1), q))[0]
    joints, aligned = dependent_joints(problem, jacobian, stretched.jacobian(q[0]))
    assert joints == [0, 1] and not aligned
    assert "joints 1 and 2 are dependent" in singular_message(joints, aligned)
    puma = preset("puma560")
    q = np.array([[0.3, 0.5, -0.8, 0.4, 0.0, 0.2]])  # q5 = 0: axes 4 and 6 in line
    target = check_targets(puma.end_effector_pose(q[0]), "pose")
    problem = make_problem(puma, target, np.ones(6), TOL, ORIENTATION_TOL)
    jacobian = problem.expand(problem.jacobian_at(np.arange(1), q))[0]
    joints, aligned = dependent_joints(problem, jacobian, puma.jacobian(q[0]))
    assert joints == [3, 5] and aligned
    assert "joints 4 and 6 are aligned" in singular_message(joints, aligned)


def test_puma_wrist_singularity_is_left_by_the_descent() -> None:
    # q5 = 0: joints 4 and 6 turn about the same line. The target is moved along the
    # direction the Jacobian cannot produce (its left null vector, in the solver's units),
    # so the error is orthogonal to every joint motion: least squares cannot move, the
    # second-order descent bends the wrist and reaches it from this one start.
    robot = preset("puma560")
    q = np.array([0.3, 0.5, -0.8, 0.4, 0.0, 0.2])
    size = characteristic_length(robot)
    left, values, _ = np.linalg.svd(robot.jacobian(q) * np.array([1 / size] * 3 + [1] * 3)[:, None])
    assert values[-1] < 1e-12 * values[0]
    u = left[:, -1]
    pose = robot.end_effector_pose(q)
    target = pose.copy()
    target[:3, 3] += 1e-3 * size * u[:3]
    target[:3, :3] = rotation_matrix(1e-3 * u[np.newaxis, 3:])[0] @ pose[:3, :3]
    result = ik(robot, target, q0=q, mode="pose", seeds=1)
    assert result.reason == "converged"
    check_solutions(robot, result, target, "pose")


def test_joint_limit_names_the_joint() -> None:
    # Both 2R solutions of this target have |q2| = 1 rad (57.3°): outside (−0.1, 0.1).
    robot = two_r().with_limits(1, (-0.1, 0.1))
    target = two_r().end_effector([0.3, 1.0])
    result = ik(robot, target)
    assert result.reason == "joint limit" and not result.success
    assert "joint 2 (q2) at" in result.message and "57.3°" in result.message
    assert "limit 5.73°" in result.message
    assert -0.1 <= result.q[1] <= 0.1
    free = ik(robot, target, respect_limits=False)
    assert free.reason == "converged" and abs(abs(free.q[1]) - 1.0) <= 1e-8


def test_prismatic_stroke_proves_a_target_out_of_reach() -> None:
    # Cylindrical robot: height = 20 + q2, stroke 0…40, so its end effector stays between
    # heights 20 and 60; a target at height 65 is 5 out of reach, proved (its turn about
    # z keeps every height).
    robot = preset("cylindrical")
    result = ik(robot, [20.0, 0.0, 65.0])
    assert result.reason == "unreachable" and result.distance_to_reach == 5.0
    assert "between heights 20 and 60 along (0, 0, 1)" in result.message
    assert "(5 off those heights)" in result.message
    assert result.position_error == pytest.approx(5.0, abs=1e-9)


def test_orientation_out_of_reach_of_a_planar_arm() -> None:
    # A planar 2R pose turned 0.3 rad about the target's own x axis: the arm can match the
    # point and its heading, never the tilt, and the warning says the pose over-constrains.
    robot = two_r()
    q = np.array([0.4, 0.9])
    target = robot.end_effector_pose(q)
    target[:3, :3] = target[:3, :3] @ rotation_matrix(np.array([[0.3, 0.0, 0.0]]))[0]
    with pytest.warns(UserWarning, match="mask"):
        result = ik(robot, target, mode="pose", q0=q, seeds=1)
    assert result.reason == "unreachable"
    assert result.orientation_error == pytest.approx(0.3, abs=1e-12)
    assert result.position_error <= 1e-12
    assert "closest configuration found" in result.message


def test_no_warning_when_unmoved_rows_are_constrained() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ik(preset("planar_2r"), [30.0, 20.0, 0.0])  # z is never moved: not over-constrained
        ik(preset("scara"), preset("scara").end_effector_pose([0.1, 0.2, 5, 0.3]), mode="pose")


def test_tolerance_below_rounding_and_few_iterations() -> None:
    robot = preset("puma560")
    target = robot.end_effector_pose([0.1, 0.2, -0.3, 0.4, 0.5, 0.6])
    tiny = ik(robot, target, mode="pose", tol=1e-300, orientation_tol=1e-300, seeds=1)
    assert tiny.reason == "iteration limit" and "float64 rounding" in tiny.message
    short = ik(robot, target, mode="pose", max_iterations=2, seeds=1)
    assert short.reason == "iteration limit" and "within 2 iterations" in short.message
    # Iterations add up over runs: 2 steps within the ranges, then 2 more from the same
    # start without them (the PUMA has clipped joints; the UR5's all wrap, so it has one
    # run), then 2 of the second-order descent from the closest of them.
    assert short.iterations == 6
    ur5 = preset("ur5")
    ur5_target = ur5.end_effector_pose([0.1, 0.2, -0.3, 0.4, 0.5, 0.6])
    assert ik(ur5, ur5_target, mode="pose", max_iterations=2, seeds=1).iterations == 2 + 2


# -- vectorization ----------------------------------------------------------------------------


def test_vectorized_equals_per_target() -> None:
    robot = preset("puma560")
    target = robot.end_effector_pose(random_q(robot, 50, seed=3))
    target[:4, :3, 3] *= 3.0  # out of reach
    batch = ik(robot, target, mode="pose")
    assert batch.q.shape == (50, 6) and len(batch) == 50
    assert batch.reason.count("unreachable") == 4
    for i in range(50):
        one = ik(robot, target[i], mode="pose")
        assert np.array_equal(one.q, batch.q[i])
        assert (one.reason, one.iterations, one.message) == (
            batch.reason[i],
            batch.iterations[i],
            batch.message[i],
        )
        assert one.success == batch[i].success


def test_per_target_starts() -> None:
    robot = two_r()
    q = np.array([[0.2, 0.5], [1.0, -0.7]])
    result = ik(robot, robot.end_effector(q), q0=q + 0.01)
    assert np.allclose(result.q, q, atol=1e-8)
    assert repr(result) == "IKResult(2 targets: 2 converged)"
    assert repr(result[0]).startswith("IKResult('converged', q=[")


def test_vectorized_equals_per_target_in_every_frame() -> None:
    # The other paths through the solver: turn rows in the target frame (a mask that
    # leaves one out, or weighs them unequally), points only, a prismatic joint.
    cases = [("puma560", "pose", [1, 1, 1, 1, 1, 0]), ("puma560", "pose", [1, 1, 1, 2, 1, 1])]
    cases += [("stanford", "pose", None), ("cylindrical", "position", None)]
    for name, mode, mask in cases:
        robot = preset(name)
        q = random_q(robot, 12, seed=9)
        target = robot.end_effector(q) if mode == "position" else robot.end_effector_pose(q)
        batch = ik(robot, target, q0=q[::-1], mode=mode, mask=mask)
        for i in range(12):
            one = ik(robot, target[i], q0=q[::-1][i], mode=mode, mask=mask)
            assert np.array_equal(one.q, batch.q[i]) and one.message == batch.message[i]


# -- the solver's own chain and its waves of starts ---------------------------------------------


def pose_problem(robot: Robot, target: np.ndarray, mask: list | None = None) -> Problem:
    """The solver's problem for pose targets (T, 4, 4), default tolerances."""
    return make_problem(robot, check_targets(target, "pose"), check_mask(mask, "pose"), TOL, TOL)


def puma_as_modules() -> Robot:
    """The PUMA 560 as the paper's modules: its twists become held "(constant)" modules."""
    puma = preset("puma560")
    modules = []
    for i, link in enumerate(puma.modules):
        for module in dh_to_modules(link):
            name = module.name or ""
            held = name.endswith("(constant)")
            modules.append(
                module.with_name(name.replace("(constant)", f"{i} (constant)")) if held else module
            )
    return Robot(modules, end_effector=puma.end_effector_point)


def odd_robots() -> dict[str, Robot]:
    paper = preset("paper")
    modules = [paper.modules[0], Module("none", q=0.7), *paper.modules[1:], Module("fixed")]
    with_gaps = Robot(modules, end_effector=(40, 0, 0)).with_module(4, Module("fixed", a=(0, 0, 5)))
    return {
        "held twists": puma_as_modules(),
        "inactive tail": preset("puma560").with_active(4),
        "none and fixed": with_gaps,
    }


@pytest.mark.parametrize("name", ["puma560", "stanford", "scara", "cylindrical", *odd_robots()])
@pytest.mark.parametrize("mask", [None, [1, 1, 1, 1, 1, 0], [0.5, 1, 1, 1, 2, 1]])
def test_error_and_jacobian_agree_with_the_robot(name: str, mask: list | None) -> None:
    # The folded chain against the robot's own forward kinematics and Jacobian.
    robot = odd_robots().get(name) or preset(name)
    q, goal_q = random_q(robot, 20, seed=1), random_q(robot, 20, seed=2)
    goals = robot.end_effector_pose(goal_q)
    problem = pose_problem(robot, goals, mask)
    error, jacobian = problem.evaluate(
        problem.positions, problem.rotations_of(np.arange(20)), q[:, problem.joints]
    )
    moving = [j for j, t in enumerate(robot.joint_types) if t in ("revolute", "prismatic")]
    moving = [j for j in moving if j < robot.active and "(constant)" not in robot.module_names[j]]
    assert list(problem.joints) == moving
    q = np.where(problem.moving, q, robot.q)  # the solver holds the other coordinates
    pose, full = robot.end_effector_pose(q), robot.jacobian(q)
    target = goals[:, :3, :3]
    turn = rotation_vector(target @ pose[:, :3, :3].transpose(0, 2, 1))
    if not problem.base_frame:  # turns about the target's own axes
        turn = np.einsum("bji,bj->bi", target, turn)
        full[:, 3:] = np.einsum("bji,bjk->bik", target, full[:, 3:])
    expected = np.concatenate([goals[:, :3, 3] - pose[:, :3, 3], turn], axis=1)
    assert problem.base_frame == (mask is None)
    assert np.allclose(error, expected[:, problem.rows], rtol=0, atol=1e-12 * problem.length)
    scaled = full[:, problem.rows][:, :, moving] * problem.scale
    assert jacobian is not None
    assert np.allclose(jacobian, scaled, rtol=0, atol=1e-12)


def test_the_solvers_rotation_vector_agrees_with_the_kinematics_one() -> None:
    # Two implementations of one map (the solver's in its own memory layout), up to 180°.
    vectors = np.random.default_rng(3).normal(size=(200, 3))
    vectors *= (np.pi * np.random.default_rng(4).random(200) / np.linalg.norm(vectors, axis=1))[
        :, np.newaxis
    ]
    matrices = rotation_matrix(vectors)
    solver = rotation_vector_last(matrices.transpose(1, 2, 0)).T
    np.testing.assert_allclose(solver, rotation_vector(matrices), rtol=0, atol=1e-12)
    np.testing.assert_allclose(solver, vectors, rtol=0, atol=1e-9)


def one_after_another(
    problem: Problem, first: np.ndarray, draws: np.ndarray, proved: np.ndarray, iterations: int
) -> Search:
    """Reference: each target's runs in the documented order, one run at a time: q0, then
    the random starts nearest first (ranked by the pose each leaves, computed here)."""
    state = Search.begin(problem, first, True)
    for i in range(len(first)):
        one = np.array([i])
        pose = problem.robot.end_effector_pose(problem.project(draws, False))
        energy = problem.energy(problem.errors_from_pose(np.full(len(draws), i), pose))
        starts = [first[i]] + [draws[k] for k in np.argsort(energy, kind="stable")]
        runs = [(k, False) for k in range(len(starts))] + [(k, True) for k in range(len(starts))]
        for k, free in runs:
            if state.status[i] == CONVERGED or proved[i]:
                break  # a target proved out of reach is left to the closest-point descent
            run = solve(problem, one, starts[k][np.newaxis], iterations, not free)
            (state.read_free if free else state.read_limited)(one, run)
    return state


def test_waves_read_the_runs_in_their_documented_order(monkeypatch: pytest.MonkeyPatch) -> None:
    # A PUMA whose shoulder may only turn 0.8 rad: many targets need a second start, a
    # run without the ranges, or end past a joint limit; two are far out of reach.
    robot = preset("puma560").with_limits(1, (0.2, 1.0))
    target = robot.end_effector_pose(random_q(preset("puma560"), 16, seed=4))
    target[:2, :3, 3] *= 3.0
    problem = pose_problem(robot, target)
    first = np.zeros((16, 6))
    draws = random_q(robot, 3, seed=8)
    proved = np.zeros(16, bool)
    proved[:2] = True
    reference = one_after_another(problem, first, draws, proved, 60)
    for wave in (128, 2):
        monkeypatch.setattr(search_module, "WAVE_RUNS", wave)
        found = search(problem, first, draws, proved, 60, True)
        for field in ("q", "error", "status", "iterations", "starts", "outside", "outside_q"):
            assert np.array_equal(getattr(found, field), getattr(reference, field)), field
    assert 0 < np.sum(found.status == CONVERGED) < 14 and found.outside.any()
    assert np.all(found.starts[:2] == 0) and np.all(found.starts[2:] >= 1)


def test_runs_of_one_target_race_without_changing_each_other() -> None:
    robot = preset("ur5")
    target = robot.end_effector_pose(random_q(robot, 1, seed=6))
    problem = pose_problem(robot, target)
    starts = random_q(robot, 6, seed=7)
    alone = [solve(problem, np.array([0]), start[np.newaxis], 100, True) for start in starts]
    raced = solve(problem, np.zeros(6, int), starts, 100, True, order=np.arange(6))
    first = next(k for k, run in enumerate(alone) if run.status[0] == CONVERGED)
    for k in range(first + 1):  # up to the first that converges, each run is as alone
        assert np.array_equal(raced.q[k], alone[k].q[0])
        assert raced.iterations[k] == alone[k].iterations[0]
    assert all(raced.iterations[k] <= alone[first].iterations[0] for k in range(first + 1, 6))


def test_answers_are_checked_with_the_robots_own_kinematics() -> None:
    robot = preset("puma560")
    q = np.array([[0.3, 0.6, -0.9, 0.4, 0.7, 0.2]])
    target = robot.end_effector_pose(q)
    problem = pose_problem(robot, target)
    for nudge, status in ((0.0, CONVERGED), (1e-7, STALLED)):
        found = Search.begin(problem, q + nudge, True)
        found.status[:] = CONVERGED
        _verify(problem, found)
        assert found.status[0] == status
        reached = robot.end_effector_pose(q + nudge)[:, :3, 3]
        assert np.allclose(found.error[:, :3], target[:, :3, 3] - reached, rtol=0, atol=1e-15)


def test_whole_turn_twins_fit_the_ranges() -> None:
    # PUMA joint 1 turns ±160° (±2.79 rad): 4 rad fits as 4 − 2π = −2.28. Joint 2 runs
    # −45°…225°: −1 rad (−57°) is 12° below, its twin 302° is 77° above, so −1 stays
    # and is named as outside.
    problem = pose_problem(preset("puma560"), np.eye(4)[np.newaxis])
    fitted, outside = fit_into_limits(problem, np.array([[4.0, -1.0, 0.0, 0.0, 0.0, 0.0]]))
    assert np.allclose(fitted[0, :2], [4.0 - 2 * np.pi, -1.0], rtol=0, atol=1e-15)
    assert outside[0].tolist() == [False, True, False, False, False, False]


# -- rotation vectors ---------------------------------------------------------------------------


def test_rotation_vector_over_the_whole_range() -> None:
    rng = np.random.default_rng(8)
    axis = rng.normal(size=(400, 3))
    axis /= np.linalg.norm(axis, axis=1, keepdims=True)
    angle = np.concatenate(
        [rng.uniform(0, np.pi, 392), [0, 1e-12, 1e-6, 1.5, 1.6, 3.0, 3.14, 3.1415926]]
    )
    vector = axis * angle[:, None]
    back = rotation_vector(rotation_matrix(vector))
    assert np.allclose(np.linalg.norm(back, axis=1), angle, atol=2e-8)
    small = angle < 3.14
    assert np.allclose(back[small], vector[small], atol=1e-12)


# -- bad input --------------------------------------------------------------------------------


def _pose() -> np.ndarray:
    return preset("puma560").end_effector_pose([0.1, 0.2, -0.3, 0.4, 0.5, 0.6])


def _bad_cases() -> list[tuple[dict, str]]:
    pose = _pose()
    skewed = pose.copy()
    skewed[0, 0] += 1e-3
    mirrored = pose.copy()
    mirrored[:3, 0] *= -1
    last_row = pose.copy()
    last_row[3, 3] = 2.0
    return [
        ({"target": [np.nan, 0, 0]}, "target"),
        ({"target": [[1, 0, 0], [np.inf, 0, 0]]}, "target[1]"),
        ({"target": [1, 2]}, "target"),
        ({"target": np.zeros((2, 3, 3))}, "target"),
        ({"target": skewed, "mode": "pose"}, "target"),
        ({"target": mirrored, "mode": "pose"}, "target"),
        ({"target": last_row}, "target"),
        ({"target": [0.5, 0, 0.5], "mode": "pose"}, "target"),
        ({"mode": "orientation"}, "mode"),
        ({"mode": 3}, "mode"),
        ({"q0": [0, 0]}, "q0"),
        ({"q0": [0, 0, np.nan, 0, 0, 0]}, "q0"),
        ({"q0": np.zeros((3, 6))}, "q0"),
        ({"tol": 0.0}, "tol"),
        ({"tol": -1e-9}, "tol"),
        ({"tol": np.nan}, "tol"),
        ({"orientation_tol": 0}, "orientation_tol"),
        ({"max_iterations": 0}, "max_iterations"),
        ({"max_iterations": 10_001}, "max_iterations"),
        ({"max_iterations": 20.0}, "max_iterations"),
        ({"seeds": 0}, "seeds"),
        ({"seeds": 65}, "seeds"),
        ({"seed": -1}, "seed"),
        ({"respect_limits": "yes"}, "respect_limits"),
        ({"mask": [0, 0, 0, 0, 0, 0], "mode": "pose", "target": pose}, "mask"),
        ({"mask": [1, 1, 1], "mode": "pose", "target": pose}, "mask"),
        ({"mask": [1, 1, 1, -1, 0, 0], "mode": "pose", "target": pose}, "mask"),
        ({"mask": [1, 1, 1, 1, 0, 0]}, "mask"),
        ({"robot": "puma560"}, "robot"),
    ]


@pytest.mark.parametrize(("changes", "field"), _bad_cases())
def test_bad_input_names_the_field(changes: dict, field: str) -> None:
    arguments = {"robot": preset("puma560"), "target": [0.5, 0.0, 0.5], **changes}
    with pytest.raises(InvalidInputError) as error:
        ik(**arguments)
    assert error.value.field == field


def test_memory_budget_is_checked_first() -> None:
    set_memory_budget(1)
    try:
        with pytest.raises(InvalidInputError) as error:
            ik(preset("puma560"), np.zeros((20_000, 3)))  # ~117 MB estimated
        assert error.value.field == "target"
    finally:
        set_memory_budget(None)
