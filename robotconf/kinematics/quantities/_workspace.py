"""The reachable workspace: sample the joint ranges, collect the end-effector points.

The paper's future work names the robot's "working space". Here it is the set of
end-effector positions ``p_EE(q)`` for ``q`` drawn from the joint ranges, either at random
(uniformly, the default) or on a regular grid. The points come from the vectorized core
(:meth:`Robot.end_effector` on a ``(T, n)`` batch), in chunks so that a progress bar can
follow long runs; tables, plots and the 3D cloud import their libraries on use.
"""

from __future__ import annotations

import time
import warnings
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np

from ..._budget import check_memory
from ..._errors import InvalidInputError
from ..._validation import as_float_array, check_flag, check_integer, check_vector3, one_line
from ..conventions._bounds import MAX_PARAMETER
from ..kernel._kernel import kernel_bytes

if TYPE_CHECKING:  # pragma: no cover
    import pandas as pd
    from matplotlib.figure import Figure

    from ..robot._robot import Robot

__all__ = [
    "workspace",
    "Workspace",
    "WORKSPACE_METHODS",
    "MAX_WORKSPACE_SAMPLES",
    "PROGRESS_AFTER",
    "workspace_bytes",
]

#: Sampling methods: ``random`` (uniform in the ranges) or ``grid`` (evenly spaced).
WORKSPACE_METHODS = ("random", "grid")

#: Ceiling on samples: each holds n + 3 floats (120 bytes for 12 modules), so 5·10⁷
#: samples already need about 6 GB; ask for fewer or raise ``max_samples`` knowingly.
#: Below it, the memory budget (:func:`robotconf.set_memory_budget`) has the last word.
MAX_WORKSPACE_SAMPLES = 50_000_000

#: A progress bar appears (with ``progress=None``) when the run is expected to last
#: longer than this many seconds, estimated from the first chunk.
PROGRESS_AFTER = 1.0

#: Samples per chunk: big enough that numpy's per-call overhead vanishes, small enough
#: that a progress bar moves about 16 times for 10⁶ samples.
CHUNK_SIZE = 65_536


def _check_count(value: Any, field: str, limit: int) -> int:
    return check_integer(value, field, 1, limit, what=f"an integer from 1 to {limit:,}")


def _check_ranges_array(values: Any, robot: Robot) -> np.ndarray:
    allowed = (
        f"shape ({robot.n}, 2): one finite (lo, hi) with lo ≤ hi and |lo|, |hi| ≤ "
        f"{MAX_PARAMETER:.0e} per coordinate"
    )
    array = as_float_array(values, "ranges", allowed)
    if array.shape != (robot.n, 2):
        raise InvalidInputError(
            "ranges",
            one_line(values),
            allowed,
            problem=f"expected shape ({robot.n}, 2), got {array.shape}:",
        )
    names = robot.coordinate_names
    for i, (lo, hi) in enumerate(array):
        if not (np.isfinite(lo) and np.isfinite(hi)):
            raise InvalidInputError(
                "ranges", (float(lo), float(hi)), allowed, problem=f"{names[i]} must be finite, got"
            )
        # hi - lo of two floats near ±1e308 would overflow, and so would the samples.
        if max(abs(lo), abs(hi)) > MAX_PARAMETER:
            raise InvalidInputError(
                "ranges", (float(lo), float(hi)), allowed, problem=f"{names[i]} is too large:"
            )
        if lo > hi:
            raise InvalidInputError(
                "ranges", (float(lo), float(hi)), allowed, problem=f"{names[i]} has lo > hi:"
            )
    return array.copy()


def _resolve_ranges(robot: Robot, ranges: Any) -> np.ndarray:
    """(n, 2) ranges: the robot's joint limits, overridden by ``ranges``."""
    if ranges is not None and not isinstance(ranges, Mapping):
        return _check_ranges_array(ranges, robot)
    base = np.array(robot.joint_limits(), dtype=float)  # type: ignore[attr-defined]
    if not ranges:
        return _check_ranges_array(base, robot)
    for key, pair in ranges.items():
        index = robot.index(key, "ranges")
        allowed = "a pair of finite numbers (lo, hi) with lo ≤ hi"
        row = as_float_array(pair, f"ranges[{key!r}]", allowed)
        if row.shape != (2,):
            raise InvalidInputError(
                f"ranges[{key!r}]",
                one_line(pair),
                allowed,
                problem=f"expected 2 numbers, got {row.shape}:",
            )
        base[index] = row
    return _check_ranges_array(base, robot)


