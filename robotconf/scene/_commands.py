"""The scene's messages: meshcat commands, batched transforms and label texts, and where
they go.

A scene speaks meshcat's own command language (``set_object``, ``set_property``,
``delete``, ``set_animation``; three.js JSON built by :mod:`robotconf.scene._three`, packed
with msgpack when it holds typed arrays, as meshcat's viewer decodes it) plus robotconf's
own operations: two batched ones that keep a slider fast (all transforms of one update in
one binary buffer, all label texts in one list), ``fit`` (the camera's distance),
``playback`` (the page's player) and ``options`` (what the page's bar shows). An
:class:`Op` is a JSON-able dict plus its binary buffers; a :class:`SceneLog` keeps the
latest op per key, so a new view, a page reload or an HTML export replays a compact scene
instead of its whole history. Every part of a scene (the robot, the ghosts, the target
marker, the taught points, the player) gets the scene's :class:`Outbox` and nothing else
of it: ``send`` gives ops to the views and records the state in the log, ``delete``
removes a subtree from both, so a page reloaded after ``clear_ghosts()`` shows no ghost.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Any, NamedTuple

import msgpack
import numpy as np

from . import _three

__all__ = [
    "Op",
    "SceneLog",
    "RecordingChannel",
    "command_op",
    "set_object_op",
    "meshcat_op",
    "transforms_op",
    "wire_matrices",
    "labels_op",
    "fit_op",
    "playback_op",
    "options_op",
    "pack_ops",
    "pack_command",
    "unpack_command",
    "shape_object",
    "ROOT",
    "Outbox",
    "log_key",
]

#: Every robotconf object lives under this meshcat path.
ROOT = "/meshcat/robotconf"


class Op(NamedTuple):
    """One operation for the viewer: a JSON-able dict and its binary buffers."""

    content: dict[str, Any]
    buffers: tuple[bytes, ...] = ()


def command_op(command: dict[str, Any]) -> Op:
    """Wrap a lowered meshcat command (``{"type": "set_object", ...}``)."""
    return Op({"op": "command", "command": command})


def set_object_op(path: str, obj: dict[str, Any]) -> Op:
    """meshcat's ``set_object``: as JSON, or msgpack-packed when it holds typed arrays.

    Typed arrays (a triad's vertices, a point cloud) are msgpack extension types, which
    only the packed form carries; plain shapes stay readable JSON.
    """
    return meshcat_op({"type": "set_object", "path": path, "object": obj})


def meshcat_op(command: dict[str, Any]) -> Op:
    """A meshcat command as JSON, or msgpack-packed when it holds typed arrays (an
    animation's keyframes, a point cloud).

    >>> meshcat_op({"type": "delete", "path": "/a"}).content["op"]
    'command'
    """
    if _has_ext(command):
        content = {"op": "packed", "type": command["type"], "path": command.get("path", "")}
        return Op(content, (pack_command(command),))
    return command_op(command)


def pack_command(command: dict[str, Any]) -> bytes:
    """A command as the msgpack bytes meshcat's viewer decodes (``handle_command_bytearray``).

    Floats stay 64-bit and strings use msgpack's str types, as meshcat's own packer writes
    them; typed arrays are extension values (:data:`~robotconf.scene._three.FLOAT32_ARRAY`).

    >>> unpack_command(pack_command({"type": "delete", "path": "/a"}))
    {'type': 'delete', 'path': '/a'}
    """
    packed: bytes = msgpack.packb(command, use_bin_type=True)
    return packed


def unpack_command(data: bytes) -> dict[str, Any]:
    """The command in :func:`pack_command`'s bytes (typed arrays stay ``msgpack.ExtType``)."""
    return dict(msgpack.unpackb(data, raw=False))


def _has_ext(value: Any) -> bool:
    if isinstance(value, dict):
        return any(_has_ext(v) for v in value.values())
    if isinstance(value, msgpack.ExtType):
        return True
    if isinstance(value, (list, tuple)):
        return any(_has_ext(v) for v in value)
    return False


def wire_matrices(matrices: np.ndarray) -> np.ndarray:
    """4×4 matrices (..., 4, 4) as the viewer reads them: float32 (what WebGL uses anyway)
    and column-major (three.js ``Matrix4.fromArray``)."""
    return np.ascontiguousarray(np.swapaxes(matrices, -1, -2), dtype=np.float32)


def transforms_op(paths: Sequence[str], matrices: np.ndarray, *, wired: bool = False) -> Op:
    """All transforms of one update: paths and one float32 buffer, column-major 4×4 each
    (``wired``: the matrices are :func:`wire_matrices` already).

    Examples
    --------
    >>> op = transforms_op(["/meshcat/a"], np.eye(4)[None])
    >>> op.content["paths"], len(op.buffers[0])
    (['/meshcat/a'], 64)
    """
    data = (matrices if wired else wire_matrices(matrices)).tobytes()
    return Op({"op": "transforms", "paths": list(paths)}, (data,))


def labels_op(paths: Sequence[str], texts: Sequence[str]) -> Op:
    """New texts for existing labels (an empty text draws nothing).

    The page draws each text beside its anchor's point, on screen: it keeps labels clear
    of each other, wraps long ones inside the pane and draws a leader line to the point
    of a label it had to move away from it.

    >>> labels_op(["/a", "/b"], ["M1", "M2"]).content["texts"]
    ['M1', 'M2']
    """
    return Op({"op": "labels", "paths": list(paths), "texts": list(texts)})


def fit_op(radius: float) -> Op:
    """Put the camera where a sphere of ``radius`` about the origin just fills the pane.

    The viewer keeps the camera's direction and changes only its distance, from the pane's
    aspect and field of view (which only the page knows).

    >>> fit_op(0.5).content
    {'op': 'fit', 'radius': 0.5}
    """
    return Op({"op": "fit", "radius": float(radius)})


def playback_op(action: str, **fields: Any) -> Op:
    """Drive the page's player: ``load`` (with ``id``, ``duration``, ``speed``, ``time``,
    ``playing``), ``play``, ``pause``, ``seek`` (``time``, motion seconds), ``speed``
    (``value``) or ``clear`` (drop the animation; the objects keep their transforms).

    >>> playback_op("seek", time=1.5).content
    {'op': 'playback', 'action': 'seek', 'time': 1.5}
    """
    return Op({"op": "playback", "action": action, **fields})


def options_op(labels: str, frames: bool, trace: bool, controls: bool) -> Op:
    """What the page's bar shows as chosen: the labels mode, frames and trace switches, and
    whether the bar is drawn at all.

    >>> options_op("names", False, True, True).content["labels"]
    'names'
    """
    return Op(
        {
            "op": "options",
            "labels": labels,
            "frames": bool(frames),
            "trace": bool(trace),
            "controls": bool(controls),
        }
    )


def pack_ops(
    ops: Iterable[Op], buffers: list[bytes] | None = None
) -> tuple[list[dict[str, Any]], list[bytes]]:
    """Flatten ops into one message: each op's ``buffers`` become indices into one list
    (``buffers``, extended in place when given, so several lists can share it).

    Examples
    --------
    >>> contents, buffers = pack_ops([transforms_op(["/a"], np.eye(4)[None])])
    >>> contents[0]["buffers"], len(buffers)
    ([0], 1)
    """
    contents: list[dict[str, Any]] = []
    buffers = [] if buffers is None else buffers
    for op in ops:
        content = dict(op.content)
        content["buffers"] = list(range(len(buffers), len(buffers) + len(op.buffers)))
        buffers.extend(op.buffers)
        contents.append(content)
    return contents, buffers


class SceneLog:
    """The latest op under each key, in the order a replay must apply them.

    Re-recording a key moves it to the end, so a replay creates objects before it moves
    them. ``forget(prefix)`` drops everything under a deleted path.
    """

    def __init__(self) -> None:
        self._entries: dict[tuple[str, str], Op] = {}

    def record(self, key: tuple[str, str], op: Op) -> None:
        self._entries.pop(key, None)
        self._entries[key] = op

    def drop(self, key: tuple[str, str]) -> None:
        """Forget one entry (nothing if absent)."""
        self._entries.pop(key, None)

    def forget(self, prefix: str) -> None:
        for key in [k for k in self._entries if k[1] == prefix or k[1].startswith(prefix + "/")]:
            del self._entries[key]

    def ops(self) -> list[Op]:
        return list(self._entries.values())

    def __len__(self) -> int:
        return len(self._entries)


class RecordingChannel:
    """A viewer stand-in for tests: remembers every op it was sent.

    Examples
    --------
    >>> channel = RecordingChannel()
    >>> channel.send([labels_op(["/a"], ["EE (70.0, 0.0, 20.0)"])])
    >>> channel.kinds()
    ['labels']
    """

    def __init__(self) -> None:
        self.messages: list[list[Op]] = []

    def send(self, ops: list[Op]) -> None:
        self.messages.append(list(ops))

    def close(self) -> None:
        """Nothing to release."""

    @property
    def ops(self) -> list[Op]:
        return [op for message in self.messages for op in message]

    def kinds(self) -> list[str]:
        """``"labels"``, ``"transforms"``, ``"visible"``, ``"fit"``, ``"playback"``,
        ``"options"`` or the meshcat command of every op."""
        return [_kind(op) for op in self.ops]

    def commands(self, kind: str) -> list[dict[str, Any]]:
        """Every meshcat command of one type (``"set_object"``, ``"delete"``, …)."""
        return [_command(op) for op in self.ops if _kind(op) == kind]

    def clear(self) -> None:
        self.messages.clear()


def _kind(op: Op) -> str:
    content = op.content
    if content["op"] == "command":
        return str(content["command"]["type"])
    return str(content.get("type", content["op"]))


def _command(op: Op) -> dict[str, Any]:
    if op.content["op"] == "packed":
        return unpack_command(op.buffers[0])
    return dict(op.content.get("command", op.content))


def shape_object(shape: str, size: float, color: int) -> dict[str, Any]:
    """The three.js JSON of one unit shape (:mod:`robotconf.scene._three`).

    Parameters
    ----------
    shape : {"sphere", "cylinder", "box", "triad", "label"}
    size : float
        Radius, half-width, triad length or a label's clearance (length units).
    color : int
        0xRRGGBB (ignored by triads and labels).

    Examples
    --------
    >>> shape_object("cylinder", 0.5, 0x2CA02C)["geometries"][0]["height"]
    1.0
    """
    if shape == "sphere":
        return _three.mesh(_three.sphere(size), _three.lambert_material(color))
    if shape == "cylinder":
        return _three.mesh(_three.cylinder(1.0, size), _three.lambert_material(color))
    if shape == "box":
        return _three.mesh(_three.box(2 * size, 1.0, 2 * size), _three.lambert_material(color))
    if shape == "triad":
        return _three.triad(size)
    if shape == "label":
        return _three.label_anchor(size)
    raise ValueError(f"shape: unknown shape {shape!r}")  # pragma: no cover - internal


class Outbox:
    """The scene's channel and log, as its parts use them.

    Parameters
    ----------
    channel : object
        Has ``send(ops)`` (a :class:`~robotconf.scene.RecordingChannel`, or the notebook
        widget's channel).

    Examples
    --------
    >>> from robotconf.scene import RecordingChannel
    >>> outbox = Outbox(RecordingChannel())
    >>> outbox.send([command_op({"type": "set_property", "path": "/a", "property": "visible",
    ...                          "value": False})])
    >>> outbox.delete("/a")
    >>> outbox.channel.kinds(), len(outbox.log)
    (['set_property', 'delete'], 0)
    """

    def __init__(self, channel: Any) -> None:
        self.channel = channel
        self.log = SceneLog()

    def send(self, ops: list[Op], *, logged: list[Op] | None = None) -> None:
        """Send ``ops`` to the live views; record ``logged`` (default: the same ops) as the
        state a new view replays."""
        for op in ops if logged is None else logged:
            self.log.record(log_key(op), op)
        if ops:
            self.channel.send(ops)

    def send_live(self, ops: list[Op]) -> None:
        """Send ``ops`` to the live views only (a command, not a state)."""
        if ops:
            self.channel.send(ops)

    def delete(self, path: str) -> None:
        """Delete ``path`` and everything under it, in the views and in the log."""
        self.log.forget(path)
        # A new view has nothing there to delete: the delete itself is not logged.
        self.channel.send([command_op({"type": "delete", "path": path})])


def log_key(op: Op) -> tuple[str, str]:
    """The log entry an op replaces: one per command and path, per batched op's paths,
    one for the fit, the options and the animation.

    >>> log_key(command_op({"type": "delete", "path": "/a"}))
    ('delete', '/a')
    """
    content = op.content
    kind = content["op"]
    if kind == "command":
        command = content["command"]
        return (command["type"], command.get("path", ""))
    if kind == "packed":
        # Keyed like its JSON form: one packed set_object per path, not one for the scene.
        return (content["type"], content["path"])
    if kind in ("transforms", "labels", "visible"):
        return (kind, "|".join(content["paths"]))
    return (kind, "")
