"""Inverse kinematics: find joint values that put the end effector on a target.

The numeric solver :func:`ik` works for every robot (damped least squares on the
geometric Jacobian, vectorized over many targets) and always says why it stopped.

The closed forms :func:`ik_all` list every solution of the classic arms (planar 2R/3R,
SCARA, 3R elbow, spherical-wrist 6R, UR) as :class:`IKSolutions`; :func:`recognize` names
the family from the robot's joint axes. :func:`ik_all_many` lists them for many targets
at once (vectorized over the targets) as :class:`IKSolutionSets`.
"""

from __future__ import annotations

from ._closed_form import ik_all
from ._numeric import ik
from ._recognize import recognize
from ._result import IKResult
from ._solutions import IKSolutions
from .batch import IKSolutionSets, ik_all_many

__all__ = ["IKResult", "ik", "IKSolutions", "ik_all", "IKSolutionSets", "ik_all_many", "recognize"]
