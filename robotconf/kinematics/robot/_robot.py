"""A serial robot: an ordered chain of links plus an end-effector point."""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_configuration, check_integer, one_line
from ..conventions._bounds import MAX_PARAMETER, check_parameter_vector
from ..conventions._names import check_name
from ..kernel._geometry import LinkGeometry
from ..links._dh import check_convention, dh_link_from_row
from ..links._limits import chain_length
from ..links._link import Link
from ._chain import RobotChain, _check_links
from ._snapshot import RobotSnapshot

if TYPE_CHECKING:
    from ...signals import Signal

__all__ = ["Robot", "characteristic_length"]


class Robot(RobotChain):
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

    __slots__ = ()

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
