"""The controls a form can show, as plain dicts the page draws (``js/controls.js``).

Every builder returns a JSON-able dict; a form is a list of :func:`row`\\ s of lines of
controls. Text is never markup: the page writes every label, message and option as text.
"""

from __future__ import annotations

import base64
from collections.abc import Sequence
from typing import Any

__all__ = [
    "number",
    "select",
    "toggle",
    "button",
    "check",
    "text",
    "image",
    "field",
    "link",
    "row",
    "message",
]


def message(text: str, tone: str = "error") -> dict[str, str] | None:
    """A message beside a control or under a row (``tone``: error, warning, ok, note);
    ``None`` for no text.

    >>> message("dt: must be positive")
    {'text': 'dt: must be positive', 'tone': 'error'}
    """
    return {"text": text, "tone": tone} if text else None


def _common(control: dict[str, Any], options: dict[str, Any]) -> dict[str, Any]:
    for name, value in options.items():
        if value is not None and value != "" and value is not False:
            control[name] = value
    return control


def number(
    key: str,
    value: float,
    low: float,
    high: float,
    step: float,
    *,
    label: str = "",
    unit: str = "",
    slider: bool = True,
    disabled: bool = False,
    rev: str = "",
    text: str | None = None,
    note: dict[str, str] | None = None,
    title: str = "",
    width: str = "",
    label_width: str = "",
    widen: bool = True,
    live: bool = False,
    css_class: str = "",
) -> dict[str, Any]:
    """A number: a slider and a box (``slider=False``: the box alone).

    Parameters
    ----------
    key : str
        The control's name in events and in ``panel.errors``.
    value : float
        The number shown (display units); the slider shows it clamped to its range.
    low, high, step : float
        The slider's range and notch (display units).
    text : str, optional
        Shown in the box instead of ``value``: what the student typed and the kernel
        refused (the message says why).
    note : dict, optional
        A :func:`message` beside the box.
    rev : str
        The control's meaning (units, row): events made for another ``rev`` are stale.
    live : bool
        Send the text during pauses in typing too (a formula that follows the box).

    Examples
    --------
    >>> number("q", 30.0, -180, 180, 1, label="q", unit="deg")["slider"]
    True
    """
    control: dict[str, Any] = {
        "type": "number",
        "key": key,
        "value": value,
        "min": low,
        "max": high,
        "step": step,
        "slider": slider,
        "rev": rev,
    }
    if not widen:
        control["widen"] = False
    return _common(
        control,
        {
            "label": label,
            "unit": unit,
            "disabled": disabled,
            "text": text,
            "message": note,
            "title": title,
            "width": width,
            "label_width": label_width,
            "live": live,
            "class": css_class,
        },
    )


def select(
    key: str,
    value: Any,
    options: Sequence[tuple[str, Any]],
    *,
    label: str = "",
    disabled: bool = False,
    rev: str = "",
    note: dict[str, str] | None = None,
    title: str = "",
    width: str = "",
    css_class: str = "",
) -> dict[str, Any]:
    """A dropdown of ``(text, value)`` options showing ``value``.

    >>> select("kind", "Rz", [("3 Rz", "Rz"), ("6 Tz", "Tz")])["options"]
    [['3 Rz', 'Rz'], ['6 Tz', 'Tz']]
    """
    control: dict[str, Any] = {
        "type": "select",
        "key": key,
        "value": value,
        "options": [[str(text), option] for text, option in options],
        "rev": rev,
    }
    return _common(
        control,
        {
            "label": label,
            "disabled": disabled,
            "message": note,
            "title": title,
            "width": width,
            "class": css_class,
        },
    )


