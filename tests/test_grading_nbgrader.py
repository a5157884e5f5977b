"""The course through nbgrader, end to end: release, generate, submit, autograde, feedback.

Two assignments of the real course, with the points of course/kit/weights.md:

- lesson 01 (matrices, no per-student numbers): all right; typical mistakes; a formula
  fitted to the check's sample points (caught by the hidden recheck);
- lesson 12 (numbers, profiles and sets, per-student numbers): a generated class — a
  student with their own right answers, one with a typical single slip in every
  exercise (2v/a, a triangle taken for a trapezoid, the cubic's factor, each joint its
  own duration, moves counted from 1, x left out), a blank copy, one whose answer cells
  ask robotconf for the answers, and one who copies another student's numbers.

The rubric's promises are asserted on the gradebook: a named single slip earns a
quarter to three quarters of the points; a shortcut cell is flagged for manual grading
and earns no automatic credit; blank earns 0. A sweep over every exercise's slips
without nbgrader is in tests/test_exercise_sweep.py.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import robotconf as rc
from robotconf import teaching
from robotconf.grading import FLAG, find_exercises, read_notebook, read_weights, release_course

from .test_grading_release import COURSE, LESSON

pytest.importorskip("nbgrader", reason="nbgrader is not installed (it is in the dev extra)")

CLASS_LESSON = "12_trajectories"
WEIGHTS = read_weights(COURSE / "kit" / "weights.md")
A1 = "[[cos(q1), -sin(q1), 0, 30], [sin(q1), cos(q1), 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]]"


def _fitted_a1() -> str:
    """Exercise 4's A1 with (1,1) = cos(q1) + ∏(q1 − p), p the visible check's 8 points."""
    points = teaching.sample_points(["q1"], 8, 0)["q1"]
    bump = "*".join(f"(q1 - {float(p)!r})" for p in points)
    return A1.replace("[[cos(q1),", f"[[cos(q1) + {bump},", 1)


#: What each student types into lesson 01's answer cells (missing: left at None).
LESSON_01 = {
    "alice": {
        "answer_1": '"[[0, 1, 0, 10], [0, 0, 1, 20], [1, 0, 0, 30], [0, 0, 0, 1]]"',
        "answer_2": "[[0, -1, 0, 30], [1, 0, 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]]",
        "answer_3": "[30, 40, 20]",
        "answer_4": repr(A1),
    },
    "bob": {
        "answer_1": "[[0, 1, 0, 10], [0, 0, 1, 20], [1, 0, 0, 30], [0, 0, 0, 1]]",
        # Turned the wrong way: a named slip, half of 2 points.
        "answer_2": "[[0, 1, 0, 30], [-1, 0, 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]]",
        # The y of the point rotated the wrong way: 2 of 3 numbers right.
        "answer_3": "[30, -40, 20]",
    },
    "carol": {"answer_4": repr(_fitted_a1())},
}
#: Points per test cell, by hand from weights.md (1, 2, 1, 2) and the rubric.
EXPECTED_01 = {
    "alice": {"test_answer_1": 1, "test_answer_2": 2, "test_answer_3": 1, "test_answer_4": 2},
    "bob": {"test_answer_1": 1, "test_answer_2": 1, "test_answer_3": 0.67, "test_answer_4": 0},
    # Passes the visible check, fails the hidden one on entry (1,1) only: 5 of 6 numbers
    # right, a wrong answer earns at most 3/4 of 2 points.
    "carol": {"test_answer_1": 0, "test_answer_2": 0, "test_answer_3": 0, "test_answer_4": 1.5},
}

#: The slip each exercise of lesson 12 gets in the "slips" student's copy.
SLIPS_12 = {
    1: "accel_time_factor",  # 2v/a for the acceleration time
    2: "triangle_as_trapezoid",  # the trapezoid's formulas for a short move
    3: "cubic_quintic_swapped",  # the cubic's 3/2 for the quintic's 15/8
    4: "not_synchronized",  # each joint its own duration
    5: "counted_from_1",  # the moves counted from 1
    6: "x_left_out",  # x* left out of v/(l1 l2 sin q2)·x
}
#: The class of lesson 12: student → (id typed, how the answers are made).
CLASS_12 = {
    "right": ("s101", "right"),
    "slips": ("s103", "slips"),
    "blank": ("s104", "blank"),
    "shortcut": ("s105", "shortcut"),
    "copier": ("s106", "copy s101"),
}


def _typed(value) -> str:
    """A value as a student types it: plain numbers, lists, text."""
    if isinstance(value, (str, dict)):
        return repr(value)
    return repr(np.asarray(value, dtype=float).tolist())


def _answers_12(student_id: str, how: str) -> dict[str, str]:
    """The answer cells' code of one student of the class."""
    task = rc.Assignment(CLASS_LESSON, student_id)
    numbers = [e.number for e in teaching.exercises.registered(CLASS_LESSON)]
    if how == "blank":
        return {}
    if how == "shortcut":  # the answers asked of robotconf, in the answer cells
        return {f"answer_{k}": f"answer_{k} = task.answer({k})" for k in numbers}
    if how.startswith("copy "):
        task = rc.Assignment(CLASS_LESSON, how.split()[1])
    if how == "slips":
        values = {k: task.exercise(k).slips(task.numbers)[SLIPS_12[k]] for k in numbers}
    else:
        values = {k: task.answer(k) for k in numbers}
    return {f"answer_{k}": f"answer_{k} = {_typed(v)}" for k, v in values.items()}


def _nbgrader(out: Path, *args: str) -> None:
    # nbgrader runs its database migrations with the `alembic` script next to Python.
    path = f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}"
    result = subprocess.run(
        [sys.executable, "-m", "nbgrader", *args],
        cwd=out,
        env={**os.environ, "PATH": path},
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]


