"""The Motion tab's form: a signal per coordinate, the time settings, Run.

The parameter boxes come from the core signal classes' own fields, so the panel shows
exactly what ``rc.signals.Sine(...)`` accepts. Each box is in the panel's units (an
amplitude of a revolute coordinate in degrees, a slope in deg/s); under the boxes, the
core signal they make, in radians: what ``rc.simulate`` receives.
"""

from __future__ import annotations

import dataclasses
from functools import lru_cache
from typing import Any

import numpy as np

from ...motion import METHODS
from ...signals import RepeatingSequence, Signal
from ..actions import EDITABLE_SIGNALS, HOLD
from ..editor import Quantity
from ..form import button, image, message, number, row, select, text, toggle
from ..state import PanelState, Units

__all__ = ["signal_rows", "settings_rows", "parameter_unit", "PARAMETER_KINDS", "CUSTOM"]

#: The choice shown for a signal only a file can make (a sum, a scaled signal).
CUSTOM = "custom"
_TIPS = {
    "frequency": "hertz (cycles per second); Simulink's block takes rad/s",
    "phase": "the sine's phase angle, in the panel's angle unit (the core takes radians)",
    "duration": "seconds, > 0",
    "accel_fraction": "0 < fraction ≤ 0.5",
}
#: What each parameter of the core's signals measures, which gives its unit: a value of
#: the coordinate, its rate (per second), an angle whatever the coordinate, a time, a
#: frequency or a plain number.
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
_METHOD_TIPS = {
    "analytic": "exact chain rule with the signals' own derivatives",
    "numeric": "central differences of sampled positions",
    "backward": "backward differences of sampled positions (Simulink's Derivative block)",
}


def parameter_unit(name: str, coordinate: str, units: Units) -> tuple[str, str]:
    """``(core unit, label)`` of signal parameter ``name`` for a coordinate whose core
    unit is ``coordinate`` (``"rad"``, ``"length"`` or ``""``).

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
        return "rad", units.angle
    return "", {"time": "s", "frequency": "Hz"}.get(kind, "")


def _parameters(signal: Signal) -> list[str]:
    return [f.name for f in dataclasses.fields(signal) if f.init and not f.name.startswith("_")]  # type: ignore[arg-type]


def _core_text(signal: Signal) -> str:
    shown = repr(signal)
    return shown if len(shown) <= _MAX_SHOWN else shown[: _MAX_SHOWN - 1] + "…"


@lru_cache(maxsize=32)
def _preview(signal: RepeatingSequence, scale: float, heading: str) -> bytes:
    """Two periods of a repeating sequence, as the table shows its values (PNG)."""
    from matplotlib.figure import Figure

    from ..files import figure_png

    t = np.linspace(0.0, 2.0 * signal.period, 400)
    figure = Figure(figsize=(4.0, 1.6), layout="constrained")
    axes = figure.subplots()
    axes.plot(t, signal.value(t) * scale, lw=1.2)
    axes.set_xlabel("time [s]", fontsize=8)
    axes.set_ylabel(heading, fontsize=8)
    axes.tick_params(labelsize=7)
    axes.grid(True, alpha=0.3)
    return figure_png(figure)


def signal_rows(state: PanelState, feedback: Any, rev: str) -> list[dict[str, Any]]:
    """One row per coordinate: its signal's type, parameters and core signal."""
    units = state.units
    robot = state.robot
    rows = [
        row(
            "signals",
            [
                text("Signals", tone="title"),
                text(
                    f"typed in {units.angle}, {units.length} and s; the core signal under each "
                    "is in radians. A held coordinate keeps its slider value.",
                    tone="note",
                ),
            ],
        )
    ]
    for name, link, signal in zip(
        robot.coordinate_names, robot.modules, state.document.motion.signals, strict=True
    ):
        prefix = f"signals.{name}"
        unit = link.unit
        shown_unit = units.coordinate(unit) or "ignored"
        options: list[tuple[str, str]] = [(f"— hold {name} —", HOLD)]
        options += [(kind, kind) for kind in EDITABLE_SIGNALS]
        kind = HOLD if signal is None else type(signal).__name__
        if signal is not None and kind not in EDITABLE_SIGNALS:
            options.append((f"custom: {signal!r}"[:40], CUSTOM))
            kind = CUSTOM
        head = [
            text(f"{name} [{shown_unit}]", tone="title"),
            select(
                prefix,
                kind,
                options,
                rev=rev,
                width="170px",
                css_class="robotconf-signal-kind",
                note=message(feedback.message(prefix)),
            ),
        ]
        lines: list[list[dict[str, Any]]] = [head]
        if kind == CUSTOM:
            lines.append([text("(from a file, in core units)", tone="note")])
        elif isinstance(signal, RepeatingSequence):
            lines += _table_lines(prefix, signal, unit, units, feedback, rev)
        elif signal is not None:
            lines.append(
                [
                    _parameter(prefix, signal, p, unit, units, feedback, rev)
                    for p in _parameters(signal)
                ]
            )
        if signal is not None and kind != CUSTOM:
            lines.append(
                [
                    text(
                        f"core signal: {_core_text(signal)}",
                        tone="note",
                        css_class="robotconf-core-signal",
                    )
                ]
            )
        rows.append(row(prefix + ".row", *lines, css_class="robotconf-signal-row"))
    return rows


