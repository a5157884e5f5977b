"""Lesson 11 (inverse kinematics): the solutions pass, blanks fail kindly, slips are named.

Each notebook run executes the whole exercises notebook once (``run_with_answers``), so
the cases are grouped: the solutions as committed, the blank exercises, two runs of
typical wrong answers, and one run of right answers written another way (the other
elbow, text, whole turns, rounded numbers).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import robotconf as rc
from robotconf.inverse_kinematics import ik, ik_all

from .course_support import COURSE, exercise_cells, run_with_answers, solutions_path

LESSON = COURSE / "11_inverse_kinematics"
EXERCISES = LESSON / "exercises.ipynb"
VARIABLES = [f"answer_{i}" for i in range(1, 8)]

# The exercise arm and target, solved by hand: r² = 7.25, cos q2 = 1/6.
L1, L2, TARGET = 2.0, 1.5, (-1.0, 2.5)
Q2 = math.acos(1 / 6)
BETA = math.atan2(L2 * math.sin(Q2), L1 + L2 * math.cos(Q2))
DOWN = (math.atan2(TARGET[1], TARGET[0]) - BETA, Q2)  # (1.3698, 1.4033)
UP = (math.atan2(TARGET[1], TARGET[0]) + BETA, -Q2)  # (2.5328, -1.4033)

# variable -> (code of the answer cell, words the failure must contain)
WRONG_A = {
    # atan(y/x) for a target with x < 0: q1 off by π
    "answer_1": (
        "answer_1 = [np.arctan(2.5 / -1.0) - np.arctan2(np.sqrt(35) / 4, 2.25), np.arccos(1 / 6)]",
        "q1 is off by half a turn",
    ),
    # the elbow-up solution forgotten
    "answer_2": (f"answer_2 = [[{DOWN[0]}, {DOWN[1]}]]", "elbow up is missing"),
    "answer_3": ("answer_3 = [l1 + l2, abs(l1 - l2)]", "The ends are swapped"),
    # e = p(q_k) − p*: the step goes the wrong way
    "answer_4": ("answer_4 = q_k - np.linalg.solve(J_k, e_k)", "the target minus the tip"),
    # the Newton step where the damped one is asked
    "answer_5": ("answer_5 = q_k + np.linalg.solve(J_k, e_k)", "Add λ = 0.5 to the diagonal"),
    # measured from the base origin: 109.66 − 70
    "answer_6": ("answer_6 = np.linalg.norm([60, 45, 80]) - 70", "Measure from the shoulder"),
    # the cause taken for the dependent joints
    "answer_7": ("answer_7 = [5]", "5 is not a solution"),
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
}

RIGHT_OTHERWISE = {
    "answer_1": f'answer_1 = "[{UP[0]:.4f}, {UP[1]:.4f}]"',
    "answer_2": (
        f'answer_2 = "[[{UP[0]:.4f}, {UP[1]:.4f}], [{DOWN[0]:.4f} + 2*pi, {DOWN[1]:.4f}]]"'
    ),
    "answer_3": 'answer_3 = "[0.5, 3.5]"',
    "answer_4": (
        "answer_4 = q_k + np.array([[J_k[1, 1], -J_k[0, 1]], [-J_k[1, 0], J_k[0, 0]]]) @ e_k"
        " / np.linalg.det(J_k)"
    ),
    "answer_5": 'answer_5 = "[1.2006, 1.5642]"',
    "answer_6": 'answer_6 = "26.05"',
    "answer_7": "answer_7 = [6, 4]",
}


def test_hand_numbers_agree_with_the_robot():
    arm = rc.preset("planar_2r", l1=L1, l2=L2)
    for q in (DOWN, UP):
        assert np.allclose(arm.end_effector(q)[:2], TARGET)
    assert np.allclose(ik_all(arm, [*TARGET, 0]).q, [DOWN, UP])
    assert ik_all(arm, [*TARGET, 0]).labels == ("elbow down", "elbow up")
    # Exercise 6: the shoulder (0, 0, 20) is the centre, l2 + l3 = 70 the radius.
    far = ik(rc.preset("paper"), [60, 45, 80])
    assert far.reason == "unreachable"
    assert far.distance_to_reach == pytest.approx(math.sqrt(60**2 + 45**2 + 60**2) - 70)
    # Exercise 5's rounded answer is the damped step.
    q_k = np.array([1.0, 1.0])
    J = rc.jacobian(arm, q_k)[:2]
    e = np.array(TARGET) - arm.end_effector(q_k)[:2]
    step = np.linalg.solve(J.T @ J + 0.5 * np.eye(2), J.T @ e)
    assert np.allclose(q_k + step, [1.2006, 1.5642], atol=1e-4)


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
