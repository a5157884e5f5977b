"""Lessons 5–8 of the course: the exercises' checks are real.

For every exercise a typical wrong answer must fail its check cell with a hint that names
the mistake, and the solutions must pass. The hints of matrix exercises come from
robotconf's checker (``rc.assert_matrix``); the other answers go through the same parser
and numeric judge with a tolerance of 0.1 % (0.001 near 0): a velocity
(``rc.assert_vector``), finite-difference spikes (``rc.assert_value``), the singular
joint values (``rc.assert_set``, modulo 2π) and an elbow angle (``rc.assert_angle``), each
with the exercise's own hint. So rounded numbers (3.1416 for π, 1.5708 for π/2), text
answers (``"[pi, 0]"``) and answers a whole turn away pass. Each notebook runs once with
every answer replaced by a wrong one and once as the solutions; lessons 7 and 8 run twice
more with rounded and text answers and once more with other typical mistakes.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest

import robotconf as rc

from .course_support import COURSE, exercise_cells, run_with_answers, solutions_path

# lesson folder -> {answer variable: (code of the wrong answer cell, words the hint must contain)}
WRONG_ANSWERS: dict[str, dict[str, tuple[str, str]]] = {
    "05_denavit_hartenberg": {
        # the modified (Craig) product when the standard one was asked
        "answer_1": (
            'answer_1 = "[[cos(q1), -sin(q1), 0, 1], [0, 0, -1, -0.5],'
            ' [sin(q1), cos(q1), 0, 0], [0, 0, 0, 1]]"',
            "You used the modified DH convention",
        ),
        # the standard product when the modified one was asked
        "answer_2": (
            'answer_2 = "[[cos(q1), 0, sin(q1), cos(q1)], [sin(q1), 0, -cos(q1), sin(q1)],'
            ' [0, 1, 0, 0.5], [0, 0, 0, 1]]"',
            "You used the standard DH convention",
        ),
        # 30 (degrees) fed to cos and sin as if it were radians
        "answer_3": (
            "answer_3 = np.round(rc.dh_matrix(30, 0, 2, 0), 4)",
            "angles in degrees fed to sin and cos",
        ),
        # the offset d = 20 of the first row forgotten
        "answer_4": (
            'answer_4 = "[[cos(q1), 0, -sin(q1), 0], [sin(q1), 0, cos(q1), 0],'
            ' [0, -1, 0, 0], [0, 0, 0, 1]]"',
            "The link offset d of A1",
        ),
        # the same mistake in a position: the column height d1 = 20 missing
        "answer_5": ("answer_5 = [0, 30, 40]", "The link offset d of A1"),
    },
    "06_real_arms": {
        # calculator in radian mode with 30 typed in
        "answer_1": (
            "answer_1 = np.round(rc.dh_matrix(30, 0, 0.4318, 0), 4)",
            "angles in degrees fed to sin and cos",
        ),
        # the flange offset d6 forgotten
        "answer_2": (
            "answer_2 = [-0.81725, -0.10915, -0.005491]",
            "The link offset d of A6",
        ),
        # A2·A1 instead of A1·A2
        "answer_3": (
            'answer_3 = rc.expected_matrix(puma, "A2").matrix'
            ' * rc.expected_matrix(puma, "A1").matrix',
            "You multiplied in the wrong order (A2·A1 instead of A1·A2)",
        ),
        # the UR5's row multiplied in Craig's order
        "answer_4": (
            "answer_4 = rc.expected_matrix(\n"
            '    rc.Robot.from_dh([(0, 0.089159, 0, np.pi / 2, "R")], convention="modified"),\n'
            '    "A1",\n'
            ").matrix",
            "You used the modified DH convention",
        ),
    },
    "07_velocity_acceleration": {
        # one row per joint instead of one column per joint
        "answer_1": (
            'answer_1 = "[[-sin(q1) - sin(q1 + q2), cos(q1) + cos(q1 + q2)],'
            ' [-sin(q1 + q2), cos(q1 + q2)]]"',
            "The whole matrix is transposed",
        ),
        # y × (p − o3) taken as +40 along z
        "answer_2": ("answer_2 = [0, 35, 40]", "The sign of z is wrong."),
        # the columns of joints 2 and 3 exchanged
        "answer_3": (
            "answer_3 = [[0, 40, 40], [30, 0, 0], [0, 0, -30]]",
            "Columns 2 and 3 are swapped",
        ),
        # the slope of the ramp instead of the finite difference across the jump
        "answer_4": ("answer_4 = 1.0", "central difference (q[k+1] - q[k-1]) / (2 dt)"),
        # the central difference when Simulink's backward one was asked
        "answer_5": ("answer_5 = -99.0", "backward difference (q[k] - q[k-1]) / dt"),
    },
    "08_workspace_singularities": {
        # the Jacobian written with one row per joint
        "answer_1": ("answer_1 = [[0, 2], [0, 1]]", "The whole matrix is transposed"),
        # det J with the wrong sign
        "answer_2": ('answer_2 = "[[-2*sin(q2)]]"', "sign error"),
        # the singular angles in degrees
        "answer_3": ("answer_3 = [0, 180]", "180 looks like a solution in degrees"),
        # the arm folded back: an elbow singularity, the tip 10 mm off the z axis
        "answer_4": ("answer_4 = np.pi", "l2 cos q2 + l3 cos(q2 + q3) = 0"),
    },
}

# More typical mistakes on the exercises that are not matrices: each is named.
MORE_WRONG_ANSWERS: dict[str, dict[str, tuple[str, str]]] = {
    "07_velocity_acceleration": {
        # the velocity in m/s·1000: mm and m mixed up
        "answer_2": ("answer_2 = [0, 0.035, -0.04]", "1000 times too small"),
        # q[k-1] - q[k+1]: the difference the wrong way round
        "answer_4": ("answer_4 = 99", "has the wrong sign"),
        # the jump not divided by dt
        "answer_5": ("answer_5 = -1.99", "100 times too small"),
    },
    "08_workspace_singularities": {
        # only the stretched arm
        "answer_3": ("answer_3 = [0]", "1 is missing: the arm folded"),
        # arccos(-3/4) in degrees
        "answer_4": ("answer_4 = 138.59", "You gave degrees: write q3 in radians"),
    },
}

# Right answers as students type them: rounded, as text, in another order, a turn away.
# Lessons run once per variant.
APPROXIMATE_ANSWERS: dict[str, list[dict[str, str]]] = {
    "07_velocity_acceleration": [
        {
            "answer_2": 'answer_2 = "[0, 35, -40]"',
            "answer_4": 'answer_4 = "(0.01 - 1.99) / (2 * 0.01)"',
            "answer_5": "answer_5 = -199.1",  # within 0.1 % of -199
        },
        {
            "answer_2": "answer_2 = np.array([[0.0], [35.0], [-40.02]])",  # a column, rounded
            "answer_4": 'answer_4 = "-99"',
            "answer_5": 'answer_5 = "-1.99 / 0.01"',
        },
    ],
    "08_workspace_singularities": [
        {
            "answer_3": 'answer_3 = "[3.1416, 0]"',  # π rounded, larger first, as text
            "answer_4": "answer_4 = 2.4189",  # arccos(-3/4) rounded
        },
        {
            "answer_3": "answer_3 = [2 * np.pi, 3.1416]",  # 0 given as a full turn
            "answer_4": 'answer_4 = "2.4189 - 2*pi"',  # the same angle, a turn back
        },
    ],
}


def _lessons() -> list[str]:
    return sorted(WRONG_ANSWERS)


def _cases() -> list[tuple[str, str]]:
    return [(lesson, variable) for lesson in _lessons() for variable in WRONG_ANSWERS[lesson]]


def _exercises(lesson: str):
    return COURSE / lesson / "exercises.ipynb"


@functools.cache
def _wrong_run(lesson: str) -> dict[str, str]:
    answers = {variable: code for variable, (code, _) in WRONG_ANSWERS[lesson].items()}
    return run_with_answers(_exercises(lesson), answers)


@functools.cache
def _solutions_run(lesson: str) -> dict[str, str]:
    return run_with_answers(solutions_path(_exercises(lesson)))


@pytest.mark.parametrize("lesson", _lessons())
def test_every_exercise_has_a_wrong_answer_test(lesson):
    exercises = exercise_cells(_exercises(lesson))
    solutions = exercise_cells(solutions_path(_exercises(lesson)))
    assert 3 <= len(exercises) <= 5
    assert sorted(WRONG_ANSWERS[lesson]) == sorted(e.variable for e in exercises)
    for exercise, solution in zip(exercises, solutions, strict=True):
        assert exercise.check_source == solution.check_source, exercise.variable


@pytest.mark.parametrize("lesson", _lessons())
def test_solutions_pass_their_checks(lesson):
    errors = _solutions_run(lesson)
    assert errors and not any(errors.values()), errors


@pytest.mark.parametrize(
    ("lesson", "variant"),
    [(lesson, i) for lesson, variants in APPROXIMATE_ANSWERS.items() for i in range(len(variants))],
)
def test_rounded_and_text_answers_pass(lesson, variant):
    answers = APPROXIMATE_ANSWERS[lesson][variant]
    errors = run_with_answers(_exercises(lesson), answers)
    assert all(errors[variable] == "" for variable in answers), errors


@pytest.mark.parametrize("lesson", sorted(MORE_WRONG_ANSWERS))
def test_more_typical_mistakes_are_named(lesson):
    mistakes = MORE_WRONG_ANSWERS[lesson]
    errors = run_with_answers(_exercises(lesson), {v: code for v, (code, _) in mistakes.items()})
    for variable, (_, words) in mistakes.items():
        assert "AssertionError" in errors[variable], errors[variable]
        assert words in errors[variable], errors[variable]


@pytest.mark.parametrize(("lesson", "variable"), _cases())
def test_typical_wrong_answer_gets_a_hint_naming_the_mistake(lesson, variable):
    error = _wrong_run(lesson)[variable]
    _, words = WRONG_ANSWERS[lesson][variable]
    assert "AssertionError" in error, error
    assert words in error, error


# -- more mistakes on the same references, without a kernel ----------------------------


def _one_link(alpha: float, d: float = 0.5, a: float = 1.0) -> rc.Robot:
    """Lesson 5, exercise 1: the standard row (θ = q1, d, a, α)."""
    return rc.Robot.from_dh([(0, d, a, alpha, "R")], convention="standard")


def test_alpha_sign_error_is_reported_as_a_sign_error():
    expected = rc.expected_matrix(_one_link(np.pi / 2), "A1")
    wrong = rc.expected_matrix(_one_link(-np.pi / 2), "A1").matrix
    result = rc.check_matrix(wrong, expected)
    assert not result.ok
    assert "sign_error" in result.mistakes
    assert "wrong sign" in " ".join(result.hints)


def test_degrees_in_the_twist_are_recognised():
    expected = rc.expected_matrix(_one_link(np.pi / 2), "A1")
    wrong = rc.expected_matrix(_one_link(90.0), "A1").matrix
    result = rc.check_matrix(wrong, expected)
    assert result.mistakes == ["degrees_as_radians"], result.hints


def test_d_and_a_swapped_is_named():
    expected = rc.expected_matrix(_one_link(np.pi / 2, d=0.5, a=1.0), "A1")
    wrong = rc.expected_matrix(_one_link(np.pi / 2, d=1.0, a=0.5), "A1").matrix
    result = rc.check_matrix(wrong, expected)
    assert not result.ok
    assert "swapped_d_a" in result.mistakes, result.hints
