"""Every bad-input branch raises a ValueError subclass naming field, value and what is allowed."""

import numpy as np
import pytest

import robotconf as rc


def test_error_is_a_value_error_with_fields():
    with pytest.raises(ValueError) as info:
        rc.Module("Rw")
    error = info.value
    assert isinstance(error, rc.InvalidInputError)
    assert (error.field, error.value) == ("kind", "Rw")
    assert "Rx (1)" in error.allowed


@pytest.mark.parametrize(
    ("kind", "pattern"),
    [
        ("Rw", r"kind: unknown movement type 'Rw'; allowed: none \(0\), Rx \(1\)"),
        (7, r"kind: unknown movement code 7; allowed: .*Tz \(6\), fixed"),
        (-1, r"kind: unknown movement code -1"),
        (2.0, r"kind: expected a name or a code 0-6, got 2.0"),
        (True, r"kind: expected a name or a code 0-6, got True"),
        (None, r"kind: expected a name or a code 0-6, got None"),
    ],
)
def test_unknown_kind(kind, pattern):
    with pytest.raises(rc.InvalidInputError, match=pattern):
        rc.Module(kind)


@pytest.mark.parametrize(
    ("a", "pattern"),
    [
        ((0, 0), r"a: expected shape \(3,\), got \(2,\): \(0, 0\); allowed: 3 finite numbers"),
        ((0, 0, 0, 0), r"a: expected shape \(3,\), got \(4,\)"),
        ((0, float("nan"), 0), r"a: entry 1 must be finite, got \(0.0, nan, 0.0\)"),
        ((0, 0, float("inf")), r"a: entry 2 must be finite"),
        ("0,0,20", r"a: text is not a vector: '0,0,20'"),
        (("x", 0, 0), r"a: not numeric: \('x', 0, 0\)"),
        ([[0, 0, 0]], r"a: expected shape \(3,\), got \(1, 3\)"),
    ],
)
def test_bad_offsets(a, pattern):
    with pytest.raises(rc.InvalidInputError, match=pattern):
        rc.Module("Rz", a=a)


@pytest.mark.parametrize(
    ("q", "pattern"),
    [
        (float("nan"), r"q: must be finite, got nan; allowed: a finite real number"),
        (float("-inf"), r"q: must be finite, got -inf"),
        ("1.5", r"q: text is not a number: '1.5'"),
        (True, r"q: a boolean is not a number: True"),
        ([1, 2], r"q: expected one number, got shape \(2,\)"),
    ],
)
def test_bad_module_coordinate(q, pattern):
    with pytest.raises(rc.InvalidInputError, match=pattern):
        rc.Module("Rz", q=q)


def test_bad_module_name():
    with pytest.raises(rc.InvalidInputError, match=r"name: invalid value 3; allowed: text or None"):
        rc.Module("Rz", name=3)


@pytest.mark.parametrize(
    ("q", "pattern"),
    [
        ([0, 0], r"q: expected shape \(3,\) or \(T, 3\), got \(2,\)"),
        ([0, 0, 0, 0], r"q: expected shape \(3,\) or \(T, 3\), got \(4,\)"),
        (np.zeros((5, 2)), r"q: expected shape \(3,\) or \(T, 3\), got \(5, 2\)"),
        (np.zeros((2, 5, 3)), r"q: expected shape \(3,\) or \(T, 3\), got \(2, 5, 3\)"),
        (0.0, r"q: expected shape \(3,\) or \(T, 3\), got \(\)"),
        ([0, float("nan"), 0], r"q: q2 must be finite, got nan"),
        ([[0, 0, 0], [0, 0, float("inf")]], r"q: q3 at sample 1 must be finite, got inf"),
        ("0 0 0", r"q: text is not a number: '0 0 0'"),
        (["a", "b", "c"], r"q: not numeric"),
    ],
)
def test_bad_robot_coordinates(paper_robot, q, pattern):
    with pytest.raises(rc.InvalidInputError, match=pattern):
        paper_robot.frame_poses(q)
    with pytest.raises(rc.InvalidInputError, match=pattern):
        paper_robot.end_effector(q)


def test_with_q_refuses_a_trajectory(paper_robot):
    with pytest.raises(rc.InvalidInputError, match=r"q: got a trajectory"):
        paper_robot.with_q(np.zeros((4, 3)))


@pytest.mark.parametrize(
    ("modules", "pattern"),
    [
        ([], r"modules: empty: \[\]; allowed: at least one Module or DHLink"),
        ("RzRyRy", r"modules: not a list: 'RzRyRy'"),
        (rc.Module("Rz"), r"modules: not a list"),
        ([rc.Module("Rz"), "Ry"], r"modules\[1\]: not a link: 'Ry'; allowed: a Module or DHLink"),
        (42, r"modules: not a list: 42"),
    ],
)
def test_bad_module_lists(modules, pattern):
    with pytest.raises(rc.InvalidInputError, match=pattern):
        rc.Robot(modules)


