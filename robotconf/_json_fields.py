"""The fields of a parsed JSON file: objects with known keys, finite numbers.

The file reader (:mod:`robotconf.io`) parses JSON so that keys given twice and numbers
robotconf refuses (NaN, ±Infinity, overflow, huge integers) stay visible until a reader
reaches them and can name their path: such a number becomes a :class:`Rejected`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from ._errors import InvalidInputError
from ._validation import one_line

__all__ = ["Rejected", "check_json_number", "check_json_object"]


class Rejected:
    """Stands in for a JSON number robotconf refuses (NaN, ±Infinity, overflow, huge ints)
    until a reader reaches it and can name its path (the file reader parses JSON so)."""

    __slots__ = ("text", "reason")

    def __init__(self, text: str, reason: str):
        self.text = text
        self.reason = reason

    def __repr__(self) -> str:
        return self.text


def check_json_object(value: Any, path: str, keys: Mapping[str, bool]) -> Mapping[str, Any]:
    """A parsed JSON object with only the known ``keys`` (True: required), each once.

    The file reader marks keys given twice in ``value.duplicates`` (json itself keeps only
    the last); such an object is refused. Every error names ``path.key``.

    >>> check_json_object({"t_end": 1.0}, "simulation", {"t_end": True, "dt": False})
    {'t_end': 1.0}
    """
    allowed = ", ".join(f"{k}" if required else f"{k} (optional)" for k, required in keys.items())
    if not isinstance(value, Mapping):
        raise InvalidInputError(
            path,
            one_line(value),
            f"an object with keys {allowed}",
            problem="expected an object, got",
        )
    duplicates = getattr(value, "duplicates", ())
    if duplicates:
        raise InvalidInputError(
            f"{path}.{duplicates[0]}", duplicates[0], "each key once", problem="duplicate key"
        )
    for key in value:
        if key not in keys:
            raise InvalidInputError(
                f"{path}.{key}",
                one_line(value[key]),
                f"the keys {allowed}",
                problem="unknown key, value",
            )
    for key, required in keys.items():
        if required and key not in value:
            raise InvalidInputError(f"{path}.{key}", None, f"the keys {allowed}", problem="missing")
    return value


def check_json_number(value: Any, path: str) -> float:
    """A finite JSON number as float; ``true``/``false``, text, NaN and infinities refused.

    >>> check_json_number(20, "robot.links[1].a[2]")
    20.0
    >>> check_json_number(True, "robot.links[0].q")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: robot.links[0].q: expected a number, got a boolean: True; ...
    """
    allowed = "a finite number"
    if isinstance(value, Rejected):
        raise InvalidInputError(path, value, allowed, problem=f"{value.reason}:")
    if isinstance(value, bool):
        raise InvalidInputError(path, value, allowed, problem="expected a number, got a boolean:")
    if not isinstance(value, (int, float)):
        raise InvalidInputError(path, one_line(value), allowed, problem="expected a number, got")
    try:
        result = float(value)
    except OverflowError:
        raise InvalidInputError(path, one_line(value), allowed, problem="too large:") from None
    if not np.isfinite(result):
        raise InvalidInputError(path, result, allowed, problem="must be finite, got")
    return result
