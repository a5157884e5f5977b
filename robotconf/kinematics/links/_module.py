"""The paper's module: a movement type, offsets ``a`` and a generalized coordinate ``q``."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import one_line
from ..conventions._bounds import check_parameter, check_parameter_vector
from ..conventions._conventions import (
    AXIS_NAMES,
    JOINT_LETTERS,
    KIND_ALIASES,
    MODULE_CODES,
    MODULE_KINDS,
    MODULE_OFFSETS,
    kind_axis,
    kind_joint_type,
)
from ..conventions._names import check_name
from ..kernel._geometry import LinkGeometry
from ._limits import check_link_limits
from ._link import Link

__all__ = ["Module", "kind_name", "transfer_matrix"]

_NAMES = {name.lower(): name for name in MODULE_KINDS}
_NAMES.update({alias.lower(): kind for alias, kind in KIND_ALIASES.items()})
_ALLOWED = ", ".join(
    f"{kind} ({MODULE_CODES[kind]})" if kind in MODULE_CODES else kind for kind in MODULE_KINDS
)
_LAST_CODE = len(MODULE_CODES) - 1


def kind_name(kind: Any) -> str:
    """Canonical name of a movement type given by name (any case) or paper code 0–6.

    Parameters
    ----------
    kind : str or int
        ``"none"`` (alias ``"null"``), ``"Rx"``, ``"Ry"``, ``"Rz"``, ``"Tx"``, ``"Ty"``,
        ``"Tz"``, ``"fixed"``, or the paper's code 0–6.

    Returns
    -------
    str
        One of :data:`MODULE_KINDS`.

    Raises
    ------
    InvalidInputError
        For an unknown name, a code outside 0–6, or another type.

    Examples
    --------
    >>> kind_name("rz"), kind_name(2), kind_name("NULL")
    ('Rz', 'Ry', 'none')
    >>> kind_name(7)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: kind: unknown movement code 7; allowed: none (0), Rx (1), ...
    """
    if isinstance(kind, str):
        name = _NAMES.get(kind.strip().lower())
        if name is None:
            raise InvalidInputError("kind", kind, _ALLOWED, problem="unknown movement type")
        return name
    if isinstance(kind, (int, np.integer)) and not isinstance(kind, (bool, np.bool_)):
        if 0 <= int(kind) <= _LAST_CODE:
            return MODULE_KINDS[int(kind)]
        raise InvalidInputError(
            "kind", one_line(int(kind)), _ALLOWED, problem="unknown movement code"
        )
    raise InvalidInputError(
        "kind", one_line(kind), _ALLOWED, problem="expected a name or a code 0-6, got"
    )


@dataclass(frozen=True)
class Module(Link):
    """One module of a modular serial robot (the paper's "kinematic couple").

    The transfer matrix translates by ``a`` in the parent frame, then moves by ``q``
    about or along the module's own axis (docs/conventions.md, paper eq. 11–16). A ``none``
    module is the identity; a ``fixed`` module is the pure offset ``a``.

    Parameters
    ----------
    kind : str or int
        Movement type: ``"none"``, ``"Rx"``, ``"Ry"``, ``"Rz"``, ``"Tx"``, ``"Ty"``,
        ``"Tz"`` (any case) or the paper's code 0–6; or ``"fixed"``.
    a : array-like, shape (3,)
        Offset ``(ax, ay, az)`` of this module's frame origin in the preceding frame
        (length units), each ``|ax| ≤ 1e150`` (:data:`MAX_PARAMETER`).
    q : float
        Generalized coordinate: radians for rotations, length for translations; ignored
        by ``none`` and ``fixed``. ``|q| ≤ 1e150``.
    name : str, optional
        Display name, at most 200 characters; the robot calls unnamed modules
        ``M1, M2, …``.
    limits : (lo, hi), optional
        Range of ``q`` (radians for rotations, length for translations), ``lo < hi``;
        only for joints. ``None``: the robot's default (see :meth:`Robot.joint_limits`).
        Not enforced on ``q``.

    Raises
    ------
    InvalidInputError
        On an unknown kind, a malformed, non-real or non-finite ``a`` or ``q`` or one
        above ``1e150`` in magnitude, a name that is not text or too long, or a
        malformed range or a range on a ``none``/``fixed`` module.

    Examples
    --------
    >>> m = Module("Ry", a=(0, 0, 20))
    >>> m
    Module('Ry', a=(0.0, 0.0, 20.0))
    >>> m.code, m.joint_type, m.axis
    (2, 'revolute', 'y')
    >>> m.matrix(np.pi / 2).round(12)
    array([[ 0.,  0.,  1.,  0.],
           [ 0.,  1.,  0.,  0.],
           [-1.,  0.,  0., 20.],
           [ 0.,  0.,  0.,  1.]])
    >>> Module("Tz", limits=(0, 50))
    Module('Tz', limits=(0.0, 50.0))
    """

    kind: str
    a: tuple[float, float, float] = (0.0, 0.0, 0.0)
    q: float = 0.0
    name: str | None = field(default=None)
    limits: tuple[float, float] | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "kind", kind_name(self.kind))
        object.__setattr__(self, "a", check_parameter_vector(self.a, "a"))
        object.__setattr__(self, "q", check_parameter(self.q, "q"))
        check_name(self.name)
        object.__setattr__(self, "limits", check_link_limits(self.limits, self.joint_type))

    def __repr__(self) -> str:
        parts = [repr(self.kind)]
        if self.a != (0.0, 0.0, 0.0):
            parts.append(f"a={self.a!r}")
        if self.q != 0.0:
            parts.append(f"q={self.q!r}")
        if self.name is not None:
            parts.append(f"name={self.name!r}")
        if self.limits is not None:
            parts.append(f"limits={self.limits!r}")
        return f"Module({', '.join(parts)})"

    @property
    def code(self) -> int | None:
        """The paper's movement code 0–6 (``None`` for ``fixed``, which the paper lacks)."""
        return MODULE_CODES.get(self.kind)

    @property
    def joint_type(self) -> str:
        """``"revolute"``, ``"prismatic"``, ``"none"`` or ``"fixed"``."""
        return kind_joint_type(self.kind)

    @property
    def axis(self) -> str | None:
        """``"x"``, ``"y"`` or ``"z"`` for a joint; ``None`` for ``none`` and ``fixed``."""
        axis = kind_axis(self.kind)
        return None if axis is None else AXIS_NAMES[axis]

    def parameters(self) -> dict[str, float]:
        """The offsets by name: ``{"ax": …, "ay": …, "az": …}`` (length units).

        >>> Module("Ry", a=(0, 0, 20)).parameters()
        {'ax': 0.0, 'ay': 0.0, 'az': 20.0}
        """
        return dict(zip(MODULE_OFFSETS, self.a, strict=True))

    def with_parameters(self, **changes: float) -> Module:
        """A copy with some offsets changed by name (``ax``, ``ay``, ``az``).

        >>> Module("Ry", a=(0, 0, 20)).with_parameters(ax=5)
        Module('Ry', a=(5.0, 0.0, 20.0))
        """
        unknown = sorted(set(changes) - set(MODULE_OFFSETS))
        if unknown:
            raise InvalidInputError(
                unknown[0], changes[unknown[0]], "ax, ay or az", problem="not a module offset:"
            )
        offsets = {**self.parameters(), **changes}
        return self.with_a([offsets[name] for name in MODULE_OFFSETS])

    def constant_length(self) -> float:
        """``|a|``, or 0 for a ``none`` module (it ignores ``a``).

        >>> Module("Ry", a=(3, 0, 4)).constant_length()
        5.0
        """
        return 0.0 if self.kind == "none" else float(np.linalg.norm(self.a))

    def geometry(self) -> LinkGeometry:
        """Kernel description: ``Trans(a) · Rot/Trans_axis(q)``."""
        if self.kind == "none":
            return LinkGeometry()
        offset = np.array(self.a) if any(self.a) else None
        if self.kind == "fixed":
            return LinkGeometry(pre_translation=offset)
        return LinkGeometry(
            pre_translation=offset,
            axis=kind_axis(self.kind),
            joint=JOINT_LETTERS[self.joint_type],
        )

    def with_q(self, q: float) -> Module:
        """A copy with another coordinate value."""
        return Module(self.kind, self.a, q, self.name, self.limits)

    def with_a(self, a: Any) -> Module:
        """A copy with other offsets."""
        return Module(self.kind, a, self.q, self.name, self.limits)

    def with_kind(self, kind: Any) -> Module:
        """A copy with another movement type (offsets, q and name kept).

        The range is kept when the joint type (revolute or prismatic) stays the same, and
        dropped otherwise: radians do not become lengths, and none/fixed have no joint.

        >>> joint = Module("Rz", limits=(-1, 1))
        >>> joint.with_kind("Ry").limits, joint.with_kind("Tz").limits
        ((-1.0, 1.0), None)
        """
        new = Module(kind, self.a, self.q, self.name)
        return new.with_limits(self.limits) if new.joint_type == self.joint_type else new

    def with_name(self, name: str | None) -> Module:
        """A copy with another display name."""
        return Module(self.kind, self.a, self.q, name, self.limits)

    def with_limits(self, limits: Any) -> Module:
        """A copy with another range ``(lo, hi)`` of ``q`` (``None``: the default).

        >>> Module("Ry").with_limits((-1.5, 1.5)).limits
        (-1.5, 1.5)
        """
        return Module(self.kind, self.a, self.q, self.name, limits)


def transfer_matrix(kind: Any, q: Any = 0.0, a: Any = (0.0, 0.0, 0.0)) -> np.ndarray:
    """Transfer matrix of a module of movement type ``kind`` (docs/conventions.md table).

    Parameters
    ----------
    kind : str or int
        Movement type name or paper code 0–6 (see :class:`Module`).
    q : float or array-like, shape (T,)
        Generalized coordinate(s): radians for rotations, length for translations.
    a : array-like, shape (3,)
        Offsets ``(ax, ay, az)`` (length units).

    Returns
    -------
    ndarray, shape (4, 4) or (T, 4, 4)

    Examples
    --------
    >>> transfer_matrix("Tx", 5, a=(1, 2, 3))
    array([[1., 0., 0., 6.],
           [0., 1., 0., 2.],
           [0., 0., 1., 3.],
           [0., 0., 0., 1.]])
    >>> transfer_matrix(3, [0.0, np.pi]).shape
    (2, 4, 4)
    """
    return Module(kind, a).matrix(q)
