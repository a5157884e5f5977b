"""Only real numbers count as numbers; huge integers and clashing names are refused clearly.

numpy turns ``True`` into 1, ``1+0j`` into 1, a date into days since 1970 and ``"1.5"``
into 1.5. robotconf refuses all of them with an error naming the field, at the validators
and at every entry point that takes numbers, and still accepts ``Decimal``, ``Fraction``
and numpy's integer and float types with their exact values.
"""

from __future__ import annotations

import datetime
import json
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import robotconf as rc
from robotconf import signals as sg
from robotconf._validation import (
    MAX_INTEGER_DIGITS,
    as_float_array,
    check_configuration,
    check_finite_number,
    check_integer,
    check_joint_values,
    check_vector3,
    one_line,
)
from robotconf.kinematics import MAX_NAME_CHARS, robot_points

# (label, value, words the message must contain)
NOT_REAL_SCALARS = [
    ("complex", 1 + 0j, "complex"),
    ("numpy complex", np.complex128(2.0), "complex"),
    ("bool", True, "boolean"),
    ("numpy bool", np.bool_(False), "boolean"),
    ("datetime64", np.datetime64("2020-01-01"), "date"),
    ("timedelta64", np.timedelta64(3, "s"), "time span"),
    ("datetime", datetime.datetime(2020, 1, 1), "date or time"),
    ("timedelta", datetime.timedelta(seconds=3), "date or time"),
    ("text", "1.5", "text"),
    ("bytes", b"1.5", "text"),
    ("numpy text", np.str_("1.5"), "text"),
]

NOT_REAL_VECTORS = [
    ("complex array", np.array([1 + 0j, 0, 0]), "complex"),
    ("complex in a list", [0.0, 1j, 0.0], "complex"),
    ("bool array", np.array([True, False, True]), "boolean"),
    ("bool among ints", [1, True, 0], "boolean"),
    ("bool among floats", (0.5, 0.0, np.bool_(True)), "boolean"),
    ("dates", np.array(["2020-01-01"] * 3, dtype="datetime64[D]"), "date"),
    ("time spans", np.array([1, 2, 3], dtype="timedelta64[s]"), "time span"),
    ("numpy text", np.array(["1", "2", "3"]), "text"),
    ("numpy bytes", np.array([b"1", b"2", b"3"]), "text"),
    ("object text", np.array(["1", "2", "3"], dtype=object), "text"),
    ("object bool", np.array([1.0, True, 2.0], dtype=object), "boolean"),
    ("nested bool", [[0.0, 1.0], [True, 2.0]], "boolean"),
    ("text in a list", [1, "2", 3], "not numeric"),
]


@pytest.mark.parametrize(("label", "value", "words"), NOT_REAL_SCALARS)
def test_check_finite_number_refuses_what_is_not_a_real_number(label, value, words):
    with pytest.raises(rc.InvalidInputError, match=words) as caught:
        check_finite_number(value, "ax")
    assert caught.value.field == "ax"


@pytest.mark.parametrize(("label", "value", "words"), NOT_REAL_SCALARS + NOT_REAL_VECTORS)
def test_as_float_array_refuses_what_is_not_a_real_number(label, value, words):
    with pytest.raises(rc.InvalidInputError, match=words) as caught:
        as_float_array(value, "times", "numbers")
    assert caught.value.field == "times"
    assert "\n" not in str(caught.value)


@pytest.mark.parametrize(("label", "value", "words"), NOT_REAL_VECTORS)
def test_check_vector3_refuses_what_is_not_a_real_number(label, value, words):
    with pytest.raises(rc.InvalidInputError, match=words) as caught:
        check_vector3(value, "end_effector")
    assert caught.value.field == "end_effector"


@pytest.mark.parametrize(("label", "value", "words"), NOT_REAL_VECTORS)
def test_check_joint_values_and_configuration_refuse_them(label, value, words):
    q = np.asarray(value, dtype=object).ravel().tolist() if label.startswith("nested") else value
    with pytest.raises(rc.InvalidInputError, match=words) as caught:
        check_joint_values(q, len(np.ravel(np.asarray(q, dtype=object))), field="q")
    assert caught.value.field == "q"
    with pytest.raises(rc.InvalidInputError, match=words):
        check_configuration(q, len(np.ravel(np.asarray(q, dtype=object))))


@pytest.mark.parametrize(
    "value", [True, np.bool_(True), 3.0, 1 + 0j, "3", np.datetime64("2020"), Decimal(3)]
)
def test_check_integer_refuses_non_integers(value):
    with pytest.raises(rc.InvalidInputError, match="not an integer") as caught:
        check_integer(value, "samples", 1)
    assert caught.value.field == "samples"


