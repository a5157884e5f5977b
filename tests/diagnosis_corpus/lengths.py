"""Lengths as a whole: the point's homogeneous coordinate 0, millimetres for metres (and
back), numbers rounded too coarsely."""

from __future__ import annotations

from .case import right, wrong

F = "lengths"

CASES = [
    # M·[P; 0] instead of M·[P; 1]
    wrong(
        F, "L1.ex3-point-as-direction", "L1.ex3", [0, 40, 0], "homogeneous_coordinate", must=True
    ),
    wrong(
        F, "L3.ex4-point-as-direction", "L3.ex4", [0, 0, 40], "homogeneous_coordinate", must=True
    ),
    wrong(F, "L3.ex3-point-as-direction", "L3.ex3", [40, 0, 0], "homogeneous_coordinate"),
    wrong(F, "L4.ex4-point-as-direction", "L4.ex4", [0, 0, -10], "homogeneous_coordinate"),
    wrong(
        F,
        "L4.ex3-point-as-direction",
        "L4.ex3",
        "[10*cos(q1)*cos(q2), 10*sin(q1)*cos(q2), -10*sin(q2)]",
        "homogeneous_coordinate",
    ),
    wrong(
        F,
        "L3.pEE-point-as-direction-4",
        "L3.pEE",
        "[40*cos(q1)*cos(q2 + q3), 40*sin(q1)*cos(q2 + q3), -40*sin(q2 + q3), 0]",
        "homogeneous_coordinate",
    ),
    # millimetres and metres
    wrong(F, "L6.ex2-in-millimetres", "L6.ex2", [-817.25, -191.45, -5.491], "unit_slip", must=True),
    wrong(
        F,
        "L6.ex1-a-in-millimetres",
        "L6.ex1",
        [[0.866, -0.5, 0, 373.95], [0.5, 0.866, 0, 215.9], [0, 0, 1, 0], [0, 0, 0, 1]],
        "unit_slip",
    ),
    wrong(
        F,
        "L6.ex3-a-in-millimetres",
        "L6.ex3",
        "[[cos(q1)*cos(q2), -cos(q1)*sin(q2), sin(q1), 431.8*cos(q1)*cos(q2)],"
        " [sin(q1)*cos(q2), -sin(q1)*sin(q2), -cos(q1), 431.8*sin(q1)*cos(q2)],"
        " [sin(q2), cos(q2), 0, 431.8*sin(q2)], [0, 0, 0, 1]]",
        "unit_slip",
    ),
    wrong(
        F,
        "L6.ex4-d-in-millimetres",
        "L6.ex4",
        "[[cos(q1), 0, sin(q1), 0], [sin(q1), 0, -cos(q1), 0], [0, 1, 0, 89.159], [0, 0, 0, 1]]",
        "unit_slip",
    ),
    wrong(F, "L3.ex4-in-metres", "L3.ex4", [0, 0.03, 0.06], "unit_slip"),
    wrong(
        F,
        "L3.pEE-in-metres",
        "L3.pEE",
        "[cos(q1)*(0.03*cos(q2) + 0.04*cos(q2 + q3)), sin(q1)*(0.03*cos(q2) + 0.04*cos(q2 + q3)),"
        " 0.02 - 0.03*sin(q2) - 0.04*sin(q2 + q3)]",
        "unit_slip",
    ),
    wrong(F, "L6.ex2-in-millimetres-one-decimal", "L6.ex2", [-817.3, -191.5, -5.5], "unit_slip"),
    # right to the digits kept, but too few digits
    # Within 0.5 % of 0.866 and 1.732: right under the course's rule (3 significant
    # digits pass); one decimal is too coarse.
    right(
        F,
        "L5.ex3-two-decimals",
        "L5.ex3",
        [[0.87, -0.5, 0, 1.73], [0.5, 0.87, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]],
    ),
    wrong(
        F,
        "L5.ex3-one-decimal",
        "L5.ex3",
        [[0.9, -0.5, 0, 1.7], [0.5, 0.9, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]],
        "coarse_rounding",
        must=True,
    ),
    wrong(F, "L6.ex2-two-decimals", "L6.ex2", [-0.82, -0.19, -0.01], "coarse_rounding", must=True),
    right(  # 0.88 and 0.48 are within 0.5 % of cos 0.5 and sin 0.5
        F,
        "L2.ex4-two-decimals",
        "L2.ex4",
        "[[0.88, -0.48, 0, 0], [0.48, 0.88, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
    ),
    wrong(
        F,
        "L2.ex4-one-decimal",
        "L2.ex4",
        "[[0.9, -0.5, 0, 0], [0.5, 0.9, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
        "coarse_rounding",
    ),
    wrong(
        F,
        "L6.ex1-two-decimals",
        "L6.ex1",
        [[0.87, -0.5, 0, 0.37], [0.5, 0.87, 0, 0.22], [0, 0, 1, 0], [0, 0, 0, 1]],
        "coarse_rounding",
    ),
    wrong(
        F,
        "L6.puma.M2-two-decimals",
        "L6.puma.M2",
        [[0.61, -0.61, 0.5, 0.26], [0.35, -0.35, -0.87, 0.15], [0.71, 0.71, 0, 0.31], [0, 0, 0, 1]],
        "coarse_rounding",
    ),
    wrong(F, "L3.pEE.q-whole-numbers", "L3.pEE.q", [63, 19, 20], "coarse_rounding"),
]
