"""What every row of the designer's tables shares: the row's name, parent, select and
remove controls, and reading an event's key back into a row index and a field.

Keys name rows by their index in the cell's table (``entry[3].pose0``), never by the
entry's name: names come from files and are the student's, and a rename must not
change what a control means. The index is only valid for the layout it was drawn in,
which the control's ``rev`` carries (an event of an older layout is dropped).
"""

from __future__ import annotations

import re
from typing import Any

from ...panel.form import button, field, select
from ..state import CellDescription, FrameItem, Item, own_name
from ._messages import Messages

__all__ = [
    "CELL_PARENT",
    "parse_key",
    "parent_choices",
    "head_controls",
    "SELECTED_CLASS",
]

#: The parent menu's value for "placed in the cell's frame" (JSON has no None option).
CELL_PARENT = ""
#: The class of a selected row (browser tests and the stylesheet find it).
SELECTED_CLASS = "robotconf-cell-selected"
_KEY = re.compile(r"^(?P<table>[a-z]+)\[(?P<index>\d+)\]\.(?P<field>[a-z_]+)(?P<part>\d*)$")


def parse_key(key: str) -> tuple[str, int, str, int | None] | None:
    """``(table, row, field, component)`` of a control key, or ``None`` for another key.

    >>> parse_key("entry[3].pose0"), parse_key("robot[0].name"), parse_key("add.box")
    (('entry', 3, 'pose', 0), ('robot', 0, 'name', None), None)
    """
    found = _KEY.match(key)
    if found is None:
        return None
    part = found.group("part")
    return found["table"], int(found["index"]), found["field"], int(part) if part else None


def parent_choices(cell: CellDescription, item: Item) -> list[tuple[str, str]]:
    """The parent menu of ``item``: the cell, then every entry it may stand on (not
    itself, nor anything standing on it)."""
    barred = cell.descendants(item.name) | {item.name}
    choices = [("— cell —", CELL_PARENT)]
    choices += [(name, name) for name in cell.names if name not in barred]
    return choices


def head_controls(
    prefix: str,
    item: Item,
    cell: CellDescription,
    selected: bool,
    messages: Messages,
    rev: str,
) -> list[dict[str, Any]]:
    """Name, parent, select and remove: the first line of a row."""
    own = own_name(item.name, item.parent) if isinstance(item, FrameItem) else item.name
    parent = CELL_PARENT if item.parent is None else item.parent
    return [
        field(f"{prefix}.name", own, width="110px", rev=rev, css_class="robotconf-cell-name"),
        select(
            f"{prefix}.parent",
            parent,
            parent_choices(cell, item),
            label="on",
            rev=rev,
            width="130px",
            title="the entry it stands on: its pose is in that entry's frame",
            note=_note(messages, f"{prefix}.parent"),
        ),
        button(
            f"{prefix}.select",
            "● selected" if selected else "select",
            title="highlight it in the view",
            rev=rev,
            css_class="robotconf-cell-select",
        ),
        button(
            f"{prefix}.remove",
            "✕",
            title="remove (↶ brings it back)",
            rev=rev,
            css_class="robotconf-cell-remove",
        ),
    ]


def _note(messages: Messages, key: str) -> dict[str, str] | None:
    text = messages.text(key)
    return {"text": text, "tone": "error"} if text else None
