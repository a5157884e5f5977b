"""Run a solutions notebook in a Jupyter kernel and read what each check compared against.

Needs nbclient and ipykernel (the ``lab`` extra), imported when a notebook runs. Every
cell has a time limit; the notebook runs in its own folder, like ``make test`` runs it.
"""

from __future__ import annotations

import ast
import copy
import json
import os
import re
import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .._errors import InvalidInputError
from ._key_run import KEY_MARKER
from ._notebook_cells import (
    RAISES_TAG,
    STUDENT_ID_VARIABLE,
    Exercise,
    cell_source,
    cell_tags,
    find_exercises,
    read_notebook,
    student_id_cell,
)

__all__ = [
    "CELL_TIMEOUT",
    "ExerciseRun",
    "SolutionsRun",
    "check_student_id",
    "run_solutions",
    "with_student_id",
]

#: Seconds each cell may run before the run is stopped.
CELL_TIMEOUT = 120
#: Longest student id (characters), as :class:`robotconf.teaching.Variant` takes them.
MAX_STUDENT_ID = 64
_ANSI = re.compile(r"\x1b\[[0-9;]*[A-Za-z]")
_LAB_EXTRA = "pip install 'robotconf[lab]' (nbclient and ipykernel run the notebooks)"


@dataclass(frozen=True)
class ExerciseRun:
    """What running one exercise of a solutions notebook showed.

    Attributes
    ----------
    exercise : Exercise
    expected : dict or None
        The reference, as :func:`~robotconf.grading._key_run.describe_reference` gives it.
    expected_from : str or None
        ``"check"`` (the checker's reference), ``"variable"`` (``expected_<k>``),
        ``"answer"`` (the solution itself) or ``None``.
    solution : dict or None
        The solution's answer, as text and/or numbers.
    checks : int
        Checker calls made by the check cell.
    error : str
        The check cell's error (``""`` when it passed).
    """

    exercise: Exercise
    expected: dict[str, Any] | None
    expected_from: str | None
    solution: dict[str, Any] | None
    checks: int
    error: str

    @property
    def kind(self) -> str | None:
        """The checker's kind (``"matrix"``, ``"vector"``, ...), when a check showed it."""
        if self.expected is None or self.expected_from != "check":
            return None
        return str(self.expected["kind"])

    @property
    def shape(self) -> tuple[int, int] | None:
        """The expected value's shape, when a check showed it."""
        if self.expected is None or self.expected_from == "answer":
            return None
        rows, cols = self.expected["shape"]
        return int(rows), int(cols)

    @property
    def symbolic(self) -> bool:
        """Whether the check compared against a formula (in q1, l1, ...)."""
        return bool(self.kind == "matrix" and self.expected and self.expected["symbols"])


@dataclass(frozen=True)
class SolutionsRun:
    """One run of a solutions notebook.

    Attributes
    ----------
    path : Path
    exercises : list of ExerciseRun
    student_id : str or None
        The id the notebook ran with (given, or its own); ``None`` without a
        ``student-id`` cell.
    """

    path: Path
    exercises: list[ExerciseRun]
    student_id: str | None


def check_student_id(value: Any) -> str:
    """A student id as given on the command line, checked (spaces around it removed).

    The id only ever enters a notebook as a Python string literal (``repr``), so any
    printable text is safe; the limits are those of per-student variants.

    Raises
    ------
    InvalidInputError
        Unless it is printable text of 1 to 64 characters.

    Examples
    --------
    >>> check_student_id(" jane.doe@uni ")
    'jane.doe@uni'
    >>> check_student_id("a" * 65)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: --student: invalid value 'aaa...'; allowed: printable text ...
    """
    allowed = f"printable text of 1 to {MAX_STUDENT_ID} characters (e.g. s1234567)"
    if not isinstance(value, str):
        raise InvalidInputError("--student", value, allowed)
    text = value.strip()
    if not text or len(text) > MAX_STUDENT_ID or not text.isprintable():
        raise InvalidInputError("--student", value, allowed)
    return text


def _id_assignments(source: str) -> list[ast.Assign]:
    return [
        node
        for node in ast.parse(source).body
        if isinstance(node, ast.Assign)
        and any(isinstance(t, ast.Name) and t.id == STUDENT_ID_VARIABLE for t in node.targets)
    ]


def with_student_id(source: str, student_id: str) -> str:
    """A ``student-id`` cell's code with ``student_id = ...`` set to another id.

    Only the assignment lines change; the rest of the cell stays.

    Examples
    --------
    >>> print(with_student_id('# your id\\nstudent_id = "s001"  # as on your card', "s002"))
    # your id
    student_id = 's002'
    """
    lines = source.split("\n")
    for node in reversed(_id_assignments(source)):
        end = node.end_lineno or node.lineno
        lines[node.lineno - 1 : end] = [f"{STUDENT_ID_VARIABLE} = {check_student_id(student_id)!r}"]
    return "\n".join(lines)


def _own_student_id(source: str) -> str | None:
    for node in _id_assignments(source):
        try:
            value = ast.literal_eval(node.value)
        except ValueError:
            continue
        if isinstance(value, str):
            return value
    return None


def _error_text(outputs: list[dict[str, Any]]) -> str:
    for output in outputs:
        if output.get("output_type") == "error":
            text = f"{output.get('ename', '')}: {output.get('evalue', '')}"
            return " ".join(_ANSI.sub("", text).split())
    return ""


