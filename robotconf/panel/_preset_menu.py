"""The preset dropdown: loads a preset, and names the robot when it is one.

The dropdown reads a preset's name whenever the panel's robot *is* that preset (equal as
robots: same links, coordinates, end-effector and name), however it got there — chosen
here, loaded from a file, brought back by undo — and "— preset —" as soon as an edit
makes it another robot.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import ipywidgets as widgets

from ..kinematics import Robot
from ..presets import preset, preset_names
from ._callbacks import observe
from ._errors_display import ErrorLabel

__all__ = ["PresetMenu", "NO_PRESET"]

#: The entry shown when the robot is no preset.
NO_PRESET = ("— preset —", "")


class PresetMenu:
    """A dropdown of the core's presets that follows the robot.

    Parameters
    ----------
    robot : Robot
        The robot shown first.
    on_load : callable
        Receives the preset's robot when the user chooses one.
    current : callable
        Returns the panel's robot (choosing "— preset —" changes nothing).

    Examples
    --------
    >>> import robotconf as rc
    >>> loaded = []
    >>> menu = PresetMenu(rc.preset("paper"), loaded.append, lambda: rc.preset("paper"))
    >>> menu.dropdown.value
    'paper'
    >>> menu.dropdown.value = "scara"
    >>> loaded[0].name
    'SCARA'
    >>> menu.show(loaded[0].with_q([0.1, 0, 0, 0])); menu.dropdown.value
    ''
    """

    def __init__(
        self, robot: Robot, on_load: Callable[[Robot], None], current: Callable[[], Robot]
    ):
        self._on_load = on_load
        self._current = current
        self._names = tuple(preset_names())
        self._robots: dict[str, Robot] | None = None  # built on first use, then kept
        self.error = ErrorLabel()
        self.dropdown = widgets.Dropdown(
            options=[NO_PRESET, *((n, n) for n in self._names)],
            value=self.name_of(robot),
            description="preset",
            disabled=not self._names,
            layout=widgets.Layout(width="220px"),
        )
        self._handler = observe(self.dropdown, self.error, self._chosen)

    def name_of(self, robot: Robot) -> str:
        """The name of the preset ``robot`` is, or ``""``.

        >>> import robotconf as rc
        >>> menu = PresetMenu(rc.preset("paper"), print, rc.preset("paper").with_name)
        >>> menu.name_of(rc.preset("puma560")), menu.name_of(rc.preset("puma560").with_name("x"))
        ('puma560', '')
        """
        if self._robots is None:
            self._robots = {name: preset(name) for name in self._names}
        for name, candidate in self._robots.items():
            # The name comparison first: most robots are no preset, and it is cheap.
            if candidate.name == robot.name and candidate == robot:
                return name
        return ""

    def show(self, robot: Robot) -> None:
        """Name ``robot``'s preset in the dropdown, or "— preset —" (no load)."""
        name = self.name_of(robot)
        if name != self.dropdown.value:
            with self._handler.paused():
                self.dropdown.value = name

    def _chosen(self, change: dict[str, Any]) -> None:
        name = change["new"]
        if not name:
            self.show(self._current())  # "— preset —" is a reading, not an action
            return
        self._on_load(preset(name))
        self.show(self._current())
