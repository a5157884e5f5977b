"""The view column: the end-effector line and the 3D scene, drawn from the state.

Both show the same :class:`~robotconf.kinematics.RobotSnapshot` of the robot the state
shows (the guided mode's robot so far while it is open): one kernel pass per change, the
header's ``p_EE`` and the scene's red sphere from the same numbers. The scene is told
only what changed: a new snapshot, a view option, the Reach tab's ghosts and target, the
Program tab's taught points, an animation to load, play or pause. What the student does in
the scene's own bar comes back as an action (``scene.on_request``), and what the page's
animation does is only mirrored (``scene.on_playback``), never sent back.
"""

from __future__ import annotations

import html
from collections.abc import Callable, Hashable
from typing import Any, NamedTuple

import numpy as np

from ...kinematics import Robot, RobotSnapshot
from ...teaching import format_number
from .. import actions as act
from ..state import PanelState

__all__ = ["ViewportView", "Extras", "Call", "NO_EXTRAS", "end_effector_text", "EE_CLASS"]

#: One call of a scene method: ``(name, args, kwargs)``.
Call = tuple[str, tuple[Any, ...], dict[str, Any]]


class Extras(NamedTuple):
    """What a tab draws in the 3D view beside the robot: scene calls, and a hashable key
    that changes exactly when they would draw something else."""

    key: Hashable
    calls: tuple[Call, ...]


#: A tab that draws nothing: whatever the Reach and Program tabs drew goes.
NO_EXTRAS = Extras(
    None,
    (("clear_ghosts", (), {}), ("clear_target", (), {}), ("clear_taught_points", (), {})),
)

#: The class browser tests and stylesheets find the end-effector line by.
EE_CLASS = "robotconf-ee"


def end_effector_text(point: Any, precision: int = 4) -> str:
    """``"p_EE = (70, 0, 20)"``: an end-effector position as the header shows it.

    >>> end_effector_text([70.0, 1e-17, 20.0])
    'p_EE = (70, 0, 20)'
    """
    values = ", ".join(format_number(v, precision) for v in np.asarray(point, dtype=float))
    return f"p_EE = ({values})"


