"""Where a work cell's parts live in the scene, and the path key of every named entry.

A cell's names are free text (``"table/pick"`` holds a ``/``, a student may type any
character); a meshcat path splits at ``/``. So each robot, object and frame gets a short
key of its own (``e1``, ``e2``, …) for its scene paths, kept while the name stays in the
cell; the names themselves travel only as label texts, which the page writes as text.
"""

from __future__ import annotations

from .._commands import ROOT

__all__ = [
    "CELL",
    "OBJECTS",
    "FRAMES",
    "NAMES",
    "ROBOTS",
    "CAPSULES",
    "CONTACTS",
    "REACH",
    "SELECTION",
    "PathKeys",
]

#: Everything a cell scene draws lives under this path.
CELL = f"{ROOT}/cell"
#: An object's group (its pose) and, at ``<object>``, its shape.
OBJECTS = f"{CELL}/objects"
#: A frame's triad.
FRAMES = f"{CELL}/frames"
#: The label anchors of the objects and frames (hidden together with "labels off").
NAMES = f"{CELL}/names"
#: Each robot's drawing (its group carries the base pose).
ROBOTS = f"{CELL}/robots"
#: Each robot's collision capsules, in the cell's frame.
CAPSULES = f"{CELL}/capsules"
#: A loaded run's contacts: red capsules and the labels at the contact points.
CONTACTS = f"{CELL}/contacts"
#: A reach map's voxels and its legend.
REACH = f"{CELL}/reach"
#: The outline around the selected entry.
SELECTION = f"{CELL}/selection"


class PathKeys:
    """A short path key per name, stable while the name is in use.

    >>> keys = PathKeys()
    >>> keys.key("table/pick"), keys.key("arm"), keys.key("table/pick")
    ('e1', 'e2', 'e1')
    >>> keys.forget("arm"); keys.key("arm")
    'e3'
    """

    def __init__(self) -> None:
        self._keys: dict[str, str] = {}
        self._count = 0

    def key(self, name: str) -> str:
        """The key of ``name`` (a new one the first time)."""
        if name not in self._keys:
            self._count += 1
            self._keys[name] = f"e{self._count}"
        return self._keys[name]

    def forget(self, name: str) -> None:
        """``name`` left the cell: a later entry of that name gets a new key (its old
        objects may still be on their way out of a view)."""
        self._keys.pop(name, None)
