"""Angle units: degrees fed to sin and cos, a calculator in degree mode, degrees for the
joint angles only or for a DH table's constant angles."""

from __future__ import annotations

import numpy as np

from .case import wrong

F = "angles"

# What a calculator in degree mode gives for 0.5 (lesson 2, exercise 4).
_C, _S = float(np.cos(np.radians(0.5))), float(np.sin(np.radians(0.5)))

CASES = [
    # the course's own wrong answers
    wrong(
        F,
        "L1.ex3-np-cos-90",
        "L1.ex3",
        [30 + 40 * float(np.cos(90)), 40 * float(np.sin(90)), 20],
        "degrees_as_radians",
        must=True,
    ),
    wrong(
        F,
        "L2.ex4-degree-mode",
        "L2.ex4",
        [[_C, -_S, 0, 0], [_S, _C, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
        "radians_as_degrees",
        must=True,
    ),
    wrong(
        F,
        "L4.ex4-np-cos-90",
        "L4.ex4",
        [30 * float(np.cos(90)) + 20 * float(np.cos(0)), 30 * float(np.sin(90)), 25],
        "degrees_as_radians",
        must=True,
    ),
    wrong(
        F,
        "L5.ex3-dh-matrix-30",
        "L5.ex3",
        [[0.1543, 0.988, 0, 0.3085], [-0.988, 0.1543, 0, -1.9761], [0, 0, 1, 0], [0, 0, 0, 1]],
        "degrees_as_radians",
        must=True,
    ),
    wrong(
        F,
        "L6.ex1-dh-matrix-30",
        "L6.ex1",
        [[0.1543, 0.988, 0, 0.0666], [-0.988, 0.1543, 0, -0.4266], [0, 0, 1, 0], [0, 0, 0, 1]],
        "degrees_as_radians",
        must=True,
    ),
    # degrees fed to sin and cos
    wrong(
        F,
        "L1.ex2-cos-90",
        "L1.ex2",
        [[-0.4481, -0.894, 0, 30], [0.894, -0.4481, 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]],
        "degrees_as_radians",
    ),
    wrong(F, "L3.ex4-degrees", "L3.ex4", [-5.4114, 10.7968, 55.7599], "degrees_as_radians"),
    wrong(F, "L5.ex5-degrees", "L5.ex5", "[-5.4114, 10.7968, 55.7599]", "degrees_as_radians"),
    wrong(
        F,
        "L5.ex1-alpha-90",
        "L5.ex1",
        "[[cos(q1), -sin(q1)*cos(90), sin(q1)*sin(90), cos(q1)],"
        " [sin(q1), cos(q1)*cos(90), -cos(q1)*sin(90), sin(q1)],"
        " [0, sin(90), cos(90), 0.5], [0, 0, 0, 1]]",
        "degrees_as_radians",
    ),
    wrong(
        F,
        "L5.ex4-alpha-minus-90",
        "L5.ex4",
        "[[cos(q1), -sin(q1)*cos(-90), sin(q1)*sin(-90), 0],"
        " [sin(q1), cos(q1)*cos(-90), -cos(q1)*sin(-90), 0],"
        " [0, sin(-90), cos(-90), 20], [0, 0, 0, 1]]",
        "degrees_as_radians",
    ),
    # degrees for the joint angle only (the table's α = π/2 read right)
    wrong(
        F,
        "L6.puma.A1-q-in-degrees",
        "L6.puma.A1",
        [[0.1543, 0, -0.988, 0], [-0.988, 0, -0.1543, 0], [0, 1, 0, 0], [0, 0, 0, 1]],
        "degrees_as_radians",
        must=True,
    ),
    wrong(
        F,
        "L6.puma.M2-q-in-degrees",
        "L6.puma.M2",
        [
            [0.081, -0.1313, -0.988, 0.035],
            [-0.519, 0.8407, -0.1543, -0.2241],
            [0.8509, 0.5253, 0, 0.3674],
            [0, 0, 0, 1],
        ],
        "degrees_as_radians",
    ),
    # degrees fed to sin and cos, then rounded
    wrong(
        F,
        "L5.ex3-dh-matrix-30-two-decimals",
        "L5.ex3",
        [[0.15, 0.99, 0, 0.31], [-0.99, 0.15, 0, -1.98], [0, 0, 1, 0], [0, 0, 0, 1]],
        "degrees_as_radians",
    ),
    wrong(F, "L3.ex4-degrees-one-decimal", "L3.ex4", [-5.4, 10.8, 55.8], "degrees_as_radians"),
    wrong(F, "L1.ex3-np-cos-90-two-decimals", "L1.ex3", "[12.08, 35.76, 20]", "degrees_as_radians"),
    # a calculator in degree mode
    wrong(F, "L3.ex4-degree-mode", "L3.ex4", [69.9587, 1.9184, 21.0965], "radians_as_degrees"),
    wrong(
        F,
        "L2.ex4-degree-mode-two-decimals",
        "L2.ex4",
        [[1, -0.01, 0, 0], [0.01, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
        "radians_as_degrees",
    ),
    wrong(F, "L1.ex3-degree-mode", "L1.ex3", [69.985, 1.0965, 20], "radians_as_degrees"),
    wrong(F, "L3.pEE.q-degree-mode", "L3.pEE.q", [69.9978, 0.3665, 20.0], "radians_as_degrees"),
]
