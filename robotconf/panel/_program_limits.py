"""The Program tab's program-wide limits: joint speed and acceleration, path speed and
acceleration, in the panel's units.

A box shows the limit the program runs with: the value typed, else the core's default
for this robot (``Program.limits``: 1 rad/s and 2 rad/s² for revolute joints, a quarter
of the robot's size per second for paths, see docs/programs.md). Only a typed value
reaches the program's settings, so an untouched box keeps following the robot's size.
Revolute and sliding joints have a box each (a robot shows the boxes of the joints it
has); the core takes one value, or one per joint when both kinds are there.
"""

from __future__ import annotations

import html
from collections.abc import Callable, Iterator, Mapping
from functools import partial
from typing import Any

import ipywidgets as widgets
import numpy as np

from ..kinematics import Robot
from ..programs import Limits, Program, Wait
from ._callbacks import observe
from ._errors_display import ErrorLabel
from ._program_row import short_number
from ._units import ANGLE_UNIT, LENGTH_UNIT, Units

__all__ = ["LimitControls", "LIMIT_FIELDS", "joint_setting"]

#: (key, program setting, joint type or None, caption): the boxes, in order.
LIMIT_FIELDS = (
    ("joint_speed", "joint_speed", "revolute", "joint speed [{angle}/s]"),
    ("joint_accel", "joint_accel", "revolute", "joint accel [{angle}/s²]"),
    ("slide_speed", "joint_speed", "prismatic", "sliding joint speed [{length}/s]"),
    ("slide_accel", "joint_accel", "prismatic", "sliding joint accel [{length}/s²]"),
    ("cartesian_speed", "cartesian_speed", None, "path speed [{length}/s]"),
    ("cartesian_accel", "cartesian_accel", None, "path accel [{length}/s²]"),
)
_CORE_UNIT = {"revolute": ANGLE_UNIT, "prismatic": LENGTH_UNIT, None: LENGTH_UNIT}


def joint_setting(robot: Robot, given: Any, defaults: np.ndarray, kind: str, value: float) -> Any:
    """A joint limit with the joints of type ``kind`` set to ``value`` (core units).

    One number when the robot's joints are all of that kind, else one per joint (the
    other kind keeping what it had: ``given``, or the ``defaults`` in force).

    Examples
    --------
    >>> import robotconf as rc
    >>> joint_setting(rc.preset("paper"), None, np.ones(3), "revolute", 2.0)
    2.0
    >>> joint_setting(rc.preset("scara"), None, np.array([1, 1, 24, 1.0]), "revolute", 2.0)
    (2.0, 2.0, 24.0, 2.0)
    """
    types = np.array(robot.joint_types)
    if not np.isin(types, ("revolute", "prismatic")).any() or np.all(
        types[np.isin(types, ("revolute", "prismatic"))] == kind
    ):
        return float(value)
    current = defaults if given is None else np.broadcast_to(np.asarray(given, float), types.shape)
    values = np.array(current, dtype=float)
    values[types == kind] = value
    return tuple(float(v) for v in values)


