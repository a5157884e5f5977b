"""The wrong configuration: the parking pose q = 0, one joint's q left out, two joints'
values exchanged."""

from __future__ import annotations

from .case import wrong

F = "joints"

CASES = [
    # worked out at q = 0
    wrong(
        F,
        "L2.ex4-identity",
        "L2.ex4",
        [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
        "parking_pose",
        must=True,
    ),
    wrong(F, "L3.ex4-at-parking", "L3.ex4", [70, 0, 20], "parking_pose", must=True),
    wrong(
        F,
        "L1.ex2-at-parking",
        "L1.ex2",
        [[1, 0, 0, 30], [0, 1, 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]],
        "parking_pose",
    ),
    wrong(F, "L1.ex3-at-parking", "L1.ex3", "[70, 0, 20]", "parking_pose"),
    wrong(F, "L4.ex4-at-parking", "L4.ex4", [50, 0, 30], "parking_pose"),
    wrong(F, "L5.ex5-at-parking", "L5.ex5", [70, 0, 20], "parking_pose"),
    wrong(F, "L3.pEE.q-at-parking", "L3.pEE.q", "[70.0, 0.0, 20.0]", "parking_pose"),
    wrong(
        F,
        "L6.puma.M2-at-parking",
        "L6.puma.M2",
        [[1, 0, 0, 0.4318], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1]],
        "parking_pose",
    ),
    # one joint left out
    wrong(
        F,
        "L3.pEE-q3-forgotten",
        "L3.pEE",
        "[70*cos(q1)*cos(q2), 70*sin(q1)*cos(q2), 20 - 70*sin(q2)]",
        "joint_left_out",
        must=True,
    ),
    wrong(
        F,
        "L3.pEE-q3-forgotten-unsummed",
        "L3.pEE",
        "[cos(q1)*(30*cos(q2) + 40*cos(q2)), sin(q1)*(30*cos(q2) + 40*cos(q2)),"
        " 20 - 30*sin(q2) - 40*sin(q2)]",
        "joint_left_out",
        must=True,
    ),
    wrong(F, "L3.ex4-q3-forgotten", "L3.ex4", [0, 70, 20], "joint_left_out", must=True),
    wrong(F, "L3.ex4-q1-forgotten", "L3.ex4", [30, 0, 60], "joint_left_out"),
    wrong(
        F, "L4.ex2-q3-forgotten", "L4.ex2", "[10*cos(q1), 10*sin(q1), q2 + 20]", "joint_left_out"
    ),
    wrong(
        F,
        "L4.ex3-q2-forgotten",
        "L4.ex3",
        "[(q3 + 10)*cos(q1), (q3 + 10)*sin(q1), 30]",
        "joint_left_out",
    ),
    wrong(
        F,
        "L4.ex1-q3-forgotten",
        "L4.ex1",
        "[[1, 0, 0, q1], [0, 1, 0, q2], [0, 0, 1, 50], [0, 0, 0, 1]]",
        "joint_left_out",
    ),
    wrong(
        F,
        "L6.ex3-q2-forgotten",
        "L6.ex3",
        "[[cos(q1), 0, sin(q1), 0.4318*cos(q1)], [sin(q1), 0, -cos(q1), 0.4318*sin(q1)],"
        " [0, 1, 0, 0], [0, 0, 0, 1]]",
        "joint_left_out",
    ),
    wrong(
        F,
        "L3.ex2-only-A2",
        "L3.ex2",
        "[[cos(q2), 0, sin(q2), 0], [0, 1, 0, 0], [-sin(q2), 0, cos(q2), l1], [0, 0, 0, 1]]",
        "joint_left_out",
    ),
    wrong(
        F,
        "L3.M3-q1-forgotten",
        "L3.M3",
        "[[cos(q2 + q3), 0, sin(q2 + q3), 30*cos(q2)], [0, 1, 0, 0],"
        " [-sin(q2 + q3), 0, cos(q2 + q3), 20 - 30*sin(q2)], [0, 0, 0, 1]]",
        "joint_left_out",
    ),
    wrong(
        F,
        "L4.scara.M2-q1-forgotten",
        "L4.scara.M2",
        "[[cos(q2), -sin(q2), 0, 30], [sin(q2), cos(q2), 0, 0], [0, 0, 1, 40], [0, 0, 0, 1]]",
        "joint_left_out",
    ),
    wrong(F, "L4.ex4-slide-forgotten", "L4.ex4", [20, 30, 30], "joint_left_out"),
    # two joints' values exchanged
    wrong(
        F,
        "L3.pEE-q2-q3-exchanged",
        "L3.pEE",
        "[cos(q1)*(30*cos(q3) + 40*cos(q2 + q3)), sin(q1)*(30*cos(q3) + 40*cos(q2 + q3)),"
        " 20 - 30*sin(q3) - 40*sin(q2 + q3)]",
        "swapped_joints",
    ),
    wrong(
        F, "L3.pEE.q-q2-q3-exchanged", "L3.pEE.q", [58.4272, 18.0736, -11.1473], "swapped_joints"
    ),
]
