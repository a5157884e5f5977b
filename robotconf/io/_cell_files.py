"""Cell files: ``cell.save(path)``, ``cell.to_json()`` and ``rc.load_cell(path)``.

The text is read as robot files are (:func:`~robotconf.io.parse_json`: at most
:data:`~robotconf.io.MAX_BYTES`, strict UTF-8, no NaN, no duplicate keys, bounded
nesting); meshes are read from their paths relative to the cell file, each within its
own budget (:data:`robotconf.cell.MAX_MESH_BYTES`).
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any, Literal, overload

from .._errors import InvalidInputError
from .._validation import one_line
from ..cell import Cell
from ._cell_programs import CellProgram
from ._cell_schema import cell_from_dict, cell_to_dict
from ._files import _NUMBER_LIST, _read, parse_json

__all__ = ["cell_to_json", "save_cell", "load_cell"]


def _folder(path: str | os.PathLike[str] | None) -> Path | None:
    return None if path is None else Path(path).resolve().parent


def cell_to_json(
    cell: Cell,
    path: str | os.PathLike[str] | None = None,
    indent: int | None = 2,
    *,
    programs: Mapping[str, Any] | None = None,
) -> str:
    """The cell file's text; mesh paths are written relative to ``path``'s folder.

    ``programs``: ``{robot name: Program, list of moves or (moves, options)}``, kept in
    the robots' entries (see :func:`~robotconf.io.cell_to_dict`).

    >>> import robotconf as rc
    >>> cell = rc.Cell()
    >>> cell.add_robot("arm", rc.preset("paper"))
    >>> load_cell(cell_to_json(cell)).robot("arm") == rc.preset("paper")
    True
    """
    if not isinstance(cell, Cell):
        raise InvalidInputError("cell", one_line(cell), "a Cell", problem="not a cell:")
    text = json.dumps(
        cell_to_dict(cell, _folder(path), programs=programs),
        indent=indent,
        ensure_ascii=False,
        allow_nan=False,
    )
    return _NUMBER_LIST.sub(
        lambda m: "[" + ", ".join(x.strip() for x in m.group(1).split(",")) + "]", text
    )


def save_cell(
    cell: Cell, path: str | os.PathLike[str], *, programs: Mapping[str, Any] | None = None
) -> Path:
    """Write the cell file (with the robots' ``programs``, if given); returns its path."""
    target = Path(path)
    target.write_text(cell_to_json(cell, target, programs=programs) + "\n", encoding="utf-8")
    return target


@overload
def load_cell(source: str | os.PathLike[str], *, with_programs: Literal[False] = False) -> Cell: ...
@overload
def load_cell(
    source: str | os.PathLike[str], *, with_programs: Literal[True]
) -> tuple[Cell, dict[str, CellProgram]]: ...
def load_cell(
    source: str | os.PathLike[str], *, with_programs: bool = False
) -> Cell | tuple[Cell, dict[str, CellProgram]]:
    """Read a cell file (a path, or the file's JSON text; meshes relative to the file).

    With ``with_programs``: ``(cell, programs)``, ``programs`` mapping each robot whose
    entry has a ``"program"`` to ``(moves, options)``, ready for
    ``cell.program(name, list(moves), **options)`` (moves may name cell frames).

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
        data, folder = parse_json(source.lstrip("\ufeff")), None
    elif isinstance(source, (str, os.PathLike)):
        data, folder = parse_json(_read(source)), _folder(source)
    else:
        raise InvalidInputError("source", one_line(source), "a path or JSON text", problem="not:")
    if with_programs:
        return cell_from_dict(data, folder, with_programs=True)
    return cell_from_dict(data, folder)
