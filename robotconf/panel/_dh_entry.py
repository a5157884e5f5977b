"""Opening the DH table from the module list: convert the robot, or start a new table.

The panel asks (inline, under the mode selector): **convert this robot to DH rows** with
the core's :func:`~robotconf.modules_to_dh` in the chosen convention — which refuses,
with the module and the reason, a chain that is no DH chain (the message shows in the
row) — or **start a new DH table**, one revolute row. Either way the module robot can be
brought back with undo.

The convention preselected is the one the robot converts in: the DH table's first, else
the other one (a module offset before its joint, as in the paper's arm, only has a
modified-DH frame), and the row says which and why. A robot neither holds keeps the
table's convention; "convert" then shows the core's reason.
"""

from __future__ import annotations

import html
from collections.abc import Callable

import ipywidgets as widgets

from .._errors import InvalidInputError
from ..kinematics import DH_CONVENTIONS, DHLink, Robot
from ._choice_prompt import ChoicePrompt
from ._conversions import to_dh
from ._ranges import length_scale

__all__ = ["DHEntry"]

Order = list[int | None]


class DHEntry:
    """The question asked when the DH table is chosen for a module robot.

    Parameters
    ----------
    robot : callable
        Returns the panel's current robot.
    load : callable
        ``load(robot, order)``: show the new robot (``order`` as in ``_conversions``).

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.Robot([rc.Module("Rz", a=(0, 0, 20)), rc.Module("Rz", a=(30, 0, 0))])
    >>> loaded = []
    >>> entry = DHEntry(lambda: arm, lambda robot, order: loaded.append(robot))
    >>> entry.ask("standard")  # the table's convention cannot hold the offset before M2's joint
    >>> entry.convention.value
    'modified'
    >>> entry.prompt.buttons["convert"].click()
    >>> [(link.d, link.a) for link in loaded[0].modules]
    [(20.0, 0.0), (0.0, 30.0)]
    >>> entry.ask("standard")
    >>> entry.convention.value = "standard"  # the student's choice, for a new table too
    >>> entry.prompt.buttons["new"].click()
    >>> loaded[1].modules
    (DHLink(theta=0.0, d=0.0, a=5.0, alpha=0.0, joint='R', convention='standard'),)
    """

    def __init__(self, robot: Callable[[], Robot], load: Callable[[Robot, Order], None]):
        self._robot = robot
        self._load = load
        self.convention = widgets.Dropdown(
            options=DH_CONVENTIONS, value=DH_CONVENTIONS[0], layout=widgets.Layout(width="110px")
        )
        # Why this convention is preselected: the student may pick the other one anyway.
        self.note = widgets.HTML(layout=widgets.Layout(margin="0 6px"))
        self.note.add_class("robotconf-dh-entry-note")
        self.prompt = ChoicePrompt(
            [
                (
                    "convert",
                    "convert this robot to DH rows",
                    "the same robot as a DH table, when its modules follow the DH pattern",
                ),
                (
                    "new",
                    "start a new DH table",
                    "one revolute row; undo brings the module robot back",
                ),
            ],
            self._answered,
            extra=[self.convention, self.note],
        )
        self.widget = self.prompt.widget

    def ask(self, convention: str) -> None:
        """Show the question, with the convention the robot converts in preselected.

        ``convention`` (the DH table's) is tried first, then the other one; when neither
        holds the robot, ``convention`` stays (and "convert" says why).
        """
        chosen, note = self._preselect(convention)
        self.convention.value = chosen
        self.note.value = html.escape(note, quote=False)  # the core's text names user modules
        self.prompt.ask("Open the DH table:")

    def _preselect(self, convention: str) -> tuple[str, str]:
        """The convention to preselect and the sentence that says why."""
        robot = self._robot()
        refused: list[tuple[str, InvalidInputError]] = []
        for candidate in (convention, *(c for c in DH_CONVENTIONS if c != convention)):
            try:
                to_dh(robot, candidate)
            except InvalidInputError as error:
                refused.append((candidate, error))
                continue
            if not refused:
                return candidate, f"(the table's convention, {candidate} DH, holds this robot)"
            why = "; ".join(f"{name} DH cannot hold it: {_reason(e)}" for name, e in refused)
            return candidate, f"({candidate} DH preselected, as {why})"
        return convention, "(neither DH convention holds this robot: convert says why)"

    def close(self) -> None:
        """Hide the question."""
        self.prompt.close()

    def _answered(self, answer: str) -> None:
        robot = self._robot()
        convention = self.convention.value
        if answer == "convert":
            self._load(*to_dh(robot, convention))
            return
        # A tenth of the robot's size, so the new link is visible at the old scale.
        row = DHLink(a=length_scale(robot) / 10.0, convention=convention)
        self._load(Robot([row], end_effector=robot.end_effector_point), [None])


def _reason(error: InvalidInputError) -> str:
    """The core's first clause of why a module breaks the DH pattern (no value dump)."""
    return error.problem.split(";")[0].rstrip(" :,")
