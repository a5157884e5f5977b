"""The robot in the scene: objects built once per structure and size, moved by snapshots.

:class:`RobotLayer` is the part of :class:`~robotconf.scene.Scene` that draws the robot
itself under ``/meshcat/robotconf/robot``. It takes a
:class:`~robotconf.kinematics.RobotSnapshot` (the robot at one ``q`` from one kernel pass)
and sends only the transforms and label texts that changed, in one message; it never
computes kinematics of its own. Its objects are rebuilt only when the robot's structure
(the number of links and their joints) changes, or its size by more than a factor of 2.
:class:`Shown` remembers what the live views show: a slider step on joint 3 moves nothing
before it, and most label texts stay the same.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..kinematics import RobotSnapshot, characteristic_length
from ._commands import (
    ROOT,
    Op,
    Outbox,
    command_op,
    labels_op,
    set_object_op,
    shape_object,
    transforms_op,
    wire_matrices,
)
from ._drawing import RobotDrawing, snapshot_size, structure_of
from ._labels import label_digits, merge_coincident

__all__ = ["RobotLayer", "Shown", "ROBOT", "RESIZE_FACTOR"]

#: The robot's objects live under this path; clouds, ghosts and markers beside it.
ROBOT = f"{ROOT}/robot"
#: Rebuild the objects when the robot's lengths change by more than this factor.
RESIZE_FACTOR = 2.0


class RobotLayer:
    """Draws one robot and moves it to each snapshot it is given.

    Parameters
    ----------
    outbox : Outbox
    label_mode : {"off", "names", "positions"}
    frames : bool
        Whether the module frames' triads show.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import RecordingChannel
    >>> layer = RobotLayer(Outbox(RecordingChannel()), "positions", False)
    >>> layer.show(rc.preset("paper").at())
    True
    >>> layer.show(rc.preset("paper").at([0.0, 0.0, 0.5]))  # same robot: no rebuild
    False
    >>> layer.labels()[-1]
    'EE (65.1, 0.0, 0.8)'
    """

    def __init__(self, outbox: Outbox, label_mode: str, frames: bool) -> None:
        self._outbox = outbox
        self.label_mode = label_mode
        self.frames = frames
        #: An animation moves the items: labels then show names, not numbers that stand
        #: still while the robot moves.
        self.moving = False
        self.drawing: RobotDrawing | None = None
        self.snapshot: RobotSnapshot | None = None
        self._shown = Shown()
        self._paths: tuple[str, ...] = ()
        self._label_paths: tuple[str, ...] = ()
        self._length = 0.0  # the drawn robot's characteristic length
        #: Decimals of the position labels: three significant digits of the robot's size.
        self.digits = 1
        self._texts_known: dict[tuple[str, tuple[float, ...]], str] = {}  # for these digits

    def show(self, snapshot: RobotSnapshot) -> bool:
        """Move the robot to ``snapshot`` (rebuilding it if needed): one message with what
        changed. Returns whether the objects were rebuilt."""
        robot = snapshot.robot
        drawing = self.drawing
        rebuilt = False
        if drawing is None or robot is not drawing.robot:
            length = characteristic_length(robot)
            if (
                drawing is None
                or drawing.structure != structure_of(snapshot)
                or _resized(self._length, length)
            ):
                drawing = RobotDrawing(robot, snapshot_size(snapshot), snapshot.joint_axes.joints)
                self._build(drawing)
                self._length = length
                rebuilt = True
            else:
                drawing.robot = robot  # the same objects; lengths may differ a little
            digits = label_digits(length)
            if digits != self.digits:
                self._texts_known.clear()
            self.digits = digits
        self.snapshot = snapshot
        wire = wire_matrices(drawing.place(snapshot))
        changed = self._shown.transforms(wire)
        live: list[Op] = []
        if len(changed):
            paths = [self._paths[k] for k in changed]
            live.append(transforms_op(paths, wire[changed], wired=True))
        logged = [transforms_op(self._paths, wire, wired=True)]
        label_live, label_logged = self._label_ops()
        self._outbox.send(live + label_live, logged=logged + label_logged)
        return rebuilt

    def labels(self) -> list[str]:
        """The position labels of the shown snapshot: ``["M1 (…)", …, "EE (…)"]``."""
        assert self.drawing is not None and self.snapshot is not None
        return self.drawing.labels(self.snapshot, self.digits)

    def set_label_mode(self, mode: str) -> None:
        """Show the labels as ``"off"``, ``"names"`` or ``"positions"`` (mode checked)."""
        self.label_mode = mode
        if mode == "off":
            self._shown.labels([])  # shown again in full when they come back
        live, logged = self._label_ops()
        visibility = self.visibility_op("labels", mode != "off")
        self._outbox.send([visibility, *live], logged=[visibility, *logged])

    def set_frames(self, visible: bool) -> None:
        """Show or hide the module frames' triads."""
        self.frames = visible
        self._outbox.send([self.visibility_op("frames", visible)])

    def set_moving(self, moving: bool) -> None:
        """An animation was loaded (the labels change to names now) or dropped (the next
        snapshot sends every transform and label: the animation moved every item)."""
        self.moving = moving
        if moving:
            live, logged = self._label_ops()
            self._outbox.send(live, logged=logged)
        else:
            self._shown.forget()

    def extent(self) -> np.ndarray:
        """Points the view must hold: the base, the frame origins, the joint axes' points
        and the end effector, shape (k, 3)."""
        snapshot = self.snapshot
        if snapshot is None:
            return np.zeros((1, 3))
        axes = snapshot.joint_axes.point
        return np.vstack(
            [
                np.zeros((1, 3)),
                snapshot.frame_origins,
                axes[~np.isnan(axes).any(axis=1)],
                snapshot.end_effector[None],
            ]
        )

    def visibility_op(self, layer: str, visible: bool) -> Op:
        """Show or hide one layer of the robot's items (``"frames"``, ``"labels"``)."""
        assert self.drawing is not None
        items = zip(self._paths, self.drawing.items, strict=True)
        paths = [path for path, item in items if item.layer == layer]
        return Op({"op": "visible", "paths": paths, "value": bool(visible)})

    def label_ops(self, mode: str) -> list[Op]:
        """The ops that show the labels in ``mode`` (for an exported page's own bar)."""
        if mode == "off" or self.drawing is None:
            return [self.visibility_op("labels", False)]
        return [self.visibility_op("labels", True), labels_op(self._label_paths, self._texts(mode))]

    def _texts(self, mode: str) -> list[str]:
        assert self.drawing is not None and self.snapshot is not None
        names = self.drawing.point_names
        if self.moving:
            # The names themselves, one per moving point: a number, or a merge of points
            # that part during the motion, would be wrong.
            return list(names)
        points = np.vstack([self.snapshot.frame_origins, self.snapshot.end_effector])
        return merge_coincident(names, points, self.digits, mode == "positions", self._texts_known)

    def _label_ops(self) -> tuple[list[Op], list[Op]]:
        """The labels that changed (for live views) and all labels (for the log)."""
        if self.label_mode == "off" or self.snapshot is None:
            return [], []
        texts = self._texts(self.label_mode)
        changed = self._shown.labels(texts)
        paths = self._label_paths
        live = [labels_op([paths[k] for k in changed], [texts[k] for k in changed])]
        return live if changed else [], [labels_op(paths, texts)]

    def _build(self, drawing: RobotDrawing) -> None:
        self._outbox.delete(ROBOT)
        self.drawing = drawing
        self._shown.forget()
        self._paths = tuple(f"{ROBOT}/{path}" for path in drawing.paths)
        self._label_paths = tuple(f"{ROBOT}/{path}" for path in drawing.label_paths)
        scale = 1.0 / drawing.size
        # Everything robotconf draws is scaled to about one unit: meshcat's camera, grid
        # and clipping planes are made for that size.
        ops = [transform_command(ROOT, np.diag([scale, scale, scale, 1.0]))]
        for path, item in zip(self._paths, drawing.items, strict=True):
            ops.append(set_object_op(path, shape_object(item.shape, item.size, item.color)))
        ops.append(self.visibility_op("frames", self.frames))
        ops.append(self.visibility_op("labels", self.label_mode != "off"))
        self._outbox.send(ops)


