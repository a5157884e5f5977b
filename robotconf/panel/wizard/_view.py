"""Guided mode: the paper's questionnaire (Figure 12) as a step-by-step wizard.

Number of modules → for each module its movement type, offsets and coordinate → the end
effector → a summary. Each step has a one-line explanation and the module's transfer
matrix from the core's symbolic table: with symbols a_x, a_y, a_z on the type step, with
the offsets as typed on the offset and coordinate steps, and below it the numeric A_i at
the typed q. Both follow the boxes as the student types. The draft is
``state.wizard``; the 3D view and the header show the robot built so far. **Finish**
loads it into the module list; **Cancel** leaves the panel's robot as it was.
"""

from __future__ import annotations

import html
import math
from collections.abc import Callable
from functools import lru_cache
from typing import Any

import ipywidgets as widgets

from ..._errors import InvalidInputError
from ...kinematics import (
    AXIS_NAMES,
    JOINT_UNITS,
    MODULE_KINDS,
    MODULE_OFFSETS,
    Module,
    kind_axis,
    kind_joint_type,
)
from .. import actions as act
from .._feedback import Feedback
from .._ranges import length_scale, length_step
from ..editor import KIND_OPTIONS, Quantity
from ..form import Form, FormEvent, button, message, number, parse_number, row, select
from ..matrices import math_html
from ..state import MAX_WIZARD_MODULES, PanelState, WizardDraft
from ..support import preformatted
from ..viewport import end_effector_text

__all__ = ["WizardView", "KIND_EXPLANATIONS"]

#: How a joint moves by q, and what q then is, by joint type.
_MOTIONS = {
    "revolute": ("rotate by q about", "an angle"),
    "prismatic": ("slide by q along", "a length"),
}
#: What the movement types without a joint are.
_NO_JOINT = {
    "none": "The null module: an identity matrix, it changes nothing (an unused block).",
    "fixed": "A rigid offset a with no joint (a base or tool frame; not in the paper).",
}
_POINT = ("Px", "Py", "Pz")


def _explanation(kind: str) -> str:
    axis = kind_axis(kind)
    if axis is None:
        return _NO_JOINT[kind]
    motion = _MOTIONS[kind_joint_type(kind)][0]
    return (
        f"Shift by a in the previous frame, then {motion} the module's own {AXIS_NAMES[axis]} axis."
    )


#: One line per movement type, as a teacher would say it.
KIND_EXPLANATIONS = {kind: _explanation(kind) for kind in MODULE_KINDS}


@lru_cache(maxsize=64)
def formula(kind: str, index: int, a: tuple[float, float, float] | None) -> str:
    """``A_i`` from the core's symbolic table as display math, with symbols or the offsets.

    >>> "A_{1}" in formula("Rz", 1, None)
    True
    """
    import sympy

    from ...teaching import exact_number, module_matrix

    q = sympy.Symbol(f"q{index}", real=True)
    if a is None:
        offsets = sympy.symbols([f"a_{axis}" for axis in AXIS_NAMES], real=True)
    else:
        offsets = tuple(exact_number(v) for v in a)
    return math_html(f"A_{{{index}}} = {sympy.latex(module_matrix(kind, q, offsets))}")


def numeric(module: Module, index: int, degrees: bool) -> str:
    """The module's matrix at its typed q, as aligned text (q in the unit it was typed in)."""
    from ...teaching import format_number, matrix_grid

    if module.is_joint:
        q = format_number(module.q, 6)
        if module.unit == "rad":
            q = f"{format_number(math.degrees(module.q), 6)}°" if degrees else f"{q} rad"
        title = f"A_{index} at q{index} = {q}:"
    else:
        title = f"A_{index} =  (q{index} is ignored)"
    return preformatted("\n".join([title, *matrix_grid(module.matrix(), False, 4)]))


