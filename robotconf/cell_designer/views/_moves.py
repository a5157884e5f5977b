"""One move of a robot's program as a row: its type, target, numbers and buttons, and
under it what the last Run said about it (the core's refusal, violations, contacts).

Keys: ``move[k].kind``, ``.target`` (a frame's name, ``point`` or ``q``), ``.q0`` …,
``.point0`` … ``.point2`` (a point in the robot's base frame), ``.via0`` … ``.via2``,
``.speed``, ``.seconds``, ``.profile``, ``.teach``, ``.up``, ``.down``, ``.delete``;
``k`` counts the rows of every program, in the order they are drawn.
"""

from __future__ import annotations

from typing import Any

from ...panel.form import button, select, text
from ...programs import CIRC, LIN, PROFILES, PTP, Move, Wait
from ..state import MOVE_KINDS, DesignerState, RobotItem, target_of
from ._boxes import LENGTH, box
from ._messages import Messages

__all__ = ["move_controls", "target_choices", "MOVE_CLASS"]

#: The class of a move's row.
MOVE_CLASS = "robotconf-cell-move"


def target_choices(state: DesignerState, move: Move) -> list[tuple[str, str]]:
    """A move's target menu: coordinates (a PTP), a point, then the cell's frames (and the
    entry a move from a file names, if it is no frame)."""
    choices = [("q (joints)", "q")] if isinstance(move, PTP) else []
    choices.append(("point (base frame)", "point"))
    names = list(state.cell.frames)
    frame = getattr(move, "frame", None)
    if frame is not None and frame not in names:
        names.append(frame)
    return choices + [(f"frame {name}", name) for name in names]


def _point_boxes(
    prefix: str,
    name: str,
    values: Any,
    state: DesignerState,
    messages: Messages,
    rev: str,
    step: float,
) -> list[dict[str, Any]]:
    return [
        box(
            f"{prefix}.{name}{k}",
            float(v),
            LENGTH,
            state.units,
            messages,
            rev,
            step=step,
            title=f"{name} {a}",
            width="58px",
        )
        for k, (v, a) in enumerate(zip(values, "xyz", strict=True))
    ]


def _target(move: Move) -> str:
    kind = target_of(move)
    return move.frame if kind == "frame" else ("point" if kind == "pose" else kind)  # type: ignore[attr-defined]


def _speed(
    prefix: str,
    move: Move,
    state: DesignerState,
    messages: Messages,
    rev: str,
    default: float,
    step: float,
) -> list[dict[str, Any]]:
    value = move.speed if move.speed is not None else default  # type: ignore[attr-defined]
    units = state.units
    return [
        text(f"speed [{units.length}/s]", tone="note"),
        box(
            f"{prefix}.speed",
            float(value),
            LENGTH,
            units,
            messages,
            rev,
            step=step,
            title="path speed (the program's until typed)",
            width="58px",
        ),
    ]


def move_controls(
    prefix: str,
    index: int,
    count: int,
    move: Move,
    item: RobotItem,
    state: DesignerState,
    messages: Messages,
    rev: str,
    path_speed: float,
    step: float,
) -> list[dict[str, Any]]:
    """The controls of move ``index`` (of ``count``) of ``item``'s program, on one line."""
    units = state.units
    parts: list[dict[str, Any]] = [
        text(f"P{index + 1}", tone="title"),
        select(f"{prefix}.kind", move.kind, [(k, k) for k in MOVE_KINDS], rev=rev, width="70px"),
    ]
    if isinstance(move, Wait):
        parts += [
            text("wait [s]", tone="note"),
            box(
                f"{prefix}.seconds",
                float(move.seconds),
                "",
                units,
                messages,
                rev,
                step=0.1,
                width="58px",
            ),
        ]
    else:
        if isinstance(move, CIRC):
            parts.append(text(f"via [{units.length}]", tone="note"))
            parts += _point_boxes(prefix, "via", move.via, state, messages, rev, step)
            parts.append(text("to", tone="note"))
        target = _target(move)
        parts.append(
            select(f"{prefix}.target", target, target_choices(state, move), rev=rev, width="150px")
        )
        if target == "q":
            robot = item.robot
            for k, value in enumerate(move.q):  # type: ignore[attr-defined]
                unit = robot.modules[k].unit if k < robot.n else ""
                parts.append(
                    box(
                        f"{prefix}.q{k}",
                        float(value),
                        unit,
                        units,
                        messages,
                        rev,
                        step=step,
                        title=f"q{k + 1}",
                        width="58px",
                        disabled=not unit,
                    )
                )
        elif target == "point":
            point = _end(move)
            if point is not None:
                parts += _point_boxes(prefix, "point", point, state, messages, rev, step)
        if isinstance(move, PTP):
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
        else:
            parts += _speed(prefix, move, state, messages, rev, path_speed, step)
        tip = "the robot's q now" if isinstance(move, PTP) else "where the TCP is now (a point)"
        parts.append(button(f"{prefix}.teach", "teach", title=f"teach: {tip}", rev=rev))
    parts += [
        button(f"{prefix}.up", "↑", title="move up", disabled=index == 0, rev=rev),
        button(f"{prefix}.down", "↓", title="move down", disabled=index == count - 1, rev=rev),
        button(
            f"{prefix}.delete",
            "✕",
            title="delete (↶ brings it back)",
            rev=rev,
            css_class="robotconf-cell-move-delete",
        ),
    ]
    return parts


def _end(move: Move) -> Any:
    """A move's end point as three numbers (a pose's translation), or ``None``."""
    value = getattr(move, "end" if isinstance(move, CIRC) else "position", None)
    if value is None and isinstance(move, (PTP, LIN)):
        value = move.pose
    if value is None:
        return None
    if len(value) == 4:
        return [row[3] for row in value[:3]]
    return value
