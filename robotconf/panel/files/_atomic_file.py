"""Replace a text file in one step, so that a reader never sees half of it.

The panel rewrites its bound file after every change. Writing the file in place would
leave it truncated if the kernel died mid-write (a restart, an out-of-memory kill); so
the text goes to a temporary file in the same folder, which :func:`os.replace` then puts
in place atomically: the file holds either the old text or the new one.

There is no ``fsync``: the threat is a kernel that dies, and the operating system keeps
what a dead process wrote; a flush to disk would cost milliseconds on every change.
"""

from __future__ import annotations

import contextlib
import os
import secrets
import stat
from pathlib import Path

__all__ = ["FileStamp", "file_stamp", "write_atomically"]

#: What identifies one version of a file on disk: inode, modification time (ns), size.
#: Every atomic replacement makes a new inode, so another writer always changes it.
FileStamp = tuple[int, int, int]


def file_stamp(path: str | os.PathLike[str]) -> FileStamp | None:
    """The :data:`FileStamp` of ``path`` now, or ``None`` if there is no such file.

    >>> file_stamp("/no/such/file") is None
    True
    """
    try:
        info = os.stat(path)
    except FileNotFoundError:
        return None
    return (info.st_ino, info.st_mtime_ns, info.st_size)


def write_atomically(path: str | os.PathLike[str], text: str) -> FileStamp:
    """Replace ``path`` by ``text`` (UTF-8) in one step; returns the new file's stamp.

    An existing file keeps its permission bits; a new one gets the usual ones (the
    umask applies). A symbolic link is followed: its target is replaced.

    Parameters
    ----------
    path : path-like
    text : str

    Returns
    -------
    FileStamp

    Raises
    ------
    OSError
        When the folder cannot be written (the file is then left as it was).

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     target = Path(folder) / "robot.json"
    ...     _ = write_atomically(target, "{}")
    ...     _ = write_atomically(target, '{"a": 1}')
    ...     target.read_text(), sorted(p.name for p in Path(folder).iterdir())
    ('{"a": 1}', ['robot.json'])
    """
    target = Path(os.path.realpath(path))
    temporary = target.with_name(f".{target.name}.{secrets.token_hex(4)}.tmp")
    # O_EXCL: never write through a file (or link) someone else put under that name.
    handle = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
    try:
        with os.fdopen(handle, "w", encoding="utf-8", newline="\n") as stream:
            stream.write(text)
        with contextlib.suppress(FileNotFoundError):  # a new file: the umask chose its mode
            os.chmod(temporary, stat.S_IMODE(os.stat(target).st_mode))
        os.replace(temporary, target)
    except BaseException:
        temporary.unlink(missing_ok=True)
        raise
    stamp = file_stamp(target)
    assert stamp is not None  # just written
    return stamp
