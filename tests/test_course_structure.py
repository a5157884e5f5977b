"""Structure of the whole course: folders, solutions, clean notebooks, no network.

Covers every lesson in ``course/`` (whoever wrote it); the conventions are in
``course/README.md``.
"""

from __future__ import annotations

import ast
import contextlib
import io
import re

import numpy as np
import pytest

from robotconf.grading import robotconf_calls
from robotconf.teaching.exercises import registered
from robotconf.teaching.reading._tolerance import ROUNDING_RULE

from .course_support import (
    ANSWER_TAG,
    CHECK_TAG,
    COURSE,
    RAISES_TAG,
    exercise_cells,
    lesson_dirs,
    read_notebook,
    solutions_path,
)

LESSONS = lesson_dirs()
NOTEBOOKS = sorted(p for p in COURSE.rglob("*.ipynb") if ".ipynb_checkpoints" not in p.parts)
EXERCISE_NOTEBOOKS = [p for p in NOTEBOOKS if p.name == "exercises.ipynb"]
NETWORK_MODULES = {
    "aiohttp",
    "ftplib",
    "http",
    "httpx",
    "requests",
    "smtplib",
    "socket",
    "urllib",
    "urllib3",
    "webbrowser",
}
URL = re.compile(r"https?://", re.IGNORECASE)


def _id(path) -> str:
    return str(path.relative_to(COURSE))


def test_course_has_a_readme_and_lessons():
    assert (COURSE / "README.md").is_file()
    assert len(LESSONS) >= 4, [p.name for p in LESSONS]


@pytest.mark.parametrize("lesson", LESSONS, ids=_id)
def test_lesson_folder_has_lesson_exercises_and_solutions(lesson):
    assert (lesson / "lesson.ipynb").is_file()
    assert (lesson / "exercises.ipynb").is_file()
    assert solutions_path(lesson / "exercises.ipynb").is_file()


def test_every_solutions_folder_belongs_to_a_lesson():
    names = {p.name for p in LESSONS}
    solutions = COURSE / "solutions"
    extra = [p.name for p in solutions.iterdir() if p.is_dir()] if solutions.is_dir() else []
    assert set(extra) <= names, sorted(set(extra) - names)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=_id)
def test_notebook_is_clean_v4_python3(path):
    notebook = read_notebook(path)
    assert notebook.nbformat == 4
    assert notebook.metadata.get("kernelspec", {}).get("name") == "python3"
    for index, cell in enumerate(notebook.cells):
        if cell.cell_type == "code":
            assert cell.get("outputs") == [], f"cell {index} has outputs"
            assert cell.get("execution_count") is None, f"cell {index} has an execution count"


def _code(source: str) -> str:
    """Cell code without IPython magics and shell lines, which ast cannot parse."""
    return "\n".join(
        "" if line.lstrip().startswith(("%", "!")) else line for line in source.splitlines()
    )


@pytest.mark.parametrize("path", NOTEBOOKS, ids=_id)
def test_notebook_needs_no_network(path):
    for index, cell in enumerate(read_notebook(path).cells):
        if cell.cell_type != "code":
            continue
        assert not URL.search(cell.source), f"cell {index} contains a URL"
        for node in ast.walk(ast.parse(_code(cell.source))):
            if isinstance(node, ast.Import):
                modules = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                modules = [node.module or ""]
            else:
                continue
            for module in modules:
                assert module.split(".")[0] not in NETWORK_MODULES, f"cell {index}: {module}"


@pytest.mark.parametrize("lesson", LESSONS, ids=_id)
def test_exercise_cells_follow_the_conventions(lesson):
    exercises = exercise_cells(lesson / "exercises.ipynb")
    solutions = exercise_cells(solutions_path(lesson / "exercises.ipynb"))
    assert exercises, "an exercises notebook needs at least one answer/check pair"
    assert [e.variable for e in exercises] == [s.variable for s in solutions]
    for exercise in exercises:
        assert set(exercise.check_tags) >= {CHECK_TAG, RAISES_TAG}, exercise.variable
        placeholder = rf"{exercise.variable}\s*=\s*None\b.*"
        assert re.fullmatch(placeholder, exercise.answer_source.strip(), re.S), exercise.variable
    for solution in solutions:
        assert RAISES_TAG not in solution.check_tags, solution.variable
        assert ANSWER_TAG not in solution.check_tags


def _rule_sentence() -> str:
    rule = ROUNDING_RULE
    return rule[0].upper() + rule[1:]


@pytest.mark.parametrize("path", EXERCISE_NOTEBOOKS, ids=_id)
def test_the_how_to_cell_states_the_rounding_rule(path):
    """Said once, the same words everywhere, before the first exercise."""
    cells = read_notebook(path).cells
    first_answer = next(i for i, c in enumerate(cells) if ANSWER_TAG in c.metadata.get("tags", []))
    stated = [
        i
        for i, cell in enumerate(cells)
        if cell.cell_type == "markdown" and _rule_sentence() in " ".join(cell.source.split())
    ]
    assert stated and stated[0] < first_answer, path


def _setup_namespace(path) -> dict:
    """The notebook's names after its setup cells (not the answers, checks or practice)."""
    namespace: dict = {}
    skip = {ANSWER_TAG, CHECK_TAG, "practice"}
    # The setup cells set numpy's print options; they are put back after the run.
    with np.printoptions(), contextlib.redirect_stdout(io.StringIO()):
        for cell in read_notebook(path).cells:
            if cell.cell_type == "code" and not skip & set(cell.metadata.get("tags", [])):
                exec(compile(_code(cell.source), str(path), "exec"), namespace)  # our notebook
    return namespace


@pytest.mark.parametrize("lesson", LESSONS, ids=_id)
def test_the_solutions_work_every_answer_by_hand(lesson):
    """No answer of the key asks robotconf for itself: a graded copy would flag it."""
    path = solutions_path(lesson / "exercises.ipynb")
    namespace = _setup_namespace(path)
    for exercise in exercise_cells(path):
        calls = robotconf_calls(exercise.answer_source, namespace)
        assert not calls, (exercise.variable, calls)


@pytest.mark.parametrize("lesson", LESSONS, ids=_id)
def test_every_exercise_with_drawn_numbers_is_checked_by_its_assignment(lesson):
    """The notebook checks exercise k with ``task.assert_answer(k, answer_k)``."""
    numbers = [e.number for e in registered(lesson.name)]
    for path in (lesson / "exercises.ipynb", solutions_path(lesson / "exercises.ipynb")):
        checks = {e.variable: e.check_source for e in exercise_cells(path)}
        for k in numbers:
            assert f"task.assert_answer({k}, answer_{k})" in checks[f"answer_{k}"], (path, k)


@pytest.mark.parametrize("lesson", LESSONS, ids=_id)
def test_practice_cells_are_no_exercise(lesson):
    """Cells tagged ``practice`` (comparisons with robotconf) leave graded copies."""
    for path in (lesson / "exercises.ipynb", solutions_path(lesson / "exercises.ipynb")):
        for cell in read_notebook(path).cells:
            tags = set(cell.metadata.get("tags", []))
            if "practice" in tags:
                assert not tags & {ANSWER_TAG, CHECK_TAG, "student-id"}, (path, tags)
