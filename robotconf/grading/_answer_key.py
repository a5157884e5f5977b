"""``robotconf course key``: the expected answer of every exercise, for the instructor.

The solutions notebooks run (:func:`~robotconf.grading.run_solutions`) and each
exercise's expected value is read from what its check compared against: a matrix or
vector as numbers, a formula as text in the checker's syntax and as LaTeX. A lesson with
per-student variants (a cell tagged ``student-id``) runs with that cell set to the given
student's id, so the key is that student's.
"""

from __future__ import annotations

import json
import os
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from .._errors import InvalidInputError
from ._course import find_course, select_lessons, solutions_notebook
from ._execute import CELL_TIMEOUT, check_student_id, run_solutions
from .rubric._points import points_for
from .rubric._weights import find_weights

__all__ = ["AnswerKey", "KeyExercise", "KeyLesson", "answer_key", "key_path", "write_answer_key"]

KEY_FORMATS = (".md", ".json")


@dataclass(frozen=True)
class KeyExercise:
    """One exercise of the key.

    Attributes
    ----------
    number : int
    variable : str
    points : float
    kind : str or None
        ``"matrix"``, ``"vector"``, ``"value"``, ``"angle"``, ``"set"``, ``"interval"``,
        ``"dh_table"``, or ``None`` when the check called no checker.
    expected : dict or None
        ``kind``, ``name``, ``q``, ``shape``, ``symbols``, ``entries`` (text),
        ``values`` (numbers, when numeric) and ``latex`` (when symbolic).
    expected_from : str or None
        ``"check"``, ``"variable"`` (``expected_<k>``) or ``"answer"``.
    solution : dict or None
        The solution notebook's answer: ``text`` and, when numeric, ``values``.
    error : str
        The check's error when the solution does not pass it (``""`` when it does).
    """

    number: int
    variable: str
    points: float
    kind: str | None
    expected: dict[str, Any] | None
    expected_from: str | None
    solution: dict[str, Any] | None
    error: str


@dataclass(frozen=True)
class KeyLesson:
    """The key of one lesson.

    Attributes
    ----------
    lesson : str
    notebook : str
        The solutions notebook it came from.
    student_id : str or None
        The id the lesson ran with; ``None`` when it has no per-student variants.
    exercises : list of KeyExercise
    """

    lesson: str
    notebook: str
    student_id: str | None
    exercises: list[KeyExercise]

    @property
    def points(self) -> float:
        """The lesson's total points."""
        return sum(e.points for e in self.exercises)


@dataclass(frozen=True)
class AnswerKey:
    """The answer key of some lessons, for one student or for everyone.

    Attributes
    ----------
    course : str
        The course folder.
    student : str or None
        The ``--student`` id, if one was given.
    lessons : list of KeyLesson
    """

    course: str
    student: str | None
    lessons: list[KeyLesson]

    def to_dict(self) -> dict[str, Any]:
        """Plain data (for JSON)."""
        return asdict(self)

    def to_json(self) -> str:
        """The key as JSON text."""
        return json.dumps(self.to_dict(), indent=1, ensure_ascii=False) + "\n"

    def to_markdown(self) -> str:
        """The key as a Markdown document (formulas as LaTeX between ``$$``)."""
        from ._key_markdown import key_markdown

        return key_markdown(self)


def _points(weights: Any, lesson: str, number: int, kind: Any, shape: Any) -> float:
    """An exercise's points: the weighting table's, else the default by kind and shape."""
    listed = weights.points_of(lesson, number) if weights is not None else None
    return listed if listed is not None else points_for(kind, shape)


def answer_key(
    course: str | os.PathLike[str] | None = None,
    lessons: str | Sequence[str] | None = None,
    *,
    student: str | None = None,
    timeout: int = CELL_TIMEOUT,
    say: Callable[[str], None] | None = None,
) -> AnswerKey:
    """Run the solutions and collect every exercise's expected answer.

    Parameters
    ----------
    course : path-like, optional
        The course folder (default: ``./course``, else the repository's).
    lessons : str or sequence of str, optional
        ``"01,03"``, lesson numbers or folder names; default every lesson.
    student : str, optional
        A student id: lessons with a ``student-id`` cell run with it.
    timeout : int
        Seconds per cell.
    say : callable, optional
        Receives one progress line per lesson.

    Returns
    -------
    AnswerKey

    Raises
    ------
    InvalidInputError
        A bad option or id, a malformed notebook, a failing cell outside the checks,
        or missing nbclient/ipykernel (the ``lab`` extra).

    Examples
    --------
    >>> key = answer_key(lessons="01")  # runs the lesson's solutions notebook
    >>> exercise = key.lessons[0].exercises[2]  # where is the point (40, 0, 0) of [T1]?
    >>> exercise.points, exercise.expected["name"], exercise.expected["values"]
    (1.0, 'p_EE', [[30.0], [40.0], [20.0], [1.0]])
    """
    say = say or (lambda _: None)
    if student is not None:
        student = check_student_id(student)
    folder = find_course(course)
    names = select_lessons(folder, lessons)
    weights = find_weights(folder)
    keyed: list[KeyLesson] = []
    for number, lesson in enumerate(names, 1):
        path = solutions_notebook(folder, lesson)
        run = run_solutions(path, student_id=student, timeout=timeout)
        exercises = [
            KeyExercise(
                r.exercise.number,
                r.exercise.variable,
                _points(weights, lesson, r.exercise.number, r.kind, r.shape),
                r.kind,
                r.expected,
                r.expected_from,
                r.solution,
                r.error,
            )
            for r in run.exercises
        ]
        keyed.append(KeyLesson(lesson, str(path), run.student_id, exercises))
        for_whom = f" for student {run.student_id}" if run.student_id is not None else ""
        say(f"[{number}/{len(names)}] {lesson}: {len(exercises)} exercises{for_whom}")
    return AnswerKey(str(folder), student, keyed)


def key_path(path: str | os.PathLike[str]) -> Path:
    """The key's file name, checked before any notebook runs.

    Raises
    ------
    InvalidInputError
        (field ``OUT``) unless it ends in ``.md`` or ``.json``, or names a folder.

    Examples
    --------
    >>> key_path("key.MD").name
    'key.MD'
    >>> key_path("key.txt")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: OUT: invalid value 'key.txt'; allowed: a file name ...
    """
    path = Path(path)
    if path.suffix.lower() not in KEY_FORMATS or path.is_dir():
        raise InvalidInputError("OUT", str(path), "a file name ending in .md or .json")
    return path


def write_answer_key(path: str | os.PathLike[str], key: AnswerKey) -> Path:
    """Write the key as Markdown (``.md``) or JSON (``.json``), by the file's suffix.

    Raises
    ------
    InvalidInputError
        (field ``OUT``) for another suffix.
    """
    path = key_path(path)
    text = key.to_markdown() if path.suffix.lower() == ".md" else key.to_json()
    if path.parent != Path(""):
        path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path
