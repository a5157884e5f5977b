"""Robot: shapes, batching, active modules and immutable editing."""

import numpy as np
import pytest

import robotconf as rc

from .conftest import assert_transform_close, reference_poses


def six_module_robot() -> rc.Robot:
    return rc.Robot(
        [
            rc.Module("Rz", a=(0, 0, 0.1)),
            rc.Module("Ry", a=(0, 0.05, 0.3)),
            rc.Module("Tz", a=(0.4, 0, 0)),
            rc.Module("Rx", a=(0.35, 0, 0.02)),
            rc.Module("none"),
            rc.Module("fixed", a=(0.1, 0.0, -0.05)),
        ],
        end_effector=(0.05, 0.01, 0.0),
    )


def test_readme_example_shapes(paper_robot):
    assert paper_robot.transfer_matrices().shape == (3, 4, 4)
    assert paper_robot.frame_poses([0, 0, 0]).shape == (3, 4, 4)
    assert paper_robot.end_effector([0, 0, 0]).shape == (3,)
    assert paper_robot.end_effector_pose([0, 0, 0]).shape == (4, 4)
    trajectory = np.zeros((1000, 3))
    assert paper_robot.frame_poses(trajectory).shape == (1000, 3, 4, 4)
    assert paper_robot.end_effector(trajectory).shape == (1000, 3)
    assert paper_robot.frame_origins(trajectory).shape == (1000, 3, 3)
    assert paper_robot.transfer_matrices(trajectory).shape == (1000, 3, 4, 4)
    assert paper_robot.end_effector_pose(trajectory).shape == (1000, 4, 4)


