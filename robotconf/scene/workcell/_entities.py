"""The cell's objects and frames in the scene, each with its name as a label.

:class:`EntitiesLayer` draws every object (a box, cylinder, sphere or mesh in the neutral
colour) and every frame (an RGB triad: x red, y green, z blue) at its pose in the cell's
frame, and a label per entry: its name, with the unit and its position in the cell's
frame when labels show positions (``"fixture (50, 0, 10) mm"``). Given the cell again it
sends only what changed: a moved entry (or one whose parent moved) is one transform, a
resized or reshaped object is rebuilt alone, a new or removed entry adds or deletes its
own objects. An object's label stands above it (at the top of its box in the cell's
frame), a frame's at its origin.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..._budget import check_memory
from ...cell import Cell, Shape
from ...kinematics import format_point
from .._commands import (
    Op,
    Outbox,
    labels_op,
    set_object_op,
    transforms_op,
)
from .._commands import (
    shape_object as unit_shape,
)
from .._three import label_anchor
from ._paths import FRAMES, NAMES, OBJECTS, PathKeys
from ._shapes import drawing_bytes, local_box, same_geometry, shape_object

__all__ = ["EntitiesLayer", "Drawn"]

#: A name label's distance from its point, relative to the frames' triad length.
LABEL_CLEARANCE = 0.15


@dataclass
class Drawn:
    """An entry as the views show it: its path key, kind, shape (objects), pose in the
    cell's frame, its label's point and text, and its box's corners (cell frame)."""

    key: str
    kind: str
    shape: Shape | None
    pose: np.ndarray
    label_point: np.ndarray
    corners: np.ndarray
    text: str = ""

    @property
    def path(self) -> str:
        """The scene path of its drawing."""
        return f"{OBJECTS if self.kind == 'object' else FRAMES}/{self.key}"

    @property
    def anchor(self) -> str:
        """The scene path of its label's anchor."""
        return f"{NAMES}/{self.key}"


