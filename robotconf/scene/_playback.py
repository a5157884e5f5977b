"""Playing a simulated motion: the page plays it, the kernel keeps track.

The page owns the clock. ``animate`` loads the motion's keyframes into every view and the
page's own player plays them to the end by itself, moving the bar's time slider as it
goes; only a student's drag of that slider seeks. The page tells the kernel only what
changes — play, pause, seek, speed, end — never each frame, and :class:`Playback`
keeps a :class:`PlaybackState` from those reports, estimating the time in between.

A motion travels as meshcat's ``set_animation`` (:func:`animation_command`): keyframe
tracks of every drawn item in motion seconds, loaded paused; the page's player applies
the speed, so playback costs the kernel nothing and survives in an HTML export. Kernel
commands (``play``, ``pause``, ``seek``, ``set_speed``) are applied in the page; a report
never triggers a command, so nothing echoes back and forth.
"""

from __future__ import annotations

from dataclasses import dataclass
from time import monotonic
from typing import Any

import msgpack
import numpy as np

from .._errors import InvalidInputError
from .._validation import check_finite_number, check_flag, check_joint_values
from ._commands import Op, Outbox, command_op, meshcat_op, playback_op, set_object_op
from ._drawing import COLORS, RobotDrawing
from ._placement import quaternions
from ._robot_layer import ROBOT
from ._three import float32_array, polyline

__all__ = [
    "Playback",
    "PlaybackState",
    "animation_command",
    "animation_state",
    "TRACE",
    "PLAYBACK_EVENTS",
    "MAX_FRAMES",
]

#: The end-effector's path during an animation, under the robot (a rebuild deletes it).
TRACE = f"{ROBOT}/trace"
#: What the page reports: a student's play, pause, seek or speed, or the motion's end.
PLAYBACK_EVENTS = ("play", "pause", "seek", "speed", "end")
#: Playback speeds the kernel accepts (× real time).
SPEED_RANGE = (1e-3, 1e3)


@dataclass(frozen=True)
class PlaybackState:
    """Where the animation of a scene is, as the kernel knows it.

    Attributes
    ----------
    loaded : bool
        Whether an animation is loaded.
    playing : bool
        Whether it plays, as last commanded or reported (the page reports the end).
    time : float
        Motion time shown (s): the last report, plus the time since at ``speed`` while
        playing (never beyond ``duration``).
    speed : float
        Playback speed (1 = real time).
    duration : float
        Length of the motion (s), 0 without an animation.

    Examples
    --------
    >>> PlaybackState(True, False, 1.5, 2.0, 3.0).time
    1.5
    """

    loaded: bool
    playing: bool
    time: float
    speed: float
    duration: float


