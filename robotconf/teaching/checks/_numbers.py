"""Checks for answers that are not matrices: one value, a vector, angles.

:func:`check_value`, :func:`check_vector` and :func:`check_angle` judge a number, a
position or velocity, and angles modulo a full turn; sets of solutions and intervals are in
:mod:`robotconf.teaching.checks._sets`, the ``assert_*`` forms for autograder cells
in :mod:`robotconf.teaching.checks._asserts`. All of them read the student's answer
through :func:`~robotconf.teaching.check_matrix`'s whitelist parser and numeric judge, so
an answer may be a number, a list, an array or text such as ``"pi/2"`` or
``"[0, 35, -40]"``; text is never evaluated.

**In a course notebook** a check cell keeps its "not answered yet" line and then calls one
assert, e.g. ``rc.assert_value(answer_4, expected_4, name="dq3/dt at t = 2 s",
unit="rad/s", hint="…")``. An answer passes when every number is within
``max(tol, rel·|expected|)`` of the expected one (by default 0.5 %, or 0.001 near zero:
the course's rule, 3 significant digits pass), so 3.14 and ``"pi"`` pass for π and 1.57
for π/2; a wrong one gets the recognised
mistake (wrong sign, swapped components, degrees for radians, a unit factor of 1000, a half
turn, too few digits, a missing or repeated solution, swapped interval ends) without the
expected value, unless ``reveal=True``. ``hint=`` adds the exercise's own sentence.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_finite_number, check_flag
from ..diagnosis._components import Setting, explain_components, names_text
from ..reading._parser import ParserLimits
from ..reading._shown import sentence
from ..reading._tolerance import ABS_TOL, REL_TOL
from ..reading._wrapper import answer_check
from ._input import (
    NO_ANSWER,
    component_names,
    expected_numbers,
    parse_answer,
    read_options,
)
from ._result import AnswerCheck, explains_all

__all__ = ["check_angle", "check_value", "check_vector", "finish", "judge_components"]


def finish(
    ok: bool,
    hints: list[str],
    codes: list[str],
    name: str,
    student: Any,
    expected: Any,
    hint: str | None,
    **more: Any,
) -> AnswerCheck:
    """The :class:`AnswerCheck`, with the exercise's own ``hint`` after the diagnosis."""
    if ok:
        return AnswerCheck(True, [], None, name, student, expected, **more)
    if hint and codes[:1] != ["no_answer"]:
        hints = [*hints, hint]
    more.setdefault("complete", explains_all(codes))
    return AnswerCheck(
        False, hints, codes[0] if codes else "wrong", name, student, expected, **more
    )


def _no_answer(name: str, expected: Any) -> AnswerCheck:
    return AnswerCheck(
        False, [NO_ANSWER], "no_answer", name, None, expected, headline=f"{name}: no answer yet."
    )


def _shape_hint(what: str, names: list[str], values: np.ndarray) -> str:
    n, k = len(names), values.size
    if n == 1:
        return f"{sentence(what)} is one number; you gave {k}."
    if min(values.shape) > 1:
        got = f"a {values.shape[0]}×{values.shape[1]} matrix"
    else:
        got = f"{k} number{'s' if k != 1 else ''}"
    text = f"{sentence(what)} has {n} components ({', '.join(names)}); you gave {got}."
    if k == n + 1 and min(values.shape) == 1 and values.flat[-1] == 1:
        text += f" Leave out the homogeneous 1: give [{', '.join(names)}]."
    return text


def judge_components(
    answer: Any,
    expected: np.ndarray,
    setting: Setting,
    names: list[str],
    what: str,
    hint: str | None,
    limits: ParserLimits | None,
    scalar: bool = False,
    part: str = "component",
) -> AnswerCheck:
    """Judge an answer of n numbers against ``expected`` (shape (n,)) component by component.

    The result's ``student`` and ``expected`` have shape () for a ``scalar`` (n = 1, and
    ``names`` is ``[what]``), else (n,). ``part`` names the components in the headline
    (``"1 wrong angle (angle 2)"``).
    """
    shape = () if scalar else expected.shape
    reference = expected.reshape(shape)
    if answer is None:
        return _no_answer(what, reference)
    parsed = parse_answer(answer, limits)
    if parsed.symbols:
        held = ", ".join(parsed.symbols)
        number = "a number" if expected.size == 1 else "numbers"
        text = f"{sentence(what)} still holds {held}: give {number}, worked out."
        return finish(False, [text], ["not_a_number"], what, None, reference, hint)
    if parsed.values is None:
        text = f"{sentence(what)} is too complicated to check: simplify it first."
        return finish(False, [text], ["too_complicated"], what, None, reference, hint)
    values = parsed.values
    if values.size != expected.size or min(values.shape) != 1:
        text = _shape_hint(what, names, values)
        return finish(False, [text], ["shape"], what, values, reference, hint)
    student = values.reshape(-1)
    wrong, hints, codes = explain_components(
        student, expected, setting, names, parsed.entries, what
    )
    count = len(wrong)
    if shape == ():
        headline = f"{what}: not right yet."
    else:
        wrong_names = names_text([names[i] for i in wrong])
        headline = f"{what}: {count} wrong {part}{'s' if count != 1 else ''} ({wrong_names})."
    return finish(
        not wrong,
        hints,
        codes,
        what,
        student.reshape(shape),
        reference,
        hint,
        wrong=wrong,
        headline=headline,
        reveal=setting.reveal,
    )


