"""The textbook arrangements of a robotics course, in plain length units.

Sources for the arrangements: M. W. Spong, S. Hutchinson, M. Vidyasagar, *Robot Modeling
and Control*, Wiley 2006, §1.3 (common kinematic arrangements) and §3.3 (DH examples);
B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, *Robotics: Modelling, Planning and
Control*, Springer 2009, §2.9 (direct kinematics of typical structures). The lengths are
illustrative, on the scale of the paper's robot (tens of units); the ranges are typical
of such machines, not one manufacturer's.
"""

from __future__ import annotations

import numpy as np

from .._validation import check_finite_number
from ..kinematics import DHLink, Module, Robot

__all__ = [
    "cartesian",
    "cylindrical",
    "spherical",
    "scara",
    "articulated",
    "planar_2r",
    "planar_3r",
]

PI = np.pi


def _lengths(**values: float) -> list[float]:
    return [check_finite_number(v, name) for name, v in values.items()]


def _stroke(value: float, name: str) -> tuple[float, float]:
    return (0.0, check_finite_number(value, name))


def cartesian(x_stroke: float = 50.0, y_stroke: float = 40.0, z_stroke: float = 30.0) -> Robot:
    """Cartesian gantry (PPP): slides along x, y and z (Spong et al. §1.3).

    The end-effector sits at ``(q1, q2, q3)``; each slide travels from 0 to its stroke.

    Examples
    --------
    >>> cartesian().end_effector([10, 20, 5])
    array([10., 20.,  5.])
    """
    return Robot(
        [
            Module("Tx", limits=_stroke(x_stroke, "x_stroke")),
            Module("Ty", limits=_stroke(y_stroke, "y_stroke")),
            Module("Tz", limits=_stroke(z_stroke, "z_stroke")),
        ],
        name="Cartesian gantry (TxTyTz)",
    )


def cylindrical(
    h: float = 20.0, tool: float = 10.0, z_stroke: float = 40.0, r_stroke: float = 30.0
) -> Robot:
    """Cylindrical robot (RPP): base turn, vertical slide, radial slide.

    Spong et al. Example 3.2 (three-link cylindrical robot) as modules Rz, Tz, Tx: the
    column starts at height ``h``, the radial slide carries a tool of length ``tool``.
    End-effector: ``((q3 + tool)·cos q1, (q3 + tool)·sin q1, h + q2)``.

    Examples
    --------
    >>> cylindrical().end_effector([np.pi / 2, 15, 20]).round(12) + 0.0
    array([ 0., 30., 35.])
    """
    h, tool = _lengths(h=h, tool=tool)
    return Robot(
        [
            Module("Rz", limits=(-PI, PI)),
            Module("Tz", a=(0.0, 0.0, h), limits=_stroke(z_stroke, "z_stroke")),
            Module("Tx", limits=_stroke(r_stroke, "r_stroke")),
        ],
        end_effector=(tool, 0.0, 0.0),
        name="cylindrical (RzTzTx)",
    )


def spherical(h: float = 20.0, tool: float = 10.0, r_stroke: float = 30.0) -> Robot:
    """Spherical (polar) robot (RRP): base turn, elevation, radial slide (Spong et al. §1.3).

    Modules Rz, Ry at height ``h``, Tx along the arm. Ry turns x towards −z, so a
    positive ``q2`` lowers the arm. End-effector with ``r = q3 + tool``:
    ``(r·cos q2·cos q1, r·cos q2·sin q1, h − r·sin q2)``.

    Examples
    --------
    >>> spherical().end_effector([0, -np.pi / 2, 10]).round(12) + 0.0
    array([ 0.,  0., 40.])
    """
    h, tool = _lengths(h=h, tool=tool)
    return Robot(
        [
            Module("Rz", limits=(-PI, PI)),
            Module("Ry", a=(0.0, 0.0, h), limits=(-PI / 2, PI / 2)),
            Module("Tx", limits=_stroke(r_stroke, "r_stroke")),
        ],
        end_effector=(tool, 0.0, 0.0),
        name="spherical (RzRyTx)",
    )


