"""Real arms with published standard-DH parameters, in metres."""

from __future__ import annotations

import numpy as np

from .._validation import check_finite_number
from ..kinematics import DHLink, Robot

__all__ = ["stanford", "puma560", "ur5"]

PI = np.pi
DEG = PI / 180
INCH = 0.0254


def stanford(tool: float = 0.0) -> Robot:
    """Stanford (Scheinman) arm, RRP + spherical wrist, standard DH.

    The frame assignment is Spong, Hutchinson & Vidyasagar, *Robot Modeling and Control*
    (Wiley 2006), Example 3.5, Table 3.4: rows ``(θ1, d1, 0, −π/2)``, ``(θ2, d2, 0, π/2)``,
    ``(0, d3, 0, 0)`` prismatic, ``(θ4, 0, 0, −π/2)``, ``(θ5, 0, 0, π/2)``,
    ``(θ6, d6, 0, 0)``. The lengths d1 = 0.412 m, d2 = 0.154 m, d6 = 0.263 m come from the
    Stanford AI memo AIM-177 (Paul 1972, Fig. 2.3) as used in Corke's Robotics Toolbox
    (``mdl_stanford``); Spong's table has d1 = 0 (base frame at the shoulder). Ranges as in
    the Toolbox: ±170° (wrist bend ±90°), the boom 12–50 inches.

    Parameters
    ----------
    tool : float
        Tool length along the last z axis (m), added as the end-effector point.

    Examples
    --------
    >>> stanford().end_effector([0, np.pi / 2, 0.5, 0, 0, 0]).round(6) + 0.0
    array([0.763, 0.154, 0.412])
    """
    tool = check_finite_number(tool, "tool")
    return Robot(
        [
            DHLink(0.0, 0.412, 0.0, -PI / 2, "R", limits=(-170 * DEG, 170 * DEG)),
            DHLink(0.0, 0.154, 0.0, PI / 2, "R", limits=(-170 * DEG, 170 * DEG)),
            DHLink(0.0, 0.0, 0.0, 0.0, "P", limits=(12 * INCH, 50 * INCH)),
            DHLink(0.0, 0.0, 0.0, -PI / 2, "R", limits=(-170 * DEG, 170 * DEG)),
            DHLink(0.0, 0.0, 0.0, PI / 2, "R", limits=(-90 * DEG, 90 * DEG)),
            DHLink(0.0, 0.263, 0.0, 0.0, "R", limits=(-170 * DEG, 170 * DEG)),
        ],
        end_effector=(0.0, 0.0, tool),
        name="Stanford arm",
    )


def puma560(tool: float = 0.0) -> Robot:
    """Unimation PUMA 560, standard DH (Paul's frames), in metres.

    Kinematics: P. Corke and B. Armstrong-Hélouvry, "A search for consensus among model
    parameters reported for the PUMA 560 robot", ICRA 1994, as in Corke's Robotics Toolbox
    (``mdl_puma560``): a2 = 0.4318, d3 = 0.15005, a3 = 0.0203, d4 = 0.4318,
    α = (π/2, 0, −π/2, π/2, −π/2, 0); the base frame is at the shoulder. Ranges:
    Unimation's, as listed in the Toolbox: ±160°, −45…225°, −225…45°, −110…170°,
    ±100°, ±266°. At q = 0 (Corke's ``qz``) the wrist centre is at
    (0.4521, −0.15005, 0.4318).

    Parameters
    ----------
    tool : float
        Tool length along the last z axis (m), added as the end-effector point.

    Examples
    --------
    >>> puma560().end_effector([0, 0, 0, 0, 0, 0]).round(5) + 0.0
    array([ 0.4521 , -0.15005,  0.4318 ])
    """
    tool = check_finite_number(tool, "tool")
    ranges = [(-160, 160), (-45, 225), (-225, 45), (-110, 170), (-100, 100), (-266, 266)]
    rows = [
        (0.0, 0.0, PI / 2),
        (0.0, 0.4318, 0.0),
        (0.15005, 0.0203, -PI / 2),
        (0.4318, 0.0, PI / 2),
        (0.0, 0.0, -PI / 2),
        (0.0, 0.0, 0.0),
    ]
    return Robot(
        [
            DHLink(0.0, d, a, alpha, "R", limits=(lo * DEG, hi * DEG))
            for (d, a, alpha), (lo, hi) in zip(rows, ranges, strict=True)
        ],
        end_effector=(0.0, 0.0, tool),
        name="PUMA 560",
    )


def ur5(tool: float = 0.0) -> Robot:
    """Universal Robots UR5, standard DH as Universal Robots publishes it, in metres.

    Universal Robots, "DH parameters for calculations of kinematics and dynamics"
    (support article, UR5 / CB-series): d1 = 0.089159, a2 = −0.425, a3 = −0.39225,
    d4 = 0.10915, d5 = 0.09465, d6 = 0.0823, α = (π/2, 0, 0, π/2, −π/2, 0). Ranges: the
    UR5 data sheet gives ±360° for every joint. At q = 0 the flange centre is at
    (−0.81725, −0.19145, −0.005491).

    Parameters
    ----------
    tool : float
        Tool length along the flange's z axis (m), added as the end-effector point.

    Examples
    --------
    >>> ur5().end_effector(np.zeros(6)).round(6) + 0.0
    array([-0.81725 , -0.19145 , -0.005491])
    """
    tool = check_finite_number(tool, "tool")
    rows = [
        (0.089159, 0.0, PI / 2),
        (0.0, -0.425, 0.0),
        (0.0, -0.39225, 0.0),
        (0.10915, 0.0, PI / 2),
        (0.09465, 0.0, -PI / 2),
        (0.0823, 0.0, 0.0),
    ]
    return Robot(
        [DHLink(0.0, d, a, alpha, "R", limits=(-2 * PI, 2 * PI)) for d, a, alpha in rows],
        end_effector=(0.0, 0.0, tool),
        name="UR5",
    )
