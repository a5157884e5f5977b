"""The DH-table checker: any table of the same robot passes, typical mistakes are named.

The robots are described independently of the tables that are checked against them
(modules for the planar arm and the paper's arm, the presets' published tables for SCARA
and the PUMA 560), and the tables were derived by hand from the frame-assignment recipe
of lesson 9. Every accepted table is also compared with the robot directly, by forward
kinematics at random joint values, so that "ok" is not the checker's word alone.
"""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc

PI = np.pi

# -- the robots ------------------------------------------------------------------------

PLANAR = rc.Robot([rc.Module("Rz"), rc.Module("Rz", a=(40, 0, 0))], end_effector=(30, 0, 0))
PAPER = rc.preset("paper")  # Rz; Ry a=(0,0,20); Ry a=(30,0,0); P=(40,0,0)
SCARA = rc.preset("scara")  # (q1,40,40,0) (q2,0,30,π) (0,q3,0,0) (q4,10,0,0)
PUMA3 = rc.Robot(list(rc.preset("puma560").modules[:3]))
CYLINDRICAL = rc.Robot(
    [rc.Module("Rz"), rc.Module("Tz", a=(0, 0, 20)), rc.Module("Tx")], end_effector=(10, 0, 0)
)

# robot -> list of (convention, tool point, table) derived by hand
RIGHT_TABLES = {
    "planar": (
        PLANAR,
        [
            ("standard", (0, 0, 0), [("q1", 0, 40, 0), ("q2", 0, 30, 0)]),
            # frame 1 on joint 1, frame 2 on joint 2; the last link is the tool point
            ("modified", (30, 0, 0), [("q1", 0, 0, 0), ("q2", 0, 40, 0)]),
        ],
    ),
    "paper": (
        PAPER,
        [
            ("standard", (0, 0, 0), [("q1", 20, 0, "-pi/2"), ("q2", 0, 30, 0), ("q3", 0, 40, 0)]),
            # the shoulder height may sit in row 1 or, along the same z0, nowhere else
            ("standard", (0, 0, 0), "[[q1, 20, 0, -pi/2], [q2, 0, 30, 0], [q3, 0, 40, 0]]"),
            ("modified", (40, 0, 0), [("q1", 20, 0, 0), ("q2", 0, 0, "-pi/2"), ("q3", 0, 30, 0)]),
        ],
    ),
    "scara": (
        SCARA,
        [
            (
                "standard",
                (0, 0, 0),
                [("q1", 40, 40, 0), ("q2", 0, 30, "pi"), (0, "q3", 0, 0), ("q4", 10, 0, 0)],
            ),
            # α = −π turns z the same way as π; the column height may move to row 2
            (
                "standard",
                (0, 0, 0),
                [("q1", 0, 40, 0), ("q2", 40, 30, "-pi"), (0, "q3", 0, 0), ("q4", 10, 0, 0)],
            ),
            (
                "modified",
                (0, 0, 0),
                [("q1", 40, 0, 0), ("q2", 0, 40, 0), (0, "q3", 30, "pi"), ("q4", 10, 0, 0)],
            ),
        ],
    ),
    "cylindrical": (
        CYLINDRICAL,
        [
            (
                "standard",
                (0, 0, 0),
                [("q1", 0, 0, 0), ("pi/2", "q2 + 20", 0, "pi/2"), (0, "q3 + 10", 0, 0)],
            ),
            # z0 and z1 are one line: the height may sit in row 1, the quarter turn either way
            (
                "standard",
                (0, 0, 0),
                [("q1", 20, 0, 0), ("-pi/2", "q2", 0, "-pi/2"), (0, "q3 + 10", 0, 0)],
            ),
        ],
    ),
    "puma3": (
        PUMA3,
        [
            (
                "standard",
                (0, 0, 0),
                [("q1", 0, 0, "pi/2"), ("q2", 0, 0.4318, 0), ("q3", 0.15005, 0.0203, "-pi/2")],
            ),
            # joints 2 and 3 are parallel: the shoulder offset d may sit in either row
            (
                "standard",
                (0, 0, 0),
                [("q1", 0, 0, "pi/2"), ("q2", 0.15005, 0.4318, 0), ("q3", 0, 0.0203, "-pi/2")],
            ),
            # Craig's rows hold a_(i-1), α_(i-1); the forearm offset a3 becomes the tool point
            (
                "modified",
                (0.0203, 0, 0),
                [("q1", 0, 0, 0), ("q2", 0, 0, "pi/2"), ("q3", 0.15005, 0.4318, 0)],
            ),
        ],
    ),
}


