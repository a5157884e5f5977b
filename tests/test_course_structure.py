"""Structure of the whole course: folders, solutions, clean notebooks, no network.

Covers every lesson in ``course/`` (whoever wrote it); the conventions are in
``course/README.md``.
"""

from __future__ import annotations

import ast
import re

import pytest

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
