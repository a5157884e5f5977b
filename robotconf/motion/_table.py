"""pandas views of a :class:`~robotconf.motion.Motion`: table, statistics, export.

Every number here comes from the motion's core arrays; pandas only labels them, so the
module imports pandas inside its functions and ``import robotconf`` stays numpy-only.
"""

from __future__ import annotations

import importlib.util
from typing import TYPE_CHECKING, Any

import numpy as np

from .._budget import check_memory
from .._errors import InvalidInputError
from ._dva import QUANTITIES
from ._memory import csv_bytes, excel_bytes, table_bytes

if TYPE_CHECKING:
    import pandas as pd

    from ._simulation import Motion

__all__ = ["motion_table", "motion_stats", "compare_motions", "motion_to_csv", "motion_to_excel"]

#: Name of the time index.
TIME_LABEL = "time (s)"
#: Columns of :func:`motion_stats`, in Simulink Scope's order.
STATS = ("max", "t_max", "min", "t_min", "peak_to_peak", "mean", "median", "rms")
#: Relative difference below which two samples are the same extreme for ``t_max`` and
#: ``t_min`` (float rounding across periods is ~1e-15; shown numbers have 6 digits).
TIE = 1e-12
#: Excel's row limit (one header row per column level is added).
EXCEL_MAX_ROWS = 1_048_576


_FEWER_SAMPLES = "a motion with fewer samples (a larger dt or a shorter run)"


def _size(motion: Motion) -> tuple[int, int, str]:
    """Rows, data columns and both in words, for the memory checks."""
    rows, columns = motion.t.size, len(motion.points) * len(QUANTITIES) * 3
    return rows, columns, f"{rows} samples × {columns} columns"


def _unbuilt_table_bytes(motion: Motion) -> float:
    """Bytes :attr:`Motion.table` still has to allocate (0 once it is cached)."""
    rows, columns, _ = _size(motion)
    return 0.0 if motion._table is not None else table_bytes(rows, columns)


def _columns(motion: Motion) -> pd.MultiIndex:
    import pandas as pd

    return pd.MultiIndex.from_product(
        [list(motion.points), list(QUANTITIES), ["x", "y", "z"]],
        names=["point", "quantity", "axis"],
    )


def motion_table(motion: Motion) -> pd.DataFrame:
    """All series of a motion as a DataFrame.

    Parameters
    ----------
    motion : Motion

    Returns
    -------
    pandas.DataFrame, shape (T, 15 · (n + 1))
        Index: sample times, named ``"time (s)"``. Columns: MultiIndex
        ``(point, quantity, axis)`` with point in ``M1 … Mn, EE``, quantity in
        ``position, displacement, velocity, acceleration, angular_velocity`` and axis in
        ``x, y, z``. Units: length, length, length/s, length/s², rad/s.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.motion import simulate
    >>> from robotconf.signals import Ramp
    >>> robot = rc.Robot([rc.Module("Tz")], end_effector=(1, 0, 0))
    >>> table = simulate(robot, {"q1": Ramp(slope=2.0)}, t_end=1.0, dt=0.5).table
    >>> table[("EE", "velocity", "z")].tolist()
    [2.0, 2.0, 2.0]
    >>> table.shape
    (3, 30)

    Raises
    ------
    InvalidInputError
        Named ``table`` when the DataFrame would exceed the memory budget.
    """
    import pandas as pd

    rows, columns, size = _size(motion)
    check_memory(
        "table",
        size,
        table_bytes(rows, columns),
        f"{_FEWER_SAMPLES}, or the raw arrays of Motion.columns() (no copy)",
    )
    index = pd.Index(motion.t, name=TIME_LABEL)
    # The (C, T) block transposed is exactly pandas' internal layout: one copy, no shuffle.
    return pd.DataFrame(motion.columns().T, index=index, columns=_columns(motion), copy=True)


def motion_stats(motion: Motion) -> pd.DataFrame:
    """Simulink Scope "Signal Statistics" for every column of :func:`motion_table`.

    Parameters
    ----------
    motion : Motion

    Returns
    -------
    pandas.DataFrame
        One row per column ``(point, quantity, axis)``; columns ``max``, ``t_max`` (time
        of the first maximum, s: values within :data:`TIE` of the series' magnitude of
        it count as the same peak), ``min``, ``t_min``, ``peak_to_peak`` (max − min),
        ``mean``, ``median`` and ``rms`` (root mean square ``sqrt(mean(x²))``), each over
        all samples.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.motion import simulate
    >>> from robotconf.signals import RepeatingSequence
    >>> robot = rc.Robot([rc.Module("Tx")])
    >>> stats = simulate(robot, {"q1": RepeatingSequence()}, t_end=3.0, dt=0.5).stats()
    >>> stats.loc[("M1", "position", "x")].tolist()
    [1.5, 1.5, 0.0, 0.0, 1.5, 0.6428571428571429, 0.5, 0.823754471047914]
    """
    import pandas as pd

    samples, columns, size = _size(motion)
    # The median sorts a copy of every series.
    check_memory("stats", size, table_bytes(samples, columns), _FEWER_SAMPLES)
    data = motion.columns()
    t = motion.t
    maxima, minima = data.max(axis=1), data.min(axis=1)
    # A periodic signal peaks once per period in exact arithmetic; in floats a later
    # period may win by a few ulps. Values within TIE of the extreme are the same peak,
    # so the time reported is the first one.
    tie = TIE * np.maximum(np.abs(maxima), np.abs(minima))
    high = np.argmax(data >= (maxima - tie)[:, np.newaxis], axis=1)
    low = np.argmax(data <= (minima + tie)[:, np.newaxis], axis=1)
    values = {
        "max": maxima,
        "t_max": t[high],
        "min": minima,
        "t_min": t[low],
        "peak_to_peak": maxima - minima,
        "mean": data.mean(axis=1),
        "median": np.median(data, axis=1),
        "rms": np.sqrt(np.einsum("ct,ct->c", data, data) / data.shape[1]),
    }
    return pd.DataFrame(values, index=_columns(motion), columns=list(STATS))


