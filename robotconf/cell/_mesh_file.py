"""Reading STL and OBJ files into a mesh, within a budget checked before parsing.

trimesh (a well-kept mesh library) parses the file; it is imported here, on first use.
Before it runs, the file's size (:data:`MAX_MESH_BYTES`) and its triangle count
(binary STL: the header's count, which must match the file's size; text STL and OBJ:
the ``facet`` and ``f`` lines) are checked against :data:`MAX_TRIANGLES`, so a huge or
hostile file is refused in milliseconds. Every error names the file.
"""

from __future__ import annotations

import os
import struct
from pathlib import Path
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from ._shapes import MAX_TRIANGLES, _size

__all__ = ["read_mesh", "MAX_MESH_BYTES", "MESH_SUFFIXES"]

#: Largest mesh file read: 20 MB (about 400 000 triangles of binary STL).
MAX_MESH_BYTES = 20_000_000

#: File types read.
MESH_SUFFIXES = (".stl", ".obj")


def _refuse(path: Path, problem: str, allowed: str = "an STL or OBJ file") -> InvalidInputError:
    return InvalidInputError("mesh file", str(path), allowed, problem=problem)


def _triangle_estimate(raw: bytes, suffix: str, path: Path) -> int:
    if suffix == ".stl" and len(raw) >= 84:
        (count,) = struct.unpack("<I", raw[80:84])
        if len(raw) == 84 + 50 * count:
            return int(count)
        if not raw.lstrip()[:5].lower() == b"solid":
            raise _refuse(
                path,
                f"malformed binary STL (the header counts {count} triangles, "
                f"the file's {len(raw)} bytes do not match):",
            )
    if suffix == ".stl":
        return raw.count(b"facet normal") + raw.count(b"facet  normal")
    # An OBJ face line with k corners makes k − 2 triangles; count corners to bound it.
    faces = [line for line in raw.splitlines() if line.lstrip().startswith(b"f ")]
    return sum(max(len(line.split()) - 3, 0) for line in faces)


def read_mesh(path: Any, scale: Any = 1.0) -> tuple[np.ndarray, np.ndarray, str, str]:
    """``(vertices·scale, faces, source, stem)`` of an STL or OBJ file.

    >>> read_mesh("missing.stl")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: mesh file: not found: 'missing.stl'; allowed: an STL or OBJ file
    """
    if not isinstance(path, (str, os.PathLike)):
        raise InvalidInputError(
            "mesh file", repr(path)[:80], "a path (str or Path)", problem="not a path:"
        )
    factor = _size(scale, "scale")
    target = Path(path)
    suffix = target.suffix.lower()
    if suffix not in MESH_SUFFIXES:
        raise _refuse(
            target, f"not a mesh file type ({suffix or 'no suffix'}):", "a .stl or .obj file"
        )
    try:
        size = target.stat().st_size
        if not target.is_file():
            raise _refuse(target, "not a file:")
    except OSError:
        raise _refuse(target, "not found:") from None
    if size > MAX_MESH_BYTES:
        raise _refuse(
            target, f"too large ({size} bytes):", f"files of at most {MAX_MESH_BYTES} bytes"
        )
    if size == 0:
        raise _refuse(target, "empty:")
    try:
        raw = target.read_bytes()
    except OSError as error:
        raise _refuse(target, f"{error.strerror}:") from None
    estimate = _triangle_estimate(raw, suffix, target)
    if estimate > MAX_TRIANGLES:
        raise _refuse(
            target, f"too many triangles (about {estimate}):", f"at most {MAX_TRIANGLES} triangles"
        )
    import io

    import trimesh

    try:
        kind = suffix[1:]
        loaded: Any = trimesh.load(io.BytesIO(raw), file_type=kind, force="mesh", process=False)
        vertices: np.ndarray = np.array(loaded.vertices, dtype=np.float64)
        faces: np.ndarray = np.array(loaded.faces, dtype=np.int64)
    except Exception as error:  # trimesh raises many kinds on a malformed file
        raise _refuse(target, f"malformed ({type(error).__name__}: {str(error)[:80]}):") from None
    if faces.ndim != 2 or faces.shape[0] == 0 or vertices.shape[0] < 3:
        raise _refuse(target, "no triangles in it:")
    if faces.shape[0] > MAX_TRIANGLES:
        raise _refuse(target, f"too many triangles ({faces.shape[0]}):", f"at most {MAX_TRIANGLES}")
    if not np.all(np.isfinite(vertices)):
        raise _refuse(target, "coordinates that are not finite (NaN or inf):")
    return vertices * np.float64(factor), faces, str(path), target.stem
