"""One coordinate's signal: a type dropdown and that signal's parameters.

The parameter boxes are generated from the core signal classes' own fields and defaults,
so the panel shows exactly what ``rc.signals.Sine(...)`` accepts. Each box is in the
panel's units (an amplitude of a revolute coordinate in degrees, a slope in deg/s) and
the line under the boxes shows the core signal they make, in radians.
"""

from __future__ import annotations

import dataclasses
import html
from collections.abc import Callable, Iterator

import ipywidgets as widgets

from .._errors import InvalidInputError
from ..signals import SIGNAL_TYPES as CORE_SIGNAL_TYPES
from ..signals import RepeatingSequence, Signal
from ._callbacks import observe
from ._errors_display import ErrorLabel
from ._repeating_table import RepeatingTable
from ._unit_box import UnitBox
from ._units import ANGLE_UNIT, Units

__all__ = ["SignalEditor", "SIGNAL_TYPES"]

#: The signal types offered: the core's registry (Simulink's order, then the
#: point-to-point profiles) without the composites, which have no form of their own.
SIGNAL_TYPES: dict[str, type[Signal]] = {
    name: cls for name, cls in CORE_SIGNAL_TYPES.items() if name not in ("Affine", "Sum")
}
_HOLD = "hold"
_CUSTOM = "custom"
_TIPS = {
    "frequency": "hertz (cycles per second); Simulink's block takes rad/s",
    "phase": "the sine's phase angle, in the panel's angle unit (the core takes radians)",
    "duration": "seconds, > 0",
    "accel_fraction": "0 < fraction ≤ 0.5",
}
#: What each parameter of the core's signals measures, which gives its unit: a value of
#: the coordinate, its rate (per second), an angle whatever the coordinate, a time, a
#: frequency or a plain number (tests/test_panel_units.py checks that every parameter
#: of every offered signal is listed).
PARAMETER_KINDS = {
    "level": "value",
    "initial": "value",
    "final": "value",
    "amplitude": "value",
    "bias": "value",
    "initial_output": "value",
    "start": "value",
    "end": "value",
    "slope": "rate",
    "phase": "angle",
    "step_time": "time",
    "start_time": "time",
    "duration": "time",
    "frequency": "frequency",
    "accel_fraction": "number",
}
#: Longest core signal shown under the boxes (a long repeating table is cut).
_MAX_SHOWN = 160


def parameter_unit(name: str, coordinate: str, units: Units) -> tuple[str, str]:
    """``(core unit, label)`` of signal parameter ``name`` for a coordinate whose core
    unit is ``coordinate`` (``"rad"``, ``"length"`` or ``""``).

    The core unit says what converts (``"rad"`` in degree mode); the label is what the
    box shows.

    >>> deg_mm = Units("mm", degrees=True)
    >>> parameter_unit("amplitude", "rad", deg_mm), parameter_unit("slope", "length", deg_mm)
    (('rad', 'deg'), ('length', 'mm/s'))
    >>> parameter_unit("phase", "length", deg_mm), parameter_unit("frequency", "rad", deg_mm)
    (('rad', 'deg'), ('', 'Hz'))
    """
    kind = PARAMETER_KINDS.get(name, "number")
    if kind in ("value", "rate"):
        return coordinate, units.coordinate(coordinate, 1 if kind == "rate" else 0)
    if kind == "angle":
        return ANGLE_UNIT, units.angle
    return "", {"time": "s", "frequency": "Hz"}.get(kind, "")


def _parameters(kind: type[Signal]) -> list[tuple[str, float]]:
    """``(name, default)`` of a signal class's numeric constructor fields."""
    if kind is RepeatingSequence:
        return []
    return [
        (f.name, float(f.default))  # type: ignore[arg-type]
        for f in dataclasses.fields(kind)  # type: ignore[arg-type]
        if f.init and not f.name.startswith("_")
    ]


