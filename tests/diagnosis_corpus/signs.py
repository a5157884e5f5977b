"""Sign slips: a joint turning the wrong way (the sines of one rotation flipped), the same
slip in every module of a kind, a single sine, the twist α of a DH row."""

from __future__ import annotations

from .case import wrong

F = "signs"

CASES = [
    # the course's own wrong answers
    wrong(
        F,
        "L2.ex1-rx-sines-swapped",
        "L2.ex1",
        "[[1, 0, 0, 0], [0, cos(q1), sin(q1), 0], [0, -sin(q1), cos(q1), 20], [0, 0, 0, 1]]",
        "rotation_direction",
        must=True,
    ),
    wrong(
        F,
        "L2.ex2-ry-pattern-of-rx",
        "L2.ex2",
        "[[cos(q1), 0, -sin(q1), 30], [0, 1, 0, 0], [sin(q1), 0, cos(q1), 0], [0, 0, 0, 1]]",
        "rotation_direction",
        must=True,
    ),
    wrong(F, "L3.ex4-q3-turned-down", "L3.ex4", [0, 30, -20], "rotation_direction", must=True),
    wrong(
        F,
        "L4.ex3-elevation-sign",
        "L4.ex3",
        "[(q3 + 10)*cos(q2)*cos(q1), (q3 + 10)*cos(q2)*sin(q1), 30 + (q3 + 10)*sin(q2)]",
        "rotation_direction",
        must=True,
    ),
    wrong(F, "L8.ex2-determinant-sign", "L8.ex2", "[[-2*sin(q2)]]", "sign_error", must=True),
    wrong(F, "L7.ex2-vz-sign", "L7.ex2", [0, 35, 40], "sign_error", must=True),
    # one module turned the wrong way
    wrong(
        F,
        "L1.ex4-rz-sines-swapped",
        "L1.ex4",
        "[[cos(q1), sin(q1), 0, 30], [-sin(q1), cos(q1), 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]]",
        "rotation_direction",
        must=True,
    ),
    wrong(
        F,
        "L1.ex2-numbers-turned-back",
        "L1.ex2",
        [[0, 1, 0, 30], [-1, 0, 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]],
        "rotation_direction",
    ),
    wrong(
        F,
        "L2.ex4-numbers-sines-swapped",
        "L2.ex4",
        [[0.8776, 0.4794, 0, 0], [-0.4794, 0.8776, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
        "rotation_direction",
    ),
    wrong(
        F,
        "L3.ex1-ry-sign",
        "L3.ex1",
        "[[cos(q2), 0, -sin(q2), 0], [0, 1, 0, 0], [sin(q2), 0, cos(q2), l1], [0, 0, 0, 1]]",
        "rotation_direction",
    ),
    wrong(
        F,
        "L3.ex2-ry-sign-in-product",
        "L3.ex2",
        "[[cos(q1)*cos(q2), -sin(q1), -cos(q1)*sin(q2), 0],"
        " [sin(q1)*cos(q2), cos(q1), -sin(q1)*sin(q2), 0],"
        " [sin(q2), 0, cos(q2), l1], [0, 0, 0, 1]]",
        "rotation_direction",
    ),
    wrong(F, "L3.ex4-q1-turned-back", "L3.ex4", [0, -30, 60], "rotation_direction"),
    wrong(
        F,
        "L3.pEE-q2-sign",
        "L3.pEE",
        "[cos(q1)*(30*cos(q2) + 40*cos(q2 - q3)), sin(q1)*(30*cos(q2) + 40*cos(q2 - q3)),"
        " 20 + 30*sin(q2) + 40*sin(q2 - q3)]",
        "rotation_direction",
    ),
    wrong(
        F,
        "L6.ex1-puma-sines-swapped",
        "L6.ex1",
        [[0.866, 0.5, 0, 0.374], [-0.5, 0.866, 0, -0.2159], [0, 0, 1, 0], [0, 0, 0, 1]],
        "rotation_direction",
    ),
    wrong(
        F,
        "L6.ex3-puma-q2-sign",
        "L6.ex3",
        "[[cos(q1)*cos(q2), cos(q1)*sin(q2), sin(q1), 0.4318*cos(q1)*cos(q2)],"
        " [sin(q1)*cos(q2), sin(q1)*sin(q2), -cos(q1), 0.4318*sin(q1)*cos(q2)],"
        " [-sin(q2), cos(q2), 0, -0.4318*sin(q2)], [0, 0, 0, 1]]",
        "rotation_direction",
    ),
    # the same slip in every module of a kind: R_y learnt with the signs of R_x and R_z
    wrong(
        F,
        "L3.M3-both-ry-flipped",
        "L3.M3",
        "[[cos(q1)*cos(q2 + q3), -sin(q1), -cos(q1)*sin(q2 + q3), 30*cos(q1)*cos(q2)],"
        " [sin(q1)*cos(q2 + q3), cos(q1), -sin(q1)*sin(q2 + q3), 30*sin(q1)*cos(q2)],"
        " [sin(q2 + q3), 0, cos(q2 + q3), 20 + 30*sin(q2)], [0, 0, 0, 1]]",
        "rotation_direction_all",
        must=True,
    ),
    wrong(
        F,
        "L3.pEE-both-ry-flipped",
        "L3.pEE",
        "[cos(q1)*(30*cos(q2) + 40*cos(q2 + q3)), sin(q1)*(30*cos(q2) + 40*cos(q2 + q3)),"
        " 20 + 30*sin(q2) + 40*sin(q2 + q3)]",
        "rotation_direction_all",
        must=True,
    ),
    wrong(
        F,
        "L4.scara.M2-both-rz-flipped",
        "L4.scara.M2",
        "[[cos(q1 + q2), sin(q1 + q2), 0, 30*cos(q1)], [-sin(q1 + q2), cos(q1 + q2), 0,"
        " -30*sin(q1)], [0, 0, 1, 40], [0, 0, 0, 1]]",
        "rotation_direction_all",
    ),
    wrong(
        F,
        "L7.pEE-every-theta-flipped",
        "L7.pEE",
        "[cos(q1) + cos(q1 + q2), -sin(q1) - sin(q1 + q2), 0]",
        "rotation_direction_all",
    ),
    # a single sine with the wrong sign
    wrong(
        F,
        "L2.ex1-one-sine",
        "L2.ex1",
        "[[1, 0, 0, 0], [0, cos(q1), sin(q1), 0], [0, sin(q1), cos(q1), 20], [0, 0, 0, 1]]",
        "sign_error",
    ),
    wrong(
        F,
        "L3.ex1-one-sine",
        "L3.ex1",
        "[[cos(q2), 0, sin(q2), 0], [0, 1, 0, 0], [sin(q2), 0, cos(q2), l1], [0, 0, 0, 1]]",
        "sign_error",
    ),
    wrong(
        F,
        "L3.M3-one-entry-sign",
        "L3.M3",
        "[[cos(q1)*cos(q2 + q3), -sin(q1), -cos(q1)*sin(q2 + q3), 30*cos(q1)*cos(q2)],"
        " [sin(q1)*cos(q2 + q3), cos(q1), sin(q1)*sin(q2 + q3), 30*sin(q1)*cos(q2)],"
        " [-sin(q2 + q3), 0, cos(q2 + q3), 20 - 30*sin(q2)], [0, 0, 0, 1]]",
        "sign_error",
    ),
    # two slips: the Ry sign, and l1 forgotten as well
    wrong(
        F,
        "L3.ex2-ry-sign-and-l1-forgotten",
        "L3.ex2",
        "[[cos(q1)*cos(q2), -sin(q1), -cos(q1)*sin(q2), 0],"
        " [sin(q1)*cos(q2), cos(q1), -sin(q1)*sin(q2), 0],"
        " [sin(q2), 0, cos(q2), 0], [0, 0, 0, 1]]",
        "rotation_direction",
    ),
    # the twist of a DH row
    wrong(
        F,
        "L5.ex4-alpha-plus",
        "L5.ex4",
        "[[cos(q1), 0, sin(q1), 0], [sin(q1), 0, -cos(q1), 0], [0, 1, 0, 20], [0, 0, 0, 1]]",
        "sign_error",
    ),
    wrong(
        F,
        "L6.ex4-alpha-minus",
        "L6.ex4",
        "[[cos(q1), 0, -sin(q1), 0], [sin(q1), 0, cos(q1), 0], [0, -1, 0, 0.089159], [0, 0, 0, 1]]",
        "sign_error",
    ),
    wrong(F, "L5.ex5-alpha-plus", "L5.ex5", [0, 30, -20], "sign_error"),
]
