"""Guided mode: the paper's questionnaire (Figure 12) as a step-by-step wizard.

Number of modules → for each module its movement type, geometric parameters and
coordinate → the end-effector → a summary. Each step has a one-line explanation and the
module's transfer matrix as a formula (from the core's symbolic table): the type step
shows it with symbols a_x, a_y, a_z; the offset and coordinate steps with the offsets as
typed, and below it the numeric matrix at the typed q. Both follow every field as it
changes. The robot built so far is previewed (``on_preview``, the panel's 3D scene), and
"Cancel" leaves without changing the robot. "Finish" hands the robot to the list editor,
so both modes end in the same robot.
"""

from __future__ import annotations

import html
import math
from collections.abc import Callable, Iterator
from typing import Any

import ipywidgets as widgets

from .._errors import InvalidInputError
from .._validation import check_finite_number
from ..kinematics import (
    AXIS_NAMES,
    JOINT_UNITS,
    MODULE_KINDS,
    MODULE_OFFSETS,
    Module,
    Robot,
    kind_axis,
    kind_joint_type,
)
from ._callbacks import observe, on_click
from ._errors_display import ErrorLabel
from ._matrices_view import end_effector_text, math_html
from ._module_row import KIND_OPTIONS
from ._monospace import preformatted
from ._number_control import NumberControl
from ._ranges import ANGLE_UNIT, length_step, q_display

__all__ = ["Wizard", "KIND_EXPLANATIONS"]

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
_MAX_MODULES = 12


def _formula(kind: str, index: int, a: Any = None) -> str:
    """``A_i`` from the core's symbolic table as display math, with symbols or the offsets."""
    import sympy

    from ..teaching import exact_number, module_matrix

    q = sympy.Symbol(f"q{index}", real=True)
    if a is None:
        offsets = sympy.symbols([f"a_{axis}" for axis in AXIS_NAMES], real=True)
    else:
        offsets = tuple(exact_number(v) for v in a)
    return math_html(f"A_{{{index}}} = {sympy.latex(module_matrix(kind, q, offsets))}")


def _numeric(module: Module, index: int, degrees: bool) -> str:
    """The module's matrix at its typed q, as aligned text (q in the unit it was typed in)."""
    from ..teaching import format_number, matrix_grid

    if module.is_joint:
        q = format_number(module.q, 6)
        if module.unit == ANGLE_UNIT:
            q = f"{format_number(math.degrees(module.q), 6)}°" if degrees else f"{q} rad"
        title = f"A_{index} at q{index} = {q}:"
    else:
        title = f"A_{index} =  (q{index} is ignored)"
    return preformatted("\n".join([title, *matrix_grid(module.matrix(), False, 4)]))


class _ModuleAnswers:
    """The answers about one module; ``on_change`` after a user edit of any of them."""

    def __init__(self, degrees: bool, scale: float, on_change: Callable[[Any], None]):
        self.kind = widgets.Dropdown(options=KIND_OPTIONS, value="Rz", description="type")
        step = length_step(scale)
        self.offsets = [
            NumberControl(
                n, 0.0, -scale, scale, slider=False, on_change=on_change, length_step=step
            )
            for n in MODULE_OFFSETS
        ]
        self.q = NumberControl(
            "q",
            0.0,
            -180,
            180,
            angle=True,
            degrees=degrees,
            slider=False,
            on_change=on_change,
            length_step=step,
        )

        # Stable hooks for browser tests and for instructors' custom CSS.
        self.kind.add_class("robotconf-wizard-kind")
        for control in self.offsets:
            control.box.add_class("robotconf-wizard-offset")
        self.q.box.add_class("robotconf-wizard-q")

    def module(self) -> Module:
        ax, ay, az = (c.core_value for c in self.offsets)
        return Module(self.kind.value, (ax, ay, az), self.q.core_value)


