"""Editing the robot in place: a coordinate, a module's type or offsets, a DH row, the end
effector, the active count, and rows added, removed or moved.

A moved coordinate keeps the robot's name (it is still the named robot); any other edit
makes another robot, which loses it.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Hashable
from dataclasses import dataclass
from typing import Any

from ..._errors import InvalidInputError
from ...kinematics import DHLink, Module, Robot
from .._ranges import length_scale
from ..state import PanelState
from ._base import Action, with_robot

__all__ = [
    "SetQ",
    "SetModuleKind",
    "SetModuleOffset",
    "SetDHParameter",
    "SetDHJoint",
    "SetEndEffector",
    "SetActive",
    "AddModule",
    "RemoveModule",
    "MoveModule",
]


def _edited(state: PanelState, index: int, link: Any) -> PanelState:
    robot = state.robot.with_module(index, link).with_name(None)
    return with_robot(state, robot)


def _module(state: PanelState, index: int) -> Module:
    link = state.robot.modules[_index(state, index)]
    if not isinstance(link, Module):
        raise InvalidInputError(
            f"modules[{index}]", repr(link), "a module (this link is a DH row: edit it as one)"
        )
    return link


def _dh(state: PanelState, index: int) -> DHLink:
    link = state.robot.modules[_index(state, index)]
    if not isinstance(link, DHLink):
        raise InvalidInputError(
            f"dh[{index}]", repr(link), "a DH row (this link is a module: edit it as one)"
        )
    return link


def _index(state: PanelState, index: int) -> int:
    return state.robot.index(index, "index")


@dataclass(frozen=True)
class SetQ(Action):
    """Move coordinate ``index`` (0-based) to ``value`` (radians or length units).

    >>> import robotconf as rc
    >>> state = SetQ(1, -1.5707963267948966).apply(PanelState.start(rc.preset("paper")))
    >>> state.robot.end_effector().round(9) + 0.0
    array([ 0.,  0., 90.])
    """

    index: int
    value: float

    def apply(self, state: PanelState) -> PanelState:
        robot = state.robot
        i = _index(state, self.index)
        q = robot.q
        q[i] = self.value
        return state.with_document(robot=robot.with_q(q))

    @property
    def gesture(self) -> Hashable:
        return ("q", self.index)


@dataclass(frozen=True)
class SetModuleKind(Action):
    """Give module ``index`` another movement type (``"Rx"`` … ``"Tz"``, ``"none"``,
    ``"fixed"``); offsets, q and name stay, a range only within the same joint type."""

    index: int
    kind: str

    def apply(self, state: PanelState) -> PanelState:
        return _edited(state, self.index, _module(state, self.index).with_kind(self.kind))


@dataclass(frozen=True)
class SetModuleOffset(Action):
    """Set offset ``axis`` (0, 1, 2 for ax, ay, az) of module ``index`` (length units)."""

    index: int
    axis: int
    value: float

    def apply(self, state: PanelState) -> PanelState:
        module = _module(state, self.index)
        a = list(module.a)
        a[self.axis] = self.value
        return _edited(state, self.index, module.with_a(a))

    @property
    def gesture(self) -> Hashable:
        return ("offset", self.index, self.axis)


@dataclass(frozen=True)
class SetDHParameter(Action):
    """Set ``name`` (``"theta"``, ``"d"``, ``"a"``, ``"alpha"``) of DH row ``index``."""

    index: int
    name: str
    value: float

    def apply(self, state: PanelState) -> PanelState:
        row = _dh(state, self.index)
        if self.name not in ("theta", "d", "a", "alpha"):
            raise InvalidInputError("name", self.name, "theta, d, a or alpha")
        changed = dataclasses.replace(row, **{self.name: self.value})  # type: ignore[arg-type]
        return _edited(state, self.index, changed)

    @property
    def gesture(self) -> Hashable:
        return ("dh", self.index, self.name)


@dataclass(frozen=True)
class SetDHJoint(Action):
    """Make DH row ``index`` revolute (``"R"``: q adds to θ) or prismatic (``"P"``: to
    d); its range goes (radians do not become lengths)."""

    index: int
    joint: str

    def apply(self, state: PanelState) -> PanelState:
        row = _dh(state, self.index)
        if row.joint == self.joint:
            return state
        return _edited(state, self.index, dataclasses.replace(row, joint=self.joint, limits=None))


@dataclass(frozen=True)
class SetEndEffector(Action):
    """Set component ``axis`` (0, 1, 2 for Px, Py, Pz) of the end-effector point."""

    axis: int
    value: float

    def apply(self, state: PanelState) -> PanelState:
        point = state.robot.end_effector_point
        point[self.axis] = self.value
        return with_robot(state, state.robot.with_end_effector(point).with_name(None))

    @property
    def gesture(self) -> Hashable:
        return ("end_effector", self.axis)


@dataclass(frozen=True)
class SetActive(Action):
    """The paper's number of active modules (all: the robot's ``n``)."""

    count: int

    def apply(self, state: PanelState) -> PanelState:
        robot = state.robot
        count = None if self.count == robot.n else self.count
        return with_robot(state, robot.with_active(count).with_name(None))

    @property
    def gesture(self) -> Hashable:
        return ("active",)


def _new_link(state: PanelState) -> Module | DHLink:
    robot = state.robot
    if state.editor == "dh":
        # A tenth of the robot's size, so that the new link shows at the robot's scale.
        convention = robot.modules[-1].convention  # type: ignore[attr-defined]
        return DHLink(a=length_scale(robot) / 10.0, convention=convention)
    return Module("Rz")  # a rotation about z at the tool end


@dataclass(frozen=True)
class AddModule(Action):
    """Append a module (a rotation about z) or, in the DH table, a revolute row.

    >>> import robotconf as rc
    >>> AddModule().apply(PanelState.start(rc.preset("paper"))).robot.modules[-1]
    Module('Rz')
    """

    def apply(self, state: PanelState) -> PanelState:
        robot = state.robot.with_appended(_new_link(state)).with_name(None)
        return with_robot(state, robot, order=[*range(state.robot.n), None])


@dataclass(frozen=True)
class RemoveModule(Action):
    """Remove module (or DH row) ``index``; a robot keeps at least one."""

    index: int

    def apply(self, state: PanelState) -> PanelState:
        i = _index(state, self.index)
        robot: Robot = state.robot.with_removed(i).with_name(None)
        order: list[int | None] = [k for k in range(state.robot.n) if k != i]
        return with_robot(state, robot, order=order)


@dataclass(frozen=True)
class MoveModule(Action):
    """Move module ``index`` one place towards the base (``step=-1``) or the tool (``+1``)."""

    index: int
    step: int

    def apply(self, state: PanelState) -> PanelState:
        i = _index(state, self.index)
        j = i + self.step
        if self.step not in (-1, 1) or not 0 <= j < state.robot.n:
            raise InvalidInputError(
                "step", self.step, f"-1 or 1, within modules 0 to {state.robot.n - 1}"
            )
        order: list[int | None] = list(range(state.robot.n))
        order[i], order[j] = order[j], order[i]
        robot = state.robot.with_moved(i, j).with_name(None)
        return with_robot(state, robot, order=order)
