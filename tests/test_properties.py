"""Invariants checked over random robots and configurations (hypothesis)."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import robotconf as rc

from .conftest import reference_poses

finite = st.floats(min_value=-10, max_value=10, allow_nan=False)
angles = st.floats(min_value=-4 * np.pi, max_value=4 * np.pi, allow_nan=False)
vectors = st.tuples(finite, finite, finite)

modules = st.builds(
    rc.Module,
    kind=st.sampled_from(["none", "Rx", "Ry", "Rz", "Tx", "Ty", "Tz", "fixed"]),
    a=vectors,
)
dh_links = st.builds(
    rc.DHLink,
    theta=angles,
    d=finite,
    a=finite,
    alpha=angles,
    joint=st.sampled_from(["R", "P"]),
    convention=st.sampled_from(["standard", "modified"]),
)
links = st.lists(st.one_of(modules, dh_links), min_size=1, max_size=7)


@st.composite
def robots_and_q(draw):
    chain = draw(links)
    robot = rc.Robot(chain, end_effector=draw(vectors))
    count = draw(st.integers(min_value=1, max_value=5))
    q = np.array(
        draw(
            st.lists(
                st.lists(angles, min_size=robot.n, max_size=robot.n), min_size=count, max_size=count
            )
        )
    )
    return robot, q


@settings(max_examples=150, deadline=None)
@given(robots_and_q())
def test_rotation_part_is_orthonormal_with_det_one(case):
    robot, q = case
    rotations = robot.frame_poses(q)[..., :3, :3]
    identity = np.broadcast_to(np.eye(3), rotations.shape)
    np.testing.assert_allclose(rotations @ np.swapaxes(rotations, -1, -2), identity, atol=1e-12)
    np.testing.assert_allclose(np.linalg.det(rotations), 1.0, atol=1e-12)
    np.testing.assert_array_equal(
        robot.frame_poses(q)[..., 3, :], np.broadcast_to([0, 0, 0, 1], rotations.shape[:-2] + (4,))
    )


@settings(max_examples=150, deadline=None)
@given(robots_and_q())
def test_kernel_agrees_with_plain_4x4_products(case):
    robot, q = case
    poses = robot.frame_poses(q)
    ee = robot.end_effector(q)
    point = np.append(robot.end_effector_point, 1.0)
    for t in range(len(q)):
        expected = reference_poses(robot, q[t])
        # Relative to the size of the numbers involved (lengths up to 10 over 7 links).
        scale = max(1.0, np.abs(expected).max())
        np.testing.assert_allclose(poses[t], expected, rtol=0, atol=1e-12 * scale)
        np.testing.assert_allclose(ee[t], (expected[-1] @ point)[:3], rtol=0, atol=1e-12 * scale)


@settings(max_examples=100, deadline=None)
@given(robots_and_q(), st.data())
def test_active_k_equals_truncated_chain(case, data):
    robot, q = case
    k = data.draw(st.integers(min_value=1, max_value=robot.n))
    limited = robot.with_active(k)
    truncated = rc.Robot(robot.modules[:k], end_effector=robot.end_effector_point)
    poses = limited.frame_poses(q)
    np.testing.assert_allclose(poses[:, :k], truncated.frame_poses(q[:, :k]), rtol=0, atol=1e-12)
    for i in range(k, robot.n):
        np.testing.assert_array_equal(poses[:, i], poses[:, k - 1])
    np.testing.assert_allclose(
        limited.end_effector(q), truncated.end_effector(q[:, :k]), rtol=0, atol=1e-12
    )


@settings(max_examples=100, deadline=None)
@given(robots_and_q())
def test_transfer_matrices_compose_to_frame_poses(case):
    robot, q = case
    transfer = robot.transfer_matrices(q)
    poses = robot.frame_poses(q)
    running = np.broadcast_to(np.eye(4), (len(q), 4, 4))
    for i in range(robot.n):
        running = running @ transfer[:, i]
        scale = max(1.0, np.abs(running).max())
        np.testing.assert_allclose(poses[:, i], running, rtol=0, atol=1e-12 * scale)
