"""Validators for the fields of moves and programs; each error names its field.

A program's numbers are bounded like a robot's (:mod:`robotconf.kinematics.conventions._bounds`), so
that planning can neither overflow nor divide by zero:

- targets, via points, pose translations and PTP coordinates: finite, ``|x| ≤``
  :data:`~robotconf.kinematics.MAX_PARAMETER` (1e150);
- speeds and accelerations (of a move, and the program's limits): from
  ``1/MAX_PARAMETER`` (1e-150) to ``MAX_PARAMETER``, so a time ``length / speed`` or
  ``speed / accel`` stays finite;
- waits, each move's duration and the whole program: at most
  :data:`~robotconf.motion.MAX_TIME` (10⁹ s), the longest run a simulation takes.

A move checks the bounds of its numbers when it is made (:func:`check_move_numbers`);
the program checks the rest against its robot (signs, shapes for its joints,
reachability) and the durations once it has planned them (:func:`check_duration`).
"""

from __future__ import annotations

from dataclasses import fields
from typing import Any

import numpy as np

from .._budget import check_finite_result
from .._errors import InvalidInputError
from .._validation import as_float_array, check_finite_number, one_line
from ..kinematics import MAX_PARAMETER, check_parameter_vector, check_rigid_pose
from ..motion import MAX_TIME

__all__ = [
    "MIN_RATE",
    "positive",
    "seconds",
    "point",
    "pose",
    "choice",
    "rates",
    "check_move_numbers",
    "check_duration",
]

#: The smallest speed or acceleration: ``1 / MAX_PARAMETER``.
MIN_RATE = 1.0 / MAX_PARAMETER

#: Fields of a move that are rates (checked from MIN_RATE to MAX_PARAMETER) and durations.
_RATE_FIELDS = {"speed": "a path speed (length/s)", "accel": "a path acceleration (length/s²)"}
_DURATION_FIELDS = ("seconds",)
#: Fields of a move that hold coordinates: a target, a via point, a pose, PTP's q.
_COORDINATE_FIELDS = ("q", "pose", "position", "via", "end")


def _rate_range(what: str) -> str:
    return f"{what} from {MIN_RATE:.0e} to {MAX_PARAMETER:.0e}"


def _rate_magnitude(number: float, field: str, what: str) -> None:
    """Refuse a nonzero rate whose size is outside ``MIN_RATE … MAX_PARAMETER``."""
    size = abs(number)
    if size > MAX_PARAMETER:
        raise InvalidInputError(
            field, number, _rate_range(what), problem=f"too large (> {MAX_PARAMETER:.0e}):"
        )
    if 0.0 < size < MIN_RATE:
        raise InvalidInputError(
            field,
            number,
            _rate_range(what),
            problem=f"too small (< {MIN_RATE:.0e}: the move would take forever):",
        )


def positive(value: Any, field: str, what: str) -> float:
    """A speed or an acceleration: finite, > 0, from ``MIN_RATE`` to ``MAX_PARAMETER``.

    >>> positive(20, "speed", "a speed (length/s)")
    20.0
    >>> positive(-1, "speed", "a speed (length/s)")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: speed: must be > 0, got -1.0; allowed: a speed (length/s) from ...
    >>> positive(1e-308, "speed", "a speed (length/s)")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: speed: too small (< 1e-150: the move would take forever): ...
    """
    number = check_finite_number(value, field)
    if not number > 0.0:
        raise InvalidInputError(field, number, _rate_range(what), problem="must be > 0, got")
    _rate_magnitude(number, field, what)
    return number


def seconds(value: Any, field: str) -> float:
    """A duration of at least 0 and at most ``MAX_TIME`` seconds.

    >>> seconds(0.5, "seconds")
    0.5
    """
    number = check_finite_number(value, field)
    if not 0.0 <= number <= MAX_TIME:
        raise InvalidInputError(
            field, number, f"a duration from 0 to {MAX_TIME:g} s", problem="out of range:"
        )
    return number


def point(value: Any, field: str) -> tuple[float, float, float]:
    """Three finite coordinates (length), each ``|x| ≤ MAX_PARAMETER``.

    >>> point([60, 10, 30], "position")
    (60.0, 10.0, 30.0)
    >>> point([1e155, 0, 0], "position")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: position: entry 0 is too large (|x| > 1e+150): ...
    """
    return check_parameter_vector(value, field)


