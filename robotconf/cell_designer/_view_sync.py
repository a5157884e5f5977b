"""The 3D view follows the state: only what changed is sent to it.

The view holds the cell, the animation of the last run, the reach map, the capsules and
the selection. :class:`ViewSync` remembers what it last sent for each and sends a part
again only when the state's value of it changed, so a selection click never redraws the
cell and a q step never reloads the map.
"""

from __future__ import annotations

from typing import Any

from .state import CellDescription, DesignerState, ReachOutcome, RunOutcome

__all__ = ["ViewSync"]


class ViewSync:
    """What the view shows now, and the calls that bring it to a new state.

    Parameters
    ----------
    scene : CellScene-like
        See :mod:`robotconf.cell_designer._scene_slot`.
    cell : CellDescription
        The cell the view was built with.
    """

    def __init__(self, scene: Any, cell: CellDescription) -> None:
        self.scene = scene
        self.cell = cell
        self.run: RunOutcome | None = None
        self.reach: ReachOutcome | None = None
        self.selected: str | None = None
        self.capsules = False

    def follow(self, state: DesignerState, *, play: bool = False, fit: bool = False) -> None:
        """Send what differs between the view and ``state`` (``play``: start a newly
        loaded run; ``fit``: frame everything afterwards)."""
        scene = self.scene
        if state.cell is not self.cell and state.cell != self.cell:
            cell = state.cell.cell
            # Each robot at its own q: the view would keep the q it last drew otherwise.
            scene.show(cell, {name: cell.robot(name).q for name in cell.robots})
            self.cell = state.cell
            self.run = None  # a new cell drops the animation of the old one
        run = state.run if state.run is not None and not state.run.stale(state.document) else None
        if run is not None and run is not self.run:
            scene.animate(run.run, play=play)
        self.run = run
        reach = state.reach_map if state.reach.on else None
        if reach is not self.reach:
            if reach is None:
                scene.clear_reach_map()
            else:
                scene.show_reach_map(reach.result)
            self.reach = reach
        if state.capsules != self.capsules:
            scene.show_capsules(state.capsules)
            self.capsules = state.capsules
        if state.selected != self.selected:
            scene.select(state.selected)
            self.selected = state.selected
        if fit:
            scene.fit_view()
