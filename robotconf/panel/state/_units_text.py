"""The core's sentences in the panel's units.

The core writes angles in radians (``q2 leaves its range [-3.14159, 3.14159] rad``,
``2e-12 rad in orientation``) and a prismatic joint's numbers in ``length``. In degree
mode every such angle is shown in degrees, and the word ``length`` becomes the panel's
length unit, so a message never speaks another unit than the controls beside it. Lengths
are named, never converted (see :mod:`._units`).
"""

from __future__ import annotations

import math
import re

from ._units import Units

__all__ = ["in_units"]

_NUMBER = r"[-+−]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?"
#: A number or a bracketed pair of numbers followed by an angle unit (rad, rad/s, rad/s²).
_ANGLE = re.compile(
    rf"(?:\[(?P<a>{_NUMBER}), (?P<b>{_NUMBER})\]|(?P<one>{_NUMBER})) rad(?P<rate>/s²|/s)?(?![\w²])"
)
#: ``length`` as a unit: after a number (``0.25 length/s``), or a rate (``(length/s)``).
_LENGTH_WORD = re.compile(
    r"(?:(?<=\d )|(?<=\())length(?P<rate>/s²|/s)?(?![\w²])|\blength(?P<per>/s²|/s)(?![\w²])"
)


def _degrees(text: str) -> str:
    value = math.degrees(float(text.replace("−", "-")))
    return f"{value:.4g}"


def _angle(match: re.Match[str]) -> str:
    rate = match.group("rate") or ""
    if match.group("one") is None:
        shown = f"[{_degrees(match.group('a'))}, {_degrees(match.group('b'))}]"
    else:
        shown = _degrees(match.group("one"))
    return f"{shown} deg{rate}"


def _length(name: str):  # type: ignore[no-untyped-def]
    def named(match: re.Match[str]) -> str:
        return name + (match.group("rate") or match.group("per") or "")

    return named


def in_units(text: str, units: Units) -> str:
    """``text`` with its radians in degrees (in degree mode) and ``length`` named.

    Examples
    --------
    >>> in_units("q2 leaves its range [-3.14159, 3.14159] rad (by up to 0.3491 rad)",
    ...          Units("mm", degrees=True))
    'q2 leaves its range [-180, 180] deg (by up to 20 deg)'
    >>> in_units("limit 1 rad/s; d moves 0.25 length/s", Units("mm", degrees=True))
    'limit 57.3 deg/s; d moves 0.25 mm/s'
    >>> in_units("allowed: a path speed (length/s); its length is 3", Units("mm"))
    'allowed: a path speed (mm/s); its length is 3'
    >>> in_units("limit 1 rad/s", Units("mm", degrees=False))
    'limit 1 rad/s'
    """
    if units.degrees:
        text = _ANGLE.sub(_angle, text)
    if units.length != "units":
        text = _LENGTH_WORD.sub(_length(units.length), text)
    return text