def _cases():
    for name, (robot, tables) in RIGHT_TABLES.items():
        for k, (convention, tool, table) in enumerate(tables):
            yield pytest.param(robot, convention, tool, table, id=f"{name}-{convention}-{k}")


def _fk_agrees(robot, table_rows, convention, tool):
    """Independent of the checker: the table's robot moves the tool like ``robot``."""
    dh = rc.Robot.from_dh(table_rows, convention=convention, end_effector=tool)
    q = np.random.default_rng(3).uniform(-PI, PI, (50, robot.n))
    return np.allclose(dh.end_effector(q), robot.end_effector(q), atol=1e-9)


@pytest.mark.parametrize(("robot", "convention", "tool", "table"), list(_cases()))
def test_hand_derived_tables_pass_and_describe_the_robot(robot, convention, tool, table):
    result = rc.check_dh_table(table, robot, convention=convention, end_effector=tool)
    assert result.ok, result.hints
    assert result.diagnosis is None and result.hints == [] and result.wrong_joints == []
    assert _fk_agrees(robot, result.rows, convention, tool)
    assert rc.assert_dh_table(table, robot, convention=convention, end_effector=tool).ok


def test_rows_are_read_as_offsets_and_joint_types():
    result = rc.check_dh_table(RIGHT_TABLES["scara"][1][0][2], SCARA)
    assert result.rows == (
        (0.0, 40.0, 40.0, 0.0, "R"),
        (0.0, 0.0, 30.0, PI, "R"),
        (0.0, 0.0, 0.0, 0.0, "P"),
        (0.0, 10.0, 0.0, 0.0, "R"),
    )


def test_other_answer_forms_pass():
    rows5 = [(0, 20, 0, -PI / 2, "R"), (0, 0, 30, 0, "r"), (0, 0, 40, 0, "revolute")]
    assert rc.check_dh_table(rows5, PAPER).ok
    assert rc.check_dh_table(np.array([[0, 0, 40, 0, "R"], [0, 0, 30, 0, "R"]]), PLANAR).ok
    named = [("q1", "l1", 0, "-pi/2"), ("q2", 0, "l2", 0), ("q3", 0, "l3", 0)]
    assert rc.check_dh_table(named, PAPER, values={"l1": 20, "l2": 30, "l3": 40}).ok
    rounded = [("q1", 20, 0, -1.5708), ("q2", 0, 30, 0), ("q3", 0, 40, 0)]
    assert rc.check_dh_table(rounded, PAPER).ok
    # the expected robot may itself be given as rows
    assert rc.check_dh_table(
        named,
        [(0, 20, 0, -PI / 2, "R"), (0, 0, 30, 0, "R"), ("q3", 0, 40, 0)],
        values={"l1": 20, "l2": 30, "l3": 40},
    ).ok


def test_a_theta_offset_written_with_the_variable_is_the_same_as_the_robot_with_it():
    bent = rc.Robot.from_dh([(PI / 2, 0, 40, 0, "R"), (0, 0, 30, 0, "R")])
    assert rc.check_dh_table([("q1 + pi/2", 0, 40, 0), ("q2", 0, 30, 0)], bent).ok
    result = rc.check_dh_table([("q1", 0, 40, 0), ("q2", 0, 30, 0)], bent)
    assert (result.ok, result.diagnosis) == (False, "theta_offset")


# -- typical mistakes ------------------------------------------------------------------

PAPER_STD = [("q1", 20, 0, "-pi/2"), ("q2", 0, 30, 0), ("q3", 0, 40, 0)]
PAPER_MOD = [("q1", 20, 0, 0), ("q2", 0, 0, "-pi/2"), ("q3", 0, 30, 0)]
PUMA_STD = [("q1", 0, 0, "pi/2"), ("q2", 0, 0.4318, 0), ("q3", 0.15005, 0.0203, "-pi/2")]

