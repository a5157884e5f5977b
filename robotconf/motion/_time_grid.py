"""The time grid ``t0, t0 + dt, …, t_end``: its documented limits and safe arithmetic.

Every time setting is bounded before any arithmetic touches it, so ``t_end − t0``,
``(t_end − t0)/dt`` and ``t0 + k·dt`` can neither overflow nor lose the step to
round-off (docs/conventions.md, "Limits of a run"):

* ``|t0|, |t_end| ≤`` :data:`MAX_TIME` (10⁹ s, about 32 years);
* :data:`MIN_TIME_STEP` ``≤ dt ≤`` :data:`MAX_TIME` (1 ns to 10⁹ s);
* ``dt ≥`` :data:`TIME_RESOLUTION` ``× max(|t0|, |t_end|)``: float64 carries about 16
  digits, so a step finer than 10⁻¹⁰ of the times would be rounded away (at t = 10⁹ s a
  1 ns step vanishes entirely) and consecutive samples would repeat;
* at most :data:`MAX_TIME_SAMPLES` samples.

Within these, the span is at most 2·10⁹ s and the step count at most 2·10¹⁸: finite,
never a denormal, and exact enough to count samples.
"""

from __future__ import annotations

import numpy as np

from .._errors import InvalidInputError

__all__ = [
    "MAX_TIME",
    "MIN_TIME_STEP",
    "TIME_RESOLUTION",
    "MAX_TIME_SAMPLES",
    "DEFAULT_TIME_STEP",
    "check_time_bounds",
    "sample_count",
    "time_grid",
]

#: Largest |t0| and |t_end| (s): 10⁹ s is about 32 years, far beyond any teaching run,
#: and keeps ``t_end − t0`` and ``(t_end − t0)/dt`` finite.
MAX_TIME = 1e9

#: Smallest time step (s): 1 ns. Smaller steps (down to the denormal 5e-324) only make
#: ``(t_end − t0)/dt`` overflow or the grid too long to hold.
MIN_TIME_STEP = 1e-9

#: dt must be at least this fraction of the largest |time|, so that ``t0 + k·dt`` keeps
#: the step to about 2·10⁻⁶ of dt (float64's relative precision is 2.2·10⁻¹⁶).
TIME_RESOLUTION = 1e-10

#: Ceiling on time samples, ``(t_end − t0)/dt + 1``, wherever settings are made (files,
#: :func:`~robotconf.motion.simulate`, the report command, the panel). 10⁷ samples are
#: 2.8 hours at 1 ms, far beyond a teaching run; the memory budget may bind earlier.
MAX_TIME_SAMPLES = 10_000_000

#: The default time step (s), Simulink's usual 1 ms.
DEFAULT_TIME_STEP = 1e-3

_TIME_ALLOWED = f"a time from {-MAX_TIME:g} to {MAX_TIME:g} s"
_STEP_ALLOWED = f"a time step from {MIN_TIME_STEP:g} s to {MAX_TIME:g} s"


def check_time_bounds(t_end: float, dt: float, t0: float) -> None:
    """Refuse finite time settings outside the documented limits (see module notes).

    Parameters
    ----------
    t_end, dt, t0 : float
        Finite floats (s), already checked to be real numbers.

    Raises
    ------
    InvalidInputError
        Naming ``t_end``, ``t0`` or ``dt``.

    Examples
    --------
    >>> check_time_bounds(10.0, 1e-3, 0.0)
    >>> check_time_bounds(1.0, 5e-324, 0.0)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: dt: below the smallest time step: 5e-324; allowed: ...
    >>> check_time_bounds(1e308, 1e-3, -1e308)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: t_end: out of range: 1e+308; allowed: a time from -1e+09 to 1e+09 s
    """
    for name, value in (("t_end", t_end), ("t0", t0)):
        if abs(value) > MAX_TIME:
            raise InvalidInputError(name, value, _TIME_ALLOWED, problem="out of range:")
    if dt <= 0.0:
        raise InvalidInputError("dt", dt, "a time step > 0 (s)", problem="must be positive, got")
    if dt < MIN_TIME_STEP:
        raise InvalidInputError("dt", dt, _STEP_ALLOWED, problem="below the smallest time step:")
    if dt > MAX_TIME:
        raise InvalidInputError("dt", dt, _STEP_ALLOWED, problem="above the largest time step:")
    if t_end <= t0:
        raise InvalidInputError(
            "t_end", t_end, f"a time after t0 = {t0} s", problem="must be later than t0, got"
        )
    largest = max(abs(t0), abs(t_end))
    if dt < TIME_RESOLUTION * largest:
        raise InvalidInputError(
            "dt",
            dt,
            f"dt ≥ {TIME_RESOLUTION:g} × max(|t0|, |t_end|) = {TIME_RESOLUTION * largest:.3g} s "
            "(or times nearer 0), so that every sample keeps its step",
            problem=f"too fine for times as large as {largest:g} s:",
        )


def sample_count(t0: float, t_end: float, dt: float) -> int:
    """Number of samples ``⌊(t_end − t0)/dt⌋ + 1``, round-off safe, ≤ :data:`MAX_TIME_SAMPLES`.

    The settings must have passed :func:`check_time_bounds`, so the quotient is finite.

    Raises
    ------
    InvalidInputError
        Named ``dt`` when there would be more than :data:`MAX_TIME_SAMPLES` samples.

    Examples
    --------
    >>> sample_count(0.0, 0.3, 0.1)  # 0.3/0.1 = 2.9999… in floats
    4
    """
    steps = (t_end - t0) / dt
    # ``not <`` also refuses a NaN, should a caller skip check_time_bounds.
    if not steps < MAX_TIME_SAMPLES:
        raise InvalidInputError(
            "dt",
            dt,
            f"at most {MAX_TIME_SAMPLES:,} time samples ((t_end − t0)/dt + 1 = {steps + 1:.4g} "
            "here): increase dt or shorten t_end − t0",
            problem="too many samples at",
        )
    # Round-off in (t_end − t0)/dt must not drop the last sample (0.3/0.1 = 2.9999…).
    return int(np.floor(steps + max(1e-9, 8.0 * np.finfo(float).eps * steps))) + 1


def time_grid(t0: float, dt: float, count: int) -> np.ndarray:
    """The sample times ``t0 + k·dt`` for ``k = 0 … count − 1`` (s), shape (count,).

    Built in place: one array of ``count`` floats, no temporaries.

    >>> time_grid(0.1, 0.3, 4)
    array([0.1, 0.4, 0.7, 1. ])
    """
    t = np.arange(count, dtype=float)
    t *= dt
    t += t0
    return t
