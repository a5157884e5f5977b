"""Save and load the robot with its signals as JSON (a download link and a file upload),
and the exports below them."""

from __future__ import annotations

import html
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any

import ipywidgets as widgets

from .._errors import InvalidInputError
from ._app_mode import code_hint
from ._callbacks import observe, on_click
from ._errors_display import ErrorLabel
from ._images import download_link

if TYPE_CHECKING:
    from ._exports import ExportsSection

__all__ = ["FilesSection"]


class FilesSection:
    """The "Save / Load" tab.

    Parameters
    ----------
    save_text : callable
        Returns the JSON text to save (raises on failure).
    load_bytes : callable
        Applies an uploaded file's bytes to the panel (raises on failure).
    app : bool
        The panel runs without cells around it (Voilà): no hint to type code in a cell.
    exports : ExportsSection, optional
        The export buttons, shown below Save and Load.
    """

    def __init__(
        self,
        save_text: Callable[[], str],
        load_bytes: Callable[[bytes], None],
        *,
        app: bool = False,
        exports: ExportsSection | None = None,
    ):
        self.exports = exports
        self._save_text = save_text
        self._load_bytes = load_bytes
        self.filename = widgets.Text(
            value="robot.json", description="file name", layout=widgets.Layout(width="260px")
        )
        self.save_button = widgets.Button(description="Save (download link)", icon="save")
        self.save_link = widgets.HTML()
        self.save_error = ErrorLabel()
        self.upload = widgets.FileUpload(accept=".json,application/json", multiple=False)
        self.load_status = widgets.HTML()
        self.load_error = ErrorLabel()
        self.widget = widgets.VBox(
            [
                widgets.HTML(
                    "<b>Save</b> the robot, its signals and time settings as JSON"
                    + code_hint(" (or <code>panel.save(path)</code> in a cell)", app)
                    + ":"
                ),
                widgets.HBox([self.filename, self.save_button]),
                widgets.HBox([self.save_link, self.save_error.widget]),
                widgets.HTML(
                    "<b>Load</b> a robotconf JSON file"
                    + code_hint(" (or <code>panel.load(path)</code>)", app)
                    + ":"
                ),
                widgets.HBox([self.upload, self.load_status, self.load_error.widget]),
                *([] if exports is None else [widgets.HTML("<hr>"), exports.widget]),
            ]
        )
        on_click(self.save_button, self.save_error, self.make_save_link)
        observe(self.upload, self.load_error, self._uploaded)

    def make_save_link(self) -> str:
        """Build the download link of the current state; returns its HTML (``""`` on error)."""
        self.save_error.clear()
        self.save_link.value = ""  # never a link to an older state, whatever fails below
        try:
            text = self._save_text()
        except InvalidInputError as error:
            self.save_error.show(str(error))
            return ""
        name = self.filename.value.strip() or "robot.json"
        self.save_link.value = download_link(text, name, "application/json", f"download {name}")
        return self.save_link.value

    def _uploaded(self, change: dict[str, Any]) -> None:
        files = change["new"]
        if not files:
            return
        upload = files[0]
        self.load_error.clear()
        self.load_status.value = ""
        try:
            self._load_bytes(bytes(upload["content"]))
        except InvalidInputError as error:
            self.load_error.show(str(error))
        else:
            # The file name is the user's: text, never markup.
            self.load_status.value = f"<small>loaded {html.escape(str(upload['name']))}</small>"

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)``: ``save``, ``load`` and ``export.<key>`` of each export."""
        yield "save", self.save_error
        yield "load", self.load_error
        if self.exports is not None:
            for key, label in self.exports.error_items():
                yield f"export.{key}", label

    def set_visible(self, visible: bool) -> None:
        """Whether the tab shows: the exports' LaTeX view waits until it does."""
        if self.exports is not None:
            self.exports.set_visible(visible)