class WizardView:
    """The questionnaire: a title, the question, its answers, the matrix so far.

    Parameters
    ----------
    dispatch : callable
        ``dispatch(action, key, typed=None)``.
    formulas : bool
        Show the symbolic A_i (sympy); ``False`` skips it.
    """

    def __init__(self, dispatch: Callable[..., None], formulas: bool = True) -> None:
        self._dispatch = dispatch
        self.formulas = formulas
        self._state: PanelState | None = None
        self.title = widgets.HTML()
        self.title.add_class("robotconf-wizard-title")
        self.explanation = widgets.HTML()
        self.form = Form(self._event, css_class="robotconf-wizard-form")
        self.formula = widgets.HTMLMath()
        self.preview = widgets.HTML()
        self.preview.add_class("robotconf-wizard-preview")
        self.widget = widgets.VBox(
            [self.title, self.explanation, self.form, self.formula, self.preview],
            layout=widgets.Layout(border="1px solid #ccd", padding="6px"),
        )
        self.widget.add_class("robotconf-wizard")

    def render(self, state: PanelState, feedback: Feedback, rev: str) -> None:
        """Show the draft's current question."""
        self._state = state
        draft = state.wizard
        if draft is None:
            return
        steps = draft.steps()
        part, i = steps[draft.step]
        self.title.value = f"<b>Step {draft.step + 1} of {len(steps)}</b>"
        answers: list[dict[str, Any]] = []
        formula_html, preview = "", ""
        units = state.units
        scale = length_scale(state.robot)
        length = Quantity("length", units, length_step(scale))
        if part == "count":
            question = "How many modules (kinematic couples) does the robot have?"
            answers.append(
                self._number(
                    feedback,
                    "wizard.count",
                    float(draft.count),
                    Quantity("", units, 1.0),
                    "modules",
                    rev,
                )
            )
        elif part in ("type", "a", "q"):
            module = draft.answers(i)
            kind = module.kind
            if part == "type":
                question = f"Module {i + 1}: which movement? {KIND_EXPLANATIONS[kind]}"
                answers.append(
                    select(
                        f"wizard.modules[{i}].kind",
                        kind,
                        KIND_OPTIONS,
                        label="type",
                        rev=rev,
                        width="110px",
                        css_class="robotconf-wizard-kind",
                    )
                )
                formula_html = self._formula(kind, i + 1, None)
            elif part == "a":
                question = (
                    f"Module {i + 1} ({kind}): where is its frame origin in the previous frame? "
                    "These are the offsets a = (ax, ay, az)."
                )
                for axis, name in enumerate(MODULE_OFFSETS):
                    answers.append(
                        self._number(
                            feedback,
                            f"wizard.modules[{i}].{name}",
                            module.a[axis],
                            length,
                            name,
                            rev,
                            css_class="robotconf-wizard-offset",
                        )
                    )
            else:
                joint = kind_joint_type(kind)
                what = _MOTIONS[joint][1] if joint in _MOTIONS else "ignored by this type"
                question = (
                    f"Module {i + 1} ({kind}): its coordinate q, {what} (0 = parking position)."
                )
                quantity = Quantity(JOINT_UNITS[joint], units, length_step(scale))
                answers.append(
                    self._number(
                        feedback,
                        f"wizard.modules[{i}].q",
                        module.q,
                        quantity,
                        "q",
                        rev,
                        css_class="robotconf-wizard-q",
                    )
                )
            if part in ("a", "q"):
                formula_html = self._formula(kind, i + 1, module.a)
                try:
                    preview = numeric(module.module(), i + 1, units.degrees)
                except InvalidInputError:
                    preview = ""
        elif part == "end_effector":
            question = "The end-effector point P in the last module's frame: p_EE = M_n·[P, 1]ᵀ."
            for axis, name in enumerate(_POINT):
                answers.append(
                    self._number(
                        feedback,
                        f"wizard.end_effector.{name}",
                        draft.end_effector[axis],
                        length,
                        name,
                        rev,
                        css_class="robotconf-wizard-point",
                    )
                )
        else:
            question = "The robot you described (Finish loads it into the module list):"
            preview = self._summary(draft)
        self.explanation.value = html.escape(question, quote=False)
        self.formula.value = formula_html
        self.preview.value = preview
        navigation = [
            button(
                "wizard.back", "← Back", disabled=draft.step == 0, css_class="robotconf-wizard-back"
            ),
            button(
                "wizard.next",
                "Finish" if part == "summary" else "Next →",
                style="primary",
                css_class="robotconf-wizard-next",
            ),
            button(
                "wizard.cancel",
                "✕ Cancel",
                title="leave the guided mode; the robot stays as it was",
                css_class="robotconf-wizard-cancel",
            ),
        ]
        self.form.show(
            [
                row("wizard.answers", answers) if answers else row("wizard.answers", []),
                row("wizard", navigation, note=message(feedback.message("wizard"))),
            ]
        )

    def _number(
        self,
        feedback: Feedback,
        key: str,
        core: float,
        quantity: Quantity,
        label: str,
        rev: str,
        css_class: str = "",
    ) -> dict[str, Any]:
        error = feedback.message(key)
        return number(
            key,
            quantity.shown(core),
            0.0,
            0.0,
            quantity.step,
            label=label,
            unit=quantity.label,
            slider=False,
            rev=rev,
            live=True,
            width="90px",
            text=feedback.typed(key) if error else None,
            note=message(error),
            css_class=css_class,
        )

    def _formula(self, kind: str, index: int, a: Any) -> str:
        if not self.formulas:
            return ""
        try:
            return formula(kind, index, None if a is None else tuple(float(v) for v in a))
        except InvalidInputError:
            return ""

    @staticmethod
    def _summary(draft: WizardDraft) -> str:
        try:
            robot = draft.built()
        except InvalidInputError as error:
            return f"<span style='color:#c62828'>{html.escape(str(error))}</span>"
        text_ = f"{robot}\n\n{end_effector_text(robot.at().end_effector)}"
        summary = preformatted(text_)
        return f"<div class='robotconf-wizard-summary'>{summary}</div>"

    # -- input --------------------------------------------------------------------------

    def _event(self, event: FormEvent) -> None:
        state = self._state
        if state is None or state.wizard is None:
            return
        key = event.key
        live = event.event == "typing"
        typed = event.text if event.event == "type" else None
        try:
            action = self._action(state, event)
        except InvalidInputError as error:
            if not live:  # text being typed that is no number yet ("-", "1e") is no mistake
                self._dispatch(error, key, typed)
            return
        if action is not None:
            self._dispatch(action, "wizard" if key in _BUTTONS else key, typed, quiet=live)

    def _action(self, state: PanelState, event: FormEvent) -> Any:
        key = event.key
        if key in _BUTTONS:
            return _BUTTONS[key]()
        if key == "wizard.count":
            value = _read(event, "count")
            if value != int(value):
                raise InvalidInputError(
                    "count", value, f"a whole number from 1 to {MAX_WIZARD_MODULES}"
                )
            return act.WizardSetCount(int(value))
        if key.startswith("wizard.end_effector."):
            axis = _POINT.index(key.rsplit(".", 1)[1])
            return act.WizardSetPoint(axis, _read(event, _POINT[axis]))
        inside = key[len("wizard.modules[") :]
        index, field = int(inside.split("]")[0]), inside.split("].")[1]
        if field == "kind":
            return act.WizardSetKind(index, str(event.value))
        if field == "q":
            kind = state.wizard.answers(index).kind  # type: ignore[union-attr]
            unit = JOINT_UNITS[kind_joint_type(kind)]
            return act.WizardSetQ(index, state.units.to_core(_read(event, "q"), unit))
        axis = MODULE_OFFSETS.index(field)
        return act.WizardSetOffset(index, axis, _read(event, field))


_BUTTONS: dict[str, Callable[[], act.Action]] = {
    "wizard.back": act.WizardBack,
    "wizard.next": act.WizardNext,
    "wizard.cancel": act.WizardCancel,
}


def _read(event: FormEvent, field: str) -> float:
    if event.event == "drag":
        return float(event.value)
    return parse_number(event.text or "", field)
