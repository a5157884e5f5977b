"""What a cell holds, by name: robots, objects and frames, each placed in a parent.

Every entry has a pose in its parent's frame (``None``: the cell's frame). Moving a
parent moves everything placed on it: a pick point on a table moves with the table. A
frame's full name joins its parent's and its own with ``/`` (``"table/pick"``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import one_line
from ..kinematics import Robot
from ._links import LinkModel
from ._shapes import Shape
from ._tool import Tool

__all__ = ["Entry", "RobotEntry", "resolve_world_poses", "MAX_ENTRIES"]

#: The most robots, objects and frames one cell may hold.
MAX_ENTRIES = 1000


@dataclass
class Entry:
    """One named thing in the cell: ``kind`` is ``"robot"``, ``"object"`` or ``"frame"``."""

    name: str
    kind: str
    pose: np.ndarray
    parent: str | None = None
    shape: Shape | None = None


@dataclass
class RobotEntry(Entry):
    """A robot in the cell: its base pose (in its parent), tool, link model and mounts."""

    robot: Robot | None = None
    tool: Tool | None = None
    radius: Any = None
    mount: tuple[str, ...] = ()
    links: LinkModel | None = field(default=None, repr=False)


def resolve_world_poses(entries: dict[str, Entry]) -> dict[str, np.ndarray]:
    """Every entry's pose in the cell's frame, following parents (cycles refused).

    >>> e = {"t": Entry("t", "object", np.eye(4)), "t/p": Entry("t/p", "frame", np.eye(4), "t")}
    >>> sorted(resolve_world_poses(e))
    ['t', 't/p']
    """
    world: dict[str, np.ndarray] = {}
    for start in entries:
        chain: list[str] = []
        name: str | None = start
        while name is not None and name not in world:
            if name in chain:
                loop = " → ".join([*chain[chain.index(name) :], name])
                raise InvalidInputError(
                    f"{start}.parent",
                    loop,
                    "parents that lead back to the cell",
                    problem="a cycle of parents:",
                )
            if name not in entries:
                raise InvalidInputError(
                    f"{chain[-1]}.parent",
                    name,
                    "the name of a robot, object or frame in the cell",
                    problem="no such parent:",
                )
            chain.append(name)
            name = entries[name].parent
        base = np.eye(4) if name is None else world[name]
        for item in reversed(chain):
            base = base @ entries[item].pose
            world[item] = base
    return world


def check_parent(entries: dict[str, Entry], parent: Any, field: str) -> str | None:
    """``None`` or the name of an entry in the cell."""
    if parent is None:
        return None
    if not isinstance(parent, str) or parent not in entries:
        raise InvalidInputError(
            field,
            one_line(parent),
            f"None or one of {sorted(entries)[:20]}",
            problem="no such parent:",
        )
    return parent


def planning_robot(entry: RobotEntry) -> Robot:
    """The robot whose end effector is the TCP (the tool's, else the flange).

    The flange frame has the last module's axes and the end-effector point as origin, so
    the TCP point is the end-effector point moved by the TCP's translation.
    """
    assert entry.robot is not None
    if entry.tool is None or not np.any(entry.tool.tcp[:3, 3]):
        return entry.robot
    return entry.robot.with_end_effector(entry.robot.end_effector_point + entry.tool.tcp[:3, 3])


def target_in_base(entry: RobotEntry, base_world: np.ndarray, target: np.ndarray) -> np.ndarray:
    """A target pose of the TCP (cell frame) as a pose of :func:`planning_robot`'s end effector
    in the robot's base frame: ``base⁻¹ · target`` with the tool's turn taken off."""
    inverse = np.eye(4)
    inverse[:3, :3] = base_world[:3, :3].T
    inverse[:3, 3] = -base_world[:3, :3].T @ base_world[:3, 3]
    local = inverse @ target
    if entry.tool is not None:
        local[:3, :3] = local[:3, :3] @ entry.tool.tcp[:3, :3].T
    return local
