"""How many bytes a simulation, its table, a CSV or Excel export and its kinks will need.

Each estimate is checked with :func:`robotconf._budget.check_memory` *before* the work
allocates anything, so a run too big for the machine ends in an
:class:`~robotconf.InvalidInputError` naming the setting to change, not in a
``MemoryError`` (or the system killing the process) half-way through.

The per-sample figures below are the peaks ``tracemalloc`` measured (numpy reports its
buffers to it) for 1 to 40 modules and 10 to 10⁵ samples, every method (``backward``
peaks where ``numeric`` does), explained term by term; the estimate adds :data:`MARGIN`
and :data:`FIXED_BYTES` on top, so it is never below the measured peak
(``tests/test_motion_limits.py`` and ``tests/test_motion_backward.py`` check this).
"""

from __future__ import annotations

import io
import math
from collections.abc import Iterable, Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from .._budget import ALWAYS_ALLOWED, check_memory, memory_budget
from ..signals import Signal
from ._time_grid import DEFAULT_TIME_STEP

if TYPE_CHECKING:
    from ._settings import SimulationSettings

__all__ = [
    "MARGIN",
    "FIXED_BYTES",
    "signal_terms",
    "simulation_bytes_per_sample",
    "simulation_bytes",
    "check_simulation_memory",
    "table_bytes",
    "csv_bytes",
    "excel_bytes",
    "kink_count",
    "check_kink_memory",
]

#: Estimates are the modelled peak times this factor (measured peaks stay within 2 %).
MARGIN = 1.1
#: Plus this many bytes: the kinematics' block scratch and small arrays (measured ≤ 0.6 MB).
FIXED_BYTES = 4 * 1024**2

# Bytes per sample, from the allocations of simulate (8-byte floats):
_GRID = 8  # the time grid
_COORDINATE = 24  # q, q̇, q̈ of each coordinate
_POINT = 120  # the results of each point: 5 quantities × 3 axes
_POSES = 96  # each frame's [R | p] in component-major layout (12 floats)
_POSES_BUILT = 129  # the (T, n, 4, 4) poses that layout is copied from + a finite mask
_SCREWS = 48  # analytic: each joint's axis and axis point
_RECURSION = 264  # analytic: v, a, ω, ω̇ and the cross products' temporaries
_RATES = 152  # numeric and backward, per frame: Ṙ, ω̂ and the differences' temporaries
_SIGNAL = 16  # per signal term: its result and Sum's stacked copy
_SIGNAL_BASE = 64  # per signal: phase, segment index and friends

# Bytes per cell of a table and of its exports:
_TABLE_CELL = 8  # the DataFrame's float64 block (and its index)
_CSV_CHUNK_CELLS = 100_000  # pandas formats this many cells at a time
_CSV_FORMATTED_CELL = 256  # a formatted cell in pandas' chunk (measured ≈ 200)
_CSV_TEXT_CELL = 50  # CSV text kept in memory: ≤ 25 characters, held twice
_EXCEL_CELL = 400  # an openpyxl cell (measured ≈ 340)
_TABLE_FIXED = 1024**2  # column labels and pandas bookkeeping

#: Bytes per kink time while a signal lists them (the times, masks, the sort of unique).
_KINK = 64


def _parts(signal: Signal) -> list[Signal]:
    """The signals inside a sum or an affine signal (none for a plain one)."""
    terms = getattr(signal, "terms", None)
    if isinstance(terms, tuple):
        return [s for s in terms if isinstance(s, Signal)]
    base = getattr(signal, "base", None)
    return [base] if isinstance(base, Signal) else []


def _leaves(signal: Signal) -> list[Signal]:
    # Iterative, so a deeply nested signal cannot exhaust the recursion limit here.
    leaves, stack = [], [signal]
    while stack:
        current = stack.pop()
        parts = _parts(current)
        if parts:
            stack.extend(parts)
        else:
            leaves.append(current)
    return leaves


def signal_terms(signal: Signal) -> int:
    """How many plain signals a sum or scaled signal adds up (1 for a plain signal).

    >>> from robotconf.signals import Ramp, Sine
    >>> signal_terms(Sine()), signal_terms((Sine() + Ramp()) * 2 + Sine())
    (1, 3)
    """
    return len(_leaves(signal))


