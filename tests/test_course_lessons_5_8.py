"""Lessons 5–8 of the course: the exercises' checks are real.

For every exercise a typical wrong answer must fail its check cell with a hint that names
the mistake, and the solutions must pass. The hints of matrix exercises come from
robotconf's checker (``rc.assert_matrix``); the other answers go through the same parser
and numeric judge with a tolerance of 0.1 % (0.001 near 0): a velocity
(``rc.assert_vector``), finite-difference spikes (``rc.assert_value``), the singular
joint values (``rc.assert_set``, modulo 2π) and an elbow angle (``rc.assert_angle``), each
with the exercise's own hint. So rounded numbers (3.1416 for π, 1.5708 for π/2), text
answers (``"[pi, 0]"``) and answers a whole turn away pass.

The numeric exercises draw their numbers from the student id (``rc.Variant``, typed in
the one cell tagged ``student-id``); the symbolic ones stay the same for everyone. The
wrong answers are written with the notebook's own numbers, so they hold for any id.
Each notebook runs once with every answer replaced by a wrong one and once as the
solutions; lessons 7 and 8 run once more with rounded and text answers, once with
another student's own numbers typed in that student's notebook (they pass), once with
the demo student's numbers in that notebook (they fail: the numbers follow the id) and
once more with other typical mistakes. The drawn numbers are read by running a
notebook's other cells here, without a kernel.
"""

from __future__ import annotations

import ast
import contextlib
import functools
import io
from typing import Any

import nbformat
import numpy as np
import pytest

import robotconf as rc

from .course_support import (
    COURSE,
    exercise_cells,
    read_notebook,
    run_with_answers,
    solutions_path,
)

OTHER_ID = "s1234567"

# lesson folder -> the exercises whose numbers follow the student id
VARIED: dict[str, tuple[str, ...]] = {
    "05_denavit_hartenberg": ("answer_3", "answer_5"),
    "06_real_arms": ("answer_1", "answer_2"),
    "07_velocity_acceleration": ("answer_2", "answer_3", "answer_4", "answer_5"),
    "08_workspace_singularities": ("answer_1", "answer_4"),
}
# The lessons whose tests run another student's notebook.
SECOND_STUDENT = ("07_velocity_acceleration", "08_workspace_singularities")

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
        # the angle in degrees fed to cos and sin as if it were radians
        "answer_3": (
            "answer_3 = np.round(rc.dh_matrix(np.degrees(q1_3), 0, a_3, 0), 4)",
            "angles in degrees fed to sin and cos",
        ),
        # the offset d = 20 of the first row forgotten
        "answer_4": (
            'answer_4 = "[[cos(q1), 0, -sin(q1), 0], [sin(q1), 0, cos(q1), 0],'
            ' [0, -1, 0, 0], [0, 0, 0, 1]]"',
            "The link offset d of A1",
        ),
        # the same mistake in a position: the column height d1 = 20 missing
        "answer_5": (
            "reach = 30 * np.cos(q_5[1]) + 40 * np.cos(q_5[1] + q_5[2])\n"
            "answer_5 = [np.cos(q_5[0]) * reach, np.sin(q_5[0]) * reach,"
            " -30 * np.sin(q_5[1]) - 40 * np.sin(q_5[1] + q_5[2])]",
            "The link offset d of A1",
        ),
    },
    "06_real_arms": {
        # calculator in radian mode with the degrees typed in
        "answer_1": (
            "answer_1 = np.round(rc.dh_matrix(np.degrees(q2_1), 0, 0.4318, 0), 4)",
            "angles in degrees fed to sin and cos",
        ),
        # the flange offset d6 forgotten: y = -d4 at q = 0, then turned by q1
        "answer_2": (
            "x0, y0 = -0.81725, -0.10915\n"
            "answer_2 = [np.cos(q1_2) * x0 - np.sin(q1_2) * y0,"
            " np.sin(q1_2) * x0 + np.cos(q1_2) * y0, -0.005491]",
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
        "answer_2": ("answer_2 = [0, 70 * qd_2[0], 40 * qd_2[2]]", "The sign of z is wrong."),
        # the columns of joints 2 and 3 exchanged
        "answer_3": (
            "s, c = np.sin(q3_3), np.cos(q3_3)\n"
            "answer_3 = [[0, -40 * s, -40 * s], [30 + 40 * c, 0, 0], [0, -40 * c, -30 - 40 * c]]",
            "Columns 2 and 3 are swapped",
        ),
        # the slope of the ramp instead of the finite difference across the jump
        "answer_4": ("answer_4 = 1.0", "1 rad/s is the ramp's own slope"),
        # the central difference when Simulink's backward one was asked
        "answer_5": (
            "answer_5 = (dt - (2 - dt)) / (2 * dt)",
            "That is the central difference (q[k+1] - q[k-1]) / (2 dt)",
        ),
    },
    "08_workspace_singularities": {
        # the Jacobian written with one row per joint
        "answer_1": (
            "answer_1 = [[-2 * np.sin(q1_1), 2 * np.cos(q1_1)], [-np.sin(q1_1), np.cos(q1_1)]]",
            "The whole matrix is transposed",
        ),
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
        "answer_2": ("answer_2 = [0, 0.07 * qd_2[0], -0.04 * qd_2[2]]", "1000 times too small"),
        # q[k-1] - q[k+1]: the difference the wrong way round
        "answer_4": ("answer_4 = ((2 - dt) - dt) / (2 * dt)", "has the wrong sign"),
        # the jump not divided by dt
        "answer_5": ("answer_5 = 0 - (2 - dt)", "Divide the difference by dt"),
    },
    "08_workspace_singularities": {
        # only the stretched arm
        "answer_3": ("answer_3 = [0]", "1 is missing: the arm folded"),
        # the angle in degrees
        "answer_4": (
            "answer_4 = np.degrees(np.arccos(-30 * np.cos(q2_4) / 40) - q2_4)",
            "You gave degrees: write q3 in radians",
        ),
    },
}

