"""The Files tab (the cell file and the scene as downloads) and a mesh from an upload.

A link is made for the document on screen when its button is pressed and goes when the
document changes, so it never points at an older cell. An uploaded mesh is written
beside the bound cell file (the file then refers to it by its relative path, as
``cell.save`` does); a designer without a file keeps it in memory and its cell file
holds the triangles inline.
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

from ..._errors import InvalidInputError
from ...cell import MAX_MESH_BYTES, Mesh
from ...panel.files import data_uri, file_stem
from ...panel.form import Form, FormEvent, button, field, link, message, row, text
from ..state import DesignerState

__all__ = ["FilesView", "mesh_from_upload", "MESH_TYPES"]

#: Mesh files an upload may hold.
MESH_TYPES = (".stl", ".obj")
#: What an export makes: the content, the file name and its MIME type.
Download = tuple[bytes | str, str, str]


def _size_text(size: int) -> str:
    return (
        f"{size} B"
        if size < 1000
        else f"{size / 1e3:.0f} kB"
        if size < 1e6
        else f"{size / 1e6:.2g} MB"
    )


def mesh_from_upload(content: bytes, filename: str, folder: Path | None) -> tuple[Mesh, str | None]:
    """``(mesh, label)`` from an uploaded STL or OBJ file.

    With ``folder`` (the bound cell file's) the bytes are written there under a safe,
    unused name and read back (``label`` is ``None``: the file names it); without, they
    are read from a temporary file and kept inline, ``label`` the upload's name.

    Raises
    ------
    InvalidInputError
        Not an STL or OBJ name, too large, or what :meth:`robotconf.Mesh.load` refuses.
    """
    suffix = Path(str(filename)).suffix.lower()
    if suffix not in MESH_TYPES:
        raise InvalidInputError("mesh file", str(filename), "an .stl or .obj file", "not a mesh:")
    if len(content) > MAX_MESH_BYTES:
        raise InvalidInputError(
            "mesh file", f"<{len(content)} bytes>", f"at most {MAX_MESH_BYTES} bytes", "too large:"
        )
    stem = file_stem(Path(str(filename)).stem, "mesh")
    if folder is not None:
        target = folder / f"{stem}{suffix}"
        count = 1
        while target.exists() and target.read_bytes() != content:
            count += 1
            target = folder / f"{stem}_{count}{suffix}"
        if not target.exists():
            with open(target, "xb") as stream:  # never through a file someone else put there
                stream.write(content)
        return Mesh.load(target, name=stem), None
    with tempfile.TemporaryDirectory() as scratch:
        path = Path(scratch, f"{stem}{suffix}")
        path.write_bytes(content)
        read = Mesh.load(path, name=stem)
    return Mesh(read.vertices, read.faces, name=stem), str(filename)


class FilesView:
    """Downloads: the cell file and the 3D scene as one HTML page that opens offline.

    Parameters
    ----------
    dispatch : callable
        ``dispatch(action_or_error, key, typed=None)``.
    cell_text : callable
        The cell file's text (raises while it cannot be written).
    scene_page : callable
        ``title -> HTML text`` of the scene.
    stem : callable
        The file-name stem (the bound file's, else the cell's name).
    """

    def __init__(
        self,
        dispatch: Callable[..., None],
        cell_text: Callable[[], str],
        scene_page: Callable[[str], str],
        stem: Callable[[], str],
    ) -> None:
        self._dispatch = dispatch
        self._cell_text = cell_text
        self._scene_page = scene_page
        self._stem = stem
        self._state: DesignerState | None = None
        self._links: dict[str, tuple[Any, dict[str, Any]]] = {}
        self.filename = ""
        self.form = Form(self._event, css_class="robotconf-cell-files")

    def render(self, state: DesignerState, messages: Any, rev: str) -> None:
        """The buttons, and the links made for this very document."""
        self._state = state
        name = self.filename or f"{self._stem()}.json"
        self.form.show(
            [
                row(
                    "save",
                    [
                        text(
                            "The cell with its programs, as a cell file (rc.load_cell reads it):",
                            tone="title",
                        )
                    ],
                    [
                        field("save.name", name, label="file name", width="200px", rev=rev),
                        button(
                            "save.make", "cell file (download)", css_class="robotconf-cell-save"
                        ),
                        *self._link("save", state),
                    ],
                    note=message(messages.text("save")),
                ),
                row(
                    "scene",
                    [
                        text(
                            "The 3D view as one HTML page that opens offline "
                            "(the last run animated):",
                            tone="title",
                        )
                    ],
                    [
                        button(
                            "scene.make",
                            "3D scene (HTML)",
                            css_class="robotconf-cell-scene-html",
                        ),
                        *self._link("scene", state),
                    ],
                    note=message(messages.text("scene")),
                ),
            ]
        )

    def _link(self, key: str, state: DesignerState) -> list[dict[str, Any]]:
        made = self._links.get(key)
        return [made[1]] if made is not None and made[0] == state.document else []

    def _event(self, event: FormEvent) -> None:
        if event.key == "save.name":
            self.filename = (event.text or "").strip()
            self._dispatch(None, "save")
        elif event.key == "save.make":
            self._make("save", self._save)
        elif event.key == "scene.make":
            self._make("scene", self._scene)

    def _make(self, key: str, produce: Callable[[], Download]) -> None:
        state = self._state
        if state is None:
            return
        self._links.pop(key, None)
        try:
            content, name, mime = produce()
        except InvalidInputError as error:
            self._dispatch(error, key)
            return
        raw = content.encode("utf-8") if isinstance(content, str) else content
        spec = link(
            data_uri(raw, mime),
            name,
            f"{name} ({_size_text(len(raw))})",
            key=f"{key}.link",
            css_class="robotconf-download",
        )
        self._links[key] = (state.document, spec)
        self._dispatch(None, key)

    def _save(self) -> Download:
        name = (
            file_stem(os.path.splitext(self.filename)[0], self._stem())
            if self.filename
            else self._stem()
        )
        return self._cell_text(), f"{name}.json", "application/json"

    def _scene(self) -> Download:
        stem = self._stem()
        return self._scene_page(stem), f"{stem}_scene.html", "text/html"
