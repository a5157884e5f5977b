"""The entries of a designed cell as frozen values: objects, frames and robots.

A :class:`~robotconf.Cell` is mutable, so the designer never keeps one in its state: it
keeps these items, each an immutable copy of one cell entry (its pose exactly as the
cell keeps it), and builds a cell from them when one is needed. Two items are equal when
their entries are, so a state compares by value and undo is going back to an older value.

A pose is kept as the cell's 4×4 matrix (a tuple of rows), never as the six numbers
the table shows: ``x, y, z`` are its translation and ``roll, pitch, yaw`` are read off
its rotation (URDF's, :func:`~robotconf.kinematics.rpy_from_matrix`). Typing one of the
six changes only that number; the others are read again from the new matrix.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ...cell import NAME_SEPARATOR, Mesh, Shape, Tool, check_pose
from ...kinematics import Robot, matrix_from_rpy, rpy_from_matrix

__all__ = [
    "Pose",
    "POSE_FIELDS",
    "pose_of",
    "pose_numbers",
    "with_pose_number",
    "ObjectItem",
    "FrameItem",
    "RobotItem",
    "Item",
    "own_name",
    "radius_value",
]

#: A pose as 4 rows of 4 floats (hashable, compared exactly).
Pose = tuple[tuple[float, ...], ...]
#: The six numbers of a pose as the table shows them: lengths, then angles (rad).
POSE_FIELDS = ("x", "y", "z", "roll", "pitch", "yaw")


def pose_of(matrix: Any, field_name: str = "pose") -> Pose:
    """A pose checked by the cell (:func:`robotconf.cell.check_pose`) as rows of floats.

    >>> pose_of(None)[0]
    (1.0, 0.0, 0.0, 0.0)
    """
    checked = check_pose(matrix, field_name)
    return tuple(tuple(float(v) for v in row) for row in checked)


def pose_numbers(pose: Pose) -> tuple[float, float, float, float, float, float]:
    """``(x, y, z, roll, pitch, yaw)`` of a pose: its translation and URDF's angles (rad).

    >>> import robotconf as rc
    >>> [round(v, 12) for v in pose_numbers(pose_of(rc.pose([1, 2, 3], [0, 0, 0.5])))]
    [1.0, 2.0, 3.0, 0.0, 0.0, 0.5]
    """
    array = np.array(pose)
    roll, pitch, yaw = rpy_from_matrix(array[:3, :3])
    x, y, z = (float(v) for v in array[:3, 3])
    return (x, y, z, float(roll), float(pitch), float(yaw))


def with_pose_number(pose: Pose, index: int, value: float) -> Pose:
    """``pose`` with one of its six numbers (:data:`POSE_FIELDS`) set to ``value``.

    A translation changes only its component (the rotation stays bit for bit); an angle
    rebuilds the rotation from the other two angles as read now and the new one.

    >>> moved = with_pose_number(pose_of(None), 2, 5.0)
    >>> [row[3] for row in moved[:3]]
    [0.0, 0.0, 5.0]
    """
    array = np.array(pose)
    if index < 3:
        array[index, 3] = value
    else:
        angles = list(rpy_from_matrix(array[:3, :3]))
        angles[index - 3] = value
        array[:3, :3] = matrix_from_rpy(*angles)
    return pose_of(array, POSE_FIELDS[index])


def own_name(full: str, parent: str | None) -> str:
    """A frame's own name: its full name without its parent's (``"table/pick"`` → ``"pick"``).

    >>> own_name("table/pick", "table"), own_name("home", None)
    ('pick', 'home')
    """
    if parent is not None and full.startswith(parent + NAME_SEPARATOR):
        return full[len(parent) + 1 :]
    return full


def radius_value(radius: Any) -> Any:
    """A robot's link radii as a hashable value: ``None``, a number, a tuple of numbers,
    or a tuple of ``(link name, radius)`` pairs (for a dict).

    >>> radius_value({"link 2": 3}), radius_value(np.array([1.0, 2.0]))
    ((('link 2', 3.0),), (1.0, 2.0))
    """
    if radius is None:
        return None
    if isinstance(radius, Mapping):
        return tuple((str(k), float(v)) for k, v in radius.items())
    if np.ndim(radius) == 0:
        return float(radius)
    return tuple(float(v) for v in np.asarray(radius, dtype=float).ravel())


@dataclass(frozen=True)
class ObjectItem:
    """A solid object: its shape (named, posed in its parent's frame) and its parent.

    ``label`` is what the table shows for a mesh that no file holds (an upload kept in
    memory): the uploaded file's name. It is not part of the cell, so it is not compared.
    """

    shape: Shape
    parent: str | None = None
    label: str | None = field(default=None, compare=False)

    kind = "object"

    @property
    def name(self) -> str:
        """The entry's name."""
        return str(self.shape.name)

    @property
    def pose(self) -> Pose:
        """The shape's pose in its parent's frame."""
        return pose_of(self.shape.pose)

    def with_pose(self, pose: Pose) -> ObjectItem:
        """The same object at another pose."""
        return ObjectItem(self.shape.with_pose(np.array(pose)), self.parent, self.label)

    def mesh_file(self) -> str:
        """What the table names a mesh by: its file's name, else the upload's, else inline.

        >>> import robotconf as rc
        >>> tetra = rc.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]], name="t")
        >>> ObjectItem(tetra).mesh_file()
        'inline, 1 triangles'
        """
        shape = self.shape
        if not isinstance(shape, Mesh):
            return ""
        if shape.source is not None:
            return str(shape.source).replace("\\", "/").rsplit("/", 1)[-1]
        if self.label:
            return self.label
        return f"inline, {len(shape.faces)} triangles"


@dataclass(frozen=True)
class FrameItem:
    """A named frame (a pick point): its full name, pose in its parent's frame, parent."""

    name: str
    pose: Pose
    parent: str | None = None

    kind = "frame"

    def with_pose(self, pose: Pose) -> FrameItem:
        """The same frame at another pose."""
        return FrameItem(self.name, pose, self.parent)


@dataclass(frozen=True)
class RobotItem:
    """A robot on its base: the robot (with its q), base pose, parent, tool, radii, mounts."""

    name: str
    robot: Robot
    pose: Pose
    parent: str | None = None
    tool: Tool | None = None
    radius: Any = None
    mount: tuple[str, ...] = ()

    kind = "robot"

    def with_pose(self, pose: Pose) -> RobotItem:
        """The same robot on another base pose."""
        return RobotItem(
            self.name, self.robot, pose, self.parent, self.tool, self.radius, self.mount
        )

    def with_robot(self, robot: Robot) -> RobotItem:
        """Another robot (another q) on the same base."""
        return RobotItem(
            self.name, robot, self.pose, self.parent, self.tool, self.radius, self.mount
        )


#: Any entry of a designed cell.
Item = ObjectItem | FrameItem | RobotItem