def _submit(out: Path, assignment: str, student: str, sources: dict[str, str]) -> None:
    """A student's copy of the released notebook with some cells' code replaced."""
    path = out / "release" / assignment / f"{assignment}.ipynb"
    notebook = read_notebook(path)
    for cell in notebook["cells"]:
        grade_id = cell["metadata"].get("nbgrader", {}).get("grade_id")
        if grade_id in sources:
            cell["source"] = sources[grade_id]
        if "student-id" in cell["metadata"].get("tags", []) and "student_id" in sources:
            cell["source"] = f"student_id = {sources['student_id']!r}"
    target = out / "submitted" / student / assignment / f"{assignment}.ipynb"
    target.parent.mkdir(parents=True)
    target.write_text(json.dumps(notebook), encoding="utf-8")


def _grades(out: Path, assignment: str) -> dict[str, dict[str, tuple[float, bool]]]:
    """student → test cell → (score, needs manual grade)."""
    from nbgrader.api import Gradebook

    grades = {}
    with Gradebook(f"sqlite:///{out / 'gradebook.db'}") as gradebook:
        for submission in gradebook.assignment_submissions(assignment):
            (notebook,) = submission.notebooks
            grades[submission.student.id] = {
                g.name: (g.score, bool(g.needs_manual_grade)) for g in notebook.grades
            }
    return grades


def _scores(out: Path, assignment: str) -> dict[str, dict[str, float]]:
    return {
        student: {name: score for name, (score, _) in cells.items()}
        for student, cells in _grades(out, assignment).items()
    }


def _points_12(number: int) -> float:
    points = WEIGHTS.points_of(CLASS_LESSON, number)
    assert points is not None
    return points


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    out = tmp_path_factory.mktemp("nbgrader_course") / "out"
    release_course(out, COURSE, "01,12")
    _nbgrader(out, "generate_assignment", "*")
    for student, answers in LESSON_01.items():
        sources = {name: f"{name} = {value}" for name, value in answers.items()}
        _submit(out, LESSON, student, sources)
    for student, (student_id, how) in CLASS_12.items():
        sources = {"student_id": student_id, **_answers_12(student_id, how)}
        _submit(out, CLASS_LESSON, student, sources)
    _nbgrader(out, "autograde", "*")
    _nbgrader(out, "generate_feedback", "*")
    return out


def _feedback(out: Path, student: str, assignment: str) -> str:
    return (out / "feedback" / student / assignment / f"{assignment}.html").read_text("utf-8")


def test_the_student_version_has_stubs_and_no_check(graded):
    for assignment in (LESSON, CLASS_LESSON):
        notebook = read_notebook(graded / "release" / assignment / f"{assignment}.ipynb")
        text = json.dumps(notebook)
        assert "BEGIN SOLUTION" not in text and "recheck" not in text
        assert "assert_answer" not in text and "Credit(" not in text
        assert "How this copy is graded" in text
        for exercise in find_exercises(notebook):
            source = "".join(notebook["cells"][exercise.answer_index]["source"])
            assert source.startswith(f"{exercise.variable} = None")
    assert "[30, 40, 20]" not in json.dumps(
        read_notebook(graded / "release" / LESSON / f"{LESSON}.ipynb")
    )


def test_lesson_01_gets_full_partial_and_hidden_test_scores(graded):
    scores = _scores(graded, LESSON)
    assert scores == EXPECTED_01  # the scores are the printed numbers, 0.01 steps
    assert sum(scores["alice"].values()) == 6


def test_right_answers_earn_every_point(graded):
    scores = _scores(graded, CLASS_LESSON)
    full = {f"test_answer_{k}": _points_12(k) for k in SLIPS_12}
    assert scores["right"] == full


def test_a_named_single_slip_earns_a_quarter_to_three_quarters(graded):
    scores = _scores(graded, CLASS_LESSON)["slips"]
    for k in SLIPS_12:
        share = scores[f"test_answer_{k}"] / _points_12(k)
        assert 0.25 <= share <= 0.75, (k, SLIPS_12[k], share)
    html = _feedback(graded, "slips", CLASS_LESSON)
    assert html.count("the checker names one slip of a right method") >= 5


def test_a_blank_copy_earns_nothing(graded):
    assert set(_scores(graded, CLASS_LESSON)["blank"].values()) == {0}
    assert "Exercise 1 is not answered yet" in _feedback(graded, "blank", CLASS_LESSON)


def test_answers_asked_of_robotconf_are_flagged_and_earn_no_automatic_credit(graded):
    cells = _grades(graded, CLASS_LESSON)["shortcut"]
    assert cells == {f"test_answer_{k}": (0, True) for k in SLIPS_12}
    html = _feedback(graded, "shortcut", CLASS_LESSON)
    assert FLAG in html and "task.answer" in html
    # nobody else is sent to manual grading
    others = _grades(graded, CLASS_LESSON)
    assert not any(flag for s, c in others.items() if s != "shortcut" for _, flag in c.values())


def test_each_student_is_graded_against_their_own_numbers(graded):
    scores = _scores(graded, CLASS_LESSON)
    copied, own = sum(scores["copier"].values()), sum(scores["right"].values())
    assert copied < own / 2, scores["copier"]


def test_feedback_says_what_cost_the_points(graded):
    html = _feedback(graded, "bob", LESSON)
    assert "Credit: 0.67 points of 1 point: 2 of the 3 numbers that count are right" in html
    assert "the checker names one slip of a right method" in html
    assert "Exercise 4 is not answered yet" in html
