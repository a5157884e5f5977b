"""The cell designer: a work cell's panel view, ``rc.cell_designer(cell_or_path)``.

Tables of objects, frames and robots with their poses, the reach map, every robot's
program and **Run** (cycle time, violations, each contact under the move that causes
it), beside the cell's 3D view; one history for undo and redo, the units, messages
beside the controls, and a bound cell file that keeps every valid change
(docs/cell.md, "Designer"). Imported on first use of :func:`robotconf.cell_designer`,
never by ``import robotconf``.

The designer
    :class:`CellDesigner` (``designer.state``, ``designer.apply(action)``,
    ``designer.cell``, ``designer.programs``, ``designer.run``, ``designer.reach_map``,
    ``designer.undo()``, ``designer.redo()``, ``designer.save(path)``,
    ``designer.load(path)``, ``designer.export_html(path)``), :func:`cell_designer`
The state and the actions
    :mod:`robotconf.cell_designer.state` (:class:`DesignerState` and its parts),
    :mod:`robotconf.cell_designer.actions` (one class per user action)
"""

from typing import Any

from . import actions, state
from .state import DesignerState

__all__ = ["CellDesigner", "cell_designer", "DesignerState", "actions", "state"]


def __getattr__(name: str) -> Any:
    # The widgets load with the designer itself: the state and the actions need none.
    if name in ("CellDesigner", "cell_designer"):
        from . import _designer

        return getattr(_designer, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
