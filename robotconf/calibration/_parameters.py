"""The robot parameters a calibration may identify, by name.

A parameter is named ``"<module>.<key>"``, the module as :meth:`Robot.index` knows it (its
display name ``M2``, its own name, or its coordinate ``q2``):

- a link's own numbers: a module's offsets ``ax``, ``ay``, ``az`` (length), a DH row's
  ``theta``, ``alpha`` (rad), ``d``, ``a`` (length);
- ``offset``: a joint's zero offset, the amount its reading is off (rad or length): the
  robot's true coordinate is ``q + offset``;
- ``EE.x``, ``EE.y``, ``EE.z``: the end-effector point (length).

A pair ``(module, key)`` works as well, inside the list of parameters.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import one_line
from ..kinematics import DHLink, Robot

__all__ = ["Parameter", "read_parameters", "default_parameters", "apply", "MAX_PARAMETERS"]

#: The most parameters one calibration identifies (every number of a 64-link robot).
MAX_PARAMETERS = 400

_EE_KEYS = ("x", "y", "z")
_ANGLES = ("theta", "alpha")


@dataclass(frozen=True)
class Parameter:
    """One parameter: its ``name``, where it lives and whether it is an angle.

    ``kind`` is ``"link"`` (``key`` one of the link's :meth:`parameters`), ``"offset"``
    (a joint's zero offset) or ``"end_effector"`` (``key`` x, y or z); ``index`` is the
    module's 0-based position (n for the end effector).
    """

    name: str
    kind: str
    index: int
    key: str
    angle: bool

    def value(self, robot: Robot) -> float:
        """The parameter's value in ``robot`` (joint offsets start at 0)."""
        if self.kind == "end_effector":
            return float(robot.end_effector_point[_EE_KEYS.index(self.key)])
        if self.kind == "offset":
            return 0.0
        return float(robot.modules[self.index].parameters()[self.key])


def _allowed(robot: Robot) -> str:
    return (
        "'<module>.<key>' with a module name or number known to the robot (M1, q1, …) and "
        "a key: ax, ay, az (modules), theta, d, a, alpha (DH rows), offset (a joint's zero "
        "offset); or EE.x, EE.y, EE.z"
    )


def _one(robot: Robot, spec: Any, field: str) -> Parameter:
    if isinstance(spec, str):
        module, dot, key = spec.rpartition(".")
        if not dot:
            raise InvalidInputError(field, spec, _allowed(robot), problem="no '.key' in")
    elif isinstance(spec, tuple) and len(spec) == 2 and isinstance(spec[1], str):
        module, key = spec
    else:
        raise InvalidInputError(field, one_line(spec), _allowed(robot), problem="not a parameter:")
    key = key.strip()
    if isinstance(module, str) and module.strip().upper() == "EE":
        if key.lower() not in _EE_KEYS:
            raise InvalidInputError(field, spec, _allowed(robot), problem="unknown key:")
        return Parameter(f"EE.{key.lower()}", "end_effector", robot.n, key.lower(), False)
    index = robot.index(module, field)
    link = robot.modules[index]
    label = robot.module_names[index]
    if key == "offset":
        joint = link.joint_type
        if joint not in ("revolute", "prismatic"):
            raise InvalidInputError(
                field, spec, "the offset of a joint", problem=f"{label} is not a joint ({joint}):"
            )
        return Parameter(f"{label}.offset", "offset", index, key, joint == "revolute")
    keys = tuple(link.parameters())
    if key not in keys:
        raise InvalidInputError(
            field,
            spec,
            f"for {label}: {', '.join(keys)} or offset",
            problem=f"not a parameter of {label}:",
        )
    angle = isinstance(link, DHLink) and key in _ANGLES
    return Parameter(f"{label}.{key}", "link", index, key, angle)


def read_parameters(robot: Robot, specs: Any) -> tuple[Parameter, ...]:
    """The parameters named by ``specs`` (a list of names or ``(module, key)`` tuples).

    >>> from robotconf.presets import preset
    >>> [p.name for p in read_parameters(preset("paper"), ["M2.az", ("q3", "ax"), "EE.x"])]
    ['M2.az', 'M3.ax', 'EE.x']
    """
    allowed = f"a list of 1 to {MAX_PARAMETERS} parameter names"
    if isinstance(specs, str):
        specs = [specs]
    if not isinstance(specs, Sequence):
        raise InvalidInputError("parameters", one_line(specs), allowed, problem="not a list:")
    if not 1 <= len(specs) <= MAX_PARAMETERS:
        raise InvalidInputError(
            "parameters", f"<{len(specs)} names>", allowed, problem="wrong number of names:"
        )
    out = [_one(robot, spec, f"parameters[{i}]") for i, spec in enumerate(specs)]
    names = [p.name for p in out]
    for i, name in enumerate(names):
        if name in names[:i]:
            raise InvalidInputError(
                f"parameters[{i}]", name, "each parameter once", problem="named twice:"
            )
    return tuple(out)


def default_parameters(robot: Robot) -> tuple[Parameter, ...]:
    """Every number of the robot's active links, then the end-effector point.

    >>> from robotconf.presets import preset
    >>> len(default_parameters(preset("paper")))  # 3 modules × 3 offsets + 3
    12
    """
    names = [
        f"{label}.{key}"
        for label, link in zip(robot.module_names[: robot.active], robot.modules, strict=False)
        for key in link.parameters()
    ]
    return read_parameters(robot, [*names, "EE.x", "EE.y", "EE.z"])


def apply(
    robot: Robot, parameters: Sequence[Parameter], values: np.ndarray
) -> tuple[Robot, np.ndarray]:
    """The robot with the parameters set to ``values``, and the joint offsets (n,)."""
    offsets = np.zeros(robot.n)
    changes: dict[int, dict[str, float]] = {}
    point = robot.end_effector_point.copy()
    for parameter, value in zip(parameters, values, strict=True):
        if parameter.kind == "offset":
            offsets[parameter.index] = value
        elif parameter.kind == "end_effector":
            point[_EE_KEYS.index(parameter.key)] = value
        else:
            changes.setdefault(parameter.index, {})[parameter.key] = float(value)
    out = robot
    for index, change in changes.items():
        out = out.with_module(index, robot.modules[index].with_parameters(**change))
    if not np.array_equal(point, robot.end_effector_point):
        out = out.with_end_effector(point)
    return out, offsets
