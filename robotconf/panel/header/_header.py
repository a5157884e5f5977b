"""The header row: undo and redo, the preset, the editing mode, degrees or radians, the
length unit; and, under it, the question the panel asks before it turns a module robot
into a DH table."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ..._errors import InvalidInputError
from ...kinematics import DH_CONVENTIONS
from .. import actions as act
from .._feedback import Feedback, Refusal
from ..actions import to_dh
from ..form import Form, FormEvent, button, message, row, select, text, toggle
from ..state import HISTORY_LIMIT, LENGTH_UNITS, PanelState
from ._presets import PRESET_OPTIONS, preset_of

__all__ = ["HeaderView", "MODE_OPTIONS", "dh_entry_note", "dh_refusal"]

#: The editing modes as the header offers them.
MODE_OPTIONS = (("Modules", "modules"), ("DH table", "dh"), ("Guided", "wizard"))
_ANGLES = (("deg", True, "angles in degrees"), ("rad", False, "angles in radians"))


def dh_entry_note(state: PanelState) -> str:
    """Why the convention beside the modules → DH question is preselected, or why neither
    holds the robot, in words a first-year student can act on."""
    prompt = state.prompt
    assert prompt is not None
    refused: list[tuple[str, InvalidInputError]] = []
    for name in DH_CONVENTIONS:
        try:
            to_dh(state.robot, name)
        except InvalidInputError as error:
            refused.append((name, error))
    if not refused:
        return f"Both DH conventions hold this robot; {prompt.convention} DH is chosen."
    if len(refused) == len(DH_CONVENTIONS):
        return dh_refusal(refused[0][1])
    name, refusal = refused[0]
    return f"{prompt.convention.capitalize()} DH is chosen: in {name} DH, " + dh_refusal(refusal)


def dh_refusal(error: InvalidInputError) -> str:
    """The core's reason why a module robot is no DH table, as one sentence about the
    module (named as the editor names it, M1, M2 …) and what to do about it.

    >>> import robotconf as rc
    >>> try:
    ...     to_dh(rc.preset("paper"), "standard")
    ... except InvalidInputError as error:
    ...     print(dh_refusal(error))
    M2 turns about the y axis, but a DH table has no y: every row turns/slides along z and
    twists about x. To use a DH table, start a new one and type in this arm's DH rows (lesson 5
    derives them), or change the modules so that every joint turns about z.
    """
    why = error.problem.rstrip(" :").removeprefix("module ")
    if "y axis" in why or "a joint that" in why:
        advice = (
            "To use a DH table, start a new one and type in this arm's DH rows (lesson 5 "
            "derives them), or change the modules so that every joint turns about z."
        )
    elif "convert_dh" in why:
        advice = "Convert the table's convention first (the DH table's selector)."
    else:
        advice = "Choose the other convention beside the question, or start a new DH table."
    return f"{why}. {advice}"


class HeaderView:
    """The header row as a form.

    Parameters
    ----------
    dispatch : callable
        ``dispatch(action, key)`` (see :class:`~robotconf.panel.editor.EditorView`).
    history : callable
        ``history()`` → ``(can_undo, can_redo)``.
    undo, redo : callable
        Go back and forth in the history.
    """

    def __init__(
        self,
        dispatch: Callable[..., None],
        history: Callable[[], tuple[bool, bool]],
        undo: Callable[[], None],
        redo: Callable[[], None],
    ) -> None:
        self._dispatch = dispatch
        self._history = history
        self._undo, self._redo = undo, redo
        self._state: PanelState | None = None
        self.form = Form(self._event, css_class="robotconf-header")

    def render(self, state: PanelState, feedback: Feedback, rev: str) -> None:
        """Show the state's preset, mode and units."""
        self._state = state
        can_undo, can_redo = self._history()
        units = state.units
        lengths = tuple(dict.fromkeys((*LENGTH_UNITS, units.length)))
        note = feedback.message
        controls: list[dict[str, Any]] = [
            button(
                "undo",
                "↶",
                title=f"undo the last change (up to {HISTORY_LIMIT} are kept)",
                disabled=not can_undo,
                css_class="robotconf-undo",
            ),
            button(
                "redo",
                "↷",
                title="redo the change just undone",
                disabled=not can_redo,
                css_class="robotconf-redo",
            ),
            select(
                "preset",
                preset_of(state.robot),
                PRESET_OPTIONS,
                label="preset",
                rev=rev,
                width="150px",
                note=message(note("preset")),
                css_class="robotconf-preset",
            ),
            toggle("mode", state.mode, MODE_OPTIONS, rev=rev, css_class="robotconf-mode"),
            toggle("angle_unit", units.degrees, _ANGLES, rev=rev, css_class="robotconf-angle-unit"),
            select(
                "length_unit",
                units.length,
                [(u, u) for u in lengths],
                label="length",
                rev=rev,
                width="72px",
                css_class="robotconf-length-unit",
                title="the unit of the robot's lengths, named in labels, tables and plots "
                "(lengths are not converted: robot files carry no unit)",
            ),
        ]
        rows = [row("header", controls, note=message(note("mode") or note("history")))]
        prompt = state.prompt
        if prompt is not None and prompt.kind == "to_dh":
            options = [(name, name) for name in DH_CONVENTIONS]
            rows.append(
                row(
                    "mode.dh",
                    [
                        text("Open the DH table:"),
                        button(
                            "mode.dh.convert",
                            "convert this robot to DH rows",
                            title="the same robot as a DH table, when its modules follow "
                            "the DH pattern",
                        ),
                        select(
                            "mode.dh.convention", prompt.convention, options, rev=rev, width="100px"
                        ),
                        button(
                            "mode.dh.new",
                            "start a new DH table",
                            title="one revolute row; undo brings the module robot back",
                        ),
                        button("mode.dh.cancel", "cancel", title="change nothing"),
                    ],
                    [text(dh_entry_note(state), tone="note", css_class="robotconf-dh-entry-note")],
                    box=True,
                    note=message(note("mode.dh")),
                    css_class="robotconf-prompt",
                )
            )
        self.form.show(rows)

    def _event(self, event: FormEvent) -> None:
        key = event.key
        if key == "undo":
            self._undo()
        elif key == "redo":
            self._redo()
        elif key == "preset":
            if event.value:  # "— preset —" is a reading, not a choice
                self._dispatch(act.LoadPreset(str(event.value)), "preset")
            else:
                self._dispatch(None, "preset")
        elif key == "mode":
            self._dispatch(act.ChooseMode(str(event.value)), "mode")
        elif key == "angle_unit":
            self._dispatch(act.SetAngleUnit(bool(event.value)), "angle_unit")
        elif key == "length_unit":
            self._dispatch(act.SetLengthUnit(str(event.value)), "length_unit")
        elif key == "mode.dh.convention":
            self._dispatch(act.SetPromptConvention(str(event.value)), "mode.dh")
        elif key == "mode.dh.convert" and self._state is not None:
            try:
                to_dh(self._state.robot, self._state.prompt.convention)  # type: ignore[union-attr]
            except InvalidInputError as error:
                self._dispatch(Refusal(dh_refusal(error)), "mode.dh")
                return
            self._dispatch(act.AnswerPrompt("convert"), "mode.dh")
        elif key.startswith("mode.dh."):
            self._dispatch(act.AnswerPrompt(key.rsplit(".", 1)[1]), "mode.dh")
