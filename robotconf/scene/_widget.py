"""The notebook transport of the 3D scene: an anywidget that runs meshcat's viewer.

No meshcat server, port or subprocess: meshcat's viewer JavaScript (bundled in the
``meshcat`` wheel, read as a file by :mod:`robotconf.scene._assets`; no meshcat Python code
runs) reaches the page once per kernel through a hidden model, and each
scene's ops travel over the widget's comm channel, batched (one message per update, ≤ 60
per second with an end-of-burst flush: Jupyter drops IOPub messages beyond about 1000/s).
A new view asks for the scene log and gets a replay, so page reloads and second views
show the same scene. The widget's page code (``js/``) draws the bar above the pane and
plays animations; what it sends back goes to :meth:`Scene.receive_from_page`.
"""

from __future__ import annotations

import asyncio
import time
from collections.abc import Callable
from typing import Any

import anywidget
import traitlets
from ipywidgets import widget_serialization

from ._assets import meshcat_source, script
from ._commands import Op, pack_ops
from ._html import PAGE_SCRIPTS

__all__ = ["SceneWidget", "WidgetChannel", "coalesce_ops", "meshcat_source", "script"]


class MeshcatCode(anywidget.AnyWidget):
    """Hidden model carrying meshcat's viewer code to the page, once per kernel."""

    _esm = traitlets.Unicode(script("glue", "loader")).tag(sync=True)
    source = traitlets.Unicode("").tag(sync=True)


_code: list[MeshcatCode] = []


def shared_code() -> MeshcatCode:
    """The kernel's one :class:`MeshcatCode` model (recreated if it was closed)."""
    if not _code or _code[0].comm is None:
        _code[:] = [MeshcatCode(source=meshcat_source())]
    return _code[0]


class SceneWidget(anywidget.AnyWidget):
    """One 3D pane in the notebook. Use it through :class:`robotconf.scene.Scene`."""

    _esm = traitlets.Unicode(script(*PAGE_SCRIPTS, "widget")).tag(sync=True)
    height = traitlets.Int(420).tag(sync=True)
    # Keeping a reference in the state makes the front end create the code model first.
    code = traitlets.Instance(MeshcatCode).tag(sync=True, **widget_serialization)


class WidgetChannel:
    """Sends ops to a :class:`SceneWidget`, rate-limited, and answers replay requests.

    Parameters
    ----------
    widget : SceneWidget
    replay : callable
        Returns the ops a new view must apply (the scene log).
    max_rate : float or None
        Messages per second at most; ``None`` sends every batch at once.
    """

    def __init__(
        self, widget: SceneWidget, replay: Callable[[], list[Op]], max_rate: float | None = 60.0
    ) -> None:
        self.widget = widget
        self._replay = replay
        self._interval = 0.0 if not max_rate else 1.0 / max_rate
        self._last = 0.0
        self._pending: list[Op] = []
        self._timer: asyncio.TimerHandle | None = None
        self.sent = 0
        #: Called with every other message a view sends (the bar's requests, the player's
        #: reports): :meth:`Scene.receive_from_page`.
        self.on_event: Callable[[dict[str, Any]], None] | None = None
        widget.on_msg(self._on_message)

    def send(self, ops: list[Op]) -> None:
        """Send now, or hold the ops for the end-of-burst flush if the rate is exceeded."""
        self._pending = coalesce_ops(self._pending + list(ops))
        now = time.perf_counter()
        if now - self._last >= self._interval:
            self.flush()
        elif self._timer is None:
            self._schedule(self._interval - (now - self._last))

    def flush(self) -> None:
        """Send whatever is held, as one message."""
        if self._timer is not None:
            self._timer.cancel()
            self._timer = None
        if not self._pending:
            return
        contents, buffers = pack_ops(self._pending)
        self._pending = []
        self._last = time.perf_counter()
        self.sent += 1
        self.widget.send({"kind": "batch", "ops": contents}, buffers)

    def _schedule(self, delay: float) -> None:
        try:
            loop = asyncio.get_running_loop()
        except RuntimeError:
            # No event loop (a script): nobody would run the flush later, so send now.
            self.flush()
            return
        self._timer = loop.call_later(max(delay, 0.0), self.flush)

    def _on_message(self, _widget: Any, content: dict[str, Any], _buffers: list[bytes]) -> None:
        if not isinstance(content, dict):
            return
        if content.get("kind") == "hello":
            self.flush()
            contents, buffers = pack_ops(self._replay())
            self.widget.send(
                {"kind": "replay", "view": str(content.get("view", "")), "ops": contents},
                buffers,
            )
        elif self.on_event is not None:
            self.on_event(content)

    def close(self) -> None:
        if self._timer is not None:
            self._timer.cancel()
            self._timer = None
        self.widget.close()


def coalesce_ops(ops: list[Op]) -> list[Op]:
    """Merge held transforms and labels: state, not events, so only the newest counts.

    Within each run of transforms and labels ops (any other op ends a run: objects it
    creates or deletes must see the transforms in order), one transforms op keeps the
    newest matrix of every path and one labels op the newest text of every label.

    Examples
    --------
    >>> import numpy as np
    >>> from ._commands import transforms_op
    >>> a = transforms_op(["/x", "/y"], np.stack([np.eye(4), np.eye(4)]))
    >>> b = transforms_op(["/y"], 2 * np.eye(4)[None])
    >>> merged = coalesce_ops([a, b])
    >>> merged[0].content["paths"], np.frombuffer(merged[0].buffers[0], np.float32)[-1]
    (['/x', '/y'], np.float32(2.0))
    """
    out: list[Op] = []
    matrices: dict[str, bytes] = {}
    labels: dict[str, str] = {}

    def end_run() -> None:
        if matrices:
            out.append(
                Op({"op": "transforms", "paths": list(matrices)}, (b"".join(matrices.values()),))
            )
            matrices.clear()
        if labels:
            out.append(Op({"op": "labels", "paths": list(labels), "texts": list(labels.values())}))
            labels.clear()

    for op in ops:
        kind = op.content["op"]
        if kind == "transforms":
            data = op.buffers[0]
            for k, path in enumerate(op.content["paths"]):
                matrices.pop(path, None)
                matrices[path] = data[64 * k : 64 * (k + 1)]
        elif kind == "labels":
            for path, text in zip(op.content["paths"], op.content["texts"], strict=True):
                labels.pop(path, None)
                labels[path] = text
        else:
            end_run()
            out.append(op)
    end_run()
    return out
