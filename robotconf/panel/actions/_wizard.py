"""The guided mode: answering the questionnaire, stepping through it, Finish and Cancel.

The answers change only the draft (``state.wizard``); **Finish** loads the robot they
describe into the module list (one undo step), **Cancel** drops the draft and leaves the
panel's robot as it was.
"""

from __future__ import annotations

from collections.abc import Hashable
from dataclasses import dataclass, replace

from ..._errors import InvalidInputError
from ..._validation import check_integer
from ...kinematics import MODULE_OFFSETS, check_parameter, kind_name
from ..state import MAX_WIZARD_MODULES, PanelState, WizardDraft
from ._base import Action, with_robot

__all__ = [
    "WizardSetCount",
    "WizardSetKind",
    "WizardSetOffset",
    "WizardSetQ",
    "WizardSetPoint",
    "WizardNext",
    "WizardBack",
    "WizardCancel",
]

_POINT = ("Px", "Py", "Pz")


def _draft(state: PanelState) -> WizardDraft:
    if state.wizard is None:
        raise InvalidInputError("wizard", "closed", "the guided mode open (choose Guided)")
    return state.wizard


def _with(state: PanelState, draft: WizardDraft) -> PanelState:
    return state.replace(wizard=draft)


@dataclass(frozen=True)
class WizardSetCount(Action):
    """How many modules the robot has, 1 … 12."""

    count: int

    def apply(self, state: PanelState) -> PanelState:
        allowed = f"an integer from 1 to {MAX_WIZARD_MODULES}"
        count = check_integer(self.count, "count", 1, MAX_WIZARD_MODULES, allowed)
        return _with(state, replace(_draft(state), count=count))


@dataclass(frozen=True)
class WizardSetKind(Action):
    """Module ``index``'s movement type (``"Rz"``, code or name)."""

    index: int
    kind: str

    def apply(self, state: PanelState) -> PanelState:
        draft = _draft(state)
        return _with(state, draft.with_answers(self.index, kind=kind_name(self.kind)))


@dataclass(frozen=True)
class WizardSetOffset(Action):
    """Module ``index``'s offset ``axis`` (0, 1, 2: ax, ay, az), length units."""

    index: int
    axis: int
    value: float

    def apply(self, state: PanelState) -> PanelState:
        draft = _draft(state)
        value = check_parameter(self.value, MODULE_OFFSETS[self.axis])
        a = list(draft.answers(self.index).a)
        a[self.axis] = value
        return _with(state, draft.with_answers(self.index, a=tuple(a)))

    @property
    def gesture(self) -> Hashable:
        return ("wizard", self.index, self.axis)


@dataclass(frozen=True)
class WizardSetQ(Action):
    """Module ``index``'s coordinate (radians or length units)."""

    index: int
    value: float

    def apply(self, state: PanelState) -> PanelState:
        draft = _draft(state)
        return _with(state, draft.with_answers(self.index, q=check_parameter(self.value, "q")))


@dataclass(frozen=True)
class WizardSetPoint(Action):
    """Component ``axis`` of the end-effector point P (length units)."""

    axis: int
    value: float

    def apply(self, state: PanelState) -> PanelState:
        draft = _draft(state)
        point = list(draft.end_effector)
        point[self.axis] = check_parameter(self.value, _POINT[self.axis])
        return _with(state, replace(draft, end_effector=(point[0], point[1], point[2])))


@dataclass(frozen=True)
class WizardNext(Action):
    """The next question; on the summary, **Finish**: the robot becomes the panel's.

    >>> import robotconf as rc
    >>> from robotconf.panel.actions import ChooseMode
    >>> state = ChooseMode("wizard").apply(PanelState.start(rc.preset("paper")))
    >>> state = WizardSetCount(1).apply(state)
    >>> for _ in range(5):
    ...     state = WizardNext().apply(state)
    >>> state.wizard.part
    'summary'
    >>> state = WizardNext().apply(state)
    >>> state.wizard is None, state.robot.modules
    (True, (Module('Rz'),))
    """

    def apply(self, state: PanelState) -> PanelState:
        draft = _draft(state)
        if draft.part != "summary":
            return _with(state, draft.go(draft.step + 1))
        robot = draft.built()
        return with_robot(state, robot, new_robot=True).replace(wizard=None)


@dataclass(frozen=True)
class WizardBack(Action):
    """The previous question (answers are kept)."""

    def apply(self, state: PanelState) -> PanelState:
        draft = _draft(state)
        return _with(state, draft.go(draft.step - 1))


@dataclass(frozen=True)
class WizardCancel(Action):
    """Leave the guided mode; the panel's robot stays as it was."""

    def apply(self, state: PanelState) -> PanelState:
        return state.replace(wizard=None)
