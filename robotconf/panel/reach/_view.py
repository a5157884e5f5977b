"""The Reach tab: a target the robot follows by inverse kinematics, the closed-form
branches as buttons, and what the 3D view draws for it (ghosts, the target marker).

Lengths are in the robot's own unit (named, never converted); roll, pitch and yaw in the
panel's angle unit, reaching the core in radians (``R = Rz(yaw)·Ry(pitch)·Rx(roll)``,
URDF's ``rpy``). Every number comes from :mod:`robotconf.inverse_kinematics`.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ...kinematics import characteristic_length
from .. import actions as act
from .._feedback import Feedback
from .._ranges import length_scale, length_step
from ..editor import Quantity, Ranges, number_spec, read_number
from ..form import Form, FormEvent, button, check, message, row, text, toggle
from ..state import PanelState, in_units, target_numbers, target_of
from ..viewport import Call, Extras

__all__ = ["ReachView", "TOLERANCE", "status_text"]

#: Within this (relative to the robot's size, and in radians) a moved robot still meets
#: the target: the numeric solver's default tolerances.
TOLERANCE = 1e-9
_ANGLES = ("roll", "pitch", "yaw")


def status_text(state: PanelState) -> tuple[str, str]:
    """The tab's status line and its tone (``ok``, ``error`` or ``note``)."""
    reach, robot = state.reach, state.robot
    outcome = reach.outcome
    if outcome is None:
        if reach.target is None:
            return "target: the end effector's current pose", "note"
        return _gap(state)
    if not outcome.success:
        return f"✗ {outcome.reason}: {outcome.message}; the robot stays where it was", "error"
    if outcome.reached is not None and outcome.reached != robot:
        return _gap(state)
    if outcome.reason == "closed form":
        return f"✓ closed-form solution: {outcome.message}", "ok"
    return f"✓ reached: {outcome.message}", "ok"


def _gap(state: PanelState) -> tuple[str, str]:
    """Whether the robot (moved since, by an edit or undo) still meets the target."""
    robot, units = state.robot, state.units
    target = target_of(target_numbers(state.reach, robot), state.reach.mode)
    pose = robot.at().end_effector_pose
    point = target if target.shape == (3,) else target[:3, 3]
    gap = float(np.linalg.norm(pose[:3, 3] - point))
    turn = 0.0
    if target.shape == (4, 4):
        cos = (np.trace(target[:3, :3].T @ pose[:3, :3]) - 1.0) / 2.0
        turn = float(np.arccos(np.clip(cos, -1.0, 1.0)))
    if gap <= TOLERANCE * characteristic_length(robot) and turn <= TOLERANCE:
        return "✓ the end effector is on the target", "ok"
    distance = f"{gap:.4g} {units.length}"
    if target.shape == (4, 4):
        distance += f" and {units.to_shown(turn, 'rad'):.4g} {units.angle}"
    return f"the end effector is {distance} from the target; press reach", "note"