def _check_method(method: Any) -> str:
    allowed = "'random' (uniform samples) or 'grid' (evenly spaced values)"
    if not isinstance(method, str) or method.strip().lower() not in WORKSPACE_METHODS:
        raise InvalidInputError("method", one_line(method), allowed, problem="unknown method")
    return method.strip().lower()


def _check_seed(seed: Any) -> int | None:
    if seed is None:
        return None
    return check_integer(seed, "seed", 0, what="None or an integer ≥ 0")


def _check_progress(progress: Any) -> bool | None:
    return None if progress is None else check_flag(progress, "progress")


def grid_size(samples: int, free: int) -> int:
    """Values per free coordinate of a grid with at most ``samples`` points.

    Parameters
    ----------
    samples : int
        Upper bound on the number of grid points.
    free : int
        Coordinates whose range is not a single value.

    Returns
    -------
    int
        The largest ``m`` with ``m ** free ≤ samples`` (1 when ``free == 0``).

    Examples
    --------
    >>> grid_size(1_000_000, 6), grid_size(999_999, 6), grid_size(10, 0)
    (10, 9, 1)
    """
    if free == 0:
        return 1
    m = max(1, int(round(samples ** (1.0 / free))))
    # Floating-point roots are off by one near exact powers (1e6 ** (1/6) = 9.999…).
    while m > 1 and m**free > samples:
        m -= 1
    while (m + 1) ** free <= samples:
        m += 1
    return m


def workspace_bytes(samples: int, n: int) -> float:
    """Peak bytes :func:`workspace` allocates for ``samples`` points of an ``n``-link robot.

    The joint values and points it keeps (``n + 3`` floats per sample) and one chunk of
    sampling and kinematics scratch; calibrated with ``tracemalloc`` (the estimate is
    never below the measured peak, for 10³ to 10⁶ samples of 3 and 6 links, random and
    grid; within 8 % of it for 10⁶ samples).

    >>> workspace_bytes(1_000_000, 6) / 1e6  # about 72 MB of points and joint values
    79.42...
    """
    chunk = min(samples, CHUNK_SIZE)
    return 8.0 * samples * (n + 3) + kernel_bytes(chunk, n, 0) + 8.0 * chunk * (n + 4)


class _Sampler:
    """Produces the joint values of chunk ``[start, stop)`` for either method."""

    def __init__(self, ranges: np.ndarray, samples: int, method: str, seed: int | None):
        self.lo, self.width = ranges[:, 0], ranges[:, 1] - ranges[:, 0]
        self.method = method
        self.rng = np.random.default_rng(seed)
        self.free = np.flatnonzero(self.width > 0.0)
        self.m = grid_size(samples, self.free.size) if method == "grid" else 0
        self.total = self.m**self.free.size if method == "grid" else samples
        if method == "grid" and self.free.size and self.m < 2:
            raise InvalidInputError(
                "samples",
                samples,
                f"at least 2^{self.free.size} = {2**self.free.size} for a grid over "
                f"{self.free.size} moving coordinates",
                problem="too few for a grid:",
            )

    def fill(self, out: np.ndarray, start: int) -> None:
        if self.method == "random":
            # One stream consumed chunk after chunk: the same seed gives the same samples
            # whatever the chunk size.
            self.rng.random(out=out)
            out *= self.width
            out += self.lo
            return
        out[:] = self.lo
        if self.free.size:
            index = np.arange(start, start + out.shape[0])
            digits = np.unravel_index(index, (self.m,) * self.free.size)
            for column, digit in zip(self.free, digits, strict=True):
                out[:, column] += self.width[column] * (digit / (self.m - 1))


def _progress_bar(total: int, done: int) -> Any:
    from tqdm.auto import tqdm  # tqdm.auto: a widget in Jupyter, text in a terminal

    return tqdm(total=total, initial=done, unit="samples", desc="workspace")


