"""The cell's robots in the scene: each drawn as :class:`~robotconf.scene.Scene` draws its
robot, on its base.

:class:`RobotsLayer` keeps one :class:`~robotconf.scene._robot_layer.RobotLayer` per robot
of the cell, under the robot's own group, whose transform is the robot's base pose in the
cell's frame: the robot's items stay in its base frame (as ``robot.at(q)`` gives them), a
moved base is one transform, a new ``q`` moves only what moved. Position labels are
written in the cell's frame, with the cell's unit, and carry the robot's name when the
cell has more than one robot (``"a EE (70.0, 0.0, 20.0) mm"``).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import one_line
from ...cell import Cell
from ...kinematics import Robot, RobotSnapshot
from .._commands import Outbox, transform_command
from .._robot_layer import RobotLayer
from ._paths import ROBOTS, PathKeys

__all__ = ["RobotsLayer", "read_qs"]


def read_qs(cell: Cell, qs: Any) -> dict[str, Any]:
    """``qs`` checked: ``None`` or a dict ``{robot name: q}`` naming robots of ``cell``.

    >>> import robotconf as rc
    >>> cell = rc.Cell(); cell.add_robot("arm", rc.preset("paper"))
    >>> read_qs(cell, {"arm": [0, 0, 0]})
    {'arm': [0, 0, 0]}
    >>> read_qs(cell, {"crane": [0]})
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: qs: not a robot of the cell: 'crane'; allowed: ...
    """
    if qs is None:
        return {}
    robots = cell.robots
    if not isinstance(qs, dict):
        raise InvalidInputError("qs", one_line(qs), "None or {robot name: q}")
    for name in qs:
        if name not in robots:
            raise InvalidInputError(
                "qs",
                one_line(name),
                f"robots of the cell: {list(robots)[:20]}",
                problem="not a robot of the cell:",
            )
    return dict(qs)


class RobotsLayer:
    """Every robot of a cell at its base pose and its own ``q``.

    Parameters
    ----------
    outbox : Outbox
    keys : PathKeys
    label_mode : {"off", "names", "positions"}
    frames : bool
        Whether the robots' module frames show.

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import RecordingChannel
    >>> cell = rc.Cell(unit="mm")
    >>> cell.add_robot("arm", rc.preset("paper"), base=rc.pose([100, 0, 0]))
    >>> layer = RobotsLayer(Outbox(RecordingChannel()), PathKeys(), "positions", False)
    >>> layer.show(cell, layer.prepare(cell, {}))
    True
    >>> layer.texts()[-1]
    'EE (170.0, 0.0, 20.0) mm'
    """

    def __init__(self, outbox: Outbox, keys: PathKeys, label_mode: str, frames: bool) -> None:
        self._outbox = outbox
        self._keys = keys
        self.label_mode = label_mode
        self.frames = frames
        self.layers: dict[str, RobotLayer] = {}
        self.bases: dict[str, np.ndarray] = {}
        self._label_frames: dict[str, tuple[bytes, str, str | None]] = {}
        self._moved: set[str] = set()  # robots an animation moved: drawn again in full

    def key(self, name: str) -> str:
        """A robot's path key."""
        return self._keys.key(name)

    def root(self, name: str) -> str:
        """The scene path of a robot's group."""
        return f"{ROBOTS}/{self._keys.key(name)}"

    @property
    def snapshots(self) -> dict[str, RobotSnapshot]:
        """Each robot as shown: ``robot.at(q)``."""
        return {n: layer.snapshot for n, layer in self.layers.items() if layer.snapshot}

    def prepare(self, cell: Cell, qs: dict[str, Any]) -> dict[str, RobotSnapshot]:
        """Every robot of ``cell`` at ``qs[name]`` or, when not given, at the ``q`` it was
        shown at (its own ``q`` for a new or another robot): all checked before anything
        is drawn."""
        snapshots = {}
        for name in cell.robots:
            robot = cell.robot(name)
            layer = self.layers.get(name)
            shown = None if layer is None else layer.snapshot
            if name not in qs and shown is not None and shown.robot is robot:
                snapshots[name] = shown  # the same robot where it was: no kernel pass
                continue
            try:
                snapshots[name] = robot.at(self._q(name, robot, qs))
            except InvalidInputError as error:
                raise error.within(f"qs[{name!r}]") from None
        return snapshots

    def show(self, cell: Cell, snapshots: dict[str, RobotSnapshot]) -> bool:
        """Draw every robot of ``cell`` at its base as ``snapshots`` (from
        :meth:`prepare`) have them. Returns whether a robot was added, removed or
        rebuilt."""
        changed = False
        for name in [n for n in self.layers if n not in snapshots]:
            self._outbox.delete(self.root(name))
            del self.layers[name], self.bases[name]
            self._label_frames.pop(name, None)
            self._keys.forget(name)
            changed = True
        prefix = len(snapshots) > 1
        for name, snapshot in snapshots.items():
            layer = self.layers.get(name)
            if layer is None:
                layer = RobotLayer(
                    self._outbox, self.label_mode, self.frames, root=self.root(name), scaled=False
                )
                self.layers[name] = layer
            base = cell.pose_of(name)
            label_frame = (base.tobytes(), f"{name} " if prefix else "", cell.unit)
            new_frame = self._label_frames.get(name) != label_frame
            if layer.snapshot is snapshot and not new_frame and name not in self._moved:
                continue  # nothing of it changed (an object moved, say)
            self._moved.discard(name)
            if layer.snapshot is None:  # before its first labels are written
                layer.set_label_frame(base, label_frame[1], cell.unit)
            rebuilt = layer.show(snapshot)
            old = self.bases.get(name)
            if rebuilt or old is None or not np.array_equal(base, old):
                # A rebuild deleted the group, and its transform with it.
                self._outbox.send([transform_command(self.root(name), base)])
                self.bases[name] = base
            if new_frame:
                layer.set_label_frame(base, label_frame[1], cell.unit)
                self._label_frames[name] = label_frame
            changed = changed or rebuilt
        return changed

    def _q(self, name: str, robot: Robot, qs: dict[str, Any]) -> Any:
        if name in qs:
            return qs[name]
        layer = self.layers.get(name)
        shown = None if layer is None else layer.snapshot
        if shown is not None and shown.robot.n == robot.n:
            return shown.q
        return None

    def texts(self) -> list[str]:
        """Every robot's label texts as shown (robot by robot)."""
        return [text for layer in self.layers.values() for text in layer.texts()]

    def set_label_mode(self, mode: str) -> None:
        """Every robot's labels in ``mode``."""
        self.label_mode = mode
        for layer in self.layers.values():
            layer.set_label_mode(mode)

    def set_frames(self, visible: bool) -> None:
        """Show or hide every robot's module frames."""
        self.frames = visible
        for layer in self.layers.values():
            layer.set_frames(visible)

    def set_moving(self, moving: bool) -> None:
        """An animation was loaded (labels show names) or dropped."""
        for layer in self.layers.values():
            layer.set_moving(moving)
        if not moving:
            self._moved.update(self.layers)

    @property
    def digits(self) -> int:
        """Decimals of the position labels: the finest of the robots' (1 without robots)."""
        return max((layer.digits for layer in self.layers.values()), default=1)

    @property
    def size(self) -> float:
        """The largest robot's drawing size (0 without robots)."""
        return max(
            (layer.drawing.size for layer in self.layers.values() if layer.drawing), default=0.0
        )

    def extent(self) -> np.ndarray:
        """Every robot's drawn points in the cell's frame, shape (k, 3)."""
        points = [np.zeros((0, 3))]
        for name, layer in self.layers.items():
            base = self.bases[name]
            points.append(layer.extent() @ base[:3, :3].T + base[:3, 3])
        return np.vstack(points)
