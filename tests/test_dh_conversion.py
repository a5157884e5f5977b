"""DH rows ⇄ modules: the same poses both ways, and explanations where DH cannot fit."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

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


def test_the_reported_frame_stays_put():
    # Row 2's d = 0.5 sits in front of its slide: it belongs to row 2, not to frame 1.
    dh = Robot.from_dh([(0, 0, 1, 0, "R"), (0, 0.5, 0, 0, "P")])
    back = rc.modules_to_dh(Robot([m for link in dh.modules for m in rc.dh_to_modules(link)]))
    assert [link.row() for link in back.modules] == [link.row() for link in dh.modules]
    np.testing.assert_allclose(back.frame_origins([0.3, 0.2])[0], [np.cos(0.3), np.sin(0.3), 0])


@pytest.mark.parametrize("name", ["puma560", "ur5", "stanford", "scara"])
def test_a_dh_table_of_the_same_convention_comes_back_unchanged(name):
    robot = rc.preset(name)
    assert rc.modules_to_dh(robot, "standard") == robot


@pytest.mark.parametrize("name", ["puma560", "ur5", "stanford", "scara"])
def test_a_dh_table_of_the_other_convention_points_to_convert_dh(name):
    # Its frames are not modified DH frames: converting it is convert_dh's job.
    with pytest.raises(
        InvalidInputError,
        match=r"modules\[0\]: module M1 is a standard DH row, whose frame sits at the far end "
        r".*convert_dh\(robot, 'modified'\) gives the same robot in modified DH",
    ):
        rc.modules_to_dh(rc.preset(name), "modified")


def _module_frames(robot, dh, joints, q):
    """The module robot's frames at the DH robot's joint values (held modules keep theirs)."""
    full = np.tile(robot.q, (len(q), 1))
    full[:, joints] = q
    return robot.frame_poses(full), robot.end_effector(full)


def test_standard_module_chain_by_hand(rng):
    robot = Robot(
        [
            Module("Rz", a=(0, 0, 0.3)),  # joint 1, d1 = 0.3
            Module("fixed", a=(0.1, 0, 0)),  # a1
            Module("Rx", q=-PI / 2),  # α1: DH frame 1 is this module's frame
            Module("Tz", a=(0, 0, 0.2)),  # joint 2, d2 = 0.2 …
            Module("fixed", a=(0, 0, 0.05)),  # … + 0.05: a shift stays with the joint before
            Module("Rz", q=0.4),  # a turn goes with the joint after: θ3
            Module("Rz"),  # joint 3
        ],
        end_effector=(0.1, 0, 0),
    )
    dh = rc.modules_to_dh(robot, constant=[2, 5])
    assert [link.row() for link in dh.modules] == [
        (0.0, 0.3, 0.1, -PI / 2, "R"),
        (0.0, 0.25, 0.0, 0.0, "P"),
        (0.4, 0.0, 0.0, 0.0, "R"),
    ]
    q = rng.uniform(-2, 2, size=(10, 3))
    frames, ee = _module_frames(robot, dh, [0, 3, 6], q)
    # Every DH frame is the frame of the module that ends its row.
    np.testing.assert_allclose(dh.frame_poses(q), frames[:, [2, 4, 6]], rtol=0, atol=1e-12)
    np.testing.assert_allclose(dh.end_effector(q), ee, rtol=0, atol=1e-12)


def test_modified_module_chain_by_hand(rng):
    robot = Robot(
        [
            Module("Rz", a=(0, 0, 0.3)),  # joint 1, d1 = 0.3
            Module("fixed", a=(0, 0, 0.05)),  # + 0.05: DH frame 1 is this module's frame
            Module("Rx", q=-PI / 2),  # α of row 2
            Module("fixed", a=(0.1, 0, 0)),  # a of row 2
            Module("Rz", q=0.4),  # θ2
            Module("Tz", a=(0, 0, 0.2)),  # joint 2, d2 = 0.2
            Module("Rz", q=0.3),  # a turn goes with the joint after: θ3
            Module("Rz"),  # joint 3
        ],
        end_effector=(0.1, 0, 0),
    )
    dh = rc.modules_to_dh(robot, "modified", constant=["M3", "M5", "M7"])
    assert [link.row() for link in dh.modules] == [
        (0.0, 0.35, 0.0, 0.0, "R"),
        (0.4, 0.2, 0.1, -PI / 2, "P"),
        (0.3, 0.0, 0.0, 0.0, "R"),
    ]
    q = rng.uniform(-2, 2, size=(10, 3))
    frames, ee = _module_frames(robot, dh, [0, 5, 7], q)
    np.testing.assert_allclose(dh.frame_poses(q), frames[:, [1, 5, 7]], rtol=0, atol=1e-12)
    np.testing.assert_allclose(dh.end_effector(q), ee, rtol=0, atol=1e-12)


def test_module_arm_by_hand(rng):
    # Trans(0,0,20)·Rz(q1) · Trans(30,0,0)·Rz(q2) · EE (40,0,0). Modified DH frames sit on
    # the joint axes, as the module frames do: row 1 (d = 20), row 2 (a = 30).
    arm = Robot([Module("Rz", a=(0, 0, 20)), Module("Rz", a=(30, 0, 0))], end_effector=(40, 0, 0))
    dh = rc.modules_to_dh(arm, "modified")
    assert [link.row() for link in dh.modules] == [
        (0.0, 20.0, 0.0, 0.0, "R"),
        (0.0, 0.0, 30.0, 0.0, "R"),
    ]
    np.testing.assert_allclose(dh.end_effector([PI / 2, -PI / 2]), [40, 30, 20], atol=1e-12)
    q = rng.uniform(-2, 2, size=(10, 2))
    np.testing.assert_allclose(dh.frame_poses(q), arm.frame_poses(q), rtol=0, atol=1e-12)
    # Standard DH frame 1 sits on joint 2's axis at the elbow, inside M2 (after its offset,
    # before its turn): no module frame is there, so the conversion says how to make one…
    with pytest.raises(
        InvalidInputError,
        match=r"modules\[1\]: module M2 is offset along x before its row's joint, .*; its offset "
        r"\(30.0, 0.0, 0.0\) would fit the row before only as a module of its own \(a fixed "
        r"module in front of it\), as every DH frame is a module's frame",
    ):
        rc.modules_to_dh(arm, "standard")
    # … and with that module, frame 1 is its frame.
    split = Robot(
        [Module("Rz", a=(0, 0, 20)), Module("fixed", a=(30, 0, 0)), Module("Rz")],
        end_effector=(40, 0, 0),
    )
    dh = rc.modules_to_dh(split, "standard")
    assert [link.row() for link in dh.modules] == [
        (0.0, 20.0, 30.0, 0.0, "R"),
        (0.0, 0.0, 0.0, 0.0, "R"),
    ]
    frames, _ = _module_frames(split, dh, [0, 2], q)
    np.testing.assert_allclose(dh.frame_poses(q), frames[:, [1, 2]], rtol=0, atol=1e-12)


def test_cylindrical_style_chain_with_twist_and_tail(rng):
    # Rz(q1)·Trans(0,0,h)·Tz(q2) · [held Rx(−π/2)] · Trans(5,0,0) · Tz(q3) · then a held Ry
    # and an offset: the trailing constants that DH cannot hold go into the end-effector point.
    robot = Robot(
        [
            Module("Rz", limits=(-1, 1)),
            Module("Tz", a=(0, 0, 20)),
            Module("Rx", q=-PI / 2),
            Module("fixed", a=(5, 0, 0)),
            Module("Tz"),
            Module("Ry", q=0.3, a=(0, 1, 0)),
        ],
        end_effector=(2, 0, 0),
    )
    dh = rc.modules_to_dh(robot, constant=[2, "M6"])
    assert dh.joint_types == ("revolute", "prismatic", "prismatic")
    # The robot resolves the held modules: coordinate names and numpy integers work too.
    assert rc.modules_to_dh(robot, constant=["q3", np.int64(5)]) == dh
    assert dh.modules[0].limits == (-1.0, 1.0)
    for q in rng.uniform(-2, 2, size=(20, 3)):
        full = np.array([q[0], q[1], -PI / 2, 0, q[2], 0.3])
        np.testing.assert_allclose(dh.end_effector(q), robot.end_effector(full), rtol=0, atol=1e-12)
        np.testing.assert_allclose(
            dh.frame_poses(q), robot.frame_poses(full)[[0, 3, 4]], rtol=0, atol=1e-12
        )


def test_split_offset_after_a_twist_is_explained():
    # Tz cannot pass the twist, so (5, 0, 3) would be cut: x for row 1, z for row 2.
    robot = Robot([Module("Rz"), Module("Rx", q=0.5), Module("fixed", a=(5, 0, 3)), Module("Rz")])
    with pytest.raises(
        InvalidInputError,
        match=r"modules\[2\]: module M3 is offset along x before its row's joint, .*; its x part "
        r"would fit the row before, its z part the next: split it in two",
    ):
        rc.modules_to_dh(robot, constant=[1])
    parts = [Module("Rz"), Module("Rx", q=0.5), Module("fixed", a=(5, 0, 0))]
    fixed = Robot([*parts, Module("fixed", a=(0, 0, 3)), Module("Rz")])
    assert [link.row() for link in rc.modules_to_dh(fixed, constant=[1]).modules] == [
        (0.0, 0.0, 5.0, 0.5, "R"),
        (0.0, 3.0, 0.0, 0.0, "R"),
    ]


def test_modified_offsets_along_z_then_x_commute():
    # Tz·Tx before the joint is Tx·Tz: a modified row holds it.
    robot = Robot([Module("fixed", a=(0, 0, 2)), Module("fixed", a=(3, 0, 0)), Module("Rz")])
    assert rc.modules_to_dh(robot, "modified").modules[0].row() == (0.0, 2.0, 3.0, 0.0, "R")
    with pytest.raises(InvalidInputError, match=r"twists about x after an offset along z"):
        rc.modules_to_dh(
            Robot([Module("fixed", a=(0, 0, 2)), Module("Rx", q=1.0), Module("Rz")]),
            "modified",
            constant=[1],
        )


def test_a_dh_row_cut_by_the_other_convention_is_named():
    # A standard row's a and α come after its joint: a modified row would end inside it.
    robot = Robot([Module("Rz"), DHLink(0, 0, 1, 0.5, "R", name="elbow")])
    with pytest.raises(InvalidInputError, match=r"modules\[1\]: module elbow is a standard DH"):
        rc.modules_to_dh(robot, "modified")


def test_a_turn_that_cannot_go_with_the_next_joint_stays_with_its_own():
    # Rz(0.5) before an offset along x cannot open a modified row: it is row 1's θ.
    robot = Robot([Module("Rz"), Module("Rz", q=0.5), Module("Rz", a=(1, 0, 0))])
    dh = rc.modules_to_dh(robot, "modified", constant=[1])
    assert [link.row() for link in dh.modules] == [
        (0.5, 0.0, 0.0, 0.0, "R"),
        (0.0, 0.0, 1.0, 0.0, "R"),
    ]


def test_inactive_and_none_modules_are_dropped(rng):
    robot = Robot(
        [Module("Rz"), Module("none"), Module("Rz", a=(1, 0, 0)), Module("Ry")],
        end_effector=(1, 0, 0),
        active=3,
    )
    dh = rc.modules_to_dh(robot, "modified")
    assert dh.n == 2
    for q in rng.uniform(-2, 2, size=(10, 2)):
        full = [q[0], 0, q[1], 0]
        np.testing.assert_allclose(dh.end_effector(q), robot.end_effector(full), atol=1e-12)
        np.testing.assert_allclose(
            dh.frame_poses(q), robot.frame_poses(full)[[1, 2]], rtol=0, atol=1e-12
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


# Zero is drawn often: the rows without θ, d, a or α are where constants could slip
# from one row into the next.
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
def test_dh_modules_dh_keeps_every_frame(case):
    robot, q = case
    convention = robot.modules[0].convention
    chain, _ = _module_chain(robot.modules)
    held = [i for i, m in enumerate(chain) if m.name.endswith("(constant)")]
    back = rc.modules_to_dh(
        Robot(chain, end_effector=robot.end_effector_point), convention, constant=held
    )
    assert [link.row()[4] for link in back.modules] == [link.row()[4] for link in robot.modules]
    np.testing.assert_allclose(
        [link.row()[:4] for link in back.modules], [link.row()[:4] for link in robot.modules]
    )
    expected = robot.frame_poses(q)
    scale = max(1.0, np.abs(expected).max(), np.abs(robot.end_effector(q)).max())
    close = {"rtol": 0, "atol": 1e-12 * scale}
    np.testing.assert_allclose(back.frame_poses(q), expected, **close)
    np.testing.assert_allclose(back.end_effector_pose(q), robot.end_effector_pose(q), **close)
    for frame in [*range(robot.n), "EE"]:
        np.testing.assert_allclose(
            back.jacobian(q, frame), robot.jacobian(q, frame), **close, err_msg=str(frame)
        )