def pose(value: Any, field: str) -> tuple[tuple[float, ...], ...]:
    """A homogeneous 4×4 pose as nested tuples, checked like ``rc.ik`` checks targets.

    >>> pose(np.eye(4), "pose")[3]
    (0.0, 0.0, 0.0, 1.0)
    >>> pose(np.diag([1.0, 1.0, -1.0, 1.0]), "pose")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: pose: the rotation is a reflection (det −1): ...
    """
    array = check_rigid_pose(value, field)
    return tuple(tuple(float(x) for x in row) for row in array)


def choice(value: Any, field: str, choices: tuple[str, ...]) -> str:
    """One of ``choices`` (any case).

    >>> choice("Quintic", "profile", ("trapezoidal", "quintic"))
    'quintic'
    """
    allowed = " or ".join(repr(c) for c in choices)
    if not isinstance(value, str):
        raise InvalidInputError(field, one_line(value), allowed, problem="expected text, got")
    name = value.strip().lower()
    if name not in choices:
        raise InvalidInputError(field, value, allowed, problem="unknown value")
    return name


def rates(value: Any, n: int, field: str, what: str) -> float | tuple[float, ...]:
    """One limit for every joint, or one per joint: each finite and > 0.

    >>> rates([1, 2], 2, "joint_speed", "a joint speed")
    (1.0, 2.0)
    """
    array = as_float_array(value, field, f"{what} > 0, or {n} of them (one per joint)")
    if array.shape == ():
        return positive(float(array), field, what)
    if array.shape != (n,):
        raise InvalidInputError(
            field,
            one_line(value),
            f"one number, or {n} (one per joint)",
            problem=f"expected shape () or ({n},), got {array.shape}:",
        )
    return tuple(positive(x, f"{field}[{j}]", what) for j, x in enumerate(array.tolist()))


def _bounded_numbers(value: Any, field: str) -> None:
    """Numbers of any shape (a target, a point, a pose, coordinates): finite, real, each
    ``|x| ≤ MAX_PARAMETER``."""
    allowed = f"finite numbers with |x| ≤ {MAX_PARAMETER:.0e}"
    array = as_float_array(value, field, allowed)
    finite = np.isfinite(array)
    if not finite.all():
        bad = array.ravel()[int(np.flatnonzero(~finite.ravel())[0])]
        raise InvalidInputError(
            field, one_line(value), allowed, problem=f"must be finite, got {bad}:"
        )
    if array.size and float(np.max(np.abs(array))) > MAX_PARAMETER:
        raise InvalidInputError(
            field, one_line(value), allowed, problem=f"too large (|x| > {MAX_PARAMETER:.0e}):"
        )


def check_move_numbers(move: Any) -> None:
    """Refuse a move whose numbers are out of the program bounds (see the module notes),
    when the move is made: each error names the move's field.

    What the numbers mean for a robot (a speed > 0, as many coordinates as joints, a
    reachable target) is checked by the program that runs the move.

    >>> from robotconf.programs import LIN
    >>> LIN(position=[1e155, 0, 0])
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: position: too large (|x| > 1e+150): [1e+155, 0, 0]; ...
    >>> LIN(position=[60, 10, 30], speed=1e-308)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: speed: too small (< 1e-150: the move would take forever): ...
    """
    for item in fields(move):
        value = getattr(move, item.name)
        if value is None:
            continue  # not given; choices and names are the program's to check
        if item.name in _COORDINATE_FIELDS:
            _bounded_numbers(value, item.name)
        elif item.name in _RATE_FIELDS:
            number = check_finite_number(value, item.name)
            _rate_magnitude(number, item.name, _RATE_FIELDS[item.name])
        elif item.name in _DURATION_FIELDS:
            number = check_finite_number(value, item.name)
            if abs(number) > MAX_TIME:
                raise InvalidInputError(
                    item.name,
                    number,
                    f"a duration from 0 to {MAX_TIME:g} s",
                    problem="out of range:",
                )


def check_duration(
    duration: float, peaks: tuple[float, ...], field: str, value: Any, what: str = "the move"
) -> None:
    """Refuse a planned move (or program, ``what``) longer than ``MAX_TIME``, or whose time
    law overflowed (``peaks``: its peak rates); ``field`` and ``value`` name the setting
    responsible.

    >>> check_duration(2.5, (0.5, 1.0), "speed", 10.0)
    >>> check_duration(3e9, (1e-9, 1e-18), "speed", 1e-8)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: speed: the move would take 3e+09 s, longer than 1e+09 s, with ...
    """
    check_finite_result([duration, *peaks], field, value, f"the time law of {what}")
    if duration > MAX_TIME:
        raise InvalidInputError(
            field,
            value,
            f"settings that keep each move and the program within {MAX_TIME:g} s",
            problem=f"{what} would take {duration:.3g} s, longer than {MAX_TIME:g} s, with",
        )
