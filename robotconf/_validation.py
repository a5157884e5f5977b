"""Validators that turn user input into clean float arrays or raise InvalidInputError.

A *real number* here is a Python or numpy integer or float, or any object that converts
to one (``Decimal``, ``Fraction``). Booleans, complex numbers (even with a zero imaginary
part), dates and times, text and numpy text arrays are refused, never coerced: numpy would
turn ``True`` into 1, ``1+0j`` into 1 and a date into days since 1970.
"""

from __future__ import annotations

import datetime
from collections.abc import Sequence
from typing import Any

import numpy as np

from ._errors import InvalidInputError

__all__ = [
    "MAX_INTEGER_DIGITS",
    "as_float_array",
    "check_finite_number",
    "check_integer",
    "check_flag",
    "check_vector3",
    "check_joint_values",
    "check_configuration",
    "one_line",
]

_FINITE = "a finite real number"

#: Integers with more decimal digits than this are refused (a 128-bit seed has 39).
#: Python cannot even print integers of more than 4300 digits.
MAX_INTEGER_DIGITS = 40

_INTEGER_LIMIT = 10**MAX_INTEGER_DIGITS

# What a value is when numpy would coerce it to a number although it is not a real one,
# keyed by numpy dtype kind.
_NOT_REAL_KINDS = {
    "b": "a boolean is not a number",
    "c": "a complex number is not a real number (even with a zero imaginary part)",
    "M": "a date is not a number",
    "m": "a time span is not a number",
    "U": "text is not a number",
    "S": "text is not a number",
    "V": "a structured record is not a number",
}
_DATES = (datetime.date, datetime.time, datetime.timedelta)


class _Shown(str):
    """Text that an error message shows as it is (its repr has no quotes)."""

    __slots__ = ()

    def __repr__(self) -> str:
        return str(self)


class _ArrayShown:
    """A small array as an error message shows it, printed only when a message is made
    (numpy's printing costs far more than the checks it is passed to)."""

    __slots__ = ("_array",)

    def __init__(self, array: np.ndarray) -> None:
        self._array = array

    def __repr__(self) -> str:
        try:
            return repr(self._array).replace("\n", " ")
        except ValueError:  # an object array holding an integer too long to print
            return f"array of shape {self._array.shape} and dtype {self._array.dtype}"

    __str__ = __repr__


def one_line(value: Any) -> Any:
    """``value`` as an error message may show it: arrays on a single line, huge ints described.

    numpy prints a 2-D array over several lines and Python refuses to print integers of
    more than 4300 digits, so neither may reach a message as it is.

    >>> one_line(np.zeros((2, 3)))
    array of shape (2, 3) and dtype float64
    >>> one_line(np.arange(3.0)), one_line([1, 2])
    (array([0., 1., 2.]), [1, 2])
    >>> one_line(10**5000)
    <an integer of about 5001 digits>
    """
    if isinstance(value, np.ndarray):
        if value.ndim <= 1 and value.size <= 8:
            return _ArrayShown(value)
        return _Shown(f"array of shape {value.shape} and dtype {value.dtype}")
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) >= _INTEGER_LIMIT:
        return _Shown(f"<an integer of about {int(value.bit_length() * 0.30103) + 1} digits>")
    try:
        repr(value)
    except ValueError:  # e.g. a list holding an integer too long to print
        return _Shown(f"<a {type(value).__name__} too large to print>")
    return value


def _not_real(item: Any) -> str | None:
    """Why ``item`` is not a real number (None when it may be one)."""
    if isinstance(item, (bool, np.bool_)):
        return _NOT_REAL_KINDS["b"]
    if isinstance(item, (complex, np.complexfloating)):
        return _NOT_REAL_KINDS["c"]
    if isinstance(item, (str, bytes)):
        return _NOT_REAL_KINDS["U"]
    if isinstance(item, _DATES):
        return "a date or time is not a number"
    if isinstance(item, (np.generic, np.ndarray)):
        if item.dtype.kind == "O" and isinstance(item, np.ndarray):
            return _first_not_real(item.ravel().tolist())
        return _NOT_REAL_KINDS.get(item.dtype.kind)
    return None


def _first_not_real(items: list[Any] | tuple[Any, ...]) -> str | None:
    """Why the first offending entry of nested lists is not a real number, or None.

    numpy hides a ``True`` among numbers (``[1, True]`` becomes ``[1, 1]``), so the
    entries are looked at one by one; floats and ints, the common case, cost one type test.
    """
    stack = [items]
    while stack:
        for item in stack.pop():
            kind = type(item)
            if kind is float or kind is int:
                continue
            if kind is list or kind is tuple:
                stack.append(item)
                continue
            reason = _not_real(item)
            if reason is not None:
                return reason
    return None


