"""One coordinate's signal: a type dropdown and that signal's parameters.

The parameter boxes are generated from the core signal classes' own fields and defaults,
so the panel shows exactly what ``rc.signals.Sine(...)`` accepts.
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
    "phase": "radians",
    "duration": "seconds, > 0",
    "accel_fraction": "0 < fraction ≤ 0.5",
}


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
        ``"rad"`` or ``"length"`` (signal values are in core units).
    on_change : callable, optional

    Examples
    --------
    >>> editor = SignalEditor("q3", "rad")
    >>> editor.kind.value = "Sine"
    >>> editor.parameters["amplitude"].value = 0.5
    >>> editor.build()
    (True, Sine(amplitude=0.5))
    >>> editor.kind.value = "hold"; editor.build()
    (True, None)
    """

    def __init__(self, name: str, unit: str, on_change: Callable[[], None] | None = None):
        self._on_change = on_change
        self._custom: Signal | None = None
        options = [(f"— hold {name} —", _HOLD), *((k, k) for k in SIGNAL_TYPES)]
        self.kind = widgets.Dropdown(
            options=options, value=_HOLD, layout=widgets.Layout(width="170px")
        )
        self.label = widgets.HTML(layout=widgets.Layout(width="90px"))
        self.rename(name, unit)
        self.parameters: dict[str, widgets.FloatText] = {}
        self.parameter_errors: dict[str, ErrorLabel] = {}
        self.error = ErrorLabel()
        self._table: RepeatingTable | None = None
        self._body = widgets.HBox(layout=widgets.Layout(flex_flow="row wrap"))
        self.widget = widgets.VBox(
            [widgets.HBox([self.label, self.kind, self.error.widget]), self._body],
            layout=widgets.Layout(border_bottom="1px solid #eee", padding="2px 0"),
        )
        self._kind_handler = observe(self.kind, self.error, lambda _: self._kind_changed())

    def rename(self, name: str, unit: str) -> None:
        """Drive coordinate ``name`` (its unit ``unit``): the heading says so."""
        self.name = name
        self.label.value = f"<b>{html.escape(name)}</b> <small>({html.escape(unit)})</small>"

    @property
    def table(self) -> RepeatingTable:
        """The repeating-sequence table (created on first use: it imports matplotlib)."""
        if self._table is None:
            self._table = RepeatingTable(on_change=self._changed)
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
            self._body.children = (widgets.HTML(f"<code>{shown}</code> (from a file)"),)
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
            box = widgets.FloatText(
                value=value,
                description=name,
                tooltip=_TIPS.get(name, name),
                style={"description_width": "initial"},
                layout=widgets.Layout(width="170px"),
            )
            self.parameters[name] = box
            self.parameter_errors[name] = ErrorLabel()
            observe(box, self.parameter_errors[name], lambda _: self._changed())
            boxes.append(widgets.HBox([box, self.parameter_errors[name].widget]))
        self._body.children = tuple(boxes)

    def build(self) -> tuple[bool, Signal | None]:
        """``(valid, signal)``: ``(True, None)`` for "hold"; ``(False, None)`` after
        showing the core's message next to the offending parameter."""
        kind = self.kind.value
        if kind == _HOLD:
            return True, None
        if kind == _CUSTOM:
            return True, self._custom
        if kind == RepeatingSequence.__name__:
            signal = self.table.build()
            return signal is not None, signal
        values = {name: box.value for name, box in self.parameters.items()}
        for label in self.parameter_errors.values():
            label.clear()
        try:
            built = SIGNAL_TYPES[kind](**values)
        except InvalidInputError as error:
            self.parameter_errors.get(error.field, self.error).show(str(error))
            return False, None
        self.error.clear()
        return True, built

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

    def error_items(self, prefix: str) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)``: ``signals.q1``, ``signals.q1.<parameter>``, ``signals.q1.table``."""
        yield prefix, self.error
        for name, label in self.parameter_errors.items():
            yield f"{prefix}.{name}", label
        if self._table is not None:
            yield f"{prefix}.table", self._table.error

    def _changed(self) -> None:
        self.build()  # immediate feedback: the core's message appears while typing
        if self._on_change is not None:
            self._on_change()
