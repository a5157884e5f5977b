"""Validators that turn user input into clean float arrays or raise InvalidInputError."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from ._errors import InvalidInputError

__all__ = ["as_float_array", "check_finite_number", "check_vector3", "check_joint_values"]

_FINITE = "a finite real number"


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
