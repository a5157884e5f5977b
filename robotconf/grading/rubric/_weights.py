"""The course's weighting table: points per exercise and the shares of slips.

A teacher edits one Markdown file, ``course/kit/weights.md``; the release reads it. Two
kinds of table are read, by their header row (other text and tables are the teacher's):

``| lesson | exercise | points | … |``
    The points of each exercise (lesson by number, ``01`` … ``12``; exercise by number).
``| lesson | exercise | slip | share | … |``
    The share of the points a slip earns (a diagnosis code, ``robotconf course rubric``
    lists them), or with ``slip`` = ``any`` the exercise's default share of a named
    slip. ``*`` in ``lesson`` or ``exercise`` stands for every one; a row for one
    exercise wins over a row for a lesson, which wins over ``* | *``.

An exercise the table does not list keeps the default points (one, two for a 4×4
matrix) and the default shares (half for a named slip).
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, field
from pathlib import Path

from ..._errors import InvalidInputError
from ._rubric import DEFAULT_SHARE, Rubric, names_a_slip

__all__ = ["WEIGHTS_FILE", "Weights", "find_weights", "read_weights"]

#: Where a course keeps its weighting table.
WEIGHTS_FILE = Path("kit") / "weights.md"
_ANY = "*"


def _cells(line: str) -> list[str]:
    return [cell.strip().strip("`") for cell in line.strip().strip("|").split("|")]


def _tables(text: str) -> list[tuple[list[str], list[tuple[int, list[str]]]]]:
    """(header, [(line number, cells)]) of every pipe table in ``text``."""
    tables: list[tuple[list[str], list[tuple[int, list[str]]]]] = []
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        rule = lines[i + 1] if i + 1 < len(lines) else ""
        if line.lstrip().startswith("|") and re.fullmatch(r"\s*\|[\s:|-]+\|?\s*", rule):
            header = [cell.lower() for cell in _cells(line)]
            rows = []
            i += 2
            while i < len(lines) and lines[i].lstrip().startswith("|"):
                rows.append((i + 1, _cells(lines[i])))
                i += 1
            tables.append((header, rows))
        else:
            i += 1
    return tables


def _key(value: str, where: str, field_name: str) -> str:
    if value == _ANY:
        return _ANY
    if not value.isdigit():
        raise InvalidInputError(where, value, f"a {field_name} number, or *")
    return str(int(value))


def _number(value: str, where: str, what: str) -> float:
    try:
        number = float(value)
    except ValueError:
        raise InvalidInputError(where, value, what) from None
    if not number >= 0 or number == float("inf"):
        raise InvalidInputError(where, value, what)
    return number


@dataclass(frozen=True)
class Weights:
    """A course's weighting table, read.

    Attributes
    ----------
    points : dict of (str, str) to float
        ``(lesson, exercise)`` → points, both as plain numbers in text (``("9", "1")``).
    shares : dict of (str, str, str) to float
        ``(lesson, exercise, slip)`` → share; ``*`` for every lesson or exercise, slip
        ``any`` for the default share of a named slip.
    source : str
        Where it was read from.
    """

    points: dict[tuple[str, str], float] = field(default_factory=dict)
    shares: dict[tuple[str, str, str], float] = field(default_factory=dict)
    source: str = ""

    def points_of(self, lesson: str, number: int) -> float | None:
        """The points of exercise ``number`` of ``lesson`` (``"09_dh_…"`` or ``"9"``)."""
        return self.points.get((_lesson_key(lesson), str(number)))

    def rubric(self, lesson: str, number: int, points: float) -> Rubric:
        """The rubric of one exercise worth ``points``, with the table's shares.

        >>> table = Weights(shares={("*", "*", "too_rounded"): 0.75, ("11", "*", "any"): 0.4})
        >>> rubric = table.rubric("11_inverse_kinematics", 2, 1.5)
        >>> rubric.share, rubric.slips
        (0.4, {'too_rounded': 0.75})
        """
        lesson_key, exercise = _lesson_key(lesson), str(number)
        scopes = [(_ANY, _ANY), (lesson_key, _ANY), (lesson_key, exercise)]
        share = DEFAULT_SHARE
        slips: dict[str, float] = {}
        for scope in scopes:  # the narrower scope wins
            for (row_lesson, row_exercise, slip), value in self.shares.items():
                if (row_lesson, row_exercise) != scope:
                    continue
                if slip == "any":
                    share = value
                else:
                    slips[slip] = value
        return Rubric(points, share, slips)

    def lessons(self) -> list[str]:
        """The lessons the table gives points for, by number (``"1"`` … ``"12"``)."""
        return sorted({lesson for lesson, _ in self.points}, key=int)


def _lesson_key(lesson: str) -> str:
    head = lesson.split("_")[0]
    return str(int(head)) if head.isdigit() else lesson


def read_weights(path: str | os.PathLike[str]) -> Weights:
    """Read a weighting table (see the module notes).

    Raises
    ------
    InvalidInputError
        Naming the file and line of a row with a bad lesson, exercise, points, slip or
        share.

    Examples
    --------
    >>> import tempfile
    >>> text = "| lesson | exercise | points |\\n|---|---|---|\\n| 09 | 1 | 2 |\\n"
    >>> with tempfile.NamedTemporaryFile("w", suffix=".md", delete=False) as file:
    ...     _ = file.write(text)
    >>> read_weights(file.name).points_of("09_dh_frame_assignment", 1)
    2.0
    """
    path = Path(path)
    points: dict[tuple[str, str], float] = {}
    shares: dict[tuple[str, str, str], float] = {}
    for header, rows in _tables(path.read_text(encoding="utf-8")):
        if header[:3] == ["lesson", "exercise", "points"]:
            for line, cells in rows:
                where = f"{path}:{line}"
                key = (_key(cells[0], where, "lesson"), _key(cells[1], where, "exercise"))
                if _ANY in key:
                    raise InvalidInputError(where, cells[:2], "one lesson and one exercise")
                points[key] = _number(cells[2], where, "points: a number ≥ 0")
        elif header[:4] == ["lesson", "exercise", "slip", "share"]:
            for line, cells in rows:
                where = f"{path}:{line}"
                slip = cells[2]
                if slip != "any" and not names_a_slip(slip):
                    raise InvalidInputError(
                        where, slip, "a diagnosis code that names a slip, or any"
                    )
                share = _number(cells[3], where, "a share from 0 to 1")
                if share > 1:
                    raise InvalidInputError(where, cells[3], "a share from 0 to 1")
                lesson = _key(cells[0], where, "lesson")
                shares[(lesson, _key(cells[1], where, "exercise"), slip)] = share
    return Weights(points, shares, str(path))


def find_weights(course: Path) -> Weights | None:
    """The weighting table of a course folder (``kit/weights.md``), if it has one."""
    path = course / WEIGHTS_FILE
    return read_weights(path) if path.is_file() else None
