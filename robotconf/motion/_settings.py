"""Simulation settings (t_end, dt, t0, method): validated once, used by every front end.

:func:`~robotconf.motion.simulate`, the file format, the ``robotconf report`` command and
the panel all build a :class:`SimulationSettings`, so the same rules, limits and messages
apply wherever a run is described.
"""

from __future__ import annotations

import dataclasses
import datetime
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._json_fields import check_json_number, check_json_object
from .._validation import check_finite_number, check_integer
from ._time_grid import (
    DEFAULT_TIME_STEP,
    MAX_TIME_SAMPLES,
    check_time_bounds,
    sample_count,
    time_grid,
)

__all__ = ["SimulationSettings", "METHODS", "MAX_TIME_SAMPLES", "MAX_SAMPLE_POINTS"]

#: The ways of differentiating (docs/conventions.md, "Motion and DVA"): the exact chain
#: rule, central differences, and Simulink's Derivative block (backward differences).
METHODS = ("analytic", "numeric", "backward")

#: Default ceiling on samples × points of one run (points = modules + EE). Each
#: sample-point holds 15 floats (120 bytes), so the default allows about 6 GB of results;
#: it only binds for robots of five or more modules, below which MAX_TIME_SAMPLES does.
MAX_SAMPLE_POINTS = 50_000_000

_FIELDS = ("t_end", "dt", "t0", "method")
_REQUIRED = {"t_end": True, "dt": False, "t0": False, "method": False}
_METHOD_ALLOWED = (
    "'analytic' (exact chain rule), 'backward' (backward differences, as Simulink's "
    "Derivative block) or 'numeric' (central differences)"
)
_SECONDS = "a finite real number of seconds"


def _check_method(method: Any) -> str:
    # numpy text (np.str_) is a str and welcome; bytes, numbers and arrays are not text.
    if not isinstance(method, str):
        raise InvalidInputError("method", method, _METHOD_ALLOWED, problem="expected text, got")
    if method.strip().lower() not in METHODS:
        raise InvalidInputError("method", method, _METHOD_ALLOWED, problem="unknown method")
    return str(method.strip().lower())


def _seconds(value: Any, field: str) -> float:
    """A time setting as a finite float of seconds.

    Dates, complex numbers, booleans and numpy text (whose dtype float() would convert
    or silently truncate) are refused by name before :func:`check_finite_number`.
    """
    kind = getattr(getattr(value, "dtype", None), "kind", None)
    if isinstance(value, (datetime.date, datetime.time, datetime.timedelta)) or kind in ("M", "m"):
        raise InvalidInputError(
            field,
            value,
            "a plain number of seconds (for a duration, its .total_seconds())",
            problem="a date or duration is not a number of seconds:",
        )
    if isinstance(value, complex) or kind == "c":
        raise InvalidInputError(field, value, _SECONDS, problem="a complex number is not a time:")
    if kind == "b":
        raise InvalidInputError(field, value, _SECONDS, problem="a boolean is not a number:")
    if kind in ("U", "S"):
        raise InvalidInputError(field, value, _SECONDS, problem="text is not a number:")
    if kind not in (None, "i", "u", "f"):
        raise InvalidInputError(
            field, value, _SECONDS, problem=f"a numpy {value.dtype} value is not a number:"
        )
    return check_finite_number(value, field)


