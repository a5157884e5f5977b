"""Smooth point-to-point profiles: cubic, quintic and trapezoidal velocity.

Each moves a coordinate from ``start`` to ``end`` in ``duration`` seconds beginning at
``start_time``; it holds ``start`` before and ``end`` after. The time laws themselves
(``start + (end − start)·u(t)``) are shared with the robot programs and the course's
profile checker (:mod:`._time_laws`). Velocity is continuous in all
three, so none has kinks. The acceleration of the cubic (at both ends) and of the
trapezoid (at its four corners) jumps; there the **right-sided** value is reported.

Limits: ``duration ≥`` :data:`~robotconf.signals.MIN_DURATION` (1e-9 s), the
trapezoid's blend ``accel_fraction · duration`` too, and the distance ``end − start``
must be small enough for the duration that the peak velocity and acceleration stay
finite with room to spare (``|Δ| / duration`` and ``|Δ| / duration²`` below 1e306 — far
beyond any machine). A profile outside these limits is refused when it is made.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_finite_number
from ._base import MAX_RATE, MIN_DURATION, Signal
from ._time_laws import polynomial_law, trapezoid_law

__all__ = ["Cubic", "Quintic", "Trapezoidal"]


@dataclass(frozen=True, repr=False)
class _PointToPoint(Signal):
    _law = "cubic"  # the time law of u(t) (a class attribute, not a field)

    start: float = 0.0
    end: float = 1.0
    duration: float = 1.0
    start_time: float = 0.0

    def __post_init__(self) -> None:
        for name in ("start", "end", "duration", "start_time"):
            object.__setattr__(self, name, check_finite_number(getattr(self, name), name))
        if self.duration <= 0.0:
            raise InvalidInputError(
                "duration", self.duration, "a duration > 0 (s)", problem="must be positive, got"
            )
        if self.duration < MIN_DURATION:
            raise InvalidInputError(
                "duration",
                self.duration,
                f"a duration ≥ {MIN_DURATION:g} s",
                problem="too short:",
            )
        if not np.isfinite(self.start_time + self.duration):
            raise InvalidInputError(
                "start_time",
                self.start_time,
                "a start time whose end time (start_time + duration) is finite",
                problem="the motion would end after the float range:",
            )
        self._check_rates(self.duration)

    def _check_rates(self, time: float) -> None:
        """Refuse a distance that overflows, or is too far for ``time`` seconds."""
        distance = self.end - self.start
        if not np.isfinite(distance):
            raise InvalidInputError(
                "end",
                self.end,
                "start and end whose difference is finite",
                problem="end − start overflows with",
            )
        velocity = abs(distance) / time
        acceleration = velocity / time
        if max(velocity, acceleration) > MAX_RATE:
            shortest = max(abs(distance) / MAX_RATE, (abs(distance) / MAX_RATE) ** 0.5)
            raise InvalidInputError(
                "duration",
                self.duration,
                f"a duration ≥ {shortest:.3g} s for a distance of {abs(distance):.3g}",
                problem="too short for the distance (the velocity or acceleration overflows):",
            )

    def _extra_repr(self) -> str:
        return ""

    def __repr__(self) -> str:
        text = f"{type(self).__name__}(start={self.start!r}, end={self.end!r}, "
        text += f"duration={self.duration!r}"
        if self.start_time != 0.0:
            text += f", start_time={self.start_time!r}"
        return text + self._extra_repr() + ")"

    @property
    def end_time(self) -> float:
        """When the motion ends (s)."""
        return self.start_time + self.duration

    def _law_at(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``u``, ``u̇``, ``ü`` of the time law at ``t`` (s, absolute time)."""
        return polynomial_law(self._law, t - self.start_time, self.duration)

    def _value(self, t: np.ndarray) -> np.ndarray:
        return self.start + (self.end - self.start) * self._law_at(t)[0]

    def _velocity(self, t: np.ndarray) -> np.ndarray:
        return (self.end - self.start) * self._law_at(t)[1]

    def _acceleration(self, t: np.ndarray) -> np.ndarray:
        return (self.end - self.start) * self._law_at(t)[2]