def simulation_bytes_per_sample(n: int, method: str, signals: Iterable[Signal] = ()) -> float:
    """Modelled peak bytes per time sample of :func:`~robotconf.motion.simulate`.

    Parameters
    ----------
    n : int
        Modules (coordinates); the results cover ``n + 1`` points.
    method : {"analytic", "numeric", "backward"}
        The two difference methods share one model (same arrays, same temporaries).
    signals : iterable of Signal
        The driving signals; a sum of many terms needs a temporary per term.

    Returns
    -------
    float
        The largest of the four phases: evaluating a signal, building the poses, and the
        DVA of the chosen method (all with the grid and ``q, q̇, q̈`` alive).

    Examples
    --------
    >>> simulation_bytes_per_sample(3, "analytic")  # the paper's robot
    1256.0
    """
    alive = _GRID + _COORDINATE * n
    terms = max((signal_terms(s) for s in signals), default=0)
    evaluating = alive + _SIGNAL_BASE + _SIGNAL * terms
    posing = alive + (_POSES_BUILT + _POSES) * n
    results = alive + _POINT * (n + 1) + _POSES * n
    if method == "analytic":
        differentiating = results + _SCREWS * n + _RECURSION
    else:
        differentiating = results + _RATES * n
    return float(max(evaluating, posing, differentiating))


def simulation_bytes(n: int, samples: int, method: str, signals: Iterable[Signal] = ()) -> float:
    """Estimated peak bytes of one :func:`~robotconf.motion.simulate` call (≥ measured).

    >>> simulation_bytes(3, 10_001, "analytic") / 1024**2  # the paper's run, MiB
    17.2...
    """
    per_sample = simulation_bytes_per_sample(n, method, signals)
    return MARGIN * per_sample * float(samples) + FIXED_BYTES


def _three_digits(value: float, up: bool) -> float:
    """``value`` rounded up or down to 3 significant digits, so a suggestion still fits."""
    scale = 10.0 ** (math.floor(math.log10(value)) - 2)
    return (math.ceil(value / scale) if up else math.floor(value / scale)) * scale


