"""Lengths gone wrong as a whole: the point's homogeneous coordinate, mm against m.

``p_EE = M_n·[Px, Py, Pz, 1]ᵀ``: with 0 instead of 1 the product only turns P and leaves
out the origin of the last frame (the translation column of ``M_n``). And a length taken
in millimetres where the exercise works in metres (or the reverse) is 1000 times off:
all lengths, or one module's offset, one DH parameter or the end-effector point.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from ...kinematics import DHLink, Module
from ._candidate import NAMED, Candidate, module_label
from ._context import MistakeContext

__all__ = ["point_candidates", "unit_candidates"]

#: A length typed in millimetres where metres are meant is 1000 times too large.
_FACTORS = {1000.0: "1000 times too large", 0.001: "1000 times too small"}
_UNIT_GUESS = {
    1000.0: "millimetres where the exercise's data are in metres?",
    0.001: "metres where the exercise's data are in millimetres?",
}


def point_candidates(context: MistakeContext) -> list[Candidate]:
    """``M_n·[Px, Py, Pz, 0]ᵀ`` for ``p_EE``: the homogeneous coordinate 0 instead of 1.

    Two versions: with the fourth entry 1 (a student giving three coordinates) and 0 (one
    giving all four).

    Parameters
    ----------
    context : MistakeContext

    Returns
    -------
    list of Candidate
        Code ``"homogeneous_coordinate"``; empty for other steps than ``p_EE``.

    Examples
    --------
    >>> from robotconf.kinematics import Robot
    >>> from robotconf.teaching import expected_matrix, sample_points
    >>> robot = Robot([Module("Rz", a=(30, 0, 20))], end_effector=(40, 0, 0))
    >>> context = MistakeContext(expected_matrix(robot, "p_EE", q=[0]), {"q1": np.zeros(1)}, 1)
    >>> point_candidates(context)[0].values[0, :, 0]
    array([40.,  0.,  0.,  1.])
    """
    if context.name != "p_EE":
        return []
    n = context.robot.n
    message = (
        f"You multiplied M{n} by [Px, Py, Pz, 0]ᵀ: a point's homogeneous coordinate is 1 (0 "
        f"is for a direction, which only turns), so the origin of the last frame — the last "
        f"column of M{n} — is missing from p_EE = M{n}·[Px, Py, Pz, 1]ᵀ."
    )
    reading = "multiplying by [Px, Py, Pz, 0]ᵀ (homogeneous coordinate 0)"
    direction = context.value(weight=0.0)
    three = direction.copy()
    three[:, 3, 0] = 1.0
    return [
        Candidate("homogeneous_coordinate", message, three, reading),
        Candidate("homogeneous_coordinate", message, direction, reading),
    ]


def _scaled_link(link: Any, factor: float, parameter: str | None) -> Any:
    if isinstance(link, Module):
        return link.with_a(np.asarray(link.a) * factor)
    names = ("d", "a") if parameter is None else (parameter,)
    return link.with_parameters(**{name: getattr(link, name) * factor for name in names})


def _editor(factor: float, module: int | None, parameter: str | None) -> Callable[[Any], Any]:
    """Robot → robot with one length group (``module`` None: the point) scaled."""

    def edit(robot: Any) -> Any:
        if module is None:
            return robot.with_end_effector(np.asarray(robot.end_effector_point) * factor)
        return robot.with_module(module, _scaled_link(robot.modules[module], factor, parameter))

    return edit


def _everything(factor: float) -> Callable[[Any], Any]:
    def edit(robot: Any) -> Any:
        links = [_scaled_link(link, factor, None) for link in robot.modules]
        point = np.asarray(robot.end_effector_point) * factor
        return type(robot)(links, end_effector=point, active=robot.active, name=robot.name)

    return edit


def _groups(context: MistakeContext) -> list[tuple[int | None, str | None, str]]:
    """The length groups of the step: ``(module, DH parameter, words)``; module None: P."""
    robot = context.robot
    groups: list[tuple[int | None, str | None, str]] = []
    for j in context.modules:
        link = robot.modules[j]
        if isinstance(link, Module) and link.kind != "none" and any(link.a):
            groups.append((j, None, f"The offset of {module_label(j + 1, link)} is"))
        elif isinstance(link, DHLink):
            for parameter, words in (("d", "The link offset d"), ("a", "The link length a")):
                if getattr(link, parameter) != 0:
                    groups.append((j, parameter, f"{words} of {module_label(j + 1, link)} is"))
    if context.name == "p_EE" and any(robot.end_effector_point):
        groups.append((None, None, "The end-effector point P is"))
    return groups


def unit_candidates(context: MistakeContext) -> list[Candidate]:
    """Lengths 1000 times too large or too small: all of them, or one length group.

    Parameters
    ----------
    context : MistakeContext

    Returns
    -------
    list of Candidate
        Code ``"unit_slip"``; none when the lengths are the symbols ``l1, l2, …``.

    Examples
    --------
    >>> from robotconf.kinematics import Robot
    >>> from robotconf.teaching import expected_matrix
    >>> robot = Robot([Module("Rz", a=(0, 0, 0.5))], end_effector=(0.2, 0, 0))
    >>> context = MistakeContext(expected_matrix(robot, "p_EE", q=[0]), {"q1": np.zeros(1)}, 1)
    >>> [c.values[0, 2, 0] for c in unit_candidates(context)][:2]
    [np.float64(500.0), np.float64(0.0005)]
    """
    if not context.numeric_lengths:
        return []
    groups = _groups(context)
    candidates = []
    for factor, size in _FACTORS.items():
        for module, parameter, words in groups:
            message = f"{words} {size}: {_UNIT_GUESS[factor]} Keep the unit of the exercise."
            values = context.value(edit=_editor(factor, module, parameter))
            candidates.append(Candidate("unit_slip", message, values, "", NAMED))
    everything = []
    if len(groups) >= 2:
        joints = context.joints()
        prismatic = [j for j in joints if context.robot.joint_types[j] == "prismatic"]
        for factor, size in _FACTORS.items():
            q = context.q.copy()
            if context.numeric_q:  # a numeric slide is a length too
                q[:, prismatic] *= factor
            message = (
                f"All your lengths are {size}: {_UNIT_GUESS[factor]} Keep the unit of the exercise."
            )
            values = context.value(q=q, edit=_everything(factor))
            everything.append(Candidate("unit_slip", message, values, "", NAMED))
    return everything + candidates
