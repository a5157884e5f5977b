"""One number of the robot as a control shows it: converted for display, with a range,
a step and a unit, and read back from what the student does.

The state holds core numbers (radians, length units). A control shows
``units.to_shown(core)`` without float noise (:func:`~robotconf.panel.form.display_number`)
and turns a drag (snapped onto the step) or typed text (read by
:func:`~robotconf.panel.form.parse_number`) back into a core number. A control whose
number the student did not touch sends nothing, so showing a number never changes it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..._errors import InvalidInputError
from .._ranges import ANGLE_STEP, ANGLE_UNIT, on_steps
from ..form import FormEvent, display_number, message, number, parse_number, snap_to_step
from ..state import Units

__all__ = ["Quantity", "Ranges", "read_number", "number_spec"]


@dataclass(frozen=True)
class Quantity:
    """How a number is shown.

    Parameters
    ----------
    unit : str
        Its core unit: ``"rad"`` (shown in the panel's angle unit), ``"length"`` (named by
        the panel's length unit, never converted) or ``""`` (a plain number).
    units : Units
        The panel's units.
    length_step : float
        The step of a length (a hundredth of the robot's size, see ``_ranges``).

    Examples
    --------
    >>> angle = Quantity("rad", Units("mm", degrees=True), 1.0)
    >>> angle.shown(0.5235987755982988), angle.step, angle.label
    (30.0, 1.0, 'deg')
    >>> Quantity("length", Units("mm", degrees=True), 1.0).label
    'mm'
    """

    unit: str
    units: Units
    length_step: float = 1.0

    @property
    def is_angle(self) -> bool:
        """Whether the number is an angle (converted in degree mode)."""
        return self.unit == ANGLE_UNIT

    @property
    def step(self) -> float:
        """The slider notch and arrow-key step: 1° / 0.01 rad, or the length step."""
        return ANGLE_STEP[self.units.degrees] if self.is_angle else self.length_step

    @property
    def label(self) -> str:
        """The unit as the control names it."""
        return self.units.coordinate(self.unit)

    def shown(self, core: float) -> float:
        """``core`` as the control shows it (display units, no float noise)."""
        return display_number(self.units.to_shown(float(core), self.unit), self.step)

    def core(self, shown: float) -> float:
        """A shown number as the core takes it (radians, length units)."""
        return self.units.to_core(float(shown), self.unit)


def read_number(event: FormEvent, quantity: Quantity, field: str) -> float:
    """The core number a drag or typed text of a control means.

    Raises
    ------
    InvalidInputError
        Naming ``field``, for typed text that is no finite number.

    Examples
    --------
    >>> angle = Quantity("rad", Units(degrees=True), 1.0)
    >>> read_number(FormEvent("q", "drag", 29.999999999999996), angle, "q2")  # a notch at 30
    0.5235987755982988
    >>> read_number(FormEvent("q", "type", text="90"), angle, "q2")
    1.5707963267948966
    """
    if event.event == "drag":
        shown = snap_to_step(float(event.value), quantity.step)
    elif event.event == "type":
        shown = parse_number(event.text or "", field)
    else:
        raise InvalidInputError(field, event.event, "a number dragged or typed")
    return quantity.core(shown)


class Ranges:
    """The slider ranges of a form's number controls: a default per control, widened by
    the student's ↔ and always wide enough for the value shown (display units).

    Examples
    --------
    >>> ranges = Ranges()
    >>> ranges.span("q", 30.0, (-180.0, 180.0), 1.0, "deg")
    (-180.0, 180.0)
    >>> ranges.span("q", 250.0, (-180.0, 180.0), 1.0, "deg")  # the value widens it
    (-180.0, 250.0)
    >>> ranges.widen("q", "deg"); ranges.span("q", 30.0, (-180.0, 180.0), 1.0, "deg")
    (-360.0, 360.0)
    """

    def __init__(self) -> None:
        self._widened: dict[str, tuple[float, str]] = {}  # key -> (factor, unit label)
        #: Bumped at every change, so a drawing made with the old ranges is not reused.
        self.version = 0

    def span(
        self, key: str, shown: float, default: tuple[float, float], step: float, unit: str
    ) -> tuple[float, float]:
        """The slider's ends for control ``key`` showing ``shown``."""
        low, high = default
        widened = self._widened.get(key)
        if widened is not None and widened[1] == unit:
            middle, half = 0.5 * (low + high), 0.5 * (high - low) * widened[0]
            low, high = middle - half, middle + half
        if math.isfinite(shown):
            low, high = min(low, shown), max(high, shown)
        return on_steps(low, high, step)

    def widen(self, key: str, unit: str) -> None:
        """Double the range of control ``key`` (showing numbers in ``unit``)."""
        factor, known = self._widened.get(key, (1.0, unit))
        self._widened[key] = (factor * 2.0 if known == unit else 2.0, unit)
        self.version += 1

    def forget(self) -> None:
        """Every range back to its default (another robot)."""
        if self._widened:
            self._widened.clear()
            self.version += 1


def number_spec(
    key: str,
    core: float,
    quantity: Quantity,
    default: tuple[float, float],
    ranges: Ranges,
    *,
    label: str,
    rev: str,
    error: str = "",
    typed: str | None = None,
    warning: str = "",
    **options: Any,
) -> dict[str, Any]:
    """The spec of one number control (see :func:`~robotconf.panel.form.number`)."""
    shown = quantity.shown(core)
    low, high = ranges.span(key, shown, default, quantity.step, quantity.label)
    note = message(error) if error else message(warning, "warning")
    return number(
        key,
        shown,
        low,
        high,
        quantity.step,
        label=label,
        unit=quantity.label,
        rev=rev,
        text=typed if error else None,
        note=note,
        **options,
    )
