"""A cell's run as one animation: every robot's program side by side on one clock.

:func:`cell_animation` turns a :class:`~robotconf.cell.CellRun` into one meshcat
``set_animation`` for the page's player (the same player and bar as one robot's motion):
each robot's items at its own program's samples (a robot the run leaves out stands at its
own ``q``, as the check measured it), each robot's capsules with it, and the contacts'
switches (:mod:`._contacts`): the red capsules follow their links and show during their
intervals, the objects turn red, the labels appear at the contact points. Every robot's
program starts at t = 0; one that ends first holds its last frame.
"""

from __future__ import annotations

from dataclasses import dataclass
from types import SimpleNamespace
from typing import Any

import numpy as np

from ..._budget import check_memory
from ..._errors import InvalidInputError
from ..._validation import one_line
from ...cell import Cell, CellRun
from .._commands import Op, labels_op, set_object_op, transform_command
from .._placement import Placement
from .._playback import animation_command, clip, keyframe_indices, placement_clips
from .._three import float32_array, label_anchor
from ._capsules import CAPSULE_PARTS, CapsulesLayer, capsule_objects, capsule_placement
from ._contacts import (
    MAX_CONTACT_LABELS,
    ContactMark,
    color_track,
    contact_marks,
    link_intervals,
    object_intervals,
    switch_track,
)
from ._entities import EntitiesLayer
from ._paths import CONTACTS, OBJECTS
from ._robots import RobotsLayer
from ._shapes import CONTACT_COLOR

__all__ = ["CellAnimation", "cell_animation", "check_run", "RED_OPACITY"]

#: The red capsules of links in contact: nearly opaque, a little wider than the link's.
RED_OPACITY = 0.8
RED_WIDER = 1.04


@dataclass
class CellAnimation:
    """What :func:`cell_animation` built.

    Attributes
    ----------
    command : dict
        meshcat's ``set_animation``, loaded paused.
    build : list of Op
        The contacts' objects (red capsules, label anchors and texts), sent before it.
    duration : float
        The run's length (s): its longest program, or the check's last sample.
    extent : ndarray, shape (k, 3)
        Where the robots go (cell frame), for the fit.
    traces : dict
        Each robot's TCP path in its base frame, by the path of its trace line.
    marks : list of ContactMark
        Every contact interval with its label and point.
    """

    command: dict[str, Any]
    build: list[Op]
    duration: float
    extent: np.ndarray
    traces: dict[str, np.ndarray]
    marks: list[ContactMark]


def check_run(cell: Cell, run: Any) -> CellRun:
    """``run`` checked against the cell shown: a CellRun whose robots are in it with
    their numbers of coordinates."""
    if not isinstance(run, CellRun):
        raise InvalidInputError("cell_run", one_line(run), "a CellRun from cell.run(programs)")
    for name, motion in run.motions.items():
        if name not in cell.robots:
            raise InvalidInputError(
                "cell_run",
                name,
                f"a run of this cell's robots {list(cell.robots)[:20]}",
                problem="a robot the cell does not have:",
            )
        if np.shape(motion.q)[1:] != (cell.robot(name).n,):
            raise InvalidInputError(
                f"cell_run.motions[{name!r}]",
                one_line(motion),
                f"a motion of the {cell.robot(name).n} coordinates of the robot placed as {name!r}",
            )
    return run


