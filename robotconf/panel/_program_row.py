"""One row of the Program tab's table: a move's type, target, speed or profile, its buttons,
and the messages about it (the core's refusal, the violations of the last Run).

A row is a view of one move of the draft: it shows the move in the panel's units and
reports what the user changes (a number in core units, a type, a click) to the tab, which
makes the new draft. Numbers set by the tab never come back as edits, so an untouched box
keeps the exact core value.
"""

from __future__ import annotations

import html
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from functools import partial
from typing import Any

import ipywidgets as widgets
import numpy as np

from ..kinematics import Robot
from ..programs import CIRC, LIN, PROFILES, PTP, Move, Wait
from ._callbacks import observe, on_click
from ._clean_numbers import display_number
from ._errors_display import ErrorLabel
from ._program_draft import MOVE_KINDS, point_of
from ._ranges import ANGLE_STEP
from ._units import ANGLE_UNIT, LENGTH_UNIT, Units

__all__ = ["MoveRow", "RowContext", "ROW_ACTIONS", "short_number"]

#: What a row's buttons ask the tab to do.
ROW_ACTIONS = ("teach", "teach via", "up", "down", "delete")
_VIOLATION_STYLE = "color:#c2410c;font-size:0.85em;line-height:1.3"
_BOX = widgets.Layout(width="66px")
_ICON = widgets.Layout(width="32px", padding="0")


@dataclass(frozen=True)
class RowContext:
    """What a row needs to show its move: the robot, the units and the program's defaults.

    Attributes
    ----------
    robot : Robot
        The panel's robot (units of the coordinates, which ones move).
    units : Units
    length_step : float
        Arrow-key step of a length box (display units).
    speed : float
        The program's path speed, shown for a LIN/CIRC without its own (length/s).
    count : int
        Rows in the table (the last one cannot move down).
    """

    robot: Robot
    units: Units
    length_step: float
    speed: float
    count: int


def short_number(value: float) -> float:
    """``value`` to 6 significant digits, as a converted number is shown (57.2958 for
    1 rad); the box's untouched value still gives back the exact number.

    >>> short_number(57.29577951308232), short_number(-7.1e-15), short_number(22.5)
    (57.2958, -0.0, 22.5)
    """
    return float(f"{value:.6g}") if np.isfinite(value) else float(value)


def _point_name(index: int) -> str:
    return f"P{index + 1}"