def workspace(
    robot: Robot,
    samples: int = 100_000,
    ranges: Any = None,
    *,
    method: str = "random",
    seed: int | None = None,
    progress: bool | None = None,
    max_samples: int = MAX_WORKSPACE_SAMPLES,
) -> Workspace:
    """Sample the joint ranges and collect the reachable end-effector points.

    Parameters
    ----------
    robot : Robot
    samples : int
        Number of configurations (``random``), or the upper bound on grid points
        (``grid``: ``m`` values per moving coordinate with ``m^k ≤ samples``).
    ranges : array-like, shape (n, 2), or dict, optional
        ``(lo, hi)`` per coordinate (radians for rotations, length for translations).
        Default: ``robot.joint_limits()``. A dict maps coordinates, named as
        :meth:`Robot.index` reads them (``"q2"``, ``"M2"``, a module's own name or a 0-based
        index), to pairs and overrides only those coordinates. A pair with
        ``lo == hi`` holds that coordinate fixed.
    method : {"random", "grid"}
        ``random``: independent uniform samples. ``grid``: every combination of ``m``
        evenly spaced values, ends included (a full turn ``(−π, π)`` therefore repeats
        its end pose).
    seed : int, optional
        Seed of ``numpy.random.default_rng``; the same seed gives the same points.
    progress : bool, optional
        ``None``: show a ``tqdm.auto`` bar when the first chunk predicts a run longer
        than :data:`PROGRESS_AFTER` seconds; ``True``: always; ``False``: never.
    max_samples : int
        Refuse more samples than this (memory guard, see :data:`MAX_WORKSPACE_SAMPLES`).

    Returns
    -------
    Workspace

    Raises
    ------
    InvalidInputError
        For ``samples`` ≤ 0 or too many (also: more than the memory budget holds, about
        ``8 (n + 3)`` bytes per sample), a wrong range shape, ``lo > hi``, NaN, infinite
        or too large (``|x| > 1e150``) ranges, an unknown coordinate name, an unknown
        method, a bad seed, or too few samples for a grid.

    Examples
    --------
    A planar 2R arm (links 2 and 1) reaches the annulus 1 ≤ r ≤ 3:

    >>> import robotconf as rc
    >>> arm = rc.Robot.from_dh([(0, 0, 2, 0, "R"), (0, 0, 1, 0, "R")])
    >>> ws = workspace(arm, 10_000, ranges=[(-np.pi, np.pi)] * 2, seed=1)
    >>> r = np.hypot(ws.points[:, 0], ws.points[:, 1])
    >>> bool(r.min() >= 1 - 1e-12 and r.max() <= 3 + 1e-12), ws.points.shape
    (True, (10000, 3))
    """
    from ..robot._robot import Robot

    if not isinstance(robot, Robot):
        raise InvalidInputError("robot", robot, "a robotconf Robot", problem="not a robot:")
    limit = _check_count(max_samples, "max_samples", 10**12)
    count = _check_count(samples, "samples", limit)
    method = _check_method(method)
    seed = _check_seed(seed)
    show = _check_progress(progress)
    bounds = _resolve_ranges(robot, ranges)
    sampler = _Sampler(bounds, count, method, seed)
    total = sampler.total
    check_memory(
        "samples",
        count,
        workspace_bytes(total, robot.n),
        "fewer samples, or a larger memory budget (robotconf.set_memory_budget)",
    )
    q = np.empty((total, robot.n))
    points = np.empty((total, 3))
    started = time.perf_counter()
    bar = _progress_bar(total, 0) if show else None
    for start in range(0, total, CHUNK_SIZE):
        stop = min(start + CHUNK_SIZE, total)
        sampler.fill(q[start:stop], start)
        robot.end_effector(q[start:stop], out=points[start:stop])
        if bar is not None:
            bar.update(stop - start)
        elif show is None and start == 0 and stop < total:
            expected = (time.perf_counter() - started) * total / stop
            if expected > PROGRESS_AFTER:
                bar = _progress_bar(total, stop)
    if bar is not None:
        bar.close()
    seconds = time.perf_counter() - started
    return Workspace(robot, points, q, bounds, method, seed, seconds)


