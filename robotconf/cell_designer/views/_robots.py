"""The table of robots: one row per robot, and a preset to add one from.

A row shows the robot's name, what it is (its preset, else its own name), its parent,
its q (a box per joint: degrees or radians for a revolute joint, the length unit for a
prismatic one) and its base pose. Keys: ``robot[i].name``, ``.parent``, ``.select``,
``.remove``, ``.q0`` …, ``.pose0`` … ``.pose5``; ``add.robot.preset`` and ``add.robot``.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ...panel.form import Form, FormEvent, button, message, row, select, text
from ...presets import preset_names
from .. import actions as act
from ..state import POSE_FIELDS, DesignerState, RobotItem
from ._boxes import ANGLE, LENGTH, box, core_value, pose_boxes
from ._messages import Messages
from ._rows import CELL_PARENT, SELECTED_CLASS, head_controls, parse_key

__all__ = ["RobotsView"]


def _q_boxes(
    prefix: str, item: RobotItem, state: DesignerState, messages: Messages, rev: str, step: float
) -> list[dict[str, Any]]:
    units = state.units
    robot = item.robot
    kinds = sorted({units.coordinate(link.unit) for link in robot.modules if link.unit})
    parts: list[dict[str, Any]] = [text(f"q [{', '.join(kinds)}]" if kinds else "q", tone="note")]
    for k, (link, value) in enumerate(zip(robot.modules, robot.q, strict=True)):
        parts.append(
            box(
                f"{prefix}.q{k}",
                float(value),
                link.unit,
                units,
                messages,
                rev,
                step=step,
                title=f"q{k + 1} ({robot.module_names[k]})",
                width="58px",
                disabled=not link.unit,
            )
        )
    return parts


class RobotsView:
    """The robots of the cell, each on its base, with its q.

    Parameters
    ----------
    dispatch : callable
        ``dispatch(action_or_error, key, typed=None)``.
    """

    def __init__(self, dispatch: Callable[..., None]) -> None:
        self._dispatch = dispatch
        self._names: dict[int, str] = {}
        self._state: DesignerState | None = None
        self.preset = "paper"
        self.form = Form(self._event, css_class="robotconf-cell-robots")

    def render(self, state: DesignerState, messages: Messages, rev: str, step: float) -> None:
        """Draw a row per robot, then the preset menu and the add button."""
        self._state = state
        self._names = {}
        rows = []
        for i, item in enumerate(state.cell.items):
            if not isinstance(item, RobotItem):
                continue
            self._names[i] = item.name
            prefix = f"robot[{i}]"
            selected = state.selected == item.name
            what = act.preset_name(item) or (item.robot.name or f"{item.robot.n}-joint robot")
            head = head_controls(prefix, item, state.cell, selected, messages, rev)
            notes = [messages.text(f"{prefix}.{k}") for k in ("name", "select", "remove")]
            rows.append(
                row(
                    prefix,
                    [text("robot", tone="title"), head[0], text(what, tone="note"), *head[1:]],
                    _q_boxes(prefix, item, state, messages, rev, step),
                    [
                        text("base", tone="note"),
                        *pose_boxes(prefix, item.pose, state.units, messages, rev, step),
                    ],
                    box=True,
                    note=message("; ".join(n for n in notes if n)),
                    css_class=SELECTED_CLASS if selected else "",
                )
            )
        rows.append(
            row(
                "add.robot",
                [
                    select(
                        "add.robot.preset",
                        self.preset,
                        [(name, name) for name in preset_names()],
                        label="preset",
                        rev=rev,
                        width="130px",
                    ),
                    button("add.robot", "+ robot", rev=rev, css_class="robotconf-add-robot"),
                ],
                note=message(messages.text("add.robot")),
            )
        )
        self.form.show(rows)

    def _event(self, event: FormEvent) -> None:
        key = event.key
        if key == "add.robot.preset":
            self.preset = str(event.value)
            self._dispatch(None, key)
            return
        if key == "add.robot":
            self._dispatch(act.AddRobot(self.preset), key)
            return
        parsed = parse_key(key)
        if parsed is None or parsed[1] not in self._names or self._state is None:
            return
        _, index, name_field, part = parsed
        name = self._names[index]
        try:
            action = self._action(self._state, name, name_field, part, event)
        except Exception as error:  # a number that is no number: said beside the box
            self._dispatch(error, key, event.text)
            return
        self._dispatch(action, key, event.text)

    @staticmethod
    def _action(
        state: DesignerState, name: str, name_field: str, part: int | None, event: FormEvent
    ) -> Any:
        units = state.units
        if name_field == "name":
            return act.RenameEntry(name, event.text or "")
        if name_field == "parent":
            return act.SetParent(name, None if event.value == CELL_PARENT else str(event.value))
        if name_field == "select":
            return act.Select(None if state.selected == name else name)
        if name_field == "remove":
            return act.RemoveEntry(name)
        if name_field == "pose" and part is not None:
            unit = LENGTH if part < 3 else ANGLE
            field = f"{name}.{POSE_FIELDS[part]}"
            return act.SetPose(name, part, core_value(event, unit, units, field))
        if name_field == "q" and part is not None:
            item = state.cell.item(name)
            assert isinstance(item, RobotItem)
            unit = item.robot.modules[part].unit
            return act.SetQ(name, part, core_value(event, unit, units, f"{name}.q{part + 1}"))
        return None
