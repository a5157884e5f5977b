"""Wrong answers no known mistake explains (a typo, a botched entry, two unrelated slips):
the right outcome is no diagnosis, only the wrong entries named."""

from __future__ import annotations

from .case import wrong

F = "unexplained"

CASES = [
    wrong(
        F,
        "L3.M3l-height-typo",
        "L3.M3l",
        "[[cos(q1)*cos(q2 + q3), -sin(q1), cos(q1)*sin(q2 + q3), l2*cos(q1)*cos(q2)],"
        " [sin(q1)*cos(q2 + q3), cos(q1), sin(q1)*sin(q2 + q3), l2*sin(q1)*cos(q2)],"
        " [-sin(q2 + q3), 0, cos(q2 + q3), l1 + 7], [0, 0, 0, 1]]",
        None,
        must=True,
    ),
    wrong(
        F,
        "L1.ex4-digit-dropped",
        "L1.ex4",
        "[[cos(q1), -sin(q1), 0, 3], [sin(q1), cos(q1), 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]]",
        None,
    ),
    wrong(
        F,
        "L3.ex2-wrong-joint-in-one-entry",
        "L3.ex2",
        "[[cos(q1)*cos(q2), -sin(q1), cos(q1)*sin(q2), 0],"
        " [sin(q1)*cos(q2), cos(q1), sin(q1)*sin(q2), 0],"
        " [-sin(q2), 0, cos(q1), l1], [0, 0, 0, 1]]",
        None,
    ),
    wrong(F, "L3.ex4-height-off", "L3.ex4", [0, 30, 50], None),
    wrong(F, "L6.ex2-one-coordinate-off", "L6.ex2", [-0.81725, -0.19145, 0.1], None),
    wrong(
        F,
        "L2.ex3-offset-subtracted",
        "L2.ex3",
        "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, q1 - 20], [0, 0, 0, 1]]",
        None,
    ),
    # v_z left out is, at these rates, exactly joint 1's part alone (q̇3 makes all of v_z)
    wrong(F, "L7.ex2-vz-forgotten", "L7.ex2", [0, 35, 0], "one_joint_only"),
    wrong(F, "L8.ex2-cosine", "L8.ex2", "[[2*cos(q2)]]", None),
    wrong(
        F,
        "L1.ex1-origin-typo",
        "L1.ex1",
        [[0, 1, 0, 10], [0, 0, 1, 20], [1, 0, 0, 3], [0, 0, 0, 1]],
        None,
    ),
    wrong(
        F,
        "L3.pEE-angle-sum-botched",
        "L3.pEE",
        "[cos(q1)*(30*cos(q2) + 40*cos(q2)*cos(q3)), sin(q1)*(30*cos(q2) + 40*cos(q2)*cos(q3)),"
        " 20 - 30*sin(q2) - 40*sin(q2)*sin(q3)]",
        None,
    ),
    wrong(
        F,
        "L6.ex3-q1-missing-in-position",
        "L6.ex3",
        "[[cos(q1)*cos(q2), -cos(q1)*sin(q2), sin(q1), 0.4318*cos(q2)],"
        " [sin(q1)*cos(q2), -sin(q1)*sin(q2), -cos(q1), 0.4318*cos(q2)],"
        " [sin(q2), cos(q2), 0, 0.4318*sin(q2)], [0, 0, 0, 1]]",
        None,
    ),
    wrong(
        F,
        "L4.ex1-height-in-y",
        "L4.ex1",
        "[[1, 0, 0, q1], [0, 1, 0, q2 + 50], [0, 0, 1, q3], [0, 0, 0, 1]]",
        None,
    ),
    wrong(
        F,
        "L2.ex1-offset-in-y",
        "L2.ex1",
        "[[1, 0, 0, 0], [0, cos(q1), -sin(q1), 20], [0, sin(q1), cos(q1), 0], [0, 0, 0, 1]]",
        None,
    ),
    wrong(
        F,
        "L4.ex3-two-slips",
        "L4.ex3",
        "[(q3 + 10)*cos(q1), (q3 + 10)*sin(q1)*cos(q2), 30 - q3*sin(q2)]",
        None,
    ),
    wrong(
        F, "L4.ex2-height-halved", "L4.ex2", "[(q3 + 10)*cos(q1), (q3 + 10)*sin(q1), q2 + 10]", None
    ),
    wrong(
        F,
        "L5.ex1-length-not-turned",
        "L5.ex1",
        "[[cos(q1), 0, sin(q1), 1], [sin(q1), 0, -cos(q1), 1], [0, 1, 0, 0.5], [0, 0, 0, 1]]",
        None,
    ),
    wrong(
        F,
        "L3.ex2-translation-invented",
        "L3.ex2",
        "[[cos(q1)*cos(q2), -sin(q1), cos(q1)*sin(q2), l1*cos(q1)],"
        " [sin(q1)*cos(q2), cos(q1), sin(q1)*sin(q2), l1*sin(q1)],"
        " [-sin(q2), 0, cos(q2), l1], [0, 0, 0, 1]]",
        None,
    ),
]
