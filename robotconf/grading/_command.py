"""``robotconf course …``: the instructor's commands (release for nbgrader, the rubric,
quizzes and the exam, the answer key).

``cli.py`` registers the subcommand with :func:`add_course_parser` and hands the parsed
arguments to :func:`run_course`; errors are ``InvalidInputError`` (a ``ValueError``) or
``OSError``, which ``cli.main`` prints as one line with exit status 2.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from typing import Any

from ._execute import CELL_TIMEOUT

__all__ = ["add_course_parser", "run_course"]

_RELEASE = """\
Write the course as an nbgrader course folder: OUT/source/<lesson>/<lesson>.ipynb (one
assignment per lesson, from the solutions notebooks, with solution markers, points,
partial credit and hidden tests), OUT/nbgrader_config.py and OUT/README.md. The
solutions run first and must pass their own checks. OUT/source holds the solutions: it
is the instructor's copy; `nbgrader generate_assignment` makes the students' copies."""

_RUBRIC = """\
Show a lesson's rubric: every exercise's points and the share a named slip earns (from
the course's kit/weights.md), the kind of answer its check judges, whether the right
numbers of a wrong answer count, and the slips the checker names. Markdown on standard
output."""

_KEY = """\
Write the answer key (every exercise's expected value, formulas also as LaTeX) as
Markdown (.md) or JSON (.json), by running the solutions notebooks. Lessons with
per-student numbers (a cell tagged student-id) run with --student's id."""


_QUIZ = """\
Write the quizzes of the course's kit/quizzes.md (a few exercises per lesson) as a course
folder: OUT/NN_quiz_name/exercises.ipynb, OUT/solutions/…, OUT/kit/weights.md. Every
item has the student's own numbers, drawn under --draw (other numbers than the
homework's), and the exercise's own check. Hand the folder out for practice, or release
it: robotconf course release NBGRADER/ --course OUT/."""

_EXAM = """\
Write the exam of the course's kit/exam_bank.md as a course folder: OUT/90_exam/
exercises.ipynb, OUT/solutions/…, OUT/kit/weights.md. Each slot offers one or more
exercises; every student gets one per slot, with their own numbers, drawn from their id
and --draw. Release it for nbgrader: robotconf course release NBGRADER/ --course OUT/."""


def _common(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--course", metavar="COURSE_DIR", help="the course folder (default: ./course)"
    )
    parser.add_argument(
        "--lessons", metavar="LIST", help="lessons by number or name, e.g. 01,03 (default: all)"
    )
    parser.add_argument(
        "--timeout",
        type=int,
        default=CELL_TIMEOUT,
        metavar="SECONDS",
        help=f"time limit per notebook cell (default {CELL_TIMEOUT})",
    )
    parser.add_argument("--quiet", action="store_true", help="no progress lines")


def add_course_parser(commands: Any) -> None:
    """Add ``course release``, ``rubric``, ``quiz``, ``exam`` and ``key`` to ``robotconf``.

    Parameters
    ----------
    commands : argparse subparsers action
        What ``ArgumentParser.add_subparsers`` returned for ``robotconf``.

    Examples
    --------
    >>> parser = argparse.ArgumentParser(prog="robotconf")
    >>> add_course_parser(parser.add_subparsers(dest="command"))
    >>> args = parser.parse_args(["course", "key", "key.md", "--student", "s1"])
    >>> args.course_command, args.out, args.student, args.timeout
    ('key', 'key.md', 's1', 120)
    """
    course = commands.add_parser(
        "course",
        help="instructor tools: the course for nbgrader, its rubric, the answer key",
        description=(
            "Instructor tools for the course: an nbgrader release, the rubric and the answer key."
        ),
    )
    actions = course.add_subparsers(dest="course_command", required=True, metavar="ACTION")
    release = actions.add_parser(
        "release", help="write an nbgrader course folder", description=_RELEASE
    )
    release.add_argument("out", metavar="OUT/", help="the nbgrader course folder (created)")
    release.add_argument(
        "--course-id", default="robotconf", help="nbgrader's course id (default robotconf)"
    )
    _common(release)
    rubric = actions.add_parser(
        "rubric", help="show a lesson's rubric (points, slips, shares)", description=_RUBRIC
    )
    rubric.add_argument("lesson", metavar="LESSON", help="a lesson number or folder name")
    rubric.add_argument(
        "--course", metavar="COURSE_DIR", help="the course folder (default: ./course)"
    )
    quiz = actions.add_parser("quiz", help="write the quizzes (a course folder)", description=_QUIZ)
    quiz.add_argument("out", metavar="OUT/", help="the quizzes' course folder (created)")
    quiz.add_argument("--course", metavar="COURSE_DIR", help="the course (default ./course)")
    quiz.add_argument("--lessons", metavar="LIST", help="lessons by number, e.g. 11,12")
    quiz.add_argument("--draw", default="quiz", help="the numbers' name (default quiz)")
    exam = actions.add_parser("exam", help="write the exam (a course folder)", description=_EXAM)
    exam.add_argument("out", metavar="OUT/", help="the exam's course folder (created)")
    exam.add_argument("--course", metavar="COURSE_DIR", help="the course (default ./course)")
    exam.add_argument("--draw", default="exam", help="the exam's name, e.g. exam-2026")
    key = actions.add_parser("key", help="write the answer key", description=_KEY)
    key.add_argument("out", metavar="OUT.md|OUT.json", help="the key file")
    key.add_argument("--student", metavar="ID", help="a student id, for per-student lessons")
    _common(key)


def run_course(args: argparse.Namespace, say: Callable[[str], None] = print) -> int:
    """Run ``robotconf course release|rubric|quiz|exam|key`` with parsed arguments.

    Raises
    ------
    InvalidInputError
        For bad options, notebooks or solutions (``cli.main`` prints it on one line).
    """
    from ._answer_key import answer_key, key_path, write_answer_key
    from ._release import release_course
    from .rubric._rubric_table import rubric_text

    if args.course_command == "rubric":
        say(rubric_text(args.lesson, args.course).rstrip("\n"))
        return 0
    if args.course_command in ("quiz", "exam"):
        from ._quiz import write_exam_course, write_quiz_course

        if args.course_command == "quiz":
            lessons = args.lessons.split(",") if args.lessons else None
            names = write_quiz_course(args.out, args.course, lessons, args.draw)
        else:
            names = [write_exam_course(args.out, args.course, args.draw)]
        say(
            f"wrote {args.out}: {', '.join(names)} (release: robotconf course release "
            f"NBGRADER/ --course {args.out})"
        )
        return 0
    if args.timeout < 1:
        from .._errors import InvalidInputError

        raise InvalidInputError("--timeout", args.timeout, "a whole number of seconds ≥ 1")
    progress = (lambda _: None) if args.quiet else say
    if args.course_command == "release":
        release = release_course(
            args.out,
            args.course,
            args.lessons,
            course_id=args.course_id,
            timeout=args.timeout,
            say=progress,
        )
        total = sum(e.points for e in release.exercises)
        for note in release.notes:
            progress(f"note: {note}")
        progress(
            f"wrote {release.out}: {len(release.assignments)} assignments, {total} points "
            "(source/ holds the solutions: instructor only; see README.md there)"
        )
        return 0
    key_path(args.out)  # before the notebooks run
    key = answer_key(
        args.course, args.lessons, student=args.student, timeout=args.timeout, say=progress
    )
    path = write_answer_key(args.out, key)
    count = sum(len(lesson.exercises) for lesson in key.lessons)
    progress(f"wrote {path}: {len(key.lessons)} lessons, {count} exercises")
    return 0
