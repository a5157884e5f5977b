"""Denavit-Hartenberg slips: the other convention, d and a swapped or missing."""

from __future__ import annotations

from .case import wrong

F = "dh"

CASES = [
    # the course's own wrong answers
    wrong(
        F,
        "L5.ex1-modified-product",
        "L5.ex1",
        "[[cos(q1), -sin(q1), 0, 1], [0, 0, -1, -0.5], [sin(q1), cos(q1), 0, 0], [0, 0, 0, 1]]",
        "dh_convention",
        must=True,
    ),
    wrong(
        F,
        "L5.ex2-standard-product",
        "L5.ex2",
        "[[cos(q1), 0, sin(q1), cos(q1)], [sin(q1), 0, -cos(q1), sin(q1)], [0, 1, 0, 0.5],"
        " [0, 0, 0, 1]]",
        "dh_convention",
        must=True,
    ),
    wrong(
        F,
        "L6.ex4-craig-order",
        "L6.ex4",
        "[[cos(q1), -sin(q1), 0, 0], [0, 0, -1, -0.089159], [sin(q1), cos(q1), 0, 0],"
        " [0, 0, 0, 1]]",
        "dh_convention",
        must=True,
    ),
    wrong(
        F,
        "L5.ex4-missing-d",
        "L5.ex4",
        "[[cos(q1), 0, -sin(q1), 0], [sin(q1), 0, cos(q1), 0], [0, -1, 0, 0], [0, 0, 0, 1]]",
        "missing_offset",
        must=True,
    ),
    wrong(F, "L5.ex5-column-height-forgotten", "L5.ex5", [0, 30, 40], "missing_offset", must=True),
    wrong(
        F,
        "L6.ex2-flange-forgotten",
        "L6.ex2",
        [-0.81725, -0.10915, -0.005491],
        "missing_offset",
        must=True,
    ),
    # more
    wrong(
        F,
        "L5.ex4-craig-order",
        "L5.ex4",
        "[[cos(q1), -sin(q1), 0, 0], [0, 0, 1, 20], [-sin(q1), -cos(q1), 0, 0], [0, 0, 0, 1]]",
        "dh_convention",
    ),
    wrong(
        F,
        "L6.ex3-craig-order",
        "L6.ex3",
        "[[cos(q1 + q2), -sin(q1 + q2), 0, 0.4318*cos(q1)], [0, 0, -1, 0],"
        " [sin(q1 + q2), cos(q1 + q2), 0, 0.4318*sin(q1)], [0, 0, 0, 1]]",
        "dh_convention",
    ),
    wrong(
        F,
        "L5.ex3-length-before-turn",
        "L5.ex3",
        [[0.866, -0.5, 0, 2], [0.5, 0.866, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
        "dh_convention",
    ),
    wrong(
        F,
        "L5.ex1-d-a-swapped",
        "L5.ex1",
        "[[cos(q1), 0, sin(q1), 0.5*cos(q1)], [sin(q1), 0, -cos(q1), 0.5*sin(q1)],"
        " [0, 1, 0, 1], [0, 0, 0, 1]]",
        "swapped_d_a",
    ),
    wrong(
        F,
        "L5.ex3-d-a-swapped",
        "L5.ex3",
        [[0.866, -0.5, 0, 0], [0.5, 0.866, 0, 0], [0, 0, 1, 2], [0, 0, 0, 1]],
        "swapped_d_a",
    ),
    wrong(
        F,
        "L6.ex1-d-a-swapped",
        "L6.ex1",
        [[0.866, -0.5, 0, 0], [0.5, 0.866, 0, 0], [0, 0, 1, 0.4318], [0, 0, 0, 1]],
        "swapped_d_a",
    ),
    wrong(
        F,
        "L5.ex1-missing-a",
        "L5.ex1",
        "[[cos(q1), 0, sin(q1), 0], [sin(q1), 0, -cos(q1), 0], [0, 1, 0, 0.5], [0, 0, 0, 1]]",
        "missing_offset",
    ),
    wrong(
        F,
        "L5.ex1-alpha-minus",
        "L5.ex1",
        "[[cos(q1), 0, -sin(q1), cos(q1)], [sin(q1), 0, cos(q1), sin(q1)], [0, -1, 0, 0.5],"
        " [0, 0, 0, 1]]",
        "sign_error",
    ),
    wrong(
        F,
        "L6.ex4-missing-d",
        "L6.ex4",
        "[[cos(q1), 0, sin(q1), 0], [sin(q1), 0, -cos(q1), 0], [0, 1, 0, 0], [0, 0, 0, 1]]",
        "missing_offset",
    ),
    wrong(
        F,
        "L5.M3-every-a-forgotten",
        "L5.M3",
        "[[cos(q1)*cos(q2 + q3), -cos(q1)*sin(q2 + q3), -sin(q1), 0],"
        " [sin(q1)*cos(q2 + q3), -sin(q1)*sin(q2 + q3), cos(q1), 0],"
        " [-sin(q2 + q3), -cos(q2 + q3), 0, 20], [0, 0, 0, 1]]",
        "missing_offset_all",
    ),
]
