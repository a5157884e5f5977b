"""Denavit–Hartenberg links, standard and modified (Craig), never guessed."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_finite_number, one_line
from ..conventions._bounds import check_parameter
from ..conventions._conventions import (
    DH_CONVENTIONS,
    DH_PARAMETERS,
    JOINT_LETTERS,
    JOINT_OF_LETTER,
    dh_formula,
)
from ..conventions._names import check_name
from ..kernel._geometry import LinkGeometry
from ._limits import check_limits
from ._link import Link

__all__ = ["DHLink", "dh_matrix", "dh_link_from_row", "check_convention"]

_CONVENTIONS_ALLOWED = " or ".join(f"'{name}' ({dh_formula(name)})" for name in DH_CONVENTIONS)


def check_convention(convention: Any) -> str:
    """Return ``convention`` if it is ``"standard"`` or ``"modified"``.

    >>> check_convention("Modified")
    'modified'
    >>> check_convention("craig")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: convention: unknown DH convention 'craig'; allowed: 'standard' ...
    """
    if not isinstance(convention, str) or convention.strip().lower() not in DH_CONVENTIONS:
        raise InvalidInputError(
            "convention",
            one_line(convention),
            _CONVENTIONS_ALLOWED,
            problem="unknown DH convention",
        )
    return convention.strip().lower()


def _rot_x(alpha: float) -> np.ndarray | None:
    if alpha == 0.0:
        return None
    c, s = np.cos(alpha), np.sin(alpha)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


@dataclass(frozen=True)
class DHLink(Link):
    """One Denavit–Hartenberg row as a link: ``(θ, d, a, α)`` and a joint type.

    Parameters
    ----------
    theta : float
        Joint angle θ (radians); ``q`` adds to it for a revolute joint.
    d : float
        Link offset d (length); ``q`` adds to it for a prismatic joint.
    a : float
        Link length a (length).
    alpha : float
        Link twist α (radians).
    joint : {"R", "P"}
        Revolute (``q`` adds to θ) or prismatic (``q`` adds to d).
    convention : {"standard", "modified"}
        ``standard``: ``Rz(θ)·Tz(d)·Tx(a)·Rx(α)``; ``modified`` (Craig):
        ``Rx(α)·Tx(a)·Rz(θ)·Tz(d)``. The default is the paper's (eq. 9); the convention
        is always part of ``repr``, so a printed link never hides which one it uses.
    q : float
        The joint coordinate's own value.
    name : str, optional
        At most 200 characters.
    limits : (lo, hi), optional
        Range of ``q`` (radians for "R", length for "P"), ``lo < hi``; ``None``: the
        robot's default (see :meth:`Robot.joint_limits`). Not enforced on ``q``.

    Every number (θ, d, a, α, q and the limits) must be finite and at most ``1e150`` in
    magnitude (:data:`~robotconf.kinematics.MAX_PARAMETER`), so no chain overflows.

    Raises
    ------
    InvalidInputError
        For a parameter that is not a real number, not finite or too large, an unknown
        joint or convention, a name that is not text or too long, or a bad range.

    Examples
    --------
    >>> link = DHLink(theta=0, d=0, a=1, alpha=np.pi / 2, joint="R")
    >>> link.matrix(np.pi / 2).round(12) + 0.0
    array([[0., 0., 1., 0.],
           [1., 0., 0., 1.],
           [0., 1., 0., 0.],
           [0., 0., 0., 1.]])
    """

    theta: float = 0.0
    d: float = 0.0
    a: float = 0.0
    alpha: float = 0.0
    joint: str = "R"
    convention: str = "standard"
    q: float = 0.0
    name: str | None = field(default=None)
    limits: tuple[float, float] | None = None

    def __post_init__(self) -> None:
        for attribute in ("theta", "d", "a", "alpha", "q"):
            value = check_parameter(getattr(self, attribute), attribute)
            object.__setattr__(self, attribute, value)
        joint_type = (
            JOINT_OF_LETTER.get(self.joint.strip().upper()) if isinstance(self.joint, str) else None
        )
        if joint_type is None:
            raise InvalidInputError(
                "joint",
                one_line(self.joint),
                "'R' (revolute: q adds to θ) or 'P' (prismatic: q adds to d)",
            )
        object.__setattr__(self, "joint", JOINT_LETTERS[joint_type])
        object.__setattr__(self, "convention", check_convention(self.convention))
        check_name(self.name)
        object.__setattr__(self, "limits", check_limits(self.limits))

    def __repr__(self) -> str:
        text = (
            f"DHLink(theta={self.theta!r}, d={self.d!r}, a={self.a!r}, alpha={self.alpha!r}, "
            f"joint={self.joint!r}, convention={self.convention!r}"
        )
        if self.q != 0.0:
            text += f", q={self.q!r}"
        if self.name is not None:
            text += f", name={self.name!r}"
        if self.limits is not None:
            text += f", limits={self.limits!r}"
        return text + ")"

    @property
    def joint_type(self) -> str:
        """``"revolute"`` or ``"prismatic"``."""
        return JOINT_OF_LETTER[self.joint]

    @property
    def axis(self) -> str:
        """The joint axis in the link's own description: always z."""
        return "z"

    def row(self) -> tuple[float, float, float, float, str]:
        """The DH row ``(theta, d, a, alpha, joint)``."""
        return (self.theta, self.d, self.a, self.alpha, self.joint)

    def parameters(self) -> dict[str, float]:
        """The row by name: ``{"theta": …, "d": …, "a": …, "alpha": …}`` (radians, length).

        >>> DHLink(d=0.5, a=2.0).parameters()
        {'theta': 0.0, 'd': 0.5, 'a': 2.0, 'alpha': 0.0}
        """
        return {name: getattr(self, name) for name in DH_PARAMETERS}

    def with_parameters(self, **changes: float) -> DHLink:
        """A copy with some of ``theta``, ``d``, ``a``, ``alpha`` changed.

        >>> DHLink(a=2.0).with_parameters(d=0.7).row()
        (0.0, 0.7, 2.0, 0.0, 'R')
        """
        unknown = sorted(set(changes) - set(DH_PARAMETERS))
        if unknown:
            raise InvalidInputError(
                unknown[0],
                changes[unknown[0]],
                "theta, d, a or alpha",
                problem="not a DH parameter:",
            )
        return self._copy(**changes)

    def constant_length(self) -> float:
        """``√(a² + d²)``; only ``a`` for a prismatic row, whose ``d`` is where ``q`` starts.

        >>> DHLink(d=4, a=3).constant_length(), DHLink(d=4, a=3, joint="P").constant_length()
        (5.0, 3.0)
        """
        return float(np.hypot(self.a, self.d if self.joint == "R" else 0.0))

    def geometry(self) -> LinkGeometry:
        """Kernel description of the row in its convention."""
        twist = _rot_x(self.alpha)
        length = np.array([self.a, 0.0, 0.0]) if self.a != 0.0 else None
        if self.convention == "standard":
            return LinkGeometry(
                axis=2,
                joint=self.joint,
                angle=self.theta,
                offset=self.d,
                post_translation=length,
                post_rotation=twist,
            )
        # Rx(α)·Tx(a) = [Rx(α) | (a, 0, 0)]: Rx leaves the x axis alone.
        return LinkGeometry(
            pre_rotation=twist,
            pre_translation=length,
            axis=2,
            joint=self.joint,
            angle=self.theta,
            offset=self.d,
        )

    def _copy(self, **changes: Any) -> DHLink:
        values = {name: getattr(self, name) for name in _ALL_FIELDS}
        values.update(changes)
        return DHLink(**values)

    def with_q(self, q: float) -> DHLink:
        """A copy with another coordinate value."""
        return self._copy(q=q)

    def with_name(self, name: str | None) -> DHLink:
        """A copy with another display name."""
        return self._copy(name=name)

    def with_limits(self, limits: Any) -> DHLink:
        """A copy with another range ``(lo, hi)`` of ``q`` (``None``: the default).

        >>> DHLink(a=1.0).with_limits((-2, 2)).limits
        (-2.0, 2.0)
        """
        return self._copy(limits=limits)


