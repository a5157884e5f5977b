"""What the live views show, so an update sends only what changed.

A slider step on joint 3 moves nothing before it: the base, links and markers of joints 1
and 2 keep their transforms, and most label texts stay the same. :class:`Shown` remembers
the last transform (as the float32 the viewer gets) and label of every path and returns
only the differences. The scene log keeps the full state for new views.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

__all__ = ["Shown"]


class Shown:
    """The transforms and labels last sent to the live views.

    Examples
    --------
    >>> shown = Shown()
    >>> paths, _ = shown.transforms(["/a", "/b"], np.stack([np.eye(4), np.eye(4)]))
    >>> paths
    ['/a', '/b']
    >>> shown.transforms(["/a", "/b"], np.stack([np.eye(4), 2 * np.eye(4)]))[0]
    ['/b']
    >>> shown.labels(["/a"], ["M1"], [0]), shown.labels(["/a"], ["M1"], [0])
    ((['/a'], ['M1'], [0]), ([], [], []))
    """

    def __init__(self) -> None:
        self._matrices: dict[str, np.ndarray] = {}
        self._labels: dict[str, tuple[str, int]] = {}

    def forget(self) -> None:
        """Everything must be sent again (new objects, or an animation moved them)."""
        self._matrices.clear()
        self._labels.clear()

    def forget_transforms(self) -> None:
        """Transforms must be sent again (an animation moved the objects)."""
        self._matrices.clear()

    def transforms(
        self, paths: Sequence[str], matrices: np.ndarray
    ) -> tuple[list[str], np.ndarray]:
        """The paths whose float32 matrix differs from the last one sent, and their matrices."""
        wire = matrices.astype(np.float32)
        keep = []
        for k, path in enumerate(paths):
            last = self._matrices.get(path)
            if last is None or not np.array_equal(last, wire[k]):
                self._matrices[path] = wire[k]
                keep.append(k)
        return [paths[k] for k in keep], matrices[keep]

    def labels(
        self, paths: Sequence[str], texts: Sequence[str], rows: Sequence[int]
    ) -> tuple[list[str], list[str], list[int]]:
        """The labels whose text or row differs from the last one sent."""
        out: tuple[list[str], list[str], list[int]] = ([], [], [])
        for path, text, row in zip(paths, texts, rows, strict=True):
            if self._labels.get(path) != (text, row):
                self._labels[path] = (text, row)
                out[0].append(path)
                out[1].append(text)
                out[2].append(row)
        return out
