"""The form widget: rows of controls drawn in the page from one spec, and the student's
input sent back as events.

One anywidget shows a whole editor (every module row, every signal, every move): the
kernel sends its spec, a JSON-able dict of rows of controls (:mod:`._controls` builds
them), and the page draws it. The page sends an event only when the student acts — a
drag, a typed value, a click — never when the kernel changes a value, a range or a step,
so a value the kernel shows can never come back as an edit. While the student holds a
control, the page keeps their value on screen. Each control carries a ``rev``: an event
made for an older meaning of the control (before a unit switch, before rows moved)
carries the old one and is dropped by :class:`Form`.

Every event is answered (``{"ack": seq}``), so the page can keep a few drag positions on
the way without waiting for each round trip.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import anywidget
import traitlets

__all__ = ["Form", "FormEvent", "EVENTS", "find_control"]

_HERE = Path(__file__).parent / "js"
#: The control views first, then the form that uses them: one module for the page.
_SCRIPT = "\n".join((_HERE / name).read_text("utf-8") for name in ("controls.js", "form.js"))
_STYLE = (_HERE / "form.css").read_text("utf-8")

#: What the page reports: a slider drag or a stepped box (``value``), typed text sent
#: with Enter or on leaving the box (``type``) or, for a live field, during a pause in
#: typing (``typing``; text that is no number yet is no mistake), a choice (``value``),
#: a click, a checkbox (``value``), the widen button.
EVENTS = ("drag", "type", "typing", "choose", "click", "check", "widen")
#: Longest typed text taken (longer text is refused before it is read).
MAX_TEXT = 200


class FormEvent:
    """One thing the student did to a control of a form.

    Attributes
    ----------
    key : str
        The control's key (``"modules[1].q"``).
    event : str
        One of :data:`EVENTS`.
    value : object
        The number dragged to, the option chosen, the box ticked (``None`` for clicks
        and typed text).
    text : str or None
        What was typed (``type`` events).
    """

    __slots__ = ("key", "event", "value", "text")

    def __init__(self, key: str, event: str, value: Any = None, text: str | None = None):
        self.key = key
        self.event = event
        self.value = value
        self.text = text

    def __repr__(self) -> str:
        return f"FormEvent({self.key!r}, {self.event!r}, value={self.value!r}, text={self.text!r})"


def _event_from(content: Any, current: dict[str, str]) -> FormEvent | None:
    """The event a page message describes, or ``None`` for a malformed or stale one."""
    if not isinstance(content, dict):
        return None
    key, event = content.get("key"), content.get("event")
    if not isinstance(key, str) or event not in EVENTS or key not in current:
        return None
    if content.get("rev") != current[key]:
        return None  # made for an older meaning of the control
    value = content.get("value")
    text = content.get("text")
    if event == "drag":
        if isinstance(value, bool) or not isinstance(value, int | float):
            return None
        if not math.isfinite(value):
            return None
        value = float(value)
    if event in ("type", "typing"):
        if not isinstance(text, str):
            return None
        text = text[: MAX_TEXT + 1]
    if event == "check":
        value = bool(value)
    return FormEvent(key, str(event), value, text)


def find_control(spec: dict[str, Any], key: str) -> dict[str, Any] | None:
    """The control with ``key`` in a form's spec, or ``None``.

    >>> spec = {"rows": [{"key": "r", "lines": [[{"type": "button", "key": "go"}]]}]}
    >>> find_control(spec, "go")["type"]
    'button'
    """
    for control in _controls(spec):
        if control.get("key") == key:
            return control
    return None


def _controls(spec: dict[str, Any]) -> Iterator[dict[str, Any]]:
    for row in spec.get("rows", ()):
        for line in row.get("lines", ()):
            yield from line


class Form(anywidget.AnyWidget):
    """Rows of controls, drawn in the page from :attr:`spec`.

    Parameters
    ----------
    on_event : callable, optional
        ``on_event(FormEvent)`` for every current event from the page (stale and
        malformed ones are dropped). Errors are the caller's to show.
    css_class : str, optional
        A class on the form's root element (for browser tests and stylesheets).

    Examples
    --------
    >>> from robotconf.panel.form import button, number, row
    >>> events = []
    >>> form = Form(events.append)
    >>> form.show([row("r", [number("q", 30.0, -180, 180, 1, label="q", unit="deg")],
    ...                [button("go", "Go")])])
    >>> form.user("q").drag(31.0)  # what the page sends while the slider is dragged
    >>> form.user("go").click()
    >>> [(e.key, e.event, e.value) for e in events]
    [('q', 'drag', 31.0), ('go', 'click', None)]
    """

    _esm = traitlets.Unicode(_SCRIPT).tag(sync=True)
    _css = traitlets.Unicode(_STYLE).tag(sync=True)
    #: The spec as JSON text: the widget layer sends a string as it is, where it would
    #: walk a dict of a hundred controls looking for binary buffers at every change.
    _spec_json = traitlets.Unicode("{}").tag(sync=True)

    def __init__(
        self,
        on_event: Callable[[FormEvent], None] | None = None,
        css_class: str = "",
        **kwargs: Any,
    ) -> None:
        super().__init__(**kwargs)
        self._on_event = on_event
        self._class = css_class
        self._revs: dict[str, str] = {}
        #: What the page shows: ``{"rows": [...], "class": ...}``.
        self.spec: dict[str, Any] = {}
        self._row_texts: dict[int, tuple[dict[str, Any], str]] = {}
        #: Events received from the page (for tests and benchmarks).
        self.received = 0
        self.on_msg(self._message)

    def show(self, rows: list[dict[str, Any]]) -> None:
        """Draw ``rows`` (the page gets the spec only when it changed)."""
        spec = {"rows": rows, "class": self._class}
        self._revs = {c["key"]: c.get("rev", "") for c in _controls(spec) if "key" in c}
        if spec == self.spec:
            return
        self.spec = spec
        # A row the caller drew again as the very same dict keeps its JSON text: a q drag
        # encodes the one row that changed, not the whole table.
        texts: dict[int, tuple[dict[str, Any], str]] = {}
        for r in rows:
            known = self._row_texts.get(id(r))
            texts[id(r)] = (r, _json(r)) if known is None or known[0] is not r else known
        self._row_texts = texts
        parts = ",".join(texts[id(r)][1] for r in rows)
        self._spec_json = f'{{"rows":[{parts}],"class":{_json(self._class)}}}'

    def control(self, key: str) -> dict[str, Any]:
        """The spec of control ``key`` as the page shows it.

        Raises
        ------
        KeyError
            No control has that key.
        """
        found = find_control(self.spec, key)
        if found is None:
            raise KeyError(key)
        return found

    def control_keys(self) -> list[str]:
        """Every control's key, in order."""
        return [c["key"] for c in _controls(self.spec) if "key" in c]

    def receive(self, content: dict[str, Any]) -> None:
        """Handle one page message (a dict as the page sends it): a current event goes to
        ``on_event``; stale and malformed ones are dropped. Answered whatever happens."""
        try:
            event = _event_from(content, self._revs)
            if event is not None:
                self.received += 1
                if self._on_event is not None:
                    self._on_event(event)
        finally:
            if isinstance(content, dict) and "seq" in content:
                self.send({"ack": content.get("seq")})

    def user(self, key: str) -> _User:
        """Act on control ``key`` as a student in the page would (tests, notebooks)."""
        self.control(key)  # only controls the page shows can be used
        return _User(self, key)

    def _message(self, _widget: Any, content: Any, _buffers: Any) -> None:
        self.receive(content)


