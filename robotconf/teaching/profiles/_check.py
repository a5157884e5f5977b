"""Checks for motion-profile answers: a trapezoid's times, a duration, peaks, coefficients.

:func:`check_profile` judges an answer about a rest-to-rest move against a
:class:`ProfileTask` (the move as the exercise states it) and names the usual slips: a
velocity that does not come back to zero at the end (or does not start at rest), a
forgotten synchronization (each joint with its own duration instead of the slowest
joint's), a triangle treated as a trapezoid (a peak speed above what the distance
allows), the acceleration time as ``2v/a`` or ``v/(2a)`` instead of ``v/a``, the ramps
left out, the cubic's numbers for the quintic's (or back), coefficients in normalized
time or in reverse order. Equivalent answers pass: text such as ``"15/8*0.6/2"``, a row
or a column, a trapezoid as a dict, a duration repeated for every joint, a cubic with
``a4 = a5 = 0``, a (times × joints) table either way round. :func:`assert_profile` is
the autograder form.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..checks._input import NO_ANSWER, read_options
from ..checks._numbers import finish
from ..checks._result import AnswerCheck, explains_all
from ..diagnosis._components import Setting, close, explain_components, names_text
from ..reading._parser import ParserLimits
from ..reading._shown import number_text, sentence
from ..reading._tolerance import ABS_TOL, REL_TOL
from ..reading._wrapper import answer_check, passed
from ._answer import (
    arrange,
    component_names,
    equal,
    read_answer,
    refuse_dict,
    structural,
)
from ._slips import profile_slips
from ._task import ProfileTask

__all__ = ["assert_profile", "check_profile"]

_WHAT = {
    "parameters": "the trapezoid",
    "duration": "the duration",
    "peak_speed": "the peak speed",
    "peak_accel": "the peak acceleration",
    "coefficients": "the coefficients",
    "velocity": "the velocity",
}


def _show(values: np.ndarray, setting: Setting) -> str:
    flat = [number_text(x) for x in np.asarray(values, dtype=float).reshape(-1)]
    text = flat[0] if np.ndim(values) == 0 else f"[{', '.join(flat)}]"
    return text + (f" {setting.unit}" if setting.unit else "")


def _verdict(
    task: ProfileTask,
    form: str,
    times: Any,
    answer: Any,
    setting: Setting,
    what: str,
    hint: str | None,
    limits: ParserLimits | None,
) -> AnswerCheck:
    expected = task.expected(form, times)
    if answer is None:
        headline = f"{what}: no answer yet."
        return AnswerCheck(False, [NO_ANSWER], "no_answer", what, None, expected, headline=headline)
    reading = read_answer(answer, limits)
    if reading.problem == "not_a_number":
        text = f"{sentence(what)} still holds {reading.detail}: give numbers, worked out."
        return finish(False, [text], ["not_a_number"], what, None, expected, hint)
    if reading.problem == "too_complicated":
        text = f"{sentence(what)} is too complicated to check: simplify it first."
        return finish(False, [text], ["too_complicated"], what, None, expected, hint)
    names = component_names(task, form, times, expected.size)
    if reading.values is None:  # a dict with other keys
        text = (
            f"Give {what} as [t_accel, t_total, v_peak], or a dict with exactly these keys "
            f"(you gave {reading.detail})."
        )
        return finish(False, [text], ["shape"], what, None, expected, hint)
    values = reading.values
    student = arrange(values, expected.shape, form)
    if equal(student, expected, setting, form):
        return AnswerCheck(True, [], None, what, student, expected)
    # the one duration, repeated for every joint
    per_joint = form == "duration" and task.n > 1 and values.size == task.n
    if per_joint and min(values.shape) == 1:
        repeated = np.full(task.n, float(expected))
        if close(values.reshape(-1), repeated, setting, None).all():
            return AnswerCheck(True, [], None, what, values.reshape(-1), expected)
    more: dict[str, Any] = {"reveal": setting.reveal}
    if student is not None and student.shape == expected.shape and expected.ndim:
        # the numbers that are wrong, for per-number credit whatever the diagnosis
        misses = ~close(student.reshape(-1), expected.reshape(-1), setting, None)
        more["wrong"] = [int(i) for i in np.flatnonzero(misses)]
    right = f" The right {what}: {_show(expected, setting)}." if setting.reveal else ""
    # Two slips may give the same numbers (T = d/v + v/(2a) is a missing ramp down, or
    # t_a = v/(2a)): every hint that fits is given, the first one's code leads.
    matched = [
        slip
        for slip in profile_slips(task, form, times)
        if equal(arrange(values, slip.values.shape, form), slip.values, setting, form)
    ]
    if matched:
        texts = list(dict.fromkeys(slip.hint for slip in matched))
        texts[-1] += right
        codes = [slip.code for slip in matched]
        shown = values if student is None else student
        # Each matched slip gives exactly the answer's numbers: it explains all of them.
        return finish(False, texts, codes, what, shown, expected, hint, complete=True, **more)
    if student is None or student.shape != expected.shape:
        count = values.size
        wanted = expected.size
        listed = f" ({names_text(names, most=4)})" if wanted > 1 else ""
        text = f"Give {what} as {'one number' if wanted == 1 else f'{wanted} numbers'}"
        text += f"{listed}; you gave {count}."
        if form == "duration" and task.n > 1 and count == task.n:
            text = (
                f"{sentence(what)} is one number: a synchronized move has one duration for "
                "all joints."
            )
        return finish(False, [text], ["shape"], what, values, expected, hint, **more)
    found = structural(task, form, times, student, setting)
    entries = list(reading.entries)
    if len(entries) != student.size:
        entries = [number_text(x) for x in student.reshape(-1)]
    elif values.shape != student.shape and values.T.shape == student.shape:
        entries = list(np.array(entries).reshape(values.shape).T.reshape(-1))
    flat_names = names if expected.ndim else [what]
    wrong, hints, codes = explain_components(
        student.reshape(-1), expected.reshape(-1), setting, flat_names, entries, what
    )
    complete = explains_all(codes)
    if found is not None:
        code, text = found
        if code == "distance_not_covered" and complete:
            # one slip (times swapped, too few digits) explains every wrong number, and
            # the distance missed follows from it: the slip leads, the distance is a note
            hints, codes = [*hints, text + right], [*codes, code]
        else:
            hints, codes = [text + right, *hints], [code, *codes]
            complete = explains_all(codes)
    if expected.ndim == 0:
        headline = f"{what}: not right yet."
    else:
        count = len(wrong)
        wrong_names = names_text([flat_names[i] for i in wrong])
        headline = f"{what}: {count} wrong number{'s' if count != 1 else ''} ({wrong_names})."
    return finish(
        False,
        hints,
        codes,
        what,
        student,
        expected,
        hint,
        wrong=wrong,
        headline=headline,
        reveal=setting.reveal,
        complete=complete,
    )


@answer_check(kind="profile")
def check_profile(
    answer: Any,
    expected: ProfileTask,
    *,
    form: str | None = None,
    times: Any = None,
    tol: float = ABS_TOL,
    rel: float = REL_TOL,
    unit: str | None = None,
    name: str | None = None,
    reveal: bool = False,
    hint: str | None = None,
    limits: ParserLimits | None = None,
) -> AnswerCheck:
    """Check an answer about a rest-to-rest move: a trapezoid, a duration, peaks, a polynomial.

    Parameters
    ----------
    answer : number, list, ndarray, text, dict or None
        In the layout of ``form``: ``[t_accel, t_total, v_peak]`` (or a dict with these
        keys), one number, one per joint, ``[a0, a1, …]``, or velocities at ``times``
        (shape (k,), or (k, n) for n joints, either way round). Text is parsed by the
        whitelist parser, never evaluated; ``None`` (not answered yet) fails kindly.
    expected : ProfileTask
        The move as the task states it; the right numbers and the slips come from it.
    form : str, optional
        What the answer is (:data:`PROFILE_FORMS`): ``"parameters"``, ``"duration"``,
        ``"peak_speed"``, ``"peak_accel"``, ``"coefficients"`` or ``"velocity"``.
        Default: ``"parameters"`` for a one-joint trapezoid, ``"coefficients"`` for a
        one-joint cubic or quintic, ``"duration"`` for several joints.
    times : array-like, shape (k,), optional
        The sample times (s) of a ``"velocity"`` answer (and only then).
    tol, rel : float
        Each number is right within ``max(tol, rel·|expected|)``: 0.5 %, or 0.001 near
        zero, by default.
    unit : str, optional
        Shown with quoted numbers.
    name : str, optional
        What the answer is called in the messages (default from the form: ``"the
        trapezoid"``, ``"the duration"``, …).
    reveal : bool
        Whether hints may quote the right numbers (by default they do not).
    hint : str, optional
        The exercise's own advice, added after the diagnosis.
    limits : ParserLimits, optional
        Caps for parsing text.

    Returns
    -------
    AnswerCheck
        ``.ok``, ``.hints``, ``.diagnosis``: one of :data:`PROFILE_DIAGNOSES`
        (``not_at_rest_end``, ``not_synchronized``, ``triangle_as_trapezoid``,
        ``accel_time_factor``, ``cubic_quintic_swapped``, …) or of ``check_value``'s
        (``sign_error``, ``unit_factor``, ``too_rounded``, ``shape``, ``not_a_number``,
        ``no_answer``, ``wrong``).

    Raises
    ------
    InvalidInputError
        For input the whitelist parser refuses (text outside it, NaN, infinities,
        imaginary or too large values), an ``expected`` that is not a ProfileTask, a
        form the task does not have, ``times`` without ``form="velocity"`` (or
        missing with it), and bad options.

    Examples
    --------
    A joint moves 2 rad at most 1 rad/s and 2 rad/s²:

    >>> task = ProfileTask(2.0, speed=1.0, accel=2.0)
    >>> check_profile([0.5, 2.5, 1.0], task).ok
    True
    >>> print(check_profile([1.0, 3.0, 1.0], task))  # t_a = 2v/a
    the trapezoid: not right yet.
    - The acceleration time is twice too long: reaching the speed v at the acceleration a ...

    Three joints, synchronized; each given its own duration:

    >>> sync = ProfileTask([0.5, -1.0, 1.5], speed=1.0, accel=2.0)
    >>> check_profile([1.0, 1.5, 2.0], sync).diagnosis
    'not_synchronized'
    """
    if not isinstance(expected, ProfileTask):
        raise InvalidInputError(
            "expected", expected, "a ProfileTask (rc.ProfileTask(distance, speed=…, accel=…))"
        )
    form = expected.check_form(form, times)
    refuse_dict(answer, form)
    options = read_options(name, _WHAT[form], tol=tol, rel=rel, unit=unit, reveal=reveal, hint=hint)
    return _verdict(
        expected, form, times, answer, options.setting, options.name, options.hint, limits
    )


def assert_profile(answer: Any, expected: ProfileTask, **options: Any) -> AnswerCheck:
    """Like :func:`check_profile`, but raise ``AssertionError`` with the hints if wrong.

    Parameters
    ----------
    answer, expected
        As in :func:`check_profile`.
    **options
        ``form``, ``times``, ``tol``, ``rel``, ``unit``, ``name``, ``reveal``, ``hint``,
        ``limits``.

    Returns
    -------
    AnswerCheck
        When the answer is right.

    Raises
    ------
    AssertionError
        When it is wrong or missing (``None``); the message is the verdict.

    Examples
    --------
    >>> task = ProfileTask(0.125, speed=1.0, accel=2.0)  # d < v²/a: a triangle
    >>> assert_profile([0.5, 0.625, 1.0], task)  # t_a = v/a, T = d/v + v/a
    Traceback (most recent call last):
    ...
    AssertionError: the trapezoid: not right yet.
    - The distance is too short to reach the speed limit (d < v_max²/a_max): the profile ...
    """
    return passed(check_profile(answer, expected, **options))