# Right answers as students type them: rounded, as text, a turn away; written with the
# notebook's own numbers (the demo student's).
APPROXIMATE_ANSWERS: dict[str, dict[str, str]] = {
    "07_velocity_acceleration": {
        "answer_2": 'answer_2 = f"[0, {70 * qd_2[0]:g}, {-40 * qd_2[2]:g}]"',
        "answer_4": 'answer_4 = f"({dt:g} - {2 - dt:g}) / (2 * {dt:g})"',
        "answer_5": "answer_5 = (dt - 2) / dt * 1.0005",  # 0.05 % off
    },
    "08_workspace_singularities": {
        "answer_3": 'answer_3 = "[3.1416, 0]"',  # π rounded, larger first, as text
        "answer_4": "answer_4 = round(float(np.arccos(-30 * np.cos(q2_4) / 40) - q2_4), 4)",
    },
}


@functools.cache
def _drawn(lesson: str, student: str) -> dict[str, Any]:
    """The numbers a student's exercises notebook works with, by variable name.

    The notebook's code cells run here (no kernel), the student-id cell set to
    ``student``, without the answer and check cells.
    """
    namespace: dict[str, Any] = {}
    with np.printoptions(), contextlib.redirect_stdout(io.StringIO()):
        for cell in read_notebook(_exercises(lesson)).cells:
            tags = set(cell.metadata.get("tags", []))
            if cell.cell_type != "code" or tags & {"answer", "check"}:
                continue
            source = f"student_id = {student!r}" if "student-id" in tags else cell.source
            exec(compile(source, f"{lesson} ({student})", "exec"), namespace)  # our notebook
    return namespace


def _rounded(values: Any, decimals: int) -> list:
    return np.round(np.asarray(values, dtype=float), decimals).tolist()


def _typed_answers(lesson: str, student: str) -> dict[str, str]:
    """A student's right answers as they would type them: numbers, text, rounded.

    Computed here, by hand-style formulas, from the numbers the student's notebook draws.
    """
    d = _drawn(lesson, student)
    if lesson == "07_velocity_acceleration":
        qd1, qd3, dt = d["qd_2"][0], d["qd_2"][2], d["dt"]
        s, c = np.sin(d["q3_3"]), np.cos(d["q3_3"])
        jacobian = [[0, -40 * s, -40 * s], [30 + 40 * c, 0, 0], [0, -30 - 40 * c, -40 * c]]
        return {
            "answer_2": f"answer_2 = np.array([[0.0], [{70 * qd1:.3f}], [{-40 * qd3:.3f}]])",
            "answer_3": f"answer_3 = {_rounded(jacobian, 3)}",
            "answer_4": f'answer_4 = "{(2 * dt - 2) / (2 * dt):.6g}"',
            "answer_5": f'answer_5 = "-{2 - dt:g} / {dt:g}"',
        }
    q1, q2 = d["q1_1"], d["q2_4"]  # lesson 8
    q3 = np.arccos(-30 * np.cos(q2) / 40) - q2
    jacobian = [[-2 * np.sin(q1), -np.sin(q1)], [2 * np.cos(q1), np.cos(q1)]]
    return {
        "answer_1": f"answer_1 = {_rounded(jacobian, 4)}",
        "answer_3": "answer_3 = [2 * np.pi, 3.1416]",  # 0 given as a full turn; the same for all
        "answer_4": f'answer_4 = "{q3:.4f} - 2*pi"',  # the same angle, a turn back
    }