def toggle(
    key: str,
    value: Any,
    options: Sequence[tuple[str, Any] | tuple[str, Any, str]],
    *,
    label: str = "",
    disabled: bool = False,
    rev: str = "",
    css_class: str = "",
) -> dict[str, Any]:
    """Side-by-side buttons, one chosen (``(text, value[, tooltip])`` options).

    >>> toggle("unit", True, [("deg", True), ("rad", False)])["options"]
    [['deg', True, ''], ['rad', False, '']]
    """
    shown = [[str(o[0]), o[1], str(o[2]) if len(o) > 2 else ""] for o in options]
    control: dict[str, Any] = {
        "type": "toggle",
        "key": key,
        "value": value,
        "options": shown,
        "rev": rev,
    }
    return _common(control, {"label": label, "disabled": disabled, "class": css_class})


def button(
    key: str,
    label: str,
    *,
    title: str = "",
    disabled: bool = False,
    style: str = "",
    rev: str = "",
    css_class: str = "",
) -> dict[str, Any]:
    """A button (``style="primary"`` for the one that runs things).

    >>> button("run", "Run", style="primary")["style"]
    'primary'
    """
    control: dict[str, Any] = {"type": "button", "key": key, "label": label, "rev": rev}
    return _common(
        control, {"title": title, "disabled": disabled, "style": style, "class": css_class}
    )


def check(
    key: str,
    value: bool,
    label: str,
    *,
    title: str = "",
    disabled: bool = False,
    rev: str = "",
    css_class: str = "",
) -> dict[str, Any]:
    """A checkbox with its label.

    >>> check("all", True, "show all solutions")["value"]
    True
    """
    control: dict[str, Any] = {
        "type": "check",
        "key": key,
        "value": bool(value),
        "label": label,
        "rev": rev,
    }
    return _common(control, {"title": title, "disabled": disabled, "class": css_class})


def text(
    value: str, *, tone: str = "", key: str = "", title: str = "", css_class: str = ""
) -> dict[str, Any]:
    """Plain text in a line (``tone``: title, note, error, warning, ok).

    >>> text("M1", tone="title")
    {'type': 'text', 'value': 'M1', 'tone': 'title'}
    """
    control: dict[str, Any] = {"type": "text", "value": value}
    return _common(control, {"tone": tone, "key": key, "title": title, "class": css_class})


def image(png: bytes, *, alt: str, width: str = "", key: str = "") -> dict[str, Any]:
    """A PNG picture (a signal's preview) in a line, as a ``data:`` URI.

    >>> image(b"\\x89PNG", alt="preview")["src"][:22]
    'data:image/png;base64,'
    """
    src = "data:image/png;base64," + base64.b64encode(png).decode("ascii")
    return _common({"type": "image", "src": src, "alt": alt}, {"width": width, "key": key})


def field(
    key: str, value: str, *, label: str = "", width: str = "", rev: str = "", css_class: str = ""
) -> dict[str, Any]:
    """A line of text to type (a file name); sent with Enter or on leaving the box.

    >>> field("save.name", "robot.json", label="file name")["value"]
    'robot.json'
    """
    control: dict[str, Any] = {"type": "field", "key": key, "value": value, "rev": rev}
    return _common(control, {"label": label, "width": width, "class": css_class})


def link(
    href: str, download: str, label: str, *, key: str = "", css_class: str = ""
) -> dict[str, Any]:
    """A download link for content the kernel made (``href``: a ``data:`` URI).

    >>> link("data:text/plain;base64,eA==", "x.txt", "x.txt (1 B)")["download"]
    'x.txt'
    """
    control = {"type": "link", "href": href, "download": download, "label": label}
    return _common(control, {"key": key, "class": css_class})


def row(
    key: str,
    *lines: Sequence[dict[str, Any]],
    box: bool = False,
    note: dict[str, str] | None = None,
    css_class: str = "",
) -> dict[str, Any]:
    """A row of the form: one or more lines of controls (each line wraps), a border
    (``box``) and a message under it.

    >>> row("m0", [text("M1")], box=True)["lines"]
    [[{'type': 'text', 'value': 'M1'}]]
    """
    shown: dict[str, Any] = {"key": key, "lines": [list(line) for line in lines]}
    return _common(shown, {"box": box, "message": note, "class": css_class})
