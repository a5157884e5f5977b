"""Memory budgets and finite-result checks, applied before and after the heavy work.

Every computation whose size follows from user input (a time grid, a workspace sample,
a CSV export, a report) estimates the bytes it will allocate and asks
:func:`check_memory` first. Going over the budget raises
:class:`~robotconf.InvalidInputError` naming the field and the size, never a
``MemoryError`` half-way through.

The budget defaults to half of the memory available at the moment of the check: the
system's free memory, or less when a container (cgroup v2 ``memory.max``) or an
address-space limit (``ulimit -v``) leaves less. Set ``ROBOTCONF_MEMORY_BUDGET`` (bytes,
or a number with a ``K``/``M``/``G`` suffix, powers of 1024) or call
:func:`set_memory_budget` to fix it.
Estimates below :data:`ALWAYS_ALLOWED` bytes are never refused, so small everyday calls do
not even read the system's memory figures.
"""

from __future__ import annotations

import os
import re
from typing import Any

import numpy as np

from ._errors import InvalidInputError

__all__ = [
    "ALWAYS_ALLOWED",
    "DEFAULT_FRACTION",
    "FALLBACK_AVAILABLE",
    "memory_budget",
    "set_memory_budget",
    "check_memory",
    "format_bytes",
    "check_finite_result",
]

#: Estimates up to this many bytes (64 MiB) pass without consulting the budget.
ALWAYS_ALLOWED = 64 * 1024**2

#: The default budget is this fraction of the memory available when the check runs.
DEFAULT_FRACTION = 0.5

#: Assumed available memory (bytes) where the system does not report it (2 GiB).
FALLBACK_AVAILABLE = 2 * 1024**3

_ENVIRONMENT = "ROBOTCONF_MEMORY_BUDGET"
_UNITS = {"": 1, "K": 1024, "M": 1024**2, "G": 1024**3, "T": 1024**4}
_SIZE_TEXT = re.compile(r"\s*(\d+(?:\.\d+)?)\s*([KMGT]?)(?:I?B)?\s*", re.IGNORECASE)

_fixed_budget: int | None = None


def _system_available() -> int | None:
    try:
        with open("/proc/meminfo", encoding="ascii") as meminfo:
            for line in meminfo:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:
        return int(os.sysconf("SC_AVPHYS_PAGES")) * int(os.sysconf("SC_PAGE_SIZE"))
    except (AttributeError, ValueError, OSError):
        return None


def _read_int(path: str) -> int | None:
    try:
        with open(path, encoding="ascii") as file:
            text = file.read().strip()
    except OSError:
        return None
    return int(text) if text.isdigit() else None


def _container_available() -> int | None:
    """What a cgroup v2 memory limit (a container, a JupyterHub spawner) still allows."""
    limit = _read_int("/sys/fs/cgroup/memory.max")  # "max" (no limit) reads as None
    if limit is None:
        return None
    used = _read_int("/sys/fs/cgroup/memory.current") or 0
    return max(limit - used, 0)


def _address_space_available() -> int | None:
    """What ``ulimit -v`` (``RLIMIT_AS``) leaves beyond what this process already maps."""
    try:
        import resource

        soft, _ = resource.getrlimit(resource.RLIMIT_AS)
        if soft == resource.RLIM_INFINITY:
            return None
        with open("/proc/self/statm", encoding="ascii") as statm:
            mapped = int(statm.read().split()[0]) * resource.getpagesize()
    except (ImportError, OSError, ValueError, IndexError):
        return None
    return max(soft - mapped, 0)


def _available_memory() -> int:
    """Bytes this process can still get: the tightest of the system's free memory, a
    container's limit and an address-space limit, or :data:`FALLBACK_AVAILABLE`."""
    # A kernel in a container sees the host's free memory; its own limit binds first.
    limits = [_system_available(), _container_available(), _address_space_available()]
    known = [limit for limit in limits if limit is not None]
    return min(known) if known else FALLBACK_AVAILABLE


def _parse_size(text: str) -> int:
    match = _SIZE_TEXT.fullmatch(text)
    if match is None or len(text) > 40:
        raise InvalidInputError(
            _ENVIRONMENT, text, "a byte count such as 2000000000, 512M or 4G", "not a size:"
        )
    return int(float(match.group(1)) * _UNITS[match.group(2).upper()])


