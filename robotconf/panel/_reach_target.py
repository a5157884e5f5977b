"""The Reach tab's target: x, y, z (+ roll, pitch, yaw for a pose) and the mode toggle.

Lengths are in the robot's own unit (the panel's length unit only names it); roll, pitch
and yaw are shown in the panel's angle unit and reach the core in radians (see
:mod:`robotconf.panel._reach_pose` for their meaning). Every control is a
:class:`~robotconf.panel._number_control.NumberControl`, so a value typed beyond a slider
widens it and an untouched box gives back the exact number it was given.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Iterator

import ipywidgets as widgets
import numpy as np

from .._errors import InvalidInputError
from ._callbacks import observe
from ._errors_display import ErrorLabel
from ._number_control import NumberControl
from ._ranges import length_step
from ._reach_pose import pose_from_xyz_rpy, xyz_rpy_from_pose
from ._units import Units

__all__ = ["TargetControls", "POSITION_FIELDS", "ANGLE_FIELDS"]

POSITION_FIELDS = ("x", "y", "z")
ANGLE_FIELDS = ("roll", "pitch", "yaw")

_MODES = (("position", "position"), ("pose", "pose"))


class TargetControls:
    """Six number controls for a target point or pose, and the position/pose toggle.

    Parameters
    ----------
    on_change : callable
        ``on_change(field)`` after the user moves a control (``"x"`` … ``"yaw"``) or the
        mode (``"mode"``).
    scale : float
        Slider half-range for lengths (the robot's size, see ``_ranges.length_scale``).
    units : Units
        The panel's units.

    Examples
    --------
    >>> changed = []
    >>> target = TargetControls(changed.append, 100.0, Units("mm", True))
    >>> target.set_pose(np.eye(4))
    >>> target.controls["x"].box.value = 30.0
    >>> changed, target.target()
    (['x'], array([30.,  0.,  0.]))
    >>> target.mode.value = "pose"
    >>> target.controls["yaw"].box.value = 90.0  # degrees
    >>> target.target().round(12)[:2, :2] + 0.0
    array([[ 0., -1.],
           [ 1.,  0.]])
    """

    def __init__(self, on_change: Callable[[str], None], scale: float, units: Units):
        self._on_change = on_change
        self._units = units
        step = length_step(scale)
        self.controls: dict[str, NumberControl] = {}
        for name in POSITION_FIELDS:
            self.controls[name] = NumberControl(
                name,
                0.0,
                -scale,
                scale,
                unit=units.length,
                on_change=functools.partial(self._changed, name),
                label_width="40px",
                length_step=step,
            )
        for name in ANGLE_FIELDS:
            self.controls[name] = NumberControl(
                name,
                0.0,
                -180.0 if units.degrees else -math.pi,
                180.0 if units.degrees else math.pi,
                angle=True,
                degrees=units.degrees,
                on_change=functools.partial(self._changed, name),
                label_width="40px",
            )
        for name, control in self.controls.items():
            control.slider.add_class(f"robotconf-reach-{name}")
            control.box.add_class(f"robotconf-reach-{name}-box")
        self.mode = widgets.ToggleButtons(
            options=_MODES,
            value="position",
            tooltips=[
                "reach a point: the end-effector's position only",
                "reach a pose: position and orientation (roll, pitch, yaw)",
            ],
            style={"button_width": "72px"},
        )
        self.mode.add_class("robotconf-reach-mode")
        self.mode_error = ErrorLabel()
        observe(self.mode, self.mode_error, self._mode_changed)
        self._angles = widgets.VBox([self.controls[name].widget for name in ANGLE_FIELDS])
        positions = widgets.VBox([self.controls[name].widget for name in POSITION_FIELDS])
        # Side by side where the output is wide enough (two 340-px columns), else stacked.
        self.widget = widgets.HBox(
            [positions, self._angles], layout=widgets.Layout(flex_flow="row wrap")
        )
        self._show_angles()

    @property
    def is_pose(self) -> bool:
        """Whether the target is a pose (orientation too) rather than a point."""
        return self.mode.value == "pose"

    def target(self) -> np.ndarray:
        """The target in core units: a point (3,) or, in pose mode, a pose (4, 4).

        Raises
        ------
        InvalidInputError
            Naming the control that holds NaN or infinity (``target.x`` …).
        """
        values = {}
        for name, control in self._active():
            value = control.core_value
            if not math.isfinite(value):
                error = InvalidInputError(
                    f"target.{name}", value, "a finite number", problem="not a number:"
                )
                control.error.show(str(error))
                raise error
            control.error.clear()
            values[name] = value
        xyz = [values[name] for name in POSITION_FIELDS]
        if not self.is_pose:
            return np.array(xyz)
        return pose_from_xyz_rpy(xyz, [values[name] for name in ANGLE_FIELDS])

    def set_pose(self, pose: np.ndarray) -> None:
        """Show a pose's point and angles (no change callback)."""
        point, rpy = xyz_rpy_from_pose(pose)
        for name, value in zip(POSITION_FIELDS, point, strict=True):
            self.controls[name].set_core_value(float(value))
        for name, value in zip(ANGLE_FIELDS, rpy, strict=True):
            self.controls[name].set_core_value(float(value))

    def set_orientation(self, pose: np.ndarray) -> None:
        """Show a pose's roll, pitch and yaw, keeping x, y, z (no change callback)."""
        _, rpy = xyz_rpy_from_pose(pose)
        for name, value in zip(ANGLE_FIELDS, rpy, strict=True):
            self.controls[name].set_core_value(float(value))

    def set_scale(self, scale: float) -> None:
        """Slider ranges and steps for a robot of another size (values kept)."""
        for name in POSITION_FIELDS:
            control = self.controls[name]
            control.set_length_step(length_step(scale))
            control.set_range(-scale, scale)

    def set_units(self, units: Units) -> None:
        """Name the length unit, show angles in degrees or radians; the target stays."""
        self._units = units
        for name, control in self.controls.items():
            if name in POSITION_FIELDS:  # the unit's name only: lengths are never converted
                control.set_angle(False, control.slider.min, control.slider.max, unit=units.length)
            else:
                control.set_degrees(units.degrees)

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)``: ``reach.mode`` and ``reach.target.x`` … ``reach.target.yaw``."""
        yield "reach.mode", self.mode_error
        for name, control in self.controls.items():
            yield f"reach.target.{name}", control.error

    def _active(self) -> Iterator[tuple[str, NumberControl]]:
        names = POSITION_FIELDS + (ANGLE_FIELDS if self.is_pose else ())
        for name in names:
            yield name, self.controls[name]

    def _show_angles(self) -> None:
        self._angles.layout.display = "" if self.is_pose else "none"

    def _changed(self, name: str, _: NumberControl) -> None:
        self._on_change(name)

    def _mode_changed(self, _: object) -> None:
        self._show_angles()
        self._on_change("mode")
