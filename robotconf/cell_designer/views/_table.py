"""The table of objects and frames: one row each, and the buttons that add them.

A row shows the entry's kind, name, parent, its sizes by kind (a box's x, y, z edges, a
cylinder's radius and length, a sphere's radius, a mesh's file and scale) and its pose
in the parent's frame (x, y, z in the cell's length unit; roll, pitch, yaw in the angle
unit). Keys: ``entry[i].name``, ``.parent``, ``.select``, ``.remove``, ``.size0`` …
``.size2``, ``.radius``, ``.length``, ``.scale``, ``.pose0`` … ``.pose5``; the add buttons
``add.box``, ``add.cylinder``, ``add.sphere``, ``add.frame``.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ...cell import Box, Cylinder, Mesh, Sphere
from ...panel.form import Form, FormEvent, button, message, row, text
from .. import actions as act
from ..state import POSE_FIELDS, DesignerState, FrameItem, Item, ObjectItem
from ._boxes import ANGLE, LENGTH, box, core_value, pose_boxes
from ._messages import Messages
from ._rows import CELL_PARENT, SELECTED_CLASS, head_controls, parse_key

__all__ = ["TableView"]

_SIZE_FIELDS = {"size": "size", "radius": "radius", "length": "length", "scale": "scale"}


def _size_boxes(
    prefix: str, item: ObjectItem, state: DesignerState, messages: Messages, rev: str, step: float
) -> list[dict[str, Any]]:
    units = state.units
    shape = item.shape

    def one(name: str, value: float, title: str, unit: str = LENGTH) -> dict[str, Any]:
        return box(f"{prefix}.{name}", value, unit, units, messages, rev, step=step, title=title)

    if isinstance(shape, Box):
        return [
            text(f"size x, y, z [{units.length}]", tone="note"),
            *(
                one(f"size{k}", v, f"edge along {a}")
                for k, (v, a) in enumerate(zip(shape.size, "xyz", strict=True))
            ),
        ]
    if isinstance(shape, Cylinder):
        return [
            text(f"radius, length (z) [{units.length}]", tone="note"),
            one("radius", shape.radius, "radius"),
            one("length", shape.length, "length along its z axis"),
        ]
    if isinstance(shape, Sphere):
        return [
            text(f"radius [{units.length}]", tone="note"),
            one("radius", shape.radius, "radius"),
        ]
    assert isinstance(shape, Mesh)
    return [
        text(f"file {item.mesh_file()}", tone="note", css_class="robotconf-cell-mesh-file"),
        text("scale", tone="note"),
        one("scale", shape.scale, "multiplies the file's coordinates", unit=""),
    ]


class TableView:
    """The objects and frames of the cell (robots have their own table).

    Parameters
    ----------
    dispatch : callable
        ``dispatch(action_or_error, key, typed=None)``: the designer's one way in.
    """

    def __init__(self, dispatch: Callable[..., None]) -> None:
        self._dispatch = dispatch
        self._names: dict[int, str] = {}
        self._state: DesignerState | None = None
        self.form = Form(self._event, css_class="robotconf-cell-table")

    def render(self, state: DesignerState, messages: Messages, rev: str, step: float) -> None:
        """Draw a row per object and frame, then the add buttons."""
        self._state = state
        self._names = {}
        rows = []
        for i, item in enumerate(state.cell.items):
            if isinstance(item, (ObjectItem, FrameItem)):
                self._names[i] = item.name
                rows.append(self._row(i, item, state, messages, rev, step))
        if not rows:
            rows.append(
                row("empty", [text("No objects or frames yet: add one below.", tone="note")])
            )
        rows.append(
            row(
                "add",
                [
                    text("add", tone="title"),
                    *(
                        button(
                            f"add.{kind}", f"+ {kind}", rev=rev, css_class=f"robotconf-add-{kind}"
                        )
                        for kind in act.ADD_KINDS
                    ),
                    button(
                        "add.frame",
                        "+ frame",
                        title="a named frame (a pick point), on the selected object",
                        rev=rev,
                        css_class="robotconf-add-frame",
                    ),
                ],
                note=message(messages.text("add")),
            )
        )
        self.form.show(rows)

    def _row(
        self, i: int, item: Item, state: DesignerState, messages: Messages, rev: str, step: float
    ) -> dict[str, Any]:
        prefix = f"entry[{i}]"
        selected = state.selected == item.name
        kind = item.shape.kind if isinstance(item, ObjectItem) else "frame"
        lines = [
            [
                text(kind, tone="title"),
                *head_controls(prefix, item, state.cell, selected, messages, rev),
            ]
        ]
        if isinstance(item, ObjectItem):
            lines.append(_size_boxes(prefix, item, state, messages, rev, step))
        lines.append(pose_boxes(prefix, item.pose, state.units, messages, rev, step))
        notes = [messages.text(f"{prefix}.{k}") for k in ("name", "select", "remove")]
        return row(
            prefix,
            *lines,
            box=True,
            note=message("; ".join(n for n in notes if n)),
            css_class=SELECTED_CLASS if selected else "",
        )

    def _event(self, event: FormEvent) -> None:
        key = event.key
        if key.startswith("add."):
            kind = key[4:]
            action: Any = act.AddFrame() if kind == "frame" else act.AddObject(kind)
            self._dispatch(action, "add")
            return
        parsed = parse_key(key)
        if parsed is None or parsed[1] not in self._names:
            return
        _, index, name_field, part = parsed
        name = self._names[index]
        units = self._state.units if self._state is not None else None
        try:
            action = self._action(name, name_field, part, event, units)
        except Exception as error:  # a number that is no number: said beside the box
            self._dispatch(error, key, event.text)
            return
        self._dispatch(action, key, event.text)

    def _action(
        self, name: str, name_field: str, part: int | None, event: FormEvent, units: Any
    ) -> Any:
        if name_field == "name":
            return act.RenameEntry(name, event.text or "")
        if name_field == "parent":
            return act.SetParent(name, None if event.value == CELL_PARENT else str(event.value))
        if name_field == "select":
            selected = self._state is not None and self._state.selected == name
            return act.Select(None if selected else name)
        if name_field == "remove":
            return act.RemoveEntry(name)
        if name_field == "pose" and part is not None:
            unit = LENGTH if part < 3 else ANGLE
            field = f"{name}.{POSE_FIELDS[part]}"
            return act.SetPose(name, part, core_value(event, unit, units, field))
        if name_field in _SIZE_FIELDS:
            field = f"{name}.{name_field}" + ("" if part is None else f"[{part}]")
            unit = "" if name_field == "scale" else LENGTH
            return act.SetSize(name, name_field, core_value(event, unit, units, field), part)
        return None
