"""The cell's robots: one added from a preset, a coordinate moved.

A robot's base pose is edited like any entry's (:class:`~._entries.SetPose`), its name
like any name (:class:`~._entries.RenameEntry`, its program follows).
"""

from __future__ import annotations

from collections.abc import Hashable
from dataclasses import dataclass

from ..._errors import InvalidInputError
from ...cell import pose
from ...kinematics import characteristic_length
from ...presets import preset, preset_names
from ..state import DesignerState, RobotItem, pose_of
from ._base import Action

__all__ = ["AddRobot", "SetQ", "preset_name"]


def preset_name(item: RobotItem) -> str:
    """The preset the robot is, at any q (``""`` for another robot).

    >>> import robotconf as rc
    >>> from robotconf.cell_designer.state import pose_of
    >>> preset_name(RobotItem("arm", rc.preset("ur5").with_q([0.1] * 6), pose_of(None)))
    'ur5'
    """
    robot = item.robot
    for name in preset_names():
        candidate = preset(name)
        if candidate.name == robot.name and candidate == robot.with_q(candidate.q):
            return name
    return ""


@dataclass(frozen=True)
class AddRobot(Action):
    """A robot from a preset, named after it, standing beside the robots there are (two
    sizes apart along x); selected.

    >>> state = AddRobot("paper").apply(AddRobot("paper").apply(DesignerState()))
    >>> state.cell.robots, state.cell.build().pose_of("paper2")[:3, 3].tolist()
    (('paper', 'paper2'), [180.0, 0.0, 0.0])
    """

    preset: str

    def apply(self, state: DesignerState) -> DesignerState:
        robot = preset(self.preset)
        names = set(state.cell.names)
        name, count = self.preset, 1
        while name in names:
            count += 1
            name = f"{self.preset}{count}"
        others = [i for i in state.cell.items if isinstance(i, RobotItem)]
        size = max(
            [characteristic_length(robot)] + [characteristic_length(i.robot) for i in others]
        )
        base = pose([2.0 * size * len(others), 0.0, 0.0])
        cell = state.cell.added(RobotItem(name, robot, pose_of(base)))
        return state.with_document(state.document.with_cell(cell)).replace(selected=name)


@dataclass(frozen=True)
class SetQ(Action):
    """Move a robot's coordinate ``index`` (0-based) to ``value`` (radians or length).

    >>> import math
    >>> state = SetQ("paper", 1, -math.pi / 2).apply(AddRobot("paper").apply(DesignerState()))
    >>> state.cell.item("paper").robot.end_effector().round(9) + 0.0
    array([ 0.,  0., 90.])
    """

    robot: str
    index: int
    value: float

    def apply(self, state: DesignerState) -> DesignerState:
        item = state.cell.item(self.robot)
        if not isinstance(item, RobotItem):
            raise InvalidInputError("robot", self.robot, f"one of {list(state.cell.robots)}")
        q = item.robot.q
        q[item.robot.index(self.index, "index")] = self.value
        moved = item.with_robot(item.robot.with_q(q))
        return state.with_document(state.document.with_cell(state.cell.replaced(moved)))

    @property
    def gesture(self) -> Hashable | None:
        return ("q", self.robot, self.index)
