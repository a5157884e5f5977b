"""Helpers for testing the course notebooks: find exercises, run them with other answers.

The notebook conventions (see ``course/README.md``): an exercise is a markdown cell with
the task, an **answer cell** tagged ``answer`` that assigns one variable
(``answer_1 = None`` in the exercises notebook), and a **check cell** tagged ``check``
that uses that variable (``rc.assert_matrix(answer_1, ...)``). In an exercises notebook
the check cell is also tagged ``raises-exception`` so that the blank notebook executes
under nbmake.

Interface (kept stable for every lesson's tests):

- :data:`COURSE`, :data:`SOLUTIONS` — the folders;
- :func:`lesson_dirs` — ``course/NN_name`` folders, sorted;
- :func:`solutions_path` — the solutions notebook of an exercises notebook;
- :func:`read_notebook` — an ``nbformat`` v4 notebook;
- :func:`exercise_cells` — the exercises of a notebook as :class:`Exercise` records;
- :func:`run_with_answers` — execute a notebook once with some answer cells replaced and
  return each check cell's error text (``""`` when it passed).
"""

from __future__ import annotations

import ast
import os
import re
from dataclasses import dataclass
from pathlib import Path

import nbformat

from robotconf.grading._notebook_cells import answer_variable

__all__ = [
    "COURSE",
    "SOLUTIONS",
    "Exercise",
    "exercise_cells",
    "lesson_dirs",
    "read_notebook",
    "run_with_answers",
    "solutions_path",
]

COURSE = Path(__file__).resolve().parents[1] / "course"
SOLUTIONS = COURSE / "solutions"

ANSWER_TAG = "answer"
CHECK_TAG = "check"
RAISES_TAG = "raises-exception"

_ANSI = re.compile(r"\x1b\[[0-9;]*[A-Za-z]")
_LESSON = re.compile(r"^\d\d_[a-z0-9_]+$")


@dataclass(frozen=True)
class Exercise:
    """One exercise of a notebook: its answer cell and its check cell.

    Attributes
    ----------
    variable : str
        The name the answer cell assigns, e.g. ``"answer_1"``.
    answer_index, check_index : int
        Positions of the two cells in ``notebook.cells``.
    answer_source, check_source : str
        Their code.
    check_tags : tuple of str
        The check cell's tags (``("check", "raises-exception")`` in an exercises notebook).
    """

    variable: str
    answer_index: int
    check_index: int
    answer_source: str
    check_source: str
    check_tags: tuple[str, ...]


def lesson_dirs() -> list[Path]:
    """The lesson folders ``course/NN_name`` (not ``solutions``), sorted by number."""
    if not COURSE.is_dir():
        return []
    return sorted(p for p in COURSE.iterdir() if p.is_dir() and _LESSON.match(p.name))


def solutions_path(exercises: str | os.PathLike) -> Path:
    """``course/NN_x/exercises.ipynb`` → ``course/solutions/NN_x/exercises.ipynb``."""
    path = Path(exercises).resolve()
    return SOLUTIONS / path.parent.name / path.name


def read_notebook(path: str | os.PathLike) -> nbformat.NotebookNode:
    """Read a notebook as nbformat v4."""
    return nbformat.read(str(path), as_version=4)


def _tags(cell: nbformat.NotebookNode) -> tuple[str, ...]:
    return tuple(cell.get("metadata", {}).get("tags", ()))


def _assigned_name(source: str, where: str) -> str:
    names = [
        target.id
        for node in ast.parse(source).body
        if isinstance(node, (ast.Assign, ast.AnnAssign))
        for target in (node.targets if isinstance(node, ast.Assign) else [node.target])
        if isinstance(target, ast.Name)
    ]
    variable = answer_variable(names)
    if variable is None:
        raise ValueError(f"{where}: an answer cell must assign one answer_ variable, got {names}")
    return variable


