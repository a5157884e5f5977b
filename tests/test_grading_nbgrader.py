"""The course through nbgrader, end to end: release, generate, submit, autograde, feedback.

Two assignments: lesson 01 of the course, and a one-exercise lab whose numbers depend on
the student id (``tests/test_grading_release.py``'s ``variant_course``). Three students
hand in lesson 01 — all right, typical mistakes, and a formula fitted to the visible
check's sample points — and two hand in the lab, one copying the other's numbers. The
expected points are counted by hand from the rules of docs/grading.md.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from robotconf import teaching
from robotconf.grading import find_exercises, read_notebook, release_course

from .test_grading_release import COURSE, LESSON, VARIANT_LESSON, variant_course, variant_l2

pytest.importorskip("nbgrader", reason="nbgrader is not installed (it is in the dev extra)")

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
        # Turned the wrong way: -1 and 1 of the 4 graded entries (-1, 30, 1, 20) wrong.
        "answer_2": "[[0, 1, 0, 30], [-1, 0, 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]]",
        # The y of the point rotated the wrong way: 1 of 3 graded entries wrong.
        "answer_3": "[30, -40, 20]",
    },
    "carol": {"answer_4": repr(_fitted_a1())},
}
#: Points per test cell, by hand: 4×4 matrices 2, the position 1; partial credit is
#: points × (1 − wrong / graded), rounded to 0.01.
EXPECTED_01 = {
    "alice": {"test_answer_1": 2, "test_answer_2": 2, "test_answer_3": 1, "test_answer_4": 2},
    "bob": {"test_answer_1": 2, "test_answer_2": 1.0, "test_answer_3": 0.67, "test_answer_4": 0},
    # Passes the visible check, fails the hidden one on entry (1,1): 2 × 5/6.
    "carol": {"test_answer_1": 0, "test_answer_2": 0, "test_answer_3": 0, "test_answer_4": 1.67},
}


def _nbgrader(out: Path, *args: str) -> None:
    # nbgrader runs its database migrations with the `alembic` script next to Python.
    path = f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}"
    result = subprocess.run(
        [sys.executable, "-m", "nbgrader", *args],
        cwd=out,
        env={**os.environ, "PATH": path},
        capture_output=True,
        text=True,
        timeout=300,
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


def _scores(out: Path, assignment: str) -> dict[str, dict[str, float]]:
    from nbgrader.api import Gradebook

    scores = {}
    with Gradebook(f"sqlite:///{out / 'gradebook.db'}") as gradebook:
        for submission in gradebook.assignment_submissions(assignment):
            (notebook,) = submission.notebooks
            scores[submission.student.id] = {g.name: g.score for g in notebook.grades}
    return scores


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    root = tmp_path_factory.mktemp("nbgrader_course")
    out = root / "out"
    release_course(out, COURSE, "01")
    release_course(out, variant_course(root / "lab"), VARIANT_LESSON)
    _nbgrader(out, "generate_assignment", "*")
    for student, answers in LESSON_01.items():
        sources = {name: f"{name} = {value}" for name, value in answers.items()}
        _submit(out, LESSON, student, sources)
    alice = f"answer_1 = [{variant_l2('s001') + 10}, 0, 0]"
    _submit(out, VARIANT_LESSON, "alice", {"student_id": "s001", "answer_1": alice})
    _submit(out, VARIANT_LESSON, "bob", {"student_id": "s002", "answer_1": alice})  # copied
    _nbgrader(out, "autograde", "*")
    _nbgrader(out, "generate_feedback", LESSON)
    return out


def test_the_student_version_has_stubs_and_no_hidden_test(graded):
    notebook = read_notebook(graded / "release" / LESSON / f"{LESSON}.ipynb")
    text = json.dumps(notebook)
    assert "BEGIN SOLUTION" not in text and "recheck" not in text and "[30, 40, 20]" not in text
    for exercise in find_exercises(notebook):
        source = "".join(notebook["cells"][exercise.answer_index]["source"])
        assert source.startswith(f"{exercise.variable} = None")
        assert "NotImplementedError" not in source


def test_autograde_gives_full_partial_and_hidden_test_scores(graded):
    scores = _scores(graded, LESSON)
    assert scores == EXPECTED_01  # the scores are the printed numbers, 0.01 steps
    assert sum(scores["alice"].values()) == 7


def test_per_student_numbers_are_graded_against_each_students_own(graded):
    assert variant_l2("s001") != variant_l2("s002")
    # Bob's x is Alice's l2 + 10, not his own: the one graded entry is wrong.
    assert _scores(graded, VARIANT_LESSON) == {
        "alice": {"test_answer_1": 1.0},
        "bob": {"test_answer_1": 0.0},
    }


def test_feedback_shows_the_hints_and_the_partial_credit(graded):
    html = (graded / "feedback" / "bob" / LESSON / f"{LESSON}.html").read_text("utf-8")
    assert "Partial credit: 0.67 of 1 points" in html
    assert "Exercise 4 is not answered yet" in html