def _with_student(path, student_id: str, folder):
    """A copy of the notebook whose student-id cell holds ``student_id``."""
    notebook = read_notebook(path)
    (cell,) = [c for c in notebook.cells if "student-id" in c.metadata.get("tags", [])]
    cell.source = f"student_id = {student_id!r}"
    copy = folder / f"{path.parent.name}-{student_id}.ipynb"
    nbformat.write(notebook, str(copy))
    return copy


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


@pytest.mark.parametrize("lesson", sorted(APPROXIMATE_ANSWERS))
def test_rounded_and_text_answers_pass(lesson):
    answers = APPROXIMATE_ANSWERS[lesson]
    errors = run_with_answers(_exercises(lesson), answers)
    assert all(errors[variable] == "" for variable in answers), errors


@pytest.mark.parametrize("lesson", SECOND_STUDENT)
def test_another_student_passes_with_their_own_numbers_typed_or_rounded(lesson, tmp_path):
    answers = _typed_answers(lesson, OTHER_ID)
    errors = run_with_answers(_with_student(_exercises(lesson), OTHER_ID, tmp_path), answers)
    assert all(errors[variable] == "" for variable in answers), errors


@pytest.mark.parametrize("lesson", SECOND_STUDENT)
def test_the_demo_students_numbers_fail_for_another_student(lesson, tmp_path):
    demo = {v: _typed_answers(lesson, "demo")[v] for v in VARIED[lesson]}
    other = _typed_answers(lesson, OTHER_ID)
    assert all(demo[variable] != other[variable] for variable in demo), (demo, other)
    errors = run_with_answers(_with_student(_exercises(lesson), OTHER_ID, tmp_path), demo)
    for variable in demo:
        assert "AssertionError" in errors[variable], errors[variable]
        assert "not answered yet" not in errors[variable]


NOTEBOOKS = [_exercises(n) for n in VARIED] + [solutions_path(_exercises(n)) for n in VARIED]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: f"{p.parent.parent.name}/{p.parent.name}")
def test_one_student_id_cell_feeds_the_variant(path):
    """The contract the answer key and the release rely on."""
    cells = read_notebook(path).cells
    tagged = [c for c in cells if "student-id" in c.metadata.get("tags", [])]
    assert len(tagged) == 1
    (statement,) = ast.parse(tagged[0].source).body
    assert isinstance(statement, ast.Assign) and statement.targets[0].id == "student_id"
    assert statement.value.value == "demo"
    code = "\n".join(c.source for c in cells if c.cell_type == "code")
    assert f'rc.Assignment("{path.parent.name}", student_id)' in code
    assert code.index("student_id =") < code.index("rc.Assignment(")


def test_the_demo_id_draws_stable_numbers():
    """The demo student's numbers stay put (the diagnosis corpus's references).

    They are the classic ones wherever those refuse every slip; lesson 5's classic pose
    (90°, 0°, -90°) hides a sign slip of q2 = 0, so screening draws the next (likewise
    lesson 6's q1 = 0 and lesson 8's zero angles).
    """
    dh = _drawn("05_denavit_hartenberg", "demo")
    assert dh["a_3"] == 2 and np.isclose(np.degrees(dh["q1_3"]), 30)
    assert np.allclose(np.degrees(dh["q_5"]), [30, -60, -120])
    arms = _drawn("06_real_arms", "demo")
    assert np.isclose(np.degrees(arms["q2_1"]), 30) and np.isclose(np.degrees(arms["q1_2"]), -120)
    velocity = _drawn("07_velocity_acceleration", "demo")
    assert velocity["qd_2"] == [0.5, 0, 1.0] and velocity["dt"] == 0.01
    assert np.isclose(np.degrees(velocity["q3_3"]), -90)
    singular = _drawn("08_workspace_singularities", "demo")
    assert np.isclose(singular["q1_1"], np.pi / 2) and np.isclose(singular["q2_4"], -np.pi / 6)


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