class MoveRow:
    """The widgets of move ``index``.

    Parameters
    ----------
    index : int
        The move's position in the program (0-based; shown as ``P1``, ``P2``, …).
    on_edit : callable
        ``on_edit(index, name, value, component)``: the user set field ``name`` (or its
        ``component``) to ``value`` in core units; ``name == "kind"`` for a new type.
    on_action : callable
        ``on_action(index, action)`` for a button (:data:`ROW_ACTIONS`).

    Examples
    --------
    >>> import robotconf as rc
    >>> edits = []
    >>> row = MoveRow(0, lambda *edit: edits.append(edit), lambda *action: None)
    >>> context = RowContext(rc.preset("paper"), Units("mm"), 1.0, 22.5, 1)
    >>> row.show(PTP(q=(0.0, 0.5235987755982988, 0.0)), context)
    >>> [box.value for box in row.boxes["q"]]  # in degrees
    [0.0, 30.0, 0.0]
    >>> row.boxes["q"][2].value = 90.0
    >>> edits  # the core's radians
    [(0, 'q', 1.5707963267948966, 2)]
    """

    def __init__(
        self,
        index: int,
        on_edit: Callable[[int, str, Any, int | None], None],
        on_action: Callable[[int, str], None],
    ):
        self.index = index
        self._on_edit = on_edit
        self._on_action = on_action
        self.move: Move | None = None
        self.boxes: dict[str, list[widgets.FloatText]] = {}
        self.target_text = widgets.HTML()  # a PTP's pose or point target, read-only
        self.profile: widgets.Dropdown | None = None
        self._look: tuple[Any, ...] | None = None
        self._units: dict[str, list[str]] = {}  # core unit of each box, by field
        self._quiet = False
        self.name = widgets.HTML(layout=widgets.Layout(width="30px"))
        self.kind = widgets.Dropdown(options=MOVE_KINDS, layout=widgets.Layout(width="72px"))
        self.fields = widgets.HBox(
            layout=widgets.Layout(flex_flow="row wrap", align_items="center")
        )
        self.teach_button = widgets.Button(
            description="teach", icon="crosshairs", layout=widgets.Layout(width="auto")
        )
        self.via_button = widgets.Button(
            description="via",
            icon="crosshairs",
            tooltip="teach the via point: where the end effector is now",
            layout=widgets.Layout(width="auto"),
        )
        self.up_button = widgets.Button(icon="arrow-up", tooltip="move up", layout=_ICON)
        self.down_button = widgets.Button(icon="arrow-down", tooltip="move down", layout=_ICON)
        self.delete_button = widgets.Button(
            icon="trash", tooltip="delete this move (↶ brings it back)", layout=_ICON
        )
        self.error = ErrorLabel()
        self.violations = widgets.HTML()
        self.messages: list[str] = []  # the violations shown, as the core wrote them
        self.violations.add_class("robotconf-program-violations")
        self.teach_button.add_class("robotconf-program-teach")
        self.kind.add_class("robotconf-program-kind")
        observe(self.kind, self.error, self._kind_changed)
        for button, action in (
            (self.teach_button, "teach"),
            (self.via_button, "teach via"),
            (self.up_button, "up"),
            (self.down_button, "down"),
            (self.delete_button, "delete"),
        ):
            on_click(button, self.error, partial(self._clicked, action))
        self.buttons = widgets.HBox([self.teach_button, self.via_button])
        self.widget = widgets.VBox(
            [
                widgets.HBox(
                    [
                        self.name,
                        self.kind,
                        self.fields,
                        self.buttons,
                        self.up_button,
                        self.down_button,
                        self.delete_button,
                    ],
                    layout=widgets.Layout(flex_flow="row wrap", align_items="center"),
                ),
                self.error.widget,
                self.violations,
            ],
            layout=widgets.Layout(border_bottom="1px solid #e5e5e5", padding="2px 0"),
        )
        self.widget.add_class("robotconf-program-row")

    # -- showing ------------------------------------------------------------------------

    def show(self, move: Move, context: RowContext) -> None:
        """Show ``move`` (its fields in the panel's units) as row :attr:`index`."""
        self.move = move
        self._quiet = True
        try:
            self.name.value = f"<b>{_point_name(self.index)}</b>"
            self.kind.value = move.kind
            look = (move.kind, _target_kind(move), context.robot.n, context.units)
            if look != self._look:
                self._build_fields(move, context)
                self._look = look
            self._fill(move, context)
        finally:
            self._quiet = False
        self.up_button.disabled = self.index == 0
        self.down_button.disabled = self.index >= context.count - 1
        self.teach_button.disabled = isinstance(move, Wait)
        self.teach_button.tooltip = _TEACH_TIPS[move.kind]
        self.via_button.layout.display = None if isinstance(move, CIRC) else "none"

    def show_violations(self, messages: list[str]) -> None:
        """The last Run's violations of this move (the core's messages), or none."""
        self.messages = list(messages)
        self.violations.value = "".join(
            f'<div style="{_VIOLATION_STYLE}">⚠ {html.escape(m)}</div>' for m in messages
        )

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)``: ``program.moves[i]``."""
        yield f"program.moves[{self.index}]", self.error

    def close(self) -> None:
        """Release the row's widgets (the table got shorter)."""
        self.widget.close()

    # -- building -----------------------------------------------------------------------

    def _build_fields(self, move: Move, context: RowContext) -> None:
        for child in self.fields.children:
            if child is not self.target_text:  # the captions, boxes and menus go
                child.close()
        self.boxes, self._units, self.profile = {}, {}, None
        units, length = context.units, context.units.length
        parts: list[widgets.Widget] = []
        if isinstance(move, PTP):
            if move.q is not None:
                core = [_coordinate_unit(context.robot, i) for i in range(len(move.q))]
                shown = sorted({units.coordinate(u) for u in core if u})
                parts.append(_caption(f"q [{', '.join(shown)}]" if shown else "q"))
                parts += self._add_boxes("q", core, context)
            else:
                parts.append(self.target_text)
            self.profile = widgets.Dropdown(
                options=PROFILES, layout=widgets.Layout(width="112px"), tooltip="time law"
            )
            observe(self.profile, self.error, lambda c: self._typed("profile", None, c["new"]))
            parts.append(self.profile)
        elif isinstance(move, (LIN, CIRC)):
            if isinstance(move, CIRC):
                parts.append(_caption(f"via [{length}]"))
                parts += self._add_boxes("via", [LENGTH_UNIT] * 3, context)
                parts.append(_caption("end"))
            else:
                parts.append(_caption(f"x, y, z [{length}]"))
            parts += self._add_boxes("point", [LENGTH_UNIT] * 3, context)
            parts.append(_caption(f"speed [{length}/s]"))
            parts += self._add_boxes("speed", [LENGTH_UNIT], context)
        else:
            parts.append(_caption("wait [s]"))
            parts += self._add_boxes("seconds", [""], context)
        self.fields.children = tuple(parts)

    def _add_boxes(self, name: str, core: list[str], context: RowContext) -> list[widgets.Widget]:
        boxes = []
        for k, unit in enumerate(core):
            step = ANGLE_STEP[context.units.degrees] if unit == ANGLE_UNIT else context.length_step
            box = widgets.FloatText(step=step if unit else 0.1, layout=_BOX)
            box.add_class(f"robotconf-program-{name}")
            box.disabled = name == "q" and not unit  # a module without a joint
            component = None if name in ("speed", "seconds") else k
            observe(box, self.error, partial(self._box_changed, name, component))
            boxes.append(box)
        self.boxes[name], self._units[name] = boxes, core
        return list(boxes)

    def _fill(self, move: Move, context: RowContext) -> None:
        units = context.units
        values: dict[str, Any] = {}
        if isinstance(move, PTP):
            if move.q is not None:
                values["q"] = move.q
            else:
                point = point_of(move)
                what = "pose" if move.pose is not None else "point"
                text = ", ".join(f"{short_number(v):g}" for v in point or ())
                self.target_text.value = (
                    f"<small>{what} ({html.escape(text)}) [{html.escape(units.length)}], "
                    "solved by rc.ik; teach to set q</small>"
                )
            if self.profile is not None:
                self.profile.value = move.profile
        elif isinstance(move, (LIN, CIRC)):
            values["point"] = point_of(move)
            if isinstance(move, CIRC):
                values["via"] = move.via
            values["speed"] = (context.speed if move.speed is None else move.speed,)
        elif isinstance(move, Wait):
            values["seconds"] = (move.seconds,)
        for name, numbers in values.items():
            for box, unit, value in zip(self.boxes[name], self._units[name], numbers, strict=False):
                shown = units.to_shown(float(value), unit) if np.isfinite(value) else value
                box.value = short_number(display_number(shown, box.step or 1.0))

    # -- user input ---------------------------------------------------------------------

    def _clicked(self, action: str) -> None:
        self._on_action(self.index, action)

    def _box_changed(self, name: str, component: int | None, change: dict[str, Any]) -> None:
        self._typed(name, component, change["new"])

    def _typed(self, name: str, component: int | None, shown: Any) -> None:
        if self._quiet:
            return
        if name == "profile":
            self._on_edit(self.index, name, shown, None)
            return
        unit = self._units[name][component or 0]
        self._on_edit(self.index, name, self._unit_view().to_core(float(shown), unit), component)

    def _unit_view(self) -> Units:
        look = self._look
        return look[3] if look is not None else Units()

    def _kind_changed(self, change: dict[str, Any]) -> None:
        if not self._quiet:
            self._on_edit(self.index, "kind", change["new"], None)


_TEACH_TIPS = {
    "PTP": "teach: the robot's current coordinates become this move's target",
    "LIN": "teach: where the end effector is now becomes this line's end",
    "CIRC": "teach: where the end effector is now becomes this arc's end",
    "Wait": "a Wait has no target",
}


def _target_kind(move: Move) -> str:
    if isinstance(move, PTP):
        return "q" if move.q is not None else "point"
    target = move.end if isinstance(move, CIRC) else getattr(move, "pose", None)
    return "pose" if target is not None and np.shape(target) == (4, 4) else ""


def _coordinate_unit(robot: Robot, i: int) -> str:
    return robot.modules[i].unit if i < robot.n else ""  # type: ignore[attr-defined,no-any-return]


def _caption(text: str) -> widgets.HTML:
    return widgets.HTML(
        f"<small>{html.escape(text)}</small>", layout=widgets.Layout(margin="0 2px 0 6px")
    )
