"""The robot editor: the module list or the DH table, the active count and the end
effector, as one form that renders the state and turns input into actions."""

from __future__ import annotations

import re
from collections.abc import Callable, Hashable
from typing import Any

from ..._errors import InvalidInputError
from ...kinematics import DH_PARAMETERS, MODULE_OFFSETS
from .. import actions as act
from .._feedback import Feedback
from .._ranges import length_scale, length_step
from ..form import Form, FormEvent, parse_number
from ..state import PanelState
from ._quantity import Quantity, Ranges, read_number
from ._rows import DH_ANGLES, POINT, EditorContext, dh_rows, extras_rows, module_rows

__all__ = ["EditorView", "Dispatch"]

#: ``dispatch(action, key, typed=None)``: apply an action for control ``key``.
Dispatch = Callable[..., None]

_ROW = re.compile(r"^(modules|dh)\[(\d+)\]\.(\w+)$")
_MOVES = {"up": -1, "down": 1}


class EditorView:
    """The module list or the DH table (by the state's editor) with the extras.

    Parameters
    ----------
    dispatch : callable
        ``dispatch(action, key, typed=None)``: the panel applies the action and shows a
        refusal beside control ``key`` (with the ``typed`` text kept in its box).
    """

    def __init__(self, dispatch: Dispatch) -> None:
        self._dispatch = dispatch
        self._state: PanelState | None = None
        self.ranges = Ranges()
        self.form = Form(self._event, css_class="robotconf-editor")
        self._rows: dict[Hashable, dict[str, Any]] = {}

    def render(self, state: PanelState, feedback: Feedback, rev: str) -> None:
        """Show the state's robot in its editor."""
        self._state = state
        ctx = EditorContext(state, feedback, self.ranges, rev, self._rows)
        rows = dh_rows(ctx) if state.editor == "dh" else module_rows(ctx)
        self.form.show(rows + extras_rows(ctx))
        ctx.keep()

    # -- input --------------------------------------------------------------------------

    def _event(self, event: FormEvent) -> None:
        state = self._state
        if state is None:
            return
        if event.event == "widen":
            unit = self.form.control(event.key).get("unit", "")
            self.ranges.widen(event.key, unit)
            self._dispatch(None, event.key)  # nothing changes but the range: draw again
            return
        key = event.key
        typed = event.text if event.event == "type" else None
        try:
            action, target = self._action(state, event)
        except InvalidInputError as error:
            self._dispatch(error, key, typed)
            return
        self._dispatch(action, target, typed)

    def _action(self, state: PanelState, event: FormEvent) -> tuple[act.Action | None, str]:
        """The action an event asks for, and the control whose message it is."""
        key = event.key
        if key in ("modules.add", "dh.add"):
            return act.AddModule(), key.split(".")[0]
        if key == "dh.convention":
            return act.ChooseConvention(str(event.value)), key
        if key.startswith("dh.prompt."):
            return act.AnswerPrompt(key.rsplit(".", 1)[1]), "dh.prompt"
        if key == "active":
            return act.SetActive(_integer(event, "active")), key
        if key.startswith("end_effector."):
            axis = POINT.index(key.split(".")[1])
            value = read_number(event, self._length(state), POINT[axis])
            return act.SetEndEffector(axis, value), key
        match = _ROW.match(key)
        if match is None:
            return None, key
        table, index, field = match.group(1), int(match.group(2)), match.group(3)
        row = f"{table}[{index}]"
        if field in _MOVES:
            return act.MoveModule(index, _MOVES[field]), row
        if field == "delete":
            return act.RemoveModule(index), row
        if field == "kind":
            return act.SetModuleKind(index, str(event.value)), row
        if field == "joint":
            return act.SetDHJoint(index, str(event.value)), row
        if field == "q":
            link = state.robot.modules[index]
            value = read_number(event, self._coordinate(state, link.unit), f"q{index + 1}")
            return act.SetQ(index, value), key
        if field in MODULE_OFFSETS:
            axis = MODULE_OFFSETS.index(field)
            value = read_number(event, self._length(state), field)
            return act.SetModuleOffset(index, axis, value), key
        if field in DH_PARAMETERS:
            unit = "rad" if field in DH_ANGLES else "length"
            value = read_number(event, self._coordinate(state, unit), field)
            return act.SetDHParameter(index, field, value), key
        return None, key

    def _length(self, state: PanelState) -> Quantity:
        return self._coordinate(state, "length")

    def _coordinate(self, state: PanelState, unit: str) -> Quantity:
        return Quantity(unit, state.units, length_step(length_scale(state.robot)))


def _integer(event: FormEvent, field: str) -> int:
    value = parse_number(event.text or "", field) if event.event == "type" else event.value
    if value is None or float(value) != int(float(value)):
        raise InvalidInputError(field, value, "a whole number of modules")
    return int(float(value))