class ReachView:
    """Target controls, the solve's outcome, the closed-form branches.

    Parameters
    ----------
    dispatch : callable
        ``dispatch(action, key, typed=None)``.
    """

    def __init__(self, dispatch: Callable[..., None]) -> None:
        self._dispatch = dispatch
        self._state: PanelState | None = None
        self.ranges = Ranges()
        self.form = Form(self._event, css_class="robotconf-reach-tab")
        self.widget = self.form

    # -- drawing ------------------------------------------------------------------------

    def render(self, state: PanelState, feedback: Feedback, rev: str, visible: bool) -> None:
        """Show the target and the branches (only while the tab shows)."""
        self._state = state
        if not visible:
            return
        robot, units, reach = state.robot, state.units, state.reach
        scale = length_scale(robot)
        numbers = target_numbers(reach, robot)
        length = Quantity("length", units, length_step(scale))
        angle = Quantity("rad", units, 1.0)
        fields = [("x", length), ("y", length), ("z", length)]
        if reach.mode == "pose":
            fields += [(name, angle) for name in _ANGLES]
        controls = []
        for k, (name, quantity) in enumerate(fields):
            key = f"reach.{name}"
            default = (
                (-scale, scale)
                if quantity is length
                else ((-180.0, 180.0) if units.degrees else (-3.1416, 3.1416))
            )
            controls.append(
                number_spec(
                    key,
                    numbers[k],
                    quantity,
                    default,
                    self.ranges,
                    label=name,
                    rev=rev,
                    error=feedback.message(key),
                    typed=feedback.typed(key),
                    label_width="40px",
                    css_class="robotconf-reach-target",
                )
            )
        status, tone = status_text(state)
        status = in_units(status, units)
        outcome = reach.outcome
        warning = in_units(outcome.warning, units) if outcome is not None else ""
        rows = [
            row(
                "reach",
                [
                    toggle(
                        "reach.mode",
                        reach.mode,
                        [("position", "position"), ("pose", "pose")],
                        rev=rev,
                        css_class="robotconf-reach-mode",
                    ),
                    button(
                        "reach.from_current",
                        "◎ from current pose",
                        title="set the target to where the end effector is now",
                        css_class="robotconf-reach-from-current",
                    ),
                    button(
                        "reach.solve",
                        "◎ reach",
                        title="solve again from the robot's current q",
                        css_class="robotconf-reach-solve",
                    ),
                ],
                note=message(feedback.message("reach")),
            ),
            row("reach.target", controls),
            row(
                "reach.status",
                [text(status, tone=tone, css_class="robotconf-reach-status")],
                [text(warning, tone="note")] if warning else [],
            ),
            row(
                "reach.ghosts",
                [
                    check(
                        "reach.show_all",
                        reach.show_all,
                        "show all solutions",
                        rev=rev,
                        css_class="robotconf-reach-ghosts",
                    )
                ],
            ),
        ]
        rows += self._solution_rows(state, numbers, rev)
        self.form.show(rows)

    def _solution_rows(self, state: PanelState, numbers: Any, rev: str) -> list[dict[str, Any]]:
        robot = state.robot
        found = act.solutions_for(robot, numbers, state.reach.mode)
        family = f" of a {found.family} arm" if found.family else ""
        lines: list[list[dict[str, Any]]] = [
            [text(f"Closed-form solutions{family}: {found.count}", tone="title")]
        ]
        if found.note:
            note = in_units(found.note, state.units)
            lines.append([text(note, tone="note", css_class="robotconf-reach-note")])
        solutions = found.solutions
        if solutions is not None:
            buttons = []
            for k, (label, q, ok) in enumerate(
                zip(solutions.labels, solutions.q, solutions.within_limits, strict=True)
            ):
                here = robot.n == q.size and act.same_configuration(robot, robot.q, q)
                tip = act.q_text(robot, q, state.units)
                classes = ["robotconf-reach-solution"]
                if not ok:
                    classes.append("robotconf-reach-outside")  # flagged, still clickable
                    tip += " — outside the joint limits"
                buttons.append(
                    button(
                        f"reach.solution.{k}",
                        ("⚠ " if not ok else "") + str(label),
                        title=tip,
                        style="current" if here else "",
                        css_class=" ".join(classes),
                    )
                )
            lines.append(buttons)
        return [row("reach.solutions", *lines)]

    def scene_extras(self, state: PanelState) -> Extras:
        """What the 3D view draws for this tab: the ghosts and the target marker, with a
        key that changes only when they do (a q drag elsewhere redraws nothing)."""
        reach, robot = state.reach, state.robot
        numbers = target_numbers(reach, robot)
        reachable = reach.outcome is None or reach.outcome.success
        structure = robot.with_q(np.zeros(robot.n))
        key = ("reach", structure, numbers, reach.mode, reach.show_all, reachable)
        found = act.solutions_for(robot, numbers, reach.mode)
        calls: list[Call] = []
        solutions = found.solutions
        if reach.show_all and solutions is not None and len(solutions):
            calls.append(("show_ghosts", (structure, solutions.q), {}))
        else:
            calls.append(("clear_ghosts", (), {}))
        calls.append(("show_target", (target_of(numbers, reach.mode), reachable), {}))
        return Extras(key, tuple(calls))

    # -- input --------------------------------------------------------------------------

    def _event(self, event: FormEvent) -> None:
        state = self._state
        if state is None:
            return
        key = event.key
        if event.event == "widen":
            self.ranges.widen(key, self.form.control(key).get("unit", ""))
            self._dispatch(None, key)
            return
        typed = event.text if event.event == "type" else None
        try:
            action = self._action(state, event)
        except InvalidInputError as error:
            self._dispatch(error, key, typed)
            return
        target = key if key.startswith("reach.") and key[6:] in act.TARGET_FIELDS else "reach"
        self._dispatch(action, target, typed)

    def _action(self, state: PanelState, event: FormEvent) -> Any:
        key = event.key
        if key == "reach.mode":
            return act.SetReachMode(str(event.value))
        if key == "reach.from_current":
            return act.ReachFromCurrent()
        if key == "reach.solve":
            return act.Solve()
        if key == "reach.show_all":
            return act.SetShowAll(bool(event.value))
        if key.startswith("reach.solution."):
            return act.PickSolution(int(key.rsplit(".", 1)[1]))
        name = key.split(".", 1)[1]
        unit = "rad" if name in _ANGLES else "length"
        quantity = Quantity(unit, state.units, length_step(length_scale(state.robot)))
        return act.SetReachTarget(name, read_number(event, quantity, name))
