"""A panel bound to a JSON file: loaded from it at start, every valid change saved to it.

``rc.configurator("my_robot.json")`` keeps the work in that file, so a kernel restart or a
reopened notebook loses nothing: run the cell again and the panel is back as it was.

- The file holds the whole setup (the core's format: robot with its q, signals, time
  settings). A missing file is created at once; an existing one is loaded.
- A file that cannot be loaded (corrupt, not robotconf, unreadable) is shown as an error
  and never written: the panel starts from the default robot and saves nothing, so the
  student's file stays as it was until they fix it or pick another name.
- Saving is cheap but not free (about 0.3 ms on a local disk, much more on a network
  home), and a dragged q slider sends dozens of values a second. So the first change is
  written at once and further changes at most every :data:`SAVE_INTERVAL` seconds, the
  last one always (a timer on the kernel's event loop). A change still waiting when the
  kernel shuts down (a restart from the menu) is written on the way out. Without a
  running event loop (a script, the tests) every change is written at once.
- A change the core refuses is not saved (the file keeps the last valid setup); nor is a
  setup with an invalid signal or time setting, until it is fixed.
- If something else rewrites the file while the panel is open (another panel on the same
  file, an editor), the panel stops saving to it rather than overwrite that work.
"""

from __future__ import annotations

import asyncio
import atexit
import html
import os
import time
import weakref
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import ipywidgets as widgets

from ..._errors import InvalidInputError
from ..support._app_mode import code_hint
from ..support._callbacks import LOGGER, guarded
from ..support._errors_display import ErrorLabel
from ._atomic_file import FileStamp, file_stamp, write_atomically
from ._setup_io import setup_parts

__all__ = ["FileBinding", "SAVE_INTERVAL", "bound_path", "event_loop_scheduler", "flush_all"]

#: Shortest time between two writes of the bound file while changes keep coming (s).
SAVE_INTERVAL = 0.5

#: ``schedule(delay, callback)``: run ``callback()`` once, ``delay`` seconds from now.
Schedule = Callable[[float, Callable[[], None]], Any]

_STATUS = '<small style="color:#555">{}</small>'
_UNBOUND = (
    "Not kept in a file: a kernel restart loses this work."
    "{hint} <b>Save</b> on the Save / Load tab downloads it."
)
_UNBOUND_HINT = ' <code>rc.configurator("my_robot.json")</code> keeps every change in that file.'

#: Every binding alive, for the last write when the kernel shuts down.
_LIVE: weakref.WeakSet[FileBinding] = weakref.WeakSet()


def bound_path(source: object) -> Path | None:
    """The file a panel keeps its work in: ``source`` if it is a path, else ``None``.

    Only ``.json`` names are taken, so that ``rc.configurator("paper")`` (meant as a preset)
    says what it accepts instead of creating a file called ``paper``.

    Raises
    ------
    InvalidInputError
        For a path whose name does not end in ``.json``.

    Examples
    --------
    >>> str(bound_path("my_robot.json")), bound_path(None)
    ('my_robot.json', None)
    >>> bound_path("paper")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: robot: invalid value 'paper'; allowed: a Robot, None, or ...
    """
    if not isinstance(source, (str, os.PathLike)):
        return None
    path = Path(source)
    if path.suffix.lower() != ".json":
        raise InvalidInputError(
            "robot",
            str(source),
            "a Robot, None, or a file name ending in .json to keep the work in",
        )
    return path


def event_loop_scheduler() -> Schedule | None:
    """The running asyncio loop's ``call_later`` (a kernel has one), else ``None``.

    >>> event_loop_scheduler() is None  # no event loop runs in a doctest
    True
    """
    try:
        return asyncio.get_running_loop().call_later
    except RuntimeError:
        return None


def flush_all() -> None:
    """Write every bound file that still waits for a change (run when the kernel exits)."""
    for binding in list(_LIVE):
        try:
            binding.flush()
        except Exception:  # noqa: BLE001 - the kernel is going away: log, never raise
            LOGGER.exception("could not save %s on exit", binding.name)


atexit.register(flush_all)


