"""Right answers written otherwise than the solutions: other factorings, cos(-q), pi/2,
decimals, homogeneous 1, the product left unmultiplied."""

from __future__ import annotations

from .case import right

F = "right"

CASES = [
    right(
        F,
        "L1.ex1-floats",
        "L1.ex1",
        [[0.0, 1.0, 0.0, 10.0], [0.0, 0.0, 1.0, 20.0], [1.0, 0.0, 0.0, 30.0], [0.0, 0.0, 0.0, 1.0]],
    ),
    right(
        F,
        "L1.ex2-pi-half",
        "L1.ex2",
        "[[cos(pi/2), -sin(pi/2), 0, 30], [sin(pi/2), cos(pi/2), 0, 0], [0, 0, 1, 20],"
        " [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L1.ex2-float-noise",
        "L1.ex2",
        [[6.123e-17, -1.0, 0, 30], [1.0, 6.123e-17, 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]],
    ),
    right(F, "L1.ex3-formula", "L1.ex3", "[30 + 40*cos(pi/2), 40*sin(pi/2), 20]"),
    right(F, "L1.ex3-homogeneous", "L1.ex3", [30, 40, 20, 1]),
    right(
        F,
        "L1.ex4-cos-minus-q",
        "L1.ex4",
        "[[cos(-q1), sin(-q1), 0, 30], [-sin(-q1), cos(-q1), 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L2.ex1-shifted-phase",
        "L2.ex1",
        "[[1, 0, 0, 0], [0, sin(q1 + pi/2), -cos(q1 - pi/2), 0], [0, sin(q1), cos(q1), 20],"
        " [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L2.ex2-decimal-offset",
        "L2.ex2",
        "[[cos(q1), 0, sin(q1), 30.0], [0, 1, 0, 0], [-sin(q1), 0, cos(q1), 0.0], [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L2.ex3-order",
        "L2.ex3",
        "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 20 + q1], [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L2.ex4-4-decimals",
        "L2.ex4",
        [[0.8776, -0.4794, 0, 0], [0.4794, 0.8776, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
    ),
    right(
        F,
        "L2.ex4-formula",
        "L2.ex4",
        "[[cos(0.5), -sin(0.5), 0, 0], [sin(0.5), cos(0.5), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L3.ex1-l1-first",
        "L3.ex1",
        "[[cos(q2), 0, sin(q2), 0], [0, 1, 0, 0], [-sin(q2), 0, cos(q2), 1*l1], [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L3.ex2-commuted",
        "L3.ex2",
        "[[cos(q2)*cos(q1), -sin(q1), sin(q2)*cos(q1), 0], [cos(q2)*sin(q1), cos(q1),"
        " sin(q2)*sin(q1), 0], [-sin(q2), 0, cos(q2), l1], [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L3.ex2-product-to-sum",
        "L3.ex2",
        "[[(cos(q1 - q2) + cos(q1 + q2))/2, -sin(q1), (sin(q1 + q2) - sin(q1 - q2))/2, 0],"
        " [(sin(q1 + q2) + sin(q1 - q2))/2, cos(q1), (cos(q1 - q2) - cos(q1 + q2))/2, 0],"
        " [-sin(q2), 0, cos(q2), l1], [0, 0, 0, 1]]",
    ),
    right(F, "L3.ex3-sum", "L3.ex3", "[30 + 40, 0, 20]"),
    right(F, "L3.ex4-floats-homogeneous", "L3.ex4", "[0.0, 30.0, 60.0, 1]"),
    right(F, "L3.ex5-column", "L3.ex5", [[70], [0], [70]]),
    right(
        F,
        "L3.M3-sum-angles",
        "L3.M3",
        "[[cos(q1)*cos(q2 + q3), -sin(q1), cos(q1)*sin(q2 + q3), 30*cos(q1)*cos(q2)],"
        " [sin(q1)*cos(q2 + q3), cos(q1), sin(q1)*sin(q2 + q3), 30*sin(q1)*cos(q2)],"
        " [-sin(q2 + q3), 0, cos(q2 + q3), 20 - 30*sin(q2)], [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L3.pEE-factored",
        "L3.pEE",
        "[cos(q1)*(30*cos(q2) + 40*cos(q2 + q3)), sin(q1)*(30*cos(q2) + 40*cos(q2 + q3)),"
        " 20 - 30*sin(q2) - 40*sin(q2 + q3)]",
    ),
    right(
        F,
        "L3.pEE.q-formula",
        "L3.pEE.q",
        "[cos(0.3)*(30*cos(-0.4) + 40*cos(0.3)), sin(0.3)*(30*cos(-0.4) + 40*cos(0.3)),"
        " 20 - 30*sin(-0.4) - 40*sin(0.3)]",
    ),
    right(
        F,
        "L4.ex1-50-first",
        "L4.ex1",
        "[[1, 0, 0, q1], [0, 1, 0, q2], [0, 0, 1, 50 + q3], [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L4.ex2-expanded",
        "L4.ex2",
        "[q3*cos(q1) + 10*cos(q1), q3*sin(q1) + 10*sin(q1), 20 + q2]",
    ),
    right(
        F,
        "L4.ex3-expanded",
        "L4.ex3",
        "[cos(q1)*cos(q2)*q3 + 10*cos(q1)*cos(q2), sin(q1)*cos(q2)*q3 + 10*sin(q1)*cos(q2),"
        " 30 - q3*sin(q2) - 10*sin(q2)]",
    ),
    right(
        F,
        "L4.ex4-formula",
        "L4.ex4",
        "[30*cos(pi/2) + 20*cos(pi/2 - pi/2), 30*sin(pi/2) + 20*sin(0), 40 - 5 - 10]",
    ),
    right(
        F,
        "L5.ex1-pi-half",
        "L5.ex1",
        "[[cos(q1), -sin(q1)*cos(pi/2), sin(q1)*sin(pi/2), 1*cos(q1)],"
        " [sin(q1), cos(q1)*cos(pi/2), -cos(q1)*sin(pi/2), 1*sin(q1)],"
        " [0, sin(pi/2), cos(pi/2), 0.5], [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L5.ex2-fraction",
        "L5.ex2",
        "[[cos(q1), -sin(q1), 0, 1], [0, 0, -1, -1/2], [sin(q1), cos(q1), 0, 0], [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L5.ex3-3-decimals",
        "L5.ex3",
        [[0.866, -0.5, 0, 1.732], [0.5, 0.866, 0, 1.0], [0, 0, 1, 0], [0, 0, 0, 1]],
    ),
    right(
        F,
        "L5.ex3-exact",
        "L5.ex3",
        "[[sqrt(3)/2, -1/2, 0, sqrt(3)], [1/2, sqrt(3)/2, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L5.ex4-minus-pi-half",
        "L5.ex4",
        "[[cos(q1), -sin(q1)*cos(-pi/2), sin(q1)*sin(-pi/2), 0],"
        " [sin(q1), cos(q1)*cos(-pi/2), -cos(q1)*sin(-pi/2), 0],"
        " [0, sin(-pi/2), cos(-pi/2), 20], [0, 0, 0, 1]]",
    ),
    right(F, "L5.ex5-homogeneous", "L5.ex5", [0, 30, 60, 1]),
    right(
        F,
        "L6.ex1-3-decimals",
        "L6.ex1",
        [[0.866, -0.5, 0, 0.374], [0.5, 0.866, 0, 0.2159], [0, 0, 1, 0], [0, 0, 0, 1]],
    ),
    right(F, "L6.ex2-4-decimals", "L6.ex2", [-0.8172, -0.1915, -0.0055]),
    right(
        F,
        "L6.ex3-half-angles",
        "L6.ex3",
        "[[cos(q1)*cos(q2), -cos(q1)*sin(q2), sin(q1), 0.4318*cos(q1)*cos(q2)],"
        " [sin(q1)*cos(q2), -sin(q1)*sin(q2), -cos(q1), 0.4318*sin(q1)*cos(q2)],"
        " [2*sin(q2/2)*cos(q2/2), cos(q2), 0, 0.4318*sin(q2)], [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L6.ex4-written-d",
        "L6.ex4",
        "[[cos(q1), 0, sin(q1), 0], [sin(q1), 0, -cos(q1), 0], [0, 1, 0, 89.159/1000],"
        " [0, 0, 0, 1]]",
    ),
    right(
        F,
        "L7.ex1-expanded",
        "L7.ex1",
        "[[-sin(q1) - sin(q1)*cos(q2) - cos(q1)*sin(q2), -sin(q1)*cos(q2) - cos(q1)*sin(q2)],"
        " [cos(q1) + cos(q1)*cos(q2) - sin(q1)*sin(q2), cos(q1)*cos(q2) - sin(q1)*sin(q2)]]",
    ),
    right(F, "L7.ex3-floats", "L7.ex3", [[0.0, 40.0, 40.0], [30.0, 0.0, 0.0], [0.0, -30.0, 0.0]]),
    right(F, "L8.ex1-floats", "L8.ex1", [[0.0, 0.0], [2.0, 1.0]]),
    right(F, "L8.ex2-half-angle", "L8.ex2", "[[4*sin(q2/2)*cos(q2/2)]]"),
    right(F, "L6.ex2-3-decimals", "L6.ex2", [-0.817, -0.191, -0.005]),
    right(
        F,
        "L3.ex4-formula",
        "L3.ex4",
        "[30*cos(pi/2) + 40*cos(pi/2)*cos(-pi/2), 30*sin(pi/2) + 40*sin(pi/2)*cos(-pi/2),"
        " 20 - 40*sin(-pi/2)]",
    ),
]
