"""The signal protocol, time validation and offset/scale/sum arithmetic.

A signal maps time ``t`` (seconds) to a generalized coordinate ``q(t)`` together with its
exact derivatives. Every signal is immutable and vectorized over a time array.

Where a derivative is undefined (a kink of a ramp or of a repeating sequence, the edge of a
step), every signal reports the **right-sided** value: the derivative of the piece that
starts at that instant. Impulses (the Dirac spikes a jump or a kink would put into the
velocity or acceleration) are not representable by numbers and are left out; the instants
where they occur are listed by :meth:`Signal.kinks`.

A signal never returns inf or NaN. Parameters whose values or derivatives overflow at
every time (a profile too fast for the float range, a sine whose ``amplitude · ω²``
overflows) are refused when the signal is made; an overflow that depends on the time (a
ramp evaluated at ``t = 1e308``) is refused when it is evaluated, naming the parameter
(or ``t``) responsible.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, fields
from decimal import Decimal
from fractions import Fraction
from typing import Any

import numpy as np

from .._budget import check_finite_result
from .._errors import InvalidInputError
from .._validation import as_float_array, check_finite_number, one_line

__all__ = ["Signal", "Affine", "Sum", "as_times", "MIN_DURATION", "MAX_RATE", "count_in_span"]

#: Shortest duration (s) of a profile and shortest period of a repeating sequence: below
#: it, slopes and kink counts leave any useful range (and 5e-324 s divides to inf).
MIN_DURATION = 1e-9

#: Largest velocity or acceleration *scale* a signal may have (a profile's ``|Δ|/D`` and
#: ``|Δ|/D²``, a sine's ``A·ω`` and ``A·ω²``): the shape factors (at most 6) then keep
#: every value finite with room to spare.
MAX_RATE = 1e306


def as_times(t: Any, field: str = "t") -> tuple[np.ndarray, bool]:
    """Validate times (seconds): a finite number or array → float array and "was scalar".

    Examples
    --------
    >>> as_times([0, 0.5])
    (array([0. , 0.5]), False)
    >>> as_times(float("nan"))
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: t: must be finite, got nan; allowed: finite times in seconds
    """
    allowed = "finite times in seconds"
    if isinstance(t, (str, bytes, bool, np.bool_)):
        raise InvalidInputError(field, one_line(t), allowed, problem="not a time:")
    array = as_float_array(t, field, allowed, what="a time")
    finite = np.isfinite(array)
    if not finite.all():
        bad = float(array.ravel()[np.flatnonzero(~finite.ravel())[0]])
        raise InvalidInputError(field, bad, allowed, problem="must be finite, got")
    return array, array.ndim == 0


def _number(value: Any, field: str) -> float | None:
    """A finite float for numbers, ``None`` for other types (so operators can decline).

    ``Fraction`` and ``Decimal`` count as numbers; numpy's complex numbers reach the check
    and are refused there, naming the field.
    """
    if isinstance(value, (bool, np.bool_)):
        return None
    if not isinstance(value, (numbers.Real, Decimal, np.number)):
        return None
    return check_finite_number(value, field)


def _plain(value: Any) -> Any:
    """A parameter as JSON-ready data: signals → dicts, tuples → lists."""
    if isinstance(value, Signal):
        return value.to_dict()
    if isinstance(value, tuple):
        return [_plain(v) for v in value]
    return value


# The private method behind each quantity, which _culprit methods evaluate again.
_METHODS = {"values": "value", "velocities": "velocity", "accelerations": "acceleration"}


def _out(array: np.ndarray, scalar: bool) -> Any:
    return float(array) if scalar else array


def count_in_span(t0: float, t1: float, phase: float, period: float) -> int:
    """How many ``k·period + phase`` (k an integer) lie in ``[t0, t1]``, in exact arithmetic.

    Counted without listing them, so the answer may be as large as ``1e317``.

    >>> count_in_span(0.0, 10.0, 0.0, 2.0), count_in_span(0.5, 10.0, 1.0, 2.0)
    (6, 5)
    """
    if t1 < t0:
        return 0
    low = math.ceil((Fraction(t0) - Fraction(phase)) / Fraction(period))
    high = math.floor((Fraction(t1) - Fraction(phase)) / Fraction(period))
    return max(0, high - low + 1)


class Signal:
    """Base class of all signals: ``q(t)``, ``q̇(t)``, ``q̈(t)`` over a time array.

    Subclasses implement ``_value``, ``_velocity`` and ``_acceleration`` on a validated
    float array and, if they have any, ``_kinks``. Signals combine with numbers and with
    each other: ``sig * 0.5 + 1``, ``-sig``, ``sig / 2``, ``1 - sig``, ``sig + other``.

    Examples
    --------
    >>> from robotconf.signals import Ramp
    >>> ramp = Ramp(slope=2.0) * 0.5 + 1
    >>> ramp
    Ramp(slope=2.0) * 0.5 + 1.0
    >>> ramp.value([0.0, 1.0]), ramp.velocity(3.0)
    (array([1., 2.]), 1.0)
    """

    __slots__ = ()

    # -- evaluation ---------------------------------------------------------------------

    def value(self, t: Any) -> Any:
        """The coordinate ``q(t)``.

        Parameters
        ----------
        t : float or array-like, shape (T,)
            Times (s).

        Returns
        -------
        float or ndarray, shape (T,)
            Radians for a rotation, length units for a translation.
        """
        times, scalar = as_times(t)
        return _out(self._evaluate(self._value, times, "values"), scalar)

    def velocity(self, t: Any) -> Any:
        """The exact first derivative ``q̇(t)`` (per second), right-sided at kinks."""
        times, scalar = as_times(t)
        return _out(self._evaluate(self._velocity, times, "velocities"), scalar)

    def acceleration(self, t: Any) -> Any:
        """The exact second derivative ``q̈(t)`` (per s²), right-sided; impulses left out."""
        times, scalar = as_times(t)
        return _out(self._evaluate(self._acceleration, times, "accelerations"), scalar)

    def __call__(self, t: Any) -> Any:
        """Same as :meth:`value`."""
        return self.value(t)

    def _evaluate(self, method: Any, t: np.ndarray, quantity: str) -> np.ndarray:
        """``method(t)`` if it is finite; else the error naming the parameter responsible."""
        # An overflow becomes the error below, not numpy's warnings first.
        with np.errstate(over="ignore", invalid="ignore"):
            out = method(t)
            if np.isfinite(out).all():
                return out
            first = float(t.ravel()[np.flatnonzero(~np.isfinite(out).ravel())[0]])
            field, value = self._culprit(_METHODS[quantity], first)
        where = f"the {quantity} of {type(self).__name__} at t = {first!r} s"
        check_finite_result(out, field, value, where)
        raise AssertionError("unreachable")  # pragma: no cover

    def _culprit(self, quantity: str, t: float) -> tuple[str, Any]:
        """The parameter (or ``"t"``) most likely to blame for an overflow at time ``t``.

        ``quantity`` is ``"value"``, ``"velocity"`` or ``"acceleration"``. By default the
        largest of the numeric parameters and ``t`` in magnitude.
        """
        candidates = [
            (item.name, getattr(self, item.name))
            for item in fields(self)  # type: ignore[arg-type]
            if item.init and isinstance(getattr(self, item.name), float)
        ]
        return max([*candidates, ("t", t)], key=lambda pair: abs(pair[1]))

    def kinks(self, t_start: float, t_stop: float) -> np.ndarray:
        """Instants in ``[t_start, t_stop]`` where ``q`` or ``q̇`` jumps.

        There the exact acceleration holds an impulse, which finite differences show as a
        spike and :meth:`acceleration` leaves out.

        Returns
        -------
        ndarray, shape (K,)
            Sorted times (s); empty for smooth signals.

        Raises
        ------
        InvalidInputError
            For times that are not finite numbers, or (field ``period``) when a repeating
            sequence has more kinks in the span than the memory budget holds; see
            :meth:`kink_count` to ask first.
        """
        t0 = check_finite_number(t_start, "t_start")
        t1 = check_finite_number(t_stop, "t_stop")
        return np.unique(self._kinks(t0, t1))

    def kink_count(self, t_start: float, t_stop: float) -> int:
        """How many kinks :meth:`kinks` would list, counted without listing them.

        Cheap at any span (a repeating sequence is counted per phase, in exact
        arithmetic), so a caller can decide before asking for the instants, e.g. against
        a memory budget. ``len(kinks(t_start, t_stop))`` can differ by one at either end
        of the span, where floating-point rounding decides whether a kink falls inside,
        and is smaller where kinks of different terms coincide or lie closer together
        than floats can tell apart.

        Parameters
        ----------
        t_start, t_stop : float
            The span (s); an empty span (``t_stop < t_start``) has no kinks.

        Returns
        -------
        int

        Examples
        --------
        >>> from robotconf.signals import RepeatingSequence
        >>> saw = RepeatingSequence(times=[0, 1e-9], values=[0, 1])
        >>> saw.kink_count(0.0, 10.0)  # kinks() would need 80 GB for these
        10000000000
        """
        t0 = check_finite_number(t_start, "t_start")
        t1 = check_finite_number(t_stop, "t_stop")
        return self._kink_count(t0, t1)

    def _kinks(self, t0: float, t1: float) -> np.ndarray:
        return np.empty(0)

    def _kink_count(self, t0: float, t1: float) -> int:
        return int(self._kinks(t0, t1).size)

    def to_dict(self) -> dict[str, Any]:
        """A lossless dict of plain values: ``{"type": class name, parameter: value, …}``.

        Every parameter is written (also defaults); tables become lists and the parts of
        :class:`Affine` and :class:`Sum` nested dicts, so ``json.dumps`` can write it and
        :func:`~robotconf.signals.signal_from_dict` rebuilds an equal signal.

        Examples
        --------
        >>> from robotconf.signals import Ramp, Sine
        >>> Sine(amplitude=2.0).to_dict()
        {'type': 'Sine', 'amplitude': 2.0, 'bias': 0.0, 'frequency': 1.0, 'phase': 0.0}
        >>> (Ramp() * 2).to_dict()["base"]
        {'type': 'Ramp', 'slope': 1.0, 'start_time': 0.0, 'initial_output': 0.0}
        """
        out: dict[str, Any] = {"type": type(self).__name__}
        for item in fields(self):  # type: ignore[arg-type]
            if item.init:
                out[item.name] = _plain(getattr(self, item.name))
        return out

    def _value(self, t: np.ndarray) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    def _velocity(self, t: np.ndarray) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    def _acceleration(self, t: np.ndarray) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    # -- arithmetic ---------------------------------------------------------------------

    def __mul__(self, other: Any) -> Signal:
        factor = _number(other, "scale")
        if factor is None:
            return NotImplemented
        if isinstance(self, Affine):
            return Affine(self.base, self.scale * factor, self.offset * factor)
        return Affine(self, factor, 0.0)

    __rmul__ = __mul__

    def __truediv__(self, other: Any) -> Signal:
        divisor = _number(other, "divisor")
        if divisor is None:
            return NotImplemented
        if divisor == 0.0:
            raise InvalidInputError("divisor", divisor, "a non-zero number", problem="zero:")
        return self * (1.0 / divisor)

    def __neg__(self) -> Signal:
        return self * -1.0

    def __pos__(self) -> Signal:
        return self

    def __add__(self, other: Any) -> Signal:
        if isinstance(other, Signal):
            left = self.terms if isinstance(self, Sum) else (self,)
            right = other.terms if isinstance(other, Sum) else (other,)
            return Sum(left + right)
        shift = _number(other, "offset")
        if shift is None:
            return NotImplemented
        if isinstance(self, Affine):
            return Affine(self.base, self.scale, self.offset + shift)
        return Affine(self, 1.0, shift)

    __radd__ = __add__

    def __sub__(self, other: Any) -> Signal:
        if isinstance(other, Signal):
            return self + (-other)
        shift = _number(other, "offset")
        return NotImplemented if shift is None else self + (-shift)

    def __rsub__(self, other: Any) -> Signal:
        return (-self) + other


@dataclass(frozen=True, repr=False)
class Affine(Signal):
    """``scale · base(t) + offset``: what ``sig * k + c`` builds.

    Examples
    --------
    >>> from robotconf.signals import Constant
    >>> (2 * Constant(3.0) - 1).value(0.0)
    5.0
    """

    base: Signal
    scale: float = 1.0
    offset: float = 0.0

    def __post_init__(self) -> None:
        if not isinstance(self.base, Signal):
            raise InvalidInputError("base", one_line(self.base), "a signal")
        object.__setattr__(self, "scale", check_finite_number(self.scale, "scale"))
        object.__setattr__(self, "offset", check_finite_number(self.offset, "offset"))

    def __repr__(self) -> str:
        text = f"({self.base!r})" if isinstance(self.base, Sum) else repr(self.base)
        if self.scale == -1.0:
            text = f"-{text}"
        elif self.scale != 1.0:
            text = f"{text} * {self.scale!r}"
        if self.offset > 0.0:
            text += f" + {self.offset!r}"
        elif self.offset < 0.0:
            text += f" - {-self.offset!r}"
        return text

    def _value(self, t: np.ndarray) -> np.ndarray:
        out = self.base._value(t)
        if self.scale != 1.0:
            out = out * self.scale
        return out + self.offset if self.offset != 0.0 else out

    def _velocity(self, t: np.ndarray) -> np.ndarray:
        return self.base._velocity(t) * self.scale

    def _acceleration(self, t: np.ndarray) -> np.ndarray:
        return self.base._acceleration(t) * self.scale

    def _kinks(self, t0: float, t1: float) -> np.ndarray:
        return self.base._kinks(t0, t1) if self.scale != 0.0 else np.empty(0)

    def _kink_count(self, t0: float, t1: float) -> int:
        return self.base._kink_count(t0, t1) if self.scale != 0.0 else 0

    def _culprit(self, quantity: str, t: float) -> tuple[str, Any]:
        inner = getattr(self.base, f"_{quantity}")(np.array([t]))
        if not np.isfinite(inner).all():
            return self.base._culprit(quantity, t)
        return ("scale", self.scale)


@dataclass(frozen=True, repr=False)
class Sum(Signal):
    """The sum of several signals: what ``a + b`` builds.

    Examples
    --------
    >>> from robotconf.signals import Constant, Ramp
    >>> total = Ramp() + Constant(1.0)
    >>> total
    Ramp() + Constant(1.0)
    >>> total.value(2.0), total.velocity(2.0)
    (3.0, 1.0)
    """

    terms: tuple[Signal, ...]

    def __post_init__(self) -> None:
        terms = tuple(self.terms)
        if not terms or not all(isinstance(s, Signal) for s in terms):
            raise InvalidInputError("terms", one_line(self.terms), "one or more signals")
        object.__setattr__(self, "terms", terms)

    def __repr__(self) -> str:
        text = repr(self.terms[0])
        for term in self.terms[1:]:
            part = repr(term)
            text += f" - {part[1:]}" if part.startswith("-") else f" + {part}"
        return text

    def _value(self, t: np.ndarray) -> np.ndarray:
        return np.sum([s._value(t) for s in self.terms], axis=0)

    def _velocity(self, t: np.ndarray) -> np.ndarray:
        return np.sum([s._velocity(t) for s in self.terms], axis=0)

    def _acceleration(self, t: np.ndarray) -> np.ndarray:
        return np.sum([s._acceleration(t) for s in self.terms], axis=0)

    def _kinks(self, t0: float, t1: float) -> np.ndarray:
        return np.concatenate([s._kinks(t0, t1) for s in self.terms])

    def _kink_count(self, t0: float, t1: float) -> int:
        return sum(s._kink_count(t0, t1) for s in self.terms)

    def _culprit(self, quantity: str, t: float) -> tuple[str, Any]:
        for term in self.terms:
            if not np.isfinite(getattr(term, f"_{quantity}")(np.array([t]))).all():
                return term._culprit(quantity, t)
        # Every term is finite, so their sum overflowed.
        return ("terms", _Terms(len(self.terms)))


class _Terms:
    """Shows a Sum's terms in a message without printing every one."""

    def __init__(self, count: int):
        self.count = count

    def __repr__(self) -> str:
        return f"<{self.count} signals whose sum overflows>"