def _json(value: Any) -> str:
    # No NaN or infinity reaches the page: JSON has none, and JSON.parse refuses them.
    return json.dumps(value, separators=(",", ":"), allow_nan=False)


class _User:
    """What a student can do to one control: the page's own messages, sent here."""

    def __init__(self, form: Form, key: str) -> None:
        self._form = form
        self._key = key

    def _send(self, event: str, **content: Any) -> None:
        rev = self._form.control(self._key).get("rev", "")
        self._form.receive({"key": self._key, "event": event, "rev": rev, **content})

    def drag(self, value: float) -> None:
        """Drag the slider (or step the box with an arrow key) to ``value``."""
        self._send("drag", value=value)

    def type(self, text: str) -> None:
        """Type ``text`` into the box and press Enter."""
        self._send("type", text=str(text))

    def typing(self, text: str) -> None:
        """Type ``text`` into a live field and pause (not yet Enter)."""
        self._send("typing", text=str(text))

    def choose(self, value: Any) -> None:
        """Pick the option whose value (or else whose label) is ``value`` in a dropdown
        or a toggle.

        Raises
        ------
        ValueError
            No option has that value or label (the page offers only its options).
        """
        options = self._form.control(self._key).get("options", [])
        values = [option[1] for option in options]
        if value not in values:
            labels = [option[0] for option in options]
            if value not in labels:
                raise ValueError(
                    f"{self._key}: no option {value!r}; allowed: {', '.join(map(repr, labels))}"
                )
            value = values[labels.index(value)]
        self._send("choose", value=value)

    def click(self) -> None:
        """Click the button."""
        self._send("click")

    def check(self, value: bool) -> None:
        """Tick (``True``) or clear the checkbox."""
        self._send("check", value=bool(value))

    def widen(self) -> None:
        """Click the slider's ↔ (double its range)."""
        self._send("widen")