@answer_check(kind="value")
def check_value(
    answer: Any,
    expected: Any,
    *,
    tol: float = ABS_TOL,
    rel: float = REL_TOL,
    unit: str | None = None,
    name: str | None = None,
    reveal: bool = False,
    hint: str | None = None,
    limits: ParserLimits | None = None,
) -> AnswerCheck:
    """Check one number: a rate, a length, a determinant at a point.

    Parameters
    ----------
    answer : number, text, sympy number or None
        ``-99``, ``"(0.01 - 1.99) / (2*0.01)"``, ``"pi/2"``; text is parsed by the
        whitelist parser, never evaluated. ``None`` (not answered yet) fails with a hint.
    expected : number
        The reference (a float, numpy or sympy number).
    tol, rel : float
        The answer is right when ``|answer − expected| ≤ max(tol, rel·|expected|)``: by
        default within 0.5 %, or within 0.001 for values near zero: a number with 3
        significant digits passes (3.14 for π), one with 2 gets the rounding hint (3.1),
        3.2 does not pass.
    unit : str, optional
        Shown with quoted numbers (``"rad/s"``).
    name : str, optional
        What the value is, for the messages (default ``"the value"``).
    reveal : bool
        Whether hints may quote the expected value (by default they do not).
    hint : str, optional
        The exercise's own advice, added after the diagnosis when the answer is wrong.
    limits : ParserLimits, optional
        Caps for parsing text.

    Returns
    -------
    AnswerCheck
        Diagnoses: ``sign_error``, ``degrees_as_radians``, ``unit_factor`` (×1000, ×100),
        ``too_rounded`` (3.1 for π), ``shape`` (a list), ``not_a_number`` (``"q1"``),
        ``no_answer``, else ``wrong``.

    Raises
    ------
    InvalidInputError
        For input :func:`check_matrix` refuses (text outside the whitelist, a typing
        slip, NaN, infinities, imaginary values, robotconf's own results), for a value
        beyond the float range, and for a bad ``expected`` or option.

    Examples
    --------
    >>> check_value(3.1416, np.pi).ok, check_value("pi", np.pi).ok, check_value(3.2, np.pi).ok
    (True, True, False)
    >>> check_value(180, np.pi).hints
    ['You gave degrees: write the value in radians (180° = π).']
    >>> print(check_value(1.0, -99, name="dq3/dt", unit="rad/s"))
    dq3/dt: not right yet.
    - 1 rad/s is not right.
    """
    options = read_options(name, "the value", tol=tol, rel=rel, unit=unit, reveal=reveal, hint=hint)
    reference = expected_numbers(expected)
    if reference.size != 1:
        raise InvalidInputError("expected", expected, "one number (check_vector takes several)")
    name = options.name
    return judge_components(
        answer, reference.reshape(1), options.setting, [name], name, options.hint, limits, True
    )


def _vector_reference(expected: Any, what: str) -> np.ndarray:
    reference = expected_numbers(expected)
    if reference.ndim == 0:
        reference = reference.reshape(1)
    if reference.ndim > 1 and sorted(reference.shape)[:-1] == [1] * (reference.ndim - 1):
        reference = reference.reshape(-1)
    if reference.ndim != 1:
        raise InvalidInputError("expected", expected, f"{what}: one list of numbers")
    return reference


