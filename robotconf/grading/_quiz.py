"""Quizzes and exams from the course's kit, written as course folders.

``course/kit/quizzes.md`` lists a short quiz per lesson (a few of its exercises);
``course/kit/exam_bank.md`` the exam's slots, each offering one or more exercises. Both
are Markdown tables a teacher edits (other text is the teacher's):

``| lesson | exercises | minutes | … |``
    A quiz: the lesson by number, its exercises (``1, 4``; ``02.4`` for another
    lesson's), the time it takes.
``| slot | options | points | … |``
    An exam slot: its options as ``lesson.exercise`` (``09.2, 09.3``) and its points.

``robotconf course quiz OUT/`` and ``robotconf course exam OUT/`` write a course folder
(``NN_name/exercises.ipynb``, ``solutions/…``, ``kit/weights.md``) in which every item is
an :class:`~robotconf.teaching.Exam` item: drawn per student, with numbers other than
the homework's, checked by the exercise's own check. The folder goes through
``robotconf course release OUT_NBGRADER/ --course OUT/`` like the course itself (hidden
checks, the rubric, the shortcut flag), or is handed out as it is for practice. The
statements are copied from the course's exercises notebooks.
"""

from __future__ import annotations

import json
import os
import platform
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .._errors import InvalidInputError
from ..teaching.exercises import registered
from ..teaching.reading import ROUNDING_RULE
from ._course import exercises_notebook, find_course, lesson_names
from ._notebook_cells import cell_source, find_exercises, read_notebook
from .rubric._weights import _tables

__all__ = [
    "EXAM_BANK_FILE",
    "QUIZZES_FILE",
    "QuizItem",
    "read_exam_bank",
    "read_quizzes",
    "write_exam_course",
    "write_quiz_course",
]

QUIZZES_FILE = Path("kit") / "quizzes.md"
EXAM_BANK_FILE = Path("kit") / "exam_bank.md"
#: What JupyterLab writes into a notebook when ipykernel starts; a written quiz holding
#: the same opens without the unsaved-changes dot (like course/ and notebooks/).
NOTEBOOK_METADATA: dict[str, Any] = {
    "kernelspec": {"display_name": "Python 3 (ipykernel)", "language": "python", "name": "python3"},
    "language_info": {
        "codemirror_mode": {"name": "ipython", "version": 3},
        "file_extension": ".py",
        "mimetype": "text/x-python",
        "name": "python",
        "nbconvert_exporter": "python",
        "pygments_lexer": "ipython3",
        "version": platform.python_version(),
    },
}
_OPTION = re.compile(r"(\d{1,2})\.(\d{1,2})")


@dataclass(frozen=True)
class QuizItem:
    """One slot of a quiz or exam: its options ``(lesson folder, exercise)`` and points."""

    options: tuple[tuple[str, int], ...]
    points: float | None = None


def _lesson(course: Path, number: str, where: str) -> str:
    names = {int(name[:2]): name for name in lesson_names(course)}
    if not number.isdigit() or int(number) not in names:
        raise InvalidInputError(where, number, "a lesson number of the course")
    return names[int(number)]


def _checked(lesson: str, number: int, where: str) -> tuple[str, int]:
    if number not in {e.number for e in registered(lesson)}:
        raise InvalidInputError(where, f"{lesson} {number}", "an exercise with per-student numbers")
    return lesson, number


def read_quizzes(course: Path) -> dict[str, list[QuizItem]]:
    """The quizzes of ``course/kit/quizzes.md``, by lesson folder (one item per exercise)."""
    path = course / QUIZZES_FILE
    quizzes: dict[str, list[QuizItem]] = {}
    for header, rows in _tables(path.read_text(encoding="utf-8")):
        if header[:3] != ["lesson", "exercises", "minutes"]:
            continue
        for line, cells in rows:
            where = f"{path}:{line}"
            lesson = _lesson(course, cells[0], where)
            parts = [part.strip() for part in cells[1].split(",") if part.strip()]
            items = []
            for part in parts:
                other = _OPTION.fullmatch(part)
                if other:  # another lesson's exercise: "02.4"
                    owner, number = _lesson(course, other.group(1), where), other.group(2)
                elif part.isdigit():
                    owner, number = lesson, part
                else:
                    raise InvalidInputError(where, part, "exercise numbers, e.g. 1, 4 or 02.4")
                items.append(QuizItem((_checked(owner, int(number), where),)))
            if not items:
                raise InvalidInputError(where, cells[1], "exercise numbers, e.g. 1, 4")
            quizzes[lesson] = items
    return quizzes