def _simulation_change(settings: SimulationSettings, samples: int, n: int, per: float) -> str:
    """What would fit: the finest dt or the longest span, from the budget now."""
    per_sample = MARGIN * per
    fit = int((memory_budget() - FIXED_BYTES) // per_sample)
    larger = "a larger budget (rc.set_memory_budget or ROBOTCONF_MEMORY_BUDGET)"
    if fit < 2:
        return larger
    dt = _three_digits((settings.t_end - settings.t0) / (fit - 1), up=True)
    span = _three_digits((fit - 1) * settings.dt, up=False)
    return (
        f"dt ≥ {dt:.3g} s or t_end − t0 ≤ {span:.3g} s ({samples:,} samples × {n + 1} "
        f"points at about {per_sample:.0f} bytes per sample), or {larger}"
    )


def check_simulation_memory(
    settings: SimulationSettings, n: int, signals: Iterable[Signal] = ()
) -> None:
    """Refuse a simulation whose estimated peak exceeds the memory budget.

    Parameters
    ----------
    settings : SimulationSettings
    n : int
        Modules of the robot.
    signals : iterable of Signal

    Raises
    ------
    InvalidInputError
        Named ``dt`` when the step is finer than the default 1 ms (the likely cause),
        else ``t_end``; the message says which dt or span would fit.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.motion import SimulationSettings
    >>> check_simulation_memory(SimulationSettings(10.0), 3)
    >>> rc.set_memory_budget("100M")
    >>> check_simulation_memory(SimulationSettings(100.0, dt=1e-4), 3)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: dt: needs about 1.29 GiB of memory (budget 100 MiB) ...
    >>> rc.set_memory_budget(None)
    """
    signals = list(signals)
    samples = settings.samples
    nbytes = simulation_bytes(n, samples, settings.method, signals)
    if nbytes <= ALWAYS_ALLOWED:
        return  # everyday runs never read the system's memory figures
    per = simulation_bytes_per_sample(n, settings.method, signals)
    field, value = (
        ("dt", settings.dt) if settings.dt < DEFAULT_TIME_STEP else ("t_end", settings.t_end)
    )
    check_memory(field, value, nbytes, _simulation_change(settings, samples, n, per))


def table_bytes(samples: int, columns: int) -> float:
    """Estimated bytes of a motion's DataFrame: ``samples`` rows, ``columns`` + the index.

    >>> table_bytes(10_001, 60) / 1024**2
    6.11...
    """
    return MARGIN * _TABLE_CELL * float(samples) * (columns + 1) + _TABLE_FIXED


def _in_memory(path: Any) -> bool:
    """Whether pandas would build the whole CSV text in memory for this target."""
    return path is None or isinstance(path, (io.StringIO, io.BytesIO))


def csv_bytes(samples: int, columns: int, path: Any = None, chunksize: Any = None) -> float:
    """Estimated peak bytes of writing the CSV text (the table itself not included).

    Parameters
    ----------
    samples, columns : int
        Rows and data columns of the table.
    path : str, path-like, file or None
        Files and paths are written chunk by chunk; ``None`` or an ``io.StringIO``
        holds the whole text (twice, while pandas returns it).
    chunksize : int, optional
        Rows per chunk, as for :meth:`pandas.DataFrame.to_csv`.

    Examples
    --------
    >>> csv_bytes(10_001, 60, "out.csv") / 1024**2  # one chunk of ~100 000 cells
    27.8...
    """
    width = columns + 1
    rows = chunksize if isinstance(chunksize, (int, np.integer)) and chunksize > 0 else 0
    rows = min(int(rows) or max(_CSV_CHUNK_CELLS // width, 1), samples)
    nbytes = MARGIN * _CSV_FORMATTED_CELL * float(rows) * width
    if _in_memory(path):
        nbytes += MARGIN * _CSV_TEXT_CELL * float(samples) * width
    return nbytes + _TABLE_FIXED


def excel_bytes(samples: int, columns: int) -> float:
    """Estimated peak bytes of an .xlsx export by openpyxl (the table not included).

    >>> excel_bytes(10_001, 60) / 1024**3
    0.26...
    """
    return MARGIN * _EXCEL_CELL * float(samples) * (columns + 1) + _TABLE_FIXED


def kink_count(signal: Signal, t_start: float, t_stop: float) -> float:
    """How many kinks a signal lists in ``[t_start, t_stop]`` (s), without listing them.

    The signal counts them per period in exact arithmetic
    (:meth:`~robotconf.signals.Signal.kink_count`), so a tiny period cannot make this call
    expensive.

    >>> from robotconf.signals import RepeatingSequence
    >>> kink_count(RepeatingSequence(), 0.0, 10.0)  # the sawtooth's jumps at 0, 2, …, 10
    6.0
    """
    return float(signal.kink_count(t_start, t_stop))


def check_kink_memory(signals: Mapping[str, Signal], t_start: float, t_stop: float) -> None:
    """Refuse listing the signals' kinks when they would not fit the memory budget.

    Parameters
    ----------
    signals : dict
        Coordinate name → signal.
    t_start, t_stop : float
        The time span (s).

    Raises
    ------
    InvalidInputError
        Named ``signals[<coordinate>]`` after the signal with the most kinks, saying how
        many there would be.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.signals import RepeatingSequence
    >>> check_kink_memory({"q3": RepeatingSequence()}, 0.0, 10.0)
    >>> rc.set_memory_budget("1G")
    >>> fast = RepeatingSequence(times=[0, 1e-9], values=[0, 1])
    >>> check_kink_memory({"q3": fast}, 0.0, 10.0)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: signals[q3]: needs about 596 GiB of memory (budget 1 GiB) ...
    >>> rc.set_memory_budget(None)
    """
    counts = {name: kink_count(signal, t_start, t_stop) for name, signal in signals.items()}
    if not counts:
        return
    name = max(counts, key=counts.__getitem__)
    check_memory(
        f"signals[{name}]",
        signals[name],
        _KINK * sum(counts.values()),
        f"fewer kinks (about {counts[name]:.3g} in t = {t_start:g} … {t_stop:g} s here): "
        "a longer period or a shorter run",
    )
