"""One widget for every editor of the panel: rows of controls drawn in the page from a
spec, the student's input sent back as events.

The widget
    :class:`Form`, :class:`FormEvent`, :data:`EVENTS`, :func:`find_control`
Controls (plain dicts)
    :func:`row`, :func:`number`, :func:`select`, :func:`toggle`, :func:`button`,
    :func:`check`, :func:`text`, :func:`image`, :func:`field`, :func:`link`,
    :func:`message`
Numbers
    :func:`display_number`, :func:`snap_to_step`, :func:`parse_number`
"""

from .._numbers import display_number, parse_number, snap_to_step
from ._controls import (
    button,
    check,
    field,
    image,
    link,
    message,
    number,
    row,
    select,
    text,
    toggle,
)
from ._widget import EVENTS, Form, FormEvent, find_control

__all__ = [
    "Form",
    "FormEvent",
    "EVENTS",
    "find_control",
    "row",
    "number",
    "select",
    "toggle",
    "button",
    "check",
    "text",
    "image",
    "field",
    "link",
    "message",
    "display_number",
    "snap_to_step",
    "parse_number",
]