_ALL_FIELDS = ("theta", "d", "a", "alpha", "joint", "convention", "q", "name", "limits")


def dh_matrix(theta: Any, d: Any, a: Any, alpha: Any, convention: str = "standard") -> np.ndarray:
    """Denavit–Hartenberg transfer matrix.

    Parameters
    ----------
    theta : float or array-like, shape (T,)
        Joint angle θ (radians).
    d : float
        Link offset (length).
    a : float
        Link length (length).
    alpha : float
        Link twist (radians).
    convention : {"standard", "modified"}
        ``standard`` (paper eq. 9–10): ``Rz(θ)·Tz(d)·Tx(a)·Rx(α)``, which multiplies out to
        ``[[cθ, −sθ cα, sθ sα, a cθ], [sθ, cθ cα, −cθ sα, a sθ], [0, sα, cα, d], [0,0,0,1]]``;
        ``modified`` (Craig): ``Rx(α)·Tx(a)·Rz(θ)·Tz(d)``.

    Returns
    -------
    ndarray, shape (4, 4) or (T, 4, 4)

    Examples
    --------
    >>> dh_matrix(np.pi / 2, 0.5, 2.0, 0.0).round(12) + 0.0  # + 0.0 turns -0.0 into 0.0
    array([[ 0. , -1. ,  0. ,  0. ],
           [ 1. ,  0. ,  0. ,  2. ],
           [ 0. ,  0. ,  1. ,  0.5],
           [ 0. ,  0. ,  0. ,  1. ]])
    """
    link = DHLink(theta=0.0, d=d, a=a, alpha=alpha, joint="R", convention=convention)
    if np.ndim(theta) == 0:
        return link.matrix(check_finite_number(theta, "theta"))
    return link.matrix(theta)


