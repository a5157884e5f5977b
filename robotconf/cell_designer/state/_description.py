"""A designed cell as one frozen value: its unit, its name and its entries, in table order.

:class:`CellDescription` is what the designer's state holds instead of a mutable
:class:`~robotconf.Cell`; :meth:`CellDescription.build` makes the cell (once per
description, cached: the designer never changes a built cell), and
:meth:`CellDescription.from_cell` reads one back, so
``CellDescription.from_cell(d.build()) == d``. Every change makes a new description and
builds its cell, so the core checks every name, parent and pose.

Names follow the cell: a frame's full name joins its parent's and its own
(``"table/pick"``), so renaming or moving an entry renames the frames on it; the
:class:`Renames` map says how, so that programs naming those frames follow.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, replace
from functools import cached_property
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ...cell import NAME_SEPARATOR, Cell
from ._items import FrameItem, Item, ObjectItem, RobotItem, own_name, pose_of, radius_value

__all__ = ["CellDescription", "Renames"]

#: Old full name → new full name of every entry a rename or a new parent renamed.
Renames = dict[str, str]


def _item_of(cell: Cell, name: str) -> Item:
    entry = cell.entries[name]
    if entry.kind == "object":
        assert entry.shape is not None
        return ObjectItem(entry.shape, entry.parent)
    if entry.kind == "frame":
        return FrameItem(name, pose_of(entry.pose), entry.parent)
    return RobotItem(
        name,
        cell.robot(name),
        pose_of(entry.pose),
        entry.parent,
        entry.tool,  # type: ignore[attr-defined]
        radius_value(entry.radius),  # type: ignore[attr-defined]
        tuple(entry.mount),  # type: ignore[attr-defined]
    )


def _radius_argument(radius: Any) -> Any:
    if isinstance(radius, tuple) and radius and isinstance(radius[0], tuple):
        return dict(radius)
    return list(radius) if isinstance(radius, tuple) else radius


@dataclass(frozen=True)
class CellDescription:
    """The cell the designer shows: unit, name and entries (objects, frames, robots).

    Examples
    --------
    >>> import robotconf as rc
    >>> cell = rc.Cell(unit="mm")
    >>> cell.add(rc.Box([60, 40, 4], pose=rc.pose([50, 0, -2]), name="table"))
    'table'
    >>> cell.add_frame("pick", rc.pose([0, 0, 10]), parent="table")
    'table/pick'
    >>> design = CellDescription.from_cell(cell)
    >>> design.names
    ('table', 'table/pick')
    >>> renamed, renames = design.renamed("table", "bench")
    >>> renamed.names, renames
    (('bench', 'bench/pick'), {'table': 'bench', 'table/pick': 'bench/pick'})
    >>> renamed.build().pose_of("bench/pick")[:3, 3]
    array([50.,  0.,  8.])
    """

    items: tuple[Item, ...] = ()
    unit: str | None = None
    name: str | None = None

    # -- cells -------------------------------------------------------------------------

    @classmethod
    def from_cell(cell_class, cell: Cell) -> CellDescription:
        """The description of ``cell`` (its entries in the cell's order)."""
        items = tuple(_item_of(cell, name) for name in cell.entries)
        return cell_class(items, cell.unit, cell.name)

    def build(self) -> Cell:
        """A new :class:`~robotconf.Cell` with these entries (parents added first).

        Raises
        ------
        InvalidInputError
            The cell's own: a name used twice, a parent that is not there, a cycle.
        """
        cell = Cell(unit=self.unit, name=self.name)
        for item in self._parents_first():
            if isinstance(item, ObjectItem):
                cell.add(item.shape, parent=item.parent)
            elif isinstance(item, FrameItem):
                cell.add_frame(own_name(item.name, item.parent), item.pose, parent=item.parent)
            else:
                cell.add_robot(
                    item.name,
                    item.robot,
                    np.array(item.pose),
                    tool=item.tool,
                    radius=_radius_argument(item.radius),
                    mount=item.mount,
                    parent=item.parent,
                )
        return cell

    @cached_property
    def cell(self) -> Cell:
        """The cell built once for this description: read it, never change it."""
        return self.build()

    def _parents_first(self) -> Iterator[Item]:
        index = {item.name: k for k, item in enumerate(self.items)}
        done: set[int] = set()
        for start in range(len(self.items)):
            chain: list[int] = []
            k: int | None = start
            while k is not None and k not in done and k not in chain:
                chain.append(k)
                parent = self.items[k].parent
                k = index.get(parent) if parent is not None else None
            for j in reversed(chain):
                if j not in done:
                    done.add(j)
                    yield self.items[j]

    # -- reading -----------------------------------------------------------------------

    @property
    def names(self) -> tuple[str, ...]:
        """Every entry's (full) name, in table order."""
        return tuple(item.name for item in self.items)

    @property
    def robots(self) -> tuple[str, ...]:
        """The robots' names."""
        return tuple(item.name for item in self.items if isinstance(item, RobotItem))

    @property
    def frames(self) -> tuple[str, ...]:
        """The frames' full names."""
        return tuple(item.name for item in self.items if isinstance(item, FrameItem))

    def item(self, name: str) -> Item:
        """The entry called ``name``.

        Raises
        ------
        InvalidInputError
            No entry has that name.
        """
        for item in self.items:
            if item.name == name:
                return item
        raise InvalidInputError("name", name, f"one of {list(self.names)[:20]}", "not in the cell:")

    def descendants(self, name: str) -> set[str]:
        """The entries placed on ``name``, directly or through others."""
        found: set[str] = set()
        grew = True
        while grew:
            grew = False
            for item in self.items:
                if item.name not in found and (item.parent == name or item.parent in found):
                    found.add(item.name)
                    grew = True
        return found

    # -- changes -----------------------------------------------------------------------

    def with_items(self, items: tuple[Item, ...]) -> CellDescription:
        """The same unit and name with other entries (their cell is built to check them)."""
        changed = replace(self, items=items)
        changed.cell  # noqa: B018 - build now: the core checks every entry
        return changed

    def with_unit(self, unit: str | None) -> CellDescription:
        """The same entries in another named unit (no number changes)."""
        return replace(self, unit=unit)

    def replaced(self, item: Item, name: str | None = None) -> CellDescription:
        """``item`` in place of the entry ``name`` (default: ``item``'s own name)."""
        old = self.item(item.name if name is None else name)
        return self.with_items(tuple(item if i is old else i for i in self.items))

    def added(self, item: Item) -> CellDescription:
        """``item`` appended to the table."""
        return self.with_items((*self.items, item))

    def removed(self, name: str) -> CellDescription:
        """Without the entry ``name``; refused, as the cell refuses it, while entries stand
        on it."""
        self.build().remove(name)  # the core's refusal, word for word
        kept = tuple(i for i in self.items if i.name != name)
        mounts = [
            replace(i, mount=tuple(m for m in i.mount if m != name))
            if isinstance(i, RobotItem)
            else i
            for i in kept
        ]
        return self.with_items(tuple(mounts))

    def renamed(self, name: str, new: str) -> tuple[CellDescription, Renames]:
        """The entry ``name`` called ``new`` (a frame: its own name); frames on it follow."""
        self.item(name)
        return self._rebuilt({name: new}, {})

    def reparented(self, name: str, parent: str | None) -> tuple[CellDescription, Renames]:
        """The entry ``name`` placed on ``parent`` (``None``: the cell), its pose kept as
        typed (relative to the new parent); a frame's full name follows its parent."""
        self.item(name)
        if parent is not None and (parent == name or parent in self.descendants(name)):
            loop = " → ".join((name, parent, name))
            raise InvalidInputError(
                f"{name}.parent", loop, "parents that lead back to the cell", "a cycle of parents:"
            )
        if parent is not None:
            self.item(parent)
        return self._rebuilt({}, {name: parent})

    def _rebuilt(
        self, owns: dict[str, str], parents: dict[str, str | None]
    ) -> tuple[CellDescription, Renames]:
        """Entries with new own names or parents, every full name recomputed from the top."""
        old = {item.name: item for item in self.items}
        own = {
            n: owns.get(n, own_name(n, i.parent) if isinstance(i, FrameItem) else n)
            for n, i in old.items()
        }
        parent_of = {n: parents.get(n, i.parent) for n, i in old.items()}
        full: dict[str, str] = {}

        def full_name(n: str) -> str:
            if n not in full:
                up = parent_of[n]
                framed = isinstance(old[n], FrameItem) and up is not None
                full[n] = f"{full_name(up)}{NAME_SEPARATOR}{own[n]}" if framed else own[n]  # type: ignore[arg-type]
            return full[n]

        items: list[Item] = []
        for n, item in old.items():
            up = parent_of[n]
            new_parent = None if up is None else full_name(up)
            if isinstance(item, ObjectItem):
                items.append(ObjectItem(item.shape.with_name(full_name(n)), new_parent, item.label))
            elif isinstance(item, FrameItem):
                items.append(FrameItem(full_name(n), item.pose, new_parent))
            else:
                mount = tuple(full.get(m, full_name(m) if m in old else m) for m in item.mount)
                items.append(replace(item, name=full_name(n), parent=new_parent, mount=mount))
        renames = {n: full_name(n) for n in old if full_name(n) != n}
        return self.with_items(tuple(items)), renames
