"""The units the panel shows, chosen once: a length unit and degrees or radians.

The core has no length unit (a robot's numbers are in whatever unit its author used) and
always works in radians. The panel's length unit therefore only *names* the robot's unit
in every label, table header and axis, while the angle unit converts: angles, angular
rates and signal values of revolute coordinates are shown and typed in degrees and
reach the core in radians. The conversion happens only here and in the controls that
show numbers, so every number on screen is one core call times at most ``180/π``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ...kinematics import JOINT_UNITS

__all__ = ["Units", "LENGTH_UNITS", "ANGLE_UNIT", "LENGTH_UNIT"]

#: Length units offered; ``"units"`` names none (the paper's plain length units).
LENGTH_UNITS = ("units", "mm", "cm", "m", "in")
#: How the core names the unit of a revolute and of a prismatic coordinate.
ANGLE_UNIT, LENGTH_UNIT = JOINT_UNITS["revolute"], JOINT_UNITS["prismatic"]
#: Per-second suffixes of a rate's unit: value, velocity, acceleration.
_PER_SECOND = ("", "/s", "/s²")


@dataclass(frozen=True)
class Units:
    """A length unit name and the angle unit.

    Parameters
    ----------
    length : str
        The robot's length unit as labels show it (``"mm"``, ``"m"``, ``"units"`` …);
        lengths are never converted.
    degrees : bool
        Angles in degrees (``True``) or radians.

    Examples
    --------
    >>> units = Units("mm", degrees=True)
    >>> units.quantity("velocity"), units.quantity("angular_velocity")
    ('mm/s', 'deg/s')
    >>> units.coordinate("rad", 2), units.coordinate("length", 1)
    ('deg/s²', 'mm/s')
    >>> units.to_core(30.0, "rad")  # 30° typed reaches the core in radians
    0.5235987755982988
    """

    length: str = "units"
    degrees: bool = True

    @property
    def angle(self) -> str:
        """``"deg"`` or ``"rad"``."""
        return "deg" if self.degrees else "rad"

    def coordinate(self, unit: str, order: int = 0) -> str:
        """Unit label of a coordinate (core unit ``"rad"`` or ``"length"``) or of its
        ``order``-th time derivative (1: per second, 2: per second squared).

        A link without a joint (core unit ``""``) has no unit.
        """
        base = {ANGLE_UNIT: self.angle, LENGTH_UNIT: self.length}.get(unit, "")
        return base + _PER_SECOND[order] if base else ""

    def quantity(self, name: str) -> str:
        """Unit label of a column of :attr:`Motion.table <robotconf.Motion.table>`."""
        if name == "angular_velocity":
            return self.angle + "/s"
        order = {"velocity": 1, "acceleration": 2}.get(name, 0)
        return self.length + _PER_SECOND[order]

    def scale(self, unit: str) -> float:
        """Shown number per core number for a quantity in core unit ``unit``:
        ``180/π`` for angles (and their rates) in degrees, else 1."""
        return 180.0 / math.pi if unit == ANGLE_UNIT and self.degrees else 1.0

    def to_core(self, shown: float, unit: str) -> float:
        """A number typed in the panel's units as the core takes it (radians, length)."""
        return math.radians(shown) if unit == ANGLE_UNIT and self.degrees else float(shown)

    def to_shown(self, core: float, unit: str) -> float:
        """A core number (radians, length) in the panel's units."""
        return math.degrees(core) if unit == ANGLE_UNIT and self.degrees else float(core)
