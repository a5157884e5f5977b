"""Editing the cell's table: objects and frames added, removed, renamed, placed and sized.

Every action builds the new cell from the new description, so the core checks it (a
name used twice, a size ≤ 0, a pose that is not a rotation) and its refusal keeps the
last valid cell. Poses are in the parent's frame; a new parent keeps the entry where it
is in the cell (its pose is rewritten relative to the new parent).
"""

from __future__ import annotations

from collections.abc import Hashable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ...cell import Box, Cylinder, Mesh, Sphere, pose
from ..state import (
    DesignerState,
    FrameItem,
    ObjectItem,
    pose_of,
    with_pose_number,
)
from ._base import Action, cell_size, nice

__all__ = [
    "ADD_KINDS",
    "AddObject",
    "AddFrame",
    "AddMesh",
    "RemoveEntry",
    "RenameEntry",
    "SetParent",
    "SetPose",
    "SetSize",
    "Select",
    "fresh_name",
]

#: What the table's add buttons make.
ADD_KINDS = ("box", "cylinder", "sphere")


def fresh_name(state: DesignerState, stem: str) -> str:
    """``stem1``, ``stem2``, …: the first name not in the cell.

    >>> fresh_name(DesignerState(), "box")
    'box1'
    """
    names = set(state.cell.names)
    count = 1
    while f"{stem}{count}" in names:
        count += 1
    return f"{stem}{count}"


@dataclass(frozen=True)
class AddObject(Action):
    """A new box, cylinder or sphere on the floor in front of the first robot, sized by
    the robot (a fifth of its size, rounded to 1, 2 or 5 × 10^k), selected.

    >>> state = AddObject("box").apply(DesignerState())
    >>> state.selected, state.cell.item("box1").shape.size
    ('box1', (0.2, 0.2, 0.2))
    """

    kind: str

    def apply(self, state: DesignerState) -> DesignerState:
        if self.kind not in ADD_KINDS:
            raise InvalidInputError("kind", self.kind, " or ".join(ADD_KINDS))
        size = nice(0.2 * cell_size(state))
        name = fresh_name(state, self.kind)
        count = sum(isinstance(i, ObjectItem) for i in state.cell.items)
        where = pose([2.5 * size, 1.5 * size * count, 0.5 * size])
        shape = {
            "box": lambda: Box([size] * 3, pose=where, name=name),
            "cylinder": lambda: Cylinder(0.5 * size, size, pose=where, name=name),
            "sphere": lambda: Sphere(0.5 * size, pose=where, name=name),
        }[self.kind]()
        cell = state.cell.added(ObjectItem(shape))
        return state.with_document(state.document.with_cell(cell)).replace(selected=name)


@dataclass(frozen=True)
class AddFrame(Action):
    """A new frame on the selected object or frame (on a box: on its top face), else in
    the cell; selected.

    >>> state = AddFrame().apply(AddObject("box").apply(DesignerState()))
    >>> state.selected, state.cell.build().pose_of("box1/frame1")[:3, 3].tolist()
    ('box1/frame1', [0.5, 0.0, 0.2])
    """

    def apply(self, state: DesignerState) -> DesignerState:
        parent = state.selected
        item = state.cell.item(parent) if parent is not None else None
        if not isinstance(item, (ObjectItem, FrameItem)):
            parent, item = None, None
        lift = 0.0
        if isinstance(item, ObjectItem) and isinstance(item.shape, Box):
            lift = 0.5 * item.shape.size[2]
        own = fresh_name(state, "frame")
        full = own if parent is None else f"{parent}/{own}"
        where = pose([0.0, 0.0, lift]) if parent is not None else pose([0.0, 0.0, 0.0])
        cell = state.cell.added(FrameItem(full, pose_of(where), parent))
        return state.with_document(state.document.with_cell(cell)).replace(selected=full)


@dataclass(frozen=True)
class AddMesh(Action):
    """A mesh (read by :meth:`robotconf.Mesh.load`) added to the cell and selected;
    ``label`` names an upload that no file holds."""

    mesh: Mesh
    label: str | None = None

    def apply(self, state: DesignerState) -> DesignerState:
        name = self.mesh.name if self.mesh.name not in state.cell.names else None
        mesh = self.mesh.with_name(name or fresh_name(state, "mesh"))
        cell = state.cell.added(ObjectItem(mesh, None, self.label))
        return state.with_document(state.document.with_cell(cell)).replace(selected=mesh.name)


def _users(state: DesignerState, name: str) -> list[str]:
    """The moves that name frame ``name``: ``"arm's move 2"``."""
    found = []
    for robot, program in state.document.programs:
        for k, move in enumerate(program.moves):
            if getattr(move, "frame", None) == name:
                found.append(f"{robot}'s move {k + 1}")
    return found


@dataclass(frozen=True)
class RemoveEntry(Action):
    """Remove an object, frame or robot (with its program); refused while entries stand
    on it or a program moves to it."""

    name: str

    def apply(self, state: DesignerState) -> DesignerState:
        users = _users(state, self.name)
        if users:
            raise InvalidInputError(
                "name",
                self.name,
                "an entry no move goes to (change those moves first)",
                problem=f"the target of {', '.join(users[:3])}:",
            )
        cell = state.cell.removed(self.name)
        return state.with_document(state.document.with_cell(cell))