_DH_FIELDS = ("theta", "d", "a", "alpha", "joint")


def dh_link_from_row(row: Any, convention: str, index: int) -> DHLink:
    """One row of a DH table as a :class:`DHLink`, with errors naming ``rows[index]``.

    Parameters
    ----------
    row : (theta, d, a, alpha, joint), dict with those keys (plus ``q``, ``name``, ``limits``),
        or DHLink
    convention : {"standard", "modified"}
        Applied to tuple and dict rows; a DHLink keeps its own.
    index : int
        Position of the row, for error messages.

    Examples
    --------
    >>> dh_link_from_row((0, 0.1, 0.5, 0, "P"), "standard", 0).joint_type
    'prismatic'
    """
    if isinstance(row, DHLink):
        return row
    field = f"rows[{index}]"
    allowed = "(theta, d, a, alpha, joint) with joint 'R' or 'P', or a dict with those keys"
    if isinstance(row, Mapping):
        unknown = set(row) - {*_DH_FIELDS, "q", "name", "limits"}
        if unknown:
            raise InvalidInputError(
                field, one_line(row), allowed, problem=f"unknown keys {sorted(unknown)}:"
            )
        missing = [key for key in _DH_FIELDS if key not in row]
        if missing:
            raise InvalidInputError(field, one_line(row), allowed, problem=f"missing {missing}:")
        values = dict(row)
    elif isinstance(row, (str, bytes)) or not isinstance(row, Sequence) or len(row) != 5:
        raise InvalidInputError(field, one_line(row), allowed, problem="expected 5 entries, got")
    else:
        values = dict(zip(_DH_FIELDS, row, strict=True))
    try:
        return DHLink(convention=convention, **values)
    except InvalidInputError as error:
        raise error.within(field) from None
