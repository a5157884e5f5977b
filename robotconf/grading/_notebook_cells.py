"""The exercises of a course notebook, found by their cell tags (``course/README.md``).

An exercise is an **answer cell** tagged ``answer`` that assigns one variable
(``answer_1 = None`` in the exercises notebook, the real answer in the solutions) and a
**check cell** tagged ``check`` that uses it. A notebook with per-student variants also
has one cell tagged ``student-id`` that assigns ``student_id = "..."``. Cells are read as
plain nbformat-4 JSON; nothing here depends on the exact text of a check cell.
"""

from __future__ import annotations

import ast
import json
import os
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .._errors import InvalidInputError

__all__ = [
    "ANSWER_TAG",
    "CHECK_TAG",
    "RAISES_TAG",
    "STUDENT_ID_TAG",
    "STUDENT_ID_VARIABLE",
    "Exercise",
    "cell_source",
    "cell_tags",
    "find_exercises",
    "read_notebook",
    "student_id_cell",
]

ANSWER_TAG = "answer"
CHECK_TAG = "check"
RAISES_TAG = "raises-exception"
STUDENT_ID_TAG = "student-id"
STUDENT_ID_VARIABLE = "student_id"

_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


@dataclass(frozen=True)
class Exercise:
    """One exercise: where its answer and check cells are.

    Attributes
    ----------
    number : int
        1-based position among the notebook's exercises.
    variable : str
        The name the answer cell assigns, e.g. ``"answer_1"``.
    answer_index, check_index : int
        Positions of the two cells in the notebook's ``cells``.
    """

    number: int
    variable: str
    answer_index: int
    check_index: int