def cell_animation(
    cell: Cell,
    run: CellRun,
    robots: RobotsLayer,
    capsules: CapsulesLayer,
    entities: EntitiesLayer,
) -> CellAnimation:
    """Build the animation of ``run`` in the cell the scene shows (checked by
    :func:`check_run`)."""
    duration = max(
        [float(run.check.t[-1]) if len(run.check.t) else 0.0]
        + [float(m.t[-1] - m.t[0]) for m in run.motions.values() if len(m.t)]
    )
    motions = {
        name: run.motions.get(name) or _standing(cell, name, duration) for name in robots.layers
    }
    _check_size(motions, capsules)
    marks = contact_marks(cell, run)
    links = link_intervals(marks)
    animations: list[dict[str, Any]] = []
    build: list[Op] = []
    extent = [np.zeros((0, 3))]
    traces: dict[str, np.ndarray] = {}
    for name, motion in motions.items():
        layer = robots.layers[name]
        assert layer.drawing is not None
        root = robots.root(name)
        animations += animation_command(layer.drawing, motion, root=root)["animations"]
        keep = keyframe_indices(len(motion.t))
        times = float32_array(np.asarray(motion.t, dtype=float)[keep] - motion.t[0])
        placement = capsule_placement(cell.link_capsules(name, np.asarray(motion.q)[keep])[0])
        animations += placement_clips(capsules.paths(name), times, placement)
        red_ops, red_clips = _red_capsules(cell, name, robots, placement, times, links)
        build += red_ops
        animations += red_clips
        base = robots.bases[name]
        if name in run.motions:
            position = np.asarray(motion.position, dtype=float)[keep]
            traces[f"{root}/trace"] = position[:, -1]
            step = max(1, len(position) // 200)  # the fit needs about 200 keyframes
            seen = np.vstack([position[::step], position[-1:]]).reshape(-1, 3)
            extent.append(seen @ base[:3, :3].T + base[:3, 3])
    for name, intervals in object_intervals(marks).items():
        key = entities.drawn[name].key
        animations.append(clip(f"{OBJECTS}/{key}/<object>", [color_track(intervals)]))
    label_ops, label_clips = _labels(marks[:MAX_CONTACT_LABELS])
    build += label_ops
    animations += label_clips
    command = {
        "type": "set_animation",
        "animations": animations,
        "options": {"play": False, "repetitions": 1},
    }
    return CellAnimation(command, build, duration, np.vstack(extent), traces, marks)


def _standing(cell: Cell, name: str, duration: float) -> Any:
    """A robot the run leaves out: at its own q all along, as the check measured it."""
    q = np.asarray(cell.robot(name).q, dtype=float)
    return SimpleNamespace(t=np.array([0.0, duration]), q=np.vstack([q, q]))


def _check_size(motions: dict[str, Any], capsules: CapsulesLayer) -> None:
    """The animation's keyframes, estimated before any is built: every robot's items,
    capsules (and as many red ones) at its kept samples, 10 floats each, several copies."""
    total = 0
    for name, motion in motions.items():
        samples = len(keyframe_indices(len(motion.t)))
        items = 5 * (np.shape(motion.q)[1] + 2) + 2 * len(capsules.paths(name))
        total += samples * items * 10 * 4 * 4
    check_memory("cell_run", f"<{len(motions)} robots>", total, "fewer samples (a larger dt)")


def _red_capsules(
    cell: Cell,
    name: str,
    robots: RobotsLayer,
    placement: Placement,
    times: Any,
    links: dict[tuple[str, str], list[tuple[float, float | None]]],
) -> tuple[list[Op], list[dict[str, Any]]]:
    """The red capsules of this robot's links in contact: objects, and clips that move
    them with the link and show them during the intervals."""
    names = cell.link_names(name)
    _, radii = cell.link_capsules(name)
    key = robots.key(name)
    ops: list[Op] = []
    clips: list[dict[str, Any]] = []
    for k, link in enumerate(names):
        intervals = links.get((name, link))
        if not intervals:
            continue
        root = f"{CONTACTS}/links/{key}/{k}"
        paths = [f"{root}/{part}" for part in CAPSULE_PARTS]
        ops += capsule_objects(paths, RED_WIDER * radii[k : k + 1], CONTACT_COLOR, RED_OPACITY)
        ops.append(Op({"op": "visible", "paths": [root], "value": False}))
        part = slice(3 * k, 3 * k + 3)
        mine = Placement(
            placement.position[:, part], placement.rotation[:, part], placement.scale[:, part]
        )
        clips += placement_clips(paths, times, mine)
        clips.append(clip(root, [switch_track(intervals)]))
    return ops, clips


def _labels(marks: list[ContactMark]) -> tuple[list[Op], list[dict[str, Any]]]:
    """A label anchor at each contact point, shown during its interval."""
    ops: list[Op] = []
    clips: list[dict[str, Any]] = []
    paths = []
    for k, mark in enumerate(marks):
        group = f"{CONTACTS}/labels/{k}"
        anchor = f"{group}/text"
        matrix = np.eye(4)
        matrix[:3, 3] = mark.point
        ops += [
            set_object_op(anchor, label_anchor(mark.radius)),
            transform_command(anchor, matrix),
            Op({"op": "visible", "paths": [group], "value": False}),
        ]
        paths.append(anchor)
        clips.append(clip(group, [switch_track([(mark.on, mark.off)])]))
    if paths:
        ops.append(labels_op(paths, [mark.text for mark in marks]))
    return ops, clips
