"""Held-out answers to lessons 9–12, written blind: from the student-facing notebooks, the
demo student's numbers and the slip codes of ``robotconf course rubric``, without reading
the diagnosis code or the other case files, and labelled before any check ran.

Every right answer was worked out by hand from ``rc.Assignment(lesson, "demo").numbers``;
every wrong one repeats that working with one slip made by hand (or two, or a slip the
rubric does not list: those are labelled ``None``).
"""

from __future__ import annotations

from .case import right, wrong

# Lesson 9, the demo student: l1 = 45, l2 = 40 (ex. 1); h = u = 40, f = 45 (ex. 2 and 4);
# h = 20, e = 5 (ex. 3). Right tables:
#   ex. 1: (q1, 0, 45, 0), (q2, 0, 40, 0)
#   ex. 2: x1 = +y: (q1 + pi/2, 40, 0, pi/2), (q2, 0, 40, 0), (q3, 0, 45, 0)
#   ex. 3: x2 = +y: (q1, 0, 0, 0), (pi/2, q2 + 20, 0, pi/2), (0, q3 + 5, 0, 0)
#   ex. 4 (modified, P = (45, 0, 0)): (q1 + pi/2, 40, 0, 0), (q2, 0, 0, pi/2), (q3, 0, 40, 0)
_EX2 = [("q1 + pi/2", 40, 0, "pi/2"), ("q2", 0, 40, 0), ("q3", 0, 45, 0)]
_EX3 = [("q1", 0, 0, 0), ("pi/2", "q2 + 20", 0, "pi/2"), (0, "q3 + 5", 0, 0)]
_EX4 = [("q1 + pi/2", 40, 0, 0), ("q2", 0, 0, "pi/2"), ("q3", 0, 40, 0)]

