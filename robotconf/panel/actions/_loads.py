"""Another robot altogether: a preset, a robot from code, a setup file.

Each is one undo step. A new robot starts the Reach target again from its end effector;
the signals stay with their coordinates by position, as far as the new robot has them.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from ..._errors import InvalidInputError
from ...kinematics import Robot
from ...presets import preset
from ..state import Document, MotionSetup, PanelState
from ..state._program_draft import draft_of
from ._base import Action, with_robot

__all__ = ["LoadPreset", "LoadRobot", "LoadSetup"]


@dataclass(frozen=True)
class LoadPreset(Action):
    """Show the core's preset ``name`` (``rc.preset(name)``).

    >>> import robotconf as rc
    >>> state = LoadPreset("puma560").apply(PanelState.start(rc.preset("paper")))
    >>> state.robot == rc.preset("puma560"), state.document.motion.signals
    (True, (None, None, None, None, None, None))
    """

    name: str

    def apply(self, state: PanelState) -> PanelState:
        return with_robot(state, preset(self.name), new_robot=True)


@dataclass(frozen=True)
class LoadRobot(Action):
    """Show ``robot`` (from a cell: ``panel.set_robot(robot)``, or the guided mode)."""

    robot: Robot

    def apply(self, state: PanelState) -> PanelState:
        if not isinstance(self.robot, Robot):
            raise InvalidInputError("robot", self.robot, "a robotconf Robot")
        return with_robot(state, self.robot, new_robot=True).replace(wizard=None)


@dataclass(frozen=True)
class LoadSetup(Action):
    """Show a saved setup: the robot with its q, its signals, time settings and program.

    ``signals`` are by coordinate name, ``simulation`` as the file holds it (``None``:
    keep the panel's time settings), ``program`` a core :class:`~robotconf.Program` or
    ``None``.
    """

    robot: Robot
    signals: Mapping[str, Any] = field(default_factory=dict)
    simulation: Mapping[str, Any] | None = None
    program: Any = None

    def apply(self, state: PanelState) -> PanelState:
        if not isinstance(self.robot, Robot):
            raise InvalidInputError("robot", self.robot, "a robotconf Robot")
        settings = state.document.motion.settings.to_dict()
        # A file without a start time starts at 0, whatever the last one had.
        settings["t0"] = 0.0
        settings.update(self.simulation or {})
        motion = MotionSetup.loaded(self.robot.coordinate_names, self.signals, settings)
        loaded = with_robot(state, self.robot, new_robot=True).replace(wizard=None)
        return loaded.replace(document=Document(self.robot, motion, draft_of(self.program)))