@pytest.mark.parametrize("samples", [1, 7, 4095, 4096, 4097, 9000])
def test_batch_equals_per_sample(samples, rng):
    robot = six_module_robot()
    q = rng.uniform(-3, 3, (samples, robot.n))
    poses = robot.frame_poses(q)
    origins = robot.frame_origins(q)
    ee = robot.end_effector(q)
    ee_pose = robot.end_effector_pose(q)
    transfer = robot.transfer_matrices(q)
    for t in sorted({0, samples // 2, samples - 1}):
        assert_transform_close(poses[t], robot.frame_poses(q[t]))
        assert_transform_close(poses[t], reference_poses(robot, q[t]))
        np.testing.assert_allclose(origins[t], poses[t][:, :3, 3], rtol=0, atol=1e-12)
        np.testing.assert_allclose(ee[t], robot.end_effector(q[t]), rtol=0, atol=1e-12)
        assert_transform_close(ee_pose[t], robot.end_effector_pose(q[t]))
        assert_transform_close(transfer[t], robot.transfer_matrices(q[t]))


def test_end_effector_pose_is_last_frame_moved_to_the_point(rng):
    robot = six_module_robot()
    q = rng.uniform(-3, 3, robot.n)
    last = robot.frame_poses(q)[-1]
    pose = robot.end_effector_pose(q)
    np.testing.assert_allclose(pose[:3, :3], last[:3, :3], atol=1e-15)
    np.testing.assert_allclose(
        pose[:3, 3], (last @ np.array([0.05, 0.01, 0.0, 1.0]))[:3], atol=1e-12
    )
    np.testing.assert_allclose(pose[:3, 3], robot.end_effector(q), atol=1e-15)


def test_empty_trajectory():
    robot = six_module_robot()
    assert robot.frame_poses(np.zeros((0, 6))).shape == (0, 6, 4, 4)
    assert robot.end_effector(np.zeros((0, 6))).shape == (0, 3)


def test_active_modules_act_as_identity(paper_robot):
    robot = paper_robot.with_active(2)
    q = [0.3, 0.5, 1.0]
    a = robot.transfer_matrices(q)
    np.testing.assert_array_equal(a[2], np.eye(4))
    poses = robot.frame_poses(q)
    np.testing.assert_array_equal(poses[2], poses[1])
    # EE = M_2 · P: the third module's offset (30, 0, 0) is gone too.
    expected = poses[1] @ np.array([40.0, 0, 0, 1])
    np.testing.assert_allclose(robot.end_effector(q), expected[:3], atol=1e-12)
    np.testing.assert_allclose(robot.with_active(2).end_effector([0, 0, 0]), [40, 0, 20])
    assert robot.active == 2 and paper_robot.active == 3


def test_with_methods_return_new_robots(paper_robot):
    moved = paper_robot.with_q([0.1, 0.2, 0.3])
    np.testing.assert_array_equal(moved.q, [0.1, 0.2, 0.3])
    np.testing.assert_array_equal(paper_robot.q, [0, 0, 0])

    swapped = paper_robot.with_module(0, rc.Module("Tz"))
    assert swapped.modules[0].kind == "Tz" and paper_robot.modules[0].kind == "Rz"

    longer = paper_robot.with_appended(rc.Module("Rx", a=(5, 0, 0)))
    assert longer.n == 4 and paper_robot.n == 3
    assert longer.modules[-1].kind == "Rx"

    inserted = paper_robot.with_inserted(1, rc.Module("Tz"))
    assert [m.kind for m in inserted.modules] == ["Rz", "Tz", "Ry", "Ry"]

    shorter = paper_robot.with_removed(0)
    assert [m.a for m in shorter.modules] == [(0, 0, 20), (30, 0, 0)]

    reordered = paper_robot.with_moved(2, 0)
    assert [m.a for m in reordered.modules] == [(30, 0, 0), (0, 0, 0), (0, 0, 20)]

    assert paper_robot.with_end_effector((1, 2, 3)).end_effector_point.tolist() == [1, 2, 3]
    assert paper_robot.with_name("RzRyRy").name == "RzRyRy"


def test_editing_keeps_active_count_consistent(paper_robot):
    robot = paper_robot.with_active(2)
    assert robot.with_inserted(0, rc.Module("Tz")).active == 3
    assert robot.with_inserted(3, rc.Module("Tz")).active == 2
    assert robot.with_removed(0).active == 1
    assert robot.with_removed(2).active == 2
    assert robot.with_active(None).active == 3


def test_names_follow_the_paper(paper_robot):
    assert paper_robot.module_names == ("M1", "M2", "M3")
    assert paper_robot.coordinate_names == ("q1", "q2", "q3")
    named = paper_robot.with_module(0, rc.Module("Rz", name="base"))
    assert named.module_names == ("base", "M2", "M3")
    assert paper_robot.joint_types == ("revolute", "revolute", "revolute")


def test_repr_round_trips_and_equality(paper_robot):
    robot = paper_robot.with_active(2).with_name("paper")
    namespace = {"Robot": rc.Robot, "Module": rc.Module, "DHLink": rc.DHLink}
    assert eval(repr(robot), namespace) == robot
    assert robot != paper_robot
    assert hash(paper_robot) == hash(eval(repr(paper_robot), namespace))
    dh = rc.Robot.from_dh([(0.1, 0.2, 0.3, 0.4, "R")], convention="modified")
    assert eval(repr(dh), namespace) == dh


def test_str_lists_modules(paper_robot):
    text = str(paper_robot.with_active(2))
    assert "M3: Module('Ry', a=(30.0, 0.0, 0.0))  (inactive)" in text
    assert "3 modules, 2 active" in text


def test_end_effector_point_is_a_copy(paper_robot):
    point = paper_robot.end_effector_point
    point[0] = 999
    np.testing.assert_array_equal(paper_robot.end_effector_point, [40, 0, 0])


def test_out_parameter_reuses_memory(paper_robot, rng):
    from robotconf.kinematics import chain_poses

    q = rng.uniform(-1, 1, (50, 3))
    out = np.full((50, 3, 4, 4), np.nan)
    result = chain_poses(paper_robot.geometry(), q, out=out)
    assert result is out
    assert_transform_close(out, paper_robot.frame_poses(q))
    with pytest.raises(
        ValueError, match=r"out: wrong output: .*float64 array of shape \(50, 3, 4, 4\)"
    ):
        chain_poses(paper_robot.geometry(), q, out=np.empty((50, 3, 4, 3)))
    with pytest.raises(ValueError, match=r"out: wrong output: 'list'"):
        paper_robot.end_effector(q, out=[0, 0, 0])
    single = np.empty((3, 4, 4))
    paper_robot.frame_poses([0, 0, 0], out=single)
    np.testing.assert_array_equal(single[2, :3, 3], [30, 0, 20])
    ee = np.empty((50, 3))
    assert paper_robot.end_effector(q, out=ee) is ee
    np.testing.assert_allclose(ee, paper_robot.end_effector(q), atol=0)


@pytest.mark.parametrize("block_size", [1, 3, 64])
def test_block_boundaries_do_not_change_results(block_size, rng):
    from robotconf.kinematics import chain_origins, chain_poses

    robot = six_module_robot()
    q = rng.uniform(-3, 3, (100, robot.n))
    assert_transform_close(
        chain_poses(robot.geometry(), q, block_size=block_size), robot.frame_poses(q)
    )
    np.testing.assert_allclose(
        chain_origins(robot.geometry(), q, block_size=block_size),
        robot.frame_origins(q),
        atol=1e-12,
    )


@pytest.mark.parametrize("name", ["q1", "Q1", "EE", " ee "])
def test_a_module_name_that_would_be_ambiguous_is_refused(name):
    # Robot.index finds modules, coordinates and the end-effector by name.
    with pytest.raises(rc.InvalidInputError, match=r"modules\[1\]\.name: ambiguous module name"):
        rc.Robot([rc.Module("Rz"), rc.Module("Rz", name=name)])
    assert rc.Robot([rc.Module("Rz"), rc.Module("Rz", name="q2")]).index("q2") == 1


def test_index_resolves_every_way_of_naming_a_module(paper_robot):
    named = paper_robot.with_module(1, paper_robot.modules[1].with_name("shoulder"))
    assert [named.index(k) for k in (1, "shoulder", "q2", "Q2", "M1", "M3")] == [1, 1, 1, 1, 0, 2]
    assert named.index("ee", "frame", end_effector=True) == 3
    with pytest.raises(rc.InvalidInputError, match=r"frame: unknown module 'EE'"):
        named.index("EE", "frame")
    with pytest.raises(rc.InvalidInputError, match=r"index: out of range: 3"):
        named.index(3)
