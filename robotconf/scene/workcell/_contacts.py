"""A run's contacts in the scene: what turns red, when, and the label at each contact.

Every contact interval of ``cell_run.check`` (:class:`~robotconf.cell.Contact`: a robot's
link meets an object, another of its links or another robot's link) turns both sides red
while the animation's time is inside it: the link as a red capsule around it (the shape
the check measured), an object by its own colour. The switches are keyframe tracks with
discrete steps in the same animation as the robots (three.js's ``.visible`` and
``.material.color``), so the page turns them on and off as it plays, with no message to
the kernel. A contact is on from its first sample in contact to the next sample after its
last (the check's times: the true start lies within one sample before).

A label names each contact at its contact point, ``"link 3 ↔ fixture, 8.56 mm"`` (the
depth as the check's sentence gives it; ``"… 1.2 mm away"`` for a contact within a
margin), shown during its interval. The contact point is the point of the link's axis
that goes deepest into the other body at the deepest sample, found with the cell's own
distances (:meth:`Obstacles.exact <robotconf.cell.distance.Obstacles.exact>`,
:func:`~robotconf.cell.distance.segment_segment_distance`) along the axis.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ...cell import Cell, CellRun, Contact
from ...cell.distance import segment_segment_distance
from .._playback import track
from .._three import float32_array
from ._shapes import CONTACT_COLOR, OBJECT_COLOR, rgb

__all__ = [
    "ContactMark",
    "contact_marks",
    "contact_text",
    "switch_track",
    "color_track",
    "link_intervals",
    "object_intervals",
    "DISCRETE",
    "MAX_CONTACT_LABELS",
    "AXIS_PROBES",
]

#: three.js's ``InterpolateDiscrete``: a track holds each value until its next keyframe.
DISCRETE = 2300
#: Contacts labelled at most (every contact still turns red).
MAX_CONTACT_LABELS = 100
#: Points along a link's axis at which the contact point is looked for.
AXIS_PROBES = 65


@dataclass(frozen=True)
class ContactMark:
    """One contact interval as the scene shows it.

    Attributes
    ----------
    contact : Contact
    text : str
        The label, ``"link 3 ↔ fixture, 8.56 mm"``.
    point : ndarray, shape (3,)
        The contact point (cell frame, length units).
    on, off : float
        When its highlight turns on and off (s); ``off`` is None when it lasts to the end.
    radius : float
        The link's capsule radius (the label keeps that far from the point).
    """

    contact: Contact
    text: str
    point: np.ndarray
    on: float
    off: float | None
    radius: float


def contact_text(contact: Contact, unit: str | None, several: bool) -> str:
    """The label of a contact: the link, what it meets, how deep (or how far, with a
    margin).

    >>> from robotconf.cell import Contact
    >>> c = Contact("a", "link 3", "b/link 2", "robot", 1.0, 2.0, 4.21, 1.5, 1, "LIN", "")
    >>> contact_text(c, "mm", several=True)
    'a link 3 ↔ b link 2, 4.21 mm'
    """
    who = f"{contact.robot} " if several else ""
    other = contact.other.replace("/", " ", 1) if contact.kind == "robot" else contact.other
    unit_text = f" {unit}" if unit else ""
    # The check's sentence writes the depth with three significant digits: the same here.
    amount = f"{abs(contact.depth):.3g}{unit_text}"
    if contact.depth < 0:
        amount += " away"
    return f"{who}{contact.link} ↔ {other}, {amount}"


def _off_time(t: np.ndarray, end: float) -> float | None:
    after = int(np.searchsorted(t, end, side="right"))
    return float(t[after]) if after < len(t) else None


def _q_at(cell: Cell, run: CellRun, robot: str, time: float) -> np.ndarray:
    """A robot's q at ``time`` as the check saw it (a robot with no program: its own)."""
    motion = run.motions.get(robot)
    if motion is None:
        return np.asarray(cell.robot(robot).q, dtype=float)
    k = min(int(np.searchsorted(motion.t, time - 1e-12)), len(motion.t) - 1)
    return np.asarray(motion.q[k], dtype=float)


