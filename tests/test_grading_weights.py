"""The course's weighting table (course/kit/weights.md) and ``robotconf course rubric``."""

from __future__ import annotations

import pytest

from robotconf import InvalidInputError
from robotconf.cli import main
from robotconf.grading import find_exercises, read_notebook, read_weights

from .course_support import COURSE, lesson_dirs, solutions_path

WEIGHTS = read_weights(COURSE / "kit" / "weights.md")


def test_every_exercise_of_the_course_has_its_points():
    listed = {key for key in WEIGHTS.points}
    found = set()
    for lesson in lesson_dirs():
        number = str(int(lesson.name[:2]))
        notebook = read_notebook(solutions_path(lesson / "exercises.ipynb"))
        found |= {(number, str(e.number)) for e in find_exercises(notebook)}
    assert listed == found
    assert sum(WEIGHTS.points.values()) == 113


def test_lesson_points_follow_the_time_per_lesson():
    """About a point per five minutes: lesson 9's four DH tables are worth 9, not 4."""
    per_lesson: dict[str, float] = {}
    for (lesson, _), points in WEIGHTS.points.items():
        per_lesson[lesson] = per_lesson.get(lesson, 0) + points
    assert per_lesson["9"] == 9 and per_lesson["5"] == 9 and per_lesson["10"] == 12
    assert per_lesson["13"] == 9


def _table(tmp_path, text: str):
    path = tmp_path / "weights.md"
    path.write_text(text, encoding="utf-8")
    return read_weights(path)


def test_shares_by_slip_exercise_and_lesson(tmp_path):
    weights = _table(
        tmp_path,
        "Some prose first.\n\n"
        "| lesson | exercise | points |\n|---|---|---:|\n| 11 | 1 | 1.5 |\n\n"
        "| lesson | exercise | slip | share | why |\n|---|---|---|---:|---|\n"
        "| * | * | too_rounded | 0.75 | a lost digit |\n"
        "| 11 | * | any | 0.4 | |\n"
        "| 11 | 1 | atan_quadrant | 0.25 | the quadrant is the point |\n"
        "| 11 | 1 | too_rounded | 0.5 | |\n",
    )
    assert weights.points_of("11_inverse_kinematics", 1) == 1.5
    assert weights.points_of("11", 2) is None
    one = weights.rubric("11", 1, 1.5)
    assert one.share == 0.4 and one.share_of("atan_quadrant") == 0.25
    assert one.share_of("too_rounded") == 0.5  # the exercise's row wins
    assert weights.rubric("11", 2, 1).share_of("too_rounded") == 0.75
    assert weights.rubric("12", 1, 1).share == 0.5  # the default


@pytest.mark.parametrize(
    ("row", "words"),
    [
        ("| 11 | 1 | wrong | 0.5 |", "names a slip"),  # "wrong" names no slip
        ("| 11 | 1 | atan_quadrant | 1.5 |", "a share from 0 to 1"),
        ("| eleven | 1 | atan_quadrant | 0.5 |", "a lesson number"),
    ],
)
def test_a_bad_row_is_named_with_its_line(tmp_path, row, words):
    text = f"| lesson | exercise | slip | share |\n|---|---|---|---|\n{row}\n"
    with pytest.raises(InvalidInputError, match=words) as error:
        _table(tmp_path, text)
    assert "weights.md:3" in str(error.value)


def test_the_rubric_command_prints_a_lessons_rubric(capsys):
    assert main(["course", "rubric", "12", "--course", str(COURSE)]) == 0
    out = capsys.readouterr().out
    assert out.startswith("# Rubric of 12_trajectories: 9 points")
    assert "| 4 | 2 | profile | 1 | per number (of several) |" in out
    assert "its typical slips `not_synchronized`" in out
    # every code a check may give is listed: those naming no slip with their share (0)
    trapezoid = out.split("**Exercise 1**")[1].split("\n")[0]
    assert "naming no slip (share 0, only the right numbers count): `distance_not_covered`" in (
        trapezoid
    )
    moves = out.split("**Exercise 5**")[1].split("\n")[0]
    assert "naming no slip" in moves and "`extra`" in moves
    assert main(["course", "rubric", "14", "--course", str(COURSE)]) == 2
    assert "robotconf: error:" in capsys.readouterr().err
