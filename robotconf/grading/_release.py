"""``robotconf course release``: the course as an nbgrader source tree of graded copies.

One assignment per lesson, ``OUT/source/<lesson>/<lesson>.ipynb``, built from the
lesson's solutions notebook: every answer cell becomes an autograded answer (the
solution between nbgrader's markers, the students' ``answer_k = None`` line kept),
every check cell an autograder test worth the exercise's points by the course's
weighting table (``course/kit/weights.md``), graded by the rubric and hidden whole from
the students' copy, so no expected value is in it; cells tagged ``practice`` (compare
with ``rc.…``) are left out; every other cell is read-only; the ``student-id`` cell
stays editable. A cell after the title tells the student how the copy is graded. The
solutions notebook runs first: its checks show each expected value's kind and shape
(for the default points) and must all pass. The markdown
text comes from the students' exercises notebook when the two line up cell by cell (the
solutions' titles say "(solutions)"). ``OUT/source`` is the instructor's tree;
``nbgrader generate_assignment`` writes the students' copies, without solutions.
"""

from __future__ import annotations

import ast
import copy
import json
import os
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .._errors import InvalidInputError
from ._course import exercises_notebook, find_course, select_lessons, solutions_notebook
from ._execute import CELL_TIMEOUT, SolutionsRun, run_solutions
from ._nbgrader_cells import answer_source, autograder_source, grade_id, nbgrader_metadata
from ._nbgrader_files import config_text, readme_text, write_if_ours
from ._notebook_cells import (
    RAISES_TAG,
    cell_source,
    cell_tags,
    find_exercises,
    read_notebook,
    student_id_cell,
)
from .rubric._points import points_for
from .rubric._rubric import Rubric
from .rubric._weights import Weights, find_weights

__all__ = ["Release", "ReleasedExercise", "release_course", "source_notebook"]

_COURSE_ID = re.compile(r"[A-Za-z0-9][A-Za-z0-9_.-]{0,63}")


@dataclass(frozen=True)
class ReleasedExercise:
    """One exercise as released.

    Attributes
    ----------
    lesson : str
    number : int
    variable : str
    points : int
    kind : str or None
        The checker's kind (``"matrix"``, ``"vector"``, ...), ``None`` when the check
        called no checker.
    partial : bool
        Whether the test cell grades a wrong answer by the rubric (its check could be
        wrapped; else right or wrong, whole points).
    hidden : bool
        Whether it rechecks a symbolic answer at other values of its symbols.
    rubric : Rubric
        How the exercise is graded (points, shares of named slips).
    """

    lesson: str
    number: int
    variable: str
    points: float
    kind: str | None
    partial: bool
    hidden: bool
    rubric: Rubric


@dataclass(frozen=True)
class Release:
    """What ``release_course`` wrote.

    Attributes
    ----------
    out : Path
    assignments : list of str
        The lessons released by this call.
    exercises : list of ReleasedExercise
    notes : list of str
        Things the instructor should know (a file left alone, text taken from the
        solutions).
    """

    out: Path
    assignments: list[str]
    exercises: list[ReleasedExercise]
    notes: list[str]

    def points(self, lesson: str) -> float:
        """Total points of one released lesson."""
        return sum(e.points for e in self.exercises if e.lesson == lesson)


def _aligned(solutions: dict[str, Any], exercises: dict[str, Any] | None) -> bool:
    """Whether the exercises notebook has the solutions' cells, one for one."""
    if exercises is None or len(exercises["cells"]) != len(solutions["cells"]):
        return False
    return all(
        a.get("cell_type") == b.get("cell_type")
        and set(cell_tags(a)) - {RAISES_TAG} == set(cell_tags(b)) - {RAISES_TAG}
        for a, b in zip(solutions["cells"], exercises["cells"], strict=True)
    )


def _stubs(exercises: dict[str, Any] | None, where: str) -> dict[str, str]:
    """The students' answer line of each variable, ``answer_k = None  # your ...``."""
    if exercises is None:
        return {}
    stubs = {}
    for exercise in find_exercises(exercises, where):
        source = cell_source(exercises["cells"][exercise.answer_index]).strip("\n")
        stubs[exercise.variable] = source
    return stubs


def _stub(variable: str, stubs: dict[str, str]) -> str:
    source = stubs.get(variable, "")
    try:
        body = ast.parse(source).body
    except SyntaxError:
        body = []
    if (
        len(body) == 1
        and isinstance(body[0], ast.Assign)
        and isinstance(body[0].value, ast.Constant)
        and body[0].value.value is None
    ):
        return source
    return f"{variable} = None  # your answer"


#: Cells only the practice copies keep ("compare with rc.…"): a graded copy leaves them out.
PRACTICE_TAG = "practice"

