"""The instructor's files beside ``source/``: ``nbgrader_config.py`` and ``README.md``.

Both start with :data:`WRITTEN_BY`; a release rewrites a file that still starts with it
(so the assignment list grows with each lesson released) and leaves alone one the
instructor has taken over by deleting that line.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from pathlib import Path

from ._nbgrader_cells import CODE_STUB
from .rubric._credit import HIDDEN_SAMPLES
from .rubric._points import POINTS_PER_EXERCISE, POINTS_PER_MATRIX

__all__ = ["WRITTEN_BY", "config_text", "readme_text", "write_if_ours"]

#: The mark of a file the release may rewrite (after ``#`` in Python, in a Markdown comment).
WRITTEN_BY = "Written by `robotconf course release`"
#: Seconds nbgrader gives each cell (its default, 30 s, is tight for a busy machine).
EXECUTE_TIMEOUT = 120
#: The autograde step that marks flagged exercises for manual grading.
FLAG_STEP = "robotconf.grading.nbgrader_flags.FlagForManualGrading"


def config_text(course_id: str, assignments: Mapping[str, float]) -> str:
    """``nbgrader_config.py`` for the course.

    Examples
    --------
    >>> text = config_text("robotconf", {"01_homogeneous_transforms": 7})
    >>> 'c.CourseDirectory.course_id = "robotconf"' in text
    True
    """
    listed = "\n".join(
        f"    {json.dumps(name)},  # {points:g} points" for name, points in assignments.items()
    )
    return f"""# {WRITTEN_BY}; it rewrites this file unless this line is removed.
# nbgrader reads it from the folder its commands run in: run them in this folder.
c = get_config()  # noqa: F821 (nbgrader defines get_config)

c.CourseDirectory.course_id = {json.dumps(course_id)}

# One assignment per lesson (source/<name>/<name>.ipynb); `nbgrader generate_assignment
# <name>` adds it to the gradebook.
ASSIGNMENTS = [
{listed}
]

# The answer cells keep their `answer_k = None` line; nbgrader puts this comment where
# the solution was (its default stub would add `raise NotImplementedError()`).
c.ClearSolutions.code_stub = {{"python": {json.dumps(CODE_STUB)}}}

# Seconds per cell when nbgrader runs a notebook (validate, autograde).
c.Execute.timeout = {EXECUTE_TIMEOUT}

# An answer cell that calls robotconf (which computes every answer of the course) earns
# no automatic points: its test cell says so, and this step marks it for manual grading.
from nbgrader.converters import Autograde  # noqa: E402
from nbgrader.preprocessors import SaveAutoGrades  # noqa: E402

_steps = list(Autograde.class_traits()["autograde_preprocessors"].default())
_steps.insert(_steps.index(SaveAutoGrades) + 1, "{FLAG_STEP}")
c.Autograde.autograde_preprocessors = _steps
"""


def readme_text(course_id: str, assignments: Mapping[str, float]) -> str:
    """``README.md``: the instructor's steps, from generating to feedback."""
    rows = "\n".join(f"| `{name}` | {points:g} |" for name, points in assignments.items())
    first = next(iter(assignments), "01_homogeneous_transforms")
    return f"""<!-- {WRITTEN_BY}; it rewrites this file unless this line is removed. -->
# nbgrader course `{course_id}`

`source/` holds every assignment **with its solutions and hidden tests**: it is the
instructor's copy, never hand it out. Students get the copies nbgrader makes in
`release/`, without either. Run every command in this folder (nbgrader reads
`nbgrader_config.py` here); requires `pip install nbgrader`.

| assignment | points |
|---|---|
{rows}

1. `nbgrader generate_assignment {first}` writes the student version to
   `release/{first}/` (solutions replaced by `answer_k = None`, hidden tests removed).
2. Hand it out: `nbgrader release_assignment {first}` (with an exchange), or copy the
   folder to the students.
3. Collect: `nbgrader collect {first}`, or put each student's notebook in
   `submitted/<student id>/{first}/{first}.ipynb`.
4. `nbgrader autograde {first}` runs every submission (with the hidden tests put back)
   and records the points in `gradebook.db`.
5. `nbgrader generate_feedback {first}` writes an HTML report per student to
   `feedback/`; `nbgrader export` writes all grades to `grades.csv`.

Points come from the course's weighting table (`course/kit/weights.md`; without it
{POINTS_PER_EXERCISE} per exercise, {POINTS_PER_MATRIX} for a 4×4 matrix). The checks are
hidden tests: the students' copies hold no expected value. A test cell prints the
checker's hints and what cost the points: a wrong answer earns the share of a named slip
of a right method (half, unless the table says otherwise) or the share of its numbers
that are right (at most three quarters); symbolic answers are checked again at
{HIDDEN_SAMPLES} other values of the symbols. An answer cell that calls robotconf earns
no automatic points and is marked "needs manual grading" (formgrader lists it). The
rules are in robotconf's `docs/grading.md`; `robotconf course rubric 09` shows a lesson's
rubric, `robotconf course key KEY.md` writes the answer key.
"""


def write_if_ours(path: Path, text: str) -> bool:
    """Write ``text`` unless ``path`` exists without :data:`WRITTEN_BY` at its top.

    Returns whether the file was written.
    """
    if path.exists():
        head = path.read_text(encoding="utf-8", errors="replace")[:200]
        if WRITTEN_BY not in head:
            return False
    path.write_text(text, encoding="utf-8")
    return True
