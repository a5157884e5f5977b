"""Numbers rounded too coarsely: right to the digits the student kept, outside tolerance.

``0.87`` for 0.8660 is not a wrong idea but a lost digit, and the hint should say so
instead of calling the entry wrong. An entry counts as coarsely rounded when the student
typed a plain number, the expected entry is one number (not a formula of q), the last
digit the student kept is at most a tenth of the expected value's size (one decimal of a
number below 1), and the two differ by at most half a unit of that digit. Matching a
candidate mistake's numbers asks for two significant digits instead.
"""

from __future__ import annotations

from collections.abc import Iterable
from decimal import Decimal
from typing import Any

import numpy as np

__all__ = ["coarse_roundings", "last_digit"]

#: The unit of the last digit assumed for a typed 0 (it has no digits of its own).
_ZERO_UNIT = 0.01


def last_digit(value: float) -> float | None:
    """The unit of the last digit of a typed number: 0.01 for 0.87, 10 for 820.

    Parameters
    ----------
    value : float

    Returns
    -------
    float or None
        ``None`` for 0 (no digits).

    Examples
    --------
    >>> last_digit(0.87), last_digit(1.7), last_digit(820.0), last_digit(3.0), last_digit(0.0)
    (0.01, 0.1, 10.0, 1.0, None)
    """
    if value == 0 or not np.isfinite(value):
        return None
    exponent = Decimal(repr(float(value))).normalize().as_tuple().exponent
    assert isinstance(exponent, int)  # finite numbers only
    return float(10.0**exponent) if exponent < 0 else float(10**exponent)


def coarse_roundings(
    student: Any,
    entries: Iterable[tuple[int, int]],
    e_values: np.ndarray,
    significant: bool = False,
) -> set[tuple[int, int]]:
    """The entries among ``entries`` that are the target number rounded too coarsely.

    Parameters
    ----------
    student : sympy.Matrix
        The student's answer (a typed number is a sympy number).
    entries : iterable of (int, int)
        0-based wrong entries.
    e_values : ndarray, shape (K, rows, cols)
        The target at the sample points: the expected matrix, or a candidate mistake's
        numbers.
    significant : bool
        Also require two significant digits of the target (``0.1`` does not round
        0.0892): for matching a candidate mistake, where one coarse number would make a
        coincidence.

    Returns
    -------
    set of (int, int)

    Examples
    --------
    >>> import sympy
    >>> student = sympy.Matrix([[sympy.Rational(87, 100), 1, sympy.Symbol("q1")]])
    >>> expected = np.array([[[0.8660254, 0.8660254, 0.8660254]]])
    >>> sorted(coarse_roundings(student, [(0, 0), (0, 1), (0, 2)], expected))
    [(0, 0)]
    >>> tenth, target = sympy.Matrix([[sympy.Rational(1, 10)]]), np.full((1, 1, 1), 0.0892)
    >>> coarse_roundings(tenth, [(0, 0)], target), coarse_roundings(tenth, [(0, 0)], target, True)
    ({(0, 0)}, set())
    """
    found = set()
    for r, c in entries:
        typed = student[r, c]
        expected = e_values[:, r, c]
        if not typed.is_Number or not np.all(np.isfinite(expected)):
            continue
        target = float(expected[0])
        if np.ptp(expected) > 1e-12 * max(1.0, abs(target)):  # a formula of q, not a number
            continue
        value = float(typed)
        units = [last_digit(value) or _ZERO_UNIT]
        if typed.is_Integer and units[0] > 1:
            units.append(1.0)  # 20 may be 19.86 to the units: its zero is a digit too
        size = abs(target) if significant else max(1.0, abs(target))
        if any(
            unit <= 0.1 * size and abs(value - target) <= 0.5 * unit * (1 + 1e-9) for unit in units
        ):
            found.add((r, c))
    return found
