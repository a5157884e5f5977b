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

from collections.abc import Mapping
from typing import Any

import numpy as np

from ...kinematics import Robot
from ...programs import Limits, resolve_limits
from ..form import message, number, text
from ..state import Units

__all__ = ["LIMIT_FIELDS", "joint_setting", "default_limits", "limit_controls", "limit_value"]

#: (key, program setting, joint type or None, caption): the boxes, in order.
LIMIT_FIELDS = (
    ("joint_speed", "joint_speed", "revolute", "joint speed [{angle}/s]"),
    ("joint_accel", "joint_accel", "revolute", "joint accel [{angle}/s²]"),
    ("slide_speed", "joint_speed", "prismatic", "sliding joint speed [{length}/s]"),
    ("slide_accel", "joint_accel", "prismatic", "sliding joint accel [{length}/s²]"),
    ("cartesian_speed", "cartesian_speed", None, "path speed [{length}/s]"),
    ("cartesian_accel", "cartesian_accel", None, "path accel [{length}/s²]"),
)
_CORE_UNIT = {"revolute": "rad", "prismatic": "length", None: "length"}


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
    moving = np.isin(types, ("revolute", "prismatic"))
    if not moving.any() or np.all(types[moving] == kind):
        return float(value)
    current = defaults if given is None else np.broadcast_to(np.asarray(given, float), types.shape)
    values = np.array(current, dtype=float)
    values[types == kind] = value
    return tuple(float(v) for v in values)


def default_limits(robot: Robot) -> Limits:
    """The core's default limits for ``robot`` (from its size and joint types)."""
    return resolve_limits(robot, {})


def _in_force(robot: Robot, settings: Mapping[str, Any], setting: str, kind: str | None) -> float:
    force = getattr(default_limits(robot), setting)
    given = settings.get(setting)
    if kind is None:
        return float(force if given is None else given)
    types = list(robot.joint_types)
    values = force if given is None else np.broadcast_to(np.asarray(given, float), len(types))
    return float(values[types.index(kind)])


def _short(value: float) -> float:
    return float(f"{value:.6g}") if np.isfinite(value) else float(value)


def limit_controls(
    robot: Robot,
    settings: Mapping[str, Any],
    units: Units,
    feedback: Any,
    rev: str,
    refused: tuple[str, str] | None = None,
) -> list[dict[str, Any]]:
    """One box per limit the robot's joints have, showing the limit in force."""
    types = set(robot.joint_types)
    controls: list[dict[str, Any]] = []
    for key, setting, kind, caption in LIMIT_FIELDS:
        if kind is not None and kind not in types:
            continue
        value = units.to_shown(_in_force(robot, settings, setting, kind), _CORE_UNIT[kind])
        name = f"program.{key}"
        error = feedback.message(name)
        if not error and refused is not None and refused[0] == f"program.{setting}":
            error = refused[1]  # the core's refusal of the value in the table
        controls.append(
            number(
                name,
                _short(value),
                0.0,
                0.0,
                1.0,
                slider=False,
                rev=rev,
                width="76px",
                label=caption.format(angle=units.angle, length=units.length),
                text=feedback.typed(name) if error else None,
                note=message(error),
                css_class=f"robotconf-program-{key}",
            )
        )
    controls.append(text("(typed, or the core's defaults)", tone="note"))
    return controls


def limit_value(
    robot: Robot, settings: Mapping[str, Any], key: str, shown: float, units: Units
) -> tuple[str, Any]:
    """The program setting a typed limit box means: ``(setting, value in core units)``."""
    _, setting, kind, _ = next(field for field in LIMIT_FIELDS if field[0] == key)
    value: Any = units.to_core(float(shown), _CORE_UNIT[kind])
    if kind is not None:
        defaults = getattr(default_limits(robot), setting)
        value = joint_setting(robot, settings.get(setting), defaults, kind, value)
    return setting, value