class EntitiesLayer:
    """Objects and frames of a cell, drawn and moved by the cell's own numbers.

    Each entry remembers what the views show of it, so an entry that did not move costs a
    comparison of its pose: a robot's ``q`` step leaves the objects alone.

    Parameters
    ----------
    outbox : Outbox
    keys : PathKeys
        The cell scene's path keys (shared with its robots).

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import RecordingChannel
    >>> cell = rc.Cell(unit="mm")
    >>> cell.add(rc.Box([20, 20, 20], pose=rc.pose([50, 0, 10]), name="fixture"))
    'fixture'
    >>> layer = EntitiesLayer(Outbox(RecordingChannel()), PathKeys())
    >>> layer.show(cell, triad=10.0, mode="positions", digits=1)
    >>> layer.texts("positions", 1)
    ['fixture (50.0, 0.0, 10.0) mm']
    """

    def __init__(self, outbox: Outbox, keys: PathKeys) -> None:
        self._outbox = outbox
        self._keys = keys
        self.drawn: dict[str, Drawn] = {}
        self.unit = ""
        self._triad = 0.0  # the frames' triad length
        self._labels: tuple[str, int, str] = ("", -1, "")  # mode, digits, unit of the texts

    def show(self, cell: Cell, *, triad: float, mode: str, digits: int) -> None:
        """Draw ``cell``'s objects and frames, sending what changed since the last call.

        ``triad`` is the frames' triad length (length units); ``mode`` and ``digits`` how
        the labels read.
        """
        self.unit = f" {cell.unit}" if cell.unit else ""
        wanted: dict[str, Shape | None] = dict(cell.objects)
        wanted.update(dict.fromkeys(cell.frames))
        for name in [n for n in self.drawn if n not in wanted]:
            self._remove(name)
        new_meshes = sum(
            drawing_bytes(s)
            for n, s in wanted.items()
            if s is not None and not _same(self.drawn.get(n), s)
        )
        check_memory("cell", f"<{len(wanted)} entries>", 3 * new_meshes, "fewer mesh triangles")
        rescaled = triad != self._triad
        self._triad = triad
        relabel = (mode, digits, self.unit) != self._labels
        self._labels = (mode, digits, self.unit)
        build: list[Op] = []
        moved: list[Drawn] = []
        relabelled: list[Drawn] = []
        for name, shape in wanted.items():
            old = self.drawn.get(name)
            pose = cell.pose_of(name)
            same_shape = _same(old, shape)
            if old is not None and same_shape and np.array_equal(old.pose, pose):
                if rescaled:
                    moved.append(old)  # triads and label clearances follow the cell's size
                if relabel:
                    old.text = self._text(name, old.pose, mode, digits)
                    relabelled.append(old)
                continue
            drawn = self._place(name, shape, pose, mode, digits)
            if not same_shape and shape is not None:
                build.append(set_object_op(drawn.path, shape_object(shape)))
            if old is None:
                if shape is None:
                    build.append(set_object_op(drawn.path, unit_shape("triad", 1.0, 0)))
                build.append(set_object_op(drawn.anchor, label_anchor(1.0)))
            self.drawn[name] = drawn
            moved.append(drawn)
            relabelled.append(drawn)
        self._outbox.send(build)
        self._send(moved, relabelled)

    def _place(
        self, name: str, shape: Shape | None, pose: np.ndarray, mode: str, digits: int
    ) -> Drawn:
        key = self._keys.key(name)
        if shape is None:
            corners = pose[None, :3, 3].copy()
            point = pose[:3, 3].copy()
        else:
            corners = _corners(shape, pose)
            point = np.array([pose[0, 3], pose[1, 3], corners[:, 2].max()])
        kind = "frame" if shape is None else "object"
        text = self._text(name, pose, mode, digits)
        return Drawn(key, kind, shape, pose, point, corners, text)

    def _text(self, name: str, pose: np.ndarray, mode: str, digits: int) -> str:
        if mode == "off":
            return ""
        if mode == "names":
            return name
        return format_point(name, pose[:3, 3], digits) + self.unit

    def _remove(self, name: str) -> None:
        drawn = self.drawn.pop(name)
        self._outbox.delete(drawn.path)
        self._outbox.delete(drawn.anchor)
        self._keys.forget(name)

    def _matrices(self, drawn: Drawn) -> tuple[np.ndarray, np.ndarray]:
        """The entry's transform (an object at its pose, a frame at its pose with the
        triad's length) and its label anchor's (at its point; the anchor's scale is the
        label's clearance from it)."""
        matrix = (
            drawn.pose
            if drawn.shape is not None
            else drawn.pose @ np.diag([self._triad] * 3 + [1.0])
        )
        anchor = np.diag([LABEL_CLEARANCE * self._triad] * 3 + [1.0])
        anchor[:3, 3] = drawn.label_point
        return matrix, anchor

    def _send(self, moved: list[Drawn], relabelled: list[Drawn]) -> None:
        """One message for the live views (the moved entries' transforms, the changed
        texts); each entry's own op in the log, so a new view replays every entry."""
        paths: list[str] = []
        rows: list[np.ndarray] = []
        logged: list[Op] = []
        for drawn in moved:
            matrix, anchor = self._matrices(drawn)
            paths += [drawn.path, drawn.anchor]
            rows += [matrix, anchor]
            logged.append(transforms_op([drawn.path], matrix[None]))
            logged.append(transforms_op([drawn.anchor], anchor[None]))
        live = [transforms_op(paths, np.array(rows))] if paths else []
        if relabelled:
            live.append(labels_op([d.anchor for d in relabelled], [d.text for d in relabelled]))
            logged += [labels_op([d.anchor], [d.text]) for d in relabelled]
        self._outbox.send(live, logged=logged)

    def texts(self, mode: str, digits: int) -> list[str]:
        """Each entry's label: its name, and in ``"positions"`` mode where its pose's
        origin is in the cell's frame, with the unit (``"off"``: no text)."""
        return [self._text(name, drawn.pose, mode, digits) for name, drawn in self.drawn.items()]

    def label_ops(self, mode: str, digits: int) -> list[Op]:
        """Every label's text in ``mode`` (for an exported page's own bar)."""
        if not self.drawn:
            return []
        anchors = [drawn.anchor for drawn in self.drawn.values()]
        return [labels_op(anchors, self.texts(mode, digits))]

    def relabel(self, mode: str, digits: int) -> None:
        """Send the labels again in another mode or precision."""
        self._labels = (mode, digits, self.unit)
        for name, drawn in self.drawn.items():
            drawn.text = self._text(name, drawn.pose, mode, digits)
        self._send([], list(self.drawn.values()))

    def extent(self) -> np.ndarray:
        """Points the view must hold: each object's box corners in the cell's frame and
        each frame's origin, shape (k, 3)."""
        return np.vstack([np.zeros((0, 3)), *(drawn.corners for drawn in self.drawn.values())])


def _same(drawn: Drawn | None, shape: Shape | None) -> bool:
    """Whether an entry drawn so keeps its drawing for ``shape`` (a frame: None)."""
    if drawn is None:
        return False
    if shape is None or drawn.shape is None:
        return shape is None and drawn.shape is None
    return shape is drawn.shape or same_geometry(drawn.shape, shape)


def _corners(shape: Shape, pose: np.ndarray) -> np.ndarray:
    centre, edges = local_box(shape)
    signs = np.array([[(b >> k & 1) - 0.5 for k in range(3)] for b in range(8)])
    local = centre + signs * edges
    return local @ pose[:3, :3].T + pose[:3, 3]
