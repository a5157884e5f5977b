"""Inverse kinematics: find joint values that put the end effector on a target.

The numeric solver :func:`ik` works for every robot (damped least squares on the
geometric Jacobian, vectorized over many targets) and always says why it stopped.

The closed forms :func:`ik_all` list every solution of the classic arms (planar 2R/3R,
SCARA, 3R elbow, spherical-wrist 6R, UR) as :class:`IKSolutions`; :func:`recognize` names
the family from the robot's joint axes.
"""

from __future__ import annotations

from ._closed_form import ik_all
from ._numeric import ik
from ._recognize import recognize
from ._result import IKResult
from ._solutions import IKSolutions

__all__ = ["IKResult", "ik", "IKSolutions", "ik_all", "recognize"]
