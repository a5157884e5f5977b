"""Offsets and order: the product in the wrong order, an offset after the rotation, a
missing offset or end-effector point, every offset missing."""

from __future__ import annotations

from .case import wrong

F = "offsets"

CASES = [
    # the course's own wrong answers
    wrong(
        F,
        "L3.ex2-A2A1",
        "L3.ex2",
        "[[cos(q2)*cos(q1), -cos(q2)*sin(q1), sin(q2), 0], [sin(q1), cos(q1), 0, 0],"
        " [-sin(q2)*cos(q1), sin(q2)*sin(q1), cos(q2), l1], [0, 0, 0, 1]]",
        "wrong_order",
        must=True,
    ),
    wrong(
        F,
        "L4.ex2-rotation-last",
        "L4.ex2",
        "[q3 + 10*cos(q1), 10*sin(q1), q2 + 20]",
        "wrong_order",
        must=True,
    ),
    wrong(
        F,
        "L1.ex4-rot-then-trans",
        "L1.ex4",
        "[[cos(q1), -sin(q1), 0, 30*cos(q1)], [sin(q1), cos(q1), 0, 30*sin(q1)],"
        " [0, 0, 1, 20], [0, 0, 0, 1]]",
        "offset_after_rotation",
        must=True,
    ),
    wrong(
        F,
        "L3.ex1-rot-then-trans",
        "L3.ex1",
        "[[cos(q2), 0, sin(q2), l1*sin(q2)], [0, 1, 0, 0], [-sin(q2), 0, cos(q2), l1*cos(q2)],"
        " [0, 0, 0, 1]]",
        "offset_after_rotation",
        must=True,
    ),
    wrong(
        F,
        "L2.ex3-offset-forgotten",
        "L2.ex3",
        "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, q1], [0, 0, 0, 1]]",
        "missing_offset",
        must=True,
    ),
    wrong(F, "L3.ex3-origin-of-frame-3", "L3.ex3", [30, 0, 20], "missing_offset", must=True),
    wrong(F, "L3.ex5-pedestal-forgotten", "L3.ex5", [70, 0, 20], "missing_offset", must=True),
    wrong(F, "L4.ex4-point-forgotten", "L4.ex4", [20, 30, 35], "missing_offset"),
    wrong(
        F,
        "L4.ex1-base-height-forgotten",
        "L4.ex1",
        "[[1, 0, 0, q1], [0, 1, 0, q2], [0, 0, 1, q3], [0, 0, 0, 1]]",
        "missing_offset",
    ),
    wrong(F, "L3.ex4-origin-of-frame-3", "L3.ex4", [0, 30, 20], "missing_offset"),
    # wrong order
    wrong(
        F,
        "L3.M3-A3A2A1",
        "L3.M3",
        "[[cos(q1)*cos(q2 + q3), -sin(q1)*cos(q2 + q3), sin(q2 + q3), 20*sin(q3) + 30],"
        " [sin(q1), cos(q1), 0, 0],"
        " [-sin(q2 + q3)*cos(q1), sin(q1)*sin(q2 + q3), cos(q2 + q3), 20*cos(q3)],"
        " [0, 0, 0, 1]]",
        "wrong_order",
    ),
    wrong(
        F,
        "L6.ex3-A2A1",
        "L6.ex3",
        "[[cos(q1 + q2), 0, sin(q1 + q2), 0.4318*cos(q2)],"
        " [sin(q1 + q2), 0, -cos(q1 + q2), 0.4318*sin(q2)], [0, 1, 0, 0], [0, 0, 0, 1]]",
        "wrong_order",
    ),
    wrong(
        F,
        "L3.M3-A3A2A1-and-a-typo",
        "L3.M3",
        "[[cos(q1)*cos(q2 + q3), -sin(q1)*cos(q2 + q3), sin(q2 + q3), 20*sin(q3) + 30],"
        " [sin(q1), cos(q1), 0, 0],"
        " [-sin(q2 + q3)*cos(q1), sin(q1)*sin(q2 + q3), cos(q2 + q3), 20*cos(q3)],"
        " [0, 0, 5, 1]]",
        "wrong_order",
    ),
    # offset after the rotation
    wrong(
        F,
        "L2.ex2-rot-then-trans",
        "L2.ex2",
        "[[cos(q1), 0, sin(q1), 30*cos(q1)], [0, 1, 0, 0], [-sin(q1), 0, cos(q1), -30*sin(q1)],"
        " [0, 0, 0, 1]]",
        "offset_after_rotation",
    ),
    wrong(
        F,
        "L2.ex1-rot-then-trans",
        "L2.ex1",
        "[[1, 0, 0, 0], [0, cos(q1), -sin(q1), -20*sin(q1)], [0, sin(q1), cos(q1), 20*cos(q1)],"
        " [0, 0, 0, 1]]",
        "offset_after_rotation",
    ),
    wrong(
        F,
        "L3.M3-every-offset-after-rotation",
        "L3.M3",
        "[[cos(q1)*cos(q2 + q3), -sin(q1), sin(q2 + q3)*cos(q1),"
        " 10*(2*sin(q2) + 3*cos(q2 + q3))*cos(q1)],"
        " [sin(q1)*cos(q2 + q3), cos(q1), sin(q1)*sin(q2 + q3),"
        " 10*(2*sin(q2) + 3*cos(q2 + q3))*sin(q1)],"
        " [-sin(q2 + q3), 0, cos(q2 + q3), 20*cos(q2) - 30*sin(q2 + q3)], [0, 0, 0, 1]]",
        "offset_after_rotation_all",
    ),
    # a missing offset or point
    wrong(
        F,
        "L1.ex4-no-offset",
        "L1.ex4",
        "[[cos(q1), -sin(q1), 0, 0], [sin(q1), cos(q1), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
        "missing_offset",
    ),
    wrong(
        F,
        "L3.ex2-l1-forgotten",
        "L3.ex2",
        "[[cos(q1)*cos(q2), -sin(q1), cos(q1)*sin(q2), 0],"
        " [sin(q1)*cos(q2), cos(q1), sin(q1)*sin(q2), 0],"
        " [-sin(q2), 0, cos(q2), 0], [0, 0, 0, 1]]",
        "missing_offset",
    ),
    wrong(
        F,
        "L3.pEE-point-forgotten",
        "L3.pEE",
        "[30*cos(q1)*cos(q2), 30*sin(q1)*cos(q2), 20 - 30*sin(q2)]",
        "missing_offset",
    ),
    wrong(
        F, "L4.ex2-point-forgotten", "L4.ex2", "[q3*cos(q1), q3*sin(q1), q2 + 20]", "missing_offset"
    ),
    wrong(
        F,
        "L4.ex3-shoulder-height-forgotten",
        "L4.ex3",
        "[(q3 + 10)*cos(q1)*cos(q2), (q3 + 10)*sin(q1)*cos(q2), -(q3 + 10)*sin(q2)]",
        "missing_offset",
    ),
    wrong(F, "L4.ex4-link-3-offset-forgotten", "L4.ex4", [0, 30, 25], "missing_offset"),
    wrong(
        F,
        "L4.ex2-point-and-height-forgotten",
        "L4.ex2",
        "[q3*cos(q1), q3*sin(q1), q2]",
        "missing_offset",
    ),
    wrong(
        F,
        "L3.M3-every-offset-forgotten",
        "L3.M3",
        "[[cos(q1)*cos(q2 + q3), -sin(q1), cos(q1)*sin(q2 + q3), 0],"
        " [sin(q1)*cos(q2 + q3), cos(q1), sin(q1)*sin(q2 + q3), 0],"
        " [-sin(q2 + q3), 0, cos(q2 + q3), 0], [0, 0, 0, 1]]",
        "missing_offset_all",
    ),
]
