"""The one way a widget event reaches the panel's code: every failure is shown, none escapes.

ipywidgets calls an observer or a button handler from the kernel's message loop. An
exception raised there never reaches the student: a button prints a traceback to the
log console, an observer's error is lost in the kernel log, and the control just seems
dead. So every ``observe`` and ``on_click`` of the panel goes through :func:`observe` and
:func:`on_click` below (``tests/test_panel_callbacks.py`` checks that none bypasses them),
which run the callback under a :class:`Guarded` that

- shows the core's :class:`~robotconf.InvalidInputError` message beside the control,
- shows any other exception as ``internal error: <type>: <message>`` beside the control
  and logs its traceback on the ``robotconf.panel`` logger,
- clears its own message at the next call, so a retry that works removes it.

The robot is replaced only after the core accepted a new one, so a failed callback keeps
the last valid robot.

Use it for a new control::

    self.reset_button = widgets.Button(description="reset")
    self.reset_error = ErrorLabel()
    on_click(self.reset_button, self.reset_error, self.reset)
    observe(self.unit, self.reset_error, lambda change: self.set_unit(change["new"]))
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

import ipywidgets as widgets

from ..._errors import InvalidInputError
from ._errors_display import ErrorLabel

__all__ = [
    "Guarded",
    "guarded",
    "observe",
    "on_click",
    "on_message",
    "failure_message",
    "Refusal",
    "LOGGER",
]

#: Where unexpected errors of the panel are logged, with their traceback.
LOGGER = logging.getLogger("robotconf.panel")

#: An error label, or a function that picks one when the error happens (the label of
#: whichever editor is showing, say).
ErrorTarget = ErrorLabel | Callable[[], ErrorLabel]


class Refusal(Exception):
    """A refusal the panel words itself (for the student), shown as its text."""


def failure_message(error: BaseException) -> str:
    """The text shown for ``error``: the core's own message, or ``internal error: …``.

    Parameters
    ----------
    error : BaseException
        What a callback raised.

    Returns
    -------
    str
        ``str(error)`` for an :class:`~robotconf.InvalidInputError` (it names the field,
        the value and what is allowed); ``internal error: <type>: <message>`` otherwise.

    Examples
    --------
    >>> failure_message(InvalidInputError("dt", 0.0, "a time step > 0 (s)", "must be positive,"))
    'dt: must be positive, 0.0; allowed: a time step > 0 (s)'
    >>> failure_message(OverflowError("math range error"))
    'internal error: OverflowError: math range error'
    >>> failure_message(MemoryError())
    'internal error: MemoryError'
    """
    if isinstance(error, (InvalidInputError, Refusal)):
        return str(error)
    detail = str(error)
    name = type(error).__name__
    return f"internal error: {name}: {detail}" if detail else f"internal error: {name}"


class Guarded:
    """A callback that shows any exception it raises on an error label instead.

    Parameters
    ----------
    label : ErrorLabel or callable
        Where a failure is shown (beside the control that calls this), or a function
        returning that label at the time of the failure.
    callback : callable
        Called with the arguments the widget passes (an observer's ``change`` dict, a
        button). Its return value is dropped.

    Examples
    --------
    >>> label = ErrorLabel()
    >>> handler = Guarded(label, lambda change: 1 / change["new"])
    >>> handler({"new": 0})
    >>> label.message
    'internal error: ZeroDivisionError: division by zero'
    >>> handler({"new": 2}); label.message  # the next call that works clears it
    ''
    >>> with handler.paused():  # a programmatic change that must not trigger it
    ...     handler({"new": 0})
    >>> label.message
    ''
    """

    def __init__(self, label: ErrorTarget, callback: Callable[..., Any]):
        self._label = label
        self._callback = callback
        self._shown: tuple[ErrorLabel, str] | None = None
        self._pauses = 0

    @property
    def label(self) -> ErrorLabel:
        """The label a failure would be shown on now."""
        return self._label if isinstance(self._label, ErrorLabel) else self._label()

    def __call__(self, *args: Any) -> None:
        if self._pauses:
            return
        if self._shown is not None:
            label, message = self._shown
            self._shown = None
            if label.message == message:  # still ours: another check may have replaced it
                label.clear()
        try:
            self._callback(*args)
        except Exception as error:  # every failure is shown; the kernel never sees one
            if not isinstance(error, InvalidInputError):
                name = getattr(self._callback, "__qualname__", repr(self._callback))
                LOGGER.exception("panel callback %s failed", name)
            label, message = self.label, failure_message(error)
            label.show(message)
            self._shown = (label, message)

    @contextmanager
    def paused(self) -> Iterator[None]:
        """Within the block the callback does nothing (the panel itself sets a value)."""
        self._pauses += 1
        try:
            yield
        finally:
            self._pauses -= 1


def guarded(label: ErrorTarget, callback: Callable[..., Any]) -> Guarded:
    """``callback`` wrapped so that any exception is shown on ``label``.

    For a callback that is not a widget's (a timer, a comm message); widgets use
    :func:`observe` and :func:`on_click`.

    Parameters
    ----------
    label : ErrorLabel or callable
        Where a failure is shown, or a function returning that label.
    callback : callable
        Called with whatever the caller passes.

    Returns
    -------
    Guarded

    Examples
    --------
    >>> label = ErrorLabel()
    >>> guarded(label, lambda: [].pop())()
    >>> label.message
    'internal error: IndexError: pop from empty list'
    """
    return Guarded(label, callback)


def observe(
    widget: widgets.Widget,
    label: ErrorTarget,
    callback: Callable[[dict[str, Any]], Any],
    names: str | list[str] = "value",
) -> Guarded:
    """Call ``callback(change)`` when trait ``names`` of ``widget`` changes, guarded.

    Parameters
    ----------
    widget : ipywidgets.Widget
        The control.
    label : ErrorLabel or callable
        Beside the control: where a failure is shown (or a function returning it).
    callback : callable
        Receives traitlets' ``change`` dict (``change["new"]`` is the new value).
    names : str or list of str
        The trait(s) to watch.

    Returns
    -------
    Guarded
        The handler; its :meth:`~Guarded.paused` lets the panel set the value itself
        without triggering it.

    Examples
    --------
    >>> box, label = widgets.FloatText(1.0), ErrorLabel()
    >>> handler = observe(box, label, lambda change: 1 / change["new"])
    >>> box.value = 0.0
    >>> label.message
    'internal error: ZeroDivisionError: float division by zero'
    """
    handler = guarded(label, callback)
    widget.observe(handler, names)
    return handler


def on_click(button: widgets.Button, label: ErrorTarget, callback: Callable[[], Any]) -> Guarded:
    """Call ``callback()`` (no argument) when ``button`` is clicked, guarded.

    Parameters
    ----------
    button : ipywidgets.Button
        The button.
    label : ErrorLabel or callable
        Beside the button: where a failure is shown (or a function returning it).
    callback : callable
        Called without arguments.

    Returns
    -------
    Guarded

    Examples
    --------
    >>> button, label = widgets.Button(), ErrorLabel()
    >>> _ = on_click(button, label, lambda: {}["missing"])
    >>> button.click()
    >>> label.message
    "internal error: KeyError: 'missing'"
    """
    handler = guarded(label, lambda _button: callback())
    button.on_click(handler)
    return handler


def on_message(
    widget: widgets.Widget, label: ErrorTarget, callback: Callable[[dict[str, Any]], Any]
) -> Guarded:
    """Call ``callback(content)`` for every custom message a widget's page sends, guarded.

    Parameters
    ----------
    widget : ipywidgets.Widget
        A widget whose front end sends custom messages (an anywidget's ``model.send``).
    label : ErrorLabel or callable
        Where a failure is shown (or a function returning it).
    callback : callable
        Receives the message content (a dict); buffers are ignored.

    Returns
    -------
    Guarded

    Examples
    --------
    >>> relay, label = widgets.DOMWidget(), ErrorLabel()
    >>> _ = on_message(relay, label, lambda content: content["missing"])
    >>> relay._handle_custom_msg({"other": 1}, [])
    >>> label.message
    "internal error: KeyError: 'missing'"
    """
    handler = guarded(label, callback)
    widget.on_msg(lambda _widget, content, _buffers: handler(content))
    return handler
