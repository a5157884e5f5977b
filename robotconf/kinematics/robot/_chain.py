"""The chain a robot stores, and what the kernel computes from it.

:class:`RobotChain` is the part of :class:`~robotconf.kinematics.Robot` that holds the
links, the end-effector point and the number of active modules, describes them (names,
:meth:`~RobotChain.index`) and runs the kernel over them (frames, origins, end effector,
the snapshot at one configuration, joint ranges). :class:`~robotconf.kinematics.Robot`
adds construction and editing, the Jacobian and files.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

from ..._budget import check_memory
from ..._errors import InvalidInputError
from ..._validation import check_configuration, check_integer, check_joint_values, one_line
from ..conventions._bounds import MAX_MODULES
from ..conventions._names import check_module_names
from ..kernel._geometry import LinkGeometry
from ..kernel._kernel import (
    chain_origins,
    chain_point,
    chain_point_pose,
    chain_poses,
    kernel_bytes,
    link_matrices,
)
from ..links._limits import chain_limits
from ..links._link import Link
from ._snapshot import RobotSnapshot, chain_snapshot

__all__ = ["RobotChain"]


def _check_links(modules: Any) -> tuple[Link, ...]:
    if isinstance(modules, (str, bytes, Link)) or not isinstance(modules, Iterable):
        raise InvalidInputError(
            "modules",
            one_line(modules),
            "a list of Module or DHLink objects",
            problem="not a list:",
        )
    allowed = f"at least one Module or DHLink, and at most {MAX_MODULES}"
    links = []
    for i, link in enumerate(modules):
        if i == MAX_MODULES:  # stop reading: the list may be huge (or endless)
            raise InvalidInputError(
                "modules", f"<more than {MAX_MODULES} links>", allowed, problem="too many:"
            )
        if not isinstance(link, Link):
            raise InvalidInputError(
                f"modules[{i}]", one_line(link), "a Module or DHLink", problem="not a link:"
            )
        links.append(link)
    if not links:
        raise InvalidInputError("modules", [], allowed, problem="empty:")
    check_module_names([link.name for link in links])
    return tuple(links)


class RobotChain:
    """The stored chain of a :class:`~robotconf.kinematics.Robot` and its kinematics.

    Not made directly: every robot is one (``Robot`` derives from it), so its methods are
    documented with the robot's.
    """

    __slots__ = ("_links", "_end_effector", "_active", "_name", "_geometry", "_at", "_shape")

    _links: tuple[Link, ...]
    _end_effector: tuple[float, float, float]
    _active: int | None
    _name: str | None
    _geometry: tuple[LinkGeometry | None, ...]
    _at: RobotSnapshot | None
    _shape: dict[str, Any]

    # -- description --------------------------------------------------------------------

    @property
    def modules(self) -> tuple[Link, ...]:
        """The links, base first."""
        return self._links

    @property
    def n(self) -> int:
        """Number of modules (and of generalized coordinates)."""
        return len(self._links)

    @property
    def active(self) -> int:
        """Number of active modules: modules after this many act as identity."""
        return self.n if self._active is None else self._active

    @property
    def name(self) -> str | None:
        """The robot's name, if it has one."""
        return self._name

    @property
    def end_effector_point(self) -> np.ndarray:
        """The end-effector point ``(Px, Py, Pz)`` in the last frame, shape (3,)."""
        return np.array(self._end_effector)

    @property
    def q(self) -> np.ndarray:
        """The modules' own coordinates, shape (n,)."""
        return np.array([link.q for link in self._links])

    @property
    def module_names(self) -> tuple[str, ...]:
        """Display names: a module's own name, else ``M1, M2, …`` as in the paper."""
        return tuple(link.name or f"M{i + 1}" for i, link in enumerate(self._links))

    @property
    def coordinate_names(self) -> tuple[str, ...]:
        """Generalized coordinate names ``q1, q2, …``."""
        return tuple(f"q{i + 1}" for i in range(self.n))

    def index(self, key: Any, field: str = "index", *, end_effector: bool = False) -> int:
        """The 0-based position of a module (and of its coordinate), however it is named.

        The one place that answers "which module": every function that takes a module or a
        coordinate by name or number asks the robot.

        Parameters
        ----------
        key : int or str
            A 0-based index ``0 … n−1``; a module's display name (``"M2"``, or its own
            name); or a coordinate name (``"q2"``, any case). A module may not be named
            after another module's coordinate or ``"EE"``, so no key means two things.
        field : str
            Name used in the error message.
        end_effector : bool
            Also accept ``"EE"`` (any case), which gives ``n``.

        Returns
        -------
        int

        Raises
        ------
        InvalidInputError
            For an unknown name, an index out of range or another type.

        Examples
        --------
        >>> from robotconf.kinematics import Module, Robot
        >>> robot = Robot([Module("Rz"), Module("Ry", name="shoulder")])
        >>> robot.index(1), robot.index("shoulder"), robot.index("Q2"), robot.index("M1")
        (1, 1, 1, 0)
        >>> robot.index("EE", "frame", end_effector=True)
        2
        >>> robot.index("elbow")
        Traceback (most recent call last):
        ...
        robotconf.InvalidInputError: index: unknown module 'elbow'; allowed: an index 0 to 1, ...
        """
        names = self.module_names
        allowed = (
            f"an index 0 to {self.n - 1}, a module name ({', '.join(names)}) or a coordinate "
            f"name (q1 to q{self.n})" + (", or 'EE' (the end-effector)" if end_effector else "")
        )
        if isinstance(key, str):
            if key in names:
                return names.index(key)
            label = key.strip().lower()
            if label in self.coordinate_names:
                return self.coordinate_names.index(label)
            if end_effector and label == "ee":
                return self.n
            raise InvalidInputError(field, key, allowed, problem="unknown module")
        return check_integer(key, field, 0, self.n - 1, what=allowed)

    @property
    def joint_types(self) -> tuple[str, ...]:
        """Each link's joint type: revolute, prismatic, none or fixed."""
        return tuple(link.joint_type for link in self._links)

    def geometry(self) -> tuple[LinkGeometry | None, ...]:
        """Kernel descriptions of the links; ``None`` where a module is inactive."""
        return self._geometry

    def __repr__(self) -> str:
        inner = ",\n".join(f"    {link!r}" for link in self._links)
        text = f"Robot([\n{inner},\n], end_effector={self._end_effector!r}"
        if self._active is not None:
            text += f", active={self._active!r}"
        if self._name is not None:
            text += f", name={self._name!r}"
        return text + ")"

    def __str__(self) -> str:
        title = self._name or "Robot"
        lines = [f"{title}: {self.n} modules, {self.active} active, EE = {self._end_effector}"]
        for i, (label, link) in enumerate(zip(self.module_names, self._links, strict=True)):
            state = "" if i < self.active else "  (inactive)"
            lines.append(f"  {label}: {link!r}{state}")
        return "\n".join(lines)

    def _repr_pretty_(self, printer: Any, cycle: bool) -> None:
        printer.text(str(self) if not cycle else "Robot(...)")

    # -- kinematics ---------------------------------------------------------------------

    def _coordinates(self, q: Any) -> tuple[np.ndarray, bool]:
        if q is None:
            return self.q[np.newaxis, :], False
        return check_joint_values(q, self.n, self.coordinate_names)

    def _compute(
        self, kernel: Any, floats: int, q: Any, out: np.ndarray | None, *args: Any
    ) -> np.ndarray:
        """Run a kernel; ``floats`` is the size of its result per sample."""
        values, batched = self._coordinates(q)
        if out is None:
            # A q given as a list or as integers was converted: that copy is alive too.
            given = isinstance(q, np.ndarray) and q.dtype == np.float64
            converted = 0.0 if q is None or given else 8.0 * values.size
            check_memory(
                "q",
                one_line(q),
                kernel_bytes(values.shape[0], self.n, floats) + converted,
                "fewer samples per call (split q into chunks), or a larger memory budget",
            )
        elif not batched:
            # A single configuration writes into out as a one-sample batch.
            out = out[np.newaxis] if isinstance(out, np.ndarray) else out
        # The modules' own q are bounded (MAX_PARAMETER), so an overflow, which the kernel
        # refuses naming q[i], can only come from a q given here.
        result = kernel(self._geometry, values, *args, out=out)
        return result if batched else result[0]

    def at(self, q: Any = None) -> RobotSnapshot:
        """The robot at one configuration, computed once: frames, end effector, joint axes
        and labelled points from a single kernel pass (what a picture of it needs).

        Parameters
        ----------
        q : array-like, shape (n,), optional
            Coordinates (radians for rotations, length for translations); default: the
            modules' own ``q``, whose snapshot is made once and kept by the robot.

        Returns
        -------
        RobotSnapshot
            Its numbers equal those of :meth:`frame_poses`, :meth:`end_effector`,
            :meth:`end_effector_pose`, :func:`~robotconf.joint_axes` and
            :func:`~robotconf.robot_points` at ``q``, bit for bit.

        Raises
        ------
        InvalidInputError
            For a bad ``q`` or a trajectory (one configuration only).

        Examples
        --------
        >>> from robotconf import Module, Robot
        >>> arm = Robot([Module("Rz"), Module("Rz", a=(1, 0, 0))], end_effector=(1, 0, 0))
        >>> at = arm.at([np.pi / 2, -np.pi / 2])
        >>> at.end_effector.round(12) + 0.0, at.frame_origins[1].round(12) + 0.0
        (array([1., 1., 0.]), array([0., 1., 0.]))
        """
        if q is None and self._at is not None:
            return self._at
        values = self.q if q is None else check_configuration(q, self.n, self.coordinate_names)
        poses, tip = chain_snapshot(
            self._geometry, values[np.newaxis], np.array(self._end_effector)
        )
        snapshot = RobotSnapshot(self, values, poses, tip)
        if q is None:
            # The robot is immutable: every view of it at its own q shares one kernel pass.
            self._at = snapshot
        return snapshot

    def transfer_matrices(self, q: Any = None, *, out: np.ndarray | None = None) -> np.ndarray:
        """Each module's transfer matrix ``A_i(q_i)`` (identity when inactive).

        Parameters
        ----------
        q : array-like, shape (n,) or (T, n), optional
            Coordinates (radians for rotations, length for translations); default: the
            modules' own ``q``.
        out : ndarray, shape (n, 4, 4) or (T, n, 4, 4), optional
            Preallocated float64 result, e.g. reused across the frames of an animation.

        Returns
        -------
        ndarray, shape (n, 4, 4) or (T, n, 4, 4)

        Examples
        --------
        >>> from robotconf import Module, Robot
        >>> robot = Robot([Module("Tz", a=(1, 0, 0)), Module("Rz")])
        >>> robot.transfer_matrices([0.5, 0.0])[0]
        array([[1. , 0. , 0. , 1. ],
               [0. , 1. , 0. , 0. ],
               [0. , 0. , 1. , 0.5],
               [0. , 0. , 0. , 1. ]])
        """
        return self._compute(link_matrices, 16 * self.n, q, out)

    def frame_poses(self, q: Any = None, *, out: np.ndarray | None = None) -> np.ndarray:
        """Cumulative matrices ``M_i = A_1·A_2⋯A_i``: each module frame in the base frame.

        Parameters
        ----------
        q : array-like, shape (n,) or (T, n), optional
            Coordinates; default: the modules' own ``q``.
        out : ndarray, shape (n, 4, 4) or (T, n, 4, 4), optional
            Preallocated float64 result.

        Returns
        -------
        ndarray, shape (n, 4, 4) or (T, n, 4, 4)
            Vectorized over ``T`` (no Python loop over samples).

        Raises
        ------
        InvalidInputError
            ``q`` for coordinates that are not finite real numbers or have the wrong
            shape, or when the result would not fit the memory budget (about ``128·n``
            bytes per sample, see :func:`robotconf.set_memory_budget`); ``q[i]`` when a
            prismatic coordinate near ``1e308`` pushes a frame past the float range. The
            other kinematics methods raise the same errors.

        Examples
        --------
        A slide along x followed by a quarter turn about z: the second frame sits where the
        slide put it, with its x axis along the base y axis.

        >>> from robotconf import Module, Robot
        >>> robot = Robot([Module("Tx"), Module("Rz", a=(0, 0, 1))])
        >>> robot.frame_poses([2.0, np.pi / 2])[1].round(12) + 0.0
        array([[ 0., -1.,  0.,  2.],
               [ 1.,  0.,  0.,  0.],
               [ 0.,  0.,  1.,  1.],
               [ 0.,  0.,  0.,  1.]])
        >>> robot.frame_poses(np.zeros((500, 2))).shape
        (500, 2, 4, 4)
        """
        return self._compute(chain_poses, 16 * self.n, q, out)

    def frame_origins(self, q: Any = None, *, out: np.ndarray | None = None) -> np.ndarray:
        """Origins of the module frames in the base frame (where the paper draws spheres).

        Parameters
        ----------
        q : array-like, shape (n,) or (T, n), optional
        out : ndarray, shape (n, 3) or (T, n, 3), optional
            Preallocated float64 result.

        Returns
        -------
        ndarray, shape (n, 3) or (T, n, 3)
            Length units; computed without building 4×4 stacks.
        """
        return self._compute(chain_origins, 3 * self.n, q, out)

    def end_effector(self, q: Any = None, *, out: np.ndarray | None = None) -> np.ndarray:
        """End-effector position ``p_EE = M_n · [Px, Py, Pz, 1]ᵀ`` in the base frame.

        Parameters
        ----------
        q : array-like, shape (n,) or (T, n), optional
        out : ndarray, shape (3,) or (T, 3), optional
            Preallocated float64 result.

        Returns
        -------
        ndarray, shape (3,) or (T, 3)
            Computed without building 4×4 stacks.

        Examples
        --------
        >>> from robotconf import Module, Robot
        >>> arm = Robot([Module("Rz"), Module("Rz", a=(1, 0, 0))], end_effector=(1, 0, 0))
        >>> arm.end_effector([np.pi / 2, -np.pi / 2]).round(12) + 0.0
        array([1., 1., 0.])
        """
        return self._compute(chain_point, 3, q, out, np.array(self._end_effector))

    def end_effector_pose(self, q: Any = None, *, out: np.ndarray | None = None) -> np.ndarray:
        """Pose of the end-effector: ``M_n`` with the EE point as its origin.

        Parameters
        ----------
        q : array-like, shape (n,) or (T, n), optional
        out : ndarray, shape (4, 4) or (T, 4, 4), optional
            Preallocated float64 result.

        Returns
        -------
        ndarray, shape (4, 4) or (T, 4, 4)

        Examples
        --------
        >>> from robotconf import Module, Robot
        >>> robot = Robot([Module("Rz", a=(0, 0, 2))], end_effector=(1, 0, 0))
        >>> robot.end_effector_pose([0.0])[:3, 3]
        array([1., 0., 2.])
        """
        return self._compute(chain_point_pose, 16, q, out, np.array(self._end_effector))

    # -- joint ranges -------------------------------------------------------------------

    def joint_limits(self) -> np.ndarray:
        """The range ``(lo, hi)`` of every coordinate, shape (n, 2).

        A link's own ``limits`` where given; otherwise the documented defaults
        (docs/conventions.md, "Joint ranges"): revolute ``(−π, π)``; prismatic ``(−L, L)``
        with ``L`` = :func:`characteristic_length`; ``none`` and ``fixed`` ``(0, 0)``.

        Returns
        -------
        ndarray, shape (n, 2)
            Radians for revolute rows, length units for prismatic rows.

        Examples
        --------
        >>> from robotconf.kinematics import Module, Robot
        >>> modules = [Module("Rz", limits=(-1, 1)), Module("Tz", a=(0, 0, 20))]
        >>> robot = Robot([*modules, Module("fixed")], end_effector=(40, 0, 0))
        >>> robot.joint_limits()
        array([[ -1.,   1.],
               [-60.,  60.],
               [  0.,   0.]])
        """
        limits = self._shape.get("limits")
        if limits is None:
            limits = self._shape["limits"] = chain_limits(self._links, self._end_effector)
        return limits.copy()
