"""Lesson 11 (inverse kinematics): the solutions pass, blanks fail kindly, slips are named.

Each notebook run executes the whole exercises notebook once (``run_with_answers``), so
the cases are grouped: the solutions as committed, the blank exercises, two runs of
typical wrong answers, and one run of right answers written another way (the other
elbow, text, π in a formula, rounded numbers).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import robotconf as rc
from robotconf.inverse_kinematics import ik, ik_all
from robotconf.teaching.exercises import registered

from .course_support import COURSE, exercise_cells, run_with_answers, solutions_path

LESSON = COURSE / "11_inverse_kinematics"
EXERCISES = LESSON / "exercises.ipynb"
VARIABLES = [f"answer_{i}" for i in range(1, 8)]

# The demo student's arm and target (rc.Assignment), solved by hand with the law of cosines.
TASK = rc.Assignment("11_inverse_kinematics", "demo")
L1, L2 = TASK["l1"], TASK["l2"]
TARGET = tuple(float(x) for x in TASK["target"][:2])
Q2 = math.acos((TARGET[0] ** 2 + TARGET[1] ** 2 - L1**2 - L2**2) / (2 * L1 * L2))
BETA = math.atan2(L2 * math.sin(Q2), L1 + L2 * math.cos(Q2))


def _wrapped(angle: float) -> float:
    """The angle in the joint range (−π, π] the exercises ask for."""
    return math.atan2(math.sin(angle), math.cos(angle))


DOWN = (_wrapped(math.atan2(TARGET[1], TARGET[0]) - BETA), Q2)
UP = (_wrapped(math.atan2(TARGET[1], TARGET[0]) + BETA), -Q2)
LAMBDA = TASK["lam"]

# variable -> (code of the answer cell, words the failure must contain)
WRONG_A = {
    # atan(y/x) for a target with x < 0: q1 off by π
    "answer_1": (
        f"answer_1 = [np.arctan({TARGET[1]} / {TARGET[0]}) - {BETA}, {Q2}]",
        "q1 is off by half a turn",
    ),
    # the elbow-up solution forgotten
    "answer_2": (f"answer_2 = [[{DOWN[0]}, {DOWN[1]}]]", "elbow up is missing"),
    "answer_3": ("answer_3 = [l1 + l2, abs(l1 - l2)]", "The ends are swapped"),
    # e = p(q_k) − p*: the step goes the wrong way
    "answer_4": ("answer_4 = q_k - np.linalg.solve(J_k, e_k)", "the target minus the tip"),
    # the Newton step where the damped one is asked
    "answer_5": ("answer_5 = q_k + np.linalg.solve(J_k, e_k)", "undamped Newton step"),
    # measured from the base origin
    "answer_6": ("answer_6 = np.linalg.norm(far) - 70", "Measure from the shoulder"),
    # the cause taken for the dependent joints
    "answer_7": ("answer_7 = [5]", "q5 = 0 is the cause"),
}
WRONG_B = {
    # degrees
    "answer_1": (
        f"answer_1 = [{math.degrees(DOWN[0])}, {math.degrees(DOWN[1])}]",
        "in degrees: give the joint angles in radians",
    ),
    # q1 of the elbow-down solution with the elbow-up q2 in the second element
    "answer_2": (
        f"answer_2 = [[{DOWN[0]}, {DOWN[1]}], [{DOWN[0]}, {-DOWN[1]}]]",
        "come from different elbow solutions",
    ),
    # the inner radius taken as 0
    "answer_3": ("answer_3 = [0, l1 + l2]", "The inner radius is not 0"),
    # Jᵀe for Newton's solve
    "answer_4": ("answer_4 = q_k + J_k.T @ e_k", "the gradient step"),
    # λ² on the diagonal
    "answer_5": (
        "answer_5 = q_k + np.linalg.solve(J_k.T @ J_k + lam**2 * np.eye(2), J_k.T @ e_k)",
        "not λ²",
    ),
    # joints counted from 0
    "answer_7": ("answer_7 = [3, 5]", "Number the joints from 1"),
}

RIGHT_OTHERWISE = {
    "answer_1": f'answer_1 = "[{UP[0]:.4f}, {UP[1]:.4f}]"',
    "answer_2": (
        f'answer_2 = "[[{UP[0]:.4f}, {UP[1]:.4f}], [{DOWN[0] - math.pi:.4f} + pi, {DOWN[1]:.4f}]]"'
    ),
    "answer_3": f'answer_3 = "[{abs(L1 - L2):.3g}, {L1 + L2:.3g}]"',
    "answer_4": (
        "answer_4 = q_k + np.array([[J_k[1, 1], -J_k[0, 1]], [-J_k[1, 0], J_k[0, 0]]]) @ e_k"
        " / np.linalg.det(J_k)"
    ),
    "answer_5": (
        "step = np.linalg.solve(J_k.T @ J_k + lam * np.eye(2), J_k.T @ e_k)\n"
        'answer_5 = "[" + ", ".join(f"{x:.3g}" for x in q_k + step) + "]"'
    ),
    "answer_6": 'answer_6 = f"{np.linalg.norm(far - [0, 0, 20]) - 70:.3g}"',
    "answer_7": "answer_7 = [6, 4]",
}


def test_hand_numbers_agree_with_the_robot():
    arm = rc.preset("planar_2r", l1=L1, l2=L2)
    assert TARGET[0] < 0  # the quadrant atan(y/x) loses
    for q in (DOWN, UP):
        assert np.allclose(arm.end_effector(q)[:2], TARGET)
    wrapped = np.angle(np.exp(1j * np.array([DOWN, UP])))  # the solver gives (−π, π]
    assert np.allclose(np.sort(ik_all(arm, [*TARGET, 0]).q, axis=0), np.sort(wrapped, axis=0))
    # Exercise 6: the shoulder (0, 0, 20) is the centre, l2 + l3 = 70 the radius.
    point = TASK["far"]
    far = ik(rc.preset("paper"), point)
    assert far.reason == "unreachable"
    assert far.distance_to_reach == pytest.approx(np.linalg.norm(point - [0, 0, 20]) - 70)
    # Exercise 5: the damped step by the normal equations.
    q_k = TASK["q_k"]
    J = rc.jacobian(arm, q_k)[:2]
    e = np.array(TARGET) - arm.end_effector(q_k)[:2]
    assert np.allclose(J, TASK["J_k"]) and np.allclose(e, TASK["e_k"])
    step = np.linalg.solve(J.T @ J + LAMBDA * np.eye(2), J.T @ e)
    assert TASK.check(5, q_k + step).ok
    # Exercise 7: with q5 = 0, joints 4 and 6 turn about one line.
    assert TASK["q_w"][4] == 0 and TASK.answer(7) == [4, 6]


def test_another_student_gets_another_arm_or_target():
    other = rc.Assignment("11_inverse_kinematics", "s1234567")
    mine = (L1, L2, tuple(TASK["target"]))
    assert (other["l1"], other["l2"], tuple(other["target"])) != mine


def test_the_exercises_pair_up():
    assert [e.variable for e in exercise_cells(EXERCISES)] == VARIABLES


def test_solutions_pass():
    errors = run_with_answers(solutions_path(EXERCISES))
    assert errors == dict.fromkeys(VARIABLES, ""), errors


def test_blank_exercises_fail_kindly():
    errors = run_with_answers(EXERCISES)
    for variable in VARIABLES:
        number = variable.split("_")[1]
        assert f"Exercise {number} is not answered yet" in errors[variable], errors[variable]
        assert "InvalidInputError" not in errors[variable]


@pytest.mark.parametrize("wrong", [WRONG_A, WRONG_B], ids=["run_a", "run_b"])
def test_typical_wrong_answers_get_the_right_hint(wrong):
    errors = run_with_answers(EXERCISES, {v: code for v, (code, _) in wrong.items()})
    for variable, (_, words) in wrong.items():
        assert errors[variable].startswith("AssertionError"), errors[variable]
        assert words in errors[variable], errors[variable]
    if wrong is WRONG_A:  # no hint quotes a solution (run B's hints quote its own answers)
        shown = errors["answer_1"] + errors["answer_2"]
        assert not [value for value in (*DOWN, *UP) if f"{value:.4g}" in shown], shown


def test_right_answers_written_another_way_pass():
    errors = run_with_answers(EXERCISES, RIGHT_OTHERWISE)
    assert errors == dict.fromkeys(VARIABLES, ""), errors


def test_an_angle_a_whole_turn_outside_the_joint_range_is_refused():
    """Arm l1 = l2 = 1, target (−1, 0): by hand cos q2 = −1/2, the solutions are
    (2π/3, 2π/3) and (−2π/3, −2π/3); 4π/3 for q1 is the second pose a whole turn away,
    outside the range (−π, π] the exercises ask for."""
    one, both = registered("11_inverse_kinematics")[:2]
    numbers = {"arm": rc.preset("planar_2r", l1=1, l2=1), "target": np.array([-1.0, 0, 0])}
    third = 2 * math.pi / 3
    assert one.check([third, third], numbers).ok
    assert one.check(f"[{-third:.4f}, {-third:.4f}]", numbers).ok
    wrapped = one.check([2 * third, -third], numbers)
    assert not wrapped.ok and wrapped.diagnosis == "outside_limits"
    assert "wrap q1 into (−π, π]" in wrapped.hints[0] and "-2.094" in wrapped.hints[0]
    assert not one.accepts([2 * third, -third], numbers)  # the fast rule agrees
    pair = both.check([[third, third], [2 * third, -third]], numbers)
    assert not pair.ok and pair.diagnosis == "outside_limits"
    assert both.check([[third, third], [-third, -third]], numbers).ok
    # π itself, rounded to 3.142 by hand, is inside: the edge keeps the rounding rule
    edge = {"arm": rc.preset("planar_2r", l1=1, l2=1), "target": np.array([-1.0, 1, 0])}
    assert one.check([3.142, -math.pi / 2], edge).ok
