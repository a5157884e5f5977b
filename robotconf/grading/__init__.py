"""Grading: the course as nbgrader assignments, partial credit, and the answer key.

Instructor tooling beside the command line (``robotconf course release`` and
``robotconf course key``); docs/grading.md walks through it. Notebooks are read and
written as nbformat-4 JSON; running them needs nbclient and ipykernel (the ``lab``
extra), imported only when a notebook runs.

In a graded notebook
    :class:`Credit` (a test cell's points by the rubric; ``credit.own_work`` flags an
    answer cell that asks robotconf for its answer)
The rubric: credit for the right method
    :class:`Rubric`, :func:`award`, :class:`Award`, :func:`names_a_slip`,
    :data:`SLIP_WORDS`, :func:`points_for`, :func:`credit_counts`,
    :func:`graded_entries`
The course's weighting table (course/kit/weights.md)
    :func:`read_weights`, :func:`find_weights`, :class:`Weights`
Answers that ask robotconf for themselves
    :func:`robotconf_calls`, :data:`FLAG`
Release for nbgrader
    :func:`release_course`, :class:`Release`, :class:`ReleasedExercise`,
    :func:`source_notebook`
Running the solutions
    :func:`run_solutions`, :class:`SolutionsRun`, :class:`ExerciseRun`
The answer key
    :func:`answer_key`, :func:`write_answer_key`, :class:`AnswerKey`, :class:`KeyLesson`,
    :class:`KeyExercise`
Exercises by their tags
    :func:`find_exercises`, :class:`Exercise`, :func:`read_notebook`
The command line
    :func:`add_course_parser`, :func:`run_course`

>>> points_for("matrix", (4, 4))
2
"""

from ._answer_key import AnswerKey, KeyExercise, KeyLesson, answer_key, write_answer_key
from ._command import add_course_parser, run_course
from ._execute import ExerciseRun, SolutionsRun, run_solutions
from ._notebook_cells import Exercise, find_exercises, read_notebook
from ._release import Release, ReleasedExercise, release_course, source_notebook
from .rubric import (
    FLAG,
    SLIP_WORDS,
    Award,
    Credit,
    Rubric,
    Weights,
    award,
    credit_counts,
    find_weights,
    graded_entries,
    names_a_slip,
    points_for,
    read_weights,
    robotconf_calls,
)

__all__ = [
    # in a graded notebook
    "Credit",
    # the rubric
    "Rubric",
    "award",
    "Award",
    "names_a_slip",
    "SLIP_WORDS",
    "points_for",
    "credit_counts",
    "graded_entries",
    # the weighting table
    "read_weights",
    "find_weights",
    "Weights",
    # answers that ask robotconf for themselves
    "robotconf_calls",
    "FLAG",
    # release for nbgrader
    "release_course",
    "Release",
    "ReleasedExercise",
    "source_notebook",
    # running the solutions
    "run_solutions",
    "SolutionsRun",
    "ExerciseRun",
    # the answer key
    "answer_key",
    "write_answer_key",
    "AnswerKey",
    "KeyLesson",
    "KeyExercise",
    # exercises by their tags
    "find_exercises",
    "Exercise",
    "read_notebook",
    # the command line
    "add_course_parser",
    "run_course",
]
