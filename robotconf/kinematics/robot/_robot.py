"""A serial robot: an ordered chain of links plus an end-effector point."""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..._budget import check_memory
from ..._errors import InvalidInputError
from ..._validation import check_configuration, check_integer, check_joint_values, one_line
from ..conventions._bounds import MAX_MODULES, MAX_PARAMETER, check_parameter_vector
from ..conventions._names import check_module_names, check_name
from ..kernel._geometry import LinkGeometry
from ..kernel._kernel import (
    chain_origins,
    chain_point,
    chain_point_pose,
    chain_poses,
    kernel_bytes,
    link_matrices,
)
from ..links._dh import check_convention, dh_link_from_row
from ..links._limits import chain_length, chain_limits
from ..links._link import Link
from ._snapshot import RobotSnapshot, chain_snapshot

if TYPE_CHECKING:
    from ...signals import Signal

__all__ = ["Robot", "characteristic_length"]


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


class Robot:
    """A serial robot: links (modules or DH rows) and an end-effector point.

    Immutable: every ``with_…`` method returns a new robot, so an editor can always keep
    the last valid one.

    Every module has a unique display name — its own ``name``, else ``M1, M2, …`` by
    position — because modules are looked up (:meth:`index`), plotted and labelled by it.
    A robot refuses two modules with the same name (the error names both indices), a
    module named like another module's default (``"M2"`` while the second module is
    unnamed), like another module's coordinate (``"q2"``) or like the end-effector
    (``"EE"``). Rename one of them, or leave it unnamed.

    Parameters
    ----------
    modules : sequence of Module or DHLink, length 1 ≤ n ≤ 64
        The chain from the base ``[T0]`` outwards; modules and DH links may be mixed.
    end_effector : array-like, shape (3,)
        The end-effector point ``P = (Px, Py, Pz)`` in the last module's frame (length),
        each ``|P| ≤ 1e150`` (:data:`~robotconf.kinematics.MAX_PARAMETER`).
    active : int, optional
        The paper's "number of active modules" ``k`` (1 ≤ k ≤ n): modules after the k-th
        act as identity. Default: all.
    name : str, optional
        At most 200 characters.

    Raises
    ------
    InvalidInputError
        For an empty or non-link module list or more than 64 links (``modules``), module
        names that clash (``modules[i].name``), a bad end-effector point, ``active`` out
        of range or a name that is not text or too long.

    Examples
    --------
    The paper's validation robot R_zR_yR_y (l1 = 20, l2 = 30, l3 = 40):

    >>> from robotconf import Module
    >>> robot = Robot(
    ...     [Module("Rz"), Module("Ry", a=(0, 0, 20)), Module("Ry", a=(30, 0, 0))],
    ...     end_effector=(40, 0, 0),
    ... )
    >>> robot.frame_origins([0, 0, 0])
    array([[ 0.,  0.,  0.],
           [ 0.,  0., 20.],
           [30.,  0., 20.]])
    >>> robot.end_effector([0, 0, 0])
    array([70.,  0., 20.])
    >>> robot.frame_poses(np.zeros((1000, 3))).shape
    (1000, 3, 4, 4)

    Two modules may not share a name:

    >>> Robot([Module("Rz", name="base"), Module("Ry", name="base")])
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: modules[1].name: modules[0] and modules[1] are both named ...
    """

    __slots__ = ("_links", "_end_effector", "_active", "_name", "_geometry", "_at", "_shape")

    def __init__(
        self,
        modules: Sequence[Link],
        end_effector: Any = (0.0, 0.0, 0.0),
        active: int | None = None,
        name: str | None = None,
    ):
        links = _check_links(modules)
        point = check_parameter_vector(end_effector, "end_effector")
        if active is not None:
            allowed = f"an integer from 1 to {len(links)}, or None for all"
            active = check_integer(active, "active", 1, len(links), allowed)
        check_name(name)
        self._links = links
        self._end_effector = point
        self._active = active
        self._name = name
        self._geometry: tuple[LinkGeometry | None, ...] = tuple(
            link.geometry() if i < self.active else None for i, link in enumerate(links)
        )
        self._at: RobotSnapshot | None = None
        # Facts that do not depend on q (size, joint ranges), shared by with_q's copies.
        self._shape: dict[str, Any] = {}

    # -- construction -------------------------------------------------------------------

    @classmethod
    def from_dh(
        cls,
        rows: Iterable[Any],
        convention: str = "standard",
        end_effector: Any = (0.0, 0.0, 0.0),
        name: str | None = None,
    ) -> Robot:
        """A robot from a Denavit–Hartenberg table.

        Parameters
        ----------
        rows : iterable of (theta, d, a, alpha, joint), dicts with those keys, or DHLink
            Angles in radians, lengths in length units; ``joint`` is ``"R"`` (q adds to θ)
            or ``"P"`` (q adds to d). Dict rows may also give ``q``, ``name``, ``limits``.
        convention : {"standard", "modified"}
            ``standard``: ``Rz(θ)·Tz(d)·Tx(a)·Rx(α)``; ``modified`` (Craig):
            ``Rx(α)·Tx(a)·Rz(θ)·Tz(d)``. Applies to every tuple or dict row.
        end_effector : array-like, shape (3,)
            Point in the last frame.
        name : str, optional

        Returns
        -------
        Robot

        Examples
        --------
        A planar 2R arm with unit links at q = (90°, 0):

        >>> arm = Robot.from_dh([(0, 0, 1, 0, "R"), (0, 0, 1, 0, "R")])
        >>> arm.end_effector([np.pi / 2, 0]).round(12)
        array([0., 2., 0.])
        """
        convention = check_convention(convention)
        if isinstance(rows, (str, bytes, Mapping)) or not isinstance(rows, Iterable):
            raise InvalidInputError(
                "rows",
                one_line(rows),
                "a list of DH rows (theta, d, a, alpha, joint)",
                problem="not a list:",
            )
        links = [dh_link_from_row(row, convention, i) for i, row in enumerate(rows)]
        if not links:
            raise InvalidInputError("rows", [], "at least one DH row", problem="empty:")
        return cls(links, end_effector=end_effector, name=name)

    def _replace(self, **changes: Any) -> Robot:
        return Robot(
            changes.get("modules", self._links),
            end_effector=changes.get("end_effector", self._end_effector),
            active=changes.get("active", self._active),
            name=changes.get("name", self._name),
        )

    def with_q(self, q: Any) -> Robot:
        """A copy whose modules hold the coordinates ``q``, shape (n,).

        Only ``q`` is checked (once, for all modules): the links are otherwise the same,
        so a slider drag costs one validation, not a rebuilt robot.

        >>> from robotconf import Module
        >>> robot = Robot([Module("Rz"), Module("Tz")]).with_q([0.5, 2.0])
        >>> robot.q
        array([0.5, 2. ])
        """
        values = check_configuration(q, self.n, self.coordinate_names)
        too_large = np.flatnonzero(np.abs(values) > MAX_PARAMETER)
        if too_large.size:  # the link's own check names the bound
            i = int(too_large[0])
            try:
                self._links[i].with_q(float(values[i]))
            except InvalidInputError as error:
                raise error.within(f"modules[{i}]") from None
        links = tuple(
            link if link.q == v else link.with_checked_q(float(v))
            for link, v in zip(self._links, values.tolist(), strict=True)
        )
        robot = object.__new__(Robot)
        robot._links = links
        robot._end_effector = self._end_effector
        robot._active = self._active
        robot._name = self._name
        robot._geometry = self._geometry  # q-independent: the same kernel description
        robot._at = None
        robot._shape = self._shape
        return robot

    def with_module(self, index: int, module: Link) -> Robot:
        """A copy with module ``index`` (0-based) replaced."""
        i = check_integer(index, "index", 0, self.n - 1)
        links = list(self._links)
        links[i] = module
        return self._replace(modules=links)

    def with_inserted(self, index: int, module: Link) -> Robot:
        """A copy with ``module`` inserted before position ``index`` (``n`` appends)."""
        i = check_integer(index, "index", 0, self.n)
        links = list(self._links)
        links.insert(i, module)
        active = None if self._active is None else self._active + (i < self._active)
        return self._replace(modules=links, active=active)

    def with_appended(self, module: Link) -> Robot:
        """A copy with ``module`` added at the end of the chain."""
        return self.with_inserted(self.n, module)

    def with_removed(self, index: int) -> Robot:
        """A copy without module ``index``; a robot keeps at least one module."""
        i = check_integer(index, "index", 0, self.n - 1)
        if self.n == 1:
            raise InvalidInputError(
                "index",
                i,
                "removing only when more than one module remains",
                problem="cannot remove the last module:",
            )
        links = list(self._links)
        del links[i]
        active = self._active
        if active is not None:
            active = max(1, min(active - (i < active), len(links)))
        return self._replace(modules=links, active=active)

    def with_moved(self, index: int, new_index: int) -> Robot:
        """A copy with module ``index`` moved to ``new_index`` (move up/down in an editor)."""
        i = check_integer(index, "index", 0, self.n - 1)
        j = check_integer(new_index, "new_index", 0, self.n - 1)
        links = list(self._links)
        links.insert(j, links.pop(i))
        return self._replace(modules=links)

    def with_end_effector(self, point: Any) -> Robot:
        """A copy with another end-effector point ``(Px, Py, Pz)``."""
        return self._replace(end_effector=point)

    def with_active(self, active: int | None) -> Robot:
        """A copy with another number of active modules (``None``: all)."""
        return self._replace(active=active)

    def with_name(self, name: str | None) -> Robot:
        """A copy with another name."""
        return self._replace(name=name)

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
        >>> from robotconf.kinematics import Module
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

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Robot):
            return NotImplemented
        return (
            self._links == other._links
            and self._end_effector == other._end_effector
            and self.active == other.active
            and self._name == other._name
        )

    def __hash__(self) -> int:
        return hash((self._links, self._end_effector, self.active, self._name))

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
        >>> from robotconf import Module
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
        >>> from robotconf import Module
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

        >>> from robotconf import Module
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
        >>> from robotconf import Module
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
        >>> from robotconf import Module
        >>> robot = Robot([Module("Rz", a=(0, 0, 2))], end_effector=(1, 0, 0))
        >>> robot.end_effector_pose([0.0])[:3, 3]
        array([1., 0., 2.])
        """
        return self._compute(chain_point_pose, 16, q, out, np.array(self._end_effector))

    def jacobian(self, q: Any = None, frame: Any = None) -> np.ndarray:
        """Geometric Jacobian of a module frame's origin or of the end-effector.

        Parameters
        ----------
        q : array-like, shape (n,) or (T, n), optional
            Coordinates; default: the modules' own ``q``.
        frame : int, str or None
            ``None`` or ``"EE"``: the end-effector; ``0 … n−1`` or a module name (``"M2"``).

        Returns
        -------
        ndarray, shape (6, n) or (T, 6, n)
            Linear rows first (length/s per unit q̇), then angular (rad/s), base frame.

        See Also
        --------
        robotconf.jacobian : the same as a function.

        Examples
        --------
        >>> from robotconf import Module
        >>> arm = Robot([Module("Rz")], end_effector=(2, 0, 0))
        >>> arm.jacobian([0.0])[:, 0]
        array([0., 2., 0., 0., 0., 1.])
        """
        from ..quantities._jacobian import jacobian  # the Jacobian module takes a Robot

        return jacobian(self, q, frame)

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
        >>> from robotconf.kinematics import Module
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

    def with_limits(self, index_or_name: Any, limits: Any) -> Robot:
        """A copy where one link has the range ``limits`` (``None``: back to the default).

        Parameters
        ----------
        index_or_name : int or str
            Which link, as :meth:`index` reads it: ``1``, ``"M2"``, ``"q2"``.
        limits : None or (lo, hi)
            Radians for revolute, length units for prismatic joints; ``lo < hi``.

        Examples
        --------
        >>> from robotconf.kinematics import Module
        >>> robot = Robot([Module("Rz"), Module("Ry")]).with_limits("M2", (0, 1.5))
        >>> robot.joint_limits()[1]
        array([0. , 1.5])
        """
        i = self.index(index_or_name)
        try:
            changed = self._links[i].with_limits(limits)
        except InvalidInputError as error:
            raise error.within(f"modules[{i}]") from None
        return self.with_module(i, changed)

    # -- files (the file format reads and writes robots, so it is imported on use) ------

    def to_json(
        self,
        *,
        signals: Mapping[str, Signal] | None = None,
        simulation: Any = None,
        indent: int | None = 2,
    ) -> str:
        """The robot (and optional signals and run settings) as robotconf JSON text.

        Parameters
        ----------
        signals : dict, optional
            Coordinate name (``"q3"``) → signal, stored with the robot.
        simulation : dict or SimulationSettings, optional
            ``t_end`` (required), ``dt``, ``t0``, ``method``.
        indent : int or None
            JSON indentation; ``None`` for one line.

        Returns
        -------
        str
            Versioned JSON (docs/file-format.md); :meth:`from_json` reads it back exactly.

        Examples
        --------
        >>> from robotconf.kinematics import Module
        >>> robot = Robot([Module("Rz", limits=(-1, 1))], end_effector=(0.1, 0, 0))
        >>> Robot.from_json(robot.to_json()) == robot
        True
        """
        from ...io import Setup

        return Setup(self, signals or {}, simulation).to_json(indent)

    @classmethod
    def from_json(cls, text: str) -> Robot:
        """A robot from robotconf JSON text (everything in it is validated).

        Examples
        --------
        >>> text = '{"format": "robotconf", "version": 1, "robot": {"links": [{"type": "module", '
        >>> text += '"kind": "Rz", "limits": [-1, 1]}], "end_effector": [2, 0, 0]}}'
        >>> Robot.from_json(text)
        Robot([
            Module('Rz', limits=(-1.0, 1.0)),
        ], end_effector=(2.0, 0.0, 0.0))
        """
        from ...io import Setup

        return Setup.from_json(text).robot

    def save(
        self,
        path: str | os.PathLike[str],
        *,
        signals: Mapping[str, Signal] | None = None,
        simulation: Any = None,
    ) -> Path:
        """Write :meth:`to_json` to ``path`` (UTF-8) and return the path.

        Examples
        --------
        >>> import tempfile
        >>> from robotconf.io import load
        >>> from robotconf.kinematics import Module
        >>> robot = Robot([Module("Rz"), Module("Rz", a=(1, 0, 0))], end_effector=(1, 0, 0))
        >>> with tempfile.TemporaryDirectory() as folder:
        ...     load(robot.save(folder + "/arm.json")) == robot
        True
        """
        from ...io import Setup

        return Setup(self, signals or {}, simulation).save(path)

    def to_urdf(self, name: str | None = None, **options: Any) -> str:
        """The robot as URDF text (kinematics only); see :func:`robotconf.to_urdf`.

        >>> from robotconf import Module
        >>> "<joint name=\\"q1\\" type=\\"revolute\\">" in Robot([Module("Rz")]).to_urdf()
        True
        """
        from ...io import to_urdf

        return to_urdf(self, name, **options)


def characteristic_length(robot: Robot) -> float:
    """The robot's size L: the default stroke of a prismatic joint is ``(−L, L)``.

    ``L`` is the sum of the constant lengths along the chain — ``|a|`` of each module,
    ``√(a² + d²)`` of each DH row (its ``d`` only when revolute, as a prismatic ``d`` is
    the coordinate's zero point) — plus ``|P|`` of the end-effector point; ``1.0`` when all
    of these are zero (a chain of bare joints).

    Examples
    --------
    >>> from robotconf.kinematics import Module
    >>> robot = Robot([Module("Rz"), Module("Tz", a=(0, 0, 20))], end_effector=(40, 0, 0))
    >>> characteristic_length(robot)
    60.0
    """
    shape = robot._shape
    length = shape.get("length")
    if length is None:
        length = shape["length"] = chain_length(robot.modules, robot.end_effector_point)
    return float(length)
