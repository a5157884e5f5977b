"""Playback: the page plays, the kernel follows its reports and never echoes them.

The page's player is simulated with :meth:`Scene.receive_from_page` (the messages the
page's ``js/player.js`` sends); the kernel's clock is ``time.monotonic`` in
``robotconf.scene._playback``, replaced here by a hand-driven one.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import robotconf as rc
from robotconf.scene import PlaybackState, RecordingChannel, Scene
from robotconf.scene import _playback as playback_module
from robotconf.scene._playback import TRACE


class Clock:
    """A monotonic clock the test moves by hand."""

    def __init__(self) -> None:
        self.now = 1000.0

    def __call__(self) -> float:
        return self.now


@pytest.fixture
def clock(monkeypatch: pytest.MonkeyPatch) -> Clock:
    clock = Clock()
    monkeypatch.setattr(playback_module, "monotonic", clock)
    return clock


@pytest.fixture
def scene(paper_robot: rc.Robot, clock: Clock) -> Scene:
    return Scene(paper_robot, channel=RecordingChannel())


def _motion(robot: rc.Robot, t_end: float = 3.0) -> Any:
    return rc.simulate(robot, {"q2": rc.signals.Sine(amplitude=1.0)}, t_end=t_end, dt=0.1)


def _player_ops(scene: Scene) -> list[dict[str, Any]]:
    return [op.content for op in scene.channel.ops if op.content["op"] == "playback"]


def _report(scene: Scene, event: str, time: float, playing: bool, **extra: Any) -> None:
    """What the page's player sends (the animation's number from its ``load`` op)."""
    load = scene._replay()[-1].content
    message = {
        "kind": "playback",
        "event": event,
        "time": time,
        "playing": playing,
        "speed": extra.pop("speed", 1.0),
        "animation": extra.pop("animation", load["id"]),
    }
    scene.receive_from_page(message)


def test_animate_loads_the_motion_and_the_page_plays_it(scene: Scene, clock: Clock) -> None:
    assert scene.playback_state == PlaybackState(False, False, 0.0, 1.0, 0.0)
    scene.channel.clear()
    scene.animate(_motion(scene.robot), speed=2.0)
    (load,) = _player_ops(scene)
    assert load == {
        "op": "playback",
        "action": "load",
        "id": 1,
        "duration": 3.0,
        "speed": 2.0,
        "time": 0.0,
        "playing": True,
    }
    # Between reports the kernel estimates the time from the speed, up to the end.
    clock.now += 0.5
    assert scene.playback_state == PlaybackState(True, True, 1.0, 2.0, 3.0)
    clock.now += 10.0
    state = scene.playback_state
    assert state.time == 3.0 and state.playing  # playing until the page reports the end
    scene.animate(_motion(scene.robot), play=False)
    assert _player_ops(scene)[-1]["id"] == 2 and not _player_ops(scene)[-1]["playing"]
    assert scene.playback_state == PlaybackState(True, False, 0.0, 1.0, 3.0)


def test_kernel_commands_are_applied_in_the_page(scene: Scene, clock: Clock) -> None:
    scene.play()  # nothing loaded: nothing to send
    scene.seek(1.0)
    assert _player_ops(scene) == []
    scene.animate(_motion(scene.robot), play=False)
    scene.channel.clear()
    scene.play()
    clock.now += 1.2
    scene.pause()
    assert scene.playback_state.time == pytest.approx(1.2)
    scene.seek(9.0)  # clamped to the motion
    scene.set_speed(0.5)
    assert [(op["action"], op.get("time"), op.get("value")) for op in _player_ops(scene)] == [
        ("play", None, None),
        ("pause", None, None),
        ("seek", 3.0, None),
        ("speed", None, 0.5),
    ]
    assert scene.playback_state == PlaybackState(True, False, 3.0, 0.5, 3.0)
    scene.play()  # an ended motion plays again from the start
    assert scene.playback_state.time == 0.0 and scene.playback_state.playing
    with pytest.raises(rc.InvalidInputError, match="speed: must be positive"):
        scene.set_speed(-1)
    with pytest.raises(rc.InvalidInputError, match="t: "):
        scene.seek(float("nan"))


def test_reports_update_the_state_and_never_send_anything(scene: Scene, clock: Clock) -> None:
    states: list[PlaybackState] = []
    requests: list[dict[str, Any]] = []
    scene.on_playback = states.append
    scene.on_request = requests.append
    scene.animate(_motion(scene.robot))
    scene.channel.clear()
    # The student pauses at 1.25 s, seeks to 2 s, doubles the speed, plays; it ends.
    _report(scene, "pause", 1.25, False)
    _report(scene, "seek", 2.0, False)
    _report(scene, "speed", 2.0, False, speed=2.0)
    _report(scene, "play", 2.0, True, speed=2.0)
    clock.now += 0.25
    assert scene.playback_state.time == pytest.approx(2.5)
    _report(scene, "end", 3.0, False, speed=2.0)
    assert scene.channel.ops == []  # a report is never answered with a command
    assert [(s.playing, s.time, s.speed) for s in states] == [
        (False, 1.25, 1.0),
        (False, 2.0, 1.0),
        (False, 2.0, 2.0),
        (True, 2.0, 2.0),
        (False, 3.0, 2.0),
    ]
    # The student's own actions are mirrored as requests, after the page did them.
    assert requests == [
        {"kind": "pause"},
        {"kind": "seek", "time": 2.0},
        {"kind": "speed", "value": 2.0},
        {"kind": "play"},
    ]
    assert scene.playback_state == PlaybackState(True, False, 3.0, 2.0, 3.0)


def test_stale_and_malformed_reports_are_ignored(scene: Scene) -> None:
    states: list[PlaybackState] = []
    scene.on_playback = states.append
    scene.receive_from_page({"kind": "playback", "event": "end", "animation": 1})  # none loaded
    scene.animate(_motion(scene.robot))
    before = scene.playback_state
    for message in (
        {"kind": "playback", "event": "end", "time": 3.0, "playing": False, "animation": 0},
        {"kind": "playback", "event": "seek", "time": float("nan"), "playing": False},
        {"kind": "playback", "event": "seek", "time": "1", "playing": False, "animation": 1},
        {"kind": "playback", "event": "rewind", "time": 1.0, "playing": False, "animation": 1},
        {"kind": "playback", "event": "play", "time": 1.0, "playing": 1, "animation": 1},
        {"kind": "playback", "event": "speed", "time": 1.0, "playing": False, "speed": 1e9},
        {"kind": "playback", "event": "seek", "time": 1.0, "playing": False, "animation": True},
        {"kind": "elsewhere"},
        ["not", "a", "dict"],
        None,
    ):
        scene.receive_from_page(message)
    assert states == [] and scene.playback_state.playing == before.playing


def test_show_drops_the_animation_and_brings_the_numbers_back(scene: Scene) -> None:
    scene.show_trace(True)
    scene.animate(_motion(scene.robot))
    labels = [op for op in scene.channel.ops if op.content["op"] == "labels"]
    assert labels[-1].content["texts"] == ["M1", "M2", "M3", "EE"]
    scene.channel.clear()
    scene.update([0.1, 0.2, 0.3])
    ops = scene.channel.ops
    assert ops[0].content == {"op": "playback", "action": "clear"}
    assert scene.channel.commands("delete") == [{"type": "delete", "path": TRACE}]
    texts = [op.content["texts"] for op in ops if op.content["op"] == "labels"][-1]
    assert texts[-1] == scene.labels()[-1] and "(" in texts[-1]
    assert scene.playback_state.loaded is False
    replay = [op.content for op in scene._replay()]
    assert not any(op.get("op") == "playback" for op in replay)
    assert not any(op.get("command", {}).get("type") == "set_animation" for op in replay)


def test_a_new_view_joins_where_the_others_are(scene: Scene, clock: Clock) -> None:
    scene.animate(_motion(scene.robot))
    clock.now += 1.0
    load = scene._replay()[-1].content
    assert (load["action"], load["time"], load["playing"]) == ("load", 1.0, True)
    clock.now += 5.0  # the motion has ended by now: a new view shows its last frame
    load = scene._replay()[-1].content
    assert (load["time"], load["playing"]) == (3.0, False)
    # An exported file plays it from the start when opened …
    assert scene._replay(from_start=True)[-1].content["time"] == 0.0
    # … unless it was paused mid-way: then that frame.
    scene.seek(1.5)
    exported = scene._replay(from_start=True)[-1].content
    assert (exported["time"], exported["playing"]) == (1.5, False)


def test_the_trace_follows_the_loaded_motion(scene: Scene) -> None:
    motion = _motion(scene.robot)
    scene.show_trace(True)  # before an animation: nothing to draw yet
    assert scene.channel.commands("set_object")[-1]["path"] != TRACE
    scene.channel.clear()
    scene.animate(motion)
    (trace,) = [c for c in scene.channel.commands("set_object") if c["path"] == TRACE]
    attribute = trace["object"]["geometries"][0]["data"]["attributes"]["position"]
    line = np.frombuffer(attribute["array"].data, dtype=np.float32).reshape(-1, 3)
    np.testing.assert_allclose(line, motion.position[:, -1], rtol=1e-6, atol=1e-4)
    scene.channel.clear()
    scene.show_trace(False)
    assert scene.channel.commands("delete") == [{"type": "delete", "path": TRACE}]
    assert scene.channel.ops[-1].content["trace"] is False  # the bar shows it