class FileBinding:
    """Keeps the panel's setup in one JSON file (see the module's description).

    Parameters
    ----------
    path : path-like or None
        The file; ``None`` for a panel that is not bound (it then shows a hint).
    save_text : callable
        Returns the setup's JSON text; raises :class:`~robotconf.InvalidInputError` while
        an input is invalid.
    app : bool
        The panel runs without cells (Voilà): the hint names no code.
    interval : float
        :data:`SAVE_INTERVAL`.
    scheduler : callable
        Returns a :data:`Schedule`, or ``None`` to write at once
        (default :func:`event_loop_scheduler`).
    clock : callable
        Seconds, monotonic.

    Attributes
    ----------
    widget : ipywidgets.HTML
        The status line: where the work is kept, or how to keep it.
    error : ErrorLabel
        Why the file was not loaded or could not be written.

    Examples
    --------
    >>> import tempfile
    >>> folder = tempfile.TemporaryDirectory()
    >>> state = {"text": "{}"}
    >>> binding = FileBinding(Path(folder.name) / "a.json", lambda: state["text"])
    >>> binding.load() is None  # no file yet
    True
    >>> binding.start()  # creates it
    >>> state["text"] = '{"b": 2}'; binding.changed()
    >>> (Path(folder.name) / "a.json").read_text()
    '{"b": 2}'
    >>> folder.cleanup()
    """

    def __init__(
        self,
        path: str | os.PathLike[str] | None,
        save_text: Callable[[], str],
        *,
        app: bool = False,
        interval: float = SAVE_INTERVAL,
        scheduler: Callable[[], Schedule | None] = event_loop_scheduler,
        clock: Callable[[], float] = time.monotonic,
    ):
        self.path = None if path is None else Path(path)
        self._save_text = save_text
        self.interval = interval
        self._scheduler = scheduler
        self._clock = clock
        self.widget = widgets.HTML()
        self.widget.add_class("robotconf-file")
        self.error = ErrorLabel()
        self._active = False  # writes allowed: started, bound, and the file is ours
        self._dirty = False
        self._holds = 0
        self._waiting = False  # a timer will write
        self._last_write = -float("inf")
        self._written: str | None = None
        self._saved_at = "not yet"
        self._stamp: FileStamp | None = None
        self._refused = False  # the file is not ours to write: never again
        self._fire = guarded(self.error, self._timer_fired)
        if self.path is None:
            self._status(_UNBOUND.format(hint=code_hint(_UNBOUND_HINT, app)))

    @property
    def name(self) -> str:
        """The file's name as given, or ``""`` when not bound."""
        return "" if self.path is None else str(self.path)

    @property
    def refused(self) -> bool:
        """The file exists but this panel does not write it (unreadable, or changed on disk)."""
        return self._refused

    def load(self) -> tuple[Any, dict[str, Any], dict[str, Any] | None, Any] | None:
        """``(robot, signals, simulation, program)`` from the file, or ``None``.

        ``None`` when not bound, when the file does not exist yet, or when it cannot be
        loaded: then :attr:`error` says why and the file will never be written.
        """
        if self.path is None:
            return None
        self._stamp = file_stamp(self.path)
        if self._stamp is None and not os.path.lexists(self.path):
            return None
        try:
            setup = setup_parts(self.path)
        except InvalidInputError as error:
            self._refuse(f"{self.name} was not loaded, and will not be overwritten: {error}")
            return None
        self._status(
            f"Loaded from <code>{html.escape(self.name)}</code>; every change is saved to it."
        )
        return setup

    def start(self) -> None:
        """Begin saving (the panel is built); a missing file is created now."""
        if self.path is None or self._refused:
            return
        self._active = True
        _LIVE.add(self)
        if self._stamp is None:
            self._dirty = True
            self.flush()

    def changed(self) -> None:
        """A valid change happened: write it now, or soon (see :data:`SAVE_INTERVAL`)."""
        if not self._active:
            return
        self._dirty = True
        if self._holds or self._waiting:
            return
        wait = self._last_write + self.interval - self._clock()
        schedule = self._scheduler() if wait > 0 else None
        if schedule is None:
            self.flush()
            return
        self._waiting = True
        schedule(wait, self._fire)

    @contextmanager
    def batch(self) -> Iterator[None]:
        """Several changes (a whole file loaded), one write at the end."""
        self._holds += 1
        try:
            yield
        finally:
            self._holds -= 1
        if not self._holds and self._dirty:
            self._dirty = False
            self.changed()

    def flush(self) -> bool:
        """Write the current setup now if it changed since the last write.

        Returns
        -------
        bool
            Whether the file was written.
        """
        if not (self._active and self._dirty) or self._holds:
            return False
        assert self.path is not None
        try:
            text = self._save_text()
        except InvalidInputError as error:
            # The file keeps its last valid setup until the cause (named here) is fixed.
            self._status(f"Changes not saved: {html.escape(str(error))}")
            return False
        self._dirty = False
        if text == self._written:
            self._saved_status()  # an input was fixed back to what the file holds
            return False
        current = file_stamp(self.path)
        if current is not None and current != self._stamp:  # a deleted file is rewritten
            self._refuse(
                f"{self.name} changed on disk since this panel saved it (another panel or an "
                "editor?): not overwritten, and this panel no longer saves to it"
            )
            return False
        try:
            self._stamp = write_atomically(self.path, text)
        except OSError as error:
            self._dirty = True  # the next change tries again
            self.error.show(f"file: cannot save to {self.name}: {error.strerror or error}")
            return False
        self.error.clear()
        self._written = text
        self._last_write = self._clock()
        self._saved_at = time.strftime("%H:%M:%S")
        self._saved_status()
        return True

    def owns(self, path: str | os.PathLike[str]) -> bool:
        """Whether ``path`` is the file this binding writes."""
        if not self._active or self.path is None:
            return False
        return os.path.realpath(path) == os.path.realpath(self.path)

    def save_now(self) -> bool:
        """Write the current setup now, whatever the time since the last write."""
        self._dirty = True
        return self.flush()

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)``: ``file``."""
        yield "file", self.error

    def _timer_fired(self) -> None:
        self._waiting = False
        self.flush()

    def _refuse(self, message: str) -> None:
        self._active = False
        self._refused = True
        self.error.show(message)
        self._status(f"<code>{html.escape(self.name)}</code> is left as it is.")

    def _saved_status(self) -> None:
        self._status(
            f"Every change is saved to <code>{html.escape(self.name)}</code> "
            f"(last {self._saved_at})."
        )

    def _status(self, text: str) -> None:
        self.widget.value = _STATUS.format(text)