def compare_motions(first: Motion, second: Motion) -> pd.DataFrame:
    """Column-wise difference ``first.table − second.table``, e.g. analytic − numeric.

    Parameters
    ----------
    first, second : Motion
        Simulations of the same robot on the same time grid.

    Returns
    -------
    pandas.DataFrame
        Same index and columns as :func:`motion_table`. ``.abs().max()`` gives the largest
        disagreement per column.

    Raises
    ------
    InvalidInputError
        If the robots or time grids differ.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.motion import simulate
    >>> from robotconf.signals import Sine
    >>> robot = rc.Robot([rc.Module("Rz")], end_effector=(1, 0, 0))
    >>> exact = simulate(robot, {"q1": Sine()}, t_end=1.0, dt=1e-3)
    >>> approx = simulate(robot, {"q1": Sine()}, t_end=1.0, dt=1e-3, method="numeric")
    >>> bool(compare_motions(exact, approx).abs().max().max() < 1e-3 * 4 * np.pi**2)
    True
    """
    from ._simulation import Motion

    if not isinstance(second, Motion):
        raise InvalidInputError("other", second, "a Motion from simulate()")
    if first.robot != second.robot:
        raise InvalidInputError(
            "other", second, "a motion of the same robot", problem="different robots:"
        )
    if first.t.shape != second.t.shape or not np.array_equal(first.t, second.t):
        raise InvalidInputError(
            "other",
            second,
            "a motion with the same t0, t_end and dt",
            problem="different time grids:",
        )
    rows, columns, size = _size(first)
    nbytes = _unbuilt_table_bytes(first) + _unbuilt_table_bytes(second)
    check_memory("other", size, nbytes + table_bytes(rows, columns), _FEWER_SAMPLES)
    return first.table - second.table


def _flat(table: pd.DataFrame) -> pd.DataFrame:
    flat = table.copy(deep=False)
    flat.columns = ["_".join(column) for column in table.columns]
    return flat


def motion_to_csv(
    motion: Motion, path: Any = None, *, flat: bool = False, **kwargs: Any
) -> str | None:
    """Write the table as CSV.

    Parameters
    ----------
    motion : Motion
    path : str or path-like or file or None
        Where to write; ``None`` returns the text instead (as pandas does).
    flat : bool
        ``False``: three header rows (point, quantity, axis); read back with
        ``pandas.read_csv(path, header=[0, 1, 2], index_col=0)``. ``True``: one header row
        with names such as ``EE_velocity_z`` (easier in a spreadsheet).
    **kwargs
        Passed to :meth:`pandas.DataFrame.to_csv`.

    Returns
    -------
    str or None
        The CSV text when ``path`` is ``None``.

    Raises
    ------
    InvalidInputError
        Named ``path`` when the table and the text would exceed the memory budget: a
        file is written in chunks, while ``None`` or an ``io.StringIO`` holds it all.
    """
    rows, columns, size = _size(motion)
    nbytes = _unbuilt_table_bytes(motion) + csv_bytes(rows, columns, path, kwargs.get("chunksize"))
    check_memory(
        "path",
        path,
        nbytes,
        f"a file path (written in chunks), or {_FEWER_SAMPLES}; the table is {size}",
    )
    table = _flat(motion.table) if flat else motion.table
    text: str | None = table.to_csv(path, **kwargs)
    return text


def motion_to_excel(motion: Motion, path: Any, *, flat: bool = False, **kwargs: Any) -> None:
    """Write the table to an .xlsx workbook (needs the ``openpyxl`` package).

    Parameters
    ----------
    motion : Motion
    path : str or path-like
    flat : bool
        As for :func:`motion_to_csv`.
    **kwargs
        Passed to :meth:`pandas.DataFrame.to_excel`.

    Raises
    ------
    ModuleNotFoundError
        If openpyxl is not installed; the message says how to install it.
    InvalidInputError
        If the motion has more rows than an Excel sheet holds, or the workbook would
        exceed the memory budget (openpyxl keeps every cell as an object, ~340 bytes).
    """
    if importlib.util.find_spec("openpyxl") is None:
        raise ModuleNotFoundError(
            "Motion.to_excel needs the 'openpyxl' package to write .xlsx files: "
            "run `pip install openpyxl` (or use Motion.to_csv)",
            name="openpyxl",
        )
    rows = motion.t.size + (1 if flat else 4)
    if rows > EXCEL_MAX_ROWS:
        raise InvalidInputError(
            "path",
            str(path),
            f"at most {EXCEL_MAX_ROWS} rows per Excel sheet: increase dt, shorten the run, "
            "or use to_csv",
            problem=f"{motion.t.size} samples do not fit in a sheet:",
        )
    _, columns, size = _size(motion)
    check_memory(
        "path",
        str(path),
        _unbuilt_table_bytes(motion) + excel_bytes(motion.t.size, columns),
        f"to_csv (written in chunks), or {_FEWER_SAMPLES}; the table is {size}",
    )
    table = _flat(motion.table) if flat else motion.table
    table.to_excel(path, **kwargs)
