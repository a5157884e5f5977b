"""What the Program tab's rows ask for, as new drafts; and the points the 3D view marks.

Pure functions of a :class:`~robotconf.panel.state.ProgramDraft` and the panel's robot:
the program actions and the Program tab's drawing use them.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ...kinematics import Robot
from ...programs import CIRC, Wait
from ..state._program_draft import ProgramDraft, converted, edited, end_points, taught

__all__ = ["edit_move", "row_action", "taught_markers"]


def edit_move(
    draft: ProgramDraft, robot: Robot, index: int, name: str, value: Any, component: int | None
) -> ProgramDraft:
    """The draft with move ``index``'s field ``name`` (or one ``component``) set to
    ``value`` (core units); ``name == "kind"`` changes the move's type, keeping its point.

    >>> import robotconf as rc
    >>> from robotconf.programs import PTP
    >>> robot = rc.preset("paper")
    >>> draft = ProgramDraft((PTP(q=(0.0, 0.0, -np.pi / 2)),))
    >>> edit_move(draft, robot, 0, "kind", "LIN", None).moves[0].position
    (30.000000000000004, 0.0, 60.0)
    """
    moves = list(draft.moves)
    if name == "kind":
        points = end_points(draft, robot)
        before = points[index - 1] if index > 0 else robot.at().end_effector
        moves[index] = converted(moves[index], value, robot, before, points[index])
    else:
        moves[index] = edited(moves[index], name, value, component)
    return draft.with_moves(moves)


def row_action(draft: ProgramDraft, robot: Robot, index: int, action: str) -> ProgramDraft:
    """The draft after a row's button: ``"teach"``, ``"teach via"``, ``"up"``, ``"down"``
    or ``"delete"`` (a move at an end of the table stays where it is).

    >>> import robotconf as rc
    >>> draft = ProgramDraft((Wait(1.0), Wait(2.0)))
    >>> row_action(draft, rc.preset("paper"), 1, "up").moves
    (Wait(seconds=2.0), Wait(seconds=1.0))
    """
    moves = list(draft.moves)
    if action in ("teach", "teach via"):
        moves[index] = taught(moves[index], robot, via=action == "teach via")
    elif action == "delete":
        del moves[index]
    else:
        other = index - 1 if action == "up" else index + 1
        if 0 <= other < len(moves):
            moves[index], moves[other] = moves[other], moves[index]
    return draft.with_moves(moves)


def taught_markers(
    draft: ProgramDraft, robot: Robot
) -> tuple[np.ndarray, list[str], np.ndarray, list[str]]:
    """Where the moves end, labelled ``P1``, ``P2``, … after their rows, and the CIRC via
    points (``P2 via``): ``(points (k, 3), labels, via (m, 3), via_labels)``.

    A Wait ends where the move before it did and gets no marker of its own.

    >>> import robotconf as rc
    >>> from robotconf.programs import LIN, PTP
    >>> draft = ProgramDraft((PTP(q=(0.0, 0.0, 0.0)), Wait(1.0), LIN(position=(60.0, 10.0, 30.0))))
    >>> points, labels, via, _ = taught_markers(draft, rc.preset("paper"))
    >>> points.tolist(), labels, via.shape
    ([[70.0, 0.0, 20.0], [60.0, 10.0, 30.0]], ['P1', 'P3'], (0, 3))
    """
    points, labels, vias, via_labels = [], [], [], []
    for i, (move, point) in enumerate(zip(draft.moves, end_points(draft, robot), strict=True)):
        if point is not None and not isinstance(move, Wait):
            points.append(point)
            labels.append(f"P{i + 1}")
        if isinstance(move, CIRC):
            via = np.asarray(move.via, dtype=float)
            if via.shape == (3,) and np.isfinite(via).all():
                vias.append(via)
                via_labels.append(f"P{i + 1} via")
    return np.reshape(points, (-1, 3)), labels, np.reshape(vias, (-1, 3)), via_labels
