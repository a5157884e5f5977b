"""A simulated motion as a meshcat animation: keyframe tracks for every drawn item.

The viewer plays the tracks itself (play, pause, time scrubber and speed in its
"Animations" menu), so playback costs the kernel nothing and survives in an HTML export.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .._errors import InvalidInputError
from .._validation import check_finite_number, check_flag, check_joint_values
from ._drawing import RobotDrawing
from ._placement import quaternions

__all__ = ["animation_command", "MAX_FRAMES"]

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
    keep = np.unique(np.linspace(0, len(t) - 1, min(len(t), MAX_FRAMES)).round().astype(int))
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


def _track(name: str, kind: str, times: list[float], values: np.ndarray) -> dict[str, Any]:
    return {
        "name": name,
        "type": kind,
        "times": times,
        "values": np.round(values, 7).ravel().tolist(),
    }
