"""Lessons 1–4 of the course: the exercises' checks are real, and the numbers follow the id.

For every exercise a typical wrong answer must fail its check cell with a hint that names
the mistake (the hint comes from robotconf's checker), and the solutions must pass; right
answers typed as text or rounded (1.5708 for π/2, 0.8776 for cos 0.5) pass too.

The numeric exercises of lessons 2–4 draw their numbers from the student id
(``rc.Variant``, typed in the one cell tagged ``student-id``); the symbolic ones and
lesson 1 stay the same for everyone. The wrong answers are written with the notebook's
own numbers, so they hold for any id. Another student's right numbers, typed as text or
rounded, pass in that student's notebook, and the demo student's numbers fail there (the
numbers follow the id). Each notebook runs once per set of answers, with all its answers
replaced; the drawn numbers are read by running a notebook's other cells here, without a
kernel.
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
    "02_elementary_transforms": ("answer_4",),
    "03_composing_a_chain": ("answer_4", "answer_5"),
    "04_module_method_classic_arms": ("answer_4",),
}
# The lessons whose tests hand the demo student's numbers in under another id.
SECOND_STUDENT = ("03_composing_a_chain", "04_module_method_classic_arms")

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
        # calculator in degree mode (q1 is the notebook's own number, in radians)
        "answer_4": (
            "c, s = np.cos(np.radians(q1)), np.sin(np.radians(q1))\n"
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
        # module 3 turned the wrong way (the sine sign of Ry): -q3 at the drawn pose q_4
        "answer_4": (
            "reach = 30 * np.cos(q_4[1]) + 40 * np.cos(q_4[1] - q_4[2])\n"
            "answer_4 = [np.cos(q_4[0]) * reach, np.sin(q_4[0]) * reach,"
            " 20 - 30 * np.sin(q_4[1]) - 40 * np.sin(q_4[1] - q_4[2])]",
            "The sine terms of A3 (module M3, Ry with a = (30, 0, 0)) have the wrong sign",
        ),
        # the pedestal module forgotten (its height h is drawn)
        "answer_5": (
            "answer_5 = [70, 0, 20]",
            "The offset of A1 (module M1, fixed with a = (0, 0, ",
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
        # degrees fed to cos and sin, at the drawn joint values q_4
        "answer_4": (
            "q1_deg, q12_deg = np.degrees(q_4[0]), np.degrees(q_4[0] + q_4[1])\n"
            "answer_4 = [30 * np.cos(q1_deg) + 20 * np.cos(q12_deg),"
            " 30 * np.sin(q1_deg) + 20 * np.sin(q12_deg), 30 + q_4[2]]",
            "angles in degrees fed to sin and cos",
        ),
    },
}


# Lesson 1 (no per-student numbers): right answers as students type them, as text with
# numbers and formulas.
APPROXIMATE_ANSWERS: dict[str, str] = {
    "answer_2": 'answer_2 = "[[cos(pi/2), -sin(pi/2), 0, 30], [sin(pi/2), cos(pi/2), 0, 0],'
    ' [0, 0, 1, 20], [0, 0, 0, 1]]"',
    # π/2 typed as 1.5708: 40·cos(1.5708) = -1.5e-4, within 0.001 of 0
    "answer_3": 'answer_3 = "[30 + 40*cos(1.5708), 40*sin(1.5708), 20]"',
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
    if lesson == "02_elementary_transforms":
        c, s = np.cos(d["q1"]), np.sin(d["q1"])  # to 4 decimals, as text
        return {
            "answer_4": f'answer_4 = "[[{c:.4f}, {-s:.4f}, 0, 0], [{s:.4f}, {c:.4f}, 0, 0],'
            f' [0, 0, 1, 0], [0, 0, 0, 1]]"'
        }
    if lesson == "03_composing_a_chain":
        q1, q2, q3 = d["q_4"]
        reach = 30 * np.cos(q2) + 40 * np.cos(q2 + q3)
        p = [np.cos(q1) * reach, np.sin(q1) * reach, 20 - 30 * np.sin(q2) - 40 * np.sin(q2 + q3)]
        return {
            "answer_3": 'answer_3 = "[30 + 40, 0, 20]"',  # the same for everyone
            "answer_4": f"answer_4 = {_rounded(p, 3)}",
            "answer_5": f"answer_5 = np.array([[70.0], [0.0], [{20 + d['h']}]])",  # a column
        }
    q1, q2, q3 = d["q_4"]  # lesson 4: the SCARA as a formula in text, angles in radians
    return {
        "answer_4": f'answer_4 = "[30*cos({q1:.5f}) + 20*cos({q1 + q2:.5f}),'
        f' 30*sin({q1:.5f}) + 20*sin({q1 + q2:.5f}), {30 + q3:g}]"'
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


def test_text_and_rounded_answers_pass():
    errors = run_with_answers(_exercises("01_homogeneous_transforms"), APPROXIMATE_ANSWERS)
    assert all(errors[variable] == "" for variable in APPROXIMATE_ANSWERS), errors


@pytest.mark.parametrize("lesson", sorted(VARIED))
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


def test_lesson_1_has_no_per_student_numbers():
    cells = read_notebook(_exercises("01_homogeneous_transforms")).cells
    assert not [c for c in cells if "student-id" in c.metadata.get("tags", [])]


def test_the_demo_id_draws_stable_numbers():
    """The demo student's numbers stay put (the diagnosis corpus's references).

    They are the classic ones wherever those refuse every slip; lesson 3's classic
    pose (90°, 0°, -90°) hides a sign slip of q2 = 0, so screening draws the next.
    """
    assert _drawn("02_elementary_transforms", "demo")["q1"] == 0.5
    chain = _drawn("03_composing_a_chain", "demo")
    assert np.allclose(np.degrees(chain["q_4"]), [30, -30, -90]) and chain["h"] == 50
    scara = _drawn("04_module_method_classic_arms", "demo")["q_4"]
    assert np.allclose(np.degrees(scara[:2]), [90, -90]) and scara[2] == -5


@pytest.mark.parametrize(("lesson", "variable"), _cases())
def test_typical_wrong_answer_gets_a_hint_naming_the_mistake(lesson, variable):
    error = _wrong_run(lesson)[variable]
    _, words = WRONG_ANSWERS[lesson][variable]
    assert "AssertionError" in error, error
    assert words in error, error
