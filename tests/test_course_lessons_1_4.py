"""Lessons 1–4 of the course: the exercises' checks are real.

For every exercise a typical wrong answer must fail its check cell with a hint that names
the mistake (the hint comes from robotconf's checker), and the solutions must pass; right
answers typed as text or rounded (1.5708 for π/2, 0.8776 for cos 0.5) pass too. Each
notebook runs once per set of answers, with all its answers replaced.
"""

from __future__ import annotations

import functools

import pytest

from .course_support import COURSE, exercise_cells, run_with_answers, solutions_path

# lesson folder -> {answer variable: (code of the wrong answer cell, words the hint must contain)}
WRONG_ANSWERS: dict[str, dict[str, tuple[str, str]]] = {
    "01_homogeneous_transforms": {
        # the new axes written as rows instead of columns
        "answer_1": (
            "answer_1 = [[0, 0, 1, 10], [1, 0, 0, 20], [0, 1, 0, 30], [0, 0, 0, 1]]",
            "write the axes as columns, not as rows",
        ),
        # only the rotation part
        "answer_2": (
            "answer_2 = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]",
            "looks like the rotation part only",
        ),
        # degrees fed to cos and sin
        "answer_3": (
            "answer_3 = [30 + 40 * np.cos(90), 40 * np.sin(90), 20]",
            "angles in degrees fed to sin and cos",
        ),
        # Rot·Trans instead of Trans·Rot
        "answer_4": (
            'answer_4 = "[[cos(q1), -sin(q1), 0, 30*cos(q1)], [sin(q1), cos(q1), 0, 30*sin(q1)],'
            ' [0, 0, 1, 20], [0, 0, 0, 1]]"',
            "the offset is applied after the rotation",
        ),
    },
    "02_elementary_transforms": {
        # the sines of Rx with swapped signs
        "answer_1": (
            'answer_1 = "[[1, 0, 0, 0], [0, cos(q1), sin(q1), 0], [0, -sin(q1), cos(q1), 20],'
            ' [0, 0, 0, 1]]"',
            "a positive rotation about x has",
        ),
        # the pattern of Rx/Rz copied to Ry: -sin above the diagonal
        "answer_2": (
            'answer_2 = "[[cos(q1), 0, -sin(q1), 30], [0, 1, 0, 0], [sin(q1), 0, cos(q1), 0],'
            ' [0, 0, 0, 1]]"',
            "a positive rotation about y has +sin in entry (1,3)",
        ),
        # the offset a forgotten: only q in the last column
        "answer_3": (
            'answer_3 = "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, q1], [0, 0, 0, 1]]"',
            "The offset of A1 (module M1, Tz with a = (0, 0, 20)) is missing",
        ),
        # calculator in degree mode
        "answer_4": (
            "c, s = np.cos(np.radians(0.5)), np.sin(np.radians(0.5))\n"
            "answer_4 = [[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
            "calculator in degree mode",
        ),
    },
    "03_composing_a_chain": {
        # Rot·Trans instead of Trans·Rot
        "answer_1": (
            'answer_1 = "[[cos(q2), 0, sin(q2), l1*sin(q2)], [0, 1, 0, 0],'
            ' [-sin(q2), 0, cos(q2), l1*cos(q2)], [0, 0, 0, 1]]"',
            "the offset is applied after the rotation",
        ),
        # A2·A1 instead of A1·A2
        "answer_2": (
            'answer_2 = "[[cos(q2)*cos(q1), -cos(q2)*sin(q1), sin(q2), 0],'
            " [sin(q1), cos(q1), 0, 0], [-sin(q2)*cos(q1), sin(q2)*sin(q1), cos(q2), l1],"
            ' [0, 0, 0, 1]]"',
            "You multiplied in the wrong order (A2·A1 instead of A1·A2)",
        ),
        # the origin of frame 3 instead of the end-effector point
        "answer_3": (
            "answer_3 = [30, 0, 20]",
            "The end-effector point P = (40, 0, 0) is missing",
        ),
        # module 3 turned the wrong way (the sine sign of Ry)
        "answer_4": (
            "answer_4 = [0, 30, -20]",
            "The sine terms of A3 (module M3, Ry with a = (30, 0, 0)) have the wrong sign",
        ),
        # the pedestal module forgotten
        "answer_5": (
            "answer_5 = [70, 0, 20]",
            "The offset of A1 (module M1, fixed with a = (0, 0, 50)) is missing",
        ),
    },
    "04_module_method_classic_arms": {
        # the translation written as the bottom row (row-vector convention)
        "answer_1": (
            'answer_1 = "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [q1, q2, q3 + 50, 1]]"',
            "The whole matrix is transposed",
        ),
        # A3·A2·A1: the rotation applied last
        "answer_2": (
            'answer_2 = "[q3 + 10*cos(q1), 10*sin(q1), q2 + 20]"',
            "You multiplied in the wrong order",
        ),
        # elevation with the sign of an x or z rotation
        "answer_3": (
            'answer_3 = "[(q3 + 10)*cos(q2)*cos(q1), (q3 + 10)*cos(q2)*sin(q1),'
            ' 30 + (q3 + 10)*sin(q2)]"',
            "The sine terms of A2 (module M2, Ry with a = (0, 0, 30)) have the wrong sign",
        ),
        # degrees fed to cos and sin
        "answer_4": (
            "answer_4 = [30 * np.cos(90) + 20 * np.cos(0), 30 * np.sin(90) + 20 * np.sin(0), 25]",
            "angles in degrees fed to sin and cos",
        ),
    },
}


