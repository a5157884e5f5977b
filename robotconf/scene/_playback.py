"""Playing a simulated motion in the scene: load, play, pause, scrub, speed and trace.

:class:`Playback` is the part of :class:`~robotconf.scene.Scene` that drives the animation
the viewer holds; the scene keeps everything else (objects, transforms, labels, the log).
The kernel's :class:`~robotconf.scene._animation.AnimationState` follows what the page
reports, so the control bar's time slider moves with playback.
"""

from __future__ import annotations

from time import monotonic
from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_finite_number, check_flag
from ._animation import AnimationState, animation_command, animation_state
from ._commands import ROOT, Op, SceneLog, animation_op, command_op, set_object_op
from ._drawing import COLORS
from ._shown import Shown
from ._three import polyline

if TYPE_CHECKING:
    from ._drawing import RobotDrawing

__all__ = ["Playback", "ROBOT", "TRACE"]

#: The robot's objects live under this path; clouds and the base frame beside it.
ROBOT = f"{ROOT}/robot"
#: The end-effector's path during an animation, under the robot (a rebuild deletes it).
TRACE = f"{ROBOT}/trace"
#: Log keys of the animation: a replay loads it paused, before the current transforms.
_ANIMATION_KEYS = (("set_animation", ""), ("animation", "speed"))


class Playback:
    """The animation methods of :class:`~robotconf.scene.Scene` (a mixin: the scene
    provides the state below).

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import RecordingChannel, Scene
    >>> robot = rc.preset("paper")
    >>> scene = Scene(robot, channel=RecordingChannel())
    >>> scene.animate(rc.simulate(robot, {"q1": rc.signals.Sine()}, t_end=1, dt=0.1))
    >>> scene.seek(0.5)
    >>> scene.channel.ops[-1].content
    {'op': 'animation', 'action': 'seek', 'value': 0.5}
    """

    _animation: AnimationState | None
    _trace_on: bool
    _log: SceneLog
    _shown: Shown

    if TYPE_CHECKING:  # provided by the scene

        def _send(
            self, ops: list[Op], *, log: bool = True, logged: list[Op] | None = None
        ) -> None: ...

        def _require_drawing(self) -> RobotDrawing: ...

        def _label_ops(self) -> tuple[list[Op], list[Op]]: ...

        def _sync_controls(self) -> None: ...

    @property
    def trace_shown(self) -> bool:
        """Whether the end-effector's path is drawn during an animation."""
        return self._trace_on

    @property
    def animation(self) -> AnimationState | None:
        """The animation loaded in the viewer, or ``None``."""
        return self._animation

    def animate(self, motion: Any, *, speed: float = 1.0, play: bool = True) -> None:
        """Play a simulated motion in the pane (the control bar plays, pauses and scrubs).

        Labels show names only while the animation is loaded: the viewer replays
        transforms, and a number that does not follow the robot would be wrong.
        ``update(q)`` drops the animation and brings the numbers back.

        Parameters
        ----------
        motion : Motion
            From :func:`robotconf.simulate` with this scene's robot.
        speed : float
            Playback speed (1 = real time).
        play : bool
            Start playing at once.
        """
        drawing = self._require_drawing()
        command = animation_command(drawing, motion, speed=speed, play=play, root=ROBOT)
        self._animation = animation_state(motion, float(speed), command["options"]["play"])
        # A replay (new view, reload, export) loads it paused: the pose stays the current q.
        paused = {**command, "options": {**command["options"], "play": False}}
        for key in _ANIMATION_KEYS:
            self._log.drop(key)
        ops = [command_op(command)]
        logged = [command_op(paused)]
        if self._trace_on:
            ops.append(self._trace_op())
        label_live, label_logged = self._label_ops()
        self._send(label_live + ops, logged=label_logged + logged + ops[1:])
        self._sync_controls()

    def play(self) -> None:
        """Play the loaded animation (from the start once it has ended)."""
        state = self._animation
        if state is not None:
            if state.time >= state.duration:
                state.time = 0.0  # the page replays an ended animation from the start
            state.playing, state.since = True, monotonic()
            self._send([animation_op("play")], log=False)

    def pause(self) -> None:
        """Pause the loaded animation where it is."""
        if self._animation is not None:
            self._animation.playing = False
            self._send([animation_op("pause")], log=False)

    def seek(self, t: float) -> None:
        """Show the loaded animation at motion time ``t`` (s), paused."""
        state = self._animation
        if state is None:
            return
        t = min(max(check_finite_number(t, "t"), 0.0), state.duration)
        state.time, state.playing = t, False
        op = animation_op("seek", t / state.clip_speed)
        self._send([op], logged=[])
        self._sync_controls()

    def set_speed(self, speed: float) -> None:
        """Playback speed of the animation: 1 is real time, 2 twice as fast."""
        speed = check_finite_number(speed, "speed")
        if speed <= 0:
            raise InvalidInputError("speed", speed, "a number > 0", problem="must be positive:")
        state = self._animation
        if state is None:
            return
        if state.playing:  # keep the end-of-playback estimate: from here at the new speed
            now = monotonic()
            state.time = min(state.time + (now - state.since) * state.speed, state.duration)
            state.since = now
        state.speed = speed
        self._send([animation_op("speed", speed / state.clip_speed)])
        self._sync_controls()

    def show_trace(self, visible: bool = True) -> None:
        """Draw the end-effector's path (a line through ``motion.position`` of the EE)
        while an animation is loaded."""
        self._trace_on = check_flag(visible, "visible")
        if self._animation is not None:
            if self._trace_on:
                self._send([self._trace_op()])
            else:
                self._log.forget(TRACE)
                self._send([command_op({"type": "delete", "path": TRACE})], log=False)
        self._sync_controls()

    def _drop_animation(self) -> list[Op]:
        """Ops that stop and forget the loaded animation; its objects need new transforms."""
        self._animation = None
        for key in _ANIMATION_KEYS:
            self._log.drop(key)
        self._shown.forget_transforms()
        self._sync_controls()
        ops = [animation_op("clear")]
        if self._trace_on:
            self._log.forget(TRACE)
            ops.append(command_op({"type": "delete", "path": TRACE}))
        return ops

    def _trace_op(self) -> Op:
        assert self._animation is not None
        return set_object_op(TRACE, polyline(self._animation.path, COLORS["end_effector"]))

    def _view_event(self, content: dict[str, Any]) -> None:
        """A view reports playback: where the animation is and whether it plays."""
        state = self._animation
        if state is None or content.get("kind") != "time":
            return
        value = content.get("value")
        if isinstance(value, (int, float)) and np.isfinite(value):
            state.time = min(max(float(value) * state.clip_speed, 0.0), state.duration)
        state.playing, state.since = bool(content.get("playing", False)), monotonic()
        self._sync_controls()
