"""The bar's requests (labels, frames, trace, fit): applied by the scene, or handed to a
panel's callback and applied only when the panel calls back; what an exported page's bar
does without a kernel; and the bar showing the kernel's values."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import robotconf as rc
from robotconf.scene import RecordingChannel, Scene
from robotconf.scene._html import bar_choices
from robotconf.scene._playback import TRACE


@pytest.fixture
def scene(paper_robot: rc.Robot) -> Scene:
    return Scene(paper_robot, channel=RecordingChannel())


def _ask(scene: Scene, **request: Any) -> None:
    scene.receive_from_page({"kind": "request", "request": request})


def _options(scene: Scene) -> dict[str, Any]:
    return [op.content for op in scene.channel.ops if op.content["op"] == "options"][-1]


def test_without_a_callback_the_scene_applies_requests(scene: Scene) -> None:
    scene.channel.clear()
    _ask(scene, kind="labels", mode="names")
    labels = [op.content for op in scene.channel.ops if op.content["op"] == "labels"]
    assert labels[-1]["texts"] == ["M1", "M2", "M3", "EE"]
    _ask(scene, kind="frames", value=True)
    _ask(scene, kind="trace", value=True)
    assert (scene.label_mode, scene.frames_shown, scene.trace_shown) == ("names", True, True)
    assert _options(scene) == {
        "op": "options",
        "labels": "names",
        "frames": True,
        "trace": True,
        "controls": True,
    }
    scene.channel.clear()
    _ask(scene, kind="fit")
    assert scene.channel.kinds()[-1] == "fit"


def test_with_a_callback_the_panel_decides(scene: Scene) -> None:
    requests: list[dict[str, Any]] = []
    scene.on_request = requests.append
    scene.channel.clear()
    for request in (
        {"kind": "labels", "mode": "off"},
        {"kind": "frames", "value": True},
        {"kind": "trace", "value": False},
        {"kind": "fit"},
    ):
        _ask(scene, **request)
    assert requests == [
        {"kind": "labels", "mode": "off"},
        {"kind": "frames", "value": True},
        {"kind": "trace", "value": False},
        {"kind": "fit"},
    ]
    # Nothing happened yet: the panel turns a request into its own action, then calls back.
    assert scene.channel.ops == []
    assert (scene.label_mode, scene.frames_shown) == ("positions", False)
    scene.set_label_mode(requests[0]["mode"])
    assert scene.label_mode == "off" and _options(scene)["labels"] == "off"


@pytest.mark.parametrize(
    "request_",
    [
        {"kind": "labels", "mode": "everything"},
        {"kind": "labels"},
        {"kind": "frames", "value": "true"},
        {"kind": "frames", "value": 1},
        {"kind": "trace"},
        {"kind": "zoom"},
        "fit",
        None,
    ],
)
def test_malformed_requests_are_ignored(scene: Scene, request_: Any) -> None:
    requests: list[dict[str, Any]] = []
    scene.channel.clear()
    scene.receive_from_page({"kind": "request", "request": request_})
    scene.on_request = requests.append
    scene.receive_from_page({"kind": "request", "request": request_})
    assert scene.channel.ops == [] and requests == []


def test_the_bar_shows_the_kernels_values_after_a_reload(paper_robot: rc.Robot) -> None:
    scene = Scene(paper_robot, labels="names", frames=True, controls=False,
                  channel=RecordingChannel())  # fmt: skip
    replay = [op.content for op in scene._replay() if op.content["op"] == "options"]
    assert replay == [
        {"op": "options", "labels": "names", "frames": True, "trace": False, "controls": False}
    ]
    scene.show_trace(True)
    replay = [op.content for op in scene._replay() if op.content["op"] == "options"]
    assert len(replay) == 1 and replay[0]["trace"] is True  # the latest only


def test_an_exported_pages_bar_has_the_ops_of_every_choice(scene: Scene) -> None:
    scene.show_taught_points([[70.0, 0.0, 20.0], [10.0, 40.0, 30.0]])
    scene.animate(rc.simulate(scene.robot, {"q1": rc.signals.Sine()}, t_end=1.0, dt=0.1))
    scene.update([0.0, 0.3, 0.2])
    scene.animate(rc.simulate(scene.robot, {"q1": rc.signals.Sine()}, t_end=1.0, dt=0.1))
    choices = bar_choices(
        scene._robot, scene._taught, scene._playback, scene._outbox.log, scene._options_op
    )
    names = choices["labels"]["names"]
    assert [op.content["op"] for op in names] == ["visible", "labels", "visible", "options"]
    assert names[1].content["texts"] == ["M1", "M2", "M3", "EE"]  # moving: names only
    off = choices["labels"]["off"]
    assert [op.content["value"] for op in off[:2]] == [False, False]  # robot and taught
    assert all(p.endswith("/label") for op in off[:2] for p in op.content["paths"])
    assert choices["frames"]["true"][0].content["value"] is True
    assert choices["trace"]["true"][0].content["path"] == TRACE
    assert choices["trace"]["false"][0].content["command"] == {"type": "delete", "path": TRACE}
    assert choices["fit"][-1].content == [op for op in scene.channel.ops if
                                          op.content["op"] == "fit"][-1].content  # fmt: skip
    for choice in ("labels", "frames", "trace"):
        for ops in choices[choice].values():
            assert ops[-1].content["op"] == "options"


def test_export_html_carries_the_bar_and_its_choices(scene: Scene, tmp_path) -> None:  # type: ignore[no-untyped-def]
    import json

    scene.animate(rc.simulate(scene.robot, {"q1": rc.signals.Sine()}, t_end=1.0, dt=0.1))
    text = scene.export_html(tmp_path / "scene.html").read_text()
    assert "rcCreateBar" in text and "rcCreatePlayer" in text
    log = json.loads(
        text.split('id="robotconf-scene-log" type="application/json">')[1].split("</script>")[0]
    )
    assert set(log["choices"]) == {"labels", "frames", "trace", "fit"}
    assert log["ops"][-1] == {
        "op": "playback",
        "action": "load",
        "id": 1,
        "duration": 1.0,
        "speed": 1.0,
        "time": 0.0,
        "playing": True,
        "buffers": [],
    }
    # Buffers of the choices (the trace travels packed) index into the one shared list.
    trace = log["choices"]["trace"]["true"][0]
    assert trace["op"] == "packed" and trace["buffers"][0] < len(log["buffers"])
    assert np.all(np.array([len(b) for b in log["buffers"]]) > 0)