def _parameter(
    prefix: str, signal: Signal, name: str, unit: str, units: Units, feedback: Any, rev: str
) -> dict[str, Any]:
    core_unit, label = parameter_unit(name, unit, units)
    quantity = Quantity(core_unit, units, 1.0)
    key = f"{prefix}.{name}"
    value = float(getattr(signal, name))
    shown = units.to_shown(value, core_unit)
    if quantity.is_angle and units.degrees:
        shown = float(f"{shown:.6g}")  # 1 rad reads 57.2958, not 57.29577951308232
    error = feedback.message(key)
    return number(
        key,
        shown,
        shown,
        shown,
        1.0,
        label=f"{name} [{label}]" if label else name,
        slider=False,
        rev=rev,
        text=feedback.typed(key) if error else None,
        note=message(error),
        title=_TIPS.get(name, name),
        width="90px",
    )


def _table_lines(
    prefix: str, signal: RepeatingSequence, unit: str, units: Units, feedback: Any, rev: str
) -> list[list[dict[str, Any]]]:
    label = units.coordinate(unit)
    heading = f"value [{label}]" if label else "value"
    lines = [[text("time [s]", tone="title"), text(heading, tone="title")]]
    for k, (t, v) in enumerate(zip(signal.times, signal.values, strict=True)):
        shown = units.to_shown(float(v), unit)
        if units.scale(unit) != 1.0:
            shown = float(f"{shown:.6g}")
        cells = []
        for cell, value in ((f"{prefix}.table.t{k}", float(t)), (f"{prefix}.table.v{k}", shown)):
            error = feedback.message(cell)
            cells.append(
                number(
                    cell,
                    value,
                    value,
                    value,
                    1.0,
                    slider=False,
                    rev=rev,
                    width="90px",
                    text=feedback.typed(cell) if error else None,
                    note=message(error),
                )
            )
        lines.append(cells)
    lines.append(
        [
            button(f"{prefix}.table.add", "+ row", title="add a row"),
            button(
                f"{prefix}.table.remove",
                "− row",
                title="remove the last row",
                disabled=len(signal.times) <= 2,
            ),
        ]
    )
    png = _preview(signal, units.scale(unit), heading)
    lines.append([image(png, alt=f"{prefix}: two periods of the sequence", width="320px")])
    return lines


def settings_rows(state: PanelState, feedback: Any, rev: str, status: str) -> list[dict[str, Any]]:
    """t_end, dt, the method and Run, with the run's status."""
    settings = state.document.motion.settings

    def seconds(name: str, value: float) -> dict[str, Any]:
        error = feedback.message(name)
        return number(
            name,
            value,
            value,
            value,
            0.001,
            label=f"{name} [s]",
            slider=False,
            rev=rev,
            width="90px",
            text=feedback.typed(name) if error else None,
            note=message(error),
        )

    methods = [(m, m, _METHOD_TIPS.get(m, m)) for m in METHODS]
    return [
        row("time", [seconds("t_end", settings.t_end), seconds("dt", settings.dt)]),
        row(
            "method",
            [toggle("method", settings.method, methods, rev=rev)],
            note=message(feedback.message("method")),
        ),
        row(
            "run",
            [
                button("run", "▶ Run", style="primary", css_class="robotconf-run"),
                text(status, tone="note", css_class="robotconf-run-status"),
            ],
            note=message(feedback.message("run")),
        ),
    ]
