"""Drive a robot's coordinates with signals and sample its motion (docs/conventions.md)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_finite_number
from ..signals import Constant, Signal
from ._dva import analytic_dva, first_derivative, numeric_dva, second_derivative
from ._motion import Motion

if TYPE_CHECKING:
    from ..kinematics import Robot

__all__ = ["simulate", "METHODS", "MAX_SAMPLE_POINTS"]

#: The two ways of differentiating (docs/conventions.md, "Motion").
METHODS = ("analytic", "numeric")

#: Default ceiling on samples × points (points = modules + EE). Each sample-point holds
#: 15 floats (120 bytes), so the default allows about 6 GB of results.
MAX_SAMPLE_POINTS = 50_000_000


def _check_method(method: Any) -> str:
    allowed = "'analytic' (exact chain rule) or 'numeric' (finite differences)"
    if not isinstance(method, str) or method.strip().lower() not in METHODS:
        raise InvalidInputError("method", method, allowed, problem="unknown method")
    return method.strip().lower()


def _time_grid(t0: Any, t_end: Any, dt: Any, points: int, limit: int) -> np.ndarray:
    start = check_finite_number(t0, "t0")
    stop = check_finite_number(t_end, "t_end")
    step = check_finite_number(dt, "dt")
    if step <= 0.0:
        raise InvalidInputError("dt", step, "a time step > 0 (s)", problem="must be positive, got")
    if stop <= start:
        raise InvalidInputError(
            "t_end", stop, f"a time after t0 = {start} s", problem="must be later than t0, got"
        )
    steps = (stop - start) / step
    # Round-off in (t_end − t0)/dt must not drop the last sample (0.3/0.1 = 2.9999…).
    count = int(np.floor(steps + max(1e-9, 8.0 * np.finfo(float).eps * steps))) + 1
    if count * points > limit:
        raise InvalidInputError(
            "dt",
            step,
            f"at most {limit:.3g} samples × points: increase dt, shorten t_end − t0, or pass "
            "a larger max_sample_points if you have the memory (120 bytes each)",
            problem=f"{count} samples × {points} points = {count * points:.3g} is too many at",
        )
    return start + step * np.arange(count)


def _check_signals(robot: Robot, signals: Any) -> dict[int, Signal]:
    names = robot.coordinate_names
    allowed = f"coordinate names {names[0]}…{names[-1]} or indices 0 to {robot.n - 1}"
    if signals is None:
        return {}
    if not isinstance(signals, Mapping):
        raise InvalidInputError(
            "signals", signals, f"a dict mapping {allowed} to signals", problem="not a dict:"
        )
    result: dict[int, Signal] = {}
    for key, signal in signals.items():
        if isinstance(key, str) and key.strip().lower() in names:
            index = names.index(key.strip().lower())
        elif isinstance(key, (int, np.integer)) and not isinstance(key, (bool, np.bool_)):
            if not 0 <= int(key) < robot.n:
                raise InvalidInputError(
                    "signals", key, allowed, problem=f"no coordinate {int(key)} on this robot:"
                )
            index = int(key)
        else:
            raise InvalidInputError("signals", key, allowed, problem="unknown coordinate")
        if index in result:
            raise InvalidInputError(
                "signals", key, allowed, problem=f"{names[index]} is given twice:"
            )
        if not isinstance(signal, Signal):
            try:
                signal = Constant(signal)
            except InvalidInputError:
                raise InvalidInputError(
                    f"signals[{key!r}]", signal, "a signal or a finite number"
                ) from None
        result[index] = signal
    return result


def simulate(
    robot: Robot,
    signals: Mapping[str | int, Signal | float] | None,
    t_end: float,
    dt: float = 1e-3,
    t0: float = 0.0,
    method: str = "analytic",
    *,
    max_sample_points: int = MAX_SAMPLE_POINTS,
) -> Motion:
    """Drive coordinates with signals and sample position, velocity and acceleration.

    Parameters
    ----------
    robot : Robot
    signals : dict
        Maps coordinate names (``"q3"``) or 0-based indices to
        :class:`~robotconf.signals.Signal` objects (a plain number means a constant).
        Coordinates without a signal hold their module's own ``q``.
    t_end : float
        Last sample time (s), included when ``t_end − t0`` is a multiple of ``dt``.
    dt : float
        Time step (s), > 0.
    t0 : float
        First sample time (s); displacement is measured from the position here.
    method : {"analytic", "numeric"}
        ``analytic``: exact chain rule with the signals' own derivatives (default);
        ``numeric``: second-order finite differences of the sampled positions, like
        Simulink's Derivative block (see :mod:`robotconf.motion._dva`). Then ``Motion.qd`` and
        ``Motion.qdd`` are finite differences too.
    max_sample_points : int
        Refuse runs with more samples × points (points = modules + EE).

    Returns
    -------
    Motion

    Raises
    ------
    InvalidInputError
        For ``dt ≤ 0``, ``t_end ≤ t0``, too many samples, an unknown method, a signal for a
        coordinate that does not exist, or fewer than 4 samples with ``numeric``.

    Examples
    --------
    The paper's demonstration (§3, Figures 16–19): Simulink's default sawtooth on q3.

    >>> import robotconf as rc
    >>> from robotconf import signals
    >>> robot = rc.Robot(
    ...     [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
    ...     end_effector=(40, 0, 0),
    ... )
    >>> motion = simulate(robot, {"q3": signals.RepeatingSequence()}, t_end=10.0)
    >>> motion
    Motion(3 modules, 10001 samples, t = 0 … 10 s, dt = 0.001 s, method='analytic', ...)
    >>> motion.velocity[0, -1] + 0.0  # EE at t = 0: q3 = 0, q̇3 = 1 rad/s
    array([  0.,   0., -40.])
    >>> float(motion.table[("EE", "position", "x")].max())  # 30 + 40 cos 0
    70.0
    """
    method = _check_method(method)
    chosen = _check_signals(robot, signals)
    limit = int(check_finite_number(max_sample_points, "max_sample_points"))
    t = _time_grid(t0, t_end, dt, robot.n + 1, limit)
    step = check_finite_number(dt, "dt")
    n, samples = robot.n, t.size
    q = np.empty((n, samples))
    qd = np.zeros((n, samples))
    qdd = np.zeros((n, samples))
    q[:] = robot.q[:, np.newaxis]
    for i, signal in chosen.items():
        q[i] = signal.value(t)
        if method == "analytic":
            qd[i] = signal.velocity(t)
            qdd[i] = signal.acceleration(t)
    if method == "analytic":
        data = analytic_dva(robot, q.T, qd.T, qdd.T)
    else:
        data = numeric_dva(robot, q.T, step)
        qd = first_derivative(q, step)
        qdd = second_derivative(q, step)
    names = robot.coordinate_names
    return Motion(robot, t, q, qd, qdd, data, method, {names[i]: s for i, s in chosen.items()})
