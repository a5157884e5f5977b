"""One number as a slider plus a number box; typing outside the range widens it.

The number box is the authoritative value (it can hold anything the user types, even
NaN, which the core then refuses with a message); the slider follows it when finite.
Angles can be shown in degrees or radians: the control converts for display only, the
core always receives radians.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import ipywidgets as widgets
import numpy as np

from ._callbacks import observe, on_click
from ._errors_display import ErrorLabel

__all__ = ["NumberControl"]


def _step(lo: float, hi: float) -> float:
    span = hi - lo
    return float(10.0 ** math.floor(math.log10(span / 200.0))) if span > 0 else 0.01


class NumberControl:
    """A labelled slider + number box (+ "widen" button) with an error label.

    Parameters
    ----------
    label : str
        Short name shown before the slider (``"ax"``, ``"q"``, ``"θ"``).
    value : float
        Initial value in core units (radians for angles).
    lo, hi : float
        Slider range in display units.
    angle : bool
        The value is an angle (shown in degrees when ``degrees``).
    degrees : bool
        Show angles in degrees.
    unit : str
        Unit text shown after the box for non-angles.
    slider : bool
        ``False`` gives a compact number box only (DH table cells).
    on_change : callable, optional
        Called with this control after every user change.

    Examples
    --------
    >>> control = NumberControl("q", 0.0, -180, 180, angle=True)
    >>> control.box.value = 90.0
    >>> round(control.core_value, 12)
    1.570796326795
    >>> control.box.value = 400.0  # beyond the slider: the range widens
    >>> control.slider.max >= 400
    True
    """

    def __init__(
        self,
        label: str,
        value: float,
        lo: float,
        hi: float,
        *,
        angle: bool = False,
        degrees: bool = True,
        unit: str = "",
        slider: bool = True,
        on_change: Callable[[NumberControl], None] | None = None,
        label_width: str = "28px",
    ):
        self.angle = angle
        self.degrees = degrees
        self.on_change = on_change
        self._unit = unit
        self._quiet = False
        self.name = widgets.Label(label, layout=widgets.Layout(width=label_width))
        shown = self._to_display(value)
        lo, hi = min(lo, shown), max(hi, shown)
        step = _step(lo, hi)
        self.slider = widgets.FloatSlider(
            value=shown,
            min=lo,
            max=hi,
            step=step,
            readout=False,
            continuous_update=True,
            layout=widgets.Layout(width="150px"),
        )
        self.box = widgets.FloatText(value=shown, step=step, layout=widgets.Layout(width="78px"))
        self.widen_button = widgets.Button(
            icon="arrows-h", tooltip="double the slider range", layout=widgets.Layout(width="30px")
        )
        self.unit_label = widgets.Label(self._unit_text(), layout=widgets.Layout(width="40px"))
        self.error = ErrorLabel()
        parts: list[widgets.Widget] = [self.name]
        if slider:
            parts += [self.slider, self.box, self.widen_button]
        else:
            parts += [self.box]
        parts += [self.unit_label, self.error.widget]
        self.widget = widgets.HBox(parts, layout=widgets.Layout(align_items="center"))
        # A failure anywhere downstream (the robot, the scene) shows beside this control.
        observe(self.slider, self.error, self._slider_changed)
        observe(self.box, self.error, self._box_changed)
        on_click(self.widen_button, self.error, self.widen)

    # -- units --------------------------------------------------------------------------

    def _unit_text(self) -> str:
        if self.angle:
            return "deg" if self.degrees else "rad"
        return self._unit

    def _to_display(self, core: float) -> float:
        return float(np.rad2deg(core)) if self.angle and self.degrees else float(core)

    def _to_core(self, shown: float) -> float:
        return float(np.deg2rad(shown)) if self.angle and self.degrees else float(shown)

    @property
    def value(self) -> float:
        """The typed value in display units (may be NaN: the core will refuse it)."""
        return float(self.box.value)

    @property
    def core_value(self) -> float:
        """The value in core units (radians for angles)."""
        return self._to_core(self.value)

    def set_core_value(self, value: float) -> None:
        """Show ``value`` (core units) without calling ``on_change``."""
        self._set_shown(self._to_display(value))

    def set_degrees(self, degrees: bool) -> None:
        """Switch an angle between degrees and radians; the core value is unchanged."""
        if not self.angle or degrees == self.degrees:
            return
        core = self.core_value
        lo, hi = self._to_core(self.slider.min), self._to_core(self.slider.max)
        self.degrees = degrees
        self.unit_label.value = self._unit_text()
        self.set_range(self._to_display(lo), self._to_display(hi))
        self._set_shown(self._to_display(core) if math.isfinite(core) else core)

    def set_angle(self, angle: bool, lo: float, hi: float, unit: str = "") -> None:
        """Make this an angle or a length control (movement type changed), keeping the number."""
        core = self.core_value
        self.angle = angle
        self._unit = unit
        self.unit_label.value = self._unit_text()
        self.set_range(lo, hi)
        self._set_shown(self._to_display(core) if math.isfinite(core) else core)

    # -- range --------------------------------------------------------------------------

    def set_range(self, lo: float, hi: float) -> None:
        """Set the slider range (display units); the typed value is kept."""
        self._quiet, quiet = True, self._quiet
        try:
            # Order matters: a new min above the old max would be refused.
            if lo > self.slider.max:
                self.slider.max, self.slider.min = hi, lo
            else:
                self.slider.min, self.slider.max = lo, hi
            self.slider.step = self.box.step = _step(lo, hi)
            if math.isfinite(self.box.value):
                self.slider.value = min(max(self.box.value, lo), hi)
        finally:
            self._quiet = quiet

    def widen(self) -> None:
        """Double the slider range around its centre."""
        lo, hi = self.slider.min, self.slider.max
        half = max(hi - lo, 1e-9)
        middle = 0.5 * (lo + hi)
        self.set_range(middle - half, middle + half)

    # -- synchronisation ----------------------------------------------------------------

    def _set_shown(self, shown: float) -> None:
        self._quiet, quiet = True, self._quiet
        try:
            if math.isfinite(shown):
                if not self.slider.min <= shown <= self.slider.max:
                    self.set_range(min(self.slider.min, shown), max(self.slider.max, shown))
                self.slider.value = shown
            self.box.value = shown
        finally:
            self._quiet = quiet

    def _slider_changed(self, change: dict[str, Any]) -> None:
        if self._quiet:
            return
        self._quiet = True
        try:
            self.box.value = change["new"]
        finally:
            self._quiet = False
        self._notify()

    def _box_changed(self, change: dict[str, Any]) -> None:
        if self._quiet:
            return
        new = change["new"]
        if math.isfinite(new):
            self._set_shown(new)
        self._notify()

    def _notify(self) -> None:
        if self.on_change is not None:
            self.on_change(self)

    def disable(self, disabled: bool) -> None:
        """Grey the control out (a coordinate that a ``none``/``fixed`` module ignores)."""
        self.slider.disabled = self.box.disabled = self.widen_button.disabled = disabled