def _refuse_not_real(value: Any, field: str, allowed: str, what: str, nested: bool) -> None:
    if isinstance(value, np.ndarray) and value.dtype.kind in "iuf":
        return
    reason = _first_not_real(value) if isinstance(value, (list, tuple)) else _not_real(value)
    if reason is None:
        return
    if reason.startswith("text"):
        # Text inside a list has always read "not numeric"; on its own it says what it is.
        problem = "not numeric:" if nested else f"text is not {what}:"
    else:
        problem = f"{reason}:"
    raise InvalidInputError(field, one_line(value), allowed, problem=problem)


def as_float_array(value: Any, field: str, allowed: str, what: str = "a number") -> np.ndarray:
    """``np.asarray(value, dtype=float)`` for real numbers only, refusing the rest clearly.

    Parameters
    ----------
    value : real number or array-like of them
        Booleans, complex numbers, dates and times, text, numpy text arrays and
        non-numeric objects are refused; ``Decimal`` and ``Fraction`` are fine.
    field : str
        Name used in the error message.
    allowed : str
        What is allowed, for the message.
    what : str
        What a single value should be, for the message about text.

    Returns
    -------
    ndarray
        Float64; not copied when ``value`` already is a float64 array. Not checked for
        NaN or infinity.

    Raises
    ------
    InvalidInputError
        For values that are not real numbers, or too large for a float.

    Examples
    --------
    >>> as_float_array([1, 2], "times", "numbers")
    array([1., 2.])
    >>> as_float_array(np.array([1 + 0j]), "a", "3 numbers")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: a: a complex number is not a real number (even with a zero ...
    """
    if isinstance(value, (str, bytes)):
        raise InvalidInputError(field, value, allowed, problem=f"text is not {what}:")
    if not isinstance(value, np.ndarray) and hasattr(value, "__array__"):
        # pandas, xarray and friends: look at their own dtype (a bool Series is no number).
        try:
            value = np.asarray(value)
        except (TypeError, ValueError):
            raise InvalidInputError(
                field, one_line(value), allowed, problem="not numeric:"
            ) from None
    _refuse_not_real(value, field, allowed, what, nested=isinstance(value, (list, tuple)))
    try:
        array = np.asarray(value, dtype=float)
    except OverflowError:
        raise InvalidInputError(
            field, one_line(value), allowed, problem="too large for a float (|x| < 1.8e308):"
        ) from None
    except (TypeError, ValueError):
        raise InvalidInputError(field, one_line(value), allowed, problem="not numeric:") from None
    return array


def check_finite_number(value: Any, field: str) -> float:
    """Return ``value`` as a finite Python float.

    Parameters
    ----------
    value : real number
        A number; booleans, complex numbers, dates, text and arrays are refused.
    field : str
        Name used in the error message.

    Returns
    -------
    float

    Raises
    ------
    InvalidInputError
        If ``value`` is not a real number, or is NaN or infinite.

    Examples
    --------
    >>> check_finite_number(3, "ax")
    3.0
    >>> check_finite_number(float("nan"), "ax")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: ax: must be finite, got nan; allowed: a finite real number
    """
    array = as_float_array(value, field, _FINITE)
    if array.shape != ():
        raise InvalidInputError(
            field,
            one_line(value),
            _FINITE,
            problem=f"expected one number, got shape {array.shape}:",
        )
    number = float(array)
    if not np.isfinite(number):
        raise InvalidInputError(field, number, _FINITE, problem="must be finite, got")
    return number


def check_integer(
    value: Any, field: str, lo: int | None = None, hi: int | None = None, what: str | None = None
) -> int:
    """Return ``value`` as a Python int within ``lo … hi`` (either bound may be open).

    Parameters
    ----------
    value : int
        A Python or numpy integer of at most :data:`MAX_INTEGER_DIGITS` digits; booleans,
        floats (even ``3.0``) and text are refused.
    field : str
        Name used in the error message.
    lo, hi : int, optional
        Inclusive bounds.
    what : str, optional
        What is allowed, for the message; default: the bounds in words.

    Returns
    -------
    int

    Raises
    ------
    InvalidInputError
        If ``value`` is not an integer or lies outside the bounds.

    Examples
    --------
    >>> check_integer(3, "samples", 1)
    3
    >>> check_integer(0, "active", 1, 3)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: active: out of range: 0; allowed: an integer from 1 to 3
    """
    if what is None:
        if lo is not None and hi is not None:
            what = f"an integer from {lo} to {hi}"
        elif lo is not None:
            what = f"an integer ≥ {lo}"
        elif hi is not None:
            what = f"an integer ≤ {hi}"
        else:
            what = "an integer"
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise InvalidInputError(field, one_line(value), what, problem="not an integer:")
    number = int(value)
    if abs(number) >= _INTEGER_LIMIT:
        raise InvalidInputError(
            field, one_line(number), what, problem=f"more than {MAX_INTEGER_DIGITS} digits:"
        )
    if (lo is not None and number < lo) or (hi is not None and number > hi):
        raise InvalidInputError(field, number, what, problem="out of range:")
    return number


