"""Save and load the robot with its signals as JSON: a download link and a file upload."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import ipywidgets as widgets

from ._errors_display import ErrorLabel
from ._images import download_link

__all__ = ["FilesSection"]


class FilesSection:
    """The "Save / Load" tab.

    Parameters
    ----------
    save_text : callable
        Returns the JSON text to save (raises on failure).
    load_bytes : callable
        Applies an uploaded file's bytes to the panel (raises on failure).
    """

    def __init__(self, save_text: Callable[[], str], load_bytes: Callable[[bytes], None]):
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
                    "<b>Save</b> the robot, its signals and time settings as JSON "
                    "(or <code>panel.save(path)</code> in a cell):"
                ),
                widgets.HBox([self.filename, self.save_button]),
                widgets.HBox([self.save_link, self.save_error.widget]),
                widgets.HTML(
                    "<b>Load</b> a robotconf JSON file (or <code>panel.load(path)</code>):"
                ),
                widgets.HBox([self.upload, self.load_status, self.load_error.widget]),
            ]
        )
        self.save_button.on_click(lambda _: self.make_save_link())
        self.upload.observe(self._uploaded, "value")

    def make_save_link(self) -> str:
        """Build the download link of the current state; returns its HTML (``""`` on error)."""
        self.save_error.clear()
        try:
            text = self._save_text()
        except ValueError as error:
            self.save_link.value = ""
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
        try:
            self._load_bytes(bytes(upload["content"]))
        except ValueError as error:
            self.load_status.value = ""
            self.load_error.show(str(error))
        else:
            self.load_status.value = f"<small>loaded {upload['name']}</small>"

    def error_items(self) -> Any:
        """``(key, label)``: ``save`` and ``load``."""
        yield "save", self.save_error
        yield "load", self.load_error