LESSON_9 = [
    # parallel axes: the common normal may sit at any height, d1 + d2 = 0
    right("right", "L9.ex1-normal-at-height-10", "L9.ex1", [
        ("q1", 10, 45, 0), ("q2", -10, 40, 0),
    ]),
    # x1 = -y: theta1 = q1 - pi/2, alpha1 = -pi/2, x2 half a turn from x1
    right("right", "L9.ex2-x1-along-minus-y", "L9.ex2", [
        ("q1 - pi/2", 40, 0, "-pi/2"), ("q2 + pi", 0, 40, 0), ("q3", 0, 45, 0),
    ]),
    # the column height as d1, the slide starting at 0
    right("right", "L9.ex3-height-in-row-1", "L9.ex3", [
        ("q1", 20, 0, 0), ("pi/2", "q2", 0, "pi/2"), (0, "q3 + 5", 0, 0),
    ]),
    right("right", "L9.ex3-x2-along-minus-y", "L9.ex3", [
        ["q1", 0, 0, 0], ["-pi/2", "q2 + 20", 0, "-pi/2"], [0, "q3 + 5", 0, 0],
    ]),
    right("right", "L9.ex4-x1-along-minus-y", "L9.ex4", [
        ("q1 - pi/2", 40, 0, 0), ("q2 + pi", 0, 0, "-pi/2"), ("q3", 0, 40, 0),
    ]),
    # exercise 1
    wrong("heldout-L9", "ex1-l1-as-d1", "L9.ex1", [
        ("q1", 45, 0, 0), ("q2", 0, 40, 0),
    ], "swapped_a_d"),
    wrong("heldout-L9", "ex1-link-lengths-swapped", "L9.ex1", [
        ("q1", 0, 40, 0), ("q2", 0, 45, 0),
    ], "a_value"),
    wrong("heldout-L9", "ex1-quarter-turn-offset", "L9.ex1", [
        ("q1 + pi/2", 0, 45, 0), ("q2", 0, 40, 0),
    ], "theta_offset"),
    wrong("heldout-L9", "ex1-a1-negative", "L9.ex1", [
        ("q1", 0, -45, 0), ("q2", 0, 40, 0),
    ], "a_sign"),
    wrong("heldout-L9", "ex1-joint-1-prismatic", "L9.ex1", [
        (0, "q1", 45, 0), ("q2", 0, 40, 0),
    ], "joint_type"),
    wrong("heldout-L9", "ex1-modified-table", "L9.ex1", [
        ("q1", 0, 0, 0), ("q2", 0, 45, 0),
    ], "convention"),
    wrong("heldout-L9", "ex1-offset-and-a-sign", "L9.ex1", [
        ("q1 + pi/2", 0, -45, 0), ("q2", 0, 40, 0),
    ], None),
    # exercise 2
    wrong("heldout-L9", "ex2-alpha1-negative", "L9.ex2", [
        ("q1 + pi/2", 40, 0, "-pi/2"), *_EX2[1:],
    ], "alpha_sign"),
    wrong("heldout-L9", "ex2-x1-minus-y-alpha-by-habit", "L9.ex2", [
        ("q1 - pi/2", 40, 0, "pi/2"), ("q2 + pi", 0, 40, 0), ("q3", 0, 45, 0),
    ], "alpha_sign"),
    wrong("heldout-L9", "ex2-theta1-offset-forgotten", "L9.ex2", [
        ("q1", 40, 0, "pi/2"), *_EX2[1:],
    ], "theta_offset"),
    wrong("heldout-L9", "ex2-h-as-a1", "L9.ex2", [
        ("q1 + pi/2", 0, 40, "pi/2"), *_EX2[1:],
    ], "swapped_a_d"),
    wrong("heldout-L9", "ex2-d1-negative", "L9.ex2", [
        ("q1 + pi/2", -40, 0, "pi/2"), *_EX2[1:],
    ], "d_sign"),
    wrong("heldout-L9", "ex2-f-for-h", "L9.ex2", [
        ("q1 + pi/2", 45, 0, "pi/2"), *_EX2[1:],
    ], "d_value"),
    wrong("heldout-L9", "ex2-tool-measured-from-joint-2", "L9.ex2", [
        *_EX2[:2], ("q3", 0, 85, 0),
    ], "a_value"),
    wrong("heldout-L9", "ex2-in-degrees", "L9.ex2", [
        ("q1 + 90", 40, 0, 90), *_EX2[1:],
    ], "degrees"),
    wrong("heldout-L9", "ex2-twist-forgotten", "L9.ex2", [
        ("q1 + pi/2", 40, 0, 0), *_EX2[1:],
    ], "twist"),
    wrong("heldout-L9", "ex2-tool-row-left-out", "L9.ex2", _EX2[:2], "row_count"),
    wrong("heldout-L9", "ex2-q2-q3-rows-swapped", "L9.ex2", [
        _EX2[0], ("q3", 0, 40, 0), ("q2", 0, 45, 0),
    ], "joint_variable"),
    wrong("heldout-L9", "ex2-alpha-sign-and-f-for-h", "L9.ex2", [
        ("q1 + pi/2", 45, 0, "-pi/2"), *_EX2[1:],
    ], None),
    # exercise 3
    wrong("heldout-L9", "ex3-theta2-offset-forgotten", "L9.ex3", [
        _EX3[0], (0, "q2 + 20", 0, "pi/2"), _EX3[2],
    ], "theta_offset"),
    wrong("heldout-L9", "ex3-alpha2-negative", "L9.ex3", [
        _EX3[0], ("pi/2", "q2 + 20", 0, "-pi/2"), _EX3[2],
    ], "alpha_sign"),
    wrong("heldout-L9", "ex3-height-subtracted", "L9.ex3", [
        _EX3[0], ("pi/2", "q2 - 20", 0, "pi/2"), _EX3[2],
    ], "d_sign"),
    wrong("heldout-L9", "ex3-column-height-forgotten", "L9.ex3", [
        _EX3[0], ("pi/2", "q2", 0, "pi/2"), _EX3[2],
    ], "d_value"),
    wrong("heldout-L9", "ex3-height-as-a1", "L9.ex3", [
        ("q1", 0, 20, 0), ("pi/2", "q2", 0, "pi/2"), _EX3[2],
    ], "swapped_a_d"),
    wrong("heldout-L9", "ex3-slide-as-revolute", "L9.ex3", [
        *_EX3[:2], ("q3", 5, 0, 0),
    ], "joint_type"),
    wrong("heldout-L9", "ex3-in-degrees", "L9.ex3", [
        _EX3[0], (90, "q2 + 20", 0, 90), _EX3[2],
    ], "degrees"),
    wrong("heldout-L9", "ex3-slide-pointing-down", "L9.ex3", [
        _EX3[0], ("pi/2", "20 - q2", 0, "pi/2"), _EX3[2],
    ], "joint_direction"),
    wrong("heldout-L9", "ex3-base-row-left-out", "L9.ex3", _EX3[1:], "row_count"),
    wrong("heldout-L9", "ex3-offset-and-height-forgotten", "L9.ex3", [
        _EX3[0], (0, "q2", 0, "pi/2"), _EX3[2],
    ], None),
    # exercise 4
    wrong("heldout-L9", "ex4-standard-table", "L9.ex4", _EX2, "convention"),
    wrong("heldout-L9", "ex4-twist-in-row-1", "L9.ex4", [
        ("q1 + pi/2", 40, 0, "pi/2"), ("q2", 0, 0, 0), ("q3", 0, 40, 0),
    ], "convention"),
    wrong("heldout-L9", "ex4-alpha1-negative", "L9.ex4", [
        _EX4[0], ("q2", 0, 0, "-pi/2"), _EX4[2],
    ], "alpha_sign"),
    wrong("heldout-L9", "ex4-theta1-offset-forgotten", "L9.ex4", [
        ("q1", 40, 0, 0), *_EX4[1:],
    ], "theta_offset"),
    wrong("heldout-L9", "ex4-h-as-a0", "L9.ex4", [
        ("q1 + pi/2", 0, 40, 0), *_EX4[1:],
    ], "swapped_a_d"),
    wrong("heldout-L9", "ex4-d1-negative", "L9.ex4", [
        ("q1 + pi/2", -40, 0, 0), *_EX4[1:],
    ], "d_sign"),
    wrong("heldout-L9", "ex4-a2-negative", "L9.ex4", [
        *_EX4[:2], ("q3", 0, -40, 0),
    ], "a_sign"),
    wrong("heldout-L9", "ex4-f-for-h", "L9.ex4", [
        ("q1 + pi/2", 45, 0, 0), *_EX4[1:],
    ], "d_value"),
    wrong("heldout-L9", "ex4-tool-as-a-row", "L9.ex4", [
        *_EX4, (0, 0, 45, 0),
    ], "row_count"),
    wrong("heldout-L9", "ex4-half-turn-twist", "L9.ex4", [
        _EX4[0], ("q2", 0, 0, "pi"), _EX4[2],
    ], "twist"),
    wrong("heldout-L9", "ex4-alpha-sign-and-offset", "L9.ex4", [
        ("q1", 40, 0, 0), ("q2", 0, 0, "-pi/2"), _EX4[2],
    ], None),
]

