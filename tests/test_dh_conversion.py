"""DH rows ⇄ modules: the same poses both ways, and explanations where DH cannot fit."""

import numpy as np
import pytest

import robotconf as rc
from robotconf import DHLink, InvalidInputError, Module, Robot

from .conftest import reference_poses

PI = np.pi


def test_standard_revolute_row_as_modules():
    modules = rc.dh_to_modules((0.5, 0.1, 0.4318, PI / 2, "R"))
    assert modules == [
        Module("Rz", q=0.5, name="θ (constant)"),
        Module("Rz"),
        Module("Rx", a=(0.4318, 0.0, 0.1), q=PI / 2, name="α (constant)"),
    ]


def test_standard_prismatic_row_as_modules():
    link = DHLink(0.25, 0.3, 0.2, 0.0, "P", q=0.7, name="slide", limits=(0, 1))
    assert rc.dh_to_modules(link) == [
        Module("Rz", q=0.25, name="slide: θ (constant)"),
        Module("Tz", a=(0, 0, 0.3), q=0.7, name="slide", limits=(0, 1)),
        Module("fixed", a=(0.2, 0, 0), name="slide: a, d (constant)"),
    ]


def test_modified_rows_as_modules():
    assert rc.dh_to_modules((0.0, 0.3, 0.2, -PI / 2, "R"), "modified") == [
        Module("Rx", q=-PI / 2, name="α (constant)"),
        Module("Rz", a=(0.2, 0, 0)),
        Module("fixed", a=(0, 0, 0.3), name="d (constant)"),
    ]
    assert rc.dh_to_modules(DHLink(0.4, 0.3, 0.2, 0.0, "P", "modified")) == [
        Module("Rz", a=(0.2, 0, 0), q=0.4, name="θ (constant)"),
        Module("Tz", a=(0, 0, 0.3)),
    ]


def test_a_bare_joint_is_one_module():
    assert rc.dh_to_modules((0, 0, 0, 0, "P")) == [Module("Tz")]


def _random_rows(rng, count, convention):
    rows = []
    for k in range(count):
        theta, d, a, alpha = rng.uniform(-2, 2, size=4)
        if k % 3 == 1:
            theta = 0.0  # also exercise the rows without θ offset
        rows.append(DHLink(theta, d, a, alpha, "RP"[k % 2], convention, name=f"J{k + 1}"))
    return rows


def _module_chain(links):
    """The modules of every row, and for each row: (its joint module, its last module)."""
    chain, marks = [], []
    for link in links:
        modules = rc.dh_to_modules(link)
        joint = len(chain) + next(i for i, m in enumerate(modules) if m.name == link.name)
        chain.extend(modules)
        marks.append((joint, len(chain) - 1))
    return chain, marks


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_dh_to_modules_gives_the_same_frames(rng, convention):
    links = _random_rows(rng, 6, convention)
    dh_robot = Robot(links, end_effector=(0.1, -0.2, 0.3))
    chain, marks = _module_chain(links)
    module_robot = Robot(chain, end_effector=(0.1, -0.2, 0.3))
    joints = [j for j, _ in marks]
    ends = [e for _, e in marks]
    for q in rng.uniform(-3, 3, size=(20, 6)):
        q_modules = module_robot.q.copy()  # the constants hold their values
        q_modules[joints] = q
        # Both sides from the independent reference products of conftest.
        expected = reference_poses(dh_robot, q)
        actual = reference_poses(module_robot, q_modules)[ends]
        np.testing.assert_allclose(actual, expected, rtol=0, atol=1e-12)
        np.testing.assert_allclose(
            module_robot.end_effector(q_modules), dh_robot.end_effector(q), rtol=0, atol=1e-12
        )


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_round_trip_dh_modules_dh(rng, convention):
    links = _random_rows(rng, 5, convention)
    dh_robot = Robot(links, end_effector=(0.3, 0.2, 0.1))
    chain, marks = _module_chain(links)
    held = [i for i, m in enumerate(chain) if m.name and m.name.endswith("(constant)")]
    back = rc.modules_to_dh(Robot(chain, end_effector=(0.3, 0.2, 0.1)), convention, constant=held)
    assert back.n == 5 and back.joint_types == dh_robot.joint_types
    for q in rng.uniform(-3, 3, size=(20, 5)):
        np.testing.assert_allclose(back.frame_poses(q), dh_robot.frame_poses(q), rtol=0, atol=1e-12)
        np.testing.assert_allclose(
            back.end_effector(q), dh_robot.end_effector(q), rtol=0, atol=1e-12
        )


@pytest.mark.parametrize("name", ["puma560", "ur5", "stanford", "scara"])
@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_dh_robots_convert_to_the_other_convention(rng, name, convention):
    robot = rc.preset(name)
    other = rc.modules_to_dh(robot, convention)
    assert all(link.convention == convention for link in other.modules)
    assert [link.limits for link in other.modules] == [link.limits for link in robot.modules]
    for q in rng.uniform(-2, 2, size=(20, robot.n)):
        np.testing.assert_allclose(other.end_effector(q), robot.end_effector(q), rtol=0, atol=1e-12)


def test_module_arm_by_hand():
    # Trans(0,0,20)·Rz(q1) · Trans(30,0,0)·Rz(q2) · EE (40,0,0): Tz(20) commutes with Rz(q1),
    # so row 1 is (θ=q1, d=20, a=30, α=0) and row 2 a bare Rz(q2) — the planar arm at z = 20.
    arm = Robot([Module("Rz", a=(0, 0, 20)), Module("Rz", a=(30, 0, 0))], end_effector=(40, 0, 0))
    dh = rc.modules_to_dh(arm)
    assert [link.row() for link in dh.modules] == [
        (0.0, 20.0, 30.0, 0.0, "R"),
        (0.0, 0.0, 0.0, 0.0, "R"),
    ]
    np.testing.assert_allclose(dh.end_effector([PI / 2, -PI / 2]), [40, 30, 20], atol=1e-12)


