"""Checks: the verdict on a student's answer, with the primary diagnosis as a hint.

Every check reads the answer through the whitelist parser and numeric judge
(:mod:`robotconf.teaching.reading`), decides by numbers at seeded points, and names the
mistake (:mod:`robotconf.teaching.diagnosis`) without quoting the expected value unless
``reveal=True``. Each ``check_*`` returns a verdict; each ``assert_*`` form raises
``AssertionError`` with the hints (for autograder cells). Both run through one wrapper
(:mod:`._wrapper`): bad input becomes one short :class:`~robotconf.InvalidInputError`
line without the checker's frames.

Matrices
    :func:`check_matrix`, :func:`assert_matrix`, :class:`MatrixCheck`,
    :data:`MATRIX_DIAGNOSES`
Numbers, vectors, angles, sets, intervals
    :func:`check_value`, :func:`check_vector`, :func:`check_angle`, :func:`check_set`,
    :func:`check_interval`, their ``assert_*`` forms, :class:`AnswerCheck`,
    :data:`DIAGNOSES`
DH tables (judged by the robot they describe)
    :func:`check_dh_table`, :func:`assert_dh_table`, :class:`DHTableCheck`,
    :func:`parse_dh_rows`, :data:`DH_DIAGNOSES`

>>> check_value("pi", 3.14159).ok
True
"""

from ._asserts import assert_angle, assert_interval, assert_set, assert_value, assert_vector
from ._dh_table import DH_DIAGNOSES, DHTableCheck, assert_dh_table, check_dh_table
from ._dh_table_text import parse_dh_rows
from ._interval import check_interval
from ._matrix import assert_matrix, check_matrix
from ._matrix_result import MATRIX_DIAGNOSES, MatrixCheck
from ._numbers import check_angle, check_value, check_vector
from ._result import DIAGNOSES, AnswerCheck
from ._sets import check_set

__all__ = [
    "check_matrix",
    "assert_matrix",
    "MatrixCheck",
    "MATRIX_DIAGNOSES",
    "check_value",
    "check_vector",
    "check_angle",
    "check_set",
    "check_interval",
    "assert_value",
    "assert_vector",
    "assert_angle",
    "assert_set",
    "assert_interval",
    "AnswerCheck",
    "DIAGNOSES",
    "check_dh_table",
    "assert_dh_table",
    "DHTableCheck",
    "DH_DIAGNOSES",
    "parse_dh_rows",
]