def test_real_numbers_of_every_kind_keep_their_exact_value():
    assert check_finite_number(Decimal("1.25"), "x") == 1.25
    assert check_finite_number(Fraction(3, 8), "x") == 0.375
    assert check_finite_number(np.float32(0.5), "x") == 0.5
    assert check_finite_number(np.int8(-7), "x") == -7.0
    assert check_finite_number(np.uint64(2**63), "x") == 2.0**63
    assert check_vector3([Decimal(1), Fraction(1, 2), np.int16(3)], "a") == (1.0, 0.5, 3.0)
    q2d, batched = check_joint_values(np.array([[1, 2], [3, 4]], dtype=np.int32), 2)
    assert batched and q2d.dtype == np.float64 and q2d.tolist() == [[1.0, 2.0], [3.0, 4.0]]
    assert check_integer(np.int64(12), "n") == 12
    assert check_integer(2**128 - 1, "seed") == 2**128 - 1  # a 128-bit seed: 39 digits


def test_a_float64_array_passes_through_without_a_copy():
    q = np.zeros((100, 3))
    assert as_float_array(q, "q", "numbers") is q
    q2d, _ = check_joint_values(q, 3)
    assert q2d is q


# -- every entry point that takes numbers ----------------------------------------------


def paper() -> rc.Robot:
    return rc.preset("paper")


ENTRY_POINTS = [
    ("Module a", lambda v: rc.Module("Rz", a=(v, 0, 0)), "a"),
    ("Module q", lambda v: rc.Module("Tz", q=v), "q"),
    ("Module limits", lambda v: rc.Module("Rz", limits=(v, 2.0)), "limits[0]"),
    ("DHLink d", lambda v: rc.DHLink(d=v), "d"),
    ("DHLink alpha", lambda v: rc.DHLink(alpha=v), "alpha"),
    ("from_dh row", lambda v: rc.Robot.from_dh([(0, v, 1, 0, "R")]), "rows[0].d"),
    ("Robot end effector", lambda v: rc.Robot([rc.Module("Rz")], end_effector=(v, 0, 0)), ""),
    ("Robot.frame_poses", lambda v: paper().frame_poses([0, v, 0]), "q"),
    ("Robot.end_effector", lambda v: paper().end_effector([[0, 0, 0], [v, 0, 0]]), "q"),
    ("Robot.transfer_matrices", lambda v: paper().transfer_matrices([v, 0, 0]), "q"),
    ("Robot.jacobian", lambda v: paper().jacobian([0, 0, v]), "q"),
    ("Robot.with_q", lambda v: paper().with_q([v, 0, 0]), "q"),
    ("robot_points", lambda v: robot_points(paper(), [v, 0, 0]), "q"),
    ("joint_axes", lambda v: rc.joint_axes(paper(), [v, 0, 0]), "q"),
    ("Module.matrix", lambda v: rc.Module("Rz").matrix([0.0, v]), "q"),
    ("transfer_matrix", lambda v: rc.transfer_matrix("Tx", v), "q"),
    ("dh_matrix", lambda v: rc.dh_matrix(v, 0, 1, 0), "theta"),
    ("format_point", lambda v: rc.format_point("EE", [v, 0, 0]), "xyz"),
    ("workspace ranges", lambda v: rc.workspace(paper(), 10, ranges={"q1": (v, 1)}), "ranges"),
    ("Sine amplitude", lambda v: sg.Sine(amplitude=v), "amplitude"),
    ("Cubic duration", lambda v: sg.Cubic(duration=v), "duration"),
    ("Repeating values", lambda v: sg.RepeatingSequence([0, 1], [0, v]), "values"),
    ("Signal.value", lambda v: sg.Sine().value([0.0, v]), "t"),
    ("Signal.kinks", lambda v: sg.RepeatingSequence().kinks(v, 5.0), "t_start"),
    ("Signal * factor", lambda v: sg.Sine() * np.asarray(v)[()], "scale"),
    ("to_urdf scale", lambda v: rc.to_urdf(paper(), scale=v), "scale"),
]

BAD_NUMBERS = [
    ("complex", 1 + 0j),
    ("numpy complex", np.complex128(1.0)),
    ("bool", True),
    ("numpy bool", np.bool_(True)),
    ("datetime64", np.datetime64("2020-01-01")),
    ("timedelta64", np.timedelta64(1, "s")),
    ("text", "1.5"),
]


