"""Signals from plain dicts (what :meth:`Signal.to_dict` writes), strictly validated.

The dict form is the one robotconf's JSON files use. Reading never evaluates text: the
``"type"`` picks a class from a fixed table, and every parameter is type-checked before the
class validates its value.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import fields
from typing import Any

from .._errors import InvalidInputError
from .._json_fields import Rejected
from .._validation import one_line
from ._base import Affine, Signal, Sum
from ._profiles import Cubic, Quintic, Trapezoidal
from ._repeating import MAX_TABLE_POINTS, RepeatingSequence
from ._sources import Constant, Ramp, Sine, Step

__all__ = ["signal_from_dict", "SIGNAL_TYPES", "MAX_TABLE_POINTS", "MAX_SIGNAL_DEPTH"]

#: The classes a dict may name in ``"type"``.
SIGNAL_TYPES: dict[str, type[Signal]] = {
    cls.__name__: cls
    for cls in (
        Constant,
        Step,
        Ramp,
        Sine,
        RepeatingSequence,
        Cubic,
        Quintic,
        Trapezoidal,
        Affine,
        Sum,
    )
}

#: Deepest nesting of Affine/Sum read from a dict; also the most terms of one Sum.
MAX_SIGNAL_DEPTH = 16
MAX_SUM_TERMS = 64

_TABLES = ("times", "values")


def _parameters(cls: type[Signal]) -> tuple[str, ...]:
    return tuple(item.name for item in fields(cls) if item.init)  # type: ignore[arg-type]


def _number(value: Any, field: str) -> float:
    if isinstance(value, Rejected):
        raise InvalidInputError(field, value, "a finite number", problem=f"{value.reason}:")
    # A bool is an int in Python but never a number in a signal (true/false in JSON).
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        problem = f"expected a number, got {type(value).__name__}"
        raise InvalidInputError(field, one_line(value), "a finite number", problem=problem)
    try:
        return float(value)
    except OverflowError:  # an int of 309 digits or more; it may be too long to print
        raise InvalidInputError(
            field, one_line(value), "a finite number", problem="too large:"
        ) from None


def _table(value: Any, field: str) -> list[float]:
    allowed = f"a list of at most {MAX_TABLE_POINTS} numbers"
    if not isinstance(value, (list, tuple)):
        raise InvalidInputError(field, one_line(value), allowed, problem="not a list:")
    if len(value) > MAX_TABLE_POINTS:
        raise InvalidInputError(
            field, f"<{len(value)} entries>", allowed, problem="table too long:"
        )
    return [_number(v, f"{field}[{i}]") for i, v in enumerate(value)]


def signal_from_dict(data: Any, field: str = "signal", *, _depth: int = 0) -> Signal:
    """Rebuild a signal from its dict form (see :meth:`Signal.to_dict`).

    Parameters
    ----------
    data : dict
        ``{"type": name, parameter: value, …}`` with a name from :data:`SIGNAL_TYPES`.
        Parameters left out take the class's default (Simulink's, for the source blocks);
        ``Affine`` needs ``"base"`` and ``Sum`` needs ``"terms"``.
    field : str
        Where the dict came from, for error messages (e.g. ``"signals.q3"``).

    Returns
    -------
    Signal

    Raises
    ------
    InvalidInputError
        Naming the path of the bad entry: a non-dict, an unknown ``type`` or key, a
        missing part, a boolean or text where a number belongs, a table longer than
        :data:`MAX_TABLE_POINTS`, nesting deeper than :data:`MAX_SIGNAL_DEPTH`, or any
        value the signal class itself refuses.

    Examples
    --------
    >>> signal_from_dict({"type": "Sine", "amplitude": 2.0})
    Sine(amplitude=2.0)
    >>> saw = signal_from_dict({"type": "RepeatingSequence", "times": [0, 2], "values": [0, 2]})
    >>> signal_from_dict(saw.to_dict()) == saw
    True
    >>> signal_from_dict({"type": "Sine", "amplitude": True}, "signals.q3")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: signals.q3.amplitude: expected a number, got bool True; ...
    """
    if _depth > MAX_SIGNAL_DEPTH:
        raise InvalidInputError(
            field,
            "<nested signal>",
            f"signals nested at most {MAX_SIGNAL_DEPTH} deep",
            problem="nested too deeply:",
        )
    if not isinstance(data, Mapping):
        raise InvalidInputError(
            field, one_line(data), "a dict with a 'type' key", problem="not a dict:"
        )
    kind = data.get("type")
    if not isinstance(kind, str) or kind not in SIGNAL_TYPES:
        raise InvalidInputError(
            f"{field}.type", one_line(kind), ", ".join(SIGNAL_TYPES), problem="unknown signal type"
        )
    cls = SIGNAL_TYPES[kind]
    names = _parameters(cls)
    unknown = sorted(str(k) for k in data if k != "type" and k not in names)
    if unknown:
        raise InvalidInputError(
            f"{field}.{unknown[0]}",
            data[unknown[0]] if unknown[0] in data else unknown[0],
            f"the keys of {kind}: type, {', '.join(names)}",
            problem="unknown key, value",
        )
    values: dict[str, Any] = {}
    for name in names:
        if name not in data:
            continue
        path = f"{field}.{name}"
        raw = data[name]
        if name == "base":
            values[name] = signal_from_dict(raw, path, _depth=_depth + 1)
        elif name == "terms":
            values[name] = _terms(raw, path, _depth)
        elif name in _TABLES:
            values[name] = _table(raw, path)
        else:
            values[name] = _number(raw, path)
    for part in ("base", "terms"):
        if part in names and part not in values:
            raise InvalidInputError(
                f"{field}.{part}", None, f"{kind} needs '{part}'", problem="missing:"
            )
    try:
        return cls(**values)
    except InvalidInputError as error:
        raise error.within(field) from None


def _terms(raw: Any, path: str, depth: int) -> tuple[Signal, ...]:
    allowed = f"a list of 1 to {MAX_SUM_TERMS} signal dicts"
    if not isinstance(raw, (list, tuple)) or not raw:
        raise InvalidInputError(path, one_line(raw), allowed, problem="not a non-empty list:")
    if len(raw) > MAX_SUM_TERMS:
        raise InvalidInputError(path, f"<{len(raw)} terms>", allowed, problem="too many terms:")
    return tuple(signal_from_dict(t, f"{path}[{i}]", _depth=depth + 1) for i, t in enumerate(raw))