# name -> (robot, answer, diagnosis, wrong joints, words of the hint, check options)
MISTAKES = {
    "alpha sign": (
        PAPER,
        [("q1", 20, 0, "pi/2"), *PAPER_STD[1:]],
        "alpha_sign",
        [2, 3],
        "Row 1: check the sign of α1",
    ),
    "alpha sign puma": (
        PUMA3,
        [("q1", 0, 0, "-pi/2"), *PUMA_STD[1:]],
        "alpha_sign",
        [2, 3],
        "so joint 2 turns backwards",
    ),
    "a and d swapped": (
        PAPER,
        [("q1", 0, 20, "-pi/2"), *PAPER_STD[1:]],
        "swapped_a_d",
        [2, 3],
        "Row 1: a1 and d1 look swapped",
    ),
    "a and d swapped planar": (
        PLANAR,
        [("q1", 40, 0, 0), ("q2", 0, 30, 0)],
        "swapped_a_d",
        [2],
        "d1 is the distance along z0",
    ),
    "a and d swapped puma": (
        PUMA3,
        [*PUMA_STD[:2], ("q3", 0.0203, 0.15005, "-pi/2")],
        "swapped_a_d",
        [],
        "Row 3: a3 and d3 look swapped",
    ),
    "theta offset": (
        PAPER,
        [PAPER_STD[0], ("q2 + pi/2", 0, 30, 0), PAPER_STD[2]],
        "theta_offset",
        [3],
        "the joint's zero moved",
    ),
    "z not along joint 2": (
        PAPER,
        [("q1", 20, 0, 0), *PAPER_STD[1:]],
        "twist",
        [2, 3],
        "z1 must lie along that axis",
    ),
    "scara slide up": (
        SCARA,
        [("q1", 40, 40, 0), ("q2", 0, 30, 0), (0, "q3", 0, 0), ("q4", 10, 0, 0)],
        "twist",
        [3, 4],
        "α2 does not turn z1 onto joint 3's axis",
    ),
    "a sign": (
        PUMA3,
        [PUMA_STD[0], ("q2", 0, -0.4318, 0), PUMA_STD[2]],
        "a_sign",
        [3],
        "sign of a2",
    ),
    "d sign": (
        PUMA3,
        [*PUMA_STD[:2], ("q3", -0.15005, 0.0203, "-pi/2")],
        "d_sign",
        [],
        "sign of d3",
    ),
    "degrees": (
        PAPER,
        [("q1", 20, 0, -90), *PAPER_STD[1:]],
        "degrees",
        [2, 3],
        "look like degrees",
    ),
    "modified given, standard asked": (
        PAPER,
        PAPER_MOD,
        "convention",
        [2, 3],
        "read as a modified DH table",
    ),
    "standard given, modified asked": (
        PAPER,
        PAPER_STD,
        "convention",
        [1, 2, 3],
        "asks for the modified convention",
        {"convention": "modified", "end_effector": (40, 0, 0)},
    ),
    "planar modified as standard": (
        PLANAR,
        [("q1", 0, 0, 0), ("q2", 0, 40, 0)],
        "convention",
        [2],
        "read as a modified DH table",
    ),
    "row missing": (PAPER, [PAPER_STD[0], ("q2", 0, 70, 0)], "row_count", [], "A row is missing"),
    "extra constant row": (
        PLANAR,
        [("q1", 0, 40, 0), ("q2", 0, 30, 0), ("q3", 0, 0, 0)],
        "row_count",
        [],
        "not into a row of its own",
    ),
    # the last link's length written wrong: its a, named with the number written
    "tool length": (
        PAPER,
        [*PAPER_STD[:2], ("q3", 0, 45, 0)],
        "a_value",
        [],
        "Row 3: a3 = 45 is not the robot's",
    ),
    # a wrong height and a wrong length in the last row: no one constant explains it
    "tool constants": (
        PAPER,
        [*PAPER_STD[:2], ("q3", 5, 45, 0)],
        "end_effector",
        [],
        "Every joint axis is right, but the end-effector is not: check the constants of the "
        "last row (d3 and a3): the tool sits at the origin of frame 3.",
    ),
    "link lengths exchanged": (
        PAPER,
        [PAPER_STD[0], ("q2", 0, 40, 0), ("q3", 0, 30, 0)],
        "a_value",
        [3],
        "Rows 2 and 3: a2 and a3 look exchanged",
    ),
    "another length for a height": (
        PAPER,
        [("q1", 30, 0, "-pi/2"), *PAPER_STD[1:]],
        "d_value",
        [2, 3],
        "Row 1: d1 = 30 is not the robot's",
    ),
    # the quarter turn between x1 and x2 forgotten; z0 and z1 are one line, so θ1 could take
    # it too, but the hint points at the row where it usually goes missing
    "cylindrical theta offset": (
        CYLINDRICAL,
        [("q1", 0, 0, 0), (0, "q2 + 20", 0, "pi/2"), (0, "q3 + 10", 0, 0)],
        "theta_offset",
        [3],
        "check the constant in θ2",
    ),
    # one twist typed in degrees among radian offsets: only that angle is read as degrees
    "a twist in degrees": (
        CYLINDRICAL,
        [("q1", 0, 0, 0), ("pi/2", "q2 + 20", 0, 90), (0, "q3 + 10", 0, 0)],
        "degrees",
        [3],
        "Your angles look like degrees",
    ),
    # every link length negative: the arm turned by a half turn, but the slip is the sign
    "lengths negative": (
        PLANAR,
        [("q1", 0, -40, 0), ("q2", 0, -30, 0)],
        "a_sign",
        [2],
        "Rows 1 and 2: check the sign of a1 and a2",
    ),
    "modified tool forgotten": (
        PAPER,
        PAPER_MOD,
        "end_effector",
        [],
        "goes into the tool point",
        {"convention": "modified"},
    ),
    "two mistakes": (
        PAPER,
        [("q1", 20, 0, 0), ("q2", 0, 31, 0), PAPER_STD[2]],
        "axis",
        [2, 3],
        "Joint 2's axis is not where your table puts z1",
    ),
    "joint reversed": (
        PUMA3,
        [("q1", 0, 0, "-pi/2"), PUMA_STD[1], ("q3", 0.0203, 0.15005, "-pi/2")],
        "reversed_axis",
        [2, 3],
        "points the other way",
    ),
    "prismatic as revolute": (
        SCARA,
        [("q1", 40, 40, 0), ("q2", 0, 30, "pi"), ("q3", 0, 0, 0), ("q4", 10, 0, 0)],
        "joint_type",
        [],
        "joint 3 is prismatic",
    ),
    "no joint variable": (
        PAPER,
        [(0, 20, 0, "-pi/2"), *PAPER_STD[1:]],
        "joint_variable",
        [],
        "Row 1 has no joint variable",
    ),
    "wrong joint variable": (
        PAPER,
        [PAPER_STD[0], ("q1", 0, 30, 0), PAPER_STD[2]],
        "joint_variable",
        [],
        "Row 2 uses q1",
    ),
    "variable in a": (
        PAPER,
        [PAPER_STD[0], (0, 0, "q2", 0), PAPER_STD[2]],
        "joint_variable",
        [],
        "q2 stands in a",
    ),
    "minus q": (
        PAPER,
        [("-q1", 20, 0, "-pi/2"), *PAPER_STD[1:]],
        "joint_direction",
        [],
        "holds -q1",
    ),
    "letter contradicts": (
        PAPER,
        [("q1", 20, 0, "-pi/2", "P"), *PAPER_STD[1:]],
        "joint_type",
        [],
        "says 'P'",
    ),
}


