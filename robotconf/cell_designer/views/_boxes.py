"""Number boxes in the designer's units, and what a student's input in one means.

Every number the tables show is a core number (radians, length units) shown in the
designer's units: angles in degrees or radians, lengths in the cell's unit (named, never
converted), without float noise. What a student types or steps to comes back through
:func:`core_value`, so an angle typed as 30 in degree mode reaches the core as π/6.
"""

from __future__ import annotations

import math
from typing import Any

from ...kinematics import JOINT_UNITS
from ...panel.form import FormEvent, display_number, message, number, parse_number, text
from ...panel.state import Units
from ..state import POSE_FIELDS, Pose, pose_numbers
from ._messages import Messages

__all__ = ["ANGLE", "LENGTH", "box", "pose_boxes", "core_value", "length_step"]

#: The core's names of the two kinds of number.
ANGLE, LENGTH = JOINT_UNITS["revolute"], JOINT_UNITS["prismatic"]


def length_step(size: float) -> float:
    """The step of a length box's arrow keys: a hundredth of the cell's size, rounded
    down to a power of ten.

    >>> length_step(90.0), length_step(1.0)
    (0.1, 0.01)
    """
    return 10.0 ** math.floor(math.log10(max(size, 1e-12) / 100.0))


def box(
    key: str,
    value: float,
    unit: str,
    units: Units,
    messages: Messages,
    rev: str,
    *,
    step: float = 1.0,
    label: str = "",
    title: str = "",
    width: str = "64px",
    disabled: bool = False,
) -> dict[str, Any]:
    """A number box showing core ``value`` (core ``unit``: ``"rad"``, ``"length"`` or
    ``""``) in the designer's units, with its refusal beside it.

    >>> import math
    >>> spec = box("q", math.pi / 6, "rad", Units("mm", True), Messages(), "0")
    >>> spec["value"], spec["slider"]
    (30.0, False)
    """
    shown_step = 1.0 if unit == ANGLE and units.degrees else (0.01 if unit == ANGLE else step)
    error = messages.text(key)
    return number(
        key,
        display_number(units.to_shown(value, unit), shown_step),
        0.0,
        0.0,
        shown_step,
        slider=False,
        rev=rev,
        width=width,
        label=label,
        title=title,
        disabled=disabled,
        text=messages.typed(key) if error else None,
        note=message(error),
    )


def pose_boxes(
    prefix: str, pose: Pose, units: Units, messages: Messages, rev: str, step: float
) -> list[dict[str, Any]]:
    """x, y, z in the length unit, then roll, pitch, yaw in the angle unit: keys
    ``prefix.pose0`` … ``prefix.pose5``.

    >>> import robotconf as rc
    >>> from robotconf.cell_designer.state import pose_of
    >>> boxes = pose_boxes("e", pose_of(rc.pose([1, 2, 3])), Units("mm"), Messages(), "0", 0.1)
    >>> [b["value"] for b in boxes if b["type"] == "number"]
    [1.0, 2.0, 3.0, 0.0, 0.0, 0.0]
    """
    numbers = pose_numbers(pose)
    parts: list[dict[str, Any]] = [text(f"x, y, z [{units.length}]", tone="note")]
    for k, name in enumerate(POSE_FIELDS):
        if k == 3:
            parts.append(text(f"roll, pitch, yaw [{units.angle}]", tone="note"))
        unit = LENGTH if k < 3 else ANGLE
        # An angle in radians shows more digits than a length (1.570796 for 90 deg).
        width = "64px" if k < 3 else "80px"
        parts.append(
            box(
                f"{prefix}.pose{k}",
                numbers[k],
                unit,
                units,
                messages,
                rev,
                step=step,
                title=name,
                width=width,
            )
        )
    return parts


def core_value(event: FormEvent, unit: str, units: Units, field: str) -> float:
    """The core number a box's event stands for: typed text parsed (refused with a
    message naming ``field``) or the stepped value, converted from the designer's units.

    >>> core_value(FormEvent("q", "type", text="90"), "rad", Units("mm", True), "q1")
    1.5707963267948966
    """
    if event.event in ("type", "typing"):
        shown = parse_number(event.text or "", field)
    else:
        shown = float(event.value)
    return units.to_core(shown, unit)
