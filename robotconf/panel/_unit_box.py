"""A number box that shows a core number in the panel's units and gives it back exactly."""

from __future__ import annotations

import math
from typing import Any

import ipywidgets as widgets

from ._units import Units

__all__ = ["UnitBox", "CORE_UNITS", "SHOWN_DIGITS"]

#: The core's own units: radians, the robot's length unit.
CORE_UNITS = Units(degrees=False)
#: Significant digits of a converted number (57.2958 for 1 rad): a box is narrow, and
#: the exact core value is kept anyway while the box is untouched.
SHOWN_DIGITS = 6


class UnitBox(widgets.FloatText):
    """A ``FloatText`` holding a core number (radians, length) shown in ``units``.

    A converted number is shown to 6 significant digits; while the box still shows it,
    :attr:`core_value` is the exact number it was given, so reading an untouched box
    never changes a signal. A typed number is converted (degrees → radians).

    Parameters
    ----------
    core : float
        The value in core units.
    unit : str
        Its core unit: ``"rad"`` (converted in degree mode), ``"length"`` or ``""``.
    units : Units, optional
        The panel's units (default: the core's, no conversion).
    **kwargs
        Passed to ``ipywidgets.FloatText`` (``description``, ``layout`` …).

    Examples
    --------
    >>> box = UnitBox(1.0, "rad", Units(degrees=True))
    >>> box.value, box.core_value  # shown rounded, read back exactly
    (57.2958, 1.0)
    >>> box.value = 30.0
    >>> box.core_value
    0.5235987755982988
    >>> box.set_units(Units(degrees=False)); box.value
    0.5235987755982988
    """

    def __init__(self, core: float, unit: str = "", units: Units | None = None, **kwargs: Any):
        super().__init__(**kwargs)
        self.unit = unit
        self.units = units or CORE_UNITS
        self._core = float(core)
        self._shown = float("nan")
        self.show_core(core)

    @property
    def core_value(self) -> float:
        """The value in core units; exact while the box shows what it was given."""
        shown = float(self.value)
        if shown == self._shown:
            return self._core
        return self.units.to_core(shown, self.unit)

    def show_core(self, core: float) -> None:
        """Show ``core`` (core units) in the panel's units."""
        shown = self.units.to_shown(core, self.unit)
        if self.units.scale(self.unit) != 1.0 and math.isfinite(shown):
            shown = float(f"{shown:.{SHOWN_DIGITS}g}")
        # Both first: an observer of ``value`` reads core_value while it is being set.
        self._core, self._shown = float(core), shown
        self.value = shown

    def set_units(self, units: Units, unit: str | None = None) -> None:
        """Show the same core value in other units (the deg/rad switch), and in core unit
        ``unit`` when the coordinate changed type (Rz → Tz keeps the number the core has)."""
        core = self.core_value
        self.units = units
        self.unit = self.unit if unit is None else unit
        self.show_core(core)
