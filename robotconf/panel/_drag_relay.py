"""A drag reaches the robot as fast as the kernel can draw it, not once per round trip.

ipywidgets keeps one state message per widget on its way to the kernel and sends the next
value only when the kernel has gone idle, so a slider drag updates ``p_EE`` and the 3D
pane once per round trip (about 80 ms on a loaded 2-core laptop: 12 updates a second).
The :class:`DragRelay` is a hidden anywidget whose page code watches the sliders' models
and forwards each value the user drags to as a custom message, with up to three
unanswered messages on the way, so the kernel computes the next pose while the previous
one travels. The kernel answers each message after handling it.

The slider's own update still arrives (later) and changes nothing, since the control
already shows that value; the last value of a drag therefore always wins. Values the
kernel sets (undo, presets) are not relayed back. A relayed value outside the slider's
range is stale (the unit or range changed since) and is dropped.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import anywidget
import ipywidgets as widgets
import traitlets
from ipywidgets import widget_serialization

from ._callbacks import guarded, on_message
from ._errors_display import ErrorLabel
from ._number_control import NumberControl

__all__ = ["DragRelay"]

_SCRIPT = (Path(__file__).parent / "js" / "drag_relay.js").read_text("utf-8")


class DragRelay(anywidget.AnyWidget):
    """Forwards slider drags of the tracked controls from the page to the kernel.

    Put it anywhere in the panel (it shows nothing) and give it the controls to watch
    with :meth:`track`.

    Examples
    --------
    >>> control = NumberControl("q", 0.0, -180, 180, angle=True)
    >>> relay = DragRelay()
    >>> relay.track([control])
    >>> relay.receive({"slider": control.slider.model_id, "value": 30.0, "seq": 1})
    >>> control.box.value, relay.received
    (30.0, 1)
    """

    _esm = traitlets.Unicode(_SCRIPT).tag(sync=True)
    sliders = traitlets.List(traitlets.Instance(widgets.FloatSlider)).tag(
        sync=True, **widget_serialization
    )

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._controls: dict[str, NumberControl] = {}
        self._error = ErrorLabel()
        #: How many relayed values arrived (for tests and benchmarks).
        self.received = 0
        on_message(self, self._error_target, self.receive)

    def _error_target(self) -> ErrorLabel:
        return self._error

    def track(self, controls: Iterable[NumberControl]) -> None:
        """Watch the sliders of ``controls`` (replacing the ones watched before)."""
        with_slider = [c for c in controls if c.slider is not None]
        self._controls = {c.slider.model_id: c for c in with_slider}
        self.sliders = [c.slider for c in with_slider]

    def receive(self, content: dict[str, Any]) -> None:
        """Handle one relayed value ``{"slider": model id, "value": v, "seq": k}``.

        The page's message is answered whatever happens, so its in-flight count stays
        right; a malformed message or an unknown slider is ignored.
        """
        if not isinstance(content, dict):
            return
        try:
            control = self._controls.get(str(content.get("slider")))
            value = content.get("value")
            if (
                control is not None
                and isinstance(value, int | float)
                and not isinstance(value, bool)
                and math.isfinite(value)
            ):
                self.received += 1
                guarded(control.error, control.drag_to)(float(value))
        finally:
            self.send({"ack": content.get("seq")})
