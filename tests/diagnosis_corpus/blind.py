"""A blind, held-out set: answers written as first-year students write them, each wrong one
derived by making the slip by hand, labelled with what a teacher would name, without
looking at the checker's diagnosis code or its output. Unlisted mistakes and real
combinations of slips are labelled ``None``."""

from __future__ import annotations

from .case import right, wrong

F = "blind"

CASES = [
    # ---------------------------------------------------------------- lesson 1
    wrong(
        F,
        "L1.ex1-axes-as-rows",
        "L1.ex1",
        [[0, 0, 1, 10], [1, 0, 0, 20], [0, 1, 0, 30], [0, 0, 0, 1]],
        "transposed_rotation",
    ),
    wrong(
        F,
        "L1.ex1-x1-y1-columns-exchanged",
        "L1.ex1",
        "[[1, 0, 0, 10], [0, 0, 1, 20], [0, 1, 0, 30], [0, 0, 0, 1]]",
        "column_swap",
    ),
    wrong(
        F,
        "L1.ex2-calculator-in-rad",
        "L1.ex2",
        [[-0.448, -0.894, 0, 30], [0.894, -0.448, 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]],
        "degrees_as_radians",
    ),
    wrong(
        F,
        "L1.ex2-not-turned",
        "L1.ex2",
        "[[1, 0, 0, 30], [0, 1, 0, 0], [0, 0, 1, 20], [0, 0, 0, 1]]",
        "parking_pose",
    ),
    wrong(F, "L1.ex3-point-with-0", "L1.ex3", [0, 40, 0], "homogeneous_coordinate"),
    right(F, "L1.ex3-homogeneous-4-vector", "L1.ex3", [30, 40, 20, 1]),
    wrong(
        F,
        "L1.ex4-offset-turned",
        "L1.ex4",
        "[[cos(q1), -sin(q1), 0, 30*cos(q1)], [sin(q1), cos(q1), 0, 30*sin(q1)],"
        " [0, 0, 1, 20], [0, 0, 0, 1]]",
        "offset_after_rotation",
    ),
    wrong(  # translation in the bottom row (graphics habit), rotation left as it was
        F,
        "L1.ex4-translation-in-last-row-only",
        "L1.ex4",
        "[[cos(q1), -sin(q1), 0, 0], [sin(q1), cos(q1), 0, 0], [0, 0, 1, 0], [30, 0, 20, 1]]",
        None,
    ),
    right(
        F,
        "L1.ex4-unsimplified-numbers",
        "L1.ex4",
        "[[cos(q1), -1*sin(q1), 0, 60/2], [sin(q1), cos(q1), 0, 0], [0, 0, 1, 20.0], [0, 0, 0, 1]]",
    ),
    # ---------------------------------------------------------------- lesson 2
    wrong(
        F,
        "L2.ex1-offset-turned",
        "L2.ex1",
        "[[1, 0, 0, 0], [0, cos(q1), -sin(q1), -20*sin(q1)], [0, sin(q1), cos(q1), 20*cos(q1)],"
        " [0, 0, 0, 1]]",
        "offset_after_rotation",
    ),
    wrong(  # rotation about x written for a module that turns about y
        F,
        "L2.ex2-rx-instead-of-ry",
        "L2.ex2",
        "[[1, 0, 0, 30], [0, cos(q1), -sin(q1), 0], [0, sin(q1), cos(q1), 0], [0, 0, 0, 1]]",
        None,
    ),
    wrong(
        F,
        "L2.ex2-whole-transposed",
        "L2.ex2",
        "[[cos(q1), 0, -sin(q1), 0], [0, 1, 0, 0], [sin(q1), 0, cos(q1), 0], [30, 0, 0, 1]]",
        "transposed_matrix",
    ),
    wrong(
        F,
        "L2.ex2-lower-sine-plus",
        "L2.ex2",
        "[[cos(q1), 0, sin(q1), 30], [0, 1, 0, 0], [sin(q1), 0, cos(q1), 0], [0, 0, 0, 1]]",
        "sign_error",
    ),
    right(
        F,
        "L2.ex2-sin-of-minus-q",
        "L2.ex2",
        "[[cos(q1), 0, sin(q1), 30], [0, 1, 0, 0], [sin(-q1), 0, cos(q1), 0], [0, 0, 0, 1]]",
    ),
    wrong(
        F,
        "L2.ex3-no-20",
        "L2.ex3",
        "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, q1], [0, 0, 0, 1]]",
        "missing_offset",
    ),
    wrong(
        F,
        "L2.ex4-calculator-in-deg",
        "L2.ex4",
        [[0.99996, -0.00873, 0, 0], [0.00873, 0.99996, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
        "radians_as_degrees",
    ),
    # Relabelled right when the course's rounding rule became "3 significant digits pass"
    # (within 0.5 %): 0.88 and 0.48 are within it. The answer is as written.
    right(
        F,
        "L2.ex4-two-decimals",
        "L2.ex4",
        [[0.88, -0.48, 0, 0], [0.48, 0.88, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
    ),
    wrong(
        F,
        "L2.ex4-rows-1-2-exchanged",
        "L2.ex4",
        [[0.4794, 0.8776, 0, 0], [0.8776, -0.4794, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
        "row_swap",
    ),
    right(
        F,
        "L2.ex4-as-text",
        "L2.ex4",
        "[[cos(0.5), -sin(0.5), 0, 0], [sin(0.5), cos(0.5), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
    ),
    # ---------------------------------------------------------------- lesson 3
    wrong(
        F,
        "L3.ex1-l1-turned",
        "L3.ex1",
        "[[cos(q2), 0, sin(q2), l1*sin(q2)], [0, 1, 0, 0], [-sin(q2), 0, cos(q2), l1*cos(q2)],"
        " [0, 0, 0, 1]]",
        "offset_after_rotation",
    ),
    wrong(
        F,
        "L3.ex2-A2-times-A1",
        "L3.ex2",
        "[[cos(q1)*cos(q2), -sin(q1)*cos(q2), sin(q2), 0], [sin(q1), cos(q1), 0, 0],"
        " [-cos(q1)*sin(q2), sin(q1)*sin(q2), cos(q2), l1], [0, 0, 0, 1]]",
        "wrong_order",
    ),
    wrong(
        F,
        "L3.ex2-rotation-transposed",
        "L3.ex2",
        "[[cos(q1)*cos(q2), sin(q1)*cos(q2), -sin(q2), 0], [-sin(q1), cos(q1), 0, 0],"
        " [cos(q1)*sin(q2), sin(q1)*sin(q2), cos(q2), l1], [0, 0, 0, 1]]",
        "transposed_rotation",
    ),
    wrong(F, "L3.ex3-point-with-0", "L3.ex3", [40, 0, 0], "homogeneous_coordinate"),
    wrong(F, "L3.ex4-calculator-in-rad", "L3.ex4", [-5.411, 10.797, 55.760], "degrees_as_radians"),
    wrong(F, "L3.ex4-at-parking", "L3.ex4", [70, 0, 20], "parking_pose"),
    wrong(F, "L3.ex4-q1-q2-exchanged", "L3.ex4", [40, 0, -10], "swapped_joints"),
    wrong(F, "L3.ex4-q1-not-turned", "L3.ex4", [30, 0, 60], "joint_left_out"),
    wrong(F, "L3.ex5-pedestal-forgotten", "L3.ex5", [70, 0, 20], "missing_offset"),
    right(F, "L3.ex5-sum-as-text", "L3.ex5", "[70, 0, 20 + 50]"),
    wrong(
        F,
        "L3.M3-q3-turned-back",
        "L3.M3",
        "[[cos(q1)*cos(q2 - q3), -sin(q1), cos(q1)*sin(q2 - q3), 30*cos(q1)*cos(q2)],"
        " [sin(q1)*cos(q2 - q3), cos(q1), sin(q1)*sin(q2 - q3), 30*sin(q1)*cos(q2)],"
        " [-sin(q2 - q3), 0, cos(q2 - q3), 20 - 30*sin(q2)], [0, 0, 0, 1]]",
        "rotation_direction",
    ),
    wrong(
        F,
        "L3.M3l-A3-A2-A1",
        "L3.M3l",
        "[[cos(q1)*cos(q2 + q3), -sin(q1)*cos(q2 + q3), sin(q2 + q3), l2 + l1*sin(q3)],"
        " [sin(q1), cos(q1), 0, 0],"
        " [-cos(q1)*sin(q2 + q3), sin(q1)*sin(q2 + q3), cos(q2 + q3), l1*cos(q3)], [0, 0, 0, 1]]",
        "wrong_order",
    ),
    right(
        F,
        "L3.M3l-angle-sums",
        "L3.M3l",
        "[[cos(q1)*cos(q2+q3), -sin(q1), cos(q1)*sin(q2+q3), l2*cos(q1)*cos(q2)],"
        " [sin(q1)*cos(q2+q3), cos(q1), sin(q1)*sin(q2+q3), l2*sin(q1)*cos(q2)],"
        " [-sin(q2+q3), 0, cos(q2+q3), l1 - l2*sin(q2)], [0, 0, 0, 1]]",
    ),
    wrong(F, "L3.pEE.q-calculator-in-deg", "L3.pEE.q", [69.998, 0.367, 20.0], "radians_as_degrees"),
    # ---------------------------------------------------------------- lesson 4
    wrong(
        F,
        "L4.ex1-q1-q2-exchanged",
        "L4.ex1",
        "[[1, 0, 0, q2], [0, 1, 0, q1], [0, 0, 1, q3 + 50], [0, 0, 0, 1]]",
        "swapped_joints",
    ),
    wrong(  # two slips: q2/q3 exchanged and the 20 forgotten
        F,
        "L4.ex2-exchanged-and-no-20",
        "L4.ex2",
        "[(q2 + 10)*cos(q1), (q2 + 10)*sin(q1), q3]",
        None,
    ),
    right(
        F,
        "L4.ex2-mixed-forms",
        "L4.ex2",
        "[q3*cos(q1) + 10*cos(q1), sin(q1)*(10 + q3), 20 + q2]",
    ),
    wrong(
        F,
        "L4.ex3-q3-left-out",
        "L4.ex3",
        "[10*cos(q1)*cos(q2), 10*sin(q1)*cos(q2), 30 - 10*sin(q2)]",
        "joint_left_out",
    ),
    wrong(  # spherical coordinates from maths class: q2 measured from the vertical
        F,
        "L4.ex3-elevation-from-vertical",
        "L4.ex3",
        "[(q3 + 10)*cos(q1)*sin(q2), (q3 + 10)*sin(q1)*sin(q2), 30 + (q3 + 10)*cos(q2)]",
        None,
    ),
    right(
        F,
        "L4.ex3-factored",
        "L4.ex3",
        "[cos(q1)*cos(q2)*(q3 + 10), sin(q1)*cos(q2)*(q3 + 10), 30 - sin(q2)*(q3 + 10)]",
    ),
    wrong(F, "L4.ex4-q2-turned-plus", "L4.ex4", [-20, 30, 25], "rotation_direction"),
    wrong(
        F,
        "L4.scara.M2-A2-A1",
        "L4.scara.M2",
        "[[cos(q1 + q2), -sin(q1 + q2), 0, 30], [sin(q1 + q2), cos(q1 + q2), 0, 0],"
        " [0, 0, 1, 40], [0, 0, 0, 1]]",
        "wrong_order",
    ),
    wrong(
        F,
        "L4.scara.M2-R-times-T",
        "L4.scara.M2",
        "[[cos(q1 + q2), -sin(q1 + q2), 0, 30*cos(q1 + q2)],"
        " [sin(q1 + q2), cos(q1 + q2), 0, 30*sin(q1 + q2)], [0, 0, 1, 40], [0, 0, 0, 1]]",
        "offset_after_rotation",
    ),
    right(
        F,
        "L4.scara.M2-angle-sums",
        "L4.scara.M2",
        "[[cos(q1+q2), -sin(q1+q2), 0, 30*cos(q1)], [sin(q1+q2), cos(q1+q2), 0, 30*sin(q1)],"
        " [0, 0, 1, 40], [0, 0, 0, 1]]",
    ),
    # ---------------------------------------------------------------- lesson 5
    wrong(
        F,
        "L5.ex1-modified-instead",
        "L5.ex1",
        "[[cos(q1), -sin(q1), 0, 1], [0, 0, -1, -0.5], [sin(q1), cos(q1), 0, 0], [0, 0, 0, 1]]",
        "dh_convention",
    ),
    wrong(
        F,
        "L5.ex1-d-a-exchanged",
        "L5.ex1",
        "[[cos(q1), 0, sin(q1), 0.5*cos(q1)], [sin(q1), 0, -cos(q1), 0.5*sin(q1)], [0, 1, 0, 1],"
        " [0, 0, 0, 1]]",
        "swapped_d_a",
    ),
    right(
        F,
        "L5.ex1-alpha-not-simplified",
        "L5.ex1",
        "[[cos(q1), -sin(q1)*cos(pi/2), sin(q1)*sin(pi/2), 1*cos(q1)],"
        " [sin(q1), cos(q1)*cos(pi/2), -cos(q1)*sin(pi/2), 1*sin(q1)],"
        " [0, sin(pi/2), cos(pi/2), 0.5], [0, 0, 0, 1]]",
    ),
    wrong(
        F,
        "L5.ex2-standard-instead",
        "L5.ex2",
        "[[cos(q1), 0, sin(q1), cos(q1)], [sin(q1), 0, -cos(q1), sin(q1)], [0, 1, 0, 0.5],"
        " [0, 0, 0, 1]]",
        "dh_convention",
    ),
    wrong(
        F,
        "L5.ex2-d-a-exchanged",
        "L5.ex2",
        "[[cos(q1), -sin(q1), 0, 0.5], [0, 0, -1, -1], [sin(q1), cos(q1), 0, 0], [0, 0, 0, 1]]",
        "swapped_d_a",
    ),
    right(
        F,
        "L5.ex2-fractions",
        "L5.ex2",
        "[[cos(q1), -sin(q1), 0, 1], [0, 0, -1, -1/2], [sin(q1), cos(q1), 0, 0], [0, 0, 0, 1]]",
    ),
    wrong(
        F,
        "L5.ex3-one-decimal",
        "L5.ex3",
        [[0.9, -0.5, 0, 1.7], [0.5, 0.9, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]],
        "coarse_rounding",
    ),
    wrong(  # a not turned with theta: Rx(0) Tx(2) Rz(q1), the modified reading
        F,
        "L5.ex3-a-not-turned",
        "L5.ex3",
        [[0.866, -0.5, 0, 2], [0.5, 0.866, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
        "dh_convention",
    ),
    right(
        F,
        "L5.ex3-pi-over-6",
        "L5.ex3",
        "[[cos(pi/6), -sin(pi/6), 0, 2*cos(pi/6)], [sin(pi/6), cos(pi/6), 0, 2*sin(pi/6)],"
        " [0, 0, 1, 0], [0, 0, 0, 1]]",
    ),
    wrong(
        F,
        "L5.ex4-modified-instead",
        "L5.ex4",
        "[[cos(q1), -sin(q1), 0, 0], [0, 0, 1, 20], [-sin(q1), -cos(q1), 0, 0], [0, 0, 0, 1]]",
        "dh_convention",
    ),
    wrong(F, "L5.ex5-q3-left-out", "L5.ex5", [0, 70, 20], "joint_left_out"),
    right(
        F,
        "L5.M3-compact",
        "L5.M3",
        "[[cos(q1)*cos(q2+q3), -cos(q1)*sin(q2+q3), -sin(q1),"
        " cos(q1)*(30*cos(q2) + 40*cos(q2+q3))],"
        " [sin(q1)*cos(q2+q3), -sin(q1)*sin(q2+q3), cos(q1), sin(q1)*(30*cos(q2) + 40*cos(q2+q3))],"
        " [-sin(q2+q3), -cos(q2+q3), 0, 20 - 30*sin(q2) - 40*sin(q2+q3)], [0, 0, 0, 1]]",
    ),
    # ---------------------------------------------------------------- lesson 6
    wrong(
        F,
        "L6.ex1-in-mm",
        "L6.ex1",
        [[0.866, -0.5, 0, 373.9], [0.5, 0.866, 0, 215.9], [0, 0, 1, 0], [0, 0, 0, 1]],
        "unit_slip",
    ),
    wrong(
        F,
        "L6.ex1-calculator-in-rad",
        "L6.ex1",
        [[0.1543, 0.9880, 0, 0.0666], [-0.9880, 0.1543, 0, -0.4266], [0, 0, 1, 0], [0, 0, 0, 1]],
        "degrees_as_radians",
    ),
    wrong(
        F,
        "L6.ex1-two-decimals",
        "L6.ex1",
        [[0.87, -0.5, 0, 0.37], [0.5, 0.87, 0, 0.22], [0, 0, 1, 0], [0, 0, 0, 1]],
        "coarse_rounding",
    ),
    wrong(  # two slips: calculator in radian mode and a in mm
        F,
        "L6.ex1-rad-mode-and-mm",
        "L6.ex1",
        [[0.1543, 0.9880, 0, 66.61], [-0.9880, 0.1543, 0, -426.63], [0, 0, 1, 0], [0, 0, 0, 1]],
        None,
    ),
    right(
        F,
        "L6.ex1-as-text",
        "L6.ex1",
        "[[cos(pi/6), -sin(pi/6), 0, 0.4318*cos(pi/6)],"
        " [sin(pi/6), cos(pi/6), 0, 0.4318*sin(pi/6)],"
        " [0, 0, 1, 0], [0, 0, 0, 1]]",
    ),
    wrong(F, "L6.ex2-in-mm", "L6.ex2", [-817.25, -191.45, -5.491], "unit_slip"),
    wrong(F, "L6.ex2-d6-forgotten", "L6.ex2", [-0.81725, -0.10915, -0.00549], "missing_offset"),
    wrong(F, "L6.ex2-a2-a3-taken-positive", "L6.ex2", [0.81725, -0.19145, -0.00549], "sign_error"),
    wrong(
        F,
        "L6.ex3-A2-A1",
        "L6.ex3",
        "[[cos(q1 + q2), 0, sin(q1 + q2), 0.4318*cos(q2)],"
        " [sin(q1 + q2), 0, -cos(q1 + q2), 0.4318*sin(q2)],"
        " [0, 1, 0, 0], [0, 0, 0, 1]]",
        "wrong_order",
    ),
    wrong(
        F,
        "L6.ex3-q1-left-out",
        "L6.ex3",
        "[[cos(q2), -sin(q2), 0, 0.4318*cos(q2)], [0, 0, -1, 0],"
        " [sin(q2), cos(q2), 0, 0.4318*sin(q2)],"
        " [0, 0, 0, 1]]",
        "joint_left_out",
    ),
    wrong(
        F,
        "L6.ex4-d-a-exchanged",
        "L6.ex4",
        "[[cos(q1), 0, sin(q1), 0.089159*cos(q1)], [sin(q1), 0, -cos(q1), 0.089159*sin(q1)],"
        " [0, 1, 0, 0], [0, 0, 0, 1]]",
        "swapped_d_a",
    ),
    wrong(
        F,
        "L6.puma.A1-rotation-transposed",
        "L6.puma.A1",
        [[0.866, 0.5, 0, 0], [0, 0, 1, 0], [0.5, -0.866, 0, 0], [0, 0, 0, 1]],
        "transposed_rotation",
    ),
    wrong(
        F,
        "L6.puma.M2-45-and-30-exchanged",
        "L6.puma.M2",
        [
            [0.6124, -0.3536, 0.7071, 0.2644],
            [0.6124, -0.3536, -0.7071, 0.2644],
            [0.5, 0.866, 0, 0.2159],
            [0, 0, 0, 1],
        ],
        "swapped_joints",
    ),
    wrong(
        F,
        "L6.puma.M2-q2-turned-back",
        "L6.puma.M2",
        [
            [0.6124, 0.6124, 0.5, 0.2644],
            [0.3536, 0.3536, -0.866, 0.1527],
            [-0.7071, 0.7071, 0, -0.3053],
            [0, 0, 0, 1],
        ],
        "rotation_direction",
    ),
    right(
        F,
        "L6.puma.M2-four-decimals",
        "L6.puma.M2",
        [
            [0.6124, -0.6124, 0.5, 0.2644],
            [0.3536, -0.3536, -0.8660, 0.1527],
            [0.7071, 0.7071, 0, 0.3053],
            [0, 0, 0, 1],
        ],
    ),
    # ---------------------------------------------------------------- lesson 7
    wrong(
        F,
        "L7.ex1-rows-are-joints",
        "L7.ex1",
        "[[-sin(q1) - sin(q1 + q2), cos(q1) + cos(q1 + q2)], [-sin(q1 + q2), cos(q1 + q2)]]",
        "transposed_matrix",
    ),
    wrong(  # d/dq cos q = +sin q
        F,
        "L7.ex1-derivative-of-cos-plus",
        "L7.ex1",
        "[[sin(q1) + sin(q1 + q2), sin(q1 + q2)], [cos(q1) + cos(q1 + q2), cos(q1 + q2)]]",
        None,
    ),
    wrong(  # the q1 inside cos(q1 + q2) not differentiated
        F,
        "L7.ex1-chain-rule-forgotten",
        "L7.ex1",
        "[[-sin(q1), -sin(q1 + q2)], [cos(q1), cos(q1 + q2)]]",
        None,
    ),
    wrong(
        F,
        "L7.ex1-one-sign",
        "L7.ex1",
        "[[-sin(q1) - sin(q1 + q2), sin(q1 + q2)], [cos(q1) + cos(q1 + q2), cos(q1 + q2)]]",
        "sign_error",
    ),
    right(
        F,
        "L7.ex1-expanded",
        "L7.ex1",
        "[[-sin(q1) - sin(q1)*cos(q2) - cos(q1)*sin(q2), -sin(q1 + q2)],"
        " [cos(q1) + cos(q1)*cos(q2) - sin(q1)*sin(q2), cos(q1 + q2)]]",
    ),
    wrong(F, "L7.ex2-in-m-per-s", "L7.ex2", [0, 0.035, -0.04], "unit_slip"),
    wrong(F, "L7.ex2-cross-product-reversed", "L7.ex2", [0, -35, 40], None),
    right(F, "L7.ex2-unsimplified", "L7.ex2", "[0.0, 0.5*70, -40]"),
    wrong(
        F,
        "L7.ex3-columns-as-rows",
        "L7.ex3",
        [[0, 30, 0], [40, 0, -30], [40, 0, 0]],
        "transposed_matrix",
    ),
    wrong(
        F,
        "L7.ex3-at-parking",
        "L7.ex3",
        [[0, 0, 0], [70, 0, 0], [0, -70, -40]],
        "parking_pose",
    ),
    wrong(
        F,
        "L7.ex3-columns-2-3-exchanged",
        "L7.ex3",
        [[0, 40, 40], [30, 0, 0], [0, 0, -30]],
        "column_swap",
    ),
    wrong(  # the second link's angle taken as q2 alone, not q1 + q2
        F,
        "L7.pEE-absolute-angle",
        "L7.pEE",
        "[cos(q1) + cos(q2), sin(q1) + sin(q2), 0]",
        None,
    ),
    wrong(
        F,
        "L7.pEE-first-link-forgotten",
        "L7.pEE",
        "[cos(q1 + q2), sin(q1 + q2), 0]",
        "missing_offset",
    ),
    # ---------------------------------------------------------------- lesson 8
    wrong(F, "L8.ex1-y-row-first", "L8.ex1", [[2, 1], [0, 0]], "row_swap"),
    right(
        F,
        "L8.ex1-evaluated-as-text",
        "L8.ex1",
        "[[-sin(0) - sin(0), -sin(0)], [cos(0) + cos(0), cos(0)]]",
    ),
    wrong(F, "L8.ex2-sin-q1", "L8.ex2", "[[2*sin(q1)]]", "swapped_joints"),
    wrong(  # ad + bc instead of ad - bc
        F,
        "L8.ex2-ad-plus-bc",
        "L8.ex2",
        "[[(-2*sin(q1) - sin(q1 + q2))*cos(q1 + q2) - sin(q1 + q2)*(2*cos(q1) + cos(q1 + q2))]]",
        None,
    ),
    right(F, "L8.ex2-double-angle", "L8.ex2", "[[4*sin(q2/2)*cos(q2/2)]]"),
]
