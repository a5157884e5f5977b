"""The Reach tab's closed-form solutions: one button per branch, and why there are none.

The solutions come from the core alone (:func:`robotconf.ik_all`, family from
:func:`robotconf.inverse_kinematics.recognize`); this module only words the cases around them — no
closed form for this geometry, a family that needs a pose while the tab asks for a point,
a target out of reach — and lists the branches as buttons, flagged when a branch lies
outside the joint limits and highlighted when the robot stands on it.
"""

from __future__ import annotations

import functools
import html
from collections.abc import Callable
from dataclasses import dataclass

import ipywidgets as widgets
import numpy as np

from .._errors import InvalidInputError
from ..inverse_kinematics import IKSolutions, ik_all, recognize
from ..kinematics import Robot, characteristic_length
from ._callbacks import on_click
from ._errors_display import ErrorLabel
from ._units import ANGLE_UNIT, Units

__all__ = ["ClosedForm", "closed_form", "SolutionList", "same_configuration"]

#: Coordinates closer than this (rad, or a fraction of the robot's size) are one pose.
SAME_Q = 1e-6


@dataclass(frozen=True)
class ClosedForm:
    """What the closed forms say about one target.

    Attributes
    ----------
    family : str or None
        The robot's closed-form family, ``None`` when it has none.
    solutions : IKSolutions or None
        Every branch (``None`` when none could be asked for).
    note : str
        Why there is no branch, or what is special about them; ``""`` otherwise.
    """

    family: str | None
    solutions: IKSolutions | None
    note: str

    @property
    def count(self) -> int:
        """How many branches there are."""
        return 0 if self.solutions is None else len(self.solutions)


def closed_form(robot: Robot, target: np.ndarray) -> ClosedForm:
    """Every closed-form solution of ``target`` for ``robot``, with a sentence around them.

    Parameters
    ----------
    robot : Robot
    target : ndarray, shape (3,) or (4, 4)
        A point or a pose (length units, base frame).

    Returns
    -------
    ClosedForm

    Examples
    --------
    >>> import robotconf as rc
    >>> found = closed_form(rc.preset("planar_2r", l1=1, l2=1), np.array([1.0, 1.0, 0.0]))
    >>> found.family, found.solutions.labels
    ('planar 2R', ('elbow down', 'elbow up'))
    >>> closed_form(rc.preset("puma560"), np.array([0.3, 0.2, 0.4])).note
    'a spherical-wrist 6R arm has closed-form solutions for a pose: choose pose to see them'
    """
    family = recognize(robot)
    if family is None:
        return ClosedForm(None, None, "no closed form for this geometry: the numeric solver only")
    try:
        solutions = ik_all(robot, target)
    except InvalidInputError as error:
        if error.field == "target" and np.shape(target) == (3,):
            # The family needs an orientation (a 6R arm) or the tool's angle (planar 3R).
            note = f"a {family} arm has closed-form solutions for a pose: choose pose to see them"
            return ClosedForm(family, None, note)
        return ClosedForm(family, None, str(error))
    return ClosedForm(family, solutions, solutions.reason)


def same_configuration(robot: Robot, a: np.ndarray, b: np.ndarray) -> bool:
    """Whether two coordinate vectors are one pose of ``robot`` (angles modulo a turn).

    >>> import robotconf as rc
    >>> arm = rc.preset("planar_2r", l1=1, l2=1)
    >>> same_configuration(arm, np.array([np.pi, 0.0]), np.array([-np.pi, 0.0]))
    True
    """
    revolute = np.array([link.unit == ANGLE_UNIT for link in robot.modules])
    gap = np.asarray(a, dtype=float) - np.asarray(b, dtype=float)
    gap = np.where(revolute, np.remainder(gap + np.pi, 2 * np.pi) - np.pi, gap)
    size = characteristic_length(robot)
    return bool(np.all(np.abs(gap) <= np.where(revolute, SAME_Q, SAME_Q * size)))