class ViewportView:
    """Keeps the end-effector line and the scene equal to the state.

    Parameters
    ----------
    scene : object
        The panel's 3D scene (:class:`robotconf.scene.Scene` or a test's look-alike).
    ee_label : ipywidgets.HTML
        The end-effector line.
    dispatch : callable
        ``dispatch(action, key)``.
    """

    def __init__(self, scene: Any, ee_label: Any, dispatch: Callable[..., None]) -> None:
        self.scene = scene
        self.ee_label = ee_label
        self._dispatch = dispatch
        self._snapshot: RobotSnapshot | None = None
        self._drawn_robot: Robot | None = None
        self._options: tuple[Any, ...] | None = None
        self._extras: Hashable = None  # what the tabs drew beside the robot: nothing yet
        self._loaded: Any = None  # the motion the scene animates (identity)
        self._wizard_structure: Robot | None = None
        if hasattr(scene, "on_request"):
            scene.on_request = self._request
        if hasattr(scene, "on_playback"):
            scene.on_playback = self._playback

    def snapshot(self, state: PanelState) -> RobotSnapshot:
        """The snapshot of the robot the state shows (made once per robot)."""
        robot = state.shown_robot
        if self._snapshot is None or self._snapshot.robot is not robot:
            self._snapshot = robot.at()
        return self._snapshot

    def render(self, state: PanelState, extras: Extras = NO_EXTRAS) -> None:
        """Show the state: the robot, the view options, the tab's extras, the playback.

        ``extras`` is what the shown tab draws beside the robot (the Reach tab's ghosts
        and target, the Program tab's taught points).
        """
        snapshot = self.snapshot(state)
        unit = html.escape(state.units.length)
        self.ee_label.value = (
            f"<b>End-effector</b> <code>{html.escape(end_effector_text(snapshot.end_effector))}"
            f"</code> <small>[{unit}]</small>"
        )
        scene = self.scene
        if snapshot.robot is not self._drawn_robot:
            self._drawn_robot = snapshot.robot
            self._loaded = None  # a new pose ends an animation (the scene drops it)
            if hasattr(scene, "show"):
                scene.show(snapshot)
            else:  # a scene that draws robots, not snapshots
                scene.set_robot(snapshot.robot, snapshot.q)
            self._fit_wizard(state)
        self._show_options(state)
        if extras.key != self._extras:
            if self._extras is not None and extras.key is not None:
                for name, args, kwargs in NO_EXTRAS.calls:  # the other tab's drawing goes
                    _call(scene, name, *args, **kwargs)
            self._extras = extras.key
            for name, args, kwargs in extras.calls:
                _call(scene, name, *args, **kwargs)
        self._show_playback(state)

    def _fit_wizard(self, state: PanelState) -> None:
        """While the guided mode builds a robot, keep it in view as it grows."""
        if state.wizard is None:
            self._wizard_structure = None
            return
        robot = state.shown_robot
        structure = robot.with_q(np.zeros(robot.n))
        if structure != self._wizard_structure:
            self._wizard_structure = structure
            _call(self.scene, "fit_view")

    def _show_options(self, state: PanelState) -> None:
        view = state.view
        options = (view.labels, view.frames, view.trace)
        if options == self._options:
            return
        old = self._options or (None, None, None)
        self._options = options
        scene = self.scene
        if view.labels != old[0] and getattr(scene, "label_mode", view.labels) != view.labels:
            _call(scene, "set_label_mode", view.labels)
        if view.frames != old[1] and getattr(scene, "frames_shown", view.frames) != view.frames:
            _call(scene, "show_frames", view.frames)
        if view.trace != old[2] and getattr(scene, "trace_shown", view.trace) != view.trace:
            _call(scene, "show_trace", view.trace)

    def _show_playback(self, state: PanelState) -> None:
        playback = state.playback
        scene = self.scene
        if playback.source is None:
            self._loaded = None
            return
        motion = state.motion if playback.source == "motion" else None
        if playback.source == "program" and state.program_run is not None:
            motion = state.program_run.motion
        if motion is None:
            return
        known = getattr(scene, "playback_state", None)
        if motion is not self._loaded:
            self._loaded = motion
            _call(scene, "animate", motion, speed=playback.speed, play=playback.playing)
            return
        if known is None:
            return
        if playback.speed != getattr(known, "speed", playback.speed):
            _call(scene, "set_speed", playback.speed)
        if playback.playing and not getattr(known, "playing", True):
            _call(scene, "play")
        elif not playback.playing and getattr(known, "playing", False):
            _call(scene, "pause")

    # -- what the scene reports ---------------------------------------------------------

    def _request(self, request: dict[str, Any]) -> None:
        """The student used the scene's bar: the state changes, then the scene follows."""
        kind = request.get("kind")
        if kind == "labels":
            self._dispatch(act.SetViewOption("labels", request.get("mode")), "scene")
        elif kind in ("frames", "trace"):
            self._dispatch(act.SetViewOption(str(kind), bool(request.get("value"))), "scene")
        elif kind == "fit":
            _call(self.scene, "fit_view")
        elif kind == "speed":
            self._dispatch(act.SetSpeed(float(request.get("value", 1.0))), "scene")

    def _playback(self, reported: Any) -> None:
        """The page's animation started, stopped, was scrubbed or ended: mirror it."""
        action = act.PlaybackReported(
            bool(getattr(reported, "playing", False)),
            float(getattr(reported, "time", 0.0)),
            float(getattr(reported, "speed", 1.0)),
        )
        self._dispatch(action, "scene")


def _call(scene: Any, name: str, *args: Any, **kwargs: Any) -> None:
    method = getattr(scene, name, None)
    if method is not None:
        method(*args, **kwargs)