def read_exam_bank(course: Path) -> list[QuizItem]:
    """The exam's slots of ``course/kit/exam_bank.md``, in order."""
    path = course / EXAM_BANK_FILE
    slots: list[QuizItem] = []
    for header, rows in _tables(path.read_text(encoding="utf-8")):
        if header[:3] != ["slot", "options", "points"]:
            continue
        for line, cells in rows:
            where = f"{path}:{line}"
            found = _OPTION.findall(cells[1])
            if not found:
                raise InvalidInputError(where, cells[1], "options such as 09.2, 09.3")
            options = tuple(
                _checked(_lesson(course, lesson, where), int(number), where)
                for lesson, number in found
            )
            try:
                points = float(cells[2])
            except ValueError:
                raise InvalidInputError(where, cells[2], "points: a number") from None
            slots.append(QuizItem(options, points))
    return slots


def _statement(course: Path, lesson: str, number: int) -> str:
    """The exercise's statement: the Markdown before its answer cell, headings demoted."""
    path = exercises_notebook(course, lesson)
    if path is None:
        raise InvalidInputError(str(course / lesson), None, "a lesson with exercises.ipynb")
    notebook = read_notebook(path)
    exercises = find_exercises(notebook, lesson)
    exercise = next(e for e in exercises if e.number == number)
    previous = [e.check_index for e in exercises if e.number < number]
    start = previous[-1] + 1 if previous else 0
    cells = notebook["cells"][start : exercise.answer_index]
    texts = [cell_source(c) for c in cells if c.get("cell_type") == "markdown"]
    text = "\n\n".join(texts).strip()
    return re.sub(r"^#{1,3} ", "#### ", text, flags=re.M)


def _cell(kind: str, source: str, tags: tuple[str, ...] = (), ident: str = "") -> dict[str, Any]:
    cell: dict[str, Any] = {
        "cell_type": kind,
        "id": ident,
        "metadata": {"tags": list(tags)} if tags else {},
        "source": source,
    }
    if kind == "code":
        cell.update(execution_count=None, outputs=[])
    return cell


def _notebook(
    course: Path, title: str, items: list[QuizItem], draw: str, solutions: bool
) -> dict[str, Any]:
    slots = [[list(option) for option in item.options] for item in items]
    rule = ROUNDING_RULE[0].upper() + ROUNDING_RULE[1:]
    cells = [
        _cell(
            "markdown",
            f"# {title}\n\nAnswer each item by hand (numpy as a calculator is fine), type "
            f"it in and run its check. {rule}. Your items and numbers are your own: type "
            "your student id in the next cell, then run the notebook from the top.",
            ident="title",
        ),
        _cell("code", 'student_id = "demo"  # your student id', ("student-id",), "student-id"),
        _cell(
            "code",
            "import numpy as np\nfrom IPython.display import Markdown, display\n\n"
            "import robotconf as rc\n\n"
            f"SLOTS = {json.dumps(slots)}\n"
            f"exam = rc.Exam(student_id, SLOTS, draw={draw!r})  # your items, from your id",
            ident="setup",
        ),
    ]
    for i, item in enumerate(items, start=1):
        parts = [f"## Item {i}"]
        several = len(item.options) > 1
        for lesson, number in item.options:
            if several:
                parts.append(f"### If your item {i} is lesson {int(lesson[:2])}, exercise {number}")
            parts.append(_statement(course, lesson, number))
        cells.append(_cell("markdown", "\n\n".join(parts), ident=f"item-{i}"))
        cells.append(_cell("code", f"display(Markdown(exam.shows({i})))", ident=f"shows-{i}"))
        answer = f"answer_{i} = exam.answer({i})" if solutions else f"answer_{i} = None"
        cells.append(_cell("code", answer, ("answer",), f"answer-{i}"))
        check = (
            f'assert answer_{i} is not None, "Item {i} is not answered yet: replace None '
            f'with your answer."\nexam.assert_answer({i}, answer_{i})'
        )
        tags = ("check",) if solutions else ("check", "raises-exception")
        cells.append(_cell("code", check, tags, f"check-{i}"))
    return {
        "cells": cells,
        "metadata": json.loads(json.dumps(NOTEBOOK_METADATA)),
        "nbformat": 4,
        "nbformat_minor": 5,
    }


