"""Joint ranges: validation on Module/DHLink, defaults of Robot.joint_limits, with_limits."""

import numpy as np
import pytest

import robotconf as rc
from robotconf import DHLink, InvalidInputError, Module, Robot

PI = np.pi


def test_module_limits_are_floats_and_part_of_repr_eq_hash():
    m = Module("Tz", a=(0, 0, 5), limits=[0, 50])
    assert m.limits == (0.0, 50.0)
    assert repr(m) == "Module('Tz', a=(0.0, 0.0, 5.0), limits=(0.0, 50.0))"
    assert eval(repr(m), {"Module": Module}) == m
    assert m != Module("Tz", a=(0, 0, 5))
    assert hash(m) == hash(Module("Tz", a=(0, 0, 5), limits=(0.0, 50.0)))


def test_with_methods_keep_limits():
    m = Module("Rz", limits=(-1, 1), name="base")
    assert m.with_q(0.5).limits == (-1.0, 1.0)
    assert m.with_a((1, 2, 3)).limits == (-1.0, 1.0)
    assert m.with_name("x").limits == (-1.0, 1.0)
    assert m.with_limits(None).limits is None
    assert m.with_limits((0, 2)) == Module("Rz", limits=(0, 2), name="base")


def test_with_kind_keeps_limits_only_for_the_same_joint_type():
    m = Module("Rz", limits=(-1, 1))
    assert m.with_kind("Rx").limits == (-1.0, 1.0)
    assert m.with_kind("Ty").limits is None  # radians do not become lengths
    assert m.with_kind("fixed").limits is None


@pytest.mark.parametrize(
    ("limits", "match"),
    [
        ("ab", r"limits: expected two numbers"),
        ((1.0,), r"limits: expected two numbers"),
        ((0, 1, 2), r"limits: expected two numbers"),
        (5.0, r"limits: expected two numbers"),
        ((float("nan"), 1), r"limits\[0\]: must be finite"),
        ((0, float("inf")), r"limits\[1\]: must be finite"),
        ((True, 2), r"limits\[0\]: a boolean is not a number"),
        ((2, 1), r"limits: lower limit must be below upper limit, got \(2.0, 1.0\)"),
        ((1, 1), r"lower limit must be below upper limit"),
    ],
)
def test_module_limits_errors(limits, match):
    with pytest.raises(InvalidInputError, match=match):
        Module("Rz", limits=limits)


@pytest.mark.parametrize("kind", ["none", "fixed"])
def test_limits_refused_on_links_without_joint(kind):
    with pytest.raises(InvalidInputError, match=rf"limits: a '{kind}' module has no joint"):
        Module(kind, limits=(0, 1))


def test_dhlink_limits_repr_roundtrip_and_with_methods():
    link = DHLink(0.1, 0.2, 0.3, 0.4, "P", q=0.5, name="slide", limits=(0, 1))
    assert repr(link).endswith("q=0.5, name='slide', limits=(0.0, 1.0))")
    assert eval(repr(link), {"DHLink": DHLink}) == link
    assert link.with_q(0.7).limits == (0.0, 1.0)
    assert link.with_name(None).limits == (0.0, 1.0)
    assert link.with_limits(None).limits is None
    with pytest.raises(InvalidInputError, match=r"limits: lower limit must be below"):
        link.with_limits((1, 0))


def test_from_dh_dict_rows_may_carry_limits():
    robot = Robot.from_dh(
        [{"theta": 0, "d": 0, "a": 1, "alpha": 0, "joint": "R", "limits": [-1, 2]}]
    )
    assert robot.modules[0].limits == (-1.0, 2.0)
    with pytest.raises(InvalidInputError, match=r"rows\[0\]\.limits: lower limit"):
        Robot.from_dh([{"theta": 0, "d": 0, "a": 1, "alpha": 0, "joint": "R", "limits": [2, 1]}])


def test_joint_limits_defaults():
    # L = |a2| + |a3| + |a4| + |P| = 20 + 5 + 13 + 40 = 78 (the none module's a is ignored).
    robot = Robot(
        [
            Module("Rz"),
            Module("Tz", a=(0, 0, 20)),
            Module("fixed", a=(3, 4, 0)),
            Module("none", a=(100, 0, 0)),
            Module("Ty", a=(5, 12, 0), limits=(-2, 3)),
        ],
        end_effector=(40, 0, 0),
    )
    expected = [[-PI, PI], [-78.0, 78.0], [0, 0], [0, 0], [-2, 3]]
    np.testing.assert_allclose(robot.joint_limits(), expected, rtol=0, atol=0)
    assert rc.characteristic_length(robot) == 78.0


def test_characteristic_length_of_dh_rows_and_of_a_bare_chain():
    # Revolute row: hypot(a, d) = hypot(3, 4) = 5; prismatic row: its d is the coordinate's
    # zero point, so only a = 2 counts; EE (0, 0, 1) adds 1.
    robot = Robot([DHLink(0, 4, 3, 0, "R"), DHLink(0, 9, 2, 0, "P")], end_effector=(0, 0, 1))
    assert rc.characteristic_length(robot) == 8.0
    np.testing.assert_array_equal(robot.joint_limits()[1], [-8.0, 8.0])
    bare = Robot([Module("Tx"), Module("Ty")])
    np.testing.assert_array_equal(bare.joint_limits(), [[-1.0, 1.0], [-1.0, 1.0]])


def test_with_limits_by_index_and_name():
    robot = Robot([Module("Rz"), Module("Ry", name="shoulder"), Module("Tz")])
    changed = robot.with_limits("shoulder", (-1, 1)).with_limits(2, (0, 5))
    np.testing.assert_array_equal(changed.joint_limits()[1:], [[-1, 1], [0, 5]])
    assert changed.with_limits("M3", None).modules[2].limits is None
    assert robot.modules[1].limits is None  # the original is untouched
    assert changed.with_q([0.1, 0.2, 0.3]).modules[1].limits == (-1.0, 1.0)


@pytest.mark.parametrize(
    ("index", "limits", "match"),
    [
        (
            "M9",
            (0, 1),
            r"index: unknown module 'M9'; allowed: an index 0 to 1, a module name \(M1, M2\)",
        ),
        (2, (0, 1), r"index: out of range: 2"),
        (True, (0, 1), r"index: not an integer: True"),
        (1.0, (0, 1), r"index: not an integer"),
        (1, (0, 1), r"modules\[1\]\.limits: a 'fixed' module has no joint"),
        (0, (1, 0), r"modules\[0\]\.limits: lower limit must be below"),
    ],
)
def test_with_limits_errors(index, limits, match):
    robot = Robot([Module("Rz"), Module("fixed")])
    with pytest.raises(InvalidInputError, match=match):
        robot.with_limits(index, limits)
