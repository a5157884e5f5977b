"""The header row: undo and redo, degrees or radians, the cell's length unit, capsules.

Keys: ``undo``, ``redo``, ``angle_unit``, ``length_unit``, ``capsules``.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ...panel.form import Form, FormEvent, button, check, message, row, select, text, toggle
from ...panel.state import LENGTH_UNITS
from .. import actions as act
from ..state import DesignerState
from ._messages import Messages

__all__ = ["HeaderView"]

_ANGLES = (("deg", True, "angles in degrees"), ("rad", False, "angles in radians"))


class HeaderView:
    """Undo, redo and the units, over every tab.

    Parameters
    ----------
    dispatch : callable
        ``dispatch(action_or_error, key, typed=None)``.
    undo, redo : callable
        The designer's own.
    can : callable
        ``() -> (can_undo, can_redo)``.
    """

    def __init__(
        self,
        dispatch: Callable[..., None],
        undo: Callable[[], None],
        redo: Callable[[], None],
        can: Callable[[], tuple[bool, bool]],
    ) -> None:
        self._dispatch = dispatch
        self._undo, self._redo, self._can = undo, redo, can
        self.form = Form(self._event, css_class="robotconf-cell-header")

    def render(self, state: DesignerState, messages: Messages, rev: str) -> None:
        """Draw the row from the state."""
        can_undo, can_redo = self._can()
        unit = state.units.length
        units = list(LENGTH_UNITS) + ([unit] if unit not in LENGTH_UNITS else [])
        notes = [messages.text(k) for k in ("undo", "length_unit", "angle_unit", "capsules")]
        self.form.show(
            [
                row(
                    "header",
                    [
                        button(
                            "undo",
                            "↶",
                            title="undo",
                            disabled=not can_undo,
                            css_class="robotconf-undo",
                        ),
                        button(
                            "redo",
                            "↷",
                            title="redo",
                            disabled=not can_redo,
                            css_class="robotconf-redo",
                        ),
                        toggle(
                            "angle_unit",
                            state.degrees,
                            _ANGLES,
                            rev=rev,
                            css_class="robotconf-angle-unit",
                        ),
                        select(
                            "length_unit",
                            unit,
                            [(u, u) for u in units],
                            label="length",
                            rev=rev,
                            width="80px",
                            title="the cell's length unit: a name, no number changes",
                        ),
                        check(
                            "capsules",
                            state.capsules,
                            "link capsules",
                            title="what collisions are checked with",
                            rev=rev,
                        ),
                        text(_counts(state), tone="note"),
                    ],
                    note=message("; ".join(n for n in notes if n)),
                )
            ]
        )

    def _event(self, event: FormEvent) -> None:
        key = event.key
        action: Any = None
        if key == "undo":
            self._undo()
            return
        if key == "redo":
            self._redo()
            return
        if key == "angle_unit":
            action = act.SetAngleUnit(bool(event.value))
        elif key == "length_unit":
            action = act.SetLengthUnit(str(event.value))
        elif key == "capsules":
            action = act.ShowCapsules(bool(event.value))
        self._dispatch(action, key)


def _counts(state: DesignerState) -> str:
    """``2 robots, 3 objects, 1 frame``: what the cell holds."""
    items = state.cell.items
    counts = [(sum(i.kind == kind for i in items), kind) for kind in ("robot", "object", "frame")]
    return ", ".join(f"{n} {kind}{'s' if n != 1 else ''}" for n, kind in counts)
