"""Ghost robots and the target marker: the ops they send, and what a reload replays."""

from __future__ import annotations

import math

import numpy as np
import pytest

import robotconf as rc
from robotconf.scene import RecordingChannel, Scene
from robotconf.scene._ghosts import GHOST_OPACITY, GHOSTS, MAX_GHOSTS
from robotconf.scene._target import TARGET, TARGET_COLORS


def _transforms(ops: list) -> dict[str, np.ndarray]:
    """The last transform of every path in ``ops``, as 4×4 matrices."""
    out: dict[str, np.ndarray] = {}
    for op in ops:
        if op.content["op"] == "transforms":
            data = np.frombuffer(op.buffers[0], dtype=np.float32).reshape(-1, 4, 4)
            for path, matrix in zip(op.content["paths"], data, strict=True):
                out[path] = matrix.T  # column-major on the wire
    return out


def _visible(ops: list) -> dict[str, bool]:
    out: dict[str, bool] = {}
    for op in ops:
        if op.content["op"] == "visible":
            for path in op.content["paths"]:
                out[path] = op.content["value"]
    return out


@pytest.fixture
def arm() -> rc.Robot:
    return rc.preset("planar_2r")  # l1 = 40, l2 = 30


@pytest.fixture
def scene(arm: rc.Robot) -> Scene:
    return Scene(arm, channel=RecordingChannel())


def test_each_ghost_stands_where_the_core_puts_its_joints(scene: Scene, arm: rc.Robot) -> None:
    rows = np.array([[0.0, math.pi / 2], [math.pi / 2, -math.pi / 2]])
    scene.channel.clear()
    scene.show_ghosts(arm, rows)
    created = [c for c in scene.channel.commands("set_object") if c["path"].startswith(GHOSTS)]
    body = [i for i in scene._robot.drawing.items if i.layer == "body" and i.shape != "triad"]
    assert len(created) == 2 * len(body)
    for command in created:
        material = command["object"]["materials"][0]
        assert material["transparent"] and material["opacity"] == GHOST_OPACITY
    moved = _transforms(scene.channel.ops)
    # By hand: ghost 0 has its elbow (standard DH: frame 1's origin) at (40, 0) and the
    # tool at (40, 30); ghost 1 the elbow at (0, 40) and the tool at (30, 40).
    for k, elbow, tool in (
        (0, [40, 0, 0], [40, 30, 0]),
        (1, [0, 40, 0], [30, 40, 0]),
    ):
        np.testing.assert_allclose(moved[f"{GHOSTS}/{k}/modules/0/sphere"][:3, 3], elbow, atol=1e-5)
        np.testing.assert_allclose(moved[f"{GHOSTS}/{k}/ee/sphere"][:3, 3], tool, atol=1e-5)
    assert scene.ghost_count == 2


def test_fewer_ghosts_reuse_the_objects_and_hide_the_rest(scene: Scene, arm: rc.Robot) -> None:
    scene.show_ghosts(arm, [[0.1, 0.2], [0.3, 0.4], [0.5, 0.6]])
    scene.channel.clear()
    scene.show_ghosts(arm, [[1.0, -1.0]])
    assert scene.channel.commands("set_object") == []  # nothing new to build
    assert _visible(scene.channel.ops) == {
        f"{GHOSTS}/0": True,
        f"{GHOSTS}/1": False,
        f"{GHOSTS}/2": False,
    }
    tool = _transforms(scene.channel.ops)[f"{GHOSTS}/0/ee/sphere"][:3, 3]
    np.testing.assert_allclose(tool, arm.end_effector([1.0, -1.0]), atol=1e-5)
    assert scene.ghost_count == 1


def test_a_reload_replays_ghosts_and_target_until_cleared(scene: Scene, arm: rc.Robot) -> None:
    scene.show_ghosts(arm, [[0.0, 0.5], [0.5, 0.0]])
    scene.show_target([50.0, 20.0, 0.0], reachable=False)
    replay = scene._replay()
    paths = {op.content.get("command", op.content).get("path") for op in replay}
    assert f"{GHOSTS}/1/ee/sphere" in paths and f"{TARGET}/sphere" in paths
    replayed = _transforms(replay)
    np.testing.assert_allclose(
        replayed[f"{GHOSTS}/1/ee/sphere"][:3, 3], arm.end_effector([0.5, 0.0]), atol=1e-5
    )
    scene.clear_ghosts()
    scene.clear_target()
    deletes = [c["path"] for c in scene.channel.commands("delete")]
    assert deletes[-2:] == [GHOSTS, TARGET]
    left = [str(op.content) for op in scene._replay()]
    assert not any(GHOSTS in text or TARGET in text for text in left)
    assert scene.ghost_count == 0 and not scene.target_shown


def test_the_target_marker_colour_position_and_pose_axes(scene: Scene) -> None:
    scene.show_target([10.0, 20.0, 5.0])
    sphere = scene.channel.commands("set_object")[-1]
    assert sphere["path"] == f"{TARGET}/sphere"
    assert sphere["object"]["materials"][0]["color"] == TARGET_COLORS[True]
    placed = [c for c in scene.channel.commands("set_transform") if c["path"] == TARGET][-1]
    matrix = np.array(placed["matrix"]).reshape(4, 4).T
    np.testing.assert_array_equal(matrix[:3, 3], [10.0, 20.0, 5.0])
    pose = np.eye(4)
    pose[:3, :3] = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]
    pose[:3, 3] = (1, 2, 3)
    scene.channel.clear()
    scene.show_target(pose, reachable=False)
    kinds = {c["path"]: c for c in scene.channel.commands("set_object")}
    assert f"{TARGET}/frame" in kinds  # the pose's axes
    assert kinds[f"{TARGET}/sphere"]["object"]["materials"][0]["color"] == TARGET_COLORS[False]
    placed = scene.channel.commands("set_transform")[-1]
    np.testing.assert_array_equal(np.array(placed["matrix"]).reshape(4, 4).T, pose)
    scene.channel.clear()
    scene.show_target([0.0, 0.0, 1.0], reachable=False)  # a point again: the axes go
    assert [c["path"] for c in scene.channel.commands("delete")] == [f"{TARGET}/frame"]
    assert scene.channel.commands("set_object") == []  # same colour: the sphere stays


def test_bad_input_names_the_field(scene: Scene, arm: rc.Robot) -> None:
    with pytest.raises(rc.InvalidInputError, match="^qs:"):
        scene.show_ghosts(arm, [0.1, 0.2])  # one configuration, no ghost axis
    with pytest.raises(rc.InvalidInputError, match="^qs"):
        scene.show_ghosts(arm, [[0.1, 0.2, 0.3]])
    with pytest.raises(rc.InvalidInputError, match="^qs:"):
        scene.show_ghosts(arm, np.zeros((MAX_GHOSTS + 1, 2)))
    with pytest.raises(rc.InvalidInputError, match="^target:"):
        scene.show_target([1.0, np.nan, 0.0])
    with pytest.raises(rc.InvalidInputError, match="^target:"):
        scene.show_target(np.zeros((4, 4)))
    with pytest.raises(rc.InvalidInputError, match="^reachable:"):
        scene.show_target([1.0, 0.0, 0.0], reachable="yes")
    scene.show_ghosts(arm, np.zeros((0, 2)))  # none: nothing drawn
    assert scene.ghost_count == 0
