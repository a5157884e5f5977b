"""The panel's only contact with the core's JSON file format (robot + signals + settings,
and the Program tab's program).

The format, its validation and its error messages belong to the core
(:meth:`Robot.to_json <robotconf.Robot.to_json>`, :func:`robotconf.load_setup`); this
module only adapts them to the panel.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from typing import Any

from ...io import Setup, load_setup
from ...kinematics import Robot
from ...motion import SimulationSettings
from ...programs import Program
from ...signals import Signal

__all__ = ["setup_to_json", "setup_from", "setup_parts"]


def setup_to_json(
    robot: Robot,
    signals: Mapping[str, Signal],
    simulation: Mapping[str, Any] | SimulationSettings | None,
    program: Program | None = None,
) -> str:
    """The core's JSON text of a robot with its signals and time settings (and a program
    of this robot, written by :class:`robotconf.io.Setup`).

    The settings pass through :class:`~robotconf.motion.SimulationSettings`, so saving
    refuses what Run refuses (errors named ``simulation.dt`` etc.).

    >>> import robotconf as rc
    >>> from robotconf.programs import Wait
    >>> robot = rc.preset("paper")
    >>> text = setup_to_json(robot, {}, None, Program(robot, [Wait(1.0)]))
    >>> setup_parts(text)[3].moves
    (Wait(seconds=1.0),)
    """
    if isinstance(simulation, SimulationSettings):
        simulation = simulation.to_dict()  # Robot.to_json's signature names a mapping
    if program is None:
        return robot.to_json(signals=dict(signals), simulation=simulation)
    return Setup(robot, dict(signals), simulation, program).to_json()


def setup_from(
    source: str | bytes | os.PathLike[str],
) -> tuple[Robot, dict[str, Signal], dict[str, Any] | None]:
    """``(robot, signals, simulation)`` from a path or uploaded bytes, validated by the core."""
    return setup_parts(source)[:3]


def setup_parts(
    source: str | bytes | os.PathLike[str],
) -> tuple[Robot, dict[str, Signal], dict[str, Any] | None, Program | None]:
    """``(robot, signals, simulation, program)`` from a path, uploaded bytes or text,
    validated by the core (``program`` is ``None`` when the file holds none)."""
    setup = load_setup(source)
    simulation = None if setup.simulation is None else setup.simulate_kwargs()
    return setup.robot, dict(setup.signals), simulation, setup.program