def _used_names(source: str) -> set[str]:
    return {node.id for node in ast.walk(ast.parse(source)) if isinstance(node, ast.Name)}


def exercise_cells(path: str | os.PathLike) -> list[Exercise]:
    """The exercises of a notebook, in order, each an answer cell paired with its check cell.

    An answer cell (tag ``answer``) assigns one ``answer_…`` variable (its worked steps may
    name helpers first); its check cell is the first later cell tagged ``check`` whose code
    uses that variable.

    Raises
    ------
    ValueError
        When an answer cell assigns several variables or has no check cell, or a check
        cell belongs to no answer cell.
    """
    notebook = read_notebook(path)
    answers: list[tuple[int, str, str]] = []
    checks: list[tuple[int, str, tuple[str, ...]]] = []
    for index, cell in enumerate(notebook.cells):
        tags = _tags(cell)
        if cell.cell_type != "code":
            continue
        if ANSWER_TAG in tags:
            where = f"{path} cell {index}"
            answers.append((index, _assigned_name(cell.source, where), cell.source))
        if CHECK_TAG in tags:
            checks.append((index, cell.source, tags))
    exercises, used = [], set()
    for index, variable, source in answers:
        for check_index, check_source, tags in checks:
            free = check_index > index and check_index not in used
            if free and variable in _used_names(check_source):
                used.add(check_index)
                exercises.append(Exercise(variable, index, check_index, source, check_source, tags))
                break
        else:
            raise ValueError(f"{path}: answer cell {index} ({variable}) has no check cell")
    orphans = [i for i, _, _ in checks if i not in used]
    if orphans:
        raise ValueError(f"{path}: check cells {orphans} use no answer variable")
    return exercises


def _error_text(outputs: list) -> str:
    parts = []
    for output in outputs:
        if output.get("output_type") == "error":
            parts.append(f"{output.get('ename', '')}: {output.get('evalue', '')}")
            parts.extend(output.get("traceback", []))
    return _ANSI.sub("", "\n".join(parts))


def run_with_answers(
    path: str | os.PathLike, answers: dict[str, str] | None = None, *, timeout: int = 120
) -> dict[str, str]:
    """Execute a notebook once with some answer cells replaced; report every check cell.

    Parameters
    ----------
    path : path of an ``.ipynb``
    answers : dict of str to str
        ``{variable: code of the whole answer cell}``, e.g.
        ``{"answer_1": "answer_1 = [[1, 0], [0, 1]]"}``; exercises not named keep the
        notebook's own answer cell.
    timeout : int
        Seconds per cell.

    Returns
    -------
    dict of str to str
        ``{variable: error text}`` for every exercise: ``""`` when its check cell passed,
        else the exception name, message and traceback (ANSI colours removed). Execution
        goes on after errors (``allow_errors=True``), in the notebook's folder, with the
        ``python3`` kernel and ``ROBOTCONF_FAST=1``, ``MPLBACKEND=Agg``.

    Raises
    ------
    KeyError
        When ``answers`` names a variable that no answer cell assigns.
    """
    from nbclient import NotebookClient

    path = Path(path)
    answers = dict(answers or {})
    exercises = exercise_cells(path)
    unknown = set(answers) - {e.variable for e in exercises}
    if unknown:
        raise KeyError(f"{path}: no answer cell assigns {sorted(unknown)}")
    notebook = read_notebook(path)
    for exercise in exercises:
        if exercise.variable in answers:
            notebook.cells[exercise.answer_index].source = answers[exercise.variable]
    os.environ.setdefault("ROBOTCONF_FAST", "1")
    os.environ.setdefault("MPLBACKEND", "Agg")
    client = NotebookClient(
        notebook,
        timeout=timeout,
        kernel_name="python3",
        allow_errors=True,
        resources={"metadata": {"path": str(path.parent)}},
    )
    client.execute()
    return {
        e.variable: _error_text(notebook.cells[e.check_index].get("outputs", [])) for e in exercises
    }