# Lesson 10, the demo student: l1 = l2 = 20, l3 = 45 mm, A = 2.2 rad, T = 2.5 s;
# q* = (90°, 45°, 30°); t3 = 3 s; B = 0.8 rad, f = 0.25 Hz, t4 = 0.8 s; dt = 0.1 s.
#   ex. 1: p = (0, 20 cos45° + 45 cos75°, 20 - 20 sin45° - 45 sin75°) = (0, 25.789, -37.609)
#   ex. 2: [0, -45, -45 (1 - cos 2.2) / 2.2] = [0, -45, -32.492]
#   ex. 3: q3 = 2.2 * 0.5 / 2.5 = 0.44, w = 0.88: 45 w (-sin q3, 0, -cos q3)
#          = (-16.867, 0, -35.828)
#   ex. 4: q3 = 0.76085, q3' = 0.38832, q3'' = -1.87731: (53.337, 0, 65.863)
#   ex. 5: 45 (1 - cos 2.112) / 0.1 = 681.83
LESSON_10 = [
    right("right", "L10.ex1-as-expressions", "L10.ex1", [
        "0", "20*cos(pi/4) + 45*cos(5*pi/12)", "20 - 20*sin(pi/4) - 45*sin(5*pi/12)",
    ]),
    right("right", "L10.ex2-mean-as-expression", "L10.ex2", [0, -45, "-45*(1 - cos(2.2))/2.2"]),
    right("right", "L10.ex4-three-digits", "L10.ex4", [53.3, 0, 65.9]),
    right("right", "L10.ex5-as-expression", "L10.ex5", "450*(1 - cos(2.112))"),
    # exercise 1
    wrong("heldout-L10", "ex1-at-q-zero", "L10.ex1", [65, 0, 20], "parking_pose"),
    wrong("heldout-L10", "ex1-q1-turned-back", "L10.ex1", [0, -25.789, -37.609],
          "rotation_direction"),
    wrong("heldout-L10", "ex1-every-joint-turned-back", "L10.ex1", [0, -25.789, 77.609],
          "rotation_direction_all"),
    wrong("heldout-L10", "ex1-degrees-in-radian-mode", "L10.ex1", [-23.293, 46.475, 20.432],
          "degrees_as_radians"),
    wrong("heldout-L10", "ex1-radians-in-degree-mode", "L10.ex1", [64.962, 1.7814, 18.698],
          "radians_as_degrees"),
    wrong("heldout-L10", "ex1-q3-as-absolute", "L10.ex1", [0, 53.113, -16.642],
          "absolute_angle"),
    wrong("heldout-L10", "ex1-l1-forgotten", "L10.ex1", [0, 25.789, -57.609], "missing_offset"),
    wrong("heldout-L10", "ex1-q2-q3-swapped", "L10.ex1", [0, 28.967, -33.467], "swapped_joints"),
    wrong("heldout-L10", "ex1-q1-left-out", "L10.ex1", [25.789, 0, -37.609], "joint_left_out"),
    wrong("heldout-L10", "ex1-with-the-1", "L10.ex1", [0, 25.789, -37.609, 1],
          "homogeneous_coordinate"),
    wrong("heldout-L10", "ex1-in-metres", "L10.ex1", [0, 0.025789, -0.037609], "unit_slip"),
    wrong("heldout-L10", "ex1-modules-rotate-then-shift", "L10.ex1", [0, 30.965, -48.643],
          "offset_after_rotation_all"),
    wrong("heldout-L10", "ex1-two-digits", "L10.ex1", [0, 26, -38], "coarse_rounding"),
    wrong("heldout-L10", "ex1-z-sign", "L10.ex1", [0, 25.789, 37.609], "sign_error"),
    wrong("heldout-L10", "ex1-absolute-and-l1-forgotten", "L10.ex1", [0, 53.113, -36.642], None),
    # exercise 2
    wrong("heldout-L10", "ex2-mean-as-midpoint", "L10.ex2", [0, -45, -22.5], "mean_as_midrange"),
    wrong("heldout-L10", "ex2-min-at-A", "L10.ex2", [0, -36.382, -32.492], "min_at_amplitude"),
    wrong("heldout-L10", "ex2-sin-of-mean-angle", "L10.ex2", [0, -45, -40.104], "mean_angle"),
    wrong("heldout-L10", "ex2-upward-displacement", "L10.ex2", [45, 0, 32.492], "sign_flipped"),
    wrong("heldout-L10", "ex2-mean-sign", "L10.ex2", [0, -45, 32.492], "sign_error"),
    wrong("heldout-L10", "ex2-in-metres", "L10.ex2", [0, -0.045, -0.032492], "unit_factor"),
    wrong("heldout-L10", "ex2-mean-in-degree-mode", "L10.ex2", [0, -45, -0.015077],
          "radians_as_degrees"),
    wrong("heldout-L10", "ex2-min-max-order", "L10.ex2", [-45, 0, -32.492], "swapped_ends"),
    wrong("heldout-L10", "ex2-two-digits", "L10.ex2", [0, -45, -32], "too_rounded"),
    wrong("heldout-L10", "ex2-z-not-displacement", "L10.ex2", [20, -25, -12.492], None),
    # exercise 3
    wrong("heldout-L10", "ex3-no-drop", "L10.ex3", [-19.041, 0, 34.722], "no_restart"),
    wrong("heldout-L10", "ex3-no-rate", "L10.ex3", [-19.167, 0, -40.714], "rate_left_out"),
    wrong("heldout-L10", "ex3-rate-T-over-A", "L10.ex3", [-21.781, 0, -46.266], "rate_inverted"),
    wrong("heldout-L10", "ex3-q3-in-degrees", "L10.ex3", [-3.0620, 0, -39.481], "degrees_in_sin"),
    wrong("heldout-L10", "ex3-all-signs", "L10.ex3", [16.867, 0, 35.828], "sign_flipped"),
    wrong("heldout-L10", "ex3-vz-sign", "L10.ex3", [-16.867, 0, 35.828], "sign_error"),
    wrong("heldout-L10", "ex3-sin-cos-swapped", "L10.ex3", [-35.828, 0, -16.867],
          "swapped_components"),
    wrong("heldout-L10", "ex3-in-m-per-s", "L10.ex3", [-0.016867, 0, -0.035828], "unit_factor"),
    wrong("heldout-L10", "ex3-no-drop-no-rate", "L10.ex3", [-21.637, 0, 39.457], None),
    wrong("heldout-L10", "ex3-radius-l2-plus-l3", "L10.ex3", [-24.364, 0, -51.752], None),
    # exercise 4
    wrong("heldout-L10", "ex4-centripetal-only", "L10.ex4", [-4.9146, 0, 4.6790],
          "centripetal_only"),
    wrong("heldout-L10", "ex4-tangential-only", "L10.ex4", [58.251, 0, 61.184],
          "tangential_only"),
    wrong("heldout-L10", "ex4-f-as-omega", "L10.ex4", [-1.6364, 0, 0.71501], "omega_as_f"),
    wrong("heldout-L10", "ex4-all-signs", "L10.ex4", [-53.337, 0, -65.863], "sign_flipped"),
    wrong("heldout-L10", "ex4-in-m-per-s2", "L10.ex4", [0.053337, 0, 0.065863], "unit_factor"),
    wrong("heldout-L10", "ex4-degree-mode", "L10.ex4", [-71.026, 0, 1.9698],
          "radians_as_degrees"),
    wrong("heldout-L10", "ex4-centripetal-with-f", "L10.ex4", [-1.7072, 0, 0.27364], None),
    wrong("heldout-L10", "ex4-q3-second-derivative-sign", "L10.ex4", [-63.166, 0, -56.505], None),
    # exercise 5
    wrong("heldout-L10", "ex5-central", "L10.ex5", 340.04, "central_for_backward"),
    wrong("heldout-L10", "ex5-q3-at-A", "L10.ex5", 714.83, "q3_at_amplitude"),
    wrong("heldout-L10", "ex5-jump-only", "L10.ex5", 68.183, "not_divided_by_dt"),
    wrong("heldout-L10", "ex5-backwards-jump", "L10.ex5", -681.83, "sign_error"),
    wrong("heldout-L10", "ex5-in-m-per-s", "L10.ex5", 0.68183, "unit_factor"),
    wrong("heldout-L10", "ex5-one-digit", "L10.ex5", 700, "too_rounded"),
    wrong("heldout-L10", "ex5-degree-mode", "L10.ex5", 0.30569, "radians_as_degrees"),
    wrong("heldout-L10", "ex5-q3-at-A-jump-only", "L10.ex5", 71.483, None),
    wrong("heldout-L10", "ex5-analytic-before-drop", "L10.ex5", -33.941, None),
]

