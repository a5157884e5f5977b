"""The Motion tab: the signals and time settings (one form), Run, and the last run's
results. Every input becomes an action on the state."""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

import ipywidgets as widgets

from ..._errors import InvalidInputError
from ...signals import RepeatingSequence
from .. import actions as act
from .._feedback import Feedback
from ..form import Form, FormEvent, parse_number
from ..state import PanelState
from ._results import ResultsView
from ._signal_rows import parameter_unit, settings_rows, signal_rows

__all__ = ["MotionTab"]

_SIGNAL = re.compile(r"^signals\.(q\d+)(?:\.(\w+))?$")
_CELL = re.compile(r"^signals\.(q\d+)\.table\.([tv])(\d+)$")
_TABLE = re.compile(r"^signals\.(q\d+)\.table\.(add|remove)$")


def _number(event: FormEvent, field: str) -> float:
    if event.event == "drag":
        return float(event.value)
    return parse_number(event.text or "", field)


class MotionTab:
    """Signals, time settings, Run, results.

    Parameters
    ----------
    dispatch : callable
        ``dispatch(action, key, typed=None)``.
    app : bool
        No notebook around the panel: no hints to type code.
    """

    def __init__(self, dispatch: Callable[..., None], app: bool = False) -> None:
        self._dispatch = dispatch
        self._state: PanelState | None = None
        self.form = Form(self._event, css_class="robotconf-motion")
        self.results = ResultsView(self._result_event, app=app)
        self.widget = widgets.VBox([self.form, self.results.widget])
        self.widget.add_class("robotconf-motion-tab")
        self._drawn: Any = None

    def render(self, state: PanelState, feedback: Feedback, rev: str, visible: bool) -> None:
        """Show the signals and the last run (drawn only while the tab shows)."""
        self._state = state
        robot = state.robot
        # A q drag changes nothing here: draw again only when what is shown changed.
        key = (
            tuple(link.unit for link in robot.modules),
            state.document.motion,
            state.units,
            feedback.version,
            rev,
            id(state.motion),
            state.motion is not None and state.motion.robot == robot,
        )
        if key != self._drawn:
            self._drawn = key
            self.form.show(
                signal_rows(state, feedback, rev)
                + settings_rows(state, feedback, rev, _status(state))
            )
        self.results.render(state, feedback, rev, visible)

    # -- input --------------------------------------------------------------------------

    def _event(self, event: FormEvent) -> None:
        state = self._state
        if state is None:
            return
        typed = event.text if event.event == "type" else None
        try:
            action, target = self._action(state, event)
        except InvalidInputError as error:
            self._dispatch(error, event.key, typed)
            return
        self._dispatch(action, target, typed)

    def _action(self, state: PanelState, event: FormEvent) -> tuple[Any, str]:
        key = event.key
        if key == "run":
            return act.Run(), "run"
        if key in ("t_end", "dt"):
            return act.SetTimeSetting(key, _number(event, key)), key
        if key == "method":
            return act.SetTimeSetting("method", str(event.value)), key
        cell = _CELL.match(key)
        if cell is not None:
            return self._cell(state, event, cell.group(1), cell.group(2), int(cell.group(3)))
        table = _TABLE.match(key)
        if table is not None:
            return self._rows(state, table.group(1), table.group(2)), f"signals.{table.group(1)}"
        match = _SIGNAL.match(key)
        if match is None:
            return None, key
        index = state.robot.index(match.group(1))
        name = match.group(2)
        if name is None:
            return act.SetSignalKind(index, str(event.value)), key
        link = state.robot.modules[index]
        core_unit, _ = parameter_unit(name, link.unit, state.units)
        value = state.units.to_core(_number(event, name), core_unit)
        return act.SetSignalParameter(index, name, value), key

    def _signal(self, state: PanelState, coordinate: str) -> tuple[int, RepeatingSequence]:
        index = state.robot.index(coordinate)
        signal = state.document.motion.signals[index]
        if not isinstance(signal, RepeatingSequence):
            raise InvalidInputError(coordinate, signal, "a repeating sequence")
        return index, signal

    def _cell(
        self, state: PanelState, event: FormEvent, coordinate: str, column: str, k: int
    ) -> tuple[Any, str]:
        index, signal = self._signal(state, coordinate)
        times, values = list(signal.times), list(signal.values)
        if column == "t":
            times[k] = _number(event, "times")
        else:
            unit = state.robot.modules[index].unit
            values[k] = state.units.to_core(_number(event, "values"), unit)
        return act.SetSignalTable(index, times, values), event.key

    def _rows(self, state: PanelState, coordinate: str, change: str) -> Any:
        index, signal = self._signal(state, coordinate)
        times, values = list(signal.times), list(signal.values)
        if change == "remove":
            times, values = times[:-1], values[:-1]
        else:
            step = times[-1] - times[-2] if len(times) > 1 else 1.0
            times.append(times[-1] + step)
            values.append(values[-1])
        return act.SetSignalTable(index, times, values)

    def _result_event(self, event: FormEvent) -> None:
        key = event.key
        if key == "results.animate":
            self._dispatch(act.Animate("motion"), "results")
        elif key == "results.csv":
            # A download link changes nothing of the state: made here, refusals shown.
            try:
                self.results.make_csv_link()
            except InvalidInputError as error:
                self._dispatch(error, "results")
        elif key == "results.point":
            self._dispatch(act.SetViewOption("result_point", event.value), "results")
        elif key == "results.view":
            self._dispatch(act.SetViewOption("result_view", event.value), "results")
        elif key in ("results.overlay", "results.displacement"):
            name = key.split(".")[1]
            self._dispatch(act.SetViewOption(name, bool(event.value)), "results")


def _status(state: PanelState) -> str:
    motion = state.motion
    if motion is None:
        return ""
    if state.program_run is not None and state.program_run.motion is motion:
        return f"showing the Program tab's run: {motion.t.size} samples, {motion.method}"
    if motion.robot != state.robot:
        return "the robot changed since this run: press Run"
    return f"{motion.t.size} samples, {motion.method}"
