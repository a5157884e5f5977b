"""The rubric: what a checked answer earns, and how a graded copy finds out.

:mod:`._rubric` (credit for the right method: a named slip's share, the right numbers'
share), :mod:`._points` (points per exercise, the numbers that count),
:mod:`._weights` (the course's weighting table), :mod:`._rubric_table` (``robotconf
course rubric``, imported by the command when it runs), :mod:`._credit` (a graded test
cell's points), :mod:`._recorder` (the checker calls of a cell), :mod:`._shortcuts` (an
answer cell that asks robotconf). :mod:`robotconf.grading` exports the same names.

In a graded notebook
    :class:`Credit`
Credit for the right method
    :class:`Rubric`, :func:`award`, :class:`Award`, :func:`names_a_slip`,
    :data:`SLIP_WORDS`, :func:`points_for`, :func:`credit_counts`,
    :func:`graded_entries`
The course's weighting table
    :func:`read_weights`, :func:`find_weights`, :class:`Weights`
Answers that ask robotconf for themselves
    :func:`robotconf_calls`, :data:`FLAG`

>>> Rubric(2, slips={"atan_quadrant": 0.25}).share_of("atan_quadrant")
0.25
"""

from ._credit import Credit
from ._points import credit_counts, graded_entries, points_for
from ._rubric import SLIP_WORDS, Award, Rubric, award, names_a_slip
from ._shortcuts import FLAG, robotconf_calls
from ._weights import Weights, find_weights, read_weights

__all__ = [
    "Credit",
    "Rubric",
    "award",
    "Award",
    "names_a_slip",
    "SLIP_WORDS",
    "points_for",
    "credit_counts",
    "graded_entries",
    "read_weights",
    "find_weights",
    "Weights",
    "robotconf_calls",
    "FLAG",
]