@dataclass(frozen=True, repr=False)
class Cubic(_PointToPoint):
    """Cubic polynomial with zero velocity at both ends: ``s(τ) = 3τ² − 2τ³``.

    Parameters
    ----------
    start, end : float
        Initial and final value.
    duration : float
        Motion time (s), ≥ 1e-9 s (:data:`~robotconf.signals.MIN_DURATION`).
    start_time : float
        When the motion begins (s).

    Raises
    ------
    InvalidInputError
        For a parameter that is not a finite real number, a duration below 1e-9 s, or a
        distance too large for the duration (see the module notes).

    Examples
    --------
    >>> move = Cubic(start=0.0, end=1.0, duration=2.0)
    >>> move.value([0.0, 1.0, 2.0, 3.0]), move.velocity(1.0), move.acceleration(0.0)
    (array([0. , 0.5, 1. , 1. ]), 0.75, 1.5)
    """

    _law = "cubic"


@dataclass(frozen=True, repr=False)
class Quintic(_PointToPoint):
    """Quintic polynomial, zero velocity and acceleration at both ends.

    ``s(τ) = 10τ³ − 15τ⁴ + 6τ⁵``; acceleration is continuous everywhere.

    Examples
    --------
    >>> move = Quintic(start=1.0, end=3.0, duration=1.0, start_time=1.0)
    >>> move.value([0.0, 1.5, 5.0]), move.velocity(1.5)
    (array([1., 2., 3.]), 3.75)
    """

    _law = "quintic"


@dataclass(frozen=True, repr=False)
class Trapezoidal(_PointToPoint):
    """Trapezoidal velocity: constant acceleration, cruise, constant deceleration.

    The acceleration and the deceleration phase each last ``accel_fraction · duration``;
    ``accel_fraction = 0.5`` gives a triangular velocity profile. The cruise velocity is
    ``(end − start) / (duration · (1 − accel_fraction))``.

    Parameters
    ----------
    start, end, duration, start_time : float
        As for :class:`Cubic`.
    accel_fraction : float
        Share of ``duration`` spent accelerating, ``0 < accel_fraction ≤ 0.5``, with a
        blend time ``accel_fraction · duration ≥ 1e-9`` s.

    Examples
    --------
    >>> move = Trapezoidal(start=0.0, end=3.0, duration=4.0, accel_fraction=0.25)
    >>> move.velocity([0.5, 2.0, 3.5]), move.acceleration([0.5, 2.0, 3.5])
    (array([0.5, 1. , 0.5]), array([ 1.,  0., -1.]))
    >>> move.value(4.0)
    3.0
    """

    accel_fraction: float = 0.25

    def __post_init__(self) -> None:
        super().__post_init__()
        fraction = check_finite_number(self.accel_fraction, "accel_fraction")
        if not 0.0 < fraction <= 0.5:
            raise InvalidInputError(
                "accel_fraction",
                fraction,
                "a number with 0 < accel_fraction ≤ 0.5",
                problem="out of range:",
            )
        # The blend is a duration of its own: the acceleration divides by it.
        if fraction * self.duration < MIN_DURATION:
            raise InvalidInputError(
                "accel_fraction",
                fraction,
                f"a fraction with accel_fraction · duration ≥ {MIN_DURATION:g} s",
                problem="the blend time is too short:",
            )
        object.__setattr__(self, "accel_fraction", fraction)
        self._check_rates(fraction * self.duration)

    def _extra_repr(self) -> str:
        return "" if self.accel_fraction == 0.25 else f", accel_fraction={self.accel_fraction!r}"

    def _law_at(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        blend = self.accel_fraction * self.duration
        speed = 1.0 / (self.duration - blend)  # the area under u̇ is 1
        return trapezoid_law(t - self.start_time, self.duration, blend, speed)
