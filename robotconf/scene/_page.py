"""What a view of the scene sends to the kernel, checked before anything acts on it.

A view (the page's bar and player, ``js/bar.js`` and ``js/player.js``) sends three kinds
of message; :meth:`Scene.receive_from_page <robotconf.scene.Scene.receive_from_page>`
takes them, so a headless test can play the page:

``{"kind": "request", "request": R}``
    The student asked for a view option in the bar. ``R`` is one of
    ``{"kind": "labels", "mode": "off" | "names" | "positions"}``,
    ``{"kind": "frames", "value": bool}``, ``{"kind": "trace", "value": bool}``,
    ``{"kind": "fit"}``.
``{"kind": "playback", "event": E, "time": t, "playing": bool, "speed": s, "animation": k}``
    The page's player changed: ``E`` is ``"play"``, ``"pause"``, ``"seek"``,
    ``"speed"`` (a student's action in the bar, already done in the page) or ``"end"``
    (the motion reached its end); ``t`` in motion seconds; ``k`` the animation's number
    (from the ``load`` op), so a late report of a replaced animation is ignored.
``{"kind": "hello", "view": id}``
    A new view asks for the scene (answered by the widget's channel with a replay).

Anything else, or a message with a wrong field, is ignored: the page is another program,
and a message it should not have sent must not raise in the kernel.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from ._labels import LABEL_MODES
from ._playback import PLAYBACK_EVENTS, SPEED_RANGE, Playback, PlaybackState

__all__ = ["read_request", "read_playback", "route_message", "PLAYBACK_REQUESTS"]

#: Playback events that a student made in the bar: reported as requests too, so a panel
#: can mirror them.
PLAYBACK_REQUESTS = ("play", "pause", "seek", "speed")


def read_request(request: Any) -> dict[str, Any] | None:
    """A view-option request as the scene passes it on, or ``None`` if malformed.

    >>> read_request({"kind": "labels", "mode": "names"})
    {'kind': 'labels', 'mode': 'names'}
    >>> read_request({"kind": "frames", "value": "yes"}) is None
    True
    """
    if not isinstance(request, dict):
        return None
    kind = request.get("kind")
    if kind == "labels" and request.get("mode") in LABEL_MODES:
        return {"kind": "labels", "mode": str(request["mode"])}
    if kind in ("frames", "trace") and isinstance(request.get("value"), bool):
        return {"kind": str(kind), "value": request["value"]}
    if kind == "fit":
        return {"kind": "fit"}
    return None


def read_playback(message: Any) -> dict[str, Any] | None:
    """A player report with checked fields, or ``None`` if malformed.

    >>> read_playback({"event": "seek", "time": 1.5, "playing": False, "speed": 1,
    ...                "animation": 2})
    {'event': 'seek', 'time': 1.5, 'playing': False, 'speed': 1.0, 'animation': 2}
    >>> read_playback({"event": "seek", "time": float("nan"), "playing": False}) is None
    True
    """
    if not isinstance(message, dict) or message.get("event") not in PLAYBACK_EVENTS:
        return None
    time, speed = message.get("time", 0.0), message.get("speed", 1.0)
    playing, animation = message.get("playing", False), message.get("animation")
    if not (_number(time) and _number(speed) and isinstance(playing, bool)):
        return None
    if not isinstance(animation, int) or isinstance(animation, bool):
        return None
    low, high = SPEED_RANGE
    if not low <= speed <= high:
        return None
    return {
        "event": str(message["event"]),
        "time": float(time),
        "playing": playing,
        "speed": float(speed),
        "animation": animation,
    }


def _number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def route_message(
    message: Any,
    playback: Playback,
    apply: Callable[[dict[str, Any]], Any],
    on_request: Callable[[dict[str, Any]], Any] | None,
    on_playback: Callable[[PlaybackState], Any] | None,
) -> None:
    """Act on one message of a view: a request goes to ``on_request`` (else ``apply``);
    a player report updates ``playback`` and goes to ``on_playback``, and a student's
    play, pause, seek or speed goes to ``on_request`` too (the page has acted already)."""
    if not isinstance(message, dict):
        return
    if message.get("kind") == "request":
        request = read_request(message.get("request"))
        if request is not None:
            (on_request or apply)(request)
        return
    if message.get("kind") != "playback":
        return
    report = read_playback(message)
    state = None if report is None else playback.report(report)
    if report is None or state is None:
        return
    if on_playback is not None:
        on_playback(state)
    event = report["event"]
    if event in PLAYBACK_REQUESTS and on_request is not None:
        request = {"kind": event}
        if event == "seek":
            request["time"] = state.time
        elif event == "speed":
            request["value"] = state.speed
        on_request(request)
