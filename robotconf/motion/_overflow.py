"""Refuse a simulation whose numbers overflowed although every input was finite.

A finite signal can still have an infinite derivative in float64 (a sine of amplitude
10³⁰⁰ at 10¹⁰ Hz has accelerations near 10³²⁰), and finite coordinates can still give
infinite positions (offsets near 10³⁰⁸). Such results are refused, naming the input
responsible, instead of being returned as inf or NaN.

The checks cost one summing pass over each array and allocate nothing (see
:func:`all_finite`); only a failing check looks for where the problem is.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from .._budget import check_finite_result
from ..signals import Signal
from ._dva import QUANTITIES

if TYPE_CHECKING:
    from ..kinematics import Robot

__all__ = ["all_finite", "check_coordinates_finite", "check_results_finite"]

_PLURAL = {
    "position": "positions",
    "displacement": "displacements",
    "velocity": "velocities",
    "acceleration": "accelerations",
    "angular_velocity": "angular velocities",
}
# Positions come from the lengths (offsets, end-effector point, prismatic coordinates);
# rates also from the signals' speeds.
_FROM_GEOMETRY = ("position", "displacement")


def all_finite(values: np.ndarray) -> bool:
    """Whether every entry is finite, without a temporary array.

    One summing pass usually decides: an inf or NaN entry makes the sum inf or NaN, so a
    finite sum proves every entry finite. Only a non-finite sum (which finite entries
    near 1e308 can also give) needs the extremes, as ``max`` and ``min`` propagate NaN.

    >>> all_finite(np.array([1.0, 2.0])), all_finite(np.array([1.0, np.nan]))
    (True, False)
    >>> all_finite(np.array([1e308, 1e308]))  # the sum overflows, the entries do not
    True
    """
    if values.size == 0:
        return True
    with np.errstate(over="ignore", invalid="ignore"):
        if np.isfinite(values.sum()):
            return True
        return bool(np.isfinite(values.max()) and np.isfinite(values.min()))


def check_coordinates_finite(
    rows: Mapping[str, np.ndarray],
    signals: Mapping[int, Signal],
    names: Sequence[str],
    finite_differences: bool = False,
) -> None:
    """Refuse driven coordinates whose values or derivatives overflowed.

    Parameters
    ----------
    rows : dict
        ``"values"``, ``"velocities"``, ``"accelerations"`` → array of shape (n, T).
    signals : dict
        Coordinate index → its signal; only these rows are checked.
    names : sequence of str
        Coordinate names ``q1 … qn``.
    finite_differences : bool
        Whether the derivatives came from finite differences (said in the message).

    Raises
    ------
    InvalidInputError
        Named ``signals[q<i>]``, e.g. "the accelerations of q1 overflow to inf or NaN".

    Examples
    --------
    >>> from robotconf.signals import Sine
    >>> q = np.zeros((1, 3)); qdd = np.array([[0.0, np.inf, 0.0]])
    >>> check_coordinates_finite({"values": q, "accelerations": qdd}, {0: Sine()}, ["q1"])
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: signals[q1]: the accelerations of q1 overflow to inf or NaN ...
    """
    for i, signal in signals.items():
        for what, array in rows.items():
            row = array[i]
            if not all_finite(row):
                label = f"finite-difference {what}" if finite_differences else what
                check_finite_result(
                    row, f"signals[{names[i]}]", signal, f"the {label} of {names[i]}"
                )


def check_results_finite(
    data: np.ndarray, robot: Robot, points: Sequence[str], signals: Mapping[str, Signal]
) -> None:
    """Refuse DVA results (shape (n + 1, 5, 3, T)) holding inf or NaN.

    Raises
    ------
    InvalidInputError
        Naming ``robot`` for positions and displacements (the lengths are too large),
        else ``signals`` (the speeds are), e.g. "the velocities of EE overflow …".
    """
    if all_finite(data):
        return
    finite = np.isfinite(data).all(axis=(2, 3))  # only on failure: (n + 1, 5) flags
    point, quantity = (int(k) for k in np.argwhere(~finite)[0])
    name = QUANTITIES[quantity]
    what = f"the {_PLURAL[name]} of {points[point]}"
    if name in _FROM_GEOMETRY or not signals:
        check_finite_result(data[point, quantity], "robot", robot, what)
    check_finite_result(data[point, quantity], "signals", dict(signals), what)