_GRADED_INTRO = """### How this copy is graded

Answer each exercise in its answer cell, as in class. The checks are not in this copy:
they run when your notebook is graded, and the feedback shows what they said.

- **Points:** {points}.
- **Rounding:** numbers with 3 significant digits are accepted (unless an exercise says
  otherwise); fewer digits lose points.
- **Credit for the method:** a wrong answer with one recognised slip of a right method
  (a sign, atan for atan2, a unit, a forgotten synchronization, …) earns a share of the
  points, usually half; an answer of several numbers earns the share of its numbers
  that are right, at most three quarters. A blank answer earns nothing.
- **Your own work:** an answer cell that calls robotconf (`rc.…`, or a method of a
  robot, program or result) is not graded automatically: it earns no points until your
  teacher has looked at it. Derive the answer yourself; numpy as a calculator is fine.
"""


def _intro_cell(released: list[ReleasedExercise]) -> dict[str, Any]:
    listed = ", ".join(f"exercise {e.number}: {e.points:g}" for e in released)
    total = sum(e.points for e in released)
    text = _GRADED_INTRO.format(points=f"{total:g} in all ({listed})")
    metadata = {"nbgrader": nbgrader_metadata("graded_copy_intro", locked=True)}
    return {
        "cell_type": "markdown",
        "id": "graded-copy-intro",
        "metadata": metadata,
        "source": text,
    }


def _rubric(
    weights: Weights | None, lesson: str, number: int, kind: str | None, shape: Any
) -> Rubric:
    """The rubric of one exercise: the table's points and shares, else the defaults."""
    points = weights.points_of(lesson, number) if weights is not None else None
    if points is None:
        points = points_for(kind, shape)
    if weights is None:
        return Rubric(points)
    return weights.rubric(lesson, number, points)


def source_notebook(
    solutions: dict[str, Any],
    run: SolutionsRun,
    lesson: str,
    exercises: dict[str, Any] | None = None,
    weights: Weights | None = None,
) -> tuple[dict[str, Any], list[ReleasedExercise]]:
    """The nbgrader source notebook of one lesson.

    Parameters
    ----------
    solutions : dict
        The solutions notebook (nbformat-4 JSON).
    run : SolutionsRun
        Its run (:func:`~robotconf.grading.run_solutions`): kinds and shapes.
    lesson : str
        The lesson's name (grade ids and messages).
    exercises : dict, optional
        The students' exercises notebook: its answer lines become the stubs, and its
        markdown the text when the two notebooks line up.
    weights : Weights, optional
        The course's weighting table (points and shares); default one point an
        exercise, two for a 4×4 matrix, half the points for a named slip.

    Returns
    -------
    (dict, list of ReleasedExercise)

    See Also
    --------
    release_course : runs the solutions and writes what this builds (with an example).
    """
    where = f"{lesson} solutions"
    notebook = copy.deepcopy(solutions)
    cells = notebook["cells"]
    found = find_exercises(solutions, where)
    stubs = _stubs(exercises, f"{lesson} exercises")
    aligned = _aligned(solutions, exercises)
    id_cell = student_id_cell(solutions, where)
    runs = {r.exercise.variable: r for r in run.exercises}
    answers = {e.answer_index: e for e in found}
    checks = {e.check_index: e for e in found}
    released: list[ReleasedExercise] = []
    for index, cell in enumerate(cells):
        metadata = cell.setdefault("metadata", {})
        tags = list(cell_tags(cell))
        if (
            aligned
            and exercises is not None
            and (cell.get("cell_type") == "markdown" or index == id_cell)
        ):
            cell["source"] = cell_source(exercises["cells"][index])
        if cell.get("cell_type") == "code":
            cell["outputs"], cell["execution_count"] = [], None
        if index in answers:
            exercise = answers[index]
            solution = cell_source(cell)
            cell["source"] = answer_source(
                _stub(exercise.variable, stubs), solution, f"{where} cell {index}"
            )
            metadata["nbgrader"] = nbgrader_metadata(grade_id(exercise.variable), solution=True)
        elif index in checks:
            exercise = checks[index]
            ran = runs[exercise.variable]
            rubric = _rubric(weights, lesson, exercise.number, ran.kind, ran.shape)
            points = rubric.points
            source, partial = autograder_source(
                cell_source(cell),
                rubric,
                variable=exercise.variable,
                recheck=ran.symbolic,
                where=f"{where} cell {index}",
            )
            cell["source"] = source
            metadata["nbgrader"] = nbgrader_metadata(
                grade_id(f"test_{exercise.variable}"), grade=True, locked=True, points=points
            )
            if RAISES_TAG not in tags:
                tags.append(RAISES_TAG)  # a student's Run All goes on past a wrong answer
            released.append(
                ReleasedExercise(
                    lesson,
                    exercise.number,
                    exercise.variable,
                    points,
                    ran.kind,
                    partial,
                    partial and ran.symbolic,
                    rubric,
                )
            )
        elif index == id_cell:
            metadata.pop("nbgrader", None)  # the student types their id here ...
            metadata["deletable"] = False  # ... and every check needs it
        else:
            metadata["nbgrader"] = nbgrader_metadata(f"locked_{index:02d}", locked=True)
        if tags:
            metadata["tags"] = tags
    kept = [cell for cell in cells if PRACTICE_TAG not in cell_tags(cell)]
    first = next((i for i, c in enumerate(kept) if c.get("cell_type") == "markdown"), -1)
    kept.insert(first + 1, _intro_cell(released))
    notebook["cells"] = cells = kept
    ids = [c["metadata"]["nbgrader"]["grade_id"] for c in cells if "nbgrader" in c["metadata"]]
    if len(ids) != len(set(ids)):
        duplicate = next(i for i in ids if ids.count(i) > 1)
        raise InvalidInputError(where, duplicate, "answer variables with distinct names")
    notebook.setdefault("metadata", {}).setdefault(
        "kernelspec", {"display_name": "Python 3", "language": "python", "name": "python3"}
    )
    return notebook, released