# Lesson 11, the demo student: l1 = 1.5, l2 = 1, target (-1.31, 0.92); q_k = (0.8, 0.8),
# lambda = 0.25; far = (60, 45, 80) mm; q_w with q5 = 0.
#   ex. 1/2: cos q2 = -0.229167, q2 = ±1.80202, atan2(0.92, -1.31) = 2.52933:
#            (1.87570, 1.80202) and (3.18296 - 2 pi = -3.10023, -1.80202)
#   ex. 3: [0.5, 2.5]
#   ex. 4: dq = J^-1 e = (-1.01038, 4.42490): (-0.21038, 5.22490)
#   ex. 5: dq = (J^T J + 0.25 I)^-1 J^T e = (-0.09142, 2.03645): (0.70858, 2.83645)
#   ex. 6: |far - (0, 0, 20)| - 70 = sqrt(9225) - 70 = 26.047
#   ex. 7: [4, 6] (the last row of V^T: joints 4 and 6, opposite)
LESSON_11 = [
    right("right", "L11.ex1-elbow-up-wrapped", "L11.ex1", [-3.1002, -1.8020]),
    right("right", "L11.ex2-other-order", "L11.ex2", [[-3.1002, -1.8020], [1.8757, 1.8020]]),
    right("right", "L11.ex4-three-digits", "L11.ex4", [-0.210, 5.22]),
    right("right", "L11.ex5-three-digits", "L11.ex5", [0.709, 2.84]),
    right("right", "L11.ex6-as-expression", "L11.ex6", "sqrt(9225) - 70"),
    right("right", "L11.ex7-other-order", "L11.ex7", [6, 4]),
    # exercise 1
    wrong("heldout-L11", "ex1-atan", "L11.ex1", [-1.2659, 1.8020], "atan_quadrant"),
    wrong("heldout-L11", "ex1-inner-angle", "L11.ex1", [2.0166, 1.3396], "cosine_law_sign"),
    wrong("heldout-L11", "ex1-in-degrees", "L11.ex1", [107.47, 103.25], "degrees_as_radians"),
    wrong("heldout-L11", "ex1-x-sign-dropped", "L11.ex1", [-0.041366, 1.8020], "wrong_target"),
    wrong("heldout-L11", "ex1-q1-not-wrapped", "L11.ex1", [3.1830, -1.8020], "outside_limits"),
    wrong("heldout-L11", "ex1-two-digits", "L11.ex1", [1.9, 1.8], "too_rounded"),
    wrong("heldout-L11", "ex1-branches-mixed", "L11.ex1", [1.8757, -1.8020], "sign_error"),
    wrong("heldout-L11", "ex1-q1-q2-swapped", "L11.ex1", [1.8020, 1.8757], None),
    wrong("heldout-L11", "ex1-atan-in-degrees", "L11.ex1", [-72.530, 103.25], None),
    # exercise 2
    wrong("heldout-L11", "ex2-atan", "L11.ex2", [[-1.2659, 1.8020], [0.041366, -1.8020]],
          "atan_quadrant"),
    wrong("heldout-L11", "ex2-inner-angle", "L11.ex2", [[2.0166, 1.3396], [3.0420, -1.3396]],
          "cosine_law_sign"),
    wrong("heldout-L11", "ex2-in-degrees", "L11.ex2", [[107.47, 103.25], [-177.63, -103.25]],
          "degrees_as_radians"),
    wrong("heldout-L11", "ex2-x-sign-dropped", "L11.ex2",
          [[-0.041366, 1.8020], [1.2659, -1.8020]], "wrong_target"),
    wrong("heldout-L11", "ex2-q1-not-wrapped", "L11.ex2", [[1.8757, 1.8020], [3.1830, -1.8020]],
          "outside_limits"),
    wrong("heldout-L11", "ex2-one-q1-for-both", "L11.ex2", [[1.8757, 1.8020], [1.8757, -1.8020]],
          "sign_error"),
    # exercise 3
    wrong("heldout-L11", "ex3-from-zero", "L11.ex3", [0, 2.5], "inner_radius_zero"),
    wrong("heldout-L11", "ex3-ends-swapped", "L11.ex3", [2.5, 0.5], "swapped_ends"),
    wrong("heldout-L11", "ex3-l2-minus-l1", "L11.ex3", [-0.5, 2.5], "sign_error"),
    wrong("heldout-L11", "ex3-l2-as-inner", "L11.ex3", [1.0, 2.5], None),
    # exercise 4
    wrong("heldout-L11", "ex4-step-only", "L11.ex4", [-1.0104, 4.4249], "step_without_q"),
    wrong("heldout-L11", "ex4-tip-minus-target", "L11.ex4", [1.8104, -3.6249], "error_reversed"),
    wrong("heldout-L11", "ex4-transpose-for-inverse", "L11.ex4", [4.4536, 3.1586],
          "transpose_for_inverse"),
    wrong("heldout-L11", "ex4-transposed-jacobian-solved", "L11.ex4", [1.9541, 0.86851],
          "inverse_transposed"),
    wrong("heldout-L11", "ex4-q1-q2-swapped", "L11.ex4", [5.2249, -0.21038],
          "swapped_components"),
    wrong("heldout-L11", "ex4-two-digits", "L11.ex4", [-0.2, 5.2], "too_rounded"),
    wrong("heldout-L11", "ex4-reversed-step-only", "L11.ex4", [1.0104, -4.4249], None),
    # exercise 5
    wrong("heldout-L11", "ex5-lambda-squared", "L11.ex5", [0.19570, 4.1830], "lambda_squared"),
    wrong("heldout-L11", "ex5-newton", "L11.ex5", [-0.21038, 5.2249], "no_damping"),
    wrong("heldout-L11", "ex5-no-transpose-on-e", "L11.ex5", [0.60607, 0.19279],
          "transpose_left_out"),
    wrong("heldout-L11", "ex5-step-only", "L11.ex5", [-0.091416, 2.0365], "step_without_q"),
    wrong("heldout-L11", "ex5-tip-minus-target", "L11.ex5", [0.89142, -1.2365],
          "error_reversed"),
    wrong("heldout-L11", "ex5-lambda-on-J", "L11.ex5", [-1.9251, 8.1039], None),
    # exercise 6
    wrong("heldout-L11", "ex6-from-base", "L11.ex6", 39.659, "from_the_base"),
    wrong("heldout-L11", "ex6-radius-90", "L11.ex6", 6.0469, "radius_with_l1"),
    wrong("heldout-L11", "ex6-inside-sign", "L11.ex6", -26.047, "sign_error"),
    wrong("heldout-L11", "ex6-in-metres", "L11.ex6", 0.026047, "unit_factor"),
    wrong("heldout-L11", "ex6-one-digit", "L11.ex6", 30, "too_rounded"),
    wrong("heldout-L11", "ex6-base-and-radius-90", "L11.ex6", 19.659, None),
    wrong("heldout-L11", "ex6-radius-not-subtracted", "L11.ex6", 96.047, None),
    # exercise 7
    wrong("heldout-L11", "ex7-from-zero", "L11.ex7", [3, 5], "counted_from_0"),
    wrong("heldout-L11", "ex7-the-zero-joint", "L11.ex7", [5], "cause_for_joints"),
    wrong("heldout-L11", "ex7-whole-wrist", "L11.ex7", [4, 5, 6], None),
]