class SignalEditor:
    """Type dropdown and parameters for the signal driving one coordinate.

    Parameters
    ----------
    name : str
        Coordinate name, ``"q1"`` ….
    unit : str
        The coordinate's core unit: ``"rad"`` or ``"length"`` (``""`` for none).
    on_change : callable, optional
    units : Units, optional
        The panel's units, in which the boxes show and take numbers (default: the
        core's, radians).

    Examples
    --------
    >>> editor = SignalEditor("q3", "rad", units=Units("mm", degrees=True))
    >>> editor.kind.value = "Sine"
    >>> editor.parameters["amplitude"].description
    'amplitude [deg]'
    >>> editor.parameters["amplitude"].value = 30.0  # degrees
    >>> editor.build()
    (True, Sine(amplitude=0.5235987755982988))
    >>> editor.kind.value = "hold"; editor.build()
    (True, None)
    """

    def __init__(
        self,
        name: str,
        unit: str,
        on_change: Callable[[], None] | None = None,
        *,
        units: Units | None = None,
    ):
        self._on_change = on_change
        self._custom: Signal | None = None
        self._quiet = False
        self.unit = unit
        self.units = units or Units(degrees=False)
        options = [(f"— hold {name} —", _HOLD), *((k, k) for k in SIGNAL_TYPES)]
        self.kind = widgets.Dropdown(
            options=options, value=_HOLD, layout=widgets.Layout(width="170px")
        )
        self.kind.add_class("robotconf-signal-kind")  # browser tests find it by this
        self.label = widgets.HTML(layout=widgets.Layout(width="90px"))
        self.rename(name, unit)
        self.parameters: dict[str, UnitBox] = {}
        self.parameter_errors: dict[str, ErrorLabel] = {}
        self.error = ErrorLabel()
        self._table: RepeatingTable | None = None
        self._body = widgets.HBox(layout=widgets.Layout(flex_flow="row wrap"))
        # The core signal the boxes make, in radians: what a cell would pass to simulate.
        self.core_call = widgets.HTML()
        self.core_call.add_class("robotconf-core-signal")
        self.widget = widgets.VBox(
            [widgets.HBox([self.label, self.kind, self.error.widget]), self._body, self.core_call],
            layout=widgets.Layout(border_bottom="1px solid #eee", padding="2px 0"),
        )
        self._kind_handler = observe(self.kind, self.error, lambda _: self._kind_changed())

    def rename(self, name: str, unit: str) -> None:
        """Drive coordinate ``name`` (its core unit ``unit``): the heading says so, and
        the boxes keep the core's numbers in the new unit (Rz → Tz)."""
        self.name = name
        if unit != getattr(self, "unit", unit):
            self.set_units(self.units, unit)
        self.unit = unit
        self._show_label()

    def _show_label(self) -> None:
        unit = self.units.coordinate(self.unit) or "ignored"
        self.label.value = f"<b>{html.escape(self.name)}</b> <small>[{html.escape(unit)}]</small>"

    def set_units(self, units: Units, unit: str | None = None) -> None:
        """Show the same signal in other units (the panel's switches); no change callback.

        ``unit``: the coordinate's new core unit when it changed type.
        """
        self.units = units
        self.unit = self.unit if unit is None else unit
        self._quiet = True  # the core signal stays the same: nothing to save
        try:
            for name, box in self.parameters.items():
                core_unit, label = parameter_unit(name, self.unit, units)
                box.set_units(units, core_unit)
                box.description = _description(name, label)
            if self._table is not None:
                self._table.set_units(units, self.unit)
        finally:
            self._quiet = False
        self._show_label()
        self.build()

    @property
    def table(self) -> RepeatingTable:
        """The repeating-sequence table (created on first use: it imports matplotlib)."""
        if self._table is None:
            self._table = RepeatingTable(on_change=self._changed, unit=self.unit, units=self.units)
        return self._table

    # -- building -----------------------------------------------------------------------

    def _kind_changed(self) -> None:
        self._make_body()
        self._changed()

    def _make_body(self, values: dict[str, float] | None = None) -> None:
        kind = self.kind.value
        self.parameters, self.parameter_errors = {}, {}
        self.error.clear()
        if kind == _CUSTOM:
            shown = html.escape(repr(self._custom))
            self._body.children = (
                widgets.HTML(f"<code>{shown}</code> (from a file, in core units)"),
            )
            return
        if kind == RepeatingSequence.__name__:
            self._body.children = (self.table.widget,)
            return
        if kind == _HOLD:
            self._body.children = ()
            return
        boxes = []
        for name, default in _parameters(SIGNAL_TYPES[kind]):
            value = default if values is None else values.get(name, default)
            core_unit, label = parameter_unit(name, self.unit, self.units)
            box = UnitBox(
                value,
                core_unit,
                self.units,
                description=_description(name, label),
                tooltip=_TIPS.get(name, name),
                style={"description_width": "initial"},
                layout=widgets.Layout(width="210px"),
            )
            self.parameters[name] = box
            self.parameter_errors[name] = ErrorLabel()
            observe(box, self.parameter_errors[name], lambda _: self._changed())
            boxes.append(widgets.HBox([box, self.parameter_errors[name].widget]))
        self._body.children = tuple(boxes)

    def build(self) -> tuple[bool, Signal | None]:
        """``(valid, signal)``: ``(True, None)`` for "hold"; ``(False, None)`` after
        showing the core's message next to the offending parameter."""
        valid, signal = self._build()
        self._show_core_call(signal)
        return valid, signal

    def _build(self) -> tuple[bool, Signal | None]:
        kind = self.kind.value
        if kind == _HOLD:
            return True, None
        if kind == _CUSTOM:
            return True, self._custom
        if kind == RepeatingSequence.__name__:
            signal = self.table.build()
            return signal is not None, signal
        values = {name: box.core_value for name, box in self.parameters.items()}
        for label in self.parameter_errors.values():
            label.clear()
        try:
            built = SIGNAL_TYPES[kind](**values)
        except InvalidInputError as error:
            self.parameter_errors.get(error.field, self.error).show(str(error))
            return False, None
        self.error.clear()
        return True, built

    def _show_core_call(self, signal: Signal | None) -> None:
        """The core signal under the boxes (radians), or nothing for hold and a file's."""
        if signal is None or self.kind.value == _CUSTOM:
            self.core_call.value = ""
            return
        text = repr(signal)
        text = text if len(text) <= _MAX_SHOWN else text[: _MAX_SHOWN - 1] + "…"
        self.core_call.value = (
            f"<small style='color:#666'>core signal: <code>{html.escape(text)}</code></small>"
        )

    def load(self, signal: Signal | None) -> None:
        """Show ``signal`` (``None``: hold); other signals (sums, scaled) show read-only."""
        with self._kind_handler.paused():
            if signal is None:
                self.kind.value = _HOLD
                self._make_body()
            elif isinstance(signal, RepeatingSequence):
                self.kind.value = RepeatingSequence.__name__
                self.table.load(signal.times, signal.values)
                self._make_body()
            elif type(signal) in SIGNAL_TYPES.values():
                self.kind.value = type(signal).__name__
                self._make_body({f: getattr(signal, f) for f, _ in _parameters(type(signal))})
            else:
                self._custom = signal
                options = [o for o in self.kind.options if o[1] != _CUSTOM]
                self.kind.options = [*options, (f"custom: {signal!r}"[:40], _CUSTOM)]
                self.kind.value = _CUSTOM
                self._make_body()
        self._show_core_call(signal)

    def error_items(self, prefix: str) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)``: ``signals.q1``, ``signals.q1.<parameter>``, ``signals.q1.table``."""
        yield prefix, self.error
        for name, label in self.parameter_errors.items():
            yield f"{prefix}.{name}", label
        if self._table is not None:
            yield f"{prefix}.table", self._table.error

    def _changed(self) -> None:
        if self._quiet:
            return
        self.build()  # immediate feedback: the core's message appears while typing
        if self._on_change is not None:
            self._on_change()


def _description(name: str, unit: str) -> str:
    """A box's description: the parameter's name and, if it has one, its unit."""
    return f"{name} [{unit}]" if unit else name
