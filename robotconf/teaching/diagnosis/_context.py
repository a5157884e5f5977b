"""A robot's derivation step evaluated with a mistake made, at the checker's sample points.

A mistake is a change to the robot (a missing offset, lengths in the wrong unit), to a
link's matrix (the joint turning the wrong way, the offset after the rotation), to the
configuration (q = 0, one joint left out) or to how the matrices are put together (the
wrong order, the point's homogeneous coordinate). :class:`MistakeContext` evaluates the
step ``A_i``, ``M_i`` or ``p_EE`` with any such change, in numpy; the mistake families
build their candidates from it.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Mapping
from functools import reduce
from typing import Any

import numpy as np

from ...kinematics import AXIS_NAMES, Module
from ..derivation._expected import ExpectedMatrix

__all__ = ["LINK_CODES", "MistakeContext", "link_matrix", "link_mistakes"]

#: Link mistakes reported under a shared code (the rest are their own code).
LINK_CODES = {
    "missing_d": "missing_offset",
    "missing_a": "missing_offset",
    "alpha_sign": "sign_error",
}

_UNITS: dict[str, Callable[[Any], Any]] = {"degrees": np.degrees, "radians": np.radians}
_CONSTANT_UNITS: dict[str, Callable[[float], float]] = {
    "degrees": math.degrees,
    "radians": math.radians,
}


def link_mistakes(link: Any) -> list[str]:
    """The slips a single link invites, by name (see :func:`link_matrix`).

    Parameters
    ----------
    link : Module or DHLink

    Returns
    -------
    list of str

    Examples
    --------
    >>> link_mistakes(Module("Ry", a=(0, 0, 20)))
    ['rotation_direction', 'offset_after_rotation', 'missing_offset']
    """
    revolute = link.joint_type == "revolute"
    # A module and a DH row invite different mistakes (an offset vs. the four parameters).
    if isinstance(link, Module):
        found = []
        if revolute:
            found.append("rotation_direction")
            if any(link.a):
                found.append("offset_after_rotation")
        if link.kind != "none" and any(link.a):
            found.append("missing_offset")
        return found
    found = ["rotation_direction"] if revolute else []
    found += ["missing_d"] if link.d != 0 else []
    found += ["missing_a"] if link.a != 0 else []
    found += ["alpha_sign"] if link.alpha != 0 else []
    found += ["swapped_d_a"] if revolute and link.d != link.a else []
    return found


def _translation(a: Any) -> np.ndarray:
    matrix = np.eye(4)
    matrix[:3, 3] = a
    return matrix


def link_matrix(
    link: Any,
    q: np.ndarray,
    mistake: str | None = None,
    units: str | None = None,
    angles: str = "all",
) -> np.ndarray:
    """A link's matrices at the coordinates ``q`` as they come out with ``mistake`` made.

    Parameters
    ----------
    link : Module or DHLink
    q : ndarray, shape (m,)
        Coordinate values (radians or length).
    mistake : str, optional
        One of :func:`link_mistakes`, or ``"convention"`` (the other DH convention).
    units : {"degrees", "radians"}, optional
        Angles reinterpreted in these units: ``"degrees"`` reads a value in degrees as if
        it were radians (``cos(30)``), ``"radians"`` the reverse (a calculator in degree
        mode).
    angles : {"all", "joints", "constants"}
        Which angles ``units`` applies to: the joint coordinate, the DH row's constant
        θ and α, or both.

    Returns
    -------
    ndarray, shape (m, 4, 4)

    Examples
    --------
    >>> link_matrix(Module("Rz"), np.array([0.5]), "rotation_direction")[0, 0, 1].round(4)
    np.float64(0.4794)
    """
    to_units = _UNITS.get(units or "")
    if to_units is not None and angles != "constants" and link.joint_type == "revolute":
        q = to_units(q)
    if isinstance(link, Module):
        if mistake == "rotation_direction":
            return link.matrix(-q)
        if mistake == "missing_offset":
            return link.with_a((0.0, 0.0, 0.0)).matrix(q)
        if mistake == "offset_after_rotation":
            return link.with_a((0.0, 0.0, 0.0)).matrix(q) @ _translation(link.a)
        return link.matrix(q)
    changes: dict[str, Any] = {}
    constant_units = _CONSTANT_UNITS.get(units or "")
    if constant_units is not None and angles != "joints":
        changes["theta"] = constant_units(link.theta)
        changes["alpha"] = constant_units(link.alpha)
    if mistake == "rotation_direction":
        changes["theta"] = -changes.get("theta", link.theta)
        q = -q
    if mistake == "missing_d":
        changes["d"] = 0.0
    if mistake == "missing_a":
        changes["a"] = 0.0
    if mistake == "alpha_sign":
        changes["alpha"] = -changes.get("alpha", link.alpha)
    if mistake == "swapped_d_a":
        changes["d"], changes["a"] = link.a, link.d
    if mistake == "convention":
        changes["convention"] = "modified" if link.convention == "standard" else "standard"
    return dataclasses.replace(link, **changes).matrix(q) if changes else link.matrix(q)


class MistakeContext:
    """The expected step of a robot, ready to be evaluated with mistakes made.

    Parameters
    ----------
    expected : ExpectedMatrix
        With robot and name (``has_context``).
    env : dict of str to ndarray, shape (K,)
        The sample points (values of ``q1 …`` and, with ``lengths``, of ``l1 …``).
    k : int
        K.

    Attributes
    ----------
    robot : Robot
    expected : ExpectedMatrix
    name : str
        ``"A<i>"``, ``"M<i>"`` or ``"p_EE"``.
    q : ndarray, shape (K, n)
        The configuration at each point: the numbers of the exercise, or the samples.
    numeric_q : bool
        Whether the exercise gives ``q`` as numbers (then degrees, the parking pose and
        unit slips of prismatic joints apply to it).
    numeric_lengths : bool
        Whether the lengths are numbers (not the symbols ``l1, l2, …``).
    """

    def __init__(self, expected: ExpectedMatrix, env: dict[str, np.ndarray], k: int) -> None:
        robot = expected.robot
        name = expected.name
        assert robot is not None and name is not None
        self.robot = robot
        self.expected = expected
        self.name = name
        self.k = k
        self.numeric_q = expected.q is not None
        self.numeric_lengths = not expected.lengths
        self._robots = [robot]
        self._links: dict[tuple[Any, ...], np.ndarray] = {}
        if expected.lengths:
            from ..derivation._symbolic_chain import symbolic_chain

            places = symbolic_chain(robot, lengths=True, simplify=False).length_places
            self._robots = [self._with_lengths(places, env, i) for i in range(k)]
        if expected.q is not None:
            self.q = np.tile(np.asarray(expected.q, dtype=float), (k, 1))
        else:
            self.q = np.column_stack([env[name] for name in robot.coordinate_names])
        index = expected.index or 1
        last = index if name.startswith(("A", "M")) else robot.n
        first = index if name.startswith("A") else 1
        #: 0-based modules the step depends on (the active ones among them).
        self.modules = range(first - 1, min(last, robot.active))
        self._count = last

    def _with_lengths(self, places: list, env: dict, i: int) -> Any:
        robot = self.robot
        labels = list(robot.module_names)
        links = list(robot.modules)
        point = list(robot.end_effector_point)
        for label, name, symbol in places:
            if symbol.name not in env:  # a length this matrix does not depend on
                continue
            value = float(env[symbol.name][i])
            if label == "EE":  # the point's coordinates are named Px, Py, Pz
                point[AXIS_NAMES.index(name[1])] = value
                continue
            j = labels.index(label)
            links[j] = links[j].with_parameters(**{name: value})
        return type(robot)(links, end_effector=point, active=robot.active, name=robot.name)

    def joints(self) -> list[int]:
        """0-based modules of the step that have a joint (revolute or prismatic)."""
        kinds = ("revolute", "prismatic")
        return [j for j in self.modules if self.robot.modules[j].joint_type in kinds]

    def value(
        self,
        mistakes: Mapping[int, str] | None = None,
        units: str | None = None,
        angles: str = "all",
        reverse: bool = False,
        point: Any = None,
        weight: float = 1.0,
        q: np.ndarray | None = None,
        edit: Callable[[Any], Any] | None = None,
    ) -> np.ndarray:
        """The expected step's value with the given mistakes, shape (K, rows, cols).

        Parameters
        ----------
        mistakes : dict of int to str, optional
            A link mistake (see :func:`link_matrix`) by 0-based module index.
        units, angles
            Angles reinterpreted, as in :func:`link_matrix`; with ``q`` as symbols
            ``"all"`` means the constant angles only.
        reverse : bool
            The product taken in the reverse order (``A_i ⋯ A_1``).
        point : array-like, shape (3,), optional
            The end-effector point used instead of the robot's.
        weight : float
            The point's homogeneous coordinate (1 for a point, 0 for a direction).
        q : ndarray, shape (K, n), optional
            Another configuration.
        edit : callable Robot -> Robot, optional
            A change to the robot (e.g. lengths in other units).
        """
        q = self.q if q is None else q
        if units is not None and not self.numeric_q and angles == "all":
            angles = "constants"  # a symbol q has no units to mistake
        robots = [edit(r) for r in self._robots] if edit is not None else self._robots
        options = (dict(mistakes or {}), units, angles, reverse, point, weight, edit is None)
        if len(robots) == 1:
            if np.all(q == q[:1]):  # numbers of the exercise: one evaluation does for all
                return np.repeat(self._step(0, robots[0], q[:1], *options), self.k, axis=0)
            return self._step(0, robots[0], q, *options)
        return np.concatenate(
            [self._step(i, r, q[i : i + 1], *options) for i, r in enumerate(robots)]
        )

    def _step(
        self,
        which: int,
        robot: Any,
        q: np.ndarray,
        mistakes: dict[int, str],
        units: str | None,
        angles: str,
        reverse: bool,
        point: Any,
        weight: float,
        own_robot: bool,
    ) -> np.ndarray:
        m = q.shape[0]

        def matrix(j: int) -> np.ndarray:
            if j >= robot.active:
                return np.broadcast_to(np.eye(4), (m, 4, 4))
            mistake = mistakes.get(j)
            if mistake is not None or not own_robot:
                return link_matrix(robot.modules[j], q[:, j], mistake, units, angles)
            # Most mistakes change one link: the others are the same in every candidate.
            key = (which, j, units, angles, q[:, j].tobytes())
            if key not in self._links:
                self._links[key] = link_matrix(robot.modules[j], q[:, j], None, units, angles)
            return self._links[key]

        if self.name.startswith("A"):
            return np.array(matrix(self._count - 1))  # a copy: the cache stays as it is
        used = [matrix(j) for j in range(self._count)]
        pose = np.array(reduce(np.matmul, used[::-1] if reverse else used))
        if self.name != "p_EE":
            return pose
        where = robot.end_effector_point if point is None else np.asarray(point, dtype=float)
        return (pose @ np.append(where, weight))[:, :, np.newaxis]