@dataclass(frozen=True)
class RenameEntry(Action):
    """Give an entry another name (a frame: its own name); frames on it and the moves
    that name them follow.

    >>> state = RenameEntry("box1", "fixture").apply(AddObject("box").apply(DesignerState()))
    >>> state.cell.names, state.selected
    (('fixture',), 'fixture')
    """

    name: str
    new: str

    def apply(self, state: DesignerState) -> DesignerState:
        new = self.new.strip() if isinstance(self.new, str) else self.new
        cell, renames = state.cell.renamed(self.name, new)
        document = state.document.with_cell(cell, renames)
        selected = renames.get(state.selected or "", state.selected)
        reach = state.reach
        if reach.robot in renames:
            reach = type(reach)(reach.on, renames[reach.robot], reach.low, reach.high, reach.step)
        return state.replace(document=document, selected=selected, reach=reach)


@dataclass(frozen=True)
class SetParent(Action):
    """Place an entry on another (``None``: the cell), keeping where it is in the cell.

    >>> state = AddObject("box").apply(AddObject("box").apply(DesignerState()))
    >>> state = SetParent("box2", "box1").apply(state)
    >>> [round(float(v), 12) for v in state.cell.item("box2").shape.pose[:3, 3]]
    [0.0, 0.3, 0.0]
    """

    name: str
    parent: str | None

    def apply(self, state: DesignerState) -> DesignerState:
        built = state.cell.cell
        world = built.pose_of(self.name)
        cell, renames = state.cell.reparented(self.name, self.parent)
        above = np.eye(4) if self.parent is None else built.pose_of(self.parent)
        local = np.linalg.solve(above, world)
        item = cell.item(renames.get(self.name, self.name))
        cell = cell.replaced(item.with_pose(pose_of(local)))
        document = state.document.with_cell(cell, renames)
        selected = renames.get(state.selected or "", state.selected)
        return state.replace(document=document, selected=selected)


@dataclass(frozen=True)
class SetPose(Action):
    """One of an entry's six pose numbers (:data:`~..state.POSE_FIELDS`: x, y, z in
    length units, roll, pitch, yaw in radians), in its parent's frame.

    >>> state = SetPose("box1", 0, 7.0).apply(AddObject("box").apply(DesignerState()))
    >>> state.cell.build().pose_of("box1")[:3, 3].tolist()
    [7.0, 0.0, 0.1]
    """

    name: str
    index: int
    value: float

    def apply(self, state: DesignerState) -> DesignerState:
        if self.index not in range(6):
            raise InvalidInputError("index", self.index, "0 … 5 (x, y, z, roll, pitch, yaw)")
        item = state.cell.item(self.name)
        moved = item.with_pose(with_pose_number(item.pose, self.index, self.value))
        return state.with_document(state.document.with_cell(state.cell.replaced(moved)))

    @property
    def gesture(self) -> Hashable | None:
        return ("pose", self.name, self.index)


def _sized(shape: Any, field: str, value: float, index: int | None) -> Any:
    if isinstance(shape, Box) and field == "size" and index in range(3):
        size = list(shape.size)
        size[index] = value  # type: ignore[index]
        return Box(size, shape.pose, shape.name)
    if isinstance(shape, Cylinder) and field in ("radius", "length"):
        numbers = {"radius": shape.radius, "length": shape.length, field: value}
        return Cylinder(numbers["radius"], numbers["length"], shape.pose, shape.name)
    if isinstance(shape, Sphere) and field == "radius":
        return Sphere(value, shape.pose, shape.name)
    if isinstance(shape, Mesh) and field == "scale":
        if shape.source is not None:  # read again: the file's numbers times the new scale
            return Mesh.load(shape.source, pose=shape.pose, scale=value, name=shape.name)
        factor = float(value) / shape.scale
        return Mesh(shape.vertices * factor, shape.faces, shape.pose, shape.name, scale=value)
    raise InvalidInputError("field", field, f"a size field of a {shape.kind}")


@dataclass(frozen=True)
class SetSize(Action):
    """A size of an object: a box's ``size`` (``index`` 0, 1, 2), a cylinder's
    ``radius`` or ``length``, a sphere's ``radius``, a mesh's ``scale`` (length units).

    >>> state = SetSize("box1", "size", 3.0, 2).apply(AddObject("box").apply(DesignerState()))
    >>> state.cell.item("box1").shape.size
    (0.2, 0.2, 3.0)
    """

    name: str
    field: str
    value: float
    index: int | None = None

    def apply(self, state: DesignerState) -> DesignerState:
        item = state.cell.item(self.name)
        if not isinstance(item, ObjectItem):
            raise InvalidInputError("name", self.name, "an object (a frame or robot has no size)")
        shape = _sized(item.shape, self.field, self.value, self.index)
        changed = ObjectItem(shape, item.parent, item.label)
        return state.with_document(state.document.with_cell(state.cell.replaced(changed)))

    @property
    def gesture(self) -> Hashable | None:
        return ("size", self.name, self.field, self.index)


@dataclass(frozen=True)
class Select(Action):
    """Highlight an entry in the table and the view (``None``: nothing)."""

    name: str | None

    def apply(self, state: DesignerState) -> DesignerState:
        if self.name is not None:
            state.cell.item(self.name)
        return state.replace(selected=self.name)