@pytest.mark.parametrize("case", MISTAKES, ids=list(MISTAKES))
def test_typical_mistakes_fail_with_the_right_diagnosis(case):
    robot, answer, diagnosis, wrong, words, *rest = MISTAKES[case]
    options = rest[0] if rest else {}
    result = rc.check_dh_table(answer, robot, **options)
    assert not result.ok and not result
    assert result.diagnosis == diagnosis, result.hints
    assert result.wrong_joints == wrong
    assert words in " ".join(result.hints), result.hints
    with pytest.raises(AssertionError, match="not yet right"):
        rc.assert_dh_table(answer, robot, **options)


def test_hints_do_not_reveal_the_right_numbers_unless_asked():
    wrong = [("q1", 20, 0, "pi/2"), *PAPER_STD[1:]]
    hidden = str(rc.check_dh_table(wrong, PAPER))
    assert "-pi/2" not in hidden and "-1.57" not in hidden
    shown = rc.check_dh_table(wrong, PAPER, reveal=True).hints[0]
    assert "A right row 1: θ = 0, d = 20, a = 0, α = -pi/2" in shown


def test_no_answer_fails_kindly():
    result = rc.check_dh_table(None, PAPER)
    assert (result.ok, result.diagnosis) == (False, "no_answer")
    assert "replace None" in str(result)


