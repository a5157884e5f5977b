"""The Reach tab's closed-form solutions, and why there are none.

The solutions come from the core alone (:func:`robotconf.ik_all`, family from
:func:`robotconf.inverse_kinematics.recognize`); this module only words the cases around
them: no closed form for this geometry, a family that needs a pose while the tab asks for
a point, a target out of reach.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..._errors import InvalidInputError
from ...inverse_kinematics import IKSolutions, ik_all, recognize
from ...kinematics import Robot, characteristic_length
from ..state import Units

ANGLE_UNIT = "rad"

__all__ = ["ClosedForm", "closed_form", "same_configuration", "q_text"]

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


def q_text(robot: Robot, q: np.ndarray, units: Units) -> str:
    """A branch's q in the panel's units, for its tooltip."""
    values = []
    for link, value in zip(robot.modules, q, strict=True):
        values.append(f"{units.to_shown(float(value), link.unit):.4g}")
    unit = units.angle if any(link.unit == ANGLE_UNIT for link in robot.modules) else ""
    return f"q = ({', '.join(values)})" + (f" [{unit}]" if unit else "")