@pytest.mark.parametrize(
    ("active", "pattern"),
    [
        (0, r"active: out of range: 0; allowed: an integer from 1 to 3"),
        (4, r"active: out of range: 4"),
        (-1, r"active: out of range: -1"),
        (1.5, r"active: not an integer: 1.5"),
        (True, r"active: not an integer: True"),
    ],
)
def test_active_out_of_range(paper_robot, active, pattern):
    with pytest.raises(rc.InvalidInputError, match=pattern):
        paper_robot.with_active(active)


@pytest.mark.parametrize(
    ("point", "pattern"),
    [
        ((40, 0), r"end_effector: expected shape \(3,\), got \(2,\)"),
        ((40, float("nan"), 0), r"end_effector: entry 1 must be finite"),
    ],
)
def test_bad_end_effector(point, pattern):
    with pytest.raises(rc.InvalidInputError, match=pattern):
        rc.Robot([rc.Module("Rz")], end_effector=point)


def test_bad_robot_name():
    with pytest.raises(rc.InvalidInputError, match=r"name: invalid value 5"):
        rc.Robot([rc.Module("Rz")], name=5)


@pytest.mark.parametrize(
    ("call", "pattern"),
    [
        (lambda r: r.with_module(3, rc.Module("Rz")), r"index: out of range: 3; allowed: .*0 to 2"),
        (lambda r: r.with_module(-1, rc.Module("Rz")), r"index: out of range: -1"),
        (lambda r: r.with_module("1", rc.Module("Rz")), r"index: not an integer: '1'"),
        (lambda r: r.with_module(0, "Rz"), r"modules\[0\]: not a link: 'Rz'"),
        (lambda r: r.with_inserted(5, rc.Module("Rz")), r"index: out of range: 5.*0 to 3"),
        (lambda r: r.with_moved(0, 3), r"new_index: out of range: 3"),
        (lambda r: r.with_removed(1).with_removed(0).with_removed(0), r"cannot remove the last"),
    ],
)
def test_bad_edits(paper_robot, call, pattern):
    with pytest.raises(rc.InvalidInputError, match=pattern):
        call(paper_robot)


@pytest.mark.parametrize(
    ("rows", "convention", "pattern"),
    [
        ([(0, 0, 1, 0, "R")], "craig", r"convention: unknown DH convention 'craig'"),
        ([(0, 0, 1, 0, "R")], None, r"convention: unknown DH convention None"),
        ([], "standard", r"rows: empty: \[\]; allowed: at least one DH row"),
        ("theta d a alpha", "standard", r"rows: not a list"),
        ([(0, 0, 1, 0)], "standard", r"rows\[0\]: expected 5 entries, got \(0, 0, 1, 0\)"),
        ([(0, 0, 1, 0, "X")], "standard", r"rows\[0\].joint: invalid value 'X'; allowed: 'R'"),
        (
            [(0, 0, 1, 0, "R"), (0, float("nan"), 1, 0, "R")],
            "standard",
            r"rows\[1\].d: must be finite",
        ),
        ([(0, "0.1", 1, 0, "R")], "standard", r"rows\[0\].d: text is not a number: '0.1'"),
        ([{"theta": 0, "d": 0, "a": 1, "alpha": 0}], "standard", r"rows\[0\]: missing \['joint'\]"),
        (
            [{"theta": 0, "d": 0, "a": 1, "alpha": 0, "joint": "R", "offset": 1}],
            "standard",
            r"rows\[0\]: unknown keys \['offset'\]",
        ),
    ],
)
def test_bad_dh_tables(rows, convention, pattern):
    with pytest.raises(rc.InvalidInputError, match=pattern):
        rc.Robot.from_dh(rows, convention=convention)


def test_bad_dh_matrix_inputs():
    with pytest.raises(rc.InvalidInputError, match=r"theta: must be finite"):
        rc.dh_matrix(float("nan"), 0, 0, 0)
    with pytest.raises(rc.InvalidInputError, match=r"alpha: text is not a number"):
        rc.dh_matrix(0, 0, 0, "90")
    with pytest.raises(
        rc.InvalidInputError, match=r"convention: unknown DH convention 'Standard DH'"
    ):
        rc.dh_matrix(0, 0, 0, 0, convention="Standard DH")


def test_bad_derivative_order():
    with pytest.raises(
        rc.InvalidInputError, match=r"order: invalid value 0; allowed: an integer ≥ 1"
    ):
        rc.Module("Rz").matrix_derivative(0.0, order=0)


def test_bad_link_coordinates():
    with pytest.raises(rc.InvalidInputError, match=r"q: .*must be finite"):
        rc.Module("Rz").matrix([0.0, float("nan")])
    with pytest.raises(
        rc.InvalidInputError, match=r"q: expected a number or shape \(T,\), got \(2, 2\)"
    ):
        rc.Module("Rz").matrix(np.zeros((2, 2)))
