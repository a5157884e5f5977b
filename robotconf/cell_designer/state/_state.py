"""The designer's one state: the document (the cell and its programs), and what is only on
screen (the angle unit, the selection, the capsules, the reach map, the last run).

Undo and redo step through :class:`DesignerDocument` values, which are also what the
bound cell file holds; the rest of :class:`DesignerState` is the view of that document.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import Any

from ...cell import CellRun, ReachMap
from ...panel.state import Units
from ._description import CellDescription
from ._programs import RobotProgram, renamed_frames

__all__ = ["DesignerDocument", "DesignerState", "ReachSetup", "ReachOutcome", "RunOutcome"]


@dataclass(frozen=True)
class DesignerDocument:
    """What the cell file holds and undo steps through: the cell and each robot's program.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.programs import Wait
    >>> cell = rc.Cell()
    >>> cell.add_robot("arm", rc.preset("paper"))
    >>> document = DesignerDocument(CellDescription.from_cell(cell))
    >>> document = document.with_program("arm", RobotProgram((Wait(1.0),)))
    >>> document.program("arm").moves
    (Wait(seconds=1.0),)
    """

    cell: CellDescription = field(default_factory=CellDescription)
    programs: tuple[tuple[str, RobotProgram], ...] = ()

    def program(self, robot: str) -> RobotProgram:
        """The robot's program (empty when it has none)."""
        return dict(self.programs).get(robot, RobotProgram())

    def with_program(self, robot: str, program: RobotProgram) -> DesignerDocument:
        """One robot's program replaced (an empty one and its options go)."""
        programs = dict(self.programs)
        if program.moves:
            programs[robot] = program
        else:
            programs.pop(robot, None)
        return replace(self, programs=self._ordered(programs, self.cell))

    def with_cell(
        self, cell: CellDescription, renames: Mapping[str, str] | None = None
    ) -> DesignerDocument:
        """Another cell; programs follow renamed robots and frames, a removed robot's goes."""
        renames = renames or {}
        programs = {
            renames.get(robot, robot): renamed_frames(program, renames)
            for robot, program in self.programs
        }
        return DesignerDocument(cell, self._ordered(programs, cell))

    @staticmethod
    def _ordered(
        programs: Mapping[str, RobotProgram], cell: CellDescription
    ) -> tuple[tuple[str, RobotProgram], ...]:
        return tuple((r, programs[r]) for r in cell.robots if r in programs)

    def file_programs(self) -> dict[str, tuple[Any, dict[str, Any]]]:
        """``{robot: (moves, options)}`` as the cell file keeps them."""
        return {robot: (p.moves, p.options) for robot, p in self.programs}

    @property
    def units_length(self) -> str:
        """The name of the cell's length unit (``"units"`` when it has none)."""
        return self.cell.unit or "units"


@dataclass(frozen=True)
class ReachSetup:
    """The reach map's controls: on or off, the robot, the region's corners, the step.

    ``None`` for a corner or the step: the default around the robot
    (:func:`robotconf.cell_designer.actions.default_region`).
    """

    on: bool = False
    robot: str | None = None
    low: tuple[float, float, float] | None = None
    high: tuple[float, float, float] | None = None
    step: float | None = None


@dataclass(frozen=True)
class ReachOutcome:
    """A reach map and what it was computed for (the cell and the controls)."""

    result: ReachMap
    cell: CellDescription
    setup: ReachSetup

    def stale(self, cell: CellDescription) -> bool:
        """Whether the cell changed since this map."""
        return cell != self.cell


@dataclass(frozen=True)
class RunOutcome:
    """The last Run: the core's :class:`~robotconf.cell.CellRun`, the document it ran."""

    run: CellRun
    document: DesignerDocument
    dt: float

    def stale(self, document: DesignerDocument) -> bool:
        """Whether the cell or a program changed since this run."""
        return document != self.document


@dataclass(frozen=True)
class DesignerState:
    """Everything the designer shows, as one immutable value.

    Attributes
    ----------
    document : DesignerDocument
        The cell and the programs (undo, redo, the bound file).
    degrees : bool
        Angles shown in degrees (else radians); the core's are radians.
    selected : str or None
        The entry highlighted in the table and the view.
    capsules : bool
        The robots' link capsules drawn in the view.
    reach : ReachSetup
    reach_map : ReachOutcome or None
        The last map computed (kept while it is switched off, for a quick way back).
    run : RunOutcome or None
    run_dt : float
        Sampling step of Run (s).
    """

    document: DesignerDocument = field(default_factory=DesignerDocument)
    degrees: bool = True
    selected: str | None = None
    capsules: bool = False
    reach: ReachSetup = field(default_factory=ReachSetup)
    reach_map: ReachOutcome | None = None
    run: RunOutcome | None = None
    run_dt: float = 0.01

    @property
    def cell(self) -> CellDescription:
        """The document's cell."""
        return self.document.cell

    @property
    def units(self) -> Units:
        """The units on screen: the cell's length unit (named) and degrees or radians."""
        return Units(self.document.units_length, self.degrees)

    def with_document(self, document: DesignerDocument) -> DesignerState:
        """The same view of another document (a selection that went is dropped)."""
        selected = self.selected if self.selected in document.cell.names else None
        robot = self.reach.robot
        reach = self.reach if robot is None or robot in document.cell.robots else ReachSetup()
        return replace(self, document=document, selected=selected, reach=reach)

    def replace(self, **changes: Any) -> DesignerState:
        """A copy with some fields changed."""
        return replace(self, **changes)
