"""Reading a profile answer: its numbers, their layout, and what they say by themselves.

The numbers come from the answer checks' reader (:func:`parse_answer`: the whitelist
parser and numeric judge of :func:`~robotconf.teaching.check_matrix`; text is never
evaluated, NaN, infinities, imaginary and huge values are refused). Here they are laid
out like the form asked for — a row or a column for a list, either orientation for a
(times × joints) table — and checked for what is wrong whatever the right answer: a
velocity that is not zero where the move is at rest, a trapezoid whose numbers do not
cover the distance, a peak speed the distance does not allow.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..checks._input import parse_answer
from ..diagnosis._components import Setting, close
from ..reading._parser import ParserLimits
from ..reading._shown import number_text
from ._forms import check_times
from ._slips import HINTS
from ._task import ProfileTask

__all__ = ["PARAMETER_NAMES", "Reading", "arrange", "component_names", "read_answer", "structural"]

#: The components of a trapezoid answer, in order (also the keys of a dict answer).
PARAMETER_NAMES = ("t_accel", "t_total", "v_peak")


@dataclass(frozen=True)
class Reading:
    """A student's answer as numbers, or why there are none.

    Attributes
    ----------
    values : ndarray, shape (rows, cols), or None
    entries : list of str
        The entries as written, row by row.
    problem : str or None
        ``"not_a_number"`` (symbols left), ``"too_complicated"`` or ``"shape"`` (a dict
        with other keys); ``None`` when ``values`` is set.
    detail : str
        The symbols left, or the keys given.
    """

    values: np.ndarray | None
    entries: list[str]
    problem: str | None = None
    detail: str = ""


def _read_dict(answer: dict[Any, Any], limits: ParserLimits | None) -> Reading:
    """A trapezoid as ``{"t_accel": …, "t_total": …, "v_peak": …}``, keys in any order."""
    keys = list(answer)
    if len(keys) != 3 or set(keys) != set(PARAMETER_NAMES):
        shown = ", ".join(str(k)[:20] for k in keys[:6])
        return Reading(None, [], "shape", shown)
    values, entries, symbols = [], [], []
    for key in PARAMETER_NAMES:
        parsed = parse_answer(answer[key], limits)
        if parsed.symbols:
            symbols.extend(parsed.symbols)
        elif parsed.values is None:
            return Reading(None, [], "too_complicated")
        elif parsed.values.size != 1:
            return Reading(None, [], "shape", f"{key} holds {parsed.values.size} numbers")
        else:
            values.append(float(parsed.values.reshape(-1)[0]))
        entries.extend(parsed.entries)
    if symbols:
        return Reading(None, entries, "not_a_number", ", ".join(sorted(set(symbols))))
    return Reading(np.array([values]), entries)


def read_answer(answer: Any, limits: ParserLimits | None) -> Reading:
    """Parse an answer (not None) into a matrix of numbers.

    Raises
    ------
    InvalidInputError
        As :func:`check_matrix` does for text outside the whitelist, NaN, infinities,
        imaginary and too large values.
    """
    if isinstance(answer, dict):
        return _read_dict(answer, limits)
    parsed = parse_answer(answer, limits)
    if parsed.symbols:
        return Reading(None, parsed.entries, "not_a_number", ", ".join(parsed.symbols))
    if parsed.values is None:
        return Reading(None, parsed.entries, "too_complicated")
    return Reading(parsed.values, parsed.entries)


def arrange(values: np.ndarray, shape: tuple[int, ...], form: str) -> np.ndarray | None:
    """``values`` (rows, cols) laid out as ``shape``, or None when they do not fit.

    A list may be a row or a column; a (times × joints) table may be given either way
    round (when it is not square). Coefficients compare with zeros appended to the
    shorter list, so a cubic written with ``a4 = a5 = 0`` is the same polynomial.
    """
    if form == "coefficients" and min(values.shape) == 1:
        flat = values.reshape(-1)
        size = int(np.prod(shape))
        if flat.size < size:
            return np.concatenate([flat, np.zeros(size - flat.size)])
        if flat.size > size:
            return flat  # compared against the expected list padded by the caller
        return flat
    if len(shape) <= 1:
        size = int(np.prod(shape))
        if min(values.shape) == 1 and values.size == size:
            return values.reshape(shape)
        return None
    if values.shape == shape:
        return values
    if values.shape == shape[::-1]:
        return values.T
    return None


def equal(student: np.ndarray | None, reference: np.ndarray, setting: Setting, form: str) -> bool:
    """Every number of ``student`` equals ``reference`` within the tolerance."""
    if student is None:
        return False
    ref = reference
    if form == "coefficients" and student.size != ref.size:
        if student.size < ref.size:
            return False
        ref = np.concatenate([ref.reshape(-1), np.zeros(student.size - ref.size)])
    if student.shape != ref.shape:
        return False
    return bool(close(student, ref, setting, None).all())


def component_names(task: ProfileTask, form: str, times: Any, count: int) -> list[str]:
    """The names of the answer's numbers, as the hints call them."""
    if form == "parameters":
        return list(PARAMETER_NAMES)
    if form == "coefficients":
        return [f"a{k}" for k in range(count)]
    if form == "velocity":
        t = check_times(times)
        if task.n == 1:
            return [f"v(t = {number_text(x)} s)" for x in t]
        return [f"{joint} at t = {number_text(x)} s" for x in t for joint in task.joints]
    if task.n == 1 or form == "duration":
        return [form.replace("_", " ")]
    return list(task.joints)


