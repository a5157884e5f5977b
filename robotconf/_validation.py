"""Validators that turn user input into clean float arrays or raise InvalidInputError."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from ._errors import InvalidInputError

__all__ = [
    "Rejected",
    "as_float_array",
    "check_finite_number",
    "check_integer",
    "check_flag",
    "check_vector3",
    "check_joint_values",
    "check_configuration",
    "check_json_number",
    "check_json_object",
]

_FINITE = "a finite real number"


class Rejected:
    """Stands in for a JSON number robotconf refuses (NaN, ±Infinity, overflow, huge ints)
    until a reader reaches it and can name its path (the file reader parses JSON so)."""

    __slots__ = ("text", "reason")

    def __init__(self, text: str, reason: str):
        self.text = text
        self.reason = reason

    def __repr__(self) -> str:
        return self.text


def as_float_array(value: Any, field: str, allowed: str, what: str = "a number") -> np.ndarray:
    """``np.asarray(value, dtype=float)``, refusing text and non-numeric objects clearly.

    >>> as_float_array([1, 2], "times", "numbers")
    array([1., 2.])
    """
    if isinstance(value, (str, bytes)):
        raise InvalidInputError(field, value, allowed, problem=f"text is not {what}:")
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InvalidInputError(field, value, allowed, problem="not numeric:") from None
    return array


def check_finite_number(value: Any, field: str) -> float:
    """Return ``value`` as a finite Python float.

    Parameters
    ----------
    value : real number
        A number; booleans and text are refused.
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
    if isinstance(value, (bool, np.bool_)):
        raise InvalidInputError(field, value, _FINITE, problem="a boolean is not a number:")
    array = as_float_array(value, field, _FINITE)
    if array.shape != ():
        raise InvalidInputError(
            field, value, _FINITE, problem=f"expected one number, got shape {array.shape}:"
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
        A Python or numpy integer; booleans, floats (even ``3.0``) and text are refused.
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
        raise InvalidInputError(field, value, what, problem="not an integer:")
    number = int(value)
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
        raise InvalidInputError(field, value, "True or False", problem="not True or False:")
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
            field, value, allowed, problem=f"expected shape (3,), got {array.shape}:"
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
            field, q, allowed, problem=f"expected shape ({n},) or (T, {n}), got {array.shape}:"
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
            q,
            f"one configuration of shape ({n},)",
            problem=f"got a trajectory of shape {values.shape}:",
        )
    return values[0]


def check_json_object(value: Any, path: str, keys: Mapping[str, bool]) -> Mapping[str, Any]:
    """A parsed JSON object with only the known ``keys`` (True: required), each once.

    The file reader marks keys given twice in ``value.duplicates`` (json itself keeps only
    the last); such an object is refused. Every error names ``path.key``.

    >>> check_json_object({"t_end": 1.0}, "simulation", {"t_end": True, "dt": False})
    {'t_end': 1.0}
    """
    allowed = ", ".join(f"{k}" if required else f"{k} (optional)" for k, required in keys.items())
    if not isinstance(value, Mapping):
        raise InvalidInputError(
            path, value, f"an object with keys {allowed}", problem="expected an object, got"
        )
    duplicates = getattr(value, "duplicates", ())
    if duplicates:
        raise InvalidInputError(
            f"{path}.{duplicates[0]}", duplicates[0], "each key once", problem="duplicate key"
        )
    for key in value:
        if key not in keys:
            raise InvalidInputError(
                f"{path}.{key}", value[key], f"the keys {allowed}", problem="unknown key, value"
            )
    for key, required in keys.items():
        if required and key not in value:
            raise InvalidInputError(f"{path}.{key}", None, f"the keys {allowed}", problem="missing")
    return value


def check_json_number(value: Any, path: str) -> float:
    """A finite JSON number as float; ``true``/``false``, text, NaN and infinities refused.

    >>> check_json_number(20, "robot.links[1].a[2]")
    20.0
    >>> check_json_number(True, "robot.links[0].q")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: robot.links[0].q: expected a number, got a boolean: True; ...
    """
    allowed = "a finite number"
    if isinstance(value, Rejected):
        raise InvalidInputError(path, value, allowed, problem=f"{value.reason}:")
    if isinstance(value, bool):
        raise InvalidInputError(path, value, allowed, problem="expected a number, got a boolean:")
    if not isinstance(value, (int, float)):
        raise InvalidInputError(path, value, allowed, problem="expected a number, got")
    try:
        result = float(value)
    except OverflowError:
        raise InvalidInputError(path, value, allowed, problem="too large:") from None
    if not np.isfinite(result):
        raise InvalidInputError(path, result, allowed, problem="must be finite, got")
    return result