def scara(
    h: float = 40.0, a1: float = 40.0, a2: float = 30.0, d4: float = 10.0, stroke: float = 30.0
) -> Robot:
    """SCARA (RRPR), standard DH as in Spong et al. Example 3.6 (Table 3.6).

    Rows ``(θ1, h, a1, 0)``, ``(θ2, 0, a2, π)``, ``(0, d3, 0, 0)`` prismatic,
    ``(θ4, d4, 0, 0)``; Spong puts the base frame at the arm's height (``h = 0``). The
    twist ``α2 = π`` points z down, so ``q3 > 0`` lowers the tool. Ranges typical of
    small SCARAs: ±130° and ±145° for the arm, a full turn for the tool.

    Examples
    --------
    >>> scara().end_effector([np.pi / 2, -np.pi / 2, 5, 0]).round(12) + 0.0
    array([30., 40., 25.])
    """
    h, a1, a2, d4 = _lengths(h=h, a1=a1, a2=a2, d4=d4)
    deg = PI / 180
    return Robot(
        [
            DHLink(0.0, h, a1, 0.0, "R", limits=(-130 * deg, 130 * deg)),
            DHLink(0.0, 0.0, a2, PI, "R", limits=(-145 * deg, 145 * deg)),
            DHLink(0.0, 0.0, 0.0, 0.0, "P", limits=_stroke(stroke, "stroke")),
            DHLink(0.0, d4, 0.0, 0.0, "R", limits=(-PI, PI)),
        ],
        name="SCARA",
    )


def articulated(h: float = 20.0, a2: float = 30.0, a3: float = 40.0) -> Robot:
    """Anthropomorphic arm (RRR), standard DH as in Siciliano et al. §2.9.4.

    Rows ``(θ1, h, 0, π/2)``, ``(θ2, 0, a2, 0)``, ``(θ3, 0, a3, 0)``; Siciliano puts the
    base frame at the shoulder (``h = 0``). The lengths repeat the paper's 20/30/40; the
    shoulder lifts the arm for ``q2 > 0``.

    Examples
    --------
    >>> articulated().end_effector([0, np.pi / 2, -np.pi / 2]).round(12) + 0.0
    array([40.,  0., 50.])
    """
    h, a2, a3 = _lengths(h=h, a2=a2, a3=a3)
    return Robot(
        [
            DHLink(0.0, h, 0.0, PI / 2, "R", limits=(-PI, PI)),
            DHLink(0.0, 0.0, a2, 0.0, "R", limits=(-PI / 2, PI / 2)),
            DHLink(0.0, 0.0, a3, 0.0, "R", limits=(-3 * PI / 4, 3 * PI / 4)),
        ],
        name="anthropomorphic arm (RRR)",
    )


def planar_2r(l1: float = 40.0, l2: float = 30.0) -> Robot:
    """Planar elbow arm (RR), standard DH as in Spong et al. Example 3.1.

    End-effector ``(l1·c1 + l2·c12, l1·s1 + l2·s12, 0)``.

    Examples
    --------
    >>> planar_2r().end_effector([np.pi / 2, -np.pi / 2]).round(12) + 0.0
    array([30., 40.,  0.])
    """
    l1, l2 = _lengths(l1=l1, l2=l2)
    return Robot(
        [DHLink(0.0, 0.0, length, 0.0, "R", limits=(-PI, PI)) for length in (l1, l2)],
        name="planar 2R",
    )


def planar_3r(l1: float = 40.0, l2: float = 30.0, l3: float = 20.0) -> Robot:
    """Three-link planar arm (RRR), standard DH as in Siciliano et al. §2.9.1.

    Examples
    --------
    >>> planar_3r().end_effector([np.pi / 2, -np.pi / 2, -np.pi / 2]).round(12) + 0.0
    array([30., 20.,  0.])
    """
    lengths = _lengths(l1=l1, l2=l2, l3=l3)
    return Robot(
        [DHLink(0.0, 0.0, length, 0.0, "R", limits=(-PI, PI)) for length in lengths],
        name="planar 3R",
    )
