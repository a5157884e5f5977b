"""The taught points of a robot program in the 3D pane: small spheres labelled P1, P2, ….

:class:`TaughtPointsLayer` is the part of :class:`~robotconf.scene.Scene` that marks where
a program's moves end (and the via points of its CIRC moves) under
``/meshcat/robotconf/taught``: one small sphere and one label per point. It uses the
scene's own ops (meshcat ``set_object``, the batched transforms and label texts), so it
needs nothing new on the page, and it sits in the scene log: a reloaded page, a second
view and an HTML export show the points too. The group lives beside the robot, not under
it, so a rebuilt robot keeps it; the spheres' size follows the robot drawing's size.
Labels of points that coincide are merged (``"P1, P4"``), as the robot's own are, and
hide with the robot's labels ("labels off"). The scene keeps every marker in view.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import as_float_array, one_line
from ._commands import ROOT, Op, Outbox, labels_op, set_object_op, shape_object, transforms_op
from ._drawing import SPHERE_RADIUS
from ._labels import merge_coincident

__all__ = ["TaughtPointsLayer", "TAUGHT", "TAUGHT_COLORS", "TAUGHT_RADIUS", "MAX_TAUGHT"]

#: The markers' group: ``…/taught/<k>/sphere`` and ``…/taught/<k>/label`` per point.
TAUGHT = f"{ROOT}/taught"
#: Sphere colours (0xRRGGBB): teal for a point a move ends at, olive for a CIRC's via.
TAUGHT_COLORS = {"point": 0x17BECF, "via": 0xBCBD22}
#: A marker's radius relative to the robot drawing's size: smaller than the EE sphere.
TAUGHT_RADIUS = 0.6 * SPHERE_RADIUS
#: More markers than a program can make (200 moves, each with a via point).
MAX_TAUGHT = 500

_POINTS = "an array of shape (k, 3): finite positions in length units"


def _check_points(value: Any, field: str) -> np.ndarray:
    array = as_float_array(value, field, _POINTS)
    if array.size == 0:
        return np.zeros((0, 3))
    if array.ndim != 2 or array.shape[1] != 3:
        raise InvalidInputError(field, one_line(value), _POINTS, problem=f"shape {array.shape}:")
    if not np.isfinite(array).all():
        raise InvalidInputError(field, one_line(value), _POINTS, problem="NaN or infinity in")
    return array


def _check_labels(labels: Any, count: int, field: str, default: str) -> list[str]:
    if labels is None:
        return [default.format(k + 1) for k in range(count)]
    if isinstance(labels, str) or not isinstance(labels, Sequence):
        raise InvalidInputError(field, one_line(labels), f"a list of {count} texts")
    texts = list(labels)
    if len(texts) != count or not all(isinstance(text, str) for text in texts):
        raise InvalidInputError(field, one_line(labels), f"a list of {count} texts")
    return texts


class TaughtPointsLayer:
    """The taught points of a program, marked beside the robot.

    Parameters
    ----------
    outbox : Outbox
    size : callable
        Returns the robot drawing's size (length units): markers are drawn at its scale.
    digits : callable
        Returns the robot labels' decimals: points equal at that precision share a label.

    Examples
    --------
    >>> from robotconf.scene import RecordingChannel
    >>> layer = TaughtPointsLayer(Outbox(RecordingChannel()), lambda: 90.0, lambda: 1)
    >>> layer.show([[70, 0, 20], [40, 10, 30], [70, 0, 20]])
    >>> layer.labels
    ['P1, P3', 'P2', '']
    >>> layer.clear(); layer.labels
    []
    """

    def __init__(
        self, outbox: Outbox, size: Callable[[], float], digits: Callable[[], int]
    ) -> None:
        self._outbox = outbox
        self._size = size
        self._digits = digits
        # What the markers show now: their points, label texts, kinds and size (None:
        # nothing), and whether their labels show.
        self._look: tuple[bytes, tuple[str, ...], tuple[str, ...], float] | None = None
        self._texts: tuple[str, ...] = ()
        self._points = np.zeros((0, 3))
        self.labels_visible = True

    @property
    def labels(self) -> list[str]:
        """The label of every marker shown (``""`` for one merged into another's label)."""
        return list(self._texts)

    def show(
        self,
        points: Any,
        labels: Sequence[str] | None = None,
        *,
        via: Any = None,
        via_labels: Sequence[str] | None = None,
    ) -> None:
        """Mark a program's taught points, replacing the markers shown before.

        Parameters
        ----------
        points : array-like, shape (k, 3)
            Where the moves end, in the base frame (length units).
        labels : list of k str, optional
            Default ``"P1"``, ``"P2"``, …; labels of coinciding points merge.
        via : array-like, shape (m, 3), optional
            Via points of CIRC moves, drawn in another colour.
        via_labels : list of m str, optional
            Default ``"via 1"``, ``"via 2"``, ….

        Raises
        ------
        InvalidInputError
            Points of the wrong shape or not finite, labels that do not match them, or
            more than :data:`MAX_TAUGHT` markers.
        """
        taught = _check_points(points, "points")
        vias = _check_points(np.zeros((0, 3)) if via is None else via, "via")
        names = _check_labels(labels, len(taught), "labels", "P{}") + _check_labels(
            via_labels, len(vias), "via_labels", "via {}"
        )
        everything = np.concatenate([taught, vias])
        if len(everything) > MAX_TAUGHT:
            raise InvalidInputError(
                "points",
                f"<{len(everything)} points>",
                f"at most {MAX_TAUGHT} markers",
                problem="too many:",
            )
        if not len(everything):
            self.clear()
            return
        kinds = tuple(["point"] * len(taught) + ["via"] * len(vias))
        texts = tuple(merge_coincident(names, everything, self._digits(), positions=False))
        size = self._size()
        look = (everything.tobytes(), texts, kinds, size)
        if look == self._look:
            return  # nothing changed: no message
        self.clear()
        ops = _marker_ops(everything, texts, kinds, size)
        ops.append(self.visibility_op(self.labels_visible, len(everything)))
        self._outbox.send(ops)
        self._look, self._texts, self._points = look, texts, everything

    def clear(self) -> None:
        """Remove the markers (from live views and from what a reload shows)."""
        if self._look is None:
            return
        self._outbox.delete(TAUGHT)
        self._look, self._texts, self._points = None, (), np.zeros((0, 3))

    def set_labels_visible(self, visible: bool) -> None:
        """Show or hide the markers' labels (the spheres stay)."""
        self.labels_visible = visible
        if self._look is not None:
            self._outbox.send([self.visibility_op(visible, len(self._texts))])

    def visibility_op(self, visible: bool, count: int | None = None) -> Op:
        """Show or hide the labels of ``count`` markers (default: those shown)."""
        count = len(self._texts) if count is None else count
        paths = [f"{TAUGHT}/{k}/label" for k in range(count)]
        return Op({"op": "visible", "paths": paths, "value": bool(visible)})

    def extent(self) -> np.ndarray:
        """Where the markers stand, shape (k, 3)."""
        return self._points


def _marker_ops(
    points: np.ndarray, texts: Sequence[str], kinds: Sequence[str], size: float
) -> list[Op]:
    """A sphere and a label per point, their transforms in one op, then the label texts."""
    ops: list[Op] = []
    paths: list[str] = []
    matrices = []
    radius = TAUGHT_RADIUS * size
    for k, (point, kind) in enumerate(zip(points, kinds, strict=True)):
        sphere, label = f"{TAUGHT}/{k}/sphere", f"{TAUGHT}/{k}/label"
        ops.append(set_object_op(sphere, shape_object("sphere", radius, TAUGHT_COLORS[kind])))
        ops.append(set_object_op(label, shape_object("label", radius, 0)))
        # The label's anchor is the point itself: the page writes the text just above it.
        for path in (sphere, label):
            matrix = np.eye(4)
            matrix[:3, 3] = point
            paths.append(path)
            matrices.append(matrix)
    ops.append(transforms_op(paths, np.array(matrices)))
    label_paths = [f"{TAUGHT}/{k}/label" for k in range(len(points))]
    ops.append(labels_op(label_paths, list(texts)))
    return ops
