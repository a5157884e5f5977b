"""Signals that drive a generalized coordinate over time: ``q(t)``, ``q̇(t)``, ``q̈(t)``.

Simulink's source blocks (Constant, Step, Ramp, Sine Wave, Repeating Sequence) and the
smooth point-to-point profiles of a robotics course (cubic, quintic, trapezoidal velocity).
Every signal is immutable, vectorized over a time array (seconds) and gives exact
derivatives; at kinks and step edges the right-sided derivative is reported and the
impulse is left out (see :meth:`Signal.kinks`). Signals combine with numbers and each
other: ``saw * 0.5 + 1``, ``-sig``, ``a + b``.

>>> from robotconf import signals
>>> saw = signals.RepeatingSequence(times=[0, 2], values=[0, 2]) * 0.5 + 1
>>> saw.value([0.0, 1.0, 2.0])
array([1. , 1.5, 1. ])
>>> saw.kinks(0.0, 5.0)
array([0., 2., 4.])

Limits (each refused with an error naming the parameter): profile durations and periods
of at least :data:`MIN_DURATION` (1e-9 s); velocity and acceleration scales below
:data:`MAX_RATE` (1e306); tables of at most :data:`MAX_TABLE_POINTS` points. A value that
would still overflow at some time (a ramp at ``t = 1e308``) is refused when evaluated.
"""

from ._base import MAX_RATE, MIN_DURATION, Affine, Signal, Sum
from ._profiles import Cubic, Quintic, Trapezoidal
from ._repeating import MAX_TABLE_POINTS, RepeatingSequence
from ._serialize import SIGNAL_TYPES, signal_from_dict
from ._sources import Constant, Ramp, Sine, Step
from ._spec import (
    MAX_NUMBER_CHARS,
    MAX_SPEC_LENGTH,
    SIGNAL_KINDS,
    SPEC_HELP,
    parse_signal,
    parse_signal_spec,
)
from ._time_laws import (
    PEAK_ACCEL,
    PEAK_SPEED,
    POLYNOMIAL_LAWS,
    TAU_COEFFICIENTS,
    fastest_polynomial,
    fastest_trapezoid,
    polynomial_law,
    trapezoid_law,
)

__all__ = [
    "Affine",
    "Constant",
    "Cubic",
    "Quintic",
    "Ramp",
    "RepeatingSequence",
    "Signal",
    "SIGNAL_TYPES",
    "signal_from_dict",
    "Sine",
    "Step",
    "Sum",
    # text specs such as "q3=sine:amplitude=0.5,frequency=0.2"
    "parse_signal_spec",
    "parse_signal",
    "SIGNAL_KINDS",
    "SPEC_HELP",
    "MAX_SPEC_LENGTH",
    "MAX_NUMBER_CHARS",
    "Trapezoidal",
    # the time laws of rest-to-rest motions (one home for signals, programs and the course)
    "polynomial_law",
    "trapezoid_law",
    "fastest_trapezoid",
    "fastest_polynomial",
    "POLYNOMIAL_LAWS",
    "TAU_COEFFICIENTS",
    "PEAK_SPEED",
    "PEAK_ACCEL",
    # limits
    "MIN_DURATION",
    "MAX_RATE",
    "MAX_TABLE_POINTS",
]
