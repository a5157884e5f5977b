"""The geometry every closed form reads: joint lines at q = 0 and the subproblems.

:func:`chain_axes` describes a robot, given by DH rows or by modules alike, as its joint
lines at the reference configuration (:class:`ChainAxes` of :class:`AxisJoint`);
:func:`angle_about`, :func:`turn_to_level` and :func:`bend_angles` are the Paden–Kahan
subproblems (their roots come as :class:`Roots`) that the closed forms of
:mod:`robotconf.inverse_kinematics.closed_form` and, over many targets,
:mod:`robotconf.inverse_kinematics.batch` are made of.
"""

from ._chain_axes import AxisJoint, ChainAxes, chain_axes, common_point
from ._subproblems import Roots, angle_about, bend_angles, turn_to_level

__all__ = [
    "AxisJoint",
    "ChainAxes",
    "chain_axes",
    "common_point",
    "Roots",
    "angle_about",
    "turn_to_level",
    "bend_angles",
]
