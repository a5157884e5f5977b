"""The Program tab's table as form rows: per move its type, target, speed or profile, its
buttons, and the messages about it (the core's refusal, the last Run's violations).

Keys: ``program.moves[i].kind``, ``….q0`` … (a PTP's coordinates), ``….point0`` … (a
LIN's end, a CIRC's end), ``….via0`` …, ``….speed``, ``….seconds``, ``….profile``, and
the buttons ``….teach``, ``….via``, ``….up``, ``….down``, ``….delete``.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ...kinematics import Robot
from ...programs import CIRC, LIN, PROFILES, PTP, Move, Wait
from ..form import button, message, number, row, select, text
from ..state import Units
from ..state._program_draft import MOVE_KINDS, point_of

__all__ = ["move_rows", "short_number", "BOX_UNITS"]

_TEACH_TIPS = {
    "PTP": "teach: the robot's current coordinates become this move's target",
    "LIN": "teach: where the end effector is now becomes this line's end",
    "CIRC": "teach: where the end effector is now becomes this arc's end",
    "Wait": "a Wait has no target",
}
#: The core unit of each box of a move, by field (a PTP's q: each coordinate's own).
BOX_UNITS = {"point": "length", "via": "length", "speed": "length", "seconds": ""}


def short_number(value: float) -> float:
    """``value`` to 6 significant digits, as a converted number is shown (57.2958 for 1 rad).

    >>> short_number(57.29577951308232), short_number(22.5)
    (57.2958, 22.5)
    """
    return float(f"{value:.6g}") + 0.0 if np.isfinite(value) else float(value)


def _boxes(
    prefix: str,
    name: str,
    values: Any,
    units_of: list[str],
    units: Units,
    feedback: Any,
    rev: str,
    disabled: list[bool] | None = None,
) -> list[dict[str, Any]]:
    single = len(units_of) == 1 and name in ("speed", "seconds")
    boxes = []
    for k, (value, unit) in enumerate(zip(values, units_of, strict=True)):
        key = f"{prefix}.{name}" if single else f"{prefix}.{name}{k}"
        shown = short_number(units.to_shown(float(value), unit)) if np.isfinite(value) else value
        error = feedback.message(key)
        held = bool(disabled and disabled[k])
        # A joint the program cannot move has no value to show in the row's unit: a dash.
        typed = "—" if held else (feedback.typed(key) if error else None)
        boxes.append(
            number(
                key,
                shown,
                0.0,
                0.0,
                1.0 if unit else 0.1,
                slider=False,
                rev=rev,
                width="66px",
                text=typed,
                note=message(error),
                disabled=held,
                css_class=f"robotconf-program-{name}",
            )
        )
    return boxes


def _fields(
    prefix: str, move: Move, robot: Robot, units: Units, speed: float, feedback: Any, rev: str
) -> list[dict[str, Any]]:
    length = units.length
    if isinstance(move, PTP):
        parts: list[dict[str, Any]] = []
        if move.q is not None:
            core = [robot.modules[i].unit if i < robot.n else "" for i in range(len(move.q))]
            shown = sorted({units.coordinate(u) for u in core if u})
            parts.append(text(f"q [{', '.join(shown)}]" if shown else "q", tone="note"))
            parts += _boxes(
                prefix, "q", move.q, core, units, feedback, rev, disabled=[not u for u in core]
            )
        else:
            point = point_of(move)
            what = "pose" if move.pose is not None else "point"
            numbers = ", ".join(f"{short_number(v):g}" for v in point or ())
            parts.append(
                text(f"{what} ({numbers}) [{length}], solved by rc.ik; teach to set q", tone="note")
            )
        parts.append(
            select(
                f"{prefix}.profile",
                move.profile,
                [(p, p) for p in PROFILES],
                rev=rev,
                width="112px",
                title="time law",
            )
        )
        return parts
    if isinstance(move, (LIN, CIRC)):
        parts = []
        if isinstance(move, CIRC):
            parts.append(text(f"via [{length}]", tone="note"))
            parts += _boxes(prefix, "via", move.via, ["length"] * 3, units, feedback, rev)
            parts.append(text("end", tone="note"))
        else:
            parts.append(text(f"x, y, z [{length}]", tone="note"))
        parts += _boxes(prefix, "point", point_of(move), ["length"] * 3, units, feedback, rev)
        parts.append(text(f"speed [{length}/s]", tone="note"))
        value = speed if move.speed is None else move.speed
        parts += _boxes(prefix, "speed", (value,), ["length"], units, feedback, rev)
        return parts
    assert isinstance(move, Wait)
    return [
        text("wait [s]", tone="note"),
        *_boxes(prefix, "seconds", (move.seconds,), [""], units, feedback, rev),
    ]


def move_rows(
    moves: tuple[Move, ...],
    robot: Robot,
    units: Units,
    speed: float,
    feedback: Any,
    rev: str,
    violations: list[list[str]],
    refusal: tuple[int, str] | None,
) -> list[dict[str, Any]]:
    """One row per move, named ``P1``, ``P2``, … as the points in the 3D view.

    ``violations[i]`` are the last Run's messages for move ``i``; ``refusal`` is the core's
    message for a move the program no longer fits (after a change of the robot).
    """
    rows = []
    count = len(moves)
    for i, move in enumerate(moves):
        prefix = f"program.moves[{i}]"
        cells: list[dict[str, Any]] = [
            text(f"P{i + 1}", tone="title"),
            select(
                f"{prefix}.kind",
                move.kind,
                [(k, k) for k in MOVE_KINDS],
                rev=rev,
                width="72px",
                css_class="robotconf-program-kind",
            ),
            *_fields(prefix, move, robot, units, speed, feedback, rev),
            button(
                f"{prefix}.teach",
                "◎ teach",
                title=_TEACH_TIPS[move.kind],
                disabled=isinstance(move, Wait),
                css_class="robotconf-program-teach",
            ),
        ]
        if isinstance(move, CIRC):
            cells.append(
                button(
                    f"{prefix}.via",
                    "◎ via",
                    title="teach the via point: where the end effector is now",
                )
            )
        cells += [
            button(f"{prefix}.up", "↑", title="move up", disabled=i == 0),
            button(f"{prefix}.down", "↓", title="move down", disabled=i >= count - 1),
            button(f"{prefix}.delete", "✕", title="delete this move (↶ brings it back)"),
        ]
        messages = feedback.message(prefix)
        if not messages and refusal is not None and refusal[0] == i:
            messages = refusal[1]
        lines = [cells]
        if i < len(violations) and violations[i]:
            lines.append(
                [
                    text(f"⚠ {m}", tone="warning", css_class="robotconf-program-violation")
                    for m in violations[i]
                ]
            )
        rows.append(row(prefix, *lines, note=message(messages), css_class="robotconf-program-row"))
    return rows
