"""Guided mode: the paper's questionnaire (Figure 12) as a step-by-step wizard.

Number of modules → for each module its movement type, geometric parameters and
coordinate → the end-effector → a summary. Each step has a one-line explanation and the
module's transfer matrix as a formula (from the core's symbolic table). "Finish" hands
the robot to the list editor, so both modes end in the same robot.
"""

from __future__ import annotations

import html
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
from ._number_control import NumberControl
from ._ranges import q_display

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


class _ModuleAnswers:
    """The answers about one module."""

    def __init__(self, degrees: bool, scale: float):
        self.kind = widgets.Dropdown(options=KIND_OPTIONS, value="Rz", description="type")
        self.offsets = [NumberControl(n, 0.0, -scale, scale, slider=False) for n in MODULE_OFFSETS]
        self.q = NumberControl("q", 0.0, -180, 180, angle=True, degrees=degrees, slider=False)

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

    Examples
    --------
    >>> built = []
    >>> wizard = Wizard(built.append, formulas=False)
    >>> wizard.count.value = 1
    >>> wizard.next()  # → type of module 1
    >>> wizard.answers[0].kind.value = "Tz"
    >>> for _ in range(4):  # geometry, coordinate, end-effector, summary
    ...     wizard.next()
    >>> wizard.next()  # Finish
    >>> built[0].modules
    (Module('Tz'),)
    """

    def __init__(
        self,
        on_finish: Callable[[Robot], None],
        degrees: bool = True,
        scale: float = 100.0,
        formulas: bool = True,
    ):
        self._on_finish = on_finish
        self.degrees = degrees
        self._scale = scale
        self.formulas = formulas
        self.count = widgets.BoundedIntText(
            value=3, min=1, max=_MAX_MODULES, description="modules", layout={"width": "160px"}
        )
        self.answers: list[_ModuleAnswers] = []
        self.end_effector = [
            NumberControl(n, 0.0, -scale, scale, slider=False) for n in ("Px", "Py", "Pz")
        ]
        self.step = 0
        self.title = widgets.HTML()
        self.explanation = widgets.HTML()
        self.formula = widgets.HTMLMath()
        self.body = widgets.VBox()
        self.error = ErrorLabel()
        self.back_button = widgets.Button(description="Back", icon="arrow-left")
        self.next_button = widgets.Button(description="Next", icon="arrow-right")
        on_click(self.back_button, self.error, self.back)
        on_click(self.next_button, self.error, self.next)
        self.robot: Robot | None = None
        self.widget = widgets.VBox(
            [
                self.title,
                self.explanation,
                self.body,
                self.formula,
                self.error.widget,
                widgets.HBox([self.back_button, self.next_button]),
            ],
            layout=widgets.Layout(border="1px solid #ccd", padding="6px"),
        )
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
            answers = _ModuleAnswers(self.degrees, self._scale)
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
                self._show_formula(kind, i + 1, [c.core_value for c in answers.offsets])
            else:
                joint_type = kind_joint_type(kind)
                unit = _MOTIONS[joint_type][1] if joint_type in _MOTIONS else "ignored by this type"
                angle, label = q_display(JOINT_UNITS[joint_type])
                answers.q.set_angle(angle, -180, 180, unit=label)
                text = f"Module {i + 1} ({kind}): its coordinate q, {unit} (0 = parking position)."
                self._say(text, [answers.q.widget])
                self._show_formula(kind, i + 1, [c.core_value for c in answers.offsets])
            return
        if part == "end_effector":
            text = "The end-effector point P in the last module's frame: p_EE = M_n·[P, 1]ᵀ."
            self._say(text, [c.widget for c in self.end_effector])
            return
        robot = self._build()
        text = "" if robot is None else f"{robot}\n\n{end_effector_text(robot)}"
        summary = f"<pre>{html.escape(text)}</pre>" if text else ""
        self._say("The robot you described (Finish loads it into the module list):", [])
        self.body.children = (widgets.HTML(summary),)

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

    # -- navigation ---------------------------------------------------------------------

    def _check(self) -> bool:
        part, i = self._steps()[self.step]
        controls: list[tuple[str, NumberControl]] = []
        if part == "a":
            controls = list(zip(MODULE_OFFSETS, self.answers[i].offsets, strict=True))
        elif part == "q":
            controls = [("q", self.answers[i].q)]
        elif part == "end_effector":
            controls = list(zip(("Px", "Py", "Pz"), self.end_effector, strict=True))
        for field, control in controls:
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

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)``: ``wizard`` and ``wizard.<field>`` of the visible step."""
        yield "wizard", self.error
        for i, answers in enumerate(self.answers):
            for name, control in zip(MODULE_OFFSETS, answers.offsets, strict=True):
                yield f"wizard.modules[{i}].{name}", control.error
            yield f"wizard.modules[{i}].q", answers.q.error
        for name, control in zip(("Px", "Py", "Pz"), self.end_effector, strict=True):
            yield f"wizard.end_effector.{name}", control.error
