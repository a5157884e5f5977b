"""A sampled motion: coordinates over time and the DVA of every frame origin and the EE."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
from ..kinematics import point_names
from ..signals import Signal
from ._dva import QUANTITIES
from ._memory import check_kink_memory

if TYPE_CHECKING:
    import pandas as pd
    from matplotlib.figure import Figure

    from ..kinematics import Robot

__all__ = ["Motion"]


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
        ``"analytic"``, ``"numeric"`` (central differences) or ``"backward"``
        (Simulink's Derivative block).
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
        """Coordinate velocities, shape (T, n) (finite differences unless ``analytic``)."""
        return self._qd.T

    @property
    def qdd(self) -> np.ndarray:
        """Coordinate accelerations, shape (T, n) (finite differences unless ``analytic``)."""
        return self._qdd.T

    def quantity(self, name: str) -> np.ndarray:
        """One quantity of every point, shape (T, n + 1, 3): points M1…Mn, EE; x, y, z.

        ``name`` is one of :data:`~robotconf.motion.QUANTITIES`.
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
        """Per driven coordinate: times where its value or velocity jumps (see plot notes).

        Raises
        ------
        InvalidInputError
            Named ``signals[q<i>]`` when listing the kinks would exceed the memory budget
            (a repeating signal with a tiny period over a long run).
        """
        t0, t1 = float(self.t[0]), float(self.t[-1])
        # Counted from the periods first: a 1 ns period over a long run has billions.
        check_kink_memory(self.signals, t0, t1)
        found = {name: s.kinks(t0, t1) for name, s in self.signals.items()}
        return {name: times for name, times in found.items() if times.size}

    # -- presentation (pandas / matplotlib imported on use) -----------------------------

    @property
    def table(self) -> pd.DataFrame:
        """pandas DataFrame indexed by time (s), columns (point, quantity, axis).

        Built once and cached; copy it before editing. Refused (``InvalidInputError``
        named ``table``) when it would exceed the memory budget.
        """
        if self._table is None:
            from ._table import motion_table

            self._table = motion_table(self)
        return self._table

    def stats(self) -> pd.DataFrame:
        """Simulink Scope "Signal Statistics" of every column (see ``_motion_table``)."""
        from ._table import motion_stats

        return motion_stats(self)

    def compare(self, other: Motion) -> pd.DataFrame:
        """Column-wise difference ``self.table − other.table`` (same time grid and robot)."""
        from ._table import compare_motions

        return compare_motions(self, other)

    def to_csv(self, path: Any = None, **kwargs: Any) -> str | None:
        """Write :attr:`table` as CSV, or return the text for ``path=None`` (see
        :func:`~robotconf.motion.motion_to_csv`)."""
        from ._table import motion_to_csv

        return motion_to_csv(self, path, **kwargs)

    def to_excel(self, path: Any, **kwargs: Any) -> None:
        """Write :attr:`table` to an .xlsx file (needs openpyxl)."""
        from ._table import motion_to_excel

        motion_to_excel(self, path, **kwargs)

    def plot(self, point: str = "EE", **kwargs: Any) -> Figure:
        """3 × 3 matplotlib figure of one point (see ``_motion_plot.plot_motion``)."""
        from ..plots import plot_motion

        return plot_motion(self, point, **kwargs)