def _contact_point(cell: Cell, run: CellRun, contact: Contact) -> tuple[np.ndarray, float]:
    """The contact point (3,) and the link's radius."""
    segments, radii = cell.link_capsules(
        contact.robot, _q_at(cell, run, contact.robot, contact.deepest)
    )
    index = cell.link_names(contact.robot).index(contact.link)
    a, b = segments[index]
    probes = a + np.linspace(0.0, 1.0, AXIS_PROBES)[:, None] * (b - a)
    if contact.kind == "object":
        obstacles, names = cell.obstacles()
        which = np.full(AXIS_PROBES, names.index(contact.other))
        distance = obstacles.exact(probes, probes, np.zeros(AXIS_PROBES), which)
    else:
        robot, link = (
            contact.other.split("/", 1)
            if contact.kind == "robot"
            else (contact.robot, contact.other)
        )
        other, _ = cell.link_capsules(robot, _q_at(cell, run, robot, contact.deepest))
        c, d = other[cell.link_names(robot).index(link)]
        ends = np.broadcast_to(c, probes.shape), np.broadcast_to(d, probes.shape)
        distance = segment_segment_distance(probes, probes, *ends)
    return probes[int(np.argmin(distance))], float(radii[index])


def contact_marks(cell: Cell, run: CellRun) -> list[ContactMark]:
    """Every contact interval of ``run.check`` with its label, point and switch times."""
    t = np.asarray(run.check.t, dtype=float)
    several = len(cell.robots) > 1
    marks = []
    for contact in run.check.contacts:
        point, radius = _contact_point(cell, run, contact)
        text = contact_text(contact, cell.unit, several)
        marks.append(
            ContactMark(contact, text, point, contact.start, _off_time(t, contact.end), radius)
        )
    return marks


def link_intervals(
    marks: list[ContactMark],
) -> dict[tuple[str, str], list[tuple[float, float | None]]]:
    """``{(robot, link): [(on, off), …]}``: when each link is in some contact (both links
    of a pair of links)."""
    out: dict[tuple[str, str], list[tuple[float, float | None]]] = {}
    for mark in marks:
        c = mark.contact
        out.setdefault((c.robot, c.link), []).append((mark.on, mark.off))
        if c.kind == "self":
            out.setdefault((c.robot, c.other), []).append((mark.on, mark.off))
        elif c.kind == "robot":
            robot, link = c.other.split("/", 1)
            out.setdefault((robot, link), []).append((mark.on, mark.off))
    return out


def object_intervals(marks: list[ContactMark]) -> dict[str, list[tuple[float, float | None]]]:
    """``{object: [(on, off), …]}``: when each object is in some contact."""
    out: dict[str, list[tuple[float, float | None]]] = {}
    for mark in marks:
        if mark.contact.kind == "object":
            out.setdefault(mark.contact.other, []).append((mark.on, mark.off))
    return out


def _switches(intervals: list[tuple[float, float | None]]) -> tuple[list[float], list[bool]]:
    """Keyframe times and on/off values of a union of intervals, from t = 0 (an ``off``
    of None lasts to the end)."""
    merged: list[list[Any]] = []
    for on, off in sorted(intervals, key=lambda item: item[0]):
        last = merged[-1] if merged else None
        if last is not None and (last[1] is None or last[1] >= on):  # overlaps: one interval
            if last[1] is not None and (off is None or off > last[1]):
                last[1] = off
            continue
        merged.append([on, off])
    times, values = [0.0], [False]
    for on, off in merged:
        if on <= 0.0:
            values[0] = True
        else:
            times.append(float(on))
            values.append(True)
        if off is not None:
            times.append(float(off))
            values.append(False)
    return times, values


def switch_track(intervals: list[tuple[float, float | None]]) -> dict[str, Any]:
    """A ``.visible`` track: on inside the intervals, off outside, in discrete steps.

    >>> switch = switch_track([(0.5, 0.8), (0.7, 1.2), (2.0, None)])
    >>> switch["values"], np.frombuffer(switch["times"].data, np.float32).tolist()
    ([False, True, False, True], [0.0, 0.5, 1.2000000476837158, 2.0])
    """
    times, values = _switches(intervals)
    return track(".visible", "bool", float32_array(np.array(times)), values, interpolation=DISCRETE)


def color_track(intervals: list[tuple[float, float | None]]) -> dict[str, Any]:
    """A ``.material.color`` track: the contact red inside the intervals, the objects'
    colour outside, in discrete steps."""
    times, values = _switches(intervals)
    colors = np.array([rgb(CONTACT_COLOR) if on else rgb(OBJECT_COLOR) for on in values])
    return track(
        ".material.color", "color", float32_array(np.array(times)), colors, interpolation=DISCRETE
    )