@dataclass(frozen=True, eq=False)
class Workspace:
    """End-effector points reached from sampled joint values (made by :func:`workspace`).

    All arrays are read-only.

    Attributes
    ----------
    robot : Robot
    points : ndarray, shape (N, 3)
        End-effector positions in the base frame (length units).
    q : ndarray, shape (N, n)
        The joint values of each point (radians / length), row by row.
    ranges : ndarray, shape (n, 2)
        The ``(lo, hi)`` sampled per coordinate.
    method : str
        ``"random"`` or ``"grid"``.
    seed : int or None
    seconds : float
        Wall time of the sampling (s).
    """

    robot: Robot
    points: np.ndarray
    q: np.ndarray
    ranges: np.ndarray
    method: str
    seed: int | None
    seconds: float

    def __post_init__(self) -> None:
        for array in (self.points, self.q, self.ranges):
            array.flags.writeable = False

    def __len__(self) -> int:
        return int(self.points.shape[0])

    def __repr__(self) -> str:
        lo, hi = self.bounds
        box = ", ".join(f"{a} {lo[i]:.4g}…{hi[i]:.4g}" for i, a in enumerate("xyz"))
        return (
            f"Workspace({len(self)} points of {self.robot.name or 'Robot'}, "
            f"method={self.method!r}, {box})"
        )

    @property
    def bounds(self) -> np.ndarray:
        """Axis-aligned box of the points: ``[[xmin, ymin, zmin], [xmax, ymax, zmax]]``.

        Returns
        -------
        ndarray, shape (2, 3)
            Length units.

        Examples
        --------
        >>> import robotconf as rc
        >>> slide = rc.Robot([rc.Module("Tx")])
        >>> workspace(slide, 3, ranges=[(0, 2)], method="grid").bounds
        array([[0., 0., 0.],
               [2., 0., 0.]])
        """
        return np.array([self.points.min(axis=0), self.points.max(axis=0)])

    def distances(self, center: Any = (0.0, 0.0, 0.0)) -> np.ndarray:
        """Distance of every point from ``center`` (length), shape (N,).

        Useful to check a shell: the paper robot's points lie 10 to 70 from (0, 0, 20).
        """
        return np.linalg.norm(self.points - np.array(check_vector3(center, "center")), axis=1)

    @cached_property
    def table(self) -> pd.DataFrame:
        """The samples as a pandas DataFrame: columns ``q1 … qn``, ``x``, ``y``, ``z``.

        One row per point (radians / length, then length units). Built once and cached,
        as :attr:`Motion.table <robotconf.motion.Motion.table>`; copy it before editing.

        Examples
        --------
        >>> import robotconf as rc
        >>> slide = rc.Robot([rc.Module("Tx")])
        >>> workspace(slide, 2, ranges=[(0, 1)], method="grid").table
            q1    x    y    z
        0  0.0  0.0  0.0  0.0
        1  1.0  1.0  0.0  0.0
        """
        import pandas as pd

        data = np.hstack([self.q, self.points])
        columns = [*self.robot.coordinate_names, "x", "y", "z"]
        return pd.DataFrame(data, columns=columns)

    def frame(self) -> pd.DataFrame:
        """Deprecated: the same DataFrame as the property :attr:`table`.

        Returns
        -------
        pandas.DataFrame, shape (N, n + 3)

        Examples
        --------
        >>> import warnings, robotconf as rc
        >>> ws = workspace(rc.Robot([rc.Module("Tx")]), 2, ranges=[(0, 1)], method="grid")
        >>> with warnings.catch_warnings(record=True) as caught:
        ...     warnings.simplefilter("always")
        ...     same = ws.frame() is ws.table
        >>> same, caught[0].category.__name__
        (True, 'DeprecationWarning')
        """
        warnings.warn(
            "Workspace.frame() is now the property Workspace.table",
            DeprecationWarning,
            stacklevel=2,
        )
        return self.table

    def plot(self, **kwargs: Any) -> Figure:
        """3D scatter plus the XY, XZ and YZ projections (see ``_workspace_plot``)."""
        from ...plots import plot_workspace

        return plot_workspace(self, **kwargs)

    def view(
        self,
        scene: Any = None,
        *,
        name: str = "workspace",
        color: Any = (0.2, 0.4, 0.9),
        size: float | None = None,
        max_points: int = 200_000,
    ) -> Any:
        """Show the points as a point cloud in the 3D scene.

        Parameters
        ----------
        scene : Scene, optional
            A scene from :func:`robotconf.view`; default: a new one of this robot.
        name : str
            Name of the cloud in the scene (replaces a cloud of the same name).
        color : (r, g, b) floats in 0…1, or array of shape (N, 3)
        size : float, optional
            Point size (length units); the scene picks one when omitted.
        max_points : int
            Show at most this many points (every k-th), so the browser stays fluid.

        Returns
        -------
        Scene
        """
        limit = _check_count(max_points, "max_points", MAX_WORKSPACE_SAMPLES)
        step = max(1, -(-len(self) // limit))
        allowed = "(r, g, b) floats in 0…1, or an array of shape (N, 3)"
        colors = as_float_array(color, "color", allowed, what="a color")
        if colors.shape != (3,) and colors.shape != (len(self), 3):
            raise InvalidInputError(
                "color", color, allowed, problem=f"expected shape (3,) or ({len(self)}, 3):"
            )
        if colors.ndim == 2:
            colors = colors[::step]
        if scene is None:
            from ...scene import view

            scene = view(self.robot)
        scene.add_point_cloud(name, self.points[::step], color=colors, size=size)
        return scene