def check_flag(value: Any, field: str) -> bool:
    """Return ``value`` if it is ``True`` or ``False`` (numpy booleans too).

    Numbers and text are refused, so ``"no"`` never counts as true.

    >>> check_flag(True, "labels")
    True
    >>> check_flag("no", "labels")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: labels: not True or False: 'no'; allowed: True or False
    """
    if not isinstance(value, (bool, np.bool_)):
        raise InvalidInputError(
            field, one_line(value), "True or False", problem="not True or False:"
        )
    return bool(value)


def check_vector3(value: Any, field: str) -> tuple[float, float, float]:
    """Return a 3-vector (``a`` offsets, an end-effector point) as a tuple of finite floats.

    Parameters
    ----------
    value : array-like, shape (3,)
        Three finite numbers (length units).
    field : str
        Name used in the error message.

    Returns
    -------
    tuple of 3 floats

    Raises
    ------
    InvalidInputError
        On a wrong length or shape, text, NaN or infinity.

    Examples
    --------
    >>> check_vector3([0, 0, 20], "a")
    (0.0, 0.0, 20.0)
    >>> check_vector3((1, 2), "a")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: a: expected shape (3,), got (2,): (1, 2); allowed: 3 finite ...
    """
    allowed = "3 finite numbers (x, y, z)"
    if isinstance(value, (str, bytes)):
        raise InvalidInputError(field, value, allowed, problem="text is not a vector:")
    array = as_float_array(value, field, allowed)
    if array.shape != (3,):
        raise InvalidInputError(
            field, one_line(value), allowed, problem=f"expected shape (3,), got {array.shape}:"
        )
    if not np.all(np.isfinite(array)):
        bad = int(np.flatnonzero(~np.isfinite(array))[0])
        raise InvalidInputError(
            field, tuple(array.tolist()), allowed, problem=f"entry {bad} must be finite, got"
        )
    return (float(array[0]), float(array[1]), float(array[2]))


def check_joint_values(
    q: Any, n: int, names: Sequence[str] | None = None, field: str = "q"
) -> tuple[np.ndarray, bool]:
    """Validate generalized coordinates for an ``n``-module robot.

    Parameters
    ----------
    q : array-like, shape (n,) or (T, n)
        One configuration or a trajectory of ``T`` samples; radians for rotations, length
        units for translations.
    n : int
        Number of modules.
    names : sequence of str, optional
        Coordinate names (``q1 … qn``) used to say which entry is bad.
    field : str
        Name used in the error message.

    Returns
    -------
    q2d : ndarray, shape (T, n)
        Float array; a single configuration becomes ``T = 1``. Not copied when already
        a C-contiguous float array.
    batched : bool
        Whether the input had a time axis.

    Raises
    ------
    InvalidInputError
        On text, wrong rank or length, NaN or infinity.

    Examples
    --------
    >>> q2d, batched = check_joint_values([0, 0.5, 1], 3)
    >>> q2d.shape, batched
    ((1, 3), False)
    >>> check_joint_values([0, 0], 3)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: q: expected shape (3,) or (T, 3), got (2,): [0, 0]; allowed: ...
    """
    allowed = "one number per module (radians for rotations, length for translations)"
    array = as_float_array(q, field, allowed)
    if array.ndim not in (1, 2) or array.shape[-1] != n:
        raise InvalidInputError(
            field,
            one_line(q),
            allowed,
            problem=f"expected shape ({n},) or (T, {n}), got {array.shape}:",
        )
    finite = np.isfinite(array)
    if not finite.all():
        index = np.unravel_index(int(np.flatnonzero(~finite.ravel())[0]), array.shape)
        column = int(index[-1])
        label = names[column] if names is not None else f"column {column}"
        where = f"{label}" if array.ndim == 1 else f"{label} at sample {int(index[0])}"
        raise InvalidInputError(
            field, float(array[index]), allowed, problem=f"{where} must be finite, got"
        )
    batched = array.ndim == 2
    return (array if batched else array[np.newaxis, :]), batched


def check_configuration(
    q: Any, n: int, names: Sequence[str] | None = None, field: str = "q"
) -> np.ndarray:
    """Validate one configuration of an ``n``-module robot (not a trajectory).

    Parameters
    ----------
    q : array-like, shape (n,)
        Radians for rotations, length units for translations.
    n : int
        Number of modules.
    names : sequence of str, optional
        Coordinate names, to say which entry is bad.
    field : str
        Name used in the error message.

    Returns
    -------
    ndarray, shape (n,)

    Raises
    ------
    InvalidInputError
        As :func:`check_joint_values`, and for a trajectory of shape (T, n).

    Examples
    --------
    >>> check_configuration([0, 1], 2)
    array([0., 1.])
    >>> check_configuration([[0, 1], [1, 2]], 2)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: q: got a trajectory of shape (2, 2): ...; allowed: one ...
    """
    values, batched = check_joint_values(q, n, names, field)
    if batched:
        raise InvalidInputError(
            field,
            one_line(q),
            f"one configuration of shape ({n},)",
            problem=f"got a trajectory of shape {values.shape}:",
        )
    return values[0]
