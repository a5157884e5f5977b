"""Layout slips: the rotation part or the whole matrix transposed, rows or columns swapped."""

from __future__ import annotations

from .case import wrong

F = "layout"

CASES = [
    # the course's own wrong answers
    wrong(
        F,
        "L1.ex1-axes-as-rows",
        "L1.ex1",
        "[[0, 0, 1, 10], [1, 0, 0, 20], [0, 1, 0, 30], [0, 0, 0, 1]]",
        "transposed_rotation",
        must=True,
    ),
    wrong(
        F,
        "L4.ex1-translation-as-bottom-row",
        "L4.ex1",
        "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [q1, q2, q3 + 50, 1]]",
        "transposed_matrix",
        must=True,
    ),
    wrong(
        F,
        "L7.ex1-row-per-joint",
        "L7.ex1",
        "[[-sin(q1) - sin(q1 + q2), cos(q1) + cos(q1 + q2)], [-sin(q1 + q2), cos(q1 + q2)]]",
        "transposed_matrix",
        must=True,
    ),
    wrong(F, "L8.ex1-row-per-joint", "L8.ex1", [[0, 2], [0, 1]], "transposed_matrix", must=True),
    wrong(
        F,
        "L7.ex3-joints-2-3-exchanged",
        "L7.ex3",
        [[0, 40, 40], [30, 0, 0], [0, 0, -30]],
        "column_swap",
        must=True,
    ),
    # more of the same
    wrong(
        F,
        "L1.ex1-whole-transposed",
        "L1.ex1",
        [[0, 0, 1, 0], [1, 0, 0, 0], [0, 1, 0, 0], [10, 20, 30, 1]],
        "transposed_matrix",
    ),
    wrong(
        F,
        "L2.ex3-translation-as-bottom-row",
        "L2.ex3",
        "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, q1 + 20, 1]]",
        "transposed_matrix",
    ),
    wrong(
        F,
        "L5.ex3-whole-transposed",
        "L5.ex3",
        [[0.866, 0.5, 0, 0], [-0.5, 0.866, 0, 0], [0, 0, 1, 0], [1.7321, 1, 0, 1]],
        "transposed_matrix",
    ),
    wrong(
        F,
        "L3.M3-rotation-transposed",
        "L3.M3",
        "[[cos(q1)*cos(q2 + q3), sin(q1)*cos(q2 + q3), -sin(q2 + q3), 30*cos(q1)*cos(q2)],"
        " [-sin(q1), cos(q1), 0, 30*sin(q1)*cos(q2)],"
        " [cos(q1)*sin(q2 + q3), sin(q1)*sin(q2 + q3), cos(q2 + q3), 20 - 30*sin(q2)],"
        " [0, 0, 0, 1]]",
        "transposed_rotation",
    ),
    wrong(
        F,
        "L3.ex2-rotation-transposed",
        "L3.ex2",
        "[[cos(q1)*cos(q2), sin(q1)*cos(q2), -sin(q2), 0], [-sin(q1), cos(q1), 0, 0],"
        " [cos(q1)*sin(q2), sin(q1)*sin(q2), cos(q2), l1], [0, 0, 0, 1]]",
        "transposed_rotation",
    ),
    wrong(
        F,
        "L6.ex3-rows-1-2-swapped",
        "L6.ex3",
        "[[sin(q1)*cos(q2), -sin(q1)*sin(q2), -cos(q1), 0.4318*sin(q1)*cos(q2)],"
        " [cos(q1)*cos(q2), -cos(q1)*sin(q2), sin(q1), 0.4318*cos(q1)*cos(q2)],"
        " [sin(q2), cos(q2), 0, 0.4318*sin(q2)], [0, 0, 0, 1]]",
        "row_swap",
    ),
    wrong(
        F,
        "L5.ex1-columns-2-3-swapped",
        "L5.ex1",
        "[[cos(q1), sin(q1), 0, cos(q1)], [sin(q1), -cos(q1), 0, sin(q1)], [0, 0, 1, 0.5],"
        " [0, 0, 0, 1]]",
        "column_swap",
    ),
    wrong(F, "L7.ex2-x-y-exchanged", "L7.ex2", [35, 0, -40], "swapped_components"),
    wrong(
        F,
        "L4.ex2-x-y-exchanged",
        "L4.ex2",
        "[(q3 + 10)*sin(q1), (q3 + 10)*cos(q1), q2 + 20]",
        "row_swap",
    ),
]
