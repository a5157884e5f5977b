"""Switching how the robot is edited: modules, DH table, guided mode; and the questions
the panel asks before it converts (never a silent swap of the robot).

- DH table → modules converts with the core's ``dh_to_modules`` (the same robot).
- Modules → DH table asks (:class:`~robotconf.panel.state.Prompt` ``"to_dh"``): convert
  the robot to DH rows in the convention chosen beside the question, or start a new DH
  table.
- Standard ⇄ modified in the DH table asks (``"convention"``): convert (the same robot)
  or reinterpret (the same numbers, another robot).
- The guided mode opens a fresh draft (:mod:`robotconf.panel.actions._wizard`).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..._errors import InvalidInputError
from ...kinematics import DH_CONVENTIONS, DHLink, Robot, reinterpret_dh
from .._ranges import length_scale
from ..state import PanelState, Prompt, WizardDraft
from ._base import Action, with_robot
from ._conversions import to_convention, to_dh, to_modules

__all__ = [
    "ChooseMode",
    "ChooseConvention",
    "SetPromptConvention",
    "AnswerPrompt",
    "MODES",
    "preselected",
]

#: The header's editing modes.
MODES = ("modules", "dh", "wizard")
_ANSWERS = {
    "to_dh": ("convert", "new", "cancel"),
    "convention": ("convert", "reinterpret", "cancel"),
}


def preselected(robot: Robot, first: str = DH_CONVENTIONS[0]) -> str:
    """The convention the modules → DH question preselects: ``first`` when it holds the
    robot, else the other one when that does, else ``first`` (convert then says why).

    >>> import robotconf as rc
    >>> arm = rc.Robot([rc.Module("Rz", a=(0, 0, 20)), rc.Module("Rz", a=(30, 0, 0))])
    >>> preselected(arm)  # an offset before M2's joint: only modified DH holds it
    'modified'
    """
    for candidate in (first, *(c for c in DH_CONVENTIONS if c != first)):
        try:
            to_dh(robot, candidate)
        except InvalidInputError:
            continue
        return candidate
    return first


@dataclass(frozen=True)
class ChooseMode(Action):
    """Pick an editing mode in the header: ``"modules"``, ``"dh"`` or ``"wizard"``.

    >>> import robotconf as rc
    >>> state = ChooseMode("dh").apply(PanelState.start(rc.preset("paper")))
    >>> state.mode, state.prompt  # the robot stays until the question is answered
    ('modules', Prompt(kind='to_dh', convention='standard'))
    """

    mode: str

    def apply(self, state: PanelState) -> PanelState:
        if self.mode not in MODES:
            raise InvalidInputError("mode", self.mode, ", ".join(MODES))
        if self.mode == "wizard":
            if state.wizard is not None:
                return state
            return state.replace(wizard=WizardDraft(), prompt=None)
        closed = state.replace(wizard=None, prompt=None)
        if self.mode == state.editor:
            return closed
        if self.mode == "modules":
            return with_robot(closed, *to_modules(state.robot))
        return closed.replace(prompt=Prompt("to_dh", preselected(state.robot)))


@dataclass(frozen=True)
class ChooseConvention(Action):
    """Pick the other DH convention in the DH table: the panel asks what it means."""

    convention: str

    def apply(self, state: PanelState) -> PanelState:
        if self.convention not in DH_CONVENTIONS:
            raise InvalidInputError("convention", self.convention, ", ".join(DH_CONVENTIONS))
        current = state.robot.modules[0]
        if isinstance(current, DHLink) and current.convention == self.convention:
            return state.replace(prompt=None)
        return state.replace(prompt=Prompt("convention", self.convention))


@dataclass(frozen=True)
class SetPromptConvention(Action):
    """The convention chosen beside the modules → DH question."""

    convention: str

    def apply(self, state: PanelState) -> PanelState:
        if state.prompt is None or state.prompt.kind != "to_dh":
            return state
        if self.convention not in DH_CONVENTIONS:
            raise InvalidInputError("convention", self.convention, ", ".join(DH_CONVENTIONS))
        return state.replace(prompt=Prompt("to_dh", self.convention))


@dataclass(frozen=True)
class AnswerPrompt(Action):
    """Answer the open question: ``"convert"``, ``"new"`` (a new DH table),
    ``"reinterpret"`` (the same numbers in the other convention) or ``"cancel"``.

    A conversion the core refuses raises its message (naming the module and why); the
    question stays open.
    """

    answer: str

    def apply(self, state: PanelState) -> PanelState:
        prompt = state.prompt
        if prompt is None:
            return state
        if self.answer not in _ANSWERS[prompt.kind]:
            raise InvalidInputError("answer", self.answer, ", ".join(_ANSWERS[prompt.kind]))
        robot = state.robot
        if self.answer == "cancel":
            return state.replace(prompt=None)
        if prompt.kind == "to_dh" and self.answer == "convert":
            return with_robot(state, *to_dh(robot, prompt.convention))
        if prompt.kind == "to_dh":
            # One revolute row, a tenth of the robot's size long: visible at its scale.
            row = DHLink(a=length_scale(robot) / 10.0, convention=prompt.convention)
            return with_robot(state, Robot([row], end_effector=robot.end_effector_point), [None])
        if self.answer == "convert":
            return with_robot(state, *to_convention(robot, prompt.convention))
        return with_robot(state, reinterpret_dh(robot, prompt.convention).with_name(None))