def _q_text(robot: Robot, q: np.ndarray, units: Units) -> str:
    values = []
    for link, value in zip(robot.modules, q, strict=True):
        values.append(f"{units.to_shown(float(value), link.unit):.4g}")
    unit = units.angle if any(link.unit == ANGLE_UNIT for link in robot.modules) else ""
    return f"q = ({', '.join(values)})" + (f" [{unit}]" if unit else "")


class SolutionList:
    """The closed-form branches as buttons, under a heading with the family's name.

    Parameters
    ----------
    on_pick : callable
        ``on_pick(i)`` when branch ``i`` is clicked.

    Attributes
    ----------
    buttons : list of ipywidgets.Button
        One per branch, described by its label (``"shoulder left, elbow up, …"``).
    note : ipywidgets.HTML
        The family, and why there is no branch (or what is special about them).

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.preset("planar_2r", l1=1, l2=1)
    >>> picked = []
    >>> found = closed_form(arm, np.array([1.0, 1.0, 0.0]))
    >>> solutions = SolutionList(picked.append)
    >>> solutions.show(arm, found, Units())
    >>> [button.description for button in solutions.buttons]
    ['elbow down', 'elbow up']
    >>> solutions.buttons[1].click(); picked
    [1]
    """

    def __init__(self, on_pick: Callable[[int], None]):
        self._on_pick = on_pick
        self.found: ClosedForm | None = None
        self.buttons: list[widgets.Button] = []
        self._pool: list[widgets.Button] = []
        self.heading = widgets.HTML("<b>Closed-form solutions</b>")
        self.note = widgets.HTML()
        self.note.add_class("robotconf-reach-note")
        self.error = ErrorLabel()
        self._box = widgets.Box(layout=widgets.Layout(flex_flow="row wrap"))
        self.widget = widgets.VBox([self.heading, self.note, self._box, self.error.widget])

    def show(self, robot: Robot, found: ClosedForm, units: Units) -> None:
        """List the branches of ``found`` (q in the panel's ``units`` in each tooltip)."""
        self.found = found
        solutions = found.solutions
        family = f" of a {html.escape(found.family)} arm" if found.family else ""
        self.heading.value = f"<b>Closed-form solutions{family}</b>: {found.count}"
        self.note.value = f"<small>{html.escape(found.note)}</small>" if found.note else ""
        branches = (
            []
            if solutions is None
            else list(zip(solutions.labels, solutions.q, solutions.within_limits, strict=True))
        )
        while len(self._pool) < len(branches):  # buttons are reused: a drag makes none
            self._pool.append(self._button(len(self._pool)))
        for button, (label, row, ok) in zip(self._pool, branches, strict=False):
            button.description = label
            button.tooltip = _q_text(robot, row, units) + (
                "" if ok else " — outside the joint limits"
            )
            # Greyed and flagged, still clickable: the panel never enforces ranges on q.
            button.icon = "" if ok else "exclamation-triangle"
            button.style.text_color = "" if ok else "#888888"
            if ok:
                button.remove_class("robotconf-reach-outside")
            else:
                button.add_class("robotconf-reach-outside")
        self.buttons = self._pool[: len(branches)]
        self._box.children = tuple(self.buttons)

    def _button(self, index: int) -> widgets.Button:
        button = widgets.Button(layout=widgets.Layout(width="auto", margin="2px 4px 2px 0"))
        button.add_class("robotconf-reach-solution")
        on_click(button, self.error, functools.partial(self._on_pick, index))
        return button

    def mark(self, robot: Robot) -> None:
        """Highlight the button of the branch the robot stands on (if any)."""
        solutions = None if self.found is None else self.found.solutions
        if solutions is None:
            return
        for button, row in zip(self.buttons, solutions.q, strict=True):
            on = robot.n == row.size and same_configuration(robot, robot.q, row)
            button.button_style = "info" if on else ""
