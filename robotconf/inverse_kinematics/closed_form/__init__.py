"""Every closed-form solution of the classic arms, for one target.

:func:`ik_all` reads the target, asks :func:`recognize` for the robot's family (from its
joint lines, never from its name), lets the family's solver list its branches —
:func:`solve_planar` (planar 2R/3R, SCARA), :func:`solve_elbow` (3R elbow),
:func:`solve_spherical_wrist` (PUMA-like 6R), :func:`solve_ur` (UR-type 6R) — and checks
each by forward kinematics and against the joint limits; the answer is
:class:`IKSolutions`.
"""

from ._elbow import solve_elbow
from ._ik_all import ik_all
from ._planar import solve_planar
from ._recognize import recognize
from ._solutions import IKSolutions
from ._spherical_wrist import solve_spherical_wrist
from ._ur import solve_ur

__all__ = [
    "ik_all",
    "IKSolutions",
    "recognize",
    "solve_planar",
    "solve_elbow",
    "solve_spherical_wrist",
    "solve_ur",
]
