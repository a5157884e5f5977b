"""Drive a robot's coordinates with signals and sample its motion (docs/conventions.md)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_finite_number
from ..kinematics import point_names
from ..signals import Constant, Signal
from ._dva import (
    analytic_dva,
    backward_derivative,
    backward_dva,
    backward_second_derivative,
    first_derivative,
    numeric_dva,
    second_derivative,
)
from ._memory import check_simulation_memory
from ._motion import Motion
from ._overflow import check_coordinates_finite, check_results_finite
from ._settings import MAX_SAMPLE_POINTS, SimulationSettings

if TYPE_CHECKING:
    from ..kinematics import Robot

__all__ = ["simulate"]


def _check_signals(robot: Robot, signals: Any) -> dict[int, Signal]:
    if signals is None:
        return {}
    if not isinstance(signals, Mapping):
        names = robot.coordinate_names
        raise InvalidInputError(
            "signals",
            signals,
            f"a dict mapping coordinate names {names[0]}…{names[-1]} or indices to signals",
            problem="not a dict:",
        )
    result: dict[int, Signal] = {}
    for key, signal in signals.items():
        index = robot.index(key, "signals")
        if index in result:
            raise InvalidInputError(
                "signals",
                key,
                "each coordinate once",
                problem=f"{robot.coordinate_names[index]} is given twice:",
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
        Maps coordinates to :class:`~robotconf.signals.Signal` objects (a plain number
        means a constant); a key is anything :meth:`Robot.index <robotconf.Robot.index>`
        reads: a coordinate name (``"q3"``), a module name (``"M3"``) or a 0-based index.
        Coordinates without a signal hold their module's own ``q``.
    t_end : float
        Last sample time (s), included when ``t_end − t0`` is a multiple of ``dt``.
    dt : float
        Time step (s), > 0.
    t0 : float
        First sample time (s); displacement is measured from the position here.
    method : {"analytic", "numeric", "backward"}
        ``analytic``: exact chain rule with the signals' own derivatives (default);
        ``numeric``: second-order central differences of the sampled positions
        (see :func:`robotconf.motion.numeric_dva`);
        ``backward``: first-order backward differences ``(x[k] − x[k−1]) / dt``, what
        Simulink's Derivative block outputs, with acceleration from a second block on
        that velocity (see :func:`robotconf.motion.backward_dva`). Like the block, whose
        initial output is zero, it gives velocity and acceleration 0 at the first
        sample, and the acceleration at the second is the velocity's step from that 0
        divided by ``dt``. With either difference method ``Motion.qd`` and
        ``Motion.qdd`` are finite differences too.
    max_sample_points : int
        Refuse runs with more samples × points (points = modules + EE); default
        :data:`MAX_SAMPLE_POINTS`. Samples alone never exceed :data:`MAX_TIME_SAMPLES`.

    The time settings are checked by :class:`SimulationSettings` (their limits are in
    docs/conventions.md, "Limits of a run"); with one at hand, call
    ``simulate(robot, signals, **settings.to_dict())``. Before allocating anything the
    peak memory is estimated (:mod:`robotconf.motion._memory`) and checked against
    :func:`robotconf.memory_budget`.

    Returns
    -------
    Motion

    Raises
    ------
    InvalidInputError
        Naming the field: a time setting outside its limits, ``t_end ≤ t0``, too many
        samples (or samples × points), a run needing more memory than the budget (named
        ``dt`` or ``t_end``), an unknown method, a signal for a coordinate that does not
        exist, fewer than 4 samples with ``numeric``, or results that overflow to inf or
        NaN (named ``signals[q<i>]``, ``signals`` or ``robot``).

    Notes
    -----
    At a drop of the paper's sawtooth (``q3`` from ``2 − dt`` to ``0``) the backward
    ``q̇3`` is ``−(2 − dt)/dt`` (−1999 rad/s at 1 ms) on one sample; the central
    difference gives ``−(2 − 2dt)/2dt`` (−999 rad/s) on two: Simulink's spikes are about
    twice as tall. The analytic method has no spike (it reports the one-sided slope).

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

    The same run as the paper's Simulink Derivative blocks see it:

    >>> simulink = simulate(robot, {"q3": signals.RepeatingSequence()}, 10.0, method="backward")
    >>> simulink.velocity[0, -1] + 0.0  # the block's initial output
    array([0., 0., 0.])
    >>> round(float(simulink.qd[2000, 2]), 6)  # t = 2 s: q3 drops from 1.999 to 0
    -1999.0
    """
    settings = SimulationSettings(t_end, dt, t0, method)
    chosen = _check_signals(robot, signals)
    limit = int(check_finite_number(max_sample_points, "max_sample_points"))
    settings.check_samples(robot.n + 1, limit)
    check_simulation_memory(settings, robot.n, chosen.values())
    t = settings.time_grid(robot.n + 1, limit)
    # Overflow is detected on the results and refused with a message naming its cause,
    # so numpy's own warnings about it would only be noise.
    with np.errstate(over="ignore", invalid="ignore"):
        return _run(robot, chosen, t, settings.method, settings.dt)


def _run(
    robot: Robot, chosen: dict[int, Signal], t: np.ndarray, method: str, step: float
) -> Motion:
    """Sample the signals on ``t`` and compute the DVA, refusing overflowed results."""
    n, samples = robot.n, t.size
    names = robot.coordinate_names
    q = np.empty((n, samples))
    qd = np.zeros((n, samples))
    qdd = np.zeros((n, samples))
    q[:] = robot.q[:, np.newaxis]
    for i, signal in chosen.items():
        try:
            q[i] = signal.value(t)
            if method == "analytic":
                qd[i] = signal.velocity(t)
                qdd[i] = signal.acceleration(t)
        except InvalidInputError as error:
            # A signal names its own parameter; say which coordinate it drives, too.
            raise error.within(f"signals[{names[i]}]") from None
    rows = {"values": q, "velocities": qd, "accelerations": qdd}
    if method == "analytic":
        check_coordinates_finite(rows, chosen, names)
        data = analytic_dva(robot, q.T, qd.T, qdd.T)
    else:
        check_coordinates_finite({"values": q}, chosen, names)
        if method == "backward":
            data = backward_dva(robot, q.T, step)
            qd = backward_derivative(q, step)
            qdd = backward_second_derivative(q, step)
        else:
            data = numeric_dva(robot, q.T, step)
            qd = first_derivative(q, step)
            qdd = second_derivative(q, step)
        rates = {"velocities": qd, "accelerations": qdd}
        check_coordinates_finite(rates, chosen, names, finite_differences=True)
    driven = {names[i]: s for i, s in chosen.items()}
    check_results_finite(data, robot, point_names(robot), driven)
    return Motion(robot, t, q, qd, qdd, data, method, driven)
