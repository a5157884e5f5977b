"""One number as a slider plus a number box; typing outside the range widens it.

The number box is the authoritative value (it can hold anything the user types, even
NaN, which the core then refuses with a message); the slider follows it when finite.
Angles can be shown in degrees or radians: the control converts for display only, the
core always receives radians.

Numbers set by the panel are shown without float noise (:func:`display_number`: 90°,
not 89.99999999999999), and the control keeps the exact value it was given: as long as
the box still shows that number, :attr:`NumberControl.core_value` is the exact value, so a
robot read back from untouched boxes is the robot that was loaded. Slider notches are
snapped onto the step (a browser slider sends 7.1e-15 for 0). The step is 1° for angles
(0.01 rad in radians) and a length step from the robot's size (see ``_ranges``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import ipywidgets as widgets
import numpy as np

from ._callbacks import observe, on_click
from ._clean_numbers import display_number, snap_to_step
from ._errors_display import ErrorLabel
from ._ranges import ANGLE_STEP, length_step, on_steps

__all__ = ["NumberControl"]


class NumberControl:
    """A labelled slider + number box (+ "widen" button) with an error label.

    Parameters
    ----------
    label : str
        Short name shown before the slider (``"ax"``, ``"q"``, ``"θ"``).
    value : float
        Initial value in core units (radians for angles).
    lo, hi : float
        Slider range in display units (rounded outwards onto the step).
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
    length_step : float, optional
        The step when the value is a length (default: from the range, see
        :func:`~robotconf.panel._ranges.length_step`). Angles step by 1° (0.01 rad).

    Examples
    --------
    >>> control = NumberControl("q", np.deg2rad(30.0), -180, 180, angle=True)
    >>> control.box.value, control.step  # rad2deg gives 29.999999999999996
    (30.0, 1.0)
    >>> control.core_value == float(np.deg2rad(30.0))  # untouched: exactly what it was given
    True
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
        length_step: float | None = None,
    ):
        self.angle = angle
        self.degrees = degrees
        self.on_change = on_change
        self._unit = unit
        self._quiet = False
        self._length_step = length_step or _default_length_step(lo, hi)
        # The exact core value last given, and the number shown for it: while the box
        # still shows that number, the exact value is the control's value (no drift).
        self._core = float(value)
        self._shown = self._clean(self._to_display(self._core))
        shown = self._shown
        self.name = widgets.Label(label, layout=widgets.Layout(width=label_width))
        step = self.step
        lo, hi = (
            on_steps(min(lo, shown), max(hi, shown), step) if math.isfinite(shown) else (lo, hi)
        )
        self.slider = widgets.FloatSlider(
            value=shown if math.isfinite(shown) else lo,
            min=lo,
            max=hi,
            step=step,
            readout=False,
            continuous_update=True,
            layout=widgets.Layout(width="150px"),
        )
        self.box = widgets.FloatText(value=shown, step=step, layout=widgets.Layout(width="78px"))
        self.widen_button = widgets.Button(
            icon="arrows-h",
            tooltip="double the slider range",
            # Without padding the icon fits; with a button's default padding a 30-px button
            # shows it cut, followed by an ellipsis.
            layout=widgets.Layout(width="32px", padding="0"),
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

    @property
    def step(self) -> float:
        """The slider and arrow-key step in display units: 1° / 0.01 rad, or the length step."""
        return ANGLE_STEP[self.degrees] if self.angle else self._length_step

    def _unit_text(self) -> str:
        if self.angle:
            return "deg" if self.degrees else "rad"
        return self._unit

    def _to_display(self, core: float) -> float:
        return float(np.rad2deg(core)) if self.angle and self.degrees else float(core)

    def _to_core(self, shown: float) -> float:
        return float(np.deg2rad(shown)) if self.angle and self.degrees else float(shown)

    def _clean(self, shown: float) -> float:
        return display_number(shown, self.step)

    @property
    def value(self) -> float:
        """The typed value in display units (may be NaN: the core will refuse it)."""
        return float(self.box.value)

    @property
    def core_value(self) -> float:
        """The value in core units (radians for angles); exact while the box is untouched."""
        shown = self.value
        if shown == self._shown:
            return self._core
        return self._to_core(shown)

    def set_core_value(self, value: float) -> None:
        """Show ``value`` (core units) without calling ``on_change``; a finite value is
        valid, so an error shown for the old one goes."""
        self._show_core(float(value))
        if math.isfinite(value):
            self.error.clear()

    def _show_core(self, core: float) -> None:
        self._core = core
        self._shown = self._clean(self._to_display(core)) if math.isfinite(core) else core
        self._set_shown(self._shown)

    def set_degrees(self, degrees: bool) -> None:
        """Switch an angle between degrees and radians; the core value is unchanged."""
        if not self.angle or degrees == self.degrees:
            return
        core = self.core_value
        lo, hi = self._to_core(self.slider.min), self._to_core(self.slider.max)
        self.degrees = degrees
        self.unit_label.value = self._unit_text()
        self.set_range(self._to_display(lo), self._to_display(hi))
        self._show_core(core)

    def set_angle(self, angle: bool, lo: float, hi: float, unit: str = "") -> None:
        """Make this an angle or a length control (movement type changed), keeping the number."""
        core = self.core_value
        self.angle = angle
        self._unit = unit
        self.unit_label.value = self._unit_text()
        self.set_range(lo, hi)
        self._show_core(core)

    def set_length_step(self, step: float) -> None:
        """Use ``step`` for a length (a robot of another size was loaded)."""
        self._length_step = step
        self.set_range(self.slider.min, self.slider.max)

    # -- range --------------------------------------------------------------------------

    def set_range(self, lo: float, hi: float) -> None:
        """Set the slider range (display units, rounded outwards onto the step); the typed
        value is kept."""
        step = self.step
        lo, hi = on_steps(lo, hi, step)
        self._quiet, quiet = True, self._quiet
        try:
            # Order matters: a new min above the old max would be refused.
            if lo > self.slider.max:
                self.slider.max, self.slider.min = hi, lo
            else:
                self.slider.min, self.slider.max = lo, hi
            self.slider.step = self.box.step = step
            if math.isfinite(self.box.value):
                self.slider.value = min(max(self.box.value, lo), hi)
        finally:
            self._quiet = quiet

    def widen(self) -> None:
        """Double the slider range around its centre."""
        lo, hi = self.slider.min, self.slider.max
        half = max(hi - lo, self.step)
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
        self.drag_to(change["new"])

    def notch(self, shown: float) -> float:
        """The slider notch nearest ``shown`` (display units), within the slider's range.

        >>> NumberControl("q", 0.0, -180, 180, angle=True).notch(34.377)
        34.0
        """
        step, slider = self.step, self.slider
        return min(max(display_number(round(shown / step) * step, step), slider.min), slider.max)

    def drag_to(self, shown: float) -> None:
        """Take a slider position the user dragged to (display units), as a move of the
        slider: the box follows and ``on_change`` runs. The page's slider already shows it.

        Used for the slider's own updates and for the drag relay's faster copies of them
        (:mod:`robotconf.panel._drag_relay`); a position outside the slider's range is a
        stale copy (the range or unit changed since) and is ignored.

        Examples
        --------
        >>> control = NumberControl("q", 0.0, -180, 180, angle=True)
        >>> control.drag_to(29.999999999999996)  # a browser's notch at 30
        >>> control.box.value, round(control.core_value, 6)
        (30.0, 0.523599)
        >>> control.drag_to(720.0)  # outside the slider: ignored
        >>> control.box.value
        30.0
        >>> control.box.value = 34.4  # typed between two notches
        >>> control.drag_to(34.0)  # the page's slider sends its notch back: not a move
        >>> control.box.value
        34.4
        >>> control.drag_to(35.0)  # a move to another notch
        >>> control.box.value
        35.0
        """
        if self._quiet or not self.slider.min <= shown <= self.slider.max:
            return
        value = self.value
        if math.isfinite(value) and value != self.notch(value) == self.notch(shown):
            # A value set between two notches (34.4°, a solved pose) reaches the page's
            # slider, which snaps it and sends the notch back as if dragged there: the
            # robot would move by up to half a step with no one touching it.
            return
        shown = snap_to_step(shown, self.step)
        if shown == self.value:
            return  # the browser's rounding noise, not a move: nothing changed
        self._quiet = True
        try:
            self.box.value = shown
        finally:
            self._quiet = False
        self._core, self._shown = self._to_core(shown), shown
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


def _default_length_step(lo: float, hi: float) -> float:
    """A length step for a control that was not told one: from its range's half-width."""
    return length_step(max(abs(lo), abs(hi)))
