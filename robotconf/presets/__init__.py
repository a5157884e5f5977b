"""A library of classic robots: ``preset(name, **overrides)`` and ``preset_names()``.

Each preset is a function in this package with a docstring citing where its parameters
come from (docs/presets.md lists them all); its keyword parameters are the overrides
``preset`` accepts, e.g. ``preset("planar_2r", l1=2.0, l2=1.0)``.

>>> import robotconf as rc
>>> rc.preset("paper").end_effector([0, 0, 0])
array([70.,  0., 20.])
>>> "ur5" in rc.preset_names()
True
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from typing import Any

from .._errors import InvalidInputError
from ..kinematics import Robot
from ._classic import articulated, cartesian, cylindrical, planar_2r, planar_3r, scara, spherical
from ._industrial import puma560, stanford, ur5
from ._paper import paper

__all__ = ["preset", "preset_names", "PRESETS"]

#: Name → function building the robot; the order is the one ``preset_names`` reports.
PRESETS: dict[str, Callable[..., Robot]] = {
    "paper": paper,
    "cartesian": cartesian,
    "cylindrical": cylindrical,
    "spherical": spherical,
    "scara": scara,
    "articulated": articulated,
    "planar_2r": planar_2r,
    "planar_3r": planar_3r,
    "stanford": stanford,
    "puma560": puma560,
    "ur5": ur5,
}


def preset_names() -> tuple[str, ...]:
    """Names accepted by :func:`preset`, the paper's robot first.

    >>> preset_names()[:3]
    ('paper', 'cartesian', 'cylindrical')
    """
    return tuple(PRESETS)


def preset(name: str, **overrides: Any) -> Robot:
    """A classic robot by name, optionally with other dimensions.

    Parameters
    ----------
    name : str
        One of :func:`preset_names` (any case).
    **overrides : float
        Keyword parameters of that preset's function (lengths in the preset's units,
        e.g. ``l1`` for ``"paper"``, ``tool`` for ``"ur5"``).

    Returns
    -------
    Robot
        With names and joint ranges (see :meth:`Robot.joint_limits`).

    Raises
    ------
    InvalidInputError
        For an unknown name (the message lists the known ones) or override.

    Examples
    --------
    >>> preset("paper", l3=50).end_effector([0, 0, 0])
    array([80.,  0., 20.])
    >>> preset("nope")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: name: unknown preset 'nope'; allowed: paper, cartesian, ...
    """
    key = name.strip().lower() if isinstance(name, str) else None
    if key not in PRESETS:
        raise InvalidInputError("name", name, ", ".join(PRESETS), problem="unknown preset")
    factory = PRESETS[key]
    parameters = tuple(inspect.signature(factory).parameters)
    for option in overrides:
        if option not in parameters:
            raise InvalidInputError(
                option,
                overrides[option],
                f"the parameters of '{key}': {', '.join(parameters) or 'none'}",
                problem="unknown override, value",
            )
    return factory(**overrides)