def memory_budget() -> int:
    """The number of bytes one computation may allocate.

    Returns
    -------
    int
        The budget set by :func:`set_memory_budget`, else ``ROBOTCONF_MEMORY_BUDGET``,
        else :data:`DEFAULT_FRACTION` of the memory available now.

    Examples
    --------
    >>> memory_budget() > 0
    True
    """
    if _fixed_budget is not None:
        return _fixed_budget
    text = os.environ.get(_ENVIRONMENT, "").strip()
    if text:
        return _parse_size(text)
    return int(_available_memory() * DEFAULT_FRACTION)


def set_memory_budget(nbytes: int | str | None) -> None:
    """Fix the memory budget (bytes, or text such as ``"512M"``), or restore the default.

    Parameters
    ----------
    nbytes : int, str or None
        The budget in bytes; ``None`` goes back to the environment variable or the
        default fraction of available memory.

    Examples
    --------
    >>> set_memory_budget("1G"); memory_budget()
    1073741824
    >>> set_memory_budget(None)
    """
    global _fixed_budget
    if nbytes is None:
        _fixed_budget = None
        return
    if isinstance(nbytes, str):
        _fixed_budget = _parse_size(nbytes)
        return
    if isinstance(nbytes, (bool, np.bool_)) or not isinstance(nbytes, (int, np.integer)):
        raise InvalidInputError("memory budget", nbytes, "a positive byte count", "not an integer:")
    if nbytes <= 0:
        raise InvalidInputError(
            "memory budget", nbytes, "a positive byte count", "must be > 0, got"
        )
    _fixed_budget = int(nbytes)


def format_bytes(nbytes: float) -> str:
    """``nbytes`` in the largest binary unit that keeps it ≥ 1.

    >>> format_bytes(3.6 * 1024**3)
    '3.6 GiB'
    >>> format_bytes(512)
    '512 B'
    """
    value = float(nbytes)
    for unit in ("B", "KiB", "MiB", "GiB", "TiB"):
        if abs(value) < 1024 or unit == "TiB":
            return f"{value:.0f} {unit}" if unit == "B" else f"{value:.3g} {unit}"
        value /= 1024
    raise AssertionError("unreachable")  # pragma: no cover


def check_memory(field: str, value: Any, nbytes: float, change: str) -> None:
    """Refuse a computation that would allocate more than the memory budget.

    Parameters
    ----------
    field : str
        The input that sets the size, e.g. ``"dt"`` or ``"samples"``.
    value : object
        Its value, shown in the message.
    nbytes : float
        The estimated peak allocation in bytes (a float, so huge products do not wrap).
    change : str
        What the user can change, e.g. ``"a larger dt or a shorter time span"``.

    Raises
    ------
    InvalidInputError
        When ``nbytes`` exceeds :func:`memory_budget` (and :data:`ALWAYS_ALLOWED`).

    Examples
    --------
    >>> check_memory("dt", 0.001, 8e6, "a larger dt")
    >>> set_memory_budget(1)
    >>> check_memory("dt", 1e-9, 1e12, "a larger dt")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: dt: needs about 931 GiB of memory (budget 1 B) with 1e-09; ...
    >>> set_memory_budget(None)
    """
    estimate = float(nbytes)
    if estimate <= ALWAYS_ALLOWED:
        return
    budget = memory_budget()
    if estimate > budget:
        raise InvalidInputError(
            field,
            value,
            change,
            problem=f"needs about {format_bytes(estimate)} of memory "
            f"(budget {format_bytes(budget)}) with",
        )


def check_finite_result(values: Any, field: str, value: Any, what: str) -> None:
    """Refuse a result that overflowed to inf or NaN although its input was finite.

    Parameters
    ----------
    values : array_like
        The computed numbers.
    field : str
        The input responsible, e.g. ``"modules[1].a"`` or ``"amplitude"``.
    value : object
        That input's value, shown in the message.
    what : str
        What overflowed, e.g. ``"the frame positions"``.

    Raises
    ------
    InvalidInputError
        When any entry of ``values`` is not finite.

    Examples
    --------
    >>> check_finite_result([1.0, 2.0], "a", 1.0, "the positions")
    >>> check_finite_result([1e308 * 10], "a", 1e308, "the positions")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: a: the positions overflow to inf or NaN with 1e+308; ...
    """
    if np.all(np.isfinite(values)):
        return
    raise InvalidInputError(
        field,
        value,
        "smaller magnitudes (|values| well below 1e308)",
        problem=f"{what} overflow to inf or NaN with",
    )
