"""Cell files: ``cell.save(path)``, ``cell.to_json()`` and ``rc.load_cell(path)``.

The text is read as robot files are (:func:`~robotconf.io.parse_json`: at most
:data:`~robotconf.io.MAX_BYTES`, strict UTF-8, no NaN, no duplicate keys, bounded
nesting); meshes are read from their paths relative to the cell file, each within its
own budget (:data:`robotconf.cell.MAX_MESH_BYTES`).
"""

from __future__ import annotations

import json
import os
from pathlib import Path

from .._errors import InvalidInputError
from .._validation import one_line
from ..cell import Cell
from ._cell_schema import cell_from_dict, cell_to_dict
from ._files import _NUMBER_LIST, _read, parse_json

__all__ = ["cell_to_json", "save_cell", "load_cell"]


def _folder(path: str | os.PathLike[str] | None) -> Path | None:
    return None if path is None else Path(path).resolve().parent


def cell_to_json(
    cell: Cell, path: str | os.PathLike[str] | None = None, indent: int | None = 2
) -> str:
    """The cell file's text; mesh paths are written relative to ``path``'s folder.

    >>> import robotconf as rc
    >>> cell = rc.Cell()
    >>> cell.add_robot("arm", rc.preset("paper"))
    >>> load_cell(cell_to_json(cell)).robot("arm") == rc.preset("paper")
    True
    """
    if not isinstance(cell, Cell):
        raise InvalidInputError("cell", one_line(cell), "a Cell", problem="not a cell:")
    text = json.dumps(
        cell_to_dict(cell, _folder(path)), indent=indent, ensure_ascii=False, allow_nan=False
    )
    return _NUMBER_LIST.sub(
        lambda m: "[" + ", ".join(x.strip() for x in m.group(1).split(",")) + "]", text
    )


def save_cell(cell: Cell, path: str | os.PathLike[str]) -> Path:
    """Write the cell file; returns its path."""
    target = Path(path)
    target.write_text(cell_to_json(cell, target) + "\n", encoding="utf-8")
    return target


def load_cell(source: str | os.PathLike[str]) -> Cell:
    """Read a cell file (a path, or the file's JSON text; meshes relative to the file).

    Raises
    ------
    InvalidInputError
        Naming the JSON path of the first problem (``frames[1].parent``: no such
        parent; ``objects[0].size[2]``: must be > 0; a duplicate name; a cycle of
        parents; a malformed mesh file). No cell is returned from a bad file.

    Examples
    --------
    >>> load_cell('{"format": "robotconf-cell", "version": 1, '
    ...           '"frames": [{"name": "pick", "parent": "table"}]}')
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: frames[0].parent: no such parent: 'table'; ...
    """
    if isinstance(source, str) and source.lstrip("\ufeff").lstrip()[:1] in ("{", "[", '"'):
        return cell_from_dict(parse_json(source.lstrip("\ufeff")), None)
    if not isinstance(source, (str, os.PathLike)):
        raise InvalidInputError("source", one_line(source), "a path or JSON text", problem="not:")
    return cell_from_dict(parse_json(_read(source)), _folder(source))
