"""Default slider ranges: wide enough for the robot at hand, always widenable by typing."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..kinematics import JOINT_UNITS

__all__ = ["length_scale", "nice_ceiling", "q_range", "q_display", "joint_limits"]

#: The units a coordinate has (a link's ``unit``): an angle or a length.
ANGLE_UNIT, LENGTH_UNIT = JOINT_UNITS["revolute"], JOINT_UNITS["prismatic"]


def nice_ceiling(value: float) -> float:
    """The smallest of 1, 2, 5 × 10^k that is ≥ ``value`` (for ``value`` > 0).

    >>> nice_ceiling(70), nice_ceiling(0.3), nice_ceiling(100)
    (100.0, 0.5, 100.0)
    """
    exponent = math.floor(math.log10(value))
    for mantissa in (1.0, 2.0, 5.0, 10.0):
        candidate = mantissa * 10.0**exponent
        if candidate >= value * (1 - 1e-12):
            return float(round(candidate, 12))
    return float(10.0 ** (exponent + 1))  # pragma: no cover - the loop always returns


def length_scale(robot: Any) -> float:
    """A slider half-range for lengths: the robot's size (the core's
    :func:`~robotconf.characteristic_length`), rounded up to 1, 2 or 5 × 10^k.

    The paper's robot (20 + 30 + 40) gets ±100; a UR5 in metres ±2.

    >>> import robotconf as rc
    >>> length_scale(rc.Robot([rc.Module("Rz", a=(0, 0, 20))], end_effector=(40, 0, 0)))
    100.0
    """
    from ..kinematics import characteristic_length

    return nice_ceiling(characteristic_length(robot))


def joint_limits(robot: Any) -> np.ndarray | None:
    """``robot.joint_limits()`` (shape (n, 2)) where the core offers it, else ``None``."""
    method = getattr(robot, "joint_limits", None)
    if method is None:
        return None
    return np.asarray(method(), dtype=float)


def q_range(
    unit: str, scale: float, limits: Any = None, degrees: bool = True
) -> tuple[float, float]:
    """Default range of a coordinate slider in display units.

    Parameters
    ----------
    unit : {"rad", "length", ""}
        The link's ``unit`` (:data:`~robotconf.kinematics.JOINT_UNITS`).
    scale : float
        Half-range for lengths (see :func:`length_scale`).
    limits : (lo, hi) or None
        Joint limits in core units (radians / length), used where finite.
    degrees : bool
        Angles shown in degrees.

    Examples
    --------
    >>> q_range("rad", 100.0), q_range("length", 100.0), q_range("rad", 1, (-1.0, 1.0), False)
    ((-180.0, 180.0), (-100.0, 100.0), (-1.0, 1.0))
    """
    if limits is not None and np.all(np.isfinite(limits)) and limits[1] > limits[0]:
        lo, hi = float(limits[0]), float(limits[1])
        if unit == ANGLE_UNIT and degrees:
            return float(np.rad2deg(lo)), float(np.rad2deg(hi))
        return lo, hi
    if unit == ANGLE_UNIT:
        return (-180.0, 180.0) if degrees else (-round(math.pi, 4), round(math.pi, 4))
    return -scale, scale


def q_display(unit: str) -> tuple[bool, str]:
    """How a coordinate control shows a link's ``unit``: (is an angle, unit label).

    An angle's label comes from the degrees/radians switch, so its own label is empty; a
    length is labelled ``length``; a link without a joint has neither.

    >>> q_display("rad"), q_display("length"), q_display("")
    ((True, ''), (False, 'length'), (False, ''))
    """
    return unit == ANGLE_UNIT, unit if unit == LENGTH_UNIT else ""
