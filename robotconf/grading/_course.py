"""Where the course is, and which of its lessons a command works on.

A course folder holds one folder per lesson, ``NN_name/exercises.ipynb`` (the students'
copy), and the answers in ``solutions/NN_name/exercises.ipynb`` (``course/README.md``).
"""

from __future__ import annotations

import os
import re
from collections.abc import Sequence
from pathlib import Path

from .._errors import InvalidInputError

__all__ = [
    "EXERCISES",
    "exercises_notebook",
    "find_course",
    "lesson_names",
    "select_lessons",
    "solutions_notebook",
]

#: The file name of a lesson's exercises (and of its solutions).
EXERCISES = "exercises.ipynb"
_LESSON = re.compile(r"\d\d_[A-Za-z0-9_]+")
_COURSE_ALLOWED = "a course folder with solutions/NN_name/exercises.ipynb"


def _is_course(folder: Path) -> bool:
    return (folder / "solutions").is_dir()


def find_course(course: str | os.PathLike[str] | None = None) -> Path:
    """The course folder: the one given, else ``./course``, else the repository's.

    Raises
    ------
    InvalidInputError
        (field ``--course``) when the folder has no ``solutions/``, or none is found.

    Examples
    --------
    >>> find_course().name
    'course'
    """
    if course is not None:
        folder = Path(course)
        if not _is_course(folder):
            raise InvalidInputError("--course", str(folder), _COURSE_ALLOWED, "no solutions/ in")
        return folder
    for folder in (Path("course"), Path(__file__).resolve().parents[2] / "course"):
        if _is_course(folder):
            return folder
    raise InvalidInputError("--course", None, _COURSE_ALLOWED, "no course folder found:")


def lesson_names(course: Path) -> list[str]:
    """Lessons that have solutions, sorted: ``["01_homogeneous_transforms", ...]``."""
    solutions = course / "solutions"
    return sorted(
        folder.name
        for folder in solutions.iterdir()
        if _LESSON.fullmatch(folder.name) and (folder / EXERCISES).is_file()
    )


def select_lessons(course: Path, lessons: str | Sequence[str] | None = None) -> list[str]:
    """The lessons named by ``--lessons``: numbers (``"01,03"``) or folder names.

    Parameters
    ----------
    course : Path
    lessons : str or sequence of str, optional
        Comma-separated in one string, or a list; ``None`` or empty: every lesson.

    Returns
    -------
    list of str
        Lesson folder names, in course order, each once.

    Raises
    ------
    InvalidInputError
        (field ``--lessons``) for a lesson the course does not have.

    Examples
    --------
    >>> select_lessons(find_course(), "3,1")
    ['01_homogeneous_transforms', '03_composing_a_chain']
    """
    available = lesson_names(course)
    if lessons is None:
        return available
    tokens = lessons.split(",") if isinstance(lessons, str) else list(lessons)
    wanted: set[str] = set()
    for token in (str(t).strip() for t in tokens):
        if not token:
            continue
        found = [name for name in available if name == token or name[:2] == token.zfill(2)]
        if not found:
            allowed = ", ".join(name[:2] for name in available) or "none: no solutions found"
            raise InvalidInputError("--lessons", token, f"lessons of {course}: {allowed}")
        wanted.update(found)
    return [name for name in available if name in wanted] if wanted else available


def solutions_notebook(course: Path, lesson: str) -> Path:
    """``course/solutions/<lesson>/exercises.ipynb``."""
    return course / "solutions" / lesson / EXERCISES


def exercises_notebook(course: Path, lesson: str) -> Path | None:
    """``course/<lesson>/exercises.ipynb``, the students' copy, when it exists."""
    path = course / lesson / EXERCISES
    return path if path.is_file() else None
