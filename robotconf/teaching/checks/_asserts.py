"""The autograder forms of the answer checks: raise ``AssertionError`` with the hints.

Made for a course notebook's check cell: the failure message is what the student reads,
its first line saying what is wrong and one line per hint, without the checker's frames
(as :func:`~robotconf.teaching.assert_matrix` does). Expected values stay hidden unless
``reveal=True``.
"""

from __future__ import annotations

from typing import Any

from ..reading._wrapper import passed
from ._interval import check_interval
from ._numbers import check_angle, check_value, check_vector
from ._result import AnswerCheck
from ._sets import check_set

__all__ = ["assert_angle", "assert_interval", "assert_set", "assert_value", "assert_vector"]


def assert_value(answer: Any, expected: Any, **options: Any) -> AnswerCheck:
    """Like :func:`check_value`, but raise ``AssertionError`` with the hints if wrong.

    Parameters
    ----------
    answer, expected
        As in :func:`check_value`.
    **options
        ``tol``, ``rel``, ``unit``, ``name``, ``reveal``, ``hint``, ``limits``.

    Returns
    -------
    AnswerCheck
        When the answer is right.

    Raises
    ------
    AssertionError
        When it is wrong or missing (``None``).

    Examples
    --------
    >>> assert_value("pi/2", 1.5708).ok
    True
    >>> assert_value(-1.0, 1.0, name="det J")
    Traceback (most recent call last):
    ...
    AssertionError: det J: not right yet.
    - det J has the wrong sign.
    """
    return passed(check_value(answer, expected, **options))


def assert_vector(answer: Any, expected: Any, **options: Any) -> AnswerCheck:
    """Like :func:`check_vector`, but raise ``AssertionError`` with the hints if wrong.

    Parameters
    ----------
    answer, expected
        As in :func:`check_vector`.
    **options
        ``tol``, ``rel``, ``unit``, ``name``, ``components``, ``reveal``, ``hint``,
        ``limits``.

    Returns
    -------
    AnswerCheck

    Raises
    ------
    AssertionError

    Examples
    --------
    >>> assert_vector([0, 35, 40], [0, 35, -40], name="the velocity")
    Traceback (most recent call last):
    ...
    AssertionError: the velocity: 1 wrong component (z).
    - The sign of z is wrong.
    """
    return passed(check_vector(answer, expected, **options))


def assert_angle(answer: Any, expected: Any, **options: Any) -> AnswerCheck:
    """Like :func:`check_angle`, but raise ``AssertionError`` with the hints if wrong.

    Parameters
    ----------
    answer, expected
        As in :func:`check_angle`.
    **options
        ``tol``, ``rel``, ``period``, ``degrees``, ``name``, ``components``, ``reveal``,
        ``hint``, ``limits``.

    Returns
    -------
    AnswerCheck

    Raises
    ------
    AssertionError

    Examples
    --------
    >>> assert_angle(138.59, 2.4189, name="q3")
    Traceback (most recent call last):
    ...
    AssertionError: q3: not right yet.
    - You gave degrees: write q3 in radians (180° = π).
    """
    return passed(check_angle(answer, expected, **options))


def assert_set(answer: Any, expected_set: Any, **options: Any) -> AnswerCheck:
    """Like :func:`check_set`, but raise ``AssertionError`` with the hints if wrong.

    Parameters
    ----------
    answer, expected_set
        As in :func:`check_set`.
    **options
        ``tol``, ``rel``, ``period``, ``unit``, ``name``, ``labels``, ``reveal``,
        ``hint``, ``limits``.

    Returns
    -------
    AnswerCheck

    Raises
    ------
    AssertionError

    Examples
    --------
    >>> assert_set([0, 0], [0, 3.1416], name="the singular q2")
    Traceback (most recent call last):
    ...
    AssertionError: the singular q2: 1 of 2 solutions right, 1 not.
    - 0 is given more than once: give each solution once.
    - You gave 1 of the 2 solutions; 1 is missing.
    """
    return passed(check_set(answer, expected_set, **options))


def assert_interval(answer: Any, expected_lo_hi: Any, **options: Any) -> AnswerCheck:
    """Like :func:`check_interval`, but raise ``AssertionError`` with the hints if wrong.

    Parameters
    ----------
    answer, expected_lo_hi
        As in :func:`check_interval`.
    **options
        ``tol``, ``rel``, ``unit``, ``name``, ``reveal``, ``hint``, ``limits``.

    Returns
    -------
    AnswerCheck

    Raises
    ------
    AssertionError

    Examples
    --------
    >>> assert_interval([70, 10], [10, 70], name="the reach")
    Traceback (most recent call last):
    ...
    AssertionError: the reach: the ends are swapped.
    - The ends are swapped: write the smaller one first, [lo, hi].
    """
    return passed(check_interval(answer, expected_lo_hi, **options))
