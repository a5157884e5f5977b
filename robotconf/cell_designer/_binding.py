"""The designer bound to a cell file: loaded from it, every valid change saved to it.

:class:`robotconf.panel.files.FileBinding` does the saving (throttled, atomic, stopped
when another program rewrites the file, the last change written when the kernel exits);
it reads robot files, so this subclass only replaces what is read: a cell file with its
programs (:func:`robotconf.load_cell`). A file that cannot be read is shown and never
overwritten, as for the configurator.
"""

from __future__ import annotations

import html
import os
from pathlib import Path
from typing import Any

from .._errors import InvalidInputError
from ..io import load_cell
from ..panel.files import FileBinding

__all__ = ["CellBinding", "cell_path"]

_UNBOUND = (
    "Not kept in a file: a kernel restart loses this work. "
    '<code>rc.cell_designer("my_cell.json")</code> keeps every change in that file; '
    "<b>Files</b> downloads it."
)


def cell_path(source: object) -> Path | None:
    """The cell file a designer keeps its work in: ``source`` if it is a path, else ``None``.

    Only ``.json`` names are taken, so a mistyped name is refused rather than created.

    >>> str(cell_path("cell.json")), cell_path(None)
    ('cell.json', None)
    >>> cell_path("cell")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: cell: invalid value 'cell'; allowed: a Cell, None, or a ...
    """
    if not isinstance(source, (str, os.PathLike)):
        return None
    path = Path(source)
    if path.suffix.lower() != ".json":
        raise InvalidInputError(
            "cell", str(source), "a Cell, None, or a file name ending in .json to keep the work in"
        )
    return path


class CellBinding(FileBinding):
    """A :class:`~robotconf.panel.files.FileBinding` whose file is a cell file.

    :meth:`load` returns ``(cell, programs)`` (``programs``: ``{robot: (moves,
    options)}``) instead of a robot setup; everything else is the base class's.
    """

    def __init__(self, path: Any, save_text: Any, **options: Any) -> None:
        super().__init__(path, save_text, **options)
        if self.path is None:
            self._status(_UNBOUND)

    def load(self) -> Any:  # type: ignore[override]
        """``(cell, programs)`` from the file, or ``None`` (not bound, not there yet, or
        not readable: then :attr:`error` says why and the file is never written)."""
        if self.path is None:
            return None
        # The base class tells its own writes from another program's by this stamp
        # (inode, modification time, size): it must know the version it read.
        self._stamp = _stamp(self.path)
        if self._stamp is None and not os.path.lexists(self.path):
            return None
        try:
            loaded = load_cell(self.path, with_programs=True)
        except InvalidInputError as error:
            self._refuse(f"{self.name} was not loaded, and will not be overwritten: {error}")
            return None
        self._status(
            f"Loaded from <code>{html.escape(self.name)}</code>; every change is saved to it."
        )
        return loaded


def _stamp(path: Path) -> tuple[int, int, int] | None:
    try:
        info = os.stat(path)
    except FileNotFoundError:
        return None
    return (info.st_ino, info.st_mtime_ns, info.st_size)
