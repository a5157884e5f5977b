"""Simulink's Repeating Sequence: a time/value table, interpolated and repeated.

Limits: at most :data:`MAX_TABLE_POINTS` points, a period (the last time) of at least
:data:`~robotconf.signals.MIN_DURATION` (1e-9 s), and finite slopes between the points.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._budget import check_memory
from .._errors import InvalidInputError
from .._validation import as_float_array, one_line
from ._base import MIN_DURATION, Signal, count_in_span

__all__ = ["RepeatingSequence", "MAX_TABLE_POINTS"]

#: Most points in one table: a hand-made or file-read sequence has a few dozen.
MAX_TABLE_POINTS = 10_000

#: Peak bytes per candidate kink while :meth:`RepeatingSequence.kinks` lists them (the
#: candidate times, the mask, the kept times and np.unique's sorted copy; measured 33).
_KINK_BYTES = 40

_TIMES = "a list of ≥ 2 finite times (s) starting at 0 and strictly increasing"
_VALUES = "a list of finite values, one per time"


def _table(raw: Any, field_name: str, allowed: str) -> np.ndarray:
    if np.ndim(raw) == 1 and len(raw) > MAX_TABLE_POINTS:  # before converting all of it
        raise InvalidInputError(
            field_name,
            f"<{len(raw)} entries>",
            f"at most {MAX_TABLE_POINTS} points",
            problem="table too long:",
        )
    array = as_float_array(raw, field_name, allowed, what="a table")
    if array.ndim != 1:
        raise InvalidInputError(
            field_name,
            one_line(raw),
            allowed,
            problem=f"expected a flat list, got shape {array.shape}:",
        )
    if array.size == 0:
        raise InvalidInputError(field_name, one_line(raw), allowed, problem="empty table:")
    finite = np.isfinite(array)
    if not finite.all():
        bad = int(np.flatnonzero(~finite)[0])
        raise InvalidInputError(
            field_name, one_line(raw), allowed, problem=f"entry {bad} is {array[bad]}, not finite:"
        )
    return array


@dataclass(frozen=True, repr=False)
class RepeatingSequence(Signal):
    """A table of (time, value) points, linearly interpolated and repeated forever.

    Simulink semantics: the period is the last time value, and the output at ``t`` is the
    table interpolated at ``t mod period``. The default table, times ``[0, 2]`` and values
    ``[0, 2]``, is Simulink's default: a sawtooth rising from 0 to 2 in 2 s and jumping
    back to 0 (the paper's Figure 16).

    Derivatives are exact inside each segment (the segment's slope; acceleration 0). At a
    table time (a kink) the velocity is the **right-sided** slope of the segment starting
    there, and the value is right-continuous (at ``t = period`` the sawtooth is back at 0).
    A jump (``values[-1] != values[0]``) or a change of slope puts an impulse into the
    exact velocity or acceleration; it is left out here and listed by :meth:`kinks`.

    Parameters
    ----------
    times : array-like, shape (m,)
        Strictly increasing times (s), ``2 ≤ m ≤ 10000``, starting at 0. The last one is
        the period, at least 1e-9 s.
    values : array-like, shape (m,)
        Output at each time.

    Raises
    ------
    InvalidInputError
        For an empty or too long table, unequal lengths, fewer than two points, NaN or
        infinity, a first time other than 0, times that do not strictly increase, a
        period below 1e-9 s, or a slope that overflows (values too far apart for the
        time between them).

    Examples
    --------
    >>> saw = RepeatingSequence()
    >>> saw
    RepeatingSequence(times=(0.0, 2.0), values=(0.0, 2.0))
    >>> saw.value([0.5, 1.999, 2.0, 3.0]), saw.velocity(1.0)
    (array([0.5  , 1.999, 0.   , 1.   ]), 1.0)
    >>> RepeatingSequence(times=[0, 2, 1], values=[0, 1, 0])
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: times: times must strictly increase, but times[2] = 1.0 ...
    """

    times: tuple[float, ...] = (0.0, 2.0)
    values: tuple[float, ...] = (0.0, 2.0)
    _t: np.ndarray = field(init=False, repr=False, compare=False)
    _v: np.ndarray = field(init=False, repr=False, compare=False)
    _slope: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        t = _table(self.times, "times", _TIMES)
        v = _table(self.values, "values", _VALUES)
        if t.size != v.size:
            raise InvalidInputError(
                "values",
                self.values,
                f"{t.size} values, one per time",
                problem=f"unequal lengths: {t.size} times but {v.size} values:",
            )
        if t.size < 2:
            raise InvalidInputError(
                "times",
                self.times,
                _TIMES,
                problem="need at least two points (the last time is the period), got",
            )
        if t[0] != 0.0:
            raise InvalidInputError("times", self.times, _TIMES, problem="first time must be 0:")
        step = np.diff(t)
        if not (step > 0.0).all():
            k = int(np.flatnonzero(step <= 0.0)[0]) + 1
            raise InvalidInputError(
                "times",
                self.times,
                _TIMES + " (for a jump, use a tiny time gap)",
                problem=f"times must strictly increase, but times[{k}] = {t[k]} follows "
                f"{t[k - 1]}:",
            )
        if t[-1] < MIN_DURATION:
            raise InvalidInputError(
                "times",
                self.times,
                f"a last time (the period) ≥ {MIN_DURATION:g} s",
                problem=f"period {float(t[-1])!r} s is too short:",
            )
        with np.errstate(over="ignore", invalid="ignore"):
            slope = np.diff(v) / step
        if not np.isfinite(slope).all():
            k = int(np.flatnonzero(~np.isfinite(slope))[0])
            raise InvalidInputError(
                "values",
                one_line(self.values),
                "values whose slope (change per second) between neighbouring times is finite",
                problem=f"the slope from values[{k}] to values[{k + 1}] overflows:",
            )
        for name, array in (("_t", t), ("_v", v), ("_slope", slope)):
            array.flags.writeable = False
            object.__setattr__(self, name, array)
        object.__setattr__(self, "times", tuple(t.tolist()))
        object.__setattr__(self, "values", tuple(v.tolist()))

    def __repr__(self) -> str:
        return f"RepeatingSequence(times={self.times!r}, values={self.values!r})"

    @property
    def period(self) -> float:
        """The period (s): the last time value."""
        return self.times[-1]

    def _segment(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Phase ``t mod period`` and the index of the segment holding it (right-sided)."""
        phase = np.mod(t, self.period)
        index = np.searchsorted(self._t, phase, side="right") - 1
        return phase, np.clip(index, 0, self._t.size - 2)

    def _value(self, t: np.ndarray) -> np.ndarray:
        phase, k = self._segment(t)
        return self._v[k] + self._slope[k] * (phase - self._t[k])

    def _velocity(self, t: np.ndarray) -> np.ndarray:
        return self._slope[self._segment(t)[1]]

    def _acceleration(self, t: np.ndarray) -> np.ndarray:
        return np.zeros(t.shape)

    def _phases(self) -> list[float]:
        """Where within a period the value or the slope jumps."""
        slope, values = self._slope, self._v
        phases = [float(self._t[k]) for k in range(1, slope.size) if slope[k] != slope[k - 1]]
        if values[-1] != values[0] or slope[-1] != slope[0]:
            phases.append(0.0)  # the wrap-around at every multiple of the period
        return phases

    def _kink_count(self, t0: float, t1: float) -> int:
        return sum(count_in_span(t0, t1, phase, self.period) for phase in self._phases())

    def _kinks(self, t0: float, t1: float) -> np.ndarray:
        phases = self._phases()
        if not phases or t1 < t0:
            return np.empty(0)
        period = self.period
        with np.errstate(over="ignore"):
            first, last = np.floor(t0 / period), np.ceil(t1 / period)
        if not (np.isfinite(first) and np.isfinite(last)):
            raise InvalidInputError(
                "period",
                period,
                "times within about 1e308 periods of t = 0",
                problem=f"t / period overflows for t in [{t0!r}, {t1!r}] with",
            )
        # Each period adds len(phases) candidates: refuse before listing 10^10 of them.
        candidates = (last - first + 1.0) * len(phases)
        check_memory(
            "period",
            period,
            _KINK_BYTES * candidates,
            "a longer period or a shorter time span (kink_count() counts them cheaply)",
        )
        cycles = np.arange(first, last + 1.0) * period
        times = (cycles[:, np.newaxis] + np.array(phases)[np.newaxis, :]).ravel()
        return times[(times >= t0) & (times <= t1)]