# Right answers as students type them: text with numbers and formulas, rounded numbers.
APPROXIMATE_ANSWERS: dict[str, dict[str, str]] = {
    "01_homogeneous_transforms": {
        "answer_2": 'answer_2 = "[[cos(pi/2), -sin(pi/2), 0, 30], [sin(pi/2), cos(pi/2), 0, 0],'
        ' [0, 0, 1, 20], [0, 0, 0, 1]]"',
        # π/2 typed as 1.5708: 40·cos(1.5708) = -1.5e-4, within 0.001 of 0
        "answer_3": 'answer_3 = "[30 + 40*cos(1.5708), 40*sin(1.5708), 20]"',
    },
    "02_elementary_transforms": {
        # cos 0.5 = 0.87758, sin 0.5 = 0.47943, to 4 decimals
        "answer_4": 'answer_4 = "[[0.8776, -0.4794, 0, 0], [0.4794, 0.8776, 0, 0],'
        ' [0, 0, 1, 0], [0, 0, 0, 1]]"',
    },
    "03_composing_a_chain": {
        "answer_3": 'answer_3 = "[30 + 40, 0, 20]"',
        "answer_4": "answer_4 = [0, 30.02, 60.05]",  # within 0.1 % of (0, 30, 60)
        "answer_5": "answer_5 = np.array([[70.0], [0.0], [70.0]])",  # a column
    },
    "04_module_method_classic_arms": {
        "answer_4": 'answer_4 = "[20*cos(0), 30*sin(pi/2), 30 - 5]"',
    },
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


@pytest.mark.parametrize("lesson", _lessons())
def test_solutions_have_the_same_exercises(lesson):
    exercises = exercise_cells(_exercises(lesson))
    solutions = exercise_cells(solutions_path(_exercises(lesson)))
    assert [e.variable for e in exercises] == [s.variable for s in solutions]
    for exercise, solution in zip(exercises, solutions, strict=True):
        assert exercise.check_source == solution.check_source, exercise.variable
    assert 3 <= len(exercises) <= 5


@pytest.mark.parametrize("lesson", _lessons())
def test_every_exercise_has_a_wrong_answer_test(lesson):
    variables = [e.variable for e in exercise_cells(_exercises(lesson))]
    assert sorted(WRONG_ANSWERS[lesson]) == sorted(variables)


@pytest.mark.parametrize("lesson", _lessons())
def test_blank_exercises_ask_for_an_answer(lesson):
    errors = run_with_answers(_exercises(lesson))
    for variable, error in errors.items():
        number = variable.split("_")[1]
        assert f"Exercise {number} is not answered yet" in error, (variable, error)


@pytest.mark.parametrize("lesson", _lessons())
def test_solutions_pass_their_checks(lesson):
    errors = run_with_answers(solutions_path(_exercises(lesson)))
    assert errors and not any(errors.values()), errors


@pytest.mark.parametrize("lesson", sorted(APPROXIMATE_ANSWERS))
def test_text_and_rounded_answers_pass(lesson):
    answers = APPROXIMATE_ANSWERS[lesson]
    errors = run_with_answers(_exercises(lesson), answers)
    assert all(errors[variable] == "" for variable in answers), errors


@pytest.mark.parametrize(("lesson", "variable"), _cases())
def test_typical_wrong_answer_gets_a_hint_naming_the_mistake(lesson, variable):
    error = _wrong_run(lesson)[variable]
    _, words = WRONG_ANSWERS[lesson][variable]
    assert "AssertionError" in error, error
    assert words in error, error
