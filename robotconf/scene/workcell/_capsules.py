"""The robots' collision capsules, as the cell's checks measure them.

A capsule is a link's segment swept by a ball (:meth:`Cell.link_capsules
<robotconf.cell.Cell.link_capsules>`, in the cell's frame). It is drawn as three items: a
cylinder of the capsule's radius along the segment (``body``: three.js's unit cylinder
along y, turned onto the segment and stretched to its length) and a ball at each end
(``end0``, ``end1``). :class:`CapsulesLayer` draws every robot's capsules see-through
(shown or hidden as one layer, :meth:`CellScene.show_capsules
<robotconf.scene.CellScene.show_capsules>`); the contacts of a run draw red ones
(:mod:`._contacts`) with the same placement.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from .._commands import Op, Outbox, set_object_op, shape_object, transforms_op
from .._ghosts import faint
from .._placement import Placement, align_y
from ._paths import CAPSULES, PathKeys

if TYPE_CHECKING:
    from ...cell import Cell

__all__ = [
    "CapsulesLayer",
    "CAPSULE_COLOR",
    "CAPSULE_OPACITY",
    "CAPSULE_PARTS",
    "capsule_placement",
    "capsule_objects",
    "capsule_paths",
]

#: The capsules' colour and opacity: see-through blue over the robot's own drawing.
CAPSULE_COLOR = 0x1F77B4
CAPSULE_OPACITY = 0.28
#: The three items of a capsule, in placement order.
CAPSULE_PARTS = ("body", "end0", "end1")


def capsule_placement(segments: np.ndarray) -> Placement:
    """Where each capsule's body and ends go: segments (..., L, 2, 3) → a placement of
    shape (..., 3L, …), for each link its body, then its two ends.

    The body is the unit cylinder (radius set when built) turned onto the segment,
    centred on it and stretched to its length; a segment of zero length leaves the two
    balls, its body drawn as nothing.

    Examples
    --------
    >>> placement = capsule_placement(np.array([[[0.0, 0, 0], [0, 0, 40.0]]]))
    >>> placement.position.tolist()
    [[0.0, 0.0, 20.0], [0.0, 0.0, 0.0], [0.0, 0.0, 40.0]]
    >>> placement.scale[0].tolist(), (placement.rotation[0] @ [0, 1, 0]).round(12).tolist()
    ([1.0, 40.0, 1.0], [0.0, 0.0, 1.0])
    """
    a, b = segments[..., 0, :], segments[..., 1, :]
    along = b - a
    length = np.linalg.norm(along, axis=-1)
    shape = segments.shape[:-2]
    position = np.stack([0.5 * (a + b), a, b], axis=-2)
    rotation = np.broadcast_to(np.eye(3), (*shape, 3, 3, 3)).copy()
    rotation[..., 0, :, :] = align_y(along)
    scale = np.ones((*shape, 3, 3))
    flat = length <= 0.0
    scale[..., 0, 0] = np.where(flat, 1e-9, 1.0)
    scale[..., 0, 1] = np.where(flat, 1e-9, length)
    scale[..., 0, 2] = np.where(flat, 1e-9, 1.0)
    merged = (*shape[:-1], 3 * shape[-1])
    return Placement(
        position.reshape(*merged, 3), rotation.reshape(*merged, 3, 3), scale.reshape(*merged, 3)
    )


def capsule_objects(paths: list[str], radii: np.ndarray, color: int, opacity: float) -> list[Op]:
    """The ``set_object`` ops of capsules of ``radii`` (L,) at ``paths`` (3L, in
    :func:`capsule_placement`'s order), see-through at ``opacity``."""
    ops = []
    for k, radius in enumerate(np.asarray(radii, dtype=float)):
        body = faint(shape_object("cylinder", float(radius), color), opacity)
        ball = faint(shape_object("sphere", float(radius), color), opacity)
        ops.append(set_object_op(paths[3 * k], body))
        ops += [set_object_op(paths[3 * k + 1], ball), set_object_op(paths[3 * k + 2], ball)]
    return ops


def capsule_paths(root: str, links: int) -> list[str]:
    """``root/k/body``, ``root/k/end0``, ``root/k/end1`` for every link k.

    >>> capsule_paths("/c", 1)
    ['/c/0/body', '/c/0/end0', '/c/0/end1']
    """
    return [f"{root}/{k}/{part}" for k in range(links) for part in CAPSULE_PARTS]


class CapsulesLayer:
    """Every robot's capsules, see-through, moved with the robots.

    The capsules' objects exist for every robot (a run animates them, a view may switch
    them on); while they are hidden they are not moved at each ``q`` step, only marked
    :attr:`stale`, and placed when they show (or a new view asks for the scene).

    Parameters
    ----------
    outbox : Outbox
    keys : PathKeys
        The cell scene's path keys (a robot's capsules use its key).

    Examples
    --------
    >>> from robotconf.scene import RecordingChannel
    >>> layer = CapsulesLayer(Outbox(RecordingChannel()), PathKeys())
    >>> layer.build({"arm": np.array([3.6])})
    >>> layer.place({"arm": np.array([[[0.0, 0, 0], [0, 0, 20.0]]])})
    >>> layer.paths("arm")
    ['/meshcat/robotconf/cell/capsules/e1/0/body', '/meshcat/robotconf/cell/capsules/e1/0/end0', \
'/meshcat/robotconf/cell/capsules/e1/0/end1']
    """

    def __init__(self, outbox: Outbox, keys: PathKeys) -> None:
        self._outbox = outbox
        self._keys = keys
        self.visible = False
        #: Whether the views show the capsules where the robots were, not where they are.
        self.stale = False
        self._radii: dict[str, tuple[float, ...]] = {}
        self._shown: dict[str, bytes] = {}  # robot → its transforms as the views have them
        self._where: tuple[Cell, dict[str, Any]] | None = None  # the cell, its snapshots

    def paths(self, robot: str) -> list[str]:
        """A robot's capsule items, in :func:`capsule_placement`'s order."""
        return capsule_paths(f"{CAPSULES}/{self._keys.key(robot)}", len(self._radii[robot]))

    def build(self, radii: dict[str, np.ndarray]) -> None:
        """Make every robot's capsule objects, ``{robot: radii (L,)}`` (rebuilt where the
        radii changed; a robot left out loses its capsules)."""
        for name in [n for n in self._radii if n not in radii]:
            self.forget(name)
        built: list[Op] = []
        for name, values in radii.items():
            wanted = tuple(float(r) for r in values)
            if self._radii.get(name) == wanted:
                continue
            self._outbox.delete(f"{CAPSULES}/{self._keys.key(name)}")
            self._shown.pop(name, None)
            self._radii[name] = wanted
            built += capsule_objects(self.paths(name), values, CAPSULE_COLOR, CAPSULE_OPACITY)
        if built:
            self._outbox.send([*built, self.visibility_op()])
            self.stale = True

    def place(self, segments: dict[str, np.ndarray]) -> None:
        """Move every robot's capsules to ``{robot: segments (L, 2, 3)}`` (cell frame):
        the robots whose capsules moved in one message."""
        live: list[Op] = []
        logged: list[Op] = []
        for name, ends in segments.items():
            op = transforms_op(self.paths(name), capsule_placement(ends).matrices())
            logged.append(op)
            if self._shown.get(name) != op.buffers[0]:
                self._shown[name] = op.buffers[0]
                live.append(op)
        self._outbox.send(live, logged=logged)
        self.stale = False

    def follow(self, cell: Cell, snapshots: dict[str, Any]) -> None:
        """The robots stand as ``snapshots`` (``{robot: RobotSnapshot}``) in ``cell``:
        capsules rebuilt where the radii changed, placed now if they show, else marked
        :attr:`stale` (placed by :meth:`catch_up`)."""
        radii = {}
        for name in snapshots:
            links = cell.robot_entry(name).links
            assert links is not None  # every robot of a cell has its link model
            radii[name] = links.radii
        self.build(radii)
        self._where = (cell, snapshots)
        self.stale = True
        if self.visible:
            self.catch_up()

    def catch_up(self) -> None:
        """Place stale capsules where the robots are (one kernel pass per robot)."""
        if not self.stale or self._where is None:
            return
        cell, snapshots = self._where
        self.place({name: cell.link_capsules(name, s.q)[0] for name, s in snapshots.items()})

    def forget(self, name: str) -> None:
        """A robot left the cell: its capsules go."""
        self._outbox.delete(f"{CAPSULES}/{self._keys.key(name)}")
        self._radii.pop(name, None)
        self._shown.pop(name, None)

    def set_visible(self, visible: bool) -> None:
        """Show or hide every capsule."""
        self.visible = visible
        self._outbox.send([self.visibility_op()])

    def visibility_op(self, visible: bool | None = None) -> Op:
        """The op that shows or hides the capsules (default: as they are)."""
        value = self.visible if visible is None else visible
        return Op({"op": "visible", "paths": [CAPSULES], "value": bool(value)})
