"""Standard ⇄ modified DH: convert_dh keeps the robot, reinterpret_dh keeps the numbers.

What convert_dh keeps, checked here with numbers: the end-effector pose, every joint's
axis (line and direction), the end-effector Jacobian, and standard frame i = modified
frame i · Tx(a_i) · Rx(α_i) — the two conventions put frame i at opposite ends of link i.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import robotconf as rc
from robotconf import DHLink, InvalidInputError, Module, Robot

PI = np.pi
EXACT = {"rtol": 0, "atol": 1e-12}


def _link_factor(a, alpha):
    """Tx(a)·Rx(α) as a 4×4 matrix, written out."""
    c, s = np.cos(alpha), np.sin(alpha)
    return np.array([[1, 0, 0, a], [0, c, -s, 0], [0, s, c, 0], [0, 0, 0, 1.0]])


def _joints(robot):
    """Positions of the rows that are joints of the original robot (not added ones)."""
    added = ("base (constant)", "tool (constant)")
    return [i for i, link in enumerate(robot.modules) if link.name not in added]


def _coordinates(robot, q):
    """q of the original joints, with the added rows held at 0."""
    full = np.zeros((len(q), robot.n))
    full[:, _joints(robot)] = q
    return full


def assert_same_robot(original, converted, q, scale=1.0):
    """Everything convert_dh promises, at the configurations q, shape (T, n)."""
    close = {"rtol": 0, "atol": 1e-12 * scale}
    full = _coordinates(converted, q)
    joints = _joints(converted)
    assert len(joints) == original.n
    # The end-effector pose (point and axes) and its Jacobian.
    np.testing.assert_allclose(
        converted.end_effector_pose(full), original.end_effector_pose(q), **close
    )
    np.testing.assert_allclose(
        converted.jacobian(full)[:, :, joints], original.jacobian(q), **close
    )
    # Every joint's axis: the same direction, and the points lie on one line.
    mine, theirs = rc.joint_axes(original, q), rc.joint_axes(converted, full)
    assert [theirs.joints[i] for i in joints] == list(mine.joints)
    direction = mine.direction
    np.testing.assert_allclose(theirs.direction[:, joints], direction, **close)
    offset = theirs.point[:, joints] - mine.point
    np.testing.assert_allclose(np.cross(offset, direction), 0.0, **close)
    if original.modules[0].convention == converted.modules[0].convention:
        return  # a round trip: its frames are checked where it is made
    # Frame i of both conventions: standard = modified · Tx(a_i)·Rx(α_i), same link.
    standard, modified = (
        (original, converted)
        if original.modules[0].convention == "standard"
        else (converted, original)
    )
    std_q, mod_q = (q, full) if standard is original else (full, q)
    std_joints, mod_joints = _joints(standard), _joints(modified)
    std_frames = standard.frame_poses(std_q)[:, std_joints]
    mod_frames = modified.frame_poses(mod_q)[:, mod_joints]
    for k, row in enumerate(standard.modules[i] for i in std_joints):
        np.testing.assert_allclose(
            std_frames[:, k], mod_frames[:, k] @ _link_factor(row.a, row.alpha), **close
        )
        # The same link, so the same angular velocity (columns of the original joints).
        np.testing.assert_allclose(
            standard.jacobian(std_q, std_joints[k])[:, 3:][:, :, std_joints],
            modified.jacobian(mod_q, mod_joints[k])[:, 3:][:, :, mod_joints],
            **close,
        )


# -- by hand ---------------------------------------------------------------------------------

ARM = Robot.from_dh([(0, 0.5, 1, PI / 2, "R"), (0, 0, 2, 0, "R")])


def test_two_links_by_hand():
    # Standard rows (θ, d, a, α): (q1, 0.5, 1, π/2), (q2, 0, 2, 0). Modified rows keep θ and d
    # and take a, α from the row before: (q1, 0.5, 0, 0), (q2, 0, 1, π/2); a2 = 2 lies past
    # the last joint, so the end-effector point takes it: P = (2, 0, 0).
    craig = rc.convert_dh(ARM, "modified")
    assert [link.row() for link in craig.modules] == [
        (0.0, 0.5, 0.0, 0.0, "R"),
        (0.0, 0.0, 1.0, PI / 2, "R"),
    ]
    assert [link.convention for link in craig.modules] == ["modified", "modified"]
    np.testing.assert_array_equal(craig.end_effector_point, [2, 0, 0])
    # The end-effector, worked out on paper from the standard table.
    for q, ee in [((0, 0), (3, 0, 0.5)), ((PI / 2, 0), (0, 3, 0.5)), ((0, PI / 2), (1, 0, 2.5))]:
        np.testing.assert_allclose(ARM.end_effector(q), ee, **EXACT)
        np.testing.assert_allclose(craig.end_effector(q), ee, **EXACT)
    # At q = (0, π/2): joint 2 turns about −y through (1, 0, 0.5), the tip is 2 above it.
    q = (0, PI / 2)
    turned = [[0, -1, 0], [0, 0, -1], [1, 0, 0]]  # Rx(π/2)·Rz(π/2)
    expected = {
        "standard": [([[1, 0, 0], [0, 0, -1], [0, 1, 0]], (1, 0, 0.5)), (turned, (1, 0, 2.5))],
        "modified": [(np.eye(3), (0, 0, 0.5)), (turned, (1, 0, 0.5))],
    }
    for robot, frames in [(ARM, expected["standard"]), (craig, expected["modified"])]:
        poses = robot.frame_poses(q)
        for pose, (rotation, origin) in zip(poses, frames, strict=True):
            np.testing.assert_allclose(pose[:3, :3], rotation, **EXACT)
            np.testing.assert_allclose(pose[:3, 3], origin, **EXACT)
    # Joint 2's axis: standard z1 through frame 1's origin, modified z2 through frame 2's.
    np.testing.assert_allclose(ARM.frame_poses(q)[0][:3, 2], [0, -1, 0], **EXACT)
    np.testing.assert_allclose(craig.frame_poses(q)[1][:3, 2], [0, -1, 0], **EXACT)
    # The Jacobian by hand: [z1 × p, z2 × (p − o2); z1, z2] with p = (1, 0, 2.5).
    jacobian = [[0, -2], [1, 0], [0, 0], [0, 0], [0, -1], [1, 0]]
    np.testing.assert_allclose(ARM.jacobian(q), jacobian, **EXACT)
    np.testing.assert_allclose(craig.jacobian(q), jacobian, **EXACT)
    # And back: the same rows, a2 staying in the point.
    back = rc.convert_dh(craig, "standard")
    assert [link.row() for link in back.modules] == [
        (0.0, 0.5, 1.0, PI / 2, "R"),
        (0.0, 0.0, 0.0, 0.0, "R"),
    ]
    np.testing.assert_array_equal(back.end_effector_point, [2, 0, 0])


def test_reinterpret_keeps_the_numbers_and_changes_the_robot():
    same_numbers = rc.reinterpret_dh(ARM, "modified")
    assert [link.row() for link in same_numbers.modules] == [link.row() for link in ARM.modules]
    assert {link.convention for link in same_numbers.modules} == {"modified"}
    # Standard: Rz(q1)·Tz(0.5)·Tx(1)·Rx(π/2) · Tx(2): the tip 3 along x1 at height 0.5.
    # Modified: Rx(π/2)·Tx(1)·Rz(q1)·Tz(0.5) · Tx(2): z1 is −y, so d = 0.5 points along −y
    # and the tip turns in the x–z plane.
    c, s = np.cos(0.5), np.sin(0.5)
    np.testing.assert_allclose(ARM.end_effector([0.5, 0]), [3 * c, 3 * s, 0.5], **EXACT)
    np.testing.assert_allclose(
        same_numbers.end_effector([0.5, 0]), [1 + 2 * c, -0.5, 2 * s], **EXACT
    )
    assert rc.reinterpret_dh(same_numbers, "standard") == ARM


def test_reinterpret_keeps_everything_but_the_convention():
    robot = Robot(
        [DHLink(0.1, 0.2, 0.3, 0.4, "P", q=0.5, name="slide", limits=(0, 1)), DHLink(a=1.0)],
        end_effector=(1, 2, 3),
        active=1,
        name="arm",
    )
    other = rc.reinterpret_dh(robot, "Modified")
    assert other.modules[0] == DHLink(0.1, 0.2, 0.3, 0.4, "P", "modified", 0.5, "slide", (0, 1))
    assert (other.active, other.name) == (1, "arm")
    np.testing.assert_array_equal(other.end_effector_point, [1, 2, 3])


def test_rows_without_length_or_twist_mean_the_same_in_both_conventions(rng):
    robot = Robot.from_dh([(0.3, 1, 0, 0, "R"), (0, 2, 0, 0, "P")], end_effector=(1, 0, 0))
    for convention in ("standard", "modified"):
        q = rng.uniform(-2, 2, size=(10, 2))
        np.testing.assert_allclose(
            rc.reinterpret_dh(robot, convention).frame_poses(q), robot.frame_poses(q), **EXACT
        )
        assert rc.convert_dh(robot, convention) == rc.reinterpret_dh(robot, convention)


# -- real arms -------------------------------------------------------------------------------


def test_puma560_in_craig_form():
    puma = rc.preset("puma560")
    craig = rc.convert_dh(puma, "modified")
    assert craig.n == 6  # α6 = 0 and a6 = 0: nothing is left over for the tool
    np.testing.assert_array_equal(craig.end_effector_point, puma.end_effector_point)
    rows = np.array([link.row()[:4] for link in craig.modules])
    np.testing.assert_array_equal(rows[:, 0], 0.0)
    np.testing.assert_array_equal(rows[:, 1], [0, 0, 0.15005, 0.4318, 0, 0])
    np.testing.assert_array_equal(rows[:, 2], [0, 0, 0.4318, 0.0203, 0, 0])
    np.testing.assert_array_equal(rows[:, 3], [0, PI / 2, 0, -PI / 2, PI / 2, -PI / 2])
    assert [link.limits for link in craig.modules] == [link.limits for link in puma.modules]
    assert rc.convert_dh(craig, "standard") == puma


def test_ur5_in_craig_form():
    ur5 = rc.preset("ur5")
    craig = rc.convert_dh(ur5, "modified")
    rows = np.array([link.row()[:4] for link in craig.modules])
    np.testing.assert_array_equal(rows[:, 1], [0.089159, 0, 0, 0.10915, 0.09465, 0.0823])
    np.testing.assert_array_equal(rows[:, 2], [0, 0, -0.425, -0.39225, 0, 0])
    np.testing.assert_array_equal(rows[:, 3], [0, PI / 2, 0, 0, PI / 2, -PI / 2])
    assert rc.convert_dh(craig, "standard") == ur5


@pytest.mark.parametrize("name", ["puma560", "ur5", "stanford", "scara", "articulated"])
def test_presets_are_the_same_robot_in_modified_dh(rng, name):
    robot = rc.preset(name)
    craig = rc.convert_dh(robot, "modified")
    q = rng.uniform(-2, 2, size=(25, robot.n))
    assert_same_robot(robot, craig, q, scale=100.0)
    assert_same_robot(craig, rc.convert_dh(craig, "standard"), q, scale=100.0)
    assert rc.convert_dh(robot, "standard") == robot  # already standard: unchanged


# -- the ends: tool and base -----------------------------------------------------------------


def test_a_tool_twist_gets_a_row_whose_frame_is_the_standard_last_frame(rng):
    robot = Robot.from_dh(
        [(0.2, 0.1, 0.5, 0.3, "R"), (0.0, 0.2, 0.4, 0.7, "P")], end_effector=(1, 2, 3)
    )
    craig = rc.convert_dh(robot, "modified")
    assert craig.modules[-1] == DHLink(0, 0, 0.4, 0.7, "R", "modified", name="tool (constant)")
    np.testing.assert_array_equal(craig.end_effector_point, [1, 2, 3])
    q = rng.uniform(-2, 2, size=(10, 2))
    full = _coordinates(craig, q)
    np.testing.assert_allclose(craig.frame_poses(full)[:, 2], robot.frame_poses(q)[:, 1], **EXACT)
    assert_same_robot(robot, craig, q)
    # Held, that row drops out again on the way back.
    back = rc.convert_dh(craig, "standard", constant="tool (constant)")
    assert back == robot
    # Not held, it stays a (bare) row.
    assert rc.convert_dh(craig, "standard").modules[-1].row() == (0, 0, 0, 0, "R")


def test_a_base_twist_gets_a_row_in_front(rng):
    robot = Robot.from_dh([(0.2, 0.1, 0.5, 0.3, "R"), (0.0, 0.2, 0.4, 0.7, "P")], "modified")
    standard = rc.convert_dh(robot, "standard")
    assert standard.modules[0] == DHLink(0, 0, 0.5, 0.3, "R", name="base (constant)")
    assert [link.row() for link in standard.modules[1:]] == [
        (0.2, 0.1, 0.4, 0.7, "R"),
        (0.0, 0.2, 0.0, 0.0, "P"),
    ]
    q = rng.uniform(-2, 2, size=(10, 2))
    assert_same_robot(robot, standard, q)
    # The joints moved one coordinate up: q1 of the modified robot is q2 here.
    np.testing.assert_allclose(
        standard.end_effector(np.column_stack([np.zeros(10), q])), robot.end_effector(q), **EXACT
    )
    assert rc.convert_dh(standard, "modified", constant=["base (constant)"]) == robot


def test_added_rows_get_free_names():
    robot = Robot(
        [
            DHLink(a=1, alpha=0.5, name="tool (constant)"),
            DHLink(a=1, alpha=0.5, name="tool 2 (constant)"),
        ]
    )
    assert rc.convert_dh(robot, "modified").modules[-1].name == "tool 3 (constant)"


def test_mixed_conventions_convert_to_one(rng):
    # A standard row then a modified one: their two link factors meet and multiply.
    robot = Robot(
        [DHLink(0.1, 0.2, 0.3, 0.4), DHLink(0.5, 0.6, 0.7, 0.8, "P", "modified"), DHLink(a=1.0)],
        end_effector=(0.1, 0.2, 0.3),
    )
    q = rng.uniform(-2, 2, size=(10, 3))
    for convention in ("standard", "modified"):
        converted = rc.convert_dh(robot, convention)
        assert {link.convention for link in converted.modules} == {convention}
        np.testing.assert_allclose(
            converted.end_effector_pose(_coordinates(converted, q)),
            robot.end_effector_pose(q),
            **EXACT,
        )
    # Tx(0.3)·Rx(0.4) · Tx(0.7)·Rx(0.8) = Tx(1.0)·Rx(1.2): one row's a and α.
    row = rc.convert_dh(robot, "standard").modules[0].row()
    assert row[4] == "R"
    np.testing.assert_allclose(row[:4], [0.1, 0.2, 1.0, 1.2], rtol=0, atol=1e-15)


def test_a_held_row_that_moves_stays():
    robot = Robot.from_dh([(0, 0, 1, 0, "R"), (0.5, 0, 1, 0, "R")])
    assert rc.convert_dh(robot, "modified", constant=1).n == 2


# -- random robots ---------------------------------------------------------------------------

lengths = st.one_of(st.just(0.0), st.floats(min_value=-10, max_value=10, allow_nan=False))
angles = st.one_of(st.just(0.0), st.floats(min_value=-4 * PI, max_value=4 * PI, allow_nan=False))


@st.composite
def dh_robots_and_q(draw):
    convention = draw(st.sampled_from(["standard", "modified"]))
    count = draw(st.integers(min_value=1, max_value=6))
    links = [
        DHLink(
            *(draw(angles), draw(lengths), draw(lengths), draw(angles)),
            draw(st.sampled_from(["R", "P"])),
            convention,
            name=f"J{k + 1}",
        )
        for k in range(count)
    ]
    robot = Robot(links, end_effector=draw(st.tuples(lengths, lengths, lengths)))
    values = st.lists(angles, min_size=count, max_size=count)
    return robot, np.array(draw(st.lists(values, min_size=1, max_size=4)))


@settings(max_examples=200, deadline=None)
@given(dh_robots_and_q())
def test_random_robots_are_the_same_robot_in_the_other_convention(case):
    robot, q = case
    convention = robot.modules[0].convention
    other = "modified" if convention == "standard" else "standard"
    converted = rc.convert_dh(robot, other)
    assert {link.convention for link in converted.modules} == {other}
    scale = max(1.0, np.abs(robot.frame_poses(q)).max(), np.abs(robot.end_effector(q)).max())
    assert_same_robot(robot, converted, q, scale)
    # Back again, dropping the rows the first conversion added.
    back = rc.convert_dh(
        converted,
        convention,
        constant=[i for i in range(converted.n) if i not in _joints(converted)],
    )
    assert_same_robot(robot, back, q, scale)
    rows, back_rows = [link.row() for link in robot.modules], [link.row() for link in back.modules]
    last = robot.modules[-1]
    moved = convention == "standard" and last.alpha == 0.0 and last.a != 0.0
    if moved:  # a_n went into the end-effector point and stays there
        rows[-1] = (*rows[-1][:2], 0.0, 0.0, rows[-1][4])
    assert back_rows == rows
    shift = [last.a, 0.0, 0.0] if moved else [0.0, 0.0, 0.0]
    np.testing.assert_array_equal(back.end_effector_point, robot.end_effector_point + shift)
    frames = robot.frame_poses(q)
    frames[:, -1] = frames[:, -1] @ _link_factor(-shift[0], 0.0)
    close = {"rtol": 0, "atol": 1e-12 * scale}
    np.testing.assert_allclose(back.frame_poses(q), frames, **close)


# -- what it refuses -------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("robot", "convention", "constant", "match"),
    [
        (
            Robot([DHLink(a=1.0), Module("Rz")]),
            "modified",
            (),
            r"modules\[1\]: is not a DH row: Module\('Rz'\); allowed: DH rows \(DHLink\) only; "
            r"modules_to_dh",
        ),
        (
            Robot([DHLink(a=1.0), DHLink(a=1.0, name="x")], active=1),
            "modified",
            (),
            r"robot: has inactive rows: '1 of 2 rows active'; allowed: all rows active",
        ),
        (Robot([DHLink(a=1.0)]), "craig", (), r"convention: unknown DH convention 'craig'"),
        (Robot([DHLink(a=1.0)]), "modified", ["wrist"], r"constant: unknown module 'wrist'"),
        (Robot([DHLink(a=1.0)]), "modified", [0], r"constant: leaves no joint: \[0\]"),
        (rc.preset("paper"), "standard", (), r"modules\[0\]: is not a DH row"),
    ],
)
def test_convert_dh_refuses(robot, convention, constant, match):
    with pytest.raises(InvalidInputError, match=match):
        rc.convert_dh(robot, convention, constant=constant)


def test_reinterpret_dh_refuses():
    with pytest.raises(InvalidInputError, match=r"robot: invalid value \[1\]; allowed: a Robot"):
        rc.reinterpret_dh([1], "modified")
    with pytest.raises(InvalidInputError, match=r"modules\[0\]: is not a DH row"):
        rc.reinterpret_dh(rc.preset("paper"), "modified")
    with pytest.raises(InvalidInputError, match=r"convention: unknown DH convention"):
        rc.reinterpret_dh(ARM, "craig")


def test_both_are_on_the_facade():
    assert {"convert_dh", "reinterpret_dh"} <= set(rc.__all__)
    assert rc.convert_dh is rc.kinematics.convert_dh
    assert rc.reinterpret_dh is rc.kinematics.reinterpret_dh