@pytest.mark.parametrize(("entry", "call", "field"), ENTRY_POINTS, ids=[e[0] for e in ENTRY_POINTS])
@pytest.mark.parametrize(("label", "value"), BAD_NUMBERS, ids=[b[0] for b in BAD_NUMBERS])
def test_entry_points_refuse_numbers_that_are_not_real(entry, call, field, label, value):
    if entry == "Signal * factor" and not isinstance(value, (np.number, complex)):
        pytest.skip("an operator declines what is no number at all (Python's TypeError)")
    with pytest.raises(rc.InvalidInputError) as caught:
        call(value)
    assert field in caught.value.field
    assert "\n" not in str(caught.value)


@pytest.mark.parametrize(("entry", "call", "field"), ENTRY_POINTS, ids=[e[0] for e in ENTRY_POINTS])
def test_entry_points_accept_decimal_and_fraction(entry, call, field):
    # 0.5 is a fine value everywhere (a duration, a scale, a time, an offset).
    for value in (Decimal("0.5"), Fraction(1, 2)):
        call(value)


@pytest.mark.parametrize(
    ("rotation", "words"),
    [
        (np.eye(3, dtype=bool), "boolean"),
        (np.eye(3, dtype=complex), "complex"),
        (np.eye(3).astype(str), "text"),
        (np.eye(2), "shape"),
        (np.full((3, 3), np.nan), "finite"),
    ],
)
def test_rpy_from_matrix_takes_a_real_rotation_only(rotation, words):
    with pytest.raises(rc.InvalidInputError, match=words) as caught:
        rc.io.rpy_from_matrix(rotation)
    assert caught.value.field == "rotation"


def test_accepted_exotic_numbers_give_the_real_numbers():
    robot = paper()
    exact = robot.end_effector([0.0, 0.5, 0.0])
    as_decimal = robot.end_effector([Decimal(0), Decimal("0.5"), Decimal(0)])
    as_fraction = robot.end_effector(np.array([0, Fraction(1, 2), 0], dtype=object))
    np.testing.assert_array_equal(as_decimal, exact)
    np.testing.assert_array_equal(as_fraction, exact)
    assert rc.Module("Tx", a=(Fraction(1, 4), 0, 0)).a == (0.25, 0.0, 0.0)
    assert sg.Ramp(slope=Decimal(2)).value(np.float32(1.5)) == 3.0


def test_time_arrays_of_dates_or_booleans_are_not_times():
    wave = sg.Sine()
    for t, words in [
        (np.array(["2020-01-01"], dtype="datetime64[D]"), "date"),
        (np.array([0.0, 1.0]) > 0.5, "boolean"),
        (np.array([0.5 + 0j]), "complex"),
    ]:
        for method in (wave.value, wave.velocity, wave.acceleration):
            with pytest.raises(rc.InvalidInputError, match=words) as caught:
                method(t)
            assert caught.value.field == "t"


# -- integers too long to print --------------------------------------------------------

HUGE = 10**5100  # Python refuses to turn more than 4300 digits into text


def test_huge_integers_are_refused_without_pythons_conversion_error():
    with pytest.raises(rc.InvalidInputError, match="digits") as caught:
        check_integer(HUGE, "samples", 1)
    assert caught.value.field == "samples"
    assert f"more than {MAX_INTEGER_DIGITS} digits" in str(caught.value)
    with pytest.raises(rc.InvalidInputError, match="too large for a float") as caught:
        check_finite_number(HUGE, "q")
    assert "about 5101 digits" in str(caught.value)
    with pytest.raises(rc.InvalidInputError, match="too large") as caught:
        check_vector3([HUGE, 0, 0], "a")
    assert caught.value.field == "a"


@pytest.mark.parametrize(
    ("call", "field"),
    [
        (lambda: rc.Module("Rz", a=(HUGE, 0, 0)), "a"),
        (lambda: rc.Module("Rz", q=HUGE), "q"),
        (lambda: rc.Module(HUGE), "kind"),
        (lambda: rc.Module("Rz", name=HUGE), "name"),
        (lambda: paper().index(HUGE), "index"),
        (lambda: paper().end_effector([HUGE, 0, 0]), "q"),
        (lambda: rc.Robot(paper().modules, active=HUGE), "active"),
        (lambda: rc.workspace(paper(), samples=HUGE), "samples"),
        (lambda: rc.workspace(paper(), 10, seed=HUGE), "seed"),
        (lambda: rc.workspace(paper(), 10, seed=10**MAX_INTEGER_DIGITS), "seed"),
        (lambda: sg.Constant(HUGE), "level"),
        (lambda: sg.signal_from_dict({"type": "Sine", "amplitude": HUGE}), "amplitude"),
        (lambda: sg.signal_from_dict({"type": "Sine", "amplitude": [HUGE]}), "amplitude"),
        (lambda: rc.io.robot_from_dict({"links": [{"type": "module", "kind": HUGE}]}), "kind"),
        (
            lambda: rc.io.robot_from_dict(
                {"links": [{"type": "module", "kind": "Rz", "a": [HUGE]}]}
            ),
            "a",
        ),
        (
            lambda: rc.Setup.from_dict({"format": "robotconf", "version": HUGE, "robot": {}}),
            "version",
        ),
    ],
)
def test_huge_integers_at_entry_points(call, field):
    with pytest.raises(rc.InvalidInputError) as caught:
        call()
    assert field in caught.value.field
    assert len(str(caught.value)) < 600