@pytest.mark.parametrize(
    ("answer", "field"),
    [
        ("__import__('os').system('echo hi')", "student"),
        ("[[q1, 0, 1, 0], [q2, 0, 1]]", "student"),
        ([("q1", 0, 1)], "answer[0]"),
        ([("q1", 0, 1, 0, "X")], "answer[0][4]"),
        ([("q1", 0, "sqrt(-1)", 0)], "answer[0][2]"),
        ([("q1", 0, True, 0)], "answer[0][2]"),
        ([("q1", 0, "x7", 0)], "student"),
        ("", "student"),
        (42, "answer"),
        ([], "answer"),
    ],
)
def test_input_that_is_not_a_table_is_refused_naming_the_field(answer, field):
    with pytest.raises(rc.InvalidInputError) as info:
        rc.check_dh_table(answer, PLANAR)
    assert info.value.field == field


def test_bad_options_are_refused():
    table = [("q1", 0, 40, 0), ("q2", 0, 30, 0)]
    for options, field in [
        ({"convention": "craig"}, "convention"),
        ({"tol": 0}, "tol"),
        ({"tol": 2}, "tol"),
        ({"samples": 0}, "samples"),
        ({"values": {"q1": 3}}, "values"),
        ({"end_effector": (1, 2)}, "end_effector"),
    ]:
        with pytest.raises(rc.InvalidInputError) as info:
            rc.check_dh_table(table, PLANAR, **options)
        assert info.value.field == field, options
    with pytest.raises(rc.InvalidInputError, match="no joint variable") as info:
        rc.check_dh_table(table, [(0, 0, 40, 0), ("q2", 0, 30, 0)])
    assert info.value.field == "expected"


def test_the_result_reads_well_as_text_and_in_a_notebook():
    right = rc.check_dh_table([("q1", 0, 40, 0), ("q2", 0, 30, 0)], PLANAR)
    assert str(right) == "DH table (standard): correct." and bool(right)
    assert right._repr_html_() == "<div><b>✔ DH table (standard): correct.</b></div>"
    wrong = rc.check_dh_table([("q1", 40, 0, 0), ("q2", 0, 30, 0)], PLANAR)
    assert str(wrong).startswith("DH table (standard): not yet right.\n- Row 1: a1 and d1")
    assert "<li>Row 1: a1 and d1 look swapped." in wrong._repr_html_()
    assert repr(wrong) == "<DHTableCheck ok=False diagnosis='swapped_a_d'>"


def test_a_long_table_gets_the_mistake_in_its_row():
    row = (0, 1.0, 2.0, PI / 3, "R")
    robot = rc.Robot.from_dh([row] * 64)
    table = [(f"q{i}", 1.0, 2.0, "pi/3") for i in range(1, 65)]
    assert rc.check_dh_table(table, robot).ok
    table[40] = ("q41", 1.0, 2.0, "-pi/3")
    result = rc.check_dh_table(table, robot)
    assert (result.diagnosis, result.wrong_joints[0]) == ("alpha_sign", 42)
    assert result.hints[0].startswith("Row 41: check the sign of α41.")


def test_a_long_wrong_table_is_judged_within_the_repair_budget(monkeypatch):
    """64 revolute rows with their lengths permuted: no single repair or exchange explains
    them, and the check tries a bounded number of tables (each builds and samples a robot),
    not every pair of rows (about 4,000)."""
    from robotconf.teaching.checks import _dh_repairs

    tried = []
    compare = _dh_repairs.compare
    monkeypatch.setattr(_dh_repairs, "compare", lambda *args: tried.append(1) or compare(*args))
    robot = rc.Robot([rc.Module("Rz", a=(1 + 0.01 * i, 0, 0)) for i in range(64)])
    rows = [(f"q{i + 1}", 0, 1 + 0.01 * ((i * 7) % 64), 0) for i in range(64)]
    result = rc.check_dh_table(rows, robot)
    assert not result.ok
    assert len(tried) <= 3 * _dh_repairs._MAX_REPAIRS
