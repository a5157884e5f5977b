"""The reach map's controls: on/off, the robot, the region's two corners, the step, and
what the map found (how many voxels the robot reaches).

Keys: ``reach.on``, ``reach.robot``, ``reach.low0`` … ``reach.low2``, ``reach.high0`` …
``reach.high2``, ``reach.step``, ``reach.update``. A refusal (too many voxels, a high
corner below the low one) is said beside the control; the last map stays.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ..._errors import InvalidInputError
from ...panel.form import Form, FormEvent, button, check, message, row, select, text
from .. import actions as act
from ..state import DesignerState
from ._boxes import LENGTH, box, core_value
from ._messages import Messages

__all__ = ["ReachView", "reach_summary"]

_KEYS = ("reach.on", "reach.robot", "reach.step", "reach.update", "reach.low", "reach.high")


def reach_summary(state: DesignerState) -> tuple[str, str]:
    """``(text, tone)`` of the line under the controls: the count, or why there is none.

    >>> reach_summary(DesignerState())
    ('Switch the map on to see which points the robot reaches (a voxel grid).', 'note')
    """
    outcome = state.reach_map
    if not state.reach.on or outcome is None:
        return "Switch the map on to see which points the robot reaches (a voxel grid).", "note"
    result = outcome.result
    count, total = int(result.reachable.sum()), len(result.points)
    most = int(result.branches.max()) if total else 0
    robots = state.cell.robots
    robot = outcome.setup.robot or (robots[0] if robots else "?")
    line = (
        f"{robot} reaches {count} of {total} voxels (green; up to {most} collision-free branches)"
    )
    if outcome.stale(state.cell):
        return line + ": the cell changed since this map, press update", "warning"
    return line, "ok"


class ReachView:
    """The Reach map tab."""

    def __init__(self, dispatch: Callable[..., None]) -> None:
        self._dispatch = dispatch
        self._state: DesignerState | None = None
        self.form = Form(self._event, css_class="robotconf-cell-reach")

    def render(self, state: DesignerState, messages: Messages, rev: str, step: float) -> None:
        """Draw the controls with the region the map uses (the defaults until typed)."""
        self._state = state
        units = state.units
        robots = state.cell.robots
        if not robots:
            self.form.show(
                [
                    row(
                        "reach",
                        [text("Add a robot first: the map shows its reach.", tone="note")],
                    )
                ]
            )
            return
        robot, low, high, grid = act.reach_region(state, state.reach)

        def corner(name: str, values: tuple[float, float, float]) -> list[dict[str, Any]]:
            return [
                box(
                    f"reach.{name}{k}",
                    v,
                    LENGTH,
                    units,
                    messages,
                    rev,
                    step=step,
                    title=f"{name} corner {a}",
                )
                for k, (v, a) in enumerate(zip(values, "xyz", strict=True))
            ]

        summary, tone = reach_summary(state)
        notes = [messages.text(k) for k in _KEYS]
        notes += [messages.text(f"reach.{c}{k}") for c in ("low", "high") for k in range(3)]
        self.form.show(
            [
                row(
                    "reach",
                    [
                        check(
                            "reach.on",
                            state.reach.on,
                            "reach map",
                            rev=rev,
                            css_class="robotconf-reach-on",
                        ),
                        select(
                            "reach.robot",
                            robot,
                            [(r, r) for r in robots],
                            label="robot",
                            rev=rev,
                            width="120px",
                        ),
                        button(
                            "reach.update",
                            "update",
                            title="compute the map again for the cell as it is",
                            rev=rev,
                        ),
                    ],
                    [text(f"low corner [{units.length}]", tone="note"), *corner("low", low)],
                    [text(f"high corner [{units.length}]", tone="note"), *corner("high", high)],
                    [
                        text(f"step [{units.length}]", tone="note"),
                        box(
                            "reach.step",
                            grid,
                            LENGTH,
                            units,
                            messages,
                            rev,
                            step=step,
                            title="voxel size",
                        ),
                        text(
                            f"{act.voxel_count(low, high, grid)} voxels "
                            f"(at most {act.MAX_DESIGNER_VOXELS})",
                            tone="note",
                        ),
                    ],
                    [
                        text(
                            summary,
                            tone=tone,
                            key="reach.summary",
                            css_class="robotconf-reach-summary",
                        )
                    ],
                    note=message("; ".join(n for n in notes if n)),
                )
            ]
        )

    def _event(self, event: FormEvent) -> None:
        key = event.key
        state = self._state
        if state is None:
            return
        try:
            action = self._action(state, key, event)
        except InvalidInputError as error:
            self._dispatch(error, key, event.text)
            return
        self._dispatch(action, key, event.text)

    @staticmethod
    def _action(state: DesignerState, key: str, event: FormEvent) -> Any:
        if key == "reach.on":
            return act.SetReachMap(bool(event.value))
        if key == "reach.robot":
            return act.SetReachRobot(str(event.value))
        if key == "reach.update":
            return act.UpdateReachMap()
        if key == "reach.step":
            return act.SetReachStep(core_value(event, LENGTH, state.units, "reach.step"))
        for corner, name in enumerate(("low", "high")):
            if key.startswith(f"reach.{name}"):
                axis = int(key[-1])
                value = core_value(event, LENGTH, state.units, f"reach.{name}")
                return act.SetReachCorner(corner, axis, value)
        return None
