"""Shared helpers for the configurator panel tests (no tests here).

A recording fake stands in for the 3D scene: the panel talks to it through the same
members as to ``robotconf.scene.Scene`` (``widget``, ``show(snapshot)``, the view options,
the Reach and Program drawings, the playback), so the tests see exactly what the panel
asked the scene to do. ``ui(panel, key)`` acts on any control of the panel as a student in
the page would (a drag, typed text, a choice, a click), through the form that shows it.
"""

from __future__ import annotations

from types import SimpleNamespace
from typing import Any

import ipywidgets as widgets
import numpy as np

import robotconf as rc
from robotconf.panel import Configurator
from robotconf.panel.form import Form


class FakeScene:
    """Records every call the panel makes; ``created`` counts factory calls."""

    created = 0

    def __init__(self, robot: rc.Robot):
        FakeScene.created += 1
        self.robot = robot
        self.q = robot.q
        self.snapshot: Any = None
        self.widget = widgets.HTML("fake scene")
        self.calls: list[tuple[str, Any]] = []
        self.label_mode, self.frames_shown, self.trace_shown = "positions", False, False
        self.playback_state = SimpleNamespace(
            loaded=False, playing=False, time=0.0, speed=1.0, duration=0.0
        )
        self.on_request: Any = None
        self.on_playback: Any = None

    def show(self, snapshot: Any) -> None:
        self.calls.append(("show", snapshot))
        self.snapshot, self.robot, self.q = snapshot, snapshot.robot, np.array(snapshot.q)
        self.playback_state.loaded = self.playback_state.playing = False

    def set_label_mode(self, mode: str) -> None:
        self.calls.append(("set_label_mode", mode))
        self.label_mode = mode

    def show_frames(self, value: bool) -> None:
        self.calls.append(("show_frames", value))
        self.frames_shown = value

    def show_trace(self, value: bool) -> None:
        self.calls.append(("show_trace", value))
        self.trace_shown = value

    def fit_view(self) -> None:
        self.calls.append(("fit_view", None))

    def animate(self, motion: Any, speed: float = 1.0, play: bool = True) -> None:
        self.calls.append(("animate", motion))
        state = self.playback_state
        state.loaded, state.playing, state.speed = True, play, speed
        state.duration, state.time = float(motion.t[-1] - motion.t[0]), 0.0

    def play(self) -> None:
        self.calls.append(("play", None))
        self.playback_state.playing = True

    def pause(self) -> None:
        self.calls.append(("pause", None))
        self.playback_state.playing = False

    def set_speed(self, speed: float) -> None:
        self.calls.append(("set_speed", speed))
        self.playback_state.speed = speed

    def show_ghosts(self, robot: Any, qs: Any) -> None:
        self.calls.append(("show_ghosts", (robot, np.array(qs))))

    def clear_ghosts(self) -> None:
        self.calls.append(("clear_ghosts", None))

    def show_target(self, target: Any, reachable: bool = True) -> None:
        self.calls.append(("show_target", (np.array(target), reachable)))

    def clear_target(self) -> None:
        self.calls.append(("clear_target", None))

    def show_taught_points(self, points: Any, labels: Any, **kwargs: Any) -> None:
        self.calls.append(("show_taught_points", (np.array(points), list(labels), kwargs)))

    def clear_taught_points(self) -> None:
        self.calls.append(("clear_taught_points", None))

    # -- what the page would report ----------------------------------------------------

    def page_reports(self, playing: bool, time: float) -> None:
        """The page's animation started, stopped or ended at ``time``."""
        state = self.playback_state
        state.playing, state.time = playing, time
        if self.on_playback is not None:
            self.on_playback(state)

    def names(self) -> list[str]:
        return [name for name, _ in self.calls]


def paper_robot() -> rc.Robot:
    """The paper's R_zR_yR_y robot (§3), built explicitly: l1 = 20, l2 = 30, l3 = 40."""
    return rc.Robot(
        [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
        end_effector=(40, 0, 0),
    )


def make_panel(robot: rc.Robot | None = None, **options: Any) -> Configurator:
    """A panel on the paper's robot (default) with a recording fake scene."""
    return Configurator(
        paper_robot() if robot is None else robot, scene_factory=FakeScene, **options
    )


def forms(panel: Configurator) -> list[Form]:
    """Every form of the panel, in page order."""
    return [
        panel.header.form,
        panel.editor.form,
        panel.wizard.form,
        panel.motion_tab.form,
        panel.motion_tab.results.controls,
        panel.matrices.controls,
        panel.reach.form,
        panel.program_tab.form,
        panel.files.form,
    ]


def form_of(panel: Configurator, key: str) -> Form:
    """The form that shows control ``key`` now."""
    for form in forms(panel):
        try:
            form.control(key)
        except KeyError:
            continue
        return form
    raise KeyError(f"no form of the panel shows {key!r}")


def ui(panel: Configurator, key: str) -> Any:
    """Act on control ``key`` as a student in the page would (``.drag``, ``.type``,
    ``.choose``, ``.click``, ``.check``, ``.widen``)."""
    return form_of(panel, key).user(key)


def shown(panel: Configurator, key: str) -> dict[str, Any]:
    """Control ``key`` as the page shows it (value, range, unit, message …)."""
    return form_of(panel, key).control(key)


def note(panel: Configurator, key: str) -> str:
    """The message beside control ``key`` (``""`` for none)."""
    message = shown(panel, key).get("message")
    return "" if not message else str(message["text"])
