"""An inline question with a few answers: the panel asks before it converts or replaces.

Switching the DH convention or the editing mode could keep the numbers or keep the robot;
the panel never picks silently. It shows a small row under the control — a question, one
button per answer and a cancel button — and acts only on a click. A refused answer (the
core cannot convert this robot) shows the core's message in the row, which stays open.
"""

from __future__ import annotations

import functools
import html
from collections.abc import Callable, Sequence

import ipywidgets as widgets

from ._callbacks import on_click
from ._errors_display import ErrorLabel

__all__ = ["ChoicePrompt"]


class ChoicePrompt:
    """A hidden row that asks a question with fixed answers.

    Parameters
    ----------
    choices : sequence of (key, label, tooltip)
        One button per answer.
    on_choice : callable
        ``on_choice(key)`` when an answer is clicked; the row closes unless it raises
        (its message is then shown in the row).
    extra : sequence of widgets, optional
        Shown between the question and the buttons (an option of the answers).

    Examples
    --------
    >>> chosen = []
    >>> prompt = ChoicePrompt([("yes", "do it", "")], chosen.append)
    >>> prompt.ask("Convert?")
    >>> prompt.visible, prompt.question.value
    (True, 'Convert?')
    >>> prompt.buttons["yes"].click()
    >>> chosen, prompt.visible
    (['yes'], False)
    """

    def __init__(
        self,
        choices: Sequence[tuple[str, str, str]],
        on_choice: Callable[[str], None],
        extra: Sequence[widgets.Widget] = (),
    ):
        self._on_choice = on_choice
        self.question = widgets.HTML()
        self.error = ErrorLabel()
        self.buttons: dict[str, widgets.Button] = {}
        for key, label, tooltip in choices:
            button = widgets.Button(
                description=label, tooltip=tooltip, layout=widgets.Layout(width="auto")
            )
            on_click(button, self.error, functools.partial(self._chosen, key))
            self.buttons[key] = button
        self.cancel_button = widgets.Button(
            description="cancel", tooltip="change nothing", layout=widgets.Layout(width="auto")
        )
        on_click(self.cancel_button, self.error, self.close)
        self.widget = widgets.HBox(
            [
                self.question,
                *extra,
                *self.buttons.values(),
                self.cancel_button,
                self.error.widget,
            ],
            layout=widgets.Layout(
                flex_flow="row wrap",
                align_items="center",
                border="1px solid #e0c060",
                padding="2px 6px",
                margin="2px 0",
                display="none",
            ),
        )

    @property
    def visible(self) -> bool:
        """Whether the question is showing."""
        return self.widget.layout.display != "none"

    def ask(self, question: str) -> None:
        """Show ``question`` (plain text) and the answers."""
        self.error.clear()
        self.question.value = html.escape(question, quote=False)
        self.widget.layout.display = "flex"

    def close(self) -> None:
        """Hide the row (nothing changes)."""
        self.error.clear()
        self.widget.layout.display = "none"

    def _chosen(self, key: str) -> None:
        self._on_choice(key)
        self.close()