class Playback:
    """The animation of a scene: loads it, drives the page's player, follows its reports.

    Parameters
    ----------
    outbox : Outbox

    Examples
    --------
    >>> import robotconf as rc
    >>> from robotconf.scene import RecordingChannel, RobotDrawing
    >>> robot = rc.preset("paper")
    >>> playback = Playback(Outbox(RecordingChannel()))
    >>> motion = rc.simulate(robot, {"q1": rc.signals.Sine()}, t_end=2, dt=0.1)
    >>> playback.load(RobotDrawing(robot, 90.0), motion, speed=1.0, play=False)
    >>> playback.seek(0.5)
    >>> playback.state()
    PlaybackState(loaded=True, playing=False, time=0.5, speed=1.0, duration=2.0)
    >>> playback.report({"event": "play", "time": 0.5, "speed": 2.0, "playing": True,
    ...                  "animation": 1}).speed
    2.0
    """

    def __init__(self, outbox: Outbox) -> None:
        self._outbox = outbox
        self.trace = False
        self._id = 0  # which animation: a report of an older one is stale
        self._duration = 0.0
        # Every labelled point (frames, then the EE) at the keyframes: the trace, the fit.
        self._points = np.zeros((0, 1, 3))
        self._loaded = False
        self._playing = False
        self._time = 0.0  # motion seconds, at monotonic() == self._since
        self._since = 0.0
        self._speed = 1.0

    @property
    def loaded(self) -> bool:
        """Whether an animation is loaded."""
        return self._loaded

    def state(self, now: float | None = None) -> PlaybackState:
        """The playback state at ``now`` (``time.monotonic()``; default: now)."""
        return PlaybackState(
            self._loaded, self._playing, self._time_at(now), self._speed, self._duration
        )

    def load(self, drawing: RobotDrawing, motion: Any, *, speed: float, play: bool) -> None:
        """Load ``motion`` of the drawn robot into the views, playing from 0 if ``play``."""
        command = animation_command(drawing, motion, root=ROBOT)
        speed = _check_speed(speed)
        play = check_flag(play, "play")
        duration, points = animation_state(motion)
        self._id += 1
        self._loaded, self._duration, self._points = True, duration, points
        self._speed = speed
        self._set(0.0, play)
        ops = [meshcat_op(command)]
        if self.trace:
            ops.append(self.trace_op())
        # The keyframes are the state a new view replays; where the player stands is
        # added by replay_ops() when a view asks.
        self._outbox.send([*ops, self._load_op()], logged=ops)

    def drop(self) -> list[Op]:
        """Forget the animation: the ops that clear it in the views (sent by the scene,
        which then sends the current transforms)."""
        if not self._loaded:
            return []
        self._loaded, self._playing, self._time, self._duration = False, False, 0.0, 0.0
        self._outbox.log.drop(("set_animation", ""))
        ops = [playback_op("clear")]
        if self.trace:
            self._outbox.log.forget(TRACE)
            ops.append(command_op({"type": "delete", "path": TRACE}))
        return ops

    def forget(self) -> None:
        """The robot was rebuilt: its objects, the animation's targets, are gone."""
        self._outbox.log.drop(("set_animation", ""))
        self._loaded, self._playing, self._time, self._duration = False, False, 0.0, 0.0

    def play(self) -> None:
        """Play the loaded animation (from the start once it has ended)."""
        if not self._loaded:
            return
        start = self._time_at(None)
        self._set(0.0 if start >= self._duration else start, True)
        self._outbox.send_live([playback_op("play")])

    def pause(self) -> None:
        """Pause the loaded animation where it is."""
        if self._loaded:
            self._set(self._time_at(None), False)
            self._outbox.send_live([playback_op("pause")])

    def seek(self, t: float) -> None:
        """Show the loaded animation at motion time ``t`` (s), paused."""
        t = check_finite_number(t, "t")
        if not self._loaded:
            return
        self._set(min(max(t, 0.0), self._duration), False)
        self._outbox.send_live([playback_op("seek", time=self._time)])

    def set_speed(self, speed: float) -> None:
        """Playback speed: 1 is real time, 2 twice as fast."""
        speed = _check_speed(speed)
        self._set(self._time_at(None), self._playing)  # the time so far was at the old speed
        self._speed = speed
        if self._loaded:
            self._outbox.send_live([playback_op("speed", value=speed)])

    def show_trace(self, visible: bool) -> None:
        """Draw the end-effector's path while an animation is loaded, or remove it."""
        self.trace = visible
        if not self._loaded:
            return
        if visible:
            self._outbox.send([self.trace_op()])
        else:
            self._outbox.delete(TRACE)

    def report(self, event: dict[str, Any]) -> PlaybackState | None:
        """Follow a report of the page's player (checked by the scene): the new state, or
        ``None`` for a report of another animation or without one loaded."""
        if not self._loaded or event.get("animation") != self._id:
            return None
        if event["event"] == "end":
            self._set(self._duration, False)
        else:
            self._set(min(max(event["time"], 0.0), self._duration), event["playing"])
        self._speed = event.get("speed", self._speed)
        return self.state()

    def replay_ops(self, *, from_start: bool = False) -> list[Op]:
        """What a new view needs to stand where the others do: the player loaded at the
        current time, playing if the animation still plays. ``from_start`` (a file that
        is opened later): a playing or ended animation plays from the start when opened;
        one paused mid-way stays at its frame."""
        if not self._loaded:
            return []
        return [self._load_op(from_start=from_start)]

    def _load_op(self, *, from_start: bool = False) -> Op:
        time = self._time_at(monotonic())
        playing = self._playing and time < self._duration
        if from_start and (playing or time >= self._duration):
            time, playing = 0.0, True
        return playback_op(
            "load",
            id=self._id,
            duration=self._duration,
            speed=self._speed,
            time=time,
            playing=playing,
        )

    def _set(self, time: float, playing: bool) -> None:
        self._time, self._playing, self._since = time, playing, monotonic()

    def _time_at(self, now: float | None) -> float:
        if not self._playing:
            return self._time
        elapsed = (monotonic() if now is None else now) - self._since
        return min(self._time + elapsed * self._speed, self._duration)

    def trace_op(self) -> Op:
        """The end-effector's path of the loaded motion, as one line."""
        return set_object_op(TRACE, polyline(self._points[:, -1], COLORS["end_effector"]))

    def extent(self) -> np.ndarray:
        """Where the loaded motion takes the frames and the end effector (k, 3), for the
        fit (at most about 200 keyframes of it)."""
        if not self._loaded:
            return np.zeros((0, 3))
        step = max(1, len(self._points) // 200)
        return np.vstack([self._points[::step], self._points[-1:]]).reshape(-1, 3)


def _check_speed(speed: Any) -> float:
    value = check_finite_number(speed, "speed")
    low, high = SPEED_RANGE
    if value <= 0:
        raise InvalidInputError("speed", value, "a number > 0", problem="must be positive:")
    if not low <= value <= high:
        raise InvalidInputError("speed", value, f"a number from {low:g} to {high:g}")
    return value


#: Keyframes kept at most; longer motions are thinned evenly (first and last kept).
MAX_FRAMES = 1500


def animation_command(drawing: RobotDrawing, motion: Any, *, root: str) -> dict[str, Any]:
    """meshcat's ``set_animation`` command for a motion of the drawn robot, loaded paused
    (the page's player plays it).

    Parameters
    ----------
    drawing : RobotDrawing
    motion : Motion
        Its ``t`` (T,) and ``q`` (T, n) are used.
    root : str
        Scene path of the drawing's items.

    Returns
    -------
    dict
        ``{"type": "set_animation", "animations": [...], "options": {...}}``.
    """
    t = getattr(motion, "t", None)
    q = getattr(motion, "q", None)
    if t is None or q is None:
        raise InvalidInputError("motion", motion, "a Motion from robotconf.simulate")
    robot = drawing.robot
    q, batched = check_joint_values(q, robot.n, robot.coordinate_names, "motion.q")
    if not batched:
        raise InvalidInputError(
            "motion.q", f"shape {q.shape[1:]}", f"a motion of this robot's {robot.n} coordinates"
        )
    t = np.asarray(t, dtype=float)
    keep = _keyframes(len(t))
    times = float32_array(t[keep] - t[0])
    placement = drawing.placements(q[keep])
    quats = quaternions(placement.rotation)
    animations = []
    for k, path in enumerate(drawing.paths):
        tracks = [
            _track(".position", "vector3", times, placement.position[:, k]),
            _track(".quaternion", "quaternion", times, quats[:, k]),
            _track(".scale", "vector3", times, placement.scale[:, k]),
        ]
        # fps = 1: keyframe times are in seconds.
        clip = {"fps": 1, "name": "default", "tracks": tracks}
        animations.append({"path": f"{root}/{path}", "clip": clip})
    return {
        "type": "set_animation",
        "animations": animations,
        "options": {"play": False, "repetitions": 1},
    }


def animation_state(motion: Any) -> tuple[float, np.ndarray]:
    """The length of ``motion`` (s) and every labelled point (the frames, then the end
    effector) at the keyframes, shape (K, n + 1, 3), for the trace and the fit
    (``motion`` checked by :func:`animation_command` first).

    >>> import robotconf as rc
    >>> robot = rc.Robot([rc.Module("Rz")], end_effector=(1, 0, 0))
    >>> motion = rc.simulate(robot, {"q1": rc.signals.Constant(0.5)}, t_end=2, dt=0.5)
    >>> duration, points = animation_state(motion)
    >>> duration, points.shape
    (2.0, (5, 2, 3))
    """
    t = np.asarray(motion.t, dtype=float)
    points = np.asarray(motion.position, dtype=float)[_keyframes(len(t))]
    duration = float(t[-1] - t[0]) if len(t) else 0.0
    return duration, points


def _keyframes(samples: int) -> np.ndarray:
    return np.unique(np.linspace(0, samples - 1, min(samples, MAX_FRAMES)).round().astype(int))


def _track(name: str, kind: str, times: msgpack.ExtType, values: np.ndarray) -> dict[str, Any]:
    # float32, as WebGL draws them anyway: an animation travels as bytes, not as text.
    return {"name": name, "type": kind, "times": times, "values": float32_array(values)}
