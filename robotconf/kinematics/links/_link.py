"""What every link of a chain offers: a 4×4 matrix as a function of q, and its derivatives."""

from __future__ import annotations

import copy
from typing import Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import as_float_array, check_finite_number, check_joint_values, one_line
from ..conventions._conventions import DH_LENGTHS, JOINT_LETTERS, JOINT_UNITS, MODULE_OFFSETS
from ..kernel._geometry import LinkGeometry
from ..kernel._kernel import link_matrices

__all__ = ["Link"]


class Link:
    """Base of :class:`~robotconf.Module` and :class:`~robotconf.DHLink`.

    A subclass provides ``q`` (its own coordinate value), ``name``, ``joint_type`` and
    :meth:`geometry`; everything numeric comes from the shared kinematics kernel.
    """

    q: float
    name: str | None
    limits: tuple[float, float] | None

    @property
    def joint_type(self) -> str:  # pragma: no cover - abstract
        raise NotImplementedError

    def geometry(self) -> LinkGeometry:  # pragma: no cover - abstract
        raise NotImplementedError

    def constant_length(self) -> float:  # pragma: no cover - abstract
        """The length the link adds to the robot's size whatever ``q`` is (length units)."""
        raise NotImplementedError

    def parameters(self) -> dict[str, float]:  # pragma: no cover - abstract
        """The link's constant parameters by name, in table order (radians, length units)."""
        raise NotImplementedError

    def with_parameters(self, **changes: float) -> Link:  # pragma: no cover - abstract
        """A copy with some constant parameters (:meth:`parameters`) changed."""
        raise NotImplementedError

    def length_parameters(self) -> tuple[str, ...]:
        """The names of the parameters that are lengths; none for a ``none`` module.

        >>> from robotconf.kinematics import DHLink, Module
        >>> Module("Ry").length_parameters(), DHLink().length_parameters()
        (('ax', 'ay', 'az'), ('d', 'a'))
        >>> Module("none", a=(1, 0, 0)).length_parameters()
        ()
        """
        if self.joint_type == "none":  # the null module ignores its offsets
            return ()
        lengths = MODULE_OFFSETS + DH_LENGTHS
        return tuple(name for name in self.parameters() if name in lengths)

    def with_q(self, q: float) -> Link:  # pragma: no cover - abstract
        """A copy with another coordinate value."""
        raise NotImplementedError

    def with_checked_q(self, q: float) -> Link:
        """A copy holding ``q``, which the caller has checked (a finite float within the
        bounds :meth:`with_q` enforces): nothing else is validated again."""
        new = copy.copy(self)
        object.__setattr__(new, "q", q)
        return new

    def with_name(self, name: str | None) -> Link:  # pragma: no cover - abstract
        """A copy with another display name."""
        raise NotImplementedError

    def with_limits(self, limits: Any) -> Link:  # pragma: no cover - abstract
        """A copy with another range ``(lo, hi)`` of ``q`` (``None``: the default)."""
        raise NotImplementedError

    @property
    def unit(self) -> str:
        """Unit of ``q``: ``"rad"`` for revolute, ``"length"`` for prismatic, else ``""``."""
        return JOINT_UNITS[self.joint_type]

    @property
    def is_joint(self) -> bool:
        """Whether ``q`` moves this link (revolute or prismatic)."""
        return self.joint_type in JOINT_LETTERS

    def _coordinates(self, q: Any) -> tuple[np.ndarray, bool]:
        if q is None:
            return np.array([[self.q]]), False
        if np.ndim(q) == 0:
            return np.array([[check_finite_number(q, "q")]]), False
        allowed = "one number, or a 1-D array of T numbers"
        values = as_float_array(q, "q", allowed)  # refuses [1, True], which numpy would not
        if values.ndim != 1:
            raise InvalidInputError(
                "q",
                one_line(q),
                allowed,
                problem=f"expected a number or shape (T,), got {values.shape}:",
            )
        column, _ = check_joint_values(values[:, np.newaxis], 1)
        return column, True

    def matrix(self, q: Any = None) -> np.ndarray:
        """The homogeneous transfer matrix ``A(q)``.

        Parameters
        ----------
        q : float or array-like, shape (T,), optional
            Coordinate value(s): radians for revolute, length for prismatic links.
            Defaults to the link's own ``q``.

        Returns
        -------
        ndarray, shape (4, 4) or (T, 4, 4)

        Examples
        --------
        >>> from robotconf import Module
        >>> Module("Ty", a=(0, 1, 0)).matrix([0.0, 2.5])[:, 1, 3]
        array([1. , 3.5])
        """
        column, batched = self._coordinates(q)
        out = link_matrices([self.geometry()], column, fields=["q"])[:, 0]
        return out if batched else out[0]

    def matrix_derivative(self, q: Any = None, order: int = 1) -> np.ndarray:
        """The derivative ``dᵏA/dqᵏ`` of the transfer matrix.

        Uses ``dᵏA/dqᵏ = P · Screw(q) · Gᵏ · Q`` with the joint generator ``G`` (see
        :class:`~robotconf.kinematics.LinkGeometry`); zero for links without joint.

        Parameters
        ----------
        q : float or array-like, shape (T,), optional
            Coordinate value(s); defaults to the link's own ``q``.
        order : int
            Derivative order ≥ 1.

        Returns
        -------
        ndarray, shape (4, 4) or (T, 4, 4)

        Examples
        --------
        The first derivative of Rx at q = 0 is the generator of rotations about x:

        >>> from robotconf import Module
        >>> Module("Rx").matrix_derivative(0.0)[:3, :3]
        array([[ 0.,  0.,  0.],
               [ 0.,  0., -1.],
               [ 0.,  1.,  0.]])
        """
        if isinstance(order, bool) or not isinstance(order, (int, np.integer)) or order < 1:
            raise InvalidInputError("order", order, "an integer ≥ 1")
        column, batched = self._coordinates(q)
        g = self.geometry()
        screw_matrices = link_matrices([g.screw()], column, fields=["q"])[:, 0]
        tail = np.linalg.matrix_power(g.generator(), int(order)) @ g.post_matrix()
        out = g.pre_matrix() @ screw_matrices @ tail
        return out if batched else out[0]
