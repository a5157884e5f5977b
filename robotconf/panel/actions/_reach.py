"""The Reach tab: a target the robot follows by inverse kinematics.

Every change of the target solves :func:`robotconf.ik` from the robot's current q; when it
converges the robot moves like an edit of its q (one undo step per drag of one target
slider), else it stays and the solver's reason is kept to show. A click on a closed-form
branch (:func:`robotconf.ik_all`) moves the robot there.
"""

from __future__ import annotations

import functools
import warnings
from collections.abc import Hashable
from dataclasses import dataclass, replace

import numpy as np

from ..._errors import InvalidInputError
from ...inverse_kinematics import ik
from ...kinematics import Robot, check_parameter, rpy_from_matrix
from ..state import REACH_MODES, PanelState, ReachOutcome, target_numbers, target_of
from ._base import Action
from ._closed_form import ClosedForm, closed_form

__all__ = [
    "SetReachMode",
    "SetReachTarget",
    "ReachFromCurrent",
    "Solve",
    "PickSolution",
    "SetShowAll",
    "TARGET_FIELDS",
    "solutions_for",
]

#: The six numbers of a target, in order (length units, then radians).
TARGET_FIELDS = ("x", "y", "z", "roll", "pitch", "yaw")


@functools.lru_cache(maxsize=16)
def _closed_form(structure: Robot, target: tuple[float, ...], mode: str) -> ClosedForm:
    return closed_form(structure, target_of(target, mode))


def solutions_for(robot: Robot, target: tuple[float, ...], mode: str) -> ClosedForm:
    """Every closed-form branch for the target, computed once per geometry and target (a
    q move of the robot reuses them)."""
    structure = robot.with_q(np.zeros(robot.n))
    return _closed_form(structure, tuple(target), mode)


def _solved(state: PanelState, numbers: tuple[float, ...], gesture: Hashable | None) -> PanelState:
    """Solve for ``numbers`` from the current q; move the robot when it converged."""
    reach = state.reach
    robot = state.robot
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = ik(robot, target_of(numbers, reach.mode), q0=robot.q, mode=reach.mode)
    warning = "; ".join(str(w.message) for w in caught)
    moved = robot.with_q(result.q) if result.success else robot
    outcome = ReachOutcome(
        bool(result.success), str(result.reason), str(result.message), warning, moved
    )
    target = (
        float(numbers[0]),
        float(numbers[1]),
        float(numbers[2]),
        float(numbers[3]),
        float(numbers[4]),
        float(numbers[5]),
    )
    reached = state.replace(reach=replace(reach, target=target, outcome=outcome))
    return reached.with_document(robot=moved) if moved != robot else reached


@dataclass(frozen=True)
class SetReachMode(Action):
    """Ask for a ``"position"`` or a full ``"pose"``; a pose starts from the tool's
    current orientation, so switching moves nothing by itself."""

    mode: str

    def apply(self, state: PanelState) -> PanelState:
        if self.mode not in REACH_MODES:
            raise InvalidInputError("mode", self.mode, ", ".join(REACH_MODES))
        if self.mode == state.reach.mode:
            return state
        numbers = list(target_numbers(state.reach, state.robot))
        if self.mode == "pose":
            pose = state.robot.at().end_effector_pose
            numbers[3:6] = rpy_from_matrix(pose[:3, :3])
        moded = state.replace(reach=replace(state.reach, mode=self.mode))
        return _solved(moded, tuple(numbers), None)


@dataclass(frozen=True)
class SetReachTarget(Action):
    """Set one number of the target (``"x"`` … ``"yaw"``; length units, radians) and
    follow it.

    >>> import robotconf as rc
    >>> state = PanelState.start(rc.preset("planar_2r", l1=1, l2=1))
    >>> state = SetReachTarget("x", 1.0).apply(state)
    >>> state = SetReachTarget("y", 1.0).apply(state)
    >>> state.reach.outcome.reason, state.robot.end_effector().round(9) + 0.0
    ('converged', array([1., 1., 0.]))
    """

    field: str
    value: float

    def apply(self, state: PanelState) -> PanelState:
        if self.field not in TARGET_FIELDS:
            raise InvalidInputError("field", self.field, ", ".join(TARGET_FIELDS))
        numbers = list(target_numbers(state.reach, state.robot))
        numbers[TARGET_FIELDS.index(self.field)] = check_parameter(self.value, self.field)
        return _solved(state, tuple(numbers), self.gesture)

    @property
    def gesture(self) -> Hashable:
        return ("reach", self.field)


@dataclass(frozen=True)
class ReachFromCurrent(Action):
    """Make the target where the end effector is now (the robot does not move)."""

    def apply(self, state: PanelState) -> PanelState:
        return state.replace(reach=replace(state.reach, target=None, outcome=None))


@dataclass(frozen=True)
class Solve(Action):
    """Solve for the target again from the robot's current q."""

    def apply(self, state: PanelState) -> PanelState:
        return _solved(state, target_numbers(state.reach, state.robot), None)


@dataclass(frozen=True)
class PickSolution(Action):
    """Move the robot to closed-form branch ``index`` of the target."""

    index: int

    def apply(self, state: PanelState) -> PanelState:
        numbers = target_numbers(state.reach, state.robot)
        found = solutions_for(state.robot, numbers, state.reach.mode)
        if found.solutions is None or not 0 <= self.index < len(found.solutions):
            raise InvalidInputError(
                "solution", self.index, f"a branch number from 0 to {found.count - 1}"
            )
        robot = state.robot.with_q(found.solutions.q[self.index])
        label = str(found.solutions.labels[self.index])
        outcome = ReachOutcome(True, "closed form", label, "", robot)
        target = numbers if state.reach.target is None else state.reach.target
        reach = replace(state.reach, target=target, outcome=outcome)
        return state.replace(reach=reach).with_document(robot=robot)


@dataclass(frozen=True)
class SetShowAll(Action):
    """Draw every closed-form solution as a ghost robot, or none."""

    value: bool

    def apply(self, state: PanelState) -> PanelState:
        return state.replace(reach=replace(state.reach, show_all=bool(self.value)))