@answer_check(kind="vector")
def check_vector(
    answer: Any,
    expected: Any,
    *,
    tol: float = ABS_TOL,
    rel: float = REL_TOL,
    unit: str | None = None,
    name: str | None = None,
    components: Sequence[str] | None = None,
    reveal: bool = False,
    hint: str | None = None,
    limits: ParserLimits | None = None,
) -> AnswerCheck:
    """Check a vector: a position, a velocity, an axis; names the wrong components.

    Parameters
    ----------
    answer : list, ndarray, text or None, n numbers
        ``[0, 35, -40]``, ``"[0, 35, -40]"``, a row or a column.
    expected : array-like, shape (n,)
    tol, rel : float
        Each component is right within ``max(tol, rel·|expected component|)`` (0.5 %, or
        0.001 near zero, by default).
    unit : str, optional
        Shown with quoted numbers (``"mm/s"``).
    name : str, optional
        Default ``"the vector"``.
    components : sequence of str, optional
        Names of the components; default x, y, z (for n ≤ 3), else component 1, 2, ….
    reveal, hint, limits
        As in :func:`check_value`.

    Returns
    -------
    AnswerCheck
        ``wrong`` lists the wrong components. Diagnoses: ``sign_flipped`` (the whole
        vector), ``sign_error`` (some components), ``swapped_components``,
        ``degrees_as_radians``, ``unit_factor`` (×1000: mm for m), ``too_rounded``,
        ``shape`` (wrong length; an extra homogeneous 1 is named), ``not_a_number``,
        ``no_answer``, ``wrong``.

    Raises
    ------
    InvalidInputError
        As :func:`check_value`.

    Examples
    --------
    >>> result = check_vector([0, 35, 40], [0, 35, -40], name="the velocity")
    >>> print(result)
    the velocity: 1 wrong component (z).
    - The sign of z is wrong.
    >>> check_vector([35, 0, -40], [0, 35, -40]).hints
    ['x and y are swapped.']
    >>> check_vector([0.07, 0, 0.02], [70, 0, 20]).diagnosis
    'unit_factor'
    """
    options = read_options(
        name, "the vector", tol=tol, rel=rel, unit=unit, reveal=reveal, hint=hint
    )
    reference = _vector_reference(expected, "a vector")
    names = component_names(components, reference.size, "component")
    return judge_components(
        answer, reference, options.setting, names, options.name, options.hint, limits
    )


@answer_check(kind="angle")
def check_angle(
    answer: Any,
    expected: Any,
    *,
    tol: float | None = None,
    rel: float = REL_TOL,
    period: float | None = None,
    degrees: bool = False,
    name: str | None = None,
    components: Sequence[str] | None = None,
    reveal: bool = False,
    hint: str | None = None,
    limits: ParserLimits | None = None,
) -> AnswerCheck:
    """Check an angle, or a vector of angles, equal modulo a full turn.

    Parameters
    ----------
    answer : number, text, list or None
        ``2.4189``, ``"pi/2"``, ``[0, "-pi/2"]``.
    expected : number or array-like, shape (n,)
        In radians, or in degrees with ``degrees=True``.
    tol : float, optional
        Absolute tolerance in the angle's unit: by default 0.001 rad (0.0573° with
        ``degrees=True``).
    rel : float
        Relative tolerance: an angle is right within ``max(tol, rel·|expected|)`` of
        ``expected`` plus any whole number of periods.
    period : float, optional
        Default a full turn: 2π, or 360 with ``degrees=True``.
    degrees : bool
        The expected angles are in degrees (then radians are diagnosed).
    name : str, optional
        Default ``"the angle"`` (``"the angles"`` for several).
    components : sequence of str, optional
        Names of several angles; default angle 1, angle 2, ….
    reveal, hint, limits
        As in :func:`check_value`.

    Returns
    -------
    AnswerCheck
        Diagnoses: ``degrees_as_radians`` ("You gave degrees"), ``radians_as_degrees``,
        ``sign_error``, ``half_turn``, ``swapped_components``, ``too_rounded``,
        ``shape``, ``not_a_number``, ``no_answer``, ``wrong``.

    Raises
    ------
    InvalidInputError
        As :func:`check_value`, and for a period that is not a positive number.

    Examples
    --------
    >>> check_angle("-3*pi/2", np.pi / 2).ok, check_angle(1.5708, np.pi / 2).ok
    (True, True)
    >>> check_angle(90, np.pi / 2, name="q2").hints
    ['You gave degrees: write q2 in radians (180° = π).']
    >>> check_angle(-90, 270, degrees=True).ok
    True
    """
    degrees = check_flag(degrees, "degrees")
    if tol is None:
        tol = math.degrees(ABS_TOL) if degrees else ABS_TOL
    if period is None:
        period = 360.0 if degrees else 2 * math.pi
    period = check_finite_number(period, "period")
    if period <= 0:
        raise InvalidInputError("period", period, "a positive number (a full turn)")
    reference = _vector_reference(expected, "an angle or a list of angles")
    several = np.ndim(expected) > 0
    default = "the angles" if several else "the angle"
    options = read_options(
        name, default, tol=tol, rel=rel, reveal=reveal, hint=hint, period=period, degrees=degrees
    )
    name = options.name
    names = component_names(components, reference.size, "angle") if several else [name]
    return judge_components(
        answer, reference, options.setting, names, name, options.hint, limits, not several, "angle"
    )
