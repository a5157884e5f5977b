"""What every designer action is: a small frozen value with ``apply(state) -> state``.

An action names one thing the student did (``SetPose("table", 2, -5.0)``); it gives the
next :class:`~robotconf.cell_designer.state.DesignerState` in one step, or raises the
core's :class:`~robotconf.InvalidInputError` (the designer then shows it beside the
control and keeps its state). Actions never touch a widget.
"""

from __future__ import annotations

import math
from collections.abc import Hashable

from ...kinematics import characteristic_length
from ..state import DesignerDocument, DesignerState, RobotItem

__all__ = ["Action", "cell_size", "nice", "with_document"]


class Action:
    """One user action on the designer's state.

    Subclasses are frozen dataclasses with an :meth:`apply`; :attr:`gesture` says which
    edits belong to one undo step (``None``: always its own).
    """

    def apply(self, state: DesignerState) -> DesignerState:  # pragma: no cover - abstract
        """The state after this action.

        Raises
        ------
        InvalidInputError
            The core refuses the result; the state stays as it was.
        """
        raise NotImplementedError

    @property
    def gesture(self) -> Hashable | None:
        """Edits of the same gesture shortly after each other are one undo step."""
        return None


def with_document(state: DesignerState, document: DesignerDocument) -> DesignerState:
    """``state`` showing ``document`` (the run and the map stay: views say when stale)."""
    return state.with_document(document)


def cell_size(state: DesignerState) -> float:
    """The size new things are made at: the largest robot's size, else 1.

    >>> import robotconf as rc
    >>> from robotconf.cell_designer.state import CellDescription, DesignerDocument
    >>> cell = rc.Cell()
    >>> cell.add_robot("arm", rc.preset("paper"))
    >>> cell_size(DesignerState(DesignerDocument(CellDescription.from_cell(cell))))
    90.0
    """
    sizes = [
        characteristic_length(item.robot)
        for item in state.cell.items
        if isinstance(item, RobotItem)
    ]
    return float(max(sizes, default=1.0))


def nice(value: float) -> float:
    """``value`` rounded down to 1, 2 or 5 × 10^k, as a person would pick a size.

    >>> nice(18.0), nice(0.37), nice(1.0)
    (10.0, 0.2, 1.0)
    """
    exponent = math.floor(math.log10(value))
    base = 10.0**exponent
    for step in (5.0, 2.0, 1.0):
        if value >= step * base * (1 - 1e-12):
            return float(f"{step * base:.12g}")
    return base
