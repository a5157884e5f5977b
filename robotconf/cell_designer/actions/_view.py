"""Units, what the view draws, and a whole document loaded (a cell file).

The angle unit is the screen's (degrees or radians; the core's are radians); the length
unit is the cell's own ``unit``, a name saved in the cell file: switching either changes
no number.
"""

from __future__ import annotations

from dataclasses import dataclass

from ...panel.actions import check_length_unit
from ..state import DesignerDocument, DesignerState, ReachSetup
from ._base import Action

__all__ = ["SetAngleUnit", "SetLengthUnit", "ShowCapsules", "LoadDocument"]


@dataclass(frozen=True)
class SetAngleUnit(Action):
    """Show angles in degrees (``True``) or radians; nothing in the cell changes."""

    degrees: bool

    def apply(self, state: DesignerState) -> DesignerState:
        return state.replace(degrees=bool(self.degrees))


@dataclass(frozen=True)
class SetLengthUnit(Action):
    """Name the cell's length unit (``"mm"``, ``"m"`` …); no number changes.

    >>> SetLengthUnit("mm").apply(DesignerState()).units.length
    'mm'
    """

    unit: str

    def apply(self, state: DesignerState) -> DesignerState:
        unit = None if self.unit == "units" else check_length_unit(self.unit)
        document = state.document.with_cell(state.cell.with_unit(unit))
        return state.with_document(document)


@dataclass(frozen=True)
class ShowCapsules(Action):
    """Draw the robots' link capsules (what collisions are checked with) in the view."""

    shown: bool

    def apply(self, state: DesignerState) -> DesignerState:
        return state.replace(capsules=bool(self.shown))


@dataclass(frozen=True)
class LoadDocument(Action):
    """Another cell with its programs (a file): the selection, the map and the run go."""

    document: DesignerDocument

    def apply(self, state: DesignerState) -> DesignerState:
        self.document.cell.cell  # noqa: B018 - built (and so checked) before it is shown
        return state.replace(
            document=self.document, selected=None, reach=ReachSetup(), reach_map=None, run=None
        )
