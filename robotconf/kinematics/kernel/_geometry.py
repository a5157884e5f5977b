"""How one link moves: a constant transform, a joint screw, and another constant transform.

Every link robotconf knows (the paper's seven modules, the ``fixed`` offset, standard and
modified Denavit–Hartenberg rows) is

.. math::

    A(q) = P \\cdot \\operatorname{Rot}_k(\\theta_0 + q_R) \\cdot
           \\operatorname{Trans}_k(d_0 + q_P) \\cdot Q

with constant homogeneous transforms ``P`` (``pre``) and ``Q`` (``post``), a principal
axis ``k`` and the coordinate ``q`` added to the angle (revolute) or to the displacement
(prismatic). Rotation and translation about the same axis commute, so the order of the
two middle factors does not matter. The kinematics kernel composes chains from this
description alone, so each link's formula lives in one place.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["LinkGeometry"]


@dataclass(frozen=True, eq=False)
class LinkGeometry:
    """Kinematic description of one link, as consumed by the kinematics kernel.

    Parameters
    ----------
    pre_rotation, post_rotation : ndarray, shape (3, 3), or None
        Rotation parts of the constant transforms; ``None`` means identity.
    pre_translation, post_translation : ndarray, shape (3,), or None
        Translation parts of the constant transforms (length); ``None`` means zero.
    axis : {0, 1, 2} or None
        Joint axis (x, y, z) in the frame after ``pre``; ``None`` for a link without joint.
    joint : {"R", "P"} or None
        Whether ``q`` adds to the angle (revolute) or to the displacement (prismatic).
    angle : float
        Constant angle about ``axis`` added to ``q`` for revolute joints (radians).
    offset : float
        Constant displacement along ``axis`` added to ``q`` for prismatic joints (length).
    """

    pre_rotation: np.ndarray | None = None
    pre_translation: np.ndarray | None = None
    axis: int | None = None
    joint: str | None = None
    angle: float = 0.0
    offset: float = 0.0
    post_rotation: np.ndarray | None = None
    post_translation: np.ndarray | None = None

    @property
    def is_identity(self) -> bool:
        """True when the link never moves anything (the paper's null module)."""
        return (
            self.pre_rotation is None
            and self.pre_translation is None
            and self.post_rotation is None
            and self.post_translation is None
            and (self.axis is None or (self.joint is None and self.angle == 0 and self.offset == 0))
        )

    def pre_matrix(self) -> np.ndarray:
        """The constant transform ``P`` before the joint, shape (4, 4).

        >>> LinkGeometry(pre_translation=np.array([1.0, 2.0, 3.0])).pre_matrix()[:3, 3]
        array([1., 2., 3.])
        """
        return _homogeneous(self.pre_rotation, self.pre_translation)

    def post_matrix(self) -> np.ndarray:
        """The constant transform ``Q`` after the joint, shape (4, 4)."""
        return _homogeneous(self.post_rotation, self.post_translation)

    def screw(self) -> LinkGeometry:
        """The joint's own motion ``Rot_k(θ₀ + q_R)·Trans_k(d₀ + q_P)``, without ``P`` and ``Q``."""
        return LinkGeometry(axis=self.axis, joint=self.joint, angle=self.angle, offset=self.offset)

    def generator(self) -> np.ndarray:
        """The joint's 4×4 generator ``G``: ``dA/dq = P · Screw(q) · G · Q``.

        Returns
        -------
        ndarray, shape (4, 4)
            Zero for links without joint.

        Examples
        --------
        >>> LinkGeometry(axis=2, joint="R").generator()[:3, :3]
        array([[ 0., -1.,  0.],
               [ 1.,  0.,  0.],
               [ 0.,  0.,  0.]])
        """
        g = np.zeros((4, 4))
        if self.axis is None or self.joint is None:
            return g
        k = self.axis
        if self.joint == "P":
            g[k, 3] = 1.0
        else:
            i, j = (k + 1) % 3, (k + 2) % 3
            g[j, i] = 1.0
            g[i, j] = -1.0
        return g


def _homogeneous(rotation: np.ndarray | None, translation: np.ndarray | None) -> np.ndarray:
    matrix = np.eye(4)
    if rotation is not None:
        matrix[:3, :3] = rotation
    if translation is not None:
        matrix[:3, 3] = translation
    return matrix
