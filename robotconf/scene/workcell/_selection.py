"""The selected entry of a cell, outlined: an amber box drawn over everything.

:class:`Selection` outlines one object, frame or robot (a cell designer's table row, say)
with the edges of a box around it, seen through whatever is in front: an object's own box
(its size and pose), a frame's triad, a robot's drawn points at its ``q`` in its base
frame. The outline follows the entry when the cell is shown again, and goes when the
entry leaves the cell.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import one_line
from .._commands import Op, Outbox, set_object_op, transform_command
from ._entities import EntitiesLayer
from ._paths import SELECTION
from ._robots import RobotsLayer
from ._shapes import SELECTION_COLOR, local_box, wire_box

__all__ = ["Selection", "OUTLINE_MARGIN"]

#: How much wider than its entry an outline is (a share of the entry's size).
OUTLINE_MARGIN = 0.06


class Selection:
    """The outline around the selected entry.

    Parameters
    ----------
    outbox : Outbox

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import RecordingChannel
    >>> from robotconf.scene.workcell._entities import EntitiesLayer
    >>> from robotconf.scene.workcell._paths import PathKeys
    >>> from robotconf.scene.workcell._robots import RobotsLayer
    >>> cell = rc.Cell()
    >>> cell.add(rc.Box([20, 10, 4], pose=rc.pose([50, 0, 2]), name="plate"))
    'plate'
    >>> outbox, keys = Outbox(RecordingChannel()), PathKeys()
    >>> entities = EntitiesLayer(outbox, keys)
    >>> entities.show(cell, triad=10.0, mode="names", digits=1)
    >>> selection = Selection(outbox)
    >>> selection.select("plate", entities, RobotsLayer(outbox, keys, "names", False), 10.0)
    >>> selection.box()[:3, :3].diagonal().round(2).tolist(), selection.box()[:3, 3].tolist()
    ([21.2, 10.6, 4.24], [50.0, 0.0, 2.0])
    """

    def __init__(self, outbox: Outbox) -> None:
        self._outbox = outbox
        self.name: str | None = None
        self._built = False
        self._matrix: np.ndarray | None = None

    def select(self, name: Any, entities: EntitiesLayer, robots: RobotsLayer, triad: float) -> None:
        """Outline ``name`` (an object, a frame or a robot of the cell shown), or nothing
        for ``None``."""
        if name is None:
            self.clear()
            return
        known = [*entities.drawn, *robots.layers]
        if not isinstance(name, str) or name not in known:
            raise InvalidInputError(
                "name", one_line(name), f"None or one of {known[:20]}", problem="not in the cell:"
            )
        self.name = name
        self.follow(entities, robots, triad)

    def follow(self, entities: EntitiesLayer, robots: RobotsLayer, triad: float) -> None:
        """Put the outline where the selected entry is now (none when it left the cell)."""
        name = self.name
        if name is None:
            return
        matrix = _outline(name, entities, robots, triad)
        if matrix is None:
            self.clear()
            return
        ops: list[Op] = []
        if not self._built:
            ops.append(set_object_op(SELECTION, wire_box(SELECTION_COLOR)))
            self._built = True
        if self._matrix is None or not np.array_equal(matrix, self._matrix):
            ops.append(transform_command(SELECTION, matrix))
            self._matrix = matrix
        self._outbox.send(ops)

    def clear(self) -> None:
        """Outline nothing."""
        self.name = None
        self._matrix = None
        if self._built:
            self._outbox.delete(SELECTION)
            self._built = False

    def box(self) -> np.ndarray:
        """The outline's transform of the unit cube (4×4), identity when none."""
        return np.eye(4) if self._matrix is None else self._matrix


def _outline(
    name: str, entities: EntitiesLayer, robots: RobotsLayer, triad: float
) -> np.ndarray | None:
    """The unit cube's transform onto the box around the entry (its own frame's box,
    widened by :data:`OUTLINE_MARGIN`), or None when it is no longer in the cell."""
    if name in entities.drawn:
        drawn = entities.drawn[name]
        pose = drawn.pose
        if drawn.shape is None:
            centre, edges = np.full(3, 0.5 * triad), np.full(3, triad)
        else:
            centre, edges = local_box(drawn.shape)
    elif name in robots.layers:
        pose = robots.bases[name]
        points = robots.layers[name].extent()
        low, high = points.min(axis=0), points.max(axis=0)
        padding = 0.05 * robots.layers[name].drawing.size  # type: ignore[union-attr]
        centre, edges = 0.5 * (low + high), high - low + 2 * padding
    else:
        return None
    edges = edges * (1 + OUTLINE_MARGIN) + 1e-9 * max(float(edges.max()), 1.0)
    box = np.diag([*edges, 1.0])
    box[:3, 3] = centre
    return pose @ box
