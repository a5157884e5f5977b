"""Simulink's source blocks: Constant, Step, Ramp and Sine Wave."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_finite_number
from ._base import MAX_RATE, Signal

__all__ = ["Constant", "Step", "Ramp", "Sine"]


def _finite_fields(obj: object, names: tuple[str, ...]) -> None:
    for name in names:
        object.__setattr__(obj, name, check_finite_number(getattr(obj, name), name))


def _within(times: list[float], t0: float, t1: float) -> np.ndarray:
    array = np.array(times, dtype=float)
    return array[(array >= t0) & (array <= t1)]


def _repr(obj: object, defaults: dict[str, float]) -> str:
    """``Name(field=value, …)`` listing only the fields that differ from their defaults."""
    parts = [
        f"{name}={getattr(obj, name)!r}"
        for name, default in defaults.items()
        if getattr(obj, name) != default
    ]
    return f"{type(obj).__name__}({', '.join(parts)})"


@dataclass(frozen=True, repr=False)
class Constant(Signal):
    """A coordinate held at ``level`` (Simulink's Constant block).

    Parameters
    ----------
    level : float
        Radians for a rotation, length units for a translation.

    Examples
    --------
    >>> Constant(0.5).value([0.0, 1.0])
    array([0.5, 0.5])
    """

    level: float = 0.0

    def __post_init__(self) -> None:
        _finite_fields(self, ("level",))

    def __repr__(self) -> str:
        return f"Constant({self.level!r})"

    def _value(self, t: np.ndarray) -> np.ndarray:
        return np.full(t.shape, self.level)

    def _velocity(self, t: np.ndarray) -> np.ndarray:
        return np.zeros(t.shape)

    def _acceleration(self, t: np.ndarray) -> np.ndarray:
        return np.zeros(t.shape)


@dataclass(frozen=True, repr=False)
class Step(Signal):
    """``initial`` before ``step_time``, ``final`` from ``step_time`` on (Simulink's Step).

    The value is right-continuous (``final`` at ``t = step_time``). Velocity and
    acceleration are zero everywhere: the impulse at the edge is not a number, so it is
    left out and reported by :meth:`kinks`.

    Parameters
    ----------
    step_time : float
        Time of the step (s).
    initial, final : float
        Values before and after.

    Examples
    --------
    >>> Step(step_time=1.0, final=2.0).value([0.5, 1.0, 1.5])
    array([0., 2., 2.])
    """

    step_time: float = 1.0
    initial: float = 0.0
    final: float = 1.0

    def __post_init__(self) -> None:
        _finite_fields(self, ("step_time", "initial", "final"))

    def __repr__(self) -> str:
        return _repr(self, {"step_time": 1.0, "initial": 0.0, "final": 1.0})

    def _value(self, t: np.ndarray) -> np.ndarray:
        return np.where(t >= self.step_time, self.final, self.initial)

    def _velocity(self, t: np.ndarray) -> np.ndarray:
        return np.zeros(t.shape)

    def _acceleration(self, t: np.ndarray) -> np.ndarray:
        return np.zeros(t.shape)

    def _kinks(self, t0: float, t1: float) -> np.ndarray:
        return _within([self.step_time] if self.initial != self.final else [], t0, t1)


@dataclass(frozen=True, repr=False)
class Ramp(Signal):
    """``initial_output`` until ``start_time``, then rising with ``slope`` (Simulink's Ramp).

    At ``t = start_time`` the velocity is the right-sided value ``slope``; the
    acceleration is zero everywhere (the impulse at the kink is left out).

    Parameters
    ----------
    slope : float
        Rate of change (per second).
    start_time : float
        When the ramp starts (s).
    initial_output : float
        Value until then.

    Examples
    --------
    >>> ramp = Ramp(slope=2.0, start_time=1.0)
    >>> ramp.value([0.0, 1.0, 2.0]), ramp.velocity([0.0, 1.0])
    (array([0., 0., 2.]), array([0., 2.]))
    """

    slope: float = 1.0
    start_time: float = 0.0
    initial_output: float = 0.0

    def __post_init__(self) -> None:
        _finite_fields(self, ("slope", "start_time", "initial_output"))

    def __repr__(self) -> str:
        return _repr(self, {"slope": 1.0, "start_time": 0.0, "initial_output": 0.0})

    def _value(self, t: np.ndarray) -> np.ndarray:
        return self.initial_output + self.slope * np.maximum(t - self.start_time, 0.0)

    def _velocity(self, t: np.ndarray) -> np.ndarray:
        return np.where(t >= self.start_time, self.slope, 0.0)

    def _acceleration(self, t: np.ndarray) -> np.ndarray:
        return np.zeros(t.shape)

    def _kinks(self, t0: float, t1: float) -> np.ndarray:
        return _within([self.start_time] if self.slope != 0.0 else [], t0, t1)


@dataclass(frozen=True, repr=False)
class Sine(Signal):
    """``bias + amplitude · sin(2π · frequency · t + phase)`` (Simulink's Sine Wave).

    Parameters
    ----------
    amplitude : float
        Peak deviation from ``bias``.
    bias : float
        Mean value.
    frequency : float
        Frequency in **hertz** (cycles per second), ≥ 0. Simulink's block takes rad/s;
        divide by 2π when copying its parameters.
    phase : float
        Phase (radians).

    The peak velocity ``|A|·ω`` and acceleration ``|A|·ω²`` (``ω = 2π·frequency``) must
    stay below ``1e306`` (:data:`~robotconf.signals.MAX_RATE`), and ``|bias| + |A|``
    finite; so at amplitude 1 the frequency may reach about 1.6e152 Hz.

    Raises
    ------
    InvalidInputError
        For a negative or too high frequency, a non-finite parameter, or a bias and
        amplitude whose sum overflows; when evaluated, ``frequency`` if ``ω·t`` overflows.

    Examples
    --------
    >>> wave = Sine(amplitude=2.0, frequency=0.25)
    >>> wave.value(1.0), wave.velocity(0.0)
    (2.0, 3.141592653589793)
    >>> Sine(frequency=-1)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: frequency: must be ≥ 0, got -1.0; allowed: a frequency ≥ 0 in Hz
    """

    amplitude: float = 1.0
    bias: float = 0.0
    frequency: float = 1.0
    phase: float = 0.0

    def __post_init__(self) -> None:
        _finite_fields(self, ("amplitude", "bias", "frequency", "phase"))
        if self.frequency < 0.0:
            raise InvalidInputError(
                "frequency", self.frequency, "a frequency ≥ 0 in Hz", problem="must be ≥ 0, got"
            )
        amplitude, w = abs(self.amplitude), 2.0 * np.pi * self.frequency
        if not (amplitude * w <= MAX_RATE and amplitude * w * w <= MAX_RATE):
            top = MAX_RATE / max(amplitude, 1e-300)
            highest = min(top, top**0.5) / (2.0 * np.pi)
            raise InvalidInputError(
                "frequency",
                self.frequency,
                f"a frequency ≤ {highest:.3g} Hz at amplitude {self.amplitude!r}",
                problem="too high (the velocity or acceleration overflows):",
            )
        if not np.isfinite(abs(self.bias) + amplitude):
            raise InvalidInputError(
                "bias",
                self.bias,
                "a bias and amplitude whose sum is finite",
                problem=f"|bias| + |amplitude| overflows with amplitude {self.amplitude!r} and",
            )

    def __repr__(self) -> str:
        return _repr(self, {"amplitude": 1.0, "bias": 0.0, "frequency": 1.0, "phase": 0.0})

    @property
    def angular_frequency(self) -> float:
        """``2π · frequency`` (rad/s)."""
        return 2.0 * np.pi * self.frequency

    def _culprit(self, quantity: str, t: float) -> tuple[str, Any]:
        # Construction bounds the amplitudes, so only the phase ω·t + φ can overflow.
        return ("frequency", self.frequency)

    def _value(self, t: np.ndarray) -> np.ndarray:
        return self.bias + self.amplitude * np.sin(self.angular_frequency * t + self.phase)

    def _velocity(self, t: np.ndarray) -> np.ndarray:
        w = self.angular_frequency
        return (self.amplitude * w) * np.cos(w * t + self.phase)

    def _acceleration(self, t: np.ndarray) -> np.ndarray:
        w = self.angular_frequency
        return (-self.amplitude * w * w) * np.sin(w * t + self.phase)