class Wizard:
    """Step-by-step robot builder.

    Parameters
    ----------
    on_finish : callable
        Receives the finished :class:`~robotconf.Robot`.
    degrees : bool
        Ask for angles in degrees.
    scale : float
        Typical length, for the number boxes' steps.
    formulas : bool
        Show the symbolic A_i (sympy); ``False`` skips it.
    on_preview : callable, optional
        Receives the robot built so far after every step and field change, or ``None``
        when there is nothing to show yet (the first question).
    on_cancel : callable, optional
        Called by the Cancel button (without it, the button is disabled).

    Examples
    --------
    >>> built = []
    >>> wizard = Wizard(built.append, formulas=False)
    >>> wizard.count.value = 1
    >>> wizard.next()  # → type of module 1
    >>> wizard.answers[0].kind.value = "Tz"
    >>> wizard.next()  # geometry: the numeric A_1 follows the boxes
    >>> wizard.answers[0].offsets[2].box.value = 20.0
    >>> "[ 1  0  0   0 ]" in wizard.preview.value, "20 ]" in wizard.preview.value
    (True, True)
    >>> for _ in range(3):  # coordinate, end-effector, summary
    ...     wizard.next()
    >>> wizard.next()  # Finish
    >>> built[0].modules
    (Module('Tz', a=(0.0, 0.0, 20.0)),)
    """

    def __init__(
        self,
        on_finish: Callable[[Robot], None],
        degrees: bool = True,
        scale: float = 100.0,
        formulas: bool = True,
        on_preview: Callable[[Robot | None], None] | None = None,
        on_cancel: Callable[[], None] | None = None,
    ):
        self._on_finish = on_finish
        self._on_preview = on_preview
        self.degrees = degrees
        self._scale = scale
        self.formulas = formulas
        self.count = widgets.BoundedIntText(
            value=3, min=1, max=_MAX_MODULES, description="modules", layout={"width": "160px"}
        )
        self.answers: list[_ModuleAnswers] = []
        self.end_effector = [
            NumberControl(
                n,
                0.0,
                -scale,
                scale,
                slider=False,
                on_change=self._field_changed,
                length_step=length_step(scale),
            )
            for n in ("Px", "Py", "Pz")
        ]
        self.step = 0
        self.title = widgets.HTML()
        self.title.add_class("robotconf-wizard-title")
        self.explanation = widgets.HTML()
        self.formula = widgets.HTMLMath()
        self.preview = widgets.HTML()
        self.preview.add_class("robotconf-wizard-preview")
        self.body = widgets.VBox()
        self.error = ErrorLabel()
        self.back_button = widgets.Button(description="Back", icon="arrow-left")
        self.next_button = widgets.Button(description="Next", icon="arrow-right")
        self.cancel_button = widgets.Button(
            description="Cancel",
            icon="times",
            tooltip="leave the guided mode; the robot stays as it was",
            disabled=on_cancel is None,
        )
        # Stable hooks for browser tests and for instructors' custom CSS.
        self.count.add_class("robotconf-wizard-count")
        for control in self.end_effector:
            control.box.add_class("robotconf-wizard-point")
        for button, name in (
            (self.back_button, "back"),
            (self.next_button, "next"),
            (self.cancel_button, "cancel"),
        ):
            button.add_class(f"robotconf-wizard-{name}")
        on_click(self.back_button, self.error, self.back)
        on_click(self.next_button, self.error, self.next)
        if on_cancel is not None:
            on_click(self.cancel_button, self.error, on_cancel)
        self.robot: Robot | None = None
        self.widget = widgets.VBox(
            [
                self.title,
                self.explanation,
                self.body,
                self.formula,
                self.preview,
                self.error.widget,
                widgets.HBox([self.back_button, self.next_button, self.cancel_button]),
            ],
            layout=widgets.Layout(border="1px solid #ccd", padding="6px"),
        )
        self.widget.add_class("robotconf-wizard")
        self._show()

    # -- steps --------------------------------------------------------------------------

    def _steps(self) -> list[tuple[str, int]]:
        per_module = [(part, i) for i in range(self.count.value) for part in ("type", "a", "q")]
        return [("count", 0), *per_module, ("end_effector", 0), ("summary", 0)]

    @property
    def step_name(self) -> str:
        """``"count"``, ``"type"``, ``"a"``, ``"q"``, ``"end_effector"`` or ``"summary"``."""
        return self._steps()[self.step][0]

    def _fit_answers(self) -> None:
        while len(self.answers) < self.count.value:
            answers = _ModuleAnswers(self.degrees, self._scale, self._field_changed)
            observe(answers.kind, self.error, lambda _: self._show())
            self.answers.append(answers)
        del self.answers[self.count.value :]

    def _show(self) -> None:
        steps = self._steps()
        part, i = steps[self.step]
        self.title.value = f"<b>Step {self.step + 1} of {len(steps)}</b>"
        self.back_button.disabled = self.step == 0
        self.next_button.description = "Finish" if part == "summary" else "Next"
        self.formula.value = ""
        self.preview.value = ""
        self._preview()
        if part == "count":
            self._say("How many modules (kinematic couples) does the robot have?", [self.count])
            return
        if part in ("type", "a", "q"):
            answers = self.answers[i]
            kind = answers.kind.value
            if part == "type":
                text = f"Module {i + 1}: which movement? {KIND_EXPLANATIONS[kind]}"
                self._say(text, [answers.kind])
                self._show_formula(kind, i + 1, None)
            elif part == "a":
                text = (
                    f"Module {i + 1} ({kind}): where is its frame origin in the previous "
                    "frame? These are the offsets a = (ax, ay, az)."
                )
                self._say(text, [c.widget for c in answers.offsets])
                self._show_matrices(i)
            else:
                joint_type = kind_joint_type(kind)
                unit = _MOTIONS[joint_type][1] if joint_type in _MOTIONS else "ignored by this type"
                angle, label = q_display(JOINT_UNITS[joint_type])
                answers.q.set_angle(angle, -180, 180, unit=label)
                text = f"Module {i + 1} ({kind}): its coordinate q, {unit} (0 = parking position)."
                self._say(text, [answers.q.widget])
                self._show_matrices(i)
            return
        if part == "end_effector":
            text = "The end-effector point P in the last module's frame: p_EE = M_n·[P, 1]ᵀ."
            self._say(text, [c.widget for c in self.end_effector])
            return
        robot = self._build()
        text = "" if robot is None else f"{robot}\n\n{end_effector_text(robot)}"
        summary = preformatted(text) if text else ""
        self._say("The robot you described (Finish loads it into the module list):", [])
        shown = widgets.HTML(summary)
        shown.add_class("robotconf-wizard-summary")
        self.body.children = (shown,)

    def _say(self, text: str, controls: list[widgets.Widget]) -> None:
        self.explanation.value = html.escape(text, quote=False)
        self.body.children = tuple(controls)

    def _show_formula(self, kind: str, index: int, a: Any) -> None:
        if not self.formulas:
            return
        try:
            self.formula.value = _formula(kind, index, a)
        except InvalidInputError:
            self.formula.value = ""  # a bad offset: the error label says why

    def _show_matrices(self, i: int) -> None:
        """A_i with the offsets as typed, and its numbers at the typed q."""
        answers = self.answers[i]
        self._show_formula(answers.kind.value, i + 1, [c.core_value for c in answers.offsets])
        try:
            self.preview.value = _numeric(answers.module(), i + 1, self.degrees)
        except InvalidInputError:
            self.preview.value = ""  # a bad value: its own label says why

    def _field_changed(self, _: Any = None) -> None:
        for _field, control in self._step_controls():
            if math.isfinite(control.core_value):
                control.error.clear()  # refused by Next, fixed since: the message goes
        part, i = self._steps()[self.step]
        if part in ("a", "q") and i < len(self.answers):
            self._show_matrices(i)
        self._preview()

    def _preview(self) -> None:
        """Hand the robot built so far to ``on_preview`` (nothing while a value is bad)."""
        if self._on_preview is None:
            return
        part, i = self._steps()[self.step]
        if part == "count" or not self.answers:
            self._on_preview(None)
            return
        count = i + 1 if part in ("type", "a", "q") else len(self.answers)
        try:
            modules = [answers.module() for answers in self.answers[:count]]
            point = (
                [c.core_value for c in self.end_effector]
                if part in ("end_effector", "summary")
                else (0.0, 0.0, 0.0)
            )
            robot = Robot(modules, end_effector=point)
        except InvalidInputError:
            return  # the field's own label says why; the last preview stays
        self._on_preview(robot)

    # -- navigation ---------------------------------------------------------------------

    def _step_controls(self) -> list[tuple[str, NumberControl]]:
        """``(field, control)`` for the number boxes of the step shown."""
        part, i = self._steps()[self.step]
        if part == "a":
            return list(zip(MODULE_OFFSETS, self.answers[i].offsets, strict=True))
        if part == "q":
            return [("q", self.answers[i].q)]
        if part == "end_effector":
            return list(zip(("Px", "Py", "Pz"), self.end_effector, strict=True))
        return []

    def _check(self) -> bool:
        for field, control in self._step_controls():
            try:
                check_finite_number(control.core_value, field)
                control.error.clear()
            except InvalidInputError as error:
                control.error.show(str(error))
                return False
        return True

    def _build(self) -> Robot | None:
        try:
            modules = [answers.module() for answers in self.answers]
            point = [c.core_value for c in self.end_effector]
            robot = Robot(modules, end_effector=point)
        except InvalidInputError as error:
            self.error.show(str(error))
            return None
        self.error.clear()
        return robot

    def next(self) -> None:
        """Check the current answer and go on; on the summary, finish."""
        if not self._check():
            return
        if self.step_name == "summary":
            robot = self._build()
            if robot is not None:
                self.robot = robot
                self._on_finish(robot)
            return
        if self.step_name == "count":
            self._fit_answers()
        self.step += 1
        self._show()

    def back(self) -> None:
        """Go to the previous question (answers are kept)."""
        if self.step > 0:
            self.step -= 1
            self._show()

    def restart(self) -> None:
        """Start again from the first question, keeping the answers as defaults."""
        self.step = 0
        self._show()

    def set_degrees(self, degrees: bool) -> None:
        """Ask for angles in degrees or radians."""
        self.degrees = degrees
        for answers in self.answers:
            answers.q.set_degrees(degrees)
        self._field_changed()  # the preview's q in the new unit

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)``: ``wizard`` and ``wizard.<field>`` of the visible step."""
        yield "wizard", self.error
        for i, answers in enumerate(self.answers):
            for name, control in zip(MODULE_OFFSETS, answers.offsets, strict=True):
                yield f"wizard.modules[{i}].{name}", control.error
            yield f"wizard.modules[{i}].q", answers.q.error
        for name, control in zip(("Px", "Py", "Pz"), self.end_effector, strict=True):
            yield f"wizard.end_effector.{name}", control.error
