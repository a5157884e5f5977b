"""Opening the DH table from the module list: convert the robot, or start a new table.

The panel asks (inline, under the mode selector): **convert this robot to DH rows** with
the core's :func:`~robotconf.modules_to_dh` in the chosen convention — which refuses,
with the module and the reason, a chain that is no DH chain (the message shows in the
row) — or **start a new DH table**, one revolute row. Either way the module robot can be
brought back with undo.
"""

from __future__ import annotations

from collections.abc import Callable

import ipywidgets as widgets

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
    >>> entry.ask("modified")
    >>> entry.prompt.buttons["convert"].click()
    >>> [(link.d, link.a) for link in loaded[0].modules]
    [(20.0, 0.0), (0.0, 30.0)]
    >>> entry.ask("standard")
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
            extra=[self.convention],
        )
        self.widget = self.prompt.widget

    def ask(self, convention: str) -> None:
        """Show the question, with ``convention`` preselected."""
        self.convention.value = convention
        self.prompt.ask("Open the DH table:")

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