def test_cylindrical_style_chain_with_twist_and_tail(rng):
    # Rz(q1)·Trans(0,0,h)·Tz(q2) · [held Rx(−π/2)] · Tz(q3) · then a held Ry and an offset:
    # the trailing constants that DH cannot hold go into the end-effector point.
    robot = Robot(
        [
            Module("Rz", limits=(-1, 1)),
            Module("Tz", a=(0, 0, 20)),
            Module("Rx", q=-PI / 2),
            Module("Tz", a=(5, 0, 0)),
            Module("Ry", q=0.3, a=(0, 1, 0)),
        ],
        end_effector=(2, 0, 0),
    )
    dh = rc.modules_to_dh(robot, constant=[2, "M5"])
    assert dh.joint_types == ("revolute", "prismatic", "prismatic")
    # The robot resolves the held modules: coordinate names and numpy integers work too.
    assert rc.modules_to_dh(robot, constant=["q3", np.int64(4)]) == dh
    assert dh.modules[0].limits == (-1.0, 1.0)
    for q in rng.uniform(-2, 2, size=(20, 3)):
        full = np.array([q[0], q[1], -PI / 2, q[2], 0.3])
        np.testing.assert_allclose(dh.end_effector(q), robot.end_effector(full), rtol=0, atol=1e-12)


def test_inactive_and_none_modules_are_dropped(rng):
    robot = Robot(
        [Module("Rz"), Module("none"), Module("Rz", a=(1, 0, 0)), Module("Ry")],
        end_effector=(1, 0, 0),
        active=3,
    )
    dh = rc.modules_to_dh(robot)
    assert dh.n == 2
    for q in rng.uniform(-2, 2, size=(10, 2)):
        np.testing.assert_allclose(
            dh.end_effector(q), robot.end_effector([q[0], 0, q[1], 0]), rtol=0, atol=1e-12
        )


@pytest.mark.parametrize(
    ("modules", "convention", "constant", "match"),
    [
        (
            [Module("Rz"), Module("Ry", a=(0, 0, 20)), Module("Ry", a=(30, 0, 0))],
            "standard",
            (),
            r"modules\[1\]: module M2 turns about the y axis, but a DH table has no y",
        ),
        (
            [Module("Rz"), Module("Rx")],
            "standard",
            (),
            r"modules\[1\]: module M2 is a joint that turns about x",
        ),
        (
            [Module("Tx"), Module("Rz")],
            "modified",
            (),
            r"modules\[0\]: module M1 is a joint that slides along x",
        ),
        (
            [Module("Rz"), Module("Tz", a=(0, 2, 0))],
            "standard",
            (),
            r"modules\[1\]: module M2 is offset along the y axis",
        ),
        (
            [Module("Rz"), Module("Ty", q=1.0), Module("Rz")],
            "standard",
            [1],
            r"modules\[1\]: module M2 is offset along the y axis",
        ),
        (
            [Module("Rz", a=(10, 0, 0)), Module("Rz")],
            "standard",
            (),
            r"modules\[0\]: module M1 is offset along x before its row's joint, but in standard DH",
        ),
        (
            [Module("Rx", q=0.5), Module("Rz")],
            "standard",
            [0],
            r"modules\[0\]: module M1 twists about x before its row's joint",
        ),
        (
            [Module("Rz", q=0.5), Module("Rz", a=(1, 0, 0))],
            "modified",
            [0],
            r"modules\[1\]: module M2 is offset along x after a constant turn about z but before",
        ),
        (
            [Module("Rz", q=0.5), Module("Rx", q=0.2), Module("Rz")],
            "modified",
            [0, 1],
            r"modules\[1\]: module M2 twists about x after a constant turn about z",
        ),
        ([Module("fixed", a=(1, 0, 0)), Module("none")], "standard", (), r"robot: has no joint"),
        (
            [Module("Rz")],
            "standard",
            [5],
            r"constant: out of range: 5; allowed: an index 0 to 0, a module name \(M1\)",
        ),
        ([Module("Rz")], "standard", ["shoulder"], r"constant: unknown module 'shoulder'"),
        ([Module("Rz")], "standard", 2.5, r"constant: not an integer: 2.5"),
        ([Module("Rz")], "craig", (), r"convention: unknown DH convention 'craig'"),
    ],
)
def test_modules_to_dh_explains_what_breaks_the_pattern(modules, convention, constant, match):
    with pytest.raises(InvalidInputError, match=match):
        rc.modules_to_dh(Robot(modules), convention, constant=constant)


def test_modules_to_dh_needs_a_robot():
    with pytest.raises(InvalidInputError, match=r"robot: invalid value \[1\]; allowed: a Robot"):
        rc.modules_to_dh([1])


@pytest.mark.parametrize(
    ("row", "convention", "match"),
    [
        (DHLink(a=1.0), "modified", r"convention: contradicts the DHLink's convention: 'modified'"),
        ((0, 0, 1, 0), None, r"row: expected 5 entries"),
        ((0, 0, 1, 0, "X"), None, r"row\.joint: invalid value 'X'"),
        ((0, 0, 1, 0, "R"), "craig", r"convention: unknown DH convention 'craig'"),
    ],
)
def test_dh_to_modules_errors(row, convention, match):
    with pytest.raises(InvalidInputError, match=match):
        rc.dh_to_modules(row, convention)
