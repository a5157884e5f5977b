"""Measured points as calibration takes them: (N, 3) arrays of bounded, finite numbers."""

from __future__ import annotations

from typing import Any

import numpy as np

from .._budget import check_memory
from .._errors import InvalidInputError
from .._validation import as_float_array, one_line
from ..kinematics import MAX_PARAMETER

__all__ = ["MAX_POINTS", "point_set"]

#: The most points (or samples) one call takes: far more than any measurement campaign.
MAX_POINTS = 1_000_000


def point_set(value: Any, field: str, minimum: int = 1, count: int | None = None) -> np.ndarray:
    """Points (N, 3) in length units: finite, ``|x| ≤ MAX_PARAMETER``, ``minimum ≤ N``.

    Parameters
    ----------
    value : array-like, shape (N, 3)
    field : str
        Name used in the error message.
    minimum : int
        The fewest points allowed.
    count : int, optional
        The exact number of points required (one per sample of another input).

    Returns
    -------
    ndarray, shape (N, 3)
        A float copy.

    Examples
    --------
    >>> point_set([[0, 0, 0], [1, 0, 0]], "measured").shape
    (2, 3)
    >>> point_set([[0, 0, 0]], "measured", minimum=3)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: measured: too few points: 1; allowed: at least 3 points (x, y, z)
    """
    allowed = f"at least {minimum} points (x, y, z)" if count is None else f"{count} points"
    if isinstance(value, np.ndarray):
        size = value.size
    elif isinstance(value, (list, tuple)):
        size = 3 * len(value)  # refused before numpy copies a huge nested list
    else:
        size = 0
    if size > 3 * MAX_POINTS:
        raise InvalidInputError(
            field, one_line(value), f"at most {MAX_POINTS} points", problem="too many points:"
        )
    array = np.array(as_float_array(value, field, allowed), dtype=float)
    if array.ndim != 2 or array.shape[1] != 3:
        raise InvalidInputError(
            field,
            one_line(value),
            allowed + ", as an array of shape (N, 3)",
            problem=f"expected shape (N, 3), got {array.shape}:",
        )
    points = array.shape[0]
    if points > MAX_POINTS:
        raise InvalidInputError(
            field, f"<{points} points>", f"at most {MAX_POINTS} points", problem="too many points:"
        )
    if count is not None and points != count:
        raise InvalidInputError(
            field,
            f"<{points} points>",
            allowed + " (one per sample)",
            problem=f"expected {count} rows, got {points}:",
        )
    if points < minimum:
        raise InvalidInputError(field, points, allowed, problem="too few points:")
    finite = np.isfinite(array)
    if not finite.all():
        row, column = (int(k) for k in np.argwhere(~finite)[0])
        raise InvalidInputError(
            field,
            float(array[row, column]),
            allowed + ", finite",
            problem=f"point {row} coordinate {'xyz'[column]} must be finite, got",
        )
    if float(np.max(np.abs(array), initial=0.0)) > MAX_PARAMETER:
        row = int(np.argmax(np.max(np.abs(array), axis=1)))
        raise InvalidInputError(
            field,
            tuple(array[row].tolist()),
            f"coordinates with |x| ≤ {MAX_PARAMETER:.0e}",
            problem=f"point {row} is too large:",
        )
    check_memory(field, f"<{points} points>", 400.0 * points, "fewer points")
    return array
