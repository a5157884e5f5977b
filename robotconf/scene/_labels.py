"""What the position labels say: precision and merged labels.

A label's precision follows the robot's size: three significant digits of its
characteristic length, so the paper robot (90 units of links) prints ``70.0`` and a UR5
(1.19 m) prints ``0.82``, never a bare ``0.8``. Points that coincide at the shown precision
(PUMA's three wrist frames, a SCARA's stacked frames) share one label, ``M4, M5, M6 (…)``.
Where a label stands is the page's business (``js/labels.js``): it knows the camera, so it
keeps labels of nearby points apart on screen, wraps long ones inside the pane, and draws a
leader line from a label to its point whenever it had to move the label away from it.
"""

from __future__ import annotations

import math

import numpy as np

from .._errors import InvalidInputError

__all__ = ["LABEL_MODES", "label_digits", "merge_coincident", "check_label_mode"]

#: What the labels show: nothing, the point names, or names with positions.
LABEL_MODES = ("off", "names", "positions")


def label_digits(length: float) -> int:
    """Decimals that give three significant digits at the robot's size ``length``.

    Examples
    --------
    >>> label_digits(70.0), label_digits(1.19), label_digits(0.4), label_digits(2500.0)
    (1, 2, 3, 0)
    """
    if not math.isfinite(length) or length <= 0:
        return 1
    return int(min(max(2 - math.floor(math.log10(length)), 0), 15))


def merge_coincident(
    names: list[str],
    points: np.ndarray,
    digits: int,
    positions: bool,
    known: dict[tuple[str, tuple[float, ...]], str] | None = None,
) -> list[str]:
    """One label per group of points equal at ``digits`` decimals; the others empty.

    The group's first label names every point of it, ``"M4, M5, M6 (0.45, -0.15, 0.43)"``
    (or ``"M4, M5, M6"`` without ``positions``); an empty text draws nothing. ``known``
    keeps texts already written (by name and rounded position, for one ``digits``): a
    slider step on the last joint writes only the labels of the points that moved.

    Examples
    --------
    >>> points = np.array([[0, 0, 0], [1, 0, 0], [1, 0, 1e-4], [2, 0, 0]])
    >>> merge_coincident(["M1", "M2", "M3", "EE"], points, 1, positions=True)
    ['M1 (0.0, 0.0, 0.0)', 'M2, M3 (1.0, 0.0, 0.0)', '', 'EE (2.0, 0.0, 0.0)']
    """
    from ..kinematics import format_point

    rows = np.asarray(points, dtype=float).tolist()
    # The rounding format_point shows: equal keys print equal numbers.
    keys = [tuple(round(v, digits) + 0.0 for v in row) for row in rows]
    groups: dict[tuple[float, ...], list[int]] = {}
    for k, key in enumerate(keys):
        groups.setdefault(key, []).append(k)
    texts = [""] * len(names)
    for key, members in groups.items():
        name = ", ".join(names[k] for k in members)
        first = members[0]
        if not positions:
            texts[first] = name
        elif known is None:
            texts[first] = format_point(name, rows[first], digits)
        else:
            text = known.get((name, key))
            if text is None:
                if len(known) > 4096:  # a long drag: forget the oldest ones
                    known.clear()
                text = known[(name, key)] = format_point(name, rows[first], digits)
            texts[first] = text
    return texts


def check_label_mode(mode: object) -> str:
    """``True`` → ``"positions"``, ``False`` → ``"off"``, or one of :data:`LABEL_MODES`.

    >>> check_label_mode(True), check_label_mode("names")
    ('positions', 'names')
    """
    if mode is True:
        return "positions"
    if mode is False:
        return "off"
    if isinstance(mode, str) and mode in LABEL_MODES:
        return mode
    raise InvalidInputError("labels", mode, "True, False, 'off', 'names' or 'positions'")
