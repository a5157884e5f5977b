"""Programs in the cell: moves that name cell frames, and every robot's program run at once.

A move's ``frame`` (``rc.LIN(frame="table/pick")``) is the pose of that cell frame for the
robot's TCP, written in the robot's base frame (:func:`~robotconf.cell._entries.target_in_base`);
the program itself runs on the robot whose end effector is the TCP. Points and poses
given directly in moves stay in the robot's base frame, as in any
:class:`~robotconf.programs.Program`.
"""

from __future__ import annotations

import warnings
from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_finite_number, one_line
from ..programs import Move, Program, ProgramMotion
from ._answers import CellRun
from ._check import check
from ._entries import planning_robot, target_in_base

if TYPE_CHECKING:
    from ._cell import Cell

__all__ = ["cell_program", "run"]


def cell_program(cell: Cell, robot: Any, moves: Any, **options: Any) -> Program:
    """A program for a robot of the cell, its frame targets resolved.

    Parameters
    ----------
    cell : Cell
    robot : str or None
    moves : list of moves
        As for :class:`~robotconf.programs.Program`; ``frame=`` names a cell frame.
    **options
        The program's options (``start``, ``joint_speed``, …).

    Examples
    --------
    >>> import robotconf as rc
    >>> cell = rc.Cell()
    >>> cell.add_robot("arm", rc.preset("paper"), base=rc.pose([100, 0, 0]))
    >>> cell.add_frame("pick", rc.pose([150, 10, 30]))
    'pick'
    >>> moves = [rc.PTP(q=[0, 0.3, -0.5]), rc.LIN(frame="pick", speed=10, accel=5)]
    >>> prog = cell.program("arm", moves)
    >>> prog.simulate(0.01).trace[-1].round(9) + 0.0  # in the robot's base frame
    array([50., 10., 30.])
    """
    entry = cell.robot_entry(robot)
    if not isinstance(moves, (list, tuple)):
        raise InvalidInputError("moves", one_line(moves), "a list of moves")
    base = cell.pose_of(entry.name)

    def lookup(name: str) -> np.ndarray:
        if name not in cell.frames and name not in cell.entries:
            raise InvalidInputError(
                "frame",
                name,
                f"a frame of the cell: {list(cell.frames)[:20]}",
                problem="no such frame:",
            )
        return target_in_base(entry, base, cell.pose_of(name))

    resolved = []
    for i, move in enumerate(moves):
        try:
            resolved.append(move.resolved(lookup) if isinstance(move, Move) else move)
        except InvalidInputError as error:
            raise error.within(f"moves[{i}]") from None
    return Program(planning_robot(entry), resolved, **options)


def run(cell: Cell, programs: Any, *, dt: Any = 0.01, margin: Any = 0.0) -> CellRun:
    """Plan every robot's program, check contacts side by side, report the cycle time.

    Parameters
    ----------
    cell : Cell
    programs : dict
        ``{robot name: Program or list of moves}`` (moves may name cell frames).
    dt : float
        Sampling step (s).
    margin : float
        Contact distance (length units).

    Examples
    --------
    >>> import robotconf as rc
    >>> cell = rc.Cell(unit="mm")
    >>> cell.add_robot("a", rc.preset("paper"))
    >>> cell.add_robot("b", rc.preset("paper"), base=rc.pose([200, 0, 0], [0, 0, np.pi]))
    >>> result = cell.run({"a": [rc.PTP(q=[0, 0, -0.3])], "b": [rc.Wait(1.0)]})
    >>> result.cycle_time, result.check.ok
    (1.0, True)
    """
    step = check_finite_number(dt, "dt")
    if not isinstance(programs, dict) or not programs:
        raise InvalidInputError(
            "programs", one_line(programs), "{robot name: Program or list of moves}"
        )
    built: dict[str, Program] = {}
    for name, value in programs.items():
        entry = cell.robot_entry(name)
        if isinstance(value, Program):
            built[entry.name] = value
        else:
            try:
                built[entry.name] = cell_program(cell, entry.name, value)
            except InvalidInputError as error:
                raise error.within(f"programs[{name!r}]") from None
    motions: dict[str, ProgramMotion] = {}
    for name, program in built.items():
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # violations are kept in the reports
            motions[name] = program.simulate(step)
    reports = {name: m.report for name, m in motions.items()}
    result = check(cell, dict(motions), margin=margin)
    cycle = max(p.duration for p in built.values())
    return CellRun(built, motions, reports, result, cycle)
