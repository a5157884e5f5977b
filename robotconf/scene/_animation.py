"""A simulated motion as a meshcat animation: keyframe tracks for every drawn item.

The viewer plays the tracks itself (the scene's control bar, or meshcat's "Animations"
menu, play, pause, scrub and change the speed), so playback costs the kernel nothing and
survives in an HTML export. :class:`AnimationState` is the kernel's record of what is
loaded: its length, its keyframe time unit and the end-effector's path for the trace.
"""

from __future__ import annotations

from dataclasses import dataclass
from time import monotonic
from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_finite_number, check_flag, check_joint_values
from ._drawing import RobotDrawing
from ._placement import quaternions

__all__ = ["AnimationState", "animation_command", "animation_state", "MAX_FRAMES"]

#: Keyframes kept at most; longer motions are thinned evenly (first and last kept).
MAX_FRAMES = 1500


def animation_command(
    drawing: RobotDrawing, motion: Any, *, speed: float = 1.0, play: bool = True, root: str
) -> dict[str, Any]:
    """meshcat's ``set_animation`` command for a motion of the drawn robot.

    Parameters
    ----------
    drawing : RobotDrawing
    motion : Motion
        Its ``t`` (T,) and ``q`` (T, n) are used.
    speed : float
        Playback speed, > 0 (1 = real time).
    play : bool
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
    speed = check_finite_number(speed, "speed")
    if speed <= 0:
        raise InvalidInputError("speed", speed, "a finite number > 0", problem="must be positive:")
    play = check_flag(play, "play")
    t = np.asarray(t, dtype=float)
    keep = _keyframes(len(t))
    times = ((t[keep] - t[0]) / speed).tolist()
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
        "options": {"play": play, "repetitions": 1},
    }


@dataclass
class AnimationState:
    """The animation loaded in the viewer.

    Attributes
    ----------
    duration : float
        Length of the motion (s).
    clip_speed : float
        The keyframes' time unit: clip time = motion time / ``clip_speed``.
    path : ndarray, shape (K, 3)
        The end-effector at the keyframes (length units).
    speed : float
        Playback speed (1 = real time).
    time : float
        Where playback is, in motion seconds (as the page last reported).
    playing : bool
    since : float
        ``time.monotonic()`` when playback (re)started from ``time``.
    """

    duration: float
    clip_speed: float
    path: np.ndarray
    speed: float
    time: float = 0.0
    playing: bool = False
    since: float = 0.0

    def still_playing(self, now: float) -> bool:
        """Whether playback started at ``since`` has not reached the end by ``now``.

        >>> state = AnimationState(2.0, 1.0, np.zeros((2, 3)), speed=2.0, playing=True)
        >>> state.still_playing(0.9), state.still_playing(1.1)
        (True, False)
        """
        return self.playing and now < self.since + (self.duration - self.time) / self.speed


def animation_state(motion: Any, speed: float, play: bool) -> AnimationState:
    """The kernel's record of ``motion`` loaded at ``speed`` (checked by
    :func:`animation_command` first).

    >>> import robotconf as rc
    >>> robot = rc.Robot([rc.Module("Rz")], end_effector=(1, 0, 0))
    >>> motion = rc.simulate(robot, {"q1": rc.signals.Constant(0.5)}, t_end=2, dt=0.5)
    >>> state = animation_state(motion, 2.0, True)
    >>> state.duration, state.path.shape
    (2.0, (5, 3))
    """
    t = np.asarray(motion.t, dtype=float)
    path = np.asarray(motion.position, dtype=float)[_keyframes(len(t)), -1]
    duration = float(t[-1] - t[0]) if len(t) else 0.0
    return AnimationState(duration, float(speed), path, float(speed), 0.0, bool(play), monotonic())


def _keyframes(samples: int) -> np.ndarray:
    return np.unique(np.linspace(0, samples - 1, min(samples, MAX_FRAMES)).round().astype(int))


def _track(name: str, kind: str, times: list[float], values: np.ndarray) -> dict[str, Any]:
    return {
        "name": name,
        "type": kind,
        "times": times,
        "values": np.round(values, 7).ravel().tolist(),
    }