def read_notebook(path: str | os.PathLike[str]) -> dict[str, Any]:
    """A notebook file as its JSON dictionary (nbformat 4).

    Raises
    ------
    InvalidInputError
        Naming the file when it is not JSON or not an nbformat-4 notebook.
    OSError
        When the file cannot be read.
    """
    path = Path(path)
    allowed = "a Jupyter notebook (nbformat 4 JSON)"
    try:
        notebook = json.loads(path.read_text(encoding="utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as error:
        raise InvalidInputError(str(path), type(error).__name__, allowed, "unreadable:") from None
    if (
        not isinstance(notebook, dict)
        or notebook.get("nbformat") != 4
        or not isinstance(notebook.get("cells"), list)
        or not all(isinstance(cell, dict) for cell in notebook["cells"])
    ):
        raise InvalidInputError(str(path), "not nbformat 4", allowed, "not a notebook:")
    return notebook


def cell_source(cell: dict[str, Any]) -> str:
    """A cell's source as one string (nbformat stores a string or a list of lines).

    >>> cell_source({"source": ["a = 1\\n", "b = 2"]})
    'a = 1\\nb = 2'
    """
    source = cell.get("source", "")
    return "".join(source) if isinstance(source, list) else str(source)


def cell_tags(cell: dict[str, Any]) -> tuple[str, ...]:
    """A cell's tags (``metadata.tags``), as a tuple.

    >>> cell_tags({"metadata": {"tags": ["answer"]}}), cell_tags({})
    (('answer',), ())
    """
    tags = cell.get("metadata", {}).get("tags", ())
    return tuple(tag for tag in tags if isinstance(tag, str))


def _assigned_names(source: str) -> list[str]:
    names = []
    for node in ast.parse(source).body:
        targets = node.targets if isinstance(node, ast.Assign) else []
        if isinstance(node, ast.AnnAssign):
            targets = [node.target]
        names += [target.id for target in targets if isinstance(target, ast.Name)]
    return names


def answer_variable(names: list[str]) -> str | None:
    """The answer an answer cell assigns: its one ``answer_…`` name, else its one name.

    A worked answer may name its steps first (``V = …``, then ``answer_4 = …``).

    >>> answer_variable(["V", "A", "answer_4"]), answer_variable(["q"]), answer_variable([])
    ('answer_4', 'q', None)
    """
    answers = {name for name in names if name.startswith("answer_")}
    if len(answers) == 1:
        return answers.pop()
    return names[0] if not answers and len(set(names)) == 1 else None


def _used_names(source: str) -> set[str]:
    try:
        return {node.id for node in ast.walk(ast.parse(source)) if isinstance(node, ast.Name)}
    except SyntaxError:  # IPython magics: the words are good enough to pair cells
        return set(_WORD.findall(source))


def find_exercises(notebook: dict[str, Any], where: str = "notebook") -> list[Exercise]:
    """The exercises of a notebook, in order: each answer cell with its check cell.

    The check cell of an answer cell is the first later cell tagged ``check`` whose
    code uses the answer's variable (as ``tests/course_support.py`` pairs them).

    Parameters
    ----------
    notebook : dict
        nbformat-4 JSON, as :func:`read_notebook` returns it.
    where : str
        How errors name the notebook.

    Returns
    -------
    list of Exercise

    Raises
    ------
    InvalidInputError
        When an answer cell assigns no single answer variable, has no check cell, or
        a check cell belongs to no answer cell.

    Examples
    --------
    >>> cells = [
    ...     {"cell_type": "code", "metadata": {"tags": ["answer"]}, "source": "answer_1 = 2"},
    ...     {"cell_type": "code", "metadata": {"tags": ["check"]}, "source": "f(answer_1)"},
    ... ]
    >>> find_exercises({"cells": cells})
    [Exercise(number=1, variable='answer_1', answer_index=0, check_index=1)]
    """
    cells = notebook["cells"]
    answers: list[tuple[int, str]] = []
    checks: list[int] = []
    for index, cell in enumerate(cells):
        if cell.get("cell_type") != "code":
            continue
        tags = cell_tags(cell)
        if ANSWER_TAG in tags:
            try:
                names = _assigned_names(cell_source(cell))
            except SyntaxError:
                names = []
            variable = answer_variable(names)
            if variable is None:
                raise InvalidInputError(
                    f"{where} cell {index}",
                    names,
                    "an answer cell that assigns one answer_ variable (helpers may come first)",
                )
            answers.append((index, variable))
        if CHECK_TAG in tags:
            checks.append(index)
    exercises: list[Exercise] = []
    used: set[int] = set()
    for index, variable in answers:
        check = next(
            (
                c
                for c in checks
                if c > index and c not in used and variable in _used_names(cell_source(cells[c]))
            ),
            None,
        )
        if check is None:
            raise InvalidInputError(
                f"{where} cell {index}", variable, "an answer cell followed by its check cell"
            )
        used.add(check)
        exercises.append(Exercise(len(exercises) + 1, variable, index, check))
    orphans = [c for c in checks if c not in used]
    if orphans:
        raise InvalidInputError(
            f"{where} cell {orphans[0]}", "check", "check cells that use an answer variable"
        )
    return exercises


def student_id_cell(notebook: dict[str, Any], where: str = "notebook") -> int | None:
    """Position of the cell tagged ``student-id``, or ``None`` when there is none.

    Raises
    ------
    InvalidInputError
        When several cells carry the tag, or it is on a cell that does not assign
        ``student_id``.

    Examples
    --------
    >>> cell = {"cell_type": "code", "metadata": {"tags": ["student-id"]},
    ...         "source": 'student_id = "s001"'}
    >>> student_id_cell({"cells": [cell]}), student_id_cell({"cells": []})
    (0, None)
    """
    found = [
        index for index, cell in enumerate(notebook["cells"]) if STUDENT_ID_TAG in cell_tags(cell)
    ]
    if not found:
        return None
    if len(found) > 1:
        raise InvalidInputError(f"{where} cells {found}", STUDENT_ID_TAG, "one student-id cell")
    cell = notebook["cells"][found[0]]
    try:
        names = _assigned_names(cell_source(cell)) if cell.get("cell_type") == "code" else []
    except SyntaxError:
        names = []
    if STUDENT_ID_VARIABLE not in names:
        raise InvalidInputError(
            f"{where} cell {found[0]}",
            cell_source(cell)[:80],
            f'a code cell that assigns {STUDENT_ID_VARIABLE} = "..."',
        )
    return found[0]