def _write(path: Path, notebook: dict[str, Any]) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(notebook, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")


def _write_assignment(
    out: Path, course: Path, name: str, title: str, items: list[QuizItem], draw: str
) -> None:
    for solutions, folder in ((False, out / name), (True, out / "solutions" / name)):
        _write(folder / "exercises.ipynb", _notebook(course, title, items, draw, solutions))


def _weights(out: Path, rows: list[tuple[str, int, float]]) -> None:
    lines = [
        "# Weights",
        "",
        "Written by robotconf course quiz/exam; edit before a release.",
        "",
        "| lesson | exercise | points |",
        "|---|---|---:|",
        *(f"| {name[:2]} | {k} | {points:g} |" for name, k, points in rows),
        "",
    ]
    path = out / "kit" / "weights.md"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines), encoding="utf-8")


def _points(course: Path, lesson: str, number: int) -> float:
    from .rubric._weights import find_weights

    weights = find_weights(course)
    found = weights.points_of(lesson, number) if weights else None
    return 1.0 if found is None else found


def write_quiz_course(
    out: str | os.PathLike[str],
    course: str | os.PathLike[str] | None = None,
    lessons: list[str] | None = None,
    draw: str = "quiz",
) -> list[str]:
    """Write one quiz per lesson of course/kit/quizzes.md as a course folder in ``out``.

    Returns the quizzes' folder names (``"12_quiz_trajectories"``).
    """
    folder = find_course(course)
    quizzes = read_quizzes(folder)
    if lessons:
        wanted = {int(str(n)[:2]) for n in lessons}
        quizzes = {k: v for k, v in quizzes.items() if int(k[:2]) in wanted}
    target = Path(out)
    names, weights = [], []
    for lesson, items in sorted(quizzes.items()):
        name = f"{lesson[:2]}_quiz_{lesson[3:]}"
        title = f"Quiz — lesson {int(lesson[:2])}: {lesson[3:].replace('_', ' ')}"
        _write_assignment(target, folder, name, title, items, f"{draw}-{lesson[:2]}")
        names.append(name)
        for i, item in enumerate(items, start=1):
            weights.append((name, i, _points(folder, *item.options[0])))
    _weights(target, weights)
    return names


def write_exam_course(
    out: str | os.PathLike[str],
    course: str | os.PathLike[str] | None = None,
    draw: str = "exam",
    name: str = "90_exam",
) -> str:
    """Write the exam of course/kit/exam_bank.md as a course folder in ``out``."""
    if not re.fullmatch(r"\d\d_[A-Za-z0-9_]+", name):
        raise InvalidInputError("--name", name, "a folder name such as 90_exam")
    folder = find_course(course)
    slots = read_exam_bank(folder)
    if not slots:
        raise InvalidInputError(str(folder / EXAM_BANK_FILE), None, "a table of slots")
    target = Path(out)
    _write_assignment(target, folder, name, f"Exam ({draw})", slots, draw)
    _weights(target, [(name, i, s.points or 1.0) for i, s in enumerate(slots, start=1)])
    return name