def test_a_5100_digit_integer_in_a_file_or_spec_is_refused_by_path():
    data = json.loads(paper().to_json())
    text = json.dumps({"format": "robotconf", "version": 1, "robot": data["robot"]})
    text = text.replace('"q": 0.0', '"q": ' + "9" * 5100, 1)
    with pytest.raises(rc.InvalidInputError, match="too many digits") as caught:
        rc.load_setup(text)
    assert caught.value.field == "robot.links[0].q"
    with pytest.raises(rc.InvalidInputError, match="too long") as caught:
        sg.parse_signal_spec("q3=sine:amplitude=" + "9" * 5100)
    assert caught.value.field == "signal"


def test_error_values_print_on_one_line():
    assert "\n" not in repr(one_line(np.zeros((3, 3))))
    assert "\n" not in repr(one_line(np.arange(100.0)))
    with pytest.raises(rc.InvalidInputError) as caught:
        paper().frame_poses(np.zeros((2, 2, 3)))
    assert caught.value.field == "q" and "\n" not in str(caught.value)
    assert "shape (2, 2, 3)" in str(caught.value)


# -- names -----------------------------------------------------------------------------


def test_two_modules_with_one_name_are_refused_naming_both():
    with pytest.raises(rc.InvalidInputError) as caught:
        rc.Robot([rc.Module("Rz", name="EEF"), rc.Module("Ry"), rc.Module("Ry", name="EEF")])
    assert caught.value.field == "modules[2].name"
    assert "modules[0] and modules[2] are both named 'EEF'" in str(caught.value)


def test_a_name_equal_to_another_modules_default_is_refused():
    with pytest.raises(rc.InvalidInputError) as caught:
        rc.Robot([rc.Module("Rz"), rc.Module("Ry", name="M1")])
    assert caught.value.field == "modules[1].name"
    assert "unnamed modules[0] is shown as 'M1'" in str(caught.value)
    # Its own default is fine, and so is any other unique name.
    robot = rc.Robot([rc.Module("Rz", name="M1"), rc.Module("Ry", name="elbow")])
    assert robot.module_names == ("M1", "elbow")


@pytest.mark.parametrize("name", ["EE", "ee", " q2 "])
def test_names_of_the_end_effector_or_another_coordinate_are_refused(name):
    with pytest.raises(rc.InvalidInputError, match="ambiguous") as caught:
        rc.Robot([rc.Module("Rz", name=name), rc.Module("Ry")])
    assert caught.value.field == "modules[0].name"


def test_editing_into_a_clash_is_refused_and_the_old_robot_survives():
    robot = rc.Robot([rc.Module("Rz", name="base"), rc.Module("Ry")])
    with pytest.raises(rc.InvalidInputError) as caught:
        robot.with_module(1, rc.Module("Ry", name="base"))
    assert caught.value.field == "modules[1].name"
    assert robot.module_names == ("base", "M2")


def test_points_of_every_robot_have_unique_names():
    robot = rc.Robot(
        [rc.Module("Rz", name="base"), rc.Module("Ry"), rc.Module("Ry", name="M9"), rc.Module("Tx")]
    )
    points = robot_points(robot, [0, 0, 0, 2])
    assert [point.name for point in points] == ["base", "M2", "M9", "M4", "EE"]
    np.testing.assert_array_equal(points[-1].position, [2.0, 0.0, 0.0])
    # The unnamed fourth module is shown as M4: naming the third one M4 would hide it.
    with pytest.raises(rc.InvalidInputError, match="shown as 'M4'"):
        robot.with_module(2, rc.Module("Ry", name="M4"))


@pytest.mark.parametrize(
    "call",
    [
        lambda name: rc.Module("Rz", name=name),
        lambda name: rc.DHLink(name=name),
        lambda name: rc.Robot([rc.Module("Rz")], name=name),
    ],
)
def test_names_longer_than_the_limit_are_refused(call):
    call("x" * MAX_NAME_CHARS)
    with pytest.raises(rc.InvalidInputError, match="longer than 200") as caught:
        call("x" * (MAX_NAME_CHARS + 1))
    assert caught.value.field == "name"
