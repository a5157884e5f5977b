"""Drive a robot's coordinates with signals and sample its motion (DESIGN.md §2)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from ._dva import QUANTITIES, analytic_dva, first_derivative, numeric_dva, second_derivative
from ._errors import InvalidInputError
from ._jacobian import point_names
from ._validation import check_finite_number
from .signals import Constant, Signal

if TYPE_CHECKING:
    import pandas as pd
    from matplotlib.figure import Figure

    from ._robot import Robot

__all__ = ["simulate", "Motion", "METHODS", "MAX_SAMPLE_POINTS"]

#: The two ways of differentiating (DESIGN.md §2).
METHODS = ("analytic", "numeric")

#: Default ceiling on samples × points (points = modules + EE). Each sample-point holds
#: 15 floats (120 bytes), so the default allows about 6 GB of results.
MAX_SAMPLE_POINTS = 50_000_000

AXES = ("x", "y", "z")


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
        Simulink's Derivative block (see :mod:`robotconf._dva`). Then ``Motion.qd`` and
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


class Motion:
    """A sampled motion: coordinates, and DVA of every frame origin and the EE.

    Built by :func:`simulate`. All arrays are read-only and in the base frame.

    Attributes
    ----------
    robot : Robot
    t : ndarray, shape (T,)
        Sample times (s).
    q, qd, qdd : ndarray, shape (T, n)
        Coordinates and their first and second derivatives.
    method : str
        ``"analytic"`` or ``"numeric"``.
    signals : dict
        Coordinate name → signal, for the driven coordinates.
    points : tuple of str
        ``M1 … Mn`` (module names) and ``"EE"``.
    """

    def __init__(
        self,
        robot: Robot,
        t: np.ndarray,
        q: np.ndarray,
        qd: np.ndarray,
        qdd: np.ndarray,
        data: np.ndarray,
        method: str,
        signals: dict[str, Signal],
    ):
        for array in (t, q, qd, qdd, data):
            array.flags.writeable = False
        self.robot = robot
        self.t = t
        self._q, self._qd, self._qdd = q, qd, qdd
        self._data = data
        self.method = method
        self.signals = dict(signals)
        self.points = point_names(robot)
        self._table: pd.DataFrame | None = None

    def __repr__(self) -> str:
        return (
            f"Motion({self.robot.n} modules, {self.t.size} samples, "
            f"t = {self.t[0]:.6g} … {self.t[-1]:.6g} s, dt = {self.dt:.6g} s, "
            f"method={self.method!r}, signals={self.signals!r})"
        )

    # -- arrays -------------------------------------------------------------------------

    @property
    def dt(self) -> float:
        """Time step (s)."""
        return float(self.t[1] - self.t[0]) if self.t.size > 1 else float("nan")

    @property
    def q(self) -> np.ndarray:
        """Coordinates, shape (T, n)."""
        return self._q.T

    @property
    def qd(self) -> np.ndarray:
        """Coordinate velocities, shape (T, n) (finite differences for ``numeric``)."""
        return self._qd.T

    @property
    def qdd(self) -> np.ndarray:
        """Coordinate accelerations, shape (T, n) (finite differences for ``numeric``)."""
        return self._qdd.T

    def quantity(self, name: str) -> np.ndarray:
        """One quantity of every point, shape (T, n + 1, 3): points M1…Mn, EE; x, y, z.

        ``name`` is one of :data:`~robotconf._dva.QUANTITIES`.
        """
        if name not in QUANTITIES:
            raise InvalidInputError("quantity", name, f"one of {QUANTITIES}")
        return self._data[:, QUANTITIES.index(name)].transpose(2, 0, 1)

    @property
    def position(self) -> np.ndarray:
        """Positions (length), shape (T, n + 1, 3)."""
        return self.quantity("position")

    @property
    def displacement(self) -> np.ndarray:
        """Position minus the position at ``t0`` (length), shape (T, n + 1, 3)."""
        return self.quantity("displacement")

    @property
    def velocity(self) -> np.ndarray:
        """Linear velocities (length/s), shape (T, n + 1, 3)."""
        return self.quantity("velocity")

    @property
    def acceleration(self) -> np.ndarray:
        """Linear accelerations (length/s²), shape (T, n + 1, 3)."""
        return self.quantity("acceleration")

    @property
    def angular_velocity(self) -> np.ndarray:
        """Angular velocity of each frame (rad/s), shape (T, n + 1, 3); EE = last frame."""
        return self.quantity("angular_velocity")

    def columns(self) -> np.ndarray:
        """All series as rows, shape (C, T), in table column order (point, quantity, axis)."""
        return self._data.reshape(-1, self.t.size)

    def kinks(self) -> dict[str, np.ndarray]:
        """Per driven coordinate: times where its value or velocity jumps (see plot notes)."""
        t0, t1 = float(self.t[0]), float(self.t[-1])
        found = {name: s.kinks(t0, t1) for name, s in self.signals.items()}
        return {name: times for name, times in found.items() if times.size}

    # -- presentation (pandas / matplotlib imported on use) -----------------------------

    @property
    def table(self) -> pd.DataFrame:
        """pandas DataFrame indexed by time (s), columns (point, quantity, axis).

        Built once and cached; copy it before editing.
        """
        if self._table is None:
            from ._motion_table import motion_table

            self._table = motion_table(self)
        return self._table

    def stats(self) -> pd.DataFrame:
        """Simulink Scope "Signal Statistics" of every column (see ``_motion_table``)."""
        from ._motion_table import motion_stats

        return motion_stats(self)

    def compare(self, other: Motion) -> pd.DataFrame:
        """Column-wise difference ``self.table − other.table`` (same time grid and robot)."""
        from ._motion_table import compare_motions

        return compare_motions(self, other)

    def to_csv(self, path: Any, **kwargs: Any) -> None:
        """Write :attr:`table` as CSV (see ``_motion_table.motion_to_csv``)."""
        from ._motion_table import motion_to_csv

        motion_to_csv(self, path, **kwargs)

    def to_excel(self, path: Any, **kwargs: Any) -> None:
        """Write :attr:`table` to an .xlsx file (needs openpyxl)."""
        from ._motion_table import motion_to_excel

        motion_to_excel(self, path, **kwargs)

    def plot(self, point: str = "EE", **kwargs: Any) -> Figure:
        """3 × 3 matplotlib figure of one point (see ``_motion_plot.plot_motion``)."""
        from ._motion_plot import plot_motion

        return plot_motion(self, point, **kwargs)