def structural(
    task: ProfileTask,
    form: str,
    times: Any,
    student: np.ndarray,
    setting: Setting,
) -> tuple[str, str] | None:
    """(code, hint) for what is wrong with the answer by itself, or None.

    ``student`` is laid out as the form (see :func:`arrange`).
    """
    if form == "velocity":
        t = check_times(times)
        moving = (np.abs(student.reshape(t.size, -1)) > setting.tol).any(axis=1)
        if (moving & (t <= 0.0)).any():
            return "not_at_rest_start", (
                "The velocity does not start at zero: the move starts from rest, so the "
                "velocity at t = 0 is 0 and grows with the acceleration."
            )
        if (moving & (t >= task.duration * (1 - 1e-12))).any():
            return "not_at_rest_end", (
                "The velocity does not come back to zero: a rest-to-rest move ends at rest, "
                "so from the end of the move on the velocity is 0 (a ramp down, not a stop "
                "from full speed)."
            )
        return None
    if task.kind != "trapezoidal" or task.n != 1:
        return None
    limits = task.limits
    assert limits is not None
    reach = abs(float(task.distance[0]))
    allowed_peak = float(min(limits[0][0], np.sqrt(reach * limits[1][0])))
    peak = float(student[2]) if form == "parameters" else float(student)
    too_fast = abs(peak) > allowed_peak * (1 + setting.rel) + setting.tol
    if form in ("parameters", "peak_speed") and task.shape == "triangle" and too_fast:
        return "triangle_as_trapezoid", HINTS["triangle_as_trapezoid"]
    if form == "parameters":
        t_accel, t_total, v_peak = (float(x) for x in student)
        covered = abs(v_peak) * (t_total - t_accel)
        # a loose bound: rounding each number a little must not read as a wrong distance
        if abs(covered - reach) > max(3 * setting.tol, 0.01 * reach):
            unit = f" {setting.unit}" if setting.unit else ""
            return "distance_not_covered", (
                "Your three numbers do not belong together: a trapezoid with them covers "
                f"v_peak·(t_total − t_accel) = {number_text(covered)}{unit}, but the move is "
                f"d = {number_text(reach)}{unit} long (the area under the velocity is the "
                "distance)."
            )
    return None


def refuse_dict(answer: Any, form: str) -> None:
    """A dict is a trapezoid's form only."""
    if isinstance(answer, dict) and form != "parameters":
        raise InvalidInputError(
            "answer", answer, "a number, a list or text (a dict only for form='parameters')"
        )
