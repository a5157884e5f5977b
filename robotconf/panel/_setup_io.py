"""The panel's only contact with the core's JSON file format (robot + signals + settings).

The format, its validation and its error messages belong to the core
(:meth:`Robot.to_json <robotconf.Robot.to_json>`, :func:`robotconf.load_setup`); this
module only adapts them to the panel.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from typing import Any

from ..io import load_setup
from ..kinematics import Robot
from ..motion import SimulationSettings
from ..signals import Signal

__all__ = ["setup_to_json", "setup_from"]


def setup_to_json(
    robot: Robot,
    signals: Mapping[str, Signal],
    simulation: Mapping[str, Any] | SimulationSettings | None,
) -> str:
    """The core's JSON text of a robot with its signals and time settings.

    The settings pass through :class:`~robotconf.motion.SimulationSettings`, so saving
    refuses what Run refuses (errors named ``simulation.dt`` etc.).
    """
    if isinstance(simulation, SimulationSettings):
        simulation = simulation.to_dict()  # Robot.to_json's signature names a mapping
    return robot.to_json(signals=dict(signals), simulation=simulation)


def setup_from(
    source: str | bytes | os.PathLike[str],
) -> tuple[Robot, dict[str, Signal], dict[str, Any] | None]:
    """``(robot, signals, simulation)`` from a path or uploaded bytes, validated by the core."""
    setup = load_setup(source)
    simulation = None if setup.simulation is None else setup.simulate_kwargs()
    return setup.robot, dict(setup.signals), simulation