# Lesson 12, the demo student: v = 0.8 rad/s, a = 2.5 rad/s²; d1 = 2.4, d2 = 0.125 rad;
# d3 = 1.4 rad in T3 = 2 s; delta_4 = (-0.6, 1.2, -0.8), v = (1.5, 0.5, 1.2),
# a = (0.6, 2, 2); l1 = 0.9, l2 = 0.4 m; x* = 1.196 m, v = 0.26 m/s.
#   ex. 1: d1 >= v²/a = 0.256, a trapezoid: [0.32, 3.0 + 0.32, 0.8]
#   ex. 2: d2 < 0.256, a triangle: [sqrt(0.05), 2 sqrt(0.05), sqrt(0.3125)]
#          = [0.22361, 0.44721, 0.55902]
#   ex. 3: 15/8 * 1.4 / 2 = 1.3125
#   ex. 4: V = min(2.5, 0.41667, 1.5) = 0.41667 (joint 2), A = min(1, 1.6667, 2.5) = 1
#          (joint 1): T = 1/V + V/A = 2.81667 (alone: 2.0, 2.65, 1.26667 s)
#   ex. 5: [3] (the LIN out to 0.995 L)
#   ex. 6: cos q2 = 0.63947, sin q2 = 0.76882: 0.26 * 1.196 / (0.36 * 0.76882) = 1.12351
LESSON_12 = [
    right("right", "L12.ex1-as-expressions", "L12.ex1", ["0.8/2.5", "2.4/0.8 + 0.8/2.5", "0.8"]),
    right("right", "L12.ex2-as-expressions", "L12.ex2", [
        "sqrt(0.125/2.5)", "2*sqrt(0.125/2.5)", "sqrt(0.125*2.5)",
    ]),
    right("right", "L12.ex3-as-expression", "L12.ex3", "15/8*1.4/2"),
    right("right", "L12.ex4-four-digits", "L12.ex4", 2.817),
    right("right", "L12.ex6-four-digits", "L12.ex6", 1.124),
    # exercise 1
    wrong("heldout-L12", "ex1-ta-2v-over-a", "L12.ex1", [0.64, 3.64, 0.8], "accel_time_factor"),
    wrong("heldout-L12", "ex1-d-over-v", "L12.ex1", [0.32, 3.0, 0.8], "ramps_forgotten"),
    wrong("heldout-L12", "ex1-no-braking", "L12.ex1", [0.32, 3.16, 0.8], "not_at_rest_end"),
    wrong("heldout-L12", "ex1-triangle-formulas", "L12.ex1", [0.97980, 1.9596, 2.4495],
          "one_limit"),
    wrong("heldout-L12", "ex1-average-as-peak", "L12.ex1", [0.32, 3.32, 0.72289],
          "average_speed"),
    wrong("heldout-L12", "ex1-times-swapped", "L12.ex1", [3.32, 0.32, 0.8],
          "swapped_components"),
    wrong("heldout-L12", "ex1-one-digit-ta", "L12.ex1", [0.3, 3.3, 0.8], "too_rounded"),
    wrong("heldout-L12", "ex1-cruise-time", "L12.ex1", [0.32, 2.68, 0.8], None),
    wrong("heldout-L12", "ex1-ta-2v-over-a-no-ramps", "L12.ex1", [0.64, 3.0, 0.8], None),
    # exercise 2
    wrong("heldout-L12", "ex2-trapezoid-formulas", "L12.ex2", [0.32, 0.47625, 0.8],
          "triangle_as_trapezoid"),
    wrong("heldout-L12", "ex2-peak-at-limit", "L12.ex2", [0.22361, 0.44721, 0.8],
          "triangle_as_trapezoid"),
    wrong("heldout-L12", "ex2-no-braking", "L12.ex2", [0.31623, 0.31623, 0.79057],
          "not_at_rest_end"),
    wrong("heldout-L12", "ex2-half-forgotten", "L12.ex2", [0.15811, 0.31623, 0.39528],
          "accel_time_factor"),
    wrong("heldout-L12", "ex2-average-as-peak", "L12.ex2", [0.22361, 0.44721, 0.27951],
          "average_speed"),
    wrong("heldout-L12", "ex2-two-digits", "L12.ex2", [0.22, 0.45, 0.56], "too_rounded"),
    wrong("heldout-L12", "ex2-times-swapped", "L12.ex2", [0.44721, 0.22361, 0.55902],
          "swapped_components"),
    wrong("heldout-L12", "ex2-trapezoid-with-2v-over-a", "L12.ex2", [0.64, 0.79625, 0.8], None),
    # exercise 3
    wrong("heldout-L12", "ex3-cubic", "L12.ex3", 1.05, "cubic_quintic_swapped"),
    wrong("heldout-L12", "ex3-average", "L12.ex3", 0.7, "average_speed"),
    wrong("heldout-L12", "ex3-per-unit-time", "L12.ex3", 2.625, "normalized_time"),
    wrong("heldout-L12", "ex3-in-degrees", "L12.ex3", 75.201, "degrees_as_radians"),
    wrong("heldout-L12", "ex3-negative", "L12.ex3", -1.3125, "sign_error"),
    wrong("heldout-L12", "ex3-peak-acceleration", "L12.ex3", 2.0207, None),
    wrong("heldout-L12", "ex3-d3-left-out", "L12.ex3", 0.9375, None),
    # exercise 4
    wrong("heldout-L12", "ex4-slowest-joint", "L12.ex4", 2.65, "mixed_limits"),
    wrong("heldout-L12", "ex4-own-durations", "L12.ex4", [2.0, 2.65, 1.2667], "not_synchronized"),
    wrong("heldout-L12", "ex4-ta-2v-over-a", "L12.ex4", 3.2333, "accel_time_factor"),
    wrong("heldout-L12", "ex4-ramps-forgotten", "L12.ex4", 2.4, "ramps_forgotten"),
    wrong("heldout-L12", "ex4-no-braking", "L12.ex4", 2.6083, "not_at_rest_end"),
    wrong("heldout-L12", "ex4-two-digits", "L12.ex4", 2.8, "too_rounded"),
    wrong("heldout-L12", "ex4-sum-of-durations", "L12.ex4", 5.9167, None),
    wrong("heldout-L12", "ex4-fastest-joint", "L12.ex4", 1.2667, None),
    # exercise 5
    wrong("heldout-L12", "ex5-from-one", "L12.ex5", [4], "counted_from_1"),
    wrong("heldout-L12", "ex5-ptp-to-the-edge-too", "L12.ex5", [1, 3], "ptp_counted"),
    wrong("heldout-L12", "ex5-both-lins", "L12.ex5", [3, 5], None),
    wrong("heldout-L12", "ex5-ptp-too-from-one", "L12.ex5", [2, 4], None),
    # exercise 6
    wrong("heldout-L12", "ex6-joint-1", "L12.ex6", 0.30649, "joint_1_speed"),
    wrong("heldout-L12", "ex6-x-left-out", "L12.ex6", 0.93939, "x_left_out"),
    wrong("heldout-L12", "ex6-L-for-x", "L12.ex6", 1.2212, "length_for_x"),
    wrong("heldout-L12", "ex6-cos-q2", "L12.ex6", 1.3508, "cos_for_sin"),
    wrong("heldout-L12", "ex6-signed", "L12.ex6", -1.1235, "sign_error"),
    wrong("heldout-L12", "ex6-in-degrees", "L12.ex6", 64.373, "degrees_as_radians"),
    wrong("heldout-L12", "ex6-two-digits", "L12.ex6", 1.1, "too_rounded"),
    wrong("heldout-L12", "ex6-l1-for-x", "L12.ex6", 0.84545, "length_for_x"),
]

CASES = [*LESSON_9, *LESSON_10, *LESSON_11, *LESSON_12]