def _assignment_points(source: Path) -> dict[str, float]:
    """Points of every assignment in ``source/`` (this and earlier releases)."""
    points: dict[str, float] = {}
    for folder in sorted(p for p in source.iterdir() if p.is_dir()):
        path = folder / f"{folder.name}.ipynb"
        if not path.is_file():
            continue
        cells = read_notebook(path)["cells"]
        points[folder.name] = sum(
            float(c["metadata"]["nbgrader"].get("points", 0))
            for c in cells
            if c.get("metadata", {}).get("nbgrader", {}).get("grade")
        )
    return points


def release_course(
    out: str | os.PathLike[str],
    course: str | os.PathLike[str] | None = None,
    lessons: str | Sequence[str] | None = None,
    *,
    course_id: str = "robotconf",
    timeout: int = CELL_TIMEOUT,
    say: Callable[[str], None] | None = None,
) -> Release:
    """Write the course as an nbgrader source tree in ``out``.

    Parameters
    ----------
    out : path-like
        The nbgrader course folder (created): ``source/<lesson>/<lesson>.ipynb``,
        ``nbgrader_config.py`` and ``README.md`` are written there.
    course : path-like, optional
        The course folder (default: ``./course``, else the repository's).
    lessons : str or sequence of str, optional
        ``"01,03"``, lesson numbers or folder names; default every lesson.
    course_id : str
        nbgrader's course id.
    timeout : int
        Seconds per cell when the solutions run.
    say : callable, optional
        Receives one progress line per lesson.

    Returns
    -------
    Release

    Raises
    ------
    InvalidInputError
        A bad option, a malformed notebook, or a solution that fails its own check.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as out:
    ...     release = release_course(out, lessons="01")  # runs the solutions notebook
    ...     written = sorted(p.name for p in Path(out).rglob("*.*"))
    >>> written
    ['01_homogeneous_transforms.ipynb', 'README.md', 'nbgrader_config.py']
    >>> [(e.variable, e.points, e.hidden) for e in release.exercises]  # course/kit/weights.md
    [('answer_1', 1.0, False), ('answer_2', 2.0, False), ('answer_3', 1.0, False),
     ('answer_4', 2.0, True)]
    """
    say = say or (lambda _: None)
    if not isinstance(course_id, str) or not _COURSE_ID.fullmatch(course_id):
        raise InvalidInputError(
            "--course-id", course_id, "1 to 64 letters, digits, _ . - (e.g. robotics101)"
        )
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise InvalidInputError("OUT", str(out), "a folder (created if missing)", "not a folder:")
    folder = find_course(course)
    names = select_lessons(folder, lessons)
    weights = find_weights(folder)
    built: list[tuple[str, dict[str, Any]]] = []
    exercises: list[ReleasedExercise] = []
    notes: list[str] = []
    for number, lesson in enumerate(names, 1):
        path = solutions_notebook(folder, lesson)
        run = run_solutions(path, timeout=timeout)
        for ran in run.exercises:
            if ran.error:
                raise InvalidInputError(
                    f"{path} exercise {ran.exercise.number} ({ran.exercise.variable})",
                    ran.error,
                    "solutions that pass their own checks",
                    "the solution fails its check:",
                )
        student_path = exercises_notebook(folder, lesson)
        students = read_notebook(student_path) if student_path else None
        solutions = read_notebook(path)
        notebook, done = source_notebook(solutions, run, lesson, students, weights)
        if not _aligned(solutions, students):
            notes.append(
                f"{lesson}: the exercises notebook does not line up with the solutions "
                "cell by cell; the text is the solutions notebook's"
            )
        built.append((lesson, notebook))
        exercises += done
        total = sum(e.points for e in done)
        say(
            f"[{number}/{len(names)}] {lesson}: {len(done)} exercises, {total} points "
            f"(partial credit on {sum(e.partial for e in done)}, hidden tests on "
            f"{sum(e.hidden for e in done)})"
        )
    source = out / "source"
    for lesson, notebook in built:
        target = source / lesson / f"{lesson}.ipynb"
        target.parent.mkdir(parents=True, exist_ok=True)
        text = json.dumps(notebook, indent=1, ensure_ascii=False)
        target.write_text(text + "\n", encoding="utf-8")
    assignments = _assignment_points(source)
    for name, text in (
        ("nbgrader_config.py", config_text(course_id, assignments)),
        ("README.md", readme_text(course_id, assignments)),
    ):
        if not write_if_ours(out / name, text):
            notes.append(f"{out / name} is the instructor's own (no 'Written by' line): kept")
    return Release(out, [lesson for lesson, _ in built], exercises, notes)
