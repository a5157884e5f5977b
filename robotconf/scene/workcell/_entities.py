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
    cell's frame, and where its label stands."""

    key: str
    kind: str
    shape: Shape | None
    pose: np.ndarray
    label_point: np.ndarray


class EntitiesLayer:
    """Objects and frames of a cell, drawn and moved by the cell's own numbers.

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
        self._shown_matrices: dict[str, bytes] = {}  # path → the transform the views have
        self._shown_texts: dict[str, str] = {}  # label path → its text in the views

    def show(self, cell: Cell, *, triad: float, mode: str, digits: int) -> None:
        """Draw ``cell``'s objects and frames, sending what changed since the last call.

        ``triad`` is the frames' triad length (length units); ``mode`` and ``digits`` how
        the labels read.
        """
        self.unit = f" {cell.unit}" if cell.unit else ""
        objects = cell.objects
        frames = cell.frames
        obstacles, names = cell.obstacles()
        top = dict(zip(names, obstacles.high[:, 2], strict=True))
        wanted: dict[str, tuple[str, Shape | None]] = {n: ("object", s) for n, s in objects.items()}
        wanted.update({name: ("frame", None) for name in frames})
        build: list[Op] = []
        for name in [n for n in self.drawn if n not in wanted]:
            self._remove(name)
        new_meshes = sum(
            drawing_bytes(s)
            for n, (kind, s) in wanted.items()
            if s is not None and not same_geometry(self._shape(n), s)
        )
        check_memory("cell", f"<{len(objects)} objects>", 3 * new_meshes, "fewer mesh triangles")
        for name, (kind, shape) in wanted.items():
            old = self.drawn.get(name)
            pose = cell.pose_of(name)
            key = self._keys.key(name)
            if shape is not None:
                point = np.array([pose[0, 3], pose[1, 3], top[name]])
                if not same_geometry(old.shape if old else None, shape):
                    build.append(set_object_op(f"{OBJECTS}/{key}", shape_object(shape)))
            else:
                point = pose[:3, 3].copy()
                if old is None:
                    build.append(set_object_op(f"{FRAMES}/{key}", unit_shape("triad", 1.0, 0)))
            if old is None:
                build.append(set_object_op(f"{NAMES}/{key}", label_anchor(1.0)))
            self.drawn[name] = Drawn(key, kind, shape, pose, point)
        self._triad = triad
        self._outbox.send(build)
        self._send_state(mode, digits)

    def _shape(self, name: str) -> Shape | None:
        drawn = self.drawn.get(name)
        return None if drawn is None else drawn.shape

    def _remove(self, name: str) -> None:
        drawn = self.drawn.pop(name)
        folder = OBJECTS if drawn.kind == "object" else FRAMES
        for path in (f"{folder}/{drawn.key}", f"{NAMES}/{drawn.key}"):
            self._outbox.delete(path)
            self._shown_matrices.pop(path, None)
            self._shown_texts.pop(path, None)
        self._keys.forget(name)

    def _matrices(self) -> tuple[list[str], np.ndarray]:
        """Every entry's transform: objects at their pose, frames at theirs with the
        triad's length, label anchors at their points (their scale is the label's
        clearance from the point)."""
        paths, matrices = [], []
        clearance = LABEL_CLEARANCE * self._triad
        for drawn in self.drawn.values():
            if drawn.kind == "object":
                paths.append(f"{OBJECTS}/{drawn.key}")
                matrices.append(drawn.pose)
            else:
                paths.append(f"{FRAMES}/{drawn.key}")
                matrices.append(drawn.pose @ np.diag([self._triad] * 3 + [1.0]))
            anchor = np.diag([clearance] * 3 + [1.0])
            anchor[:3, 3] = drawn.label_point
            paths.append(f"{NAMES}/{drawn.key}")
            matrices.append(anchor)
        return paths, np.array(matrices).reshape(-1, 4, 4)

    def _send_state(self, mode: str, digits: int) -> None:
        """The transforms and label texts that changed (live), each entry's own (log)."""
        paths, matrices = self._matrices()
        live_paths, live_rows, logged = [], [], []
        for path, matrix in zip(paths, matrices, strict=True):
            op = transforms_op([path], matrix[None])
            logged.append(op)
            if self._shown_matrices.get(path) != op.buffers[0]:
                self._shown_matrices[path] = op.buffers[0]
                live_paths.append(path)
                live_rows.append(matrix)
        live = [transforms_op(live_paths, np.array(live_rows))] if live_paths else []
        label_live, label_logged = self._label_ops(mode, digits)
        self._outbox.send(live + label_live, logged=logged + label_logged)

    def texts(self, mode: str, digits: int) -> list[str]:
        """Each entry's label: its name, and in ``"positions"`` mode where its pose's
        origin is in the cell's frame, with the unit (``"off"``: no text)."""
        if mode == "off":
            return ["" for _ in self.drawn]
        if mode == "names":
            return list(self.drawn)
        return [
            format_point(name, drawn.pose[:3, 3], digits) + self.unit
            for name, drawn in self.drawn.items()
        ]

    def label_ops(self, mode: str, digits: int) -> list[Op]:
        """Every label's text in ``mode`` (for an exported page's own bar)."""
        paths = [f"{NAMES}/{drawn.key}" for drawn in self.drawn.values()]
        return [labels_op(paths, self.texts(mode, digits))] if paths else []

    def _label_ops(self, mode: str, digits: int) -> tuple[list[Op], list[Op]]:
        paths = [f"{NAMES}/{drawn.key}" for drawn in self.drawn.values()]
        texts = self.texts(mode, digits)
        changed = [k for k, path in enumerate(paths) if self._shown_texts.get(path) != texts[k]]
        for k in changed:
            self._shown_texts[paths[k]] = texts[k]
        live = [labels_op([paths[k] for k in changed], [texts[k] for k in changed])]
        logged = [labels_op([path], [text]) for path, text in zip(paths, texts, strict=True)]
        return (live if changed else []), logged

    def relabel(self, mode: str, digits: int) -> None:
        """Send the labels again in another mode or precision (only the changed texts)."""
        live, logged = self._label_ops(mode, digits)
        self._outbox.send(live, logged=logged)

    def extent(self) -> np.ndarray:
        """Points the view must hold: each object's box corners in the cell's frame and
        each frame's origin, shape (k, 3)."""
        points = [np.zeros((0, 3))]
        for drawn in self.drawn.values():
            if drawn.shape is None:
                points.append(drawn.pose[None, :3, 3])
            else:
                points.append(_corners(drawn.shape, drawn.pose))
        return np.vstack(points)


def _corners(shape: Shape, pose: np.ndarray) -> np.ndarray:
    centre, edges = local_box(shape)
    signs = np.array([[(b >> k & 1) - 0.5 for k in range(3)] for b in range(8)])
    local = centre + signs * edges
    return local @ pose[:3, :3].T + pose[:3, 3]
