"""Default slider ranges and steps: wide enough for the robot at hand, widenable by typing.

The step of a control depends on what it holds, never on its range, so every angle moves
by the same notch and widening a slider does not change it:

- an angle: 1° (0.01 rad when angles are shown in radians);
- a length: a hundredth of the robot's size rounded down to a power of ten
  (:func:`length_step`: 1 for the paper's robot, 0.01 for a UR5 in metres).

A slider's ends are rounded outwards onto that step (:func:`on_steps`), so its notches
fall on round numbers (0, 1°, 2° …) whatever the joint limits.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..kinematics import JOINT_UNITS
from ._numbers import display_number

__all__ = [
    "length_scale",
    "nice_ceiling",
    "q_range",
    "q_display",
    "joint_limits",
    "ANGLE_STEP",
    "length_step",
    "on_steps",
]

#: The units a coordinate has (a link's ``unit``): an angle or a length.
ANGLE_UNIT, LENGTH_UNIT = JOINT_UNITS["revolute"], JOINT_UNITS["prismatic"]
#: The step of an angle control, by "shown in degrees": 1° or 0.01 rad.
ANGLE_STEP = {True: 1.0, False: 0.01}


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


def length_step(scale: float) -> float:
    """The step of a length control: ``scale / 100`` rounded down to a power of ten.

    ``scale`` is the slider half-range (:func:`length_scale`); a power of ten keeps typed
    and stepped values round.

    >>> length_step(100.0), length_step(200.0), length_step(2.0), length_step(0.5)
    (1.0, 1.0, 0.01, 0.001)
    """
    if not math.isfinite(scale) or scale <= 0:
        return 0.01
    return float(10.0 ** (math.floor(math.log10(scale) + 1e-12) - 2))


def on_steps(lo: float, hi: float, step: float) -> tuple[float, float]:
    """``(lo, hi)`` rounded outwards onto multiples of ``step``.

    A slider's notches are ``lo + k·step``; with ``lo`` on the step they are round numbers.

    >>> on_steps(-57.29577951308232, 114.59155902616465, 1.0)
    (-58.0, 115.0)
    >>> on_steps(-100.0, 100.0, 1.0)
    (-100.0, 100.0)
    """
    # The tolerance keeps a bound that is a multiple up to noise (225.00000000000003).
    low = math.floor(lo / step + 1e-9) * step
    high = math.ceil(hi / step - 1e-9) * step
    return display_number(low, step), display_number(high, step)


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
