"""The semester kit (course/kit/): outcomes, plan, misconceptions, quizzes and the exam.

The quizzes and the exam are drawn per student from the course's exercises
(``rc.Exam``); ``robotconf course quiz|exam`` write them as course folders, which these
tests run (in this process, without a kernel) and check like the lessons.
"""

from __future__ import annotations

import contextlib
import io
import re
from collections import Counter

import pytest

import robotconf as rc
from robotconf import InvalidInputError
from robotconf.cli import main
from robotconf.grading import SLIP_WORDS, read_weights
from robotconf.grading._quiz import read_exam_bank, read_quizzes
from robotconf.grading.rubric._rubric import UNEXPLAINED

from .course_support import COURSE, exercise_cells, lesson_dirs, read_notebook

KIT = COURSE / "kit"


def test_the_kit_has_its_parts_and_the_instructor_notes_link_them():
    names = {"outcomes.md", "plan.md", "misconceptions.md", "quizzes.md", "exam_bank.md"}
    assert names | {"weights.md"} <= {p.name for p in KIT.iterdir()}
    notes = (COURSE / "INSTRUCTOR.md").read_text(encoding="utf-8")
    assert all(f"kit/{name}" in notes for name in names | {"weights.md"})


def test_every_lesson_has_a_quiz_of_registered_exercises():
    quizzes = read_quizzes(COURSE)
    assert sorted(quizzes) == [p.name for p in lesson_dirs()]
    assert all(1 <= len(items) <= 2 for items in quizzes.values())


def test_the_exam_bank_has_a_slot_per_outcome_and_30_points():
    slots = read_exam_bank(COURSE)
    assert len(slots) == 8 and sum(s.points for s in slots) == 30
    assert all(len(s.options) >= 2 for s in slots)
    text = (KIT / "exam_bank.md").read_text(encoding="utf-8")
    assert [f"O{k}" for k in range(1, 9)] == re.findall(r"\| (O\d) \|", text)


def test_the_outcomes_cover_the_homework_points():
    text = (KIT / "outcomes.md").read_text(encoding="utf-8")
    rows = [line for line in text.splitlines() if re.match(r"\| O\d \|", line)]
    assert len(rows) == 9
    points = sum(float(x) for row in rows for x in re.findall(r"\((\d+(?:\.\d+)?)\)", row))
    assert points == sum(read_weights(KIT / "weights.md").points.values()) == 113


def test_the_plan_has_14_weeks_and_a_buffer():
    text = (KIT / "plan.md").read_text(encoding="utf-8")
    weeks = re.findall(r"^\| (\d+) \|", text, flags=re.M)
    assert weeks == [str(k) for k in range(1, 15)]
    assert text.count("**buffer**") == 1


def test_misconceptions_name_real_diagnosis_codes():
    text = (KIT / "misconceptions.md").read_text(encoding="utf-8")
    codes = set(re.findall(r"\(`([a-z_0-9]+)`", text)) | set(re.findall(r", `([a-z_0-9]+)`", text))
    assert len(codes) >= 25
    unknown = sorted(c for c in codes if c not in SLIP_WORDS and c not in UNEXPLAINED)
    assert not unknown, unknown


SLOTS = [[("12_trajectories", 1), ("12_trajectories", 2)], [("11_inverse_kinematics", 4)]]


def test_an_exam_is_drawn_per_student_with_its_own_numbers():
    first = Counter(rc.Exam(f"s{i}", SLOTS, draw="t").item(1) for i in range(12))
    assert set(first) == {("12_trajectories", 1), ("12_trajectories", 2)}
    exam = rc.Exam("s1", SLOTS, draw="t")
    assert exam.item(1) == rc.Exam(" S1 ", SLOTS, draw="t").item(1)
    homework = rc.Assignment("11_inverse_kinematics", "s1")
    assert list(exam.numbers(2)["target"]) != list(homework["target"])  # not the homework's
    assert exam.check(2, exam.answer(2)).ok
    assert "Item 2: lesson 11, exercise 4" in exam.shows(2)
    with pytest.raises(AssertionError, match="q_k"):
        exam.assert_answer(2, exam.task(2)["q_k"].tolist())


@pytest.mark.parametrize(
    ("slots", "field"),
    [([], "slots"), ([[]], "slots[0]"), ([[("12_trajectories", 9)]], "slots[0]")],
)
def test_bad_slots_are_refused(slots, field):
    with pytest.raises(InvalidInputError, match=re.escape(field)):
        rc.Exam("s1", slots)


def _run(path) -> dict:
    """Run a notebook's code cells here; return the check cells' errors by variable."""
    notebook = read_notebook(path)
    checks = {e.check_index: e.variable for e in exercise_cells(path)}
    namespace: dict = {}
    errors = {}
    with contextlib.redirect_stdout(io.StringIO()):
        for index, cell in enumerate(notebook.cells):
            if cell.cell_type != "code":
                continue
            try:
                exec(compile(cell.source, str(path), "exec"), namespace)  # our notebook
            except AssertionError as error:
                if index not in checks:
                    raise
                errors[checks[index]] = str(error)
    return errors


def test_the_exam_and_a_quiz_are_course_folders_that_run(tmp_path, capsys):
    exam, quizzes = tmp_path / "exam", tmp_path / "quizzes"
    assert main(["course", "exam", str(exam), "--draw", "exam-test"]) == 0
    assert main(["course", "quiz", str(quizzes), "--lessons", "12"]) == 0
    assert "wrote" in capsys.readouterr().out
    for folder, name, items in ((exam, "90_exam", 8), (quizzes, "12_quiz_trajectories", 2)):
        exercises = folder / name / "exercises.ipynb"
        solutions = folder / "solutions" / name / "exercises.ipynb"
        assert len(exercise_cells(exercises)) == len(exercise_cells(solutions)) == items
        assert _run(solutions) == {}  # every item's key passes its check
        blank = _run(exercises)
        assert len(blank) == items and all("not answered yet" in e for e in blank.values())
        assert read_weights(folder / "kit" / "weights.md").points
    text = (exam / "90_exam" / "exercises.ipynb").read_text(encoding="utf-8")
    assert "If your item 3 is lesson 9, exercise 2" in text