class LimitControls:
    """Boxes for the program's limits, each with its error label.

    Parameters
    ----------
    on_edit : callable
        ``on_edit(setting, value)``: the user typed a limit; ``value`` is what
        :class:`~robotconf.programs.Program` takes for ``setting`` (core units).

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.programs import Program, Wait
    >>> robot, typed = rc.preset("paper"), []
    >>> controls = LimitControls(lambda *edit: typed.append(edit))
    >>> controls.show(robot, {}, Program(robot, [Wait(0.0)]).limits, Units("mm"))
    >>> controls.boxes["joint_speed"].value, controls.boxes["cartesian_speed"].value
    (57.2958, 22.5)
    >>> controls.boxes["joint_speed"].value = 90.0
    >>> typed  # degrees typed, radians for the core
    [('joint_speed', 1.5707963267948966)]
    """

    def __init__(self, on_edit: Callable[[str, Any], None]):
        self._on_edit = on_edit
        self._quiet = False
        self._robot: Robot | None = None
        self._settings: Mapping[str, Any] = {}
        self._defaults: Limits | None = None
        self._cached: tuple[Robot, Limits] | None = None  # defaults of a robot at q = 0
        self.units = Units()
        self.boxes: dict[str, widgets.FloatText] = {}
        self.captions: dict[str, widgets.HTML] = {}
        self.errors = {setting: ErrorLabel() for _, setting, _, _ in LIMIT_FIELDS}
        cells = []
        for key, _setting, _kind, _caption in LIMIT_FIELDS:
            box = widgets.FloatText(layout=widgets.Layout(width="76px"))
            box.add_class(f"robotconf-program-{key}")
            caption = widgets.HTML(layout=widgets.Layout(margin="0 4px 0 0"))
            observe(box, self._error_for(key), partial(self._box_changed, key))
            self.boxes[key], self.captions[key] = box, caption
            cells.append(
                widgets.HBox(
                    [caption, box], layout=widgets.Layout(align_items="center", margin="0 12px 0 0")
                )
            )
        self.cells = dict(zip(self.boxes, cells, strict=True))
        self.widget = widgets.VBox(
            [
                widgets.HBox(cells, layout=widgets.Layout(flex_flow="row wrap")),
                widgets.HBox([label.widget for label in self.errors.values()]),
            ]
        )

    def show(
        self, robot: Robot, settings: Mapping[str, Any], defaults: Limits, units: Units
    ) -> None:
        """Show the limits in force for ``robot``: typed ``settings``, else ``defaults``."""
        self._robot, self._settings, self._defaults, self.units = robot, settings, defaults, units
        types = list(robot.joint_types)
        self._quiet = True
        try:
            for key, setting, kind, caption in LIMIT_FIELDS:
                shown = kind is None or kind in types
                self.cells[key].layout.display = None if shown else "none"
                text = caption.format(angle=units.angle, length=units.length)
                self.captions[key].value = f"<small>{html.escape(text)}</small>"
                if shown:
                    value = self._in_force(setting, kind, types)
                    shown_value = units.to_shown(value, _CORE_UNIT[kind])
                    self.boxes[key].value = short_number(shown_value)
        finally:
            self._quiet = False

    def defaults(self, robot: Robot) -> Limits:
        """The core's default limits for ``robot`` (from its size and joint types)."""
        structure = robot.with_q(np.zeros(robot.n))
        if self._cached is None or self._cached[0] != structure:
            self._cached = (structure, Program(robot, [Wait(0.0)]).limits)
        return self._cached[1]

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)``: ``program.<setting>`` for each limit."""
        for setting, label in self.errors.items():
            yield f"program.{setting}", label

    def _in_force(self, setting: str, kind: str | None, types: list[str]) -> float:
        assert self._defaults is not None
        force = getattr(self._defaults, setting)
        given = self._settings.get(setting)
        if kind is None:
            return float(force if given is None else given)
        values = force if given is None else np.broadcast_to(np.asarray(given, float), len(types))
        return float(values[types.index(kind)])

    def _error_for(self, key: str) -> ErrorLabel:
        setting = next(s for k, s, _, _ in LIMIT_FIELDS if k == key)
        return self.errors[setting]

    def _box_changed(self, key: str, change: dict[str, Any]) -> None:
        self._typed(key, change["new"])

    def _typed(self, key: str, shown: float) -> None:
        if self._quiet or self._robot is None or self._defaults is None:
            return
        _, setting, kind, _ = next(field for field in LIMIT_FIELDS if field[0] == key)
        value = self.units.to_core(float(shown), _CORE_UNIT[kind])
        if kind is not None:
            defaults = getattr(self._defaults, setting)
            value = joint_setting(self._robot, self._settings.get(setting), defaults, kind, value)
        self._on_edit(setting, value)