@dataclass(frozen=True)
class SimulationSettings:
    """When and how a run samples its signals: ``t0 … t_end`` every ``dt``, one method.

    Parameters
    ----------
    t_end : float
        Last sample time (s), included when ``t_end − t0`` is a multiple of ``dt``;
        later than ``t0``; ``|t_end| ≤`` :data:`~robotconf.motion.MAX_TIME` (10⁹ s).
    dt : float
        Time step (s), from :data:`~robotconf.motion.MIN_TIME_STEP` (1 ns) to 10⁹ s, and
        at least :data:`~robotconf.motion.TIME_RESOLUTION` × max(|t0|, |t_end|).
    t0 : float
        First sample time (s), ``|t0| ≤`` 10⁹ s.
    method : {"analytic", "numeric", "backward"}
        How velocities and accelerations are found (any case; stored in lower case):
        the exact chain rule, central differences, or the backward differences of
        Simulink's Derivative block (see :func:`~robotconf.motion.simulate`).

    Times are real numbers of seconds: booleans, complex numbers, dates and durations
    (``datetime``, ``numpy.datetime64``) and text are refused.

    Raises
    ------
    InvalidInputError
        Naming the field: a value that is not a finite real number, a time or step
        outside the limits above, ``t_end ≤ t0``, an unknown method, or more than
        :data:`MAX_TIME_SAMPLES` samples (named ``dt``).

    Examples
    --------
    The paper's run (§3, Figures 16–19): Simulink's default stop time at 1 ms.

    >>> settings = SimulationSettings(t_end=10.0)
    >>> settings.samples
    10001
    >>> settings.to_dict()
    {'t_end': 10.0, 'dt': 0.001, 't0': 0.0, 'method': 'analytic'}
    >>> SimulationSettings(0.3, dt=0.1).time_grid()
    array([0. , 0.1, 0.2, 0.3])
    >>> SimulationSettings(10.0, method="Backward").method  # Simulink's Derivative block
    'backward'
    >>> SimulationSettings(1.0, dt=0.0)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: dt: must be positive, got 0.0; allowed: a time step > 0 (s)
    """

    t_end: float
    dt: float = DEFAULT_TIME_STEP
    t0: float = 0.0
    method: str = "analytic"

    def __post_init__(self) -> None:
        t_end = _seconds(self.t_end, "t_end")
        dt = _seconds(self.dt, "dt")
        t0 = _seconds(self.t0, "t0")
        # Bounds first: after them no time arithmetic can overflow or lose the step.
        check_time_bounds(t_end, dt, t0)
        method = _check_method(self.method)
        sample_count(t0, t_end, dt)
        for name, value in (("t_end", t_end), ("dt", dt), ("t0", t0), ("method", method)):
            object.__setattr__(self, name, value)

    @property
    def samples(self) -> int:
        """Number of sample times, ``⌊(t_end − t0)/dt⌋ + 1`` (round-off safe).

        >>> SimulationSettings(0.3, dt=0.1).samples  # 0.3/0.1 = 2.9999… in floats
        4
        """
        return sample_count(self.t0, self.t_end, self.dt)

    def check_samples(self, points: int = 1, limit: int = MAX_SAMPLE_POINTS) -> int:
        """The number of samples, refusing more than ``limit`` samples × points.

        Parameters
        ----------
        points : int
            Points computed at every sample (modules + EE for a robot), ≥ 1.
        limit : int
            Largest allowed samples × points (see :data:`MAX_SAMPLE_POINTS`).

        Returns
        -------
        int

        Raises
        ------
        InvalidInputError
            Named ``dt`` when samples × points exceeds ``limit``.

        Examples
        --------
        >>> SimulationSettings(10.0).check_samples(points=4)
        10001
        >>> SimulationSettings(10.0).check_samples(points=4, limit=40_000)
        Traceback (most recent call last):
        ...
        robotconf.InvalidInputError: dt: 10001 samples × 4 points = 4e+04 is too many at ...
        """
        points = check_integer(points, "points", 1)
        limit = check_integer(limit, "max_sample_points")
        count = self.samples
        if count * points > limit:
            raise InvalidInputError(
                "dt",
                self.dt,
                f"at most {limit:.3g} samples × points: increase dt, shorten t_end − t0, or "
                "pass a larger max_sample_points if you have the memory (120 bytes each)",
                problem=f"{count} samples × {points} points = {count * points:.3g} is too many at",
            )
        return count

    def time_grid(self, points: int = 1, limit: int = MAX_SAMPLE_POINTS) -> np.ndarray:
        """The sample times ``t0, t0 + dt, …`` (s), refusing runs too big for memory.

        Parameters
        ----------
        points, limit : int
            As for :meth:`check_samples`.

        Returns
        -------
        ndarray, shape (samples,)

        Raises
        ------
        InvalidInputError
            Named ``dt`` when samples × points exceeds ``limit``.

        Examples
        --------
        >>> SimulationSettings(1.0, dt=0.3, t0=0.1).time_grid()
        array([0.1, 0.4, 0.7, 1. ])
        >>> SimulationSettings(10.0).time_grid(points=4, limit=40_000)
        Traceback (most recent call last):
        ...
        robotconf.InvalidInputError: dt: 10001 samples × 4 points = 4e+04 is too many at ...
        """
        return time_grid(self.t0, self.dt, self.check_samples(points, limit))

    def with_changes(self, **changes: Any) -> SimulationSettings:
        """A copy with some fields replaced, validated as a whole.

        >>> SimulationSettings(10.0).with_changes(dt=0.01, method="numeric")
        SimulationSettings(t_end=10.0, dt=0.01, t0=0.0, method='numeric')
        """
        for key in changes:
            if key not in _FIELDS:
                raise InvalidInputError(
                    key, changes[key], f"the fields {', '.join(_FIELDS)}", problem="unknown field"
                )
        return dataclasses.replace(self, **changes)

    def to_dict(self) -> dict[str, Any]:
        """All four settings as plain data (the file format's ``"simulation"`` object).

        >>> SimulationSettings(2.0, method="Numeric").to_dict()
        {'t_end': 2.0, 'dt': 0.001, 't0': 0.0, 'method': 'numeric'}
        """
        return {"t_end": self.t_end, "dt": self.dt, "t0": self.t0, "method": self.method}

    @classmethod
    def from_dict(cls, data: Any, path: str = "simulation") -> SimulationSettings:
        """Settings from parsed JSON: only the four keys, ``t_end`` required.

        Parameters
        ----------
        data : dict
            ``t_end``, ``dt``, ``t0`` (JSON numbers, s) and ``method`` (text); keys left
            out take the defaults.
        path : str
            Where ``data`` sits in its document; every error names ``path.key``.

        Returns
        -------
        SimulationSettings

        Raises
        ------
        InvalidInputError
            For anything but an object, an unknown, repeated or missing key, a value of
            the wrong JSON type, or any rule of the constructor.

        Examples
        --------
        >>> SimulationSettings.from_dict({"t_end": 5, "dt": 0.01})
        SimulationSettings(t_end=5.0, dt=0.01, t0=0.0, method='analytic')
        >>> SimulationSettings.from_dict({"t_end": 5, "dt": True})
        Traceback (most recent call last):
        ...
        robotconf.InvalidInputError: simulation.dt: expected a number, got a boolean: True; ...
        """
        check_json_object(data, path, _REQUIRED)
        values: dict[str, Any] = {}
        for key in ("t_end", "dt", "t0"):
            if key in data:
                values[key] = check_json_number(data[key], f"{path}.{key}")
        if "method" in data:
            if not isinstance(data["method"], str):
                raise InvalidInputError(
                    f"{path}.method", data["method"], _METHOD_ALLOWED, problem="expected text, got"
                )
            values["method"] = data["method"]
        try:
            return cls(**values)
        except InvalidInputError as error:
            raise error.within(path) from None
