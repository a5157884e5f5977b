"""What every part of the panel shares: guarded callbacks for the few ipywidgets it
observes, the error label, app mode (Voilà), the page layout and monospace text."""

from ._app_mode import VOILA_VARIABLES, app_mode, code_hint, running_in_voila
from ._callbacks import (
    LOGGER,
    Guarded,
    Refusal,
    failure_message,
    guarded,
    observe,
    on_click,
    on_message,
)
from ._errors_display import ErrorLabel
from ._layout import PANEL_CLASS, STYLE, VIEW_CLASS, stylesheet, view_column, workspace
from ._monospace import preformatted

__all__ = [
    "Guarded",
    "guarded",
    "observe",
    "on_click",
    "on_message",
    "failure_message",
    "Refusal",
    "LOGGER",
    "ErrorLabel",
    "app_mode",
    "code_hint",
    "running_in_voila",
    "VOILA_VARIABLES",
    "PANEL_CLASS",
    "VIEW_CLASS",
    "STYLE",
    "stylesheet",
    "view_column",
    "workspace",
    "preformatted",
]