def _code_cell(source: str, cell_id: str) -> dict[str, Any]:
    return {
        "cell_type": "code",
        "execution_count": None,
        "id": cell_id,
        "metadata": {},
        "outputs": [],
        "source": source,
    }


def _execute(notebook: dict[str, Any], path: Path, timeout: int) -> dict[str, Any]:
    try:
        import nbformat
        from jupyter_client.kernelspec import NoSuchKernel
        from nbclient import NotebookClient
        from nbclient.exceptions import CellTimeoutError, DeadKernelError
    except ImportError as error:
        raise InvalidInputError(
            "notebooks", str(error.name or error), _LAB_EXTRA, "cannot run without"
        ) from None
    node = nbformat.reads(json.dumps(notebook), as_version=4)
    kernel = notebook.get("metadata", {}).get("kernelspec", {}).get("name") or "python3"
    client = NotebookClient(
        node,
        timeout=timeout,
        kernel_name=kernel,
        allow_errors=True,
        resources={"metadata": {"path": str(path.parent)}},
        extra_arguments=["--HistoryManager.hist_file=:memory:"],
    )
    env = {**os.environ, "MPLBACKEND": os.environ.get("MPLBACKEND", "Agg")}
    try:
        # The kernel's own start-up chatter would reach the terminal: it says nothing here.
        client.execute(env=env, stderr=subprocess.DEVNULL)
    except NoSuchKernel:
        raise InvalidInputError("kernel", kernel, _LAB_EXTRA, "no such Jupyter kernel:") from None
    except CellTimeoutError:
        raise InvalidInputError(
            str(path),
            f"{timeout} s",
            "cells that finish within --timeout SECONDS",
            "a cell ran longer than",
        ) from None
    except DeadKernelError:
        died = InvalidInputError(str(path), "its kernel", "a notebook that runs", "stopped:")
        raise died from None
    return json.loads(json.dumps(node))  # type: ignore[no-any-return]


def run_solutions(
    path: str | os.PathLike[str], *, student_id: str | None = None, timeout: int = CELL_TIMEOUT
) -> SolutionsRun:
    """Run a solutions notebook and read, for every exercise, what its check compared to.

    Parameters
    ----------
    path : path of a solutions ``.ipynb``
    student_id : str, optional
        Runs the notebook with its ``student-id`` cell set to this id (a notebook
        without such a cell ignores it).
    timeout : int
        Seconds per cell.

    Returns
    -------
    SolutionsRun

    Raises
    ------
    InvalidInputError
        A malformed notebook, a bad student id, a cell outside the checks that fails
        (naming it), a run that does not reach its end, or missing nbclient/ipykernel.
    """
    path = Path(path)
    where = str(path)
    notebook = read_notebook(path)
    exercises = find_exercises(notebook, where)
    cells = copy.deepcopy(notebook["cells"])
    id_index = student_id_cell(notebook, where)
    used_id = None
    if id_index is not None:
        source = cell_source(cells[id_index])
        if student_id is not None:
            source = with_student_id(source, student_id)
            cells[id_index]["source"] = source
        used_id = _own_student_id(source)
    checks = {e.check_index: e for e in exercises}
    runnable: list[dict[str, Any]] = [
        _code_cell(
            "from robotconf.grading._key_run import KeyRun as _RobotconfKeyRun\n"
            "_robotconf_key = _RobotconfKeyRun()",
            "robotconf-key-start",
        )
    ]
    positions: dict[int, int] = {}
    for index, cell in enumerate(cells):
        if cell.get("cell_type") == "code":
            cell["outputs"], cell["execution_count"] = [], None
        if index in checks:
            label = f"_robotconf_key.label = {checks[index].variable!r}"
            runnable.append(_code_cell(label, f"robotconf-key-{index}"))
        positions[index] = len(runnable)
        runnable.append(cell)
        if index in checks:
            runnable.append(_code_cell("_robotconf_key.label = None", f"robotconf-key-{index}-end"))
    variables = [e.variable for e in exercises]
    dump = f"_robotconf_key.dump(globals(), {variables!r})"
    runnable.append(_code_cell(dump, "robotconf-key-end"))
    ran = _execute({**notebook, "cells": runnable}, path, timeout)["cells"]
    for index, position in positions.items():
        error = _error_text(ran[position].get("outputs", []))
        if error and index not in checks and RAISES_TAG not in cell_tags(cells[index]):
            raise InvalidInputError(
                f"{where} cell {index}", error, "solutions whose cells run", "fails:"
            )
    record = None
    for output in ran[-1].get("outputs", []):
        for line in str(output.get("text", "")).splitlines():
            if line.startswith(KEY_MARKER):
                record = json.loads(line[len(KEY_MARKER) :])
    if record is None:
        problem = _error_text(ran[-1].get("outputs", [])) or _error_text(ran[0].get("outputs", []))
        raise InvalidInputError(where, problem or "no record", "a notebook that runs to its end")
    runs = [
        ExerciseRun(
            exercise,
            record[exercise.variable]["expected"],
            record[exercise.variable]["expected_from"],
            record[exercise.variable]["solution"],
            int(record[exercise.variable]["checks"]),
            _error_text(ran[positions[exercise.check_index]].get("outputs", [])),
        )
        for exercise in exercises
    ]
    return SolutionsRun(path, runs, used_id)