def transform_command(path: str, matrix: np.ndarray) -> Op:
    """meshcat's ``set_transform`` of one path (``matrix`` 4×4, sent column-major)."""
    return command_op({"type": "set_transform", "path": path, "matrix": matrix.T.ravel().tolist()})


def _resized(old: float, new: float) -> bool:
    if old <= 0 or new <= 0:
        return (old > 0) != (new > 0)
    return not 1 / RESIZE_FACTOR <= new / old <= RESIZE_FACTOR


class Shown:
    """The transforms and labels last sent to the live views, for one fixed set of paths.

    Examples
    --------
    >>> shown = Shown()
    >>> shown.transforms(np.stack([np.eye(4), np.eye(4)])).tolist()
    [0, 1]
    >>> shown.transforms(np.stack([np.eye(4), 2 * np.eye(4)])).tolist()
    [1]
    >>> shown.labels(["M1", "EE"]), shown.labels(["M1", "EE (1.0, 0.0, 0.0)"])
    ([0, 1], [1])
    """

    def __init__(self) -> None:
        self._matrices: np.ndarray | None = None
        self._labels: list[str] | None = None

    def forget(self) -> None:
        """Everything must be sent again (new objects)."""
        self._matrices = None
        self._labels = None

    def forget_transforms(self) -> None:
        """Transforms must be sent again (an animation moved the objects)."""
        self._matrices = None

    def transforms(self, wire: np.ndarray) -> np.ndarray:
        """Indices of the items whose matrix, as the viewer gets it (float32), differs
        from the last one sent."""
        last = self._matrices
        self._matrices = wire
        if last is None or last.shape != wire.shape:
            return np.arange(len(wire))
        return np.flatnonzero((wire != last).any(axis=(1, 2)))

    def labels(self, texts: Sequence[str]) -> list[int]:
        """Indices of the labels whose text differs from the last one sent."""
        last = self._labels
        self._labels = list(texts)
        if last is None or len(last) != len(texts):
            return list(range(len(texts)))
        return [k for k, (old, new) in enumerate(zip(last, texts, strict=True)) if old != new]
