"""The taught points of a program in the 3D scene: ops checked against hand-computed
positions and sizes, the labels, the scene log (what a reload replays) and bad input."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.scene import RecordingChannel, Scene
from robotconf.scene._commands import Op
from robotconf.scene._taught_points import TAUGHT, TAUGHT_COLORS, TAUGHT_RADIUS

POINTS = np.array([[70.0, 0.0, 20.0], [30.0, 30.0, 60.0]])


def paper_scene() -> Scene:
    return Scene(rc.preset("paper"), channel=RecordingChannel())


def transforms(ops: list[Op]) -> dict[str, np.ndarray]:
    """Path → 4×4 matrix of every batched transform among ``ops`` (column-major float32)."""
    found: dict[str, np.ndarray] = {}
    for op in ops:
        if op.content["op"] == "transforms":
            data = np.frombuffer(op.buffers[0], dtype=np.float32).reshape(-1, 4, 4)
            for path, matrix in zip(op.content["paths"], data, strict=True):
                found[path] = matrix.T
    return found


def test_spheres_and_labels_stand_at_the_points() -> None:
    scene = paper_scene()
    scene.channel.clear()
    scene.show_taught_points(POINTS, via=[[50.0, 20.0, 40.0]])
    size = scene._robot.drawing.size
    spheres = {
        c["path"]: c["object"]
        for c in scene.channel.commands("set_object")
        if "sphere" in c["path"]
    }
    assert sorted(spheres) == [f"{TAUGHT}/{k}/sphere" for k in range(3)]
    radius = TAUGHT_RADIUS * size
    for k, color in enumerate(["point", "point", "via"]):
        obj = spheres[f"{TAUGHT}/{k}/sphere"]
        assert obj["geometries"][0]["radius"] == pytest.approx(radius)
        assert obj["materials"][0]["color"] == TAUGHT_COLORS[color]
    labels = [c for c in scene.channel.commands("set_object") if c["path"].endswith("/label")]
    assert len(labels) == 3
    placed = transforms(scene.channel.ops)
    every = np.vstack([POINTS, [[50.0, 20.0, 40.0]]])
    for k, point in enumerate(every):
        np.testing.assert_allclose(placed[f"{TAUGHT}/{k}/sphere"][:3, 3], point, rtol=1e-6)
        # The label's anchor at the point itself, never turned (the page lifts the text).
        np.testing.assert_allclose(placed[f"{TAUGHT}/{k}/label"][:3, 3], point, rtol=1e-6)
        np.testing.assert_array_equal(placed[f"{TAUGHT}/{k}/label"][:3, :3], np.eye(3))
    texts = [op.content for op in scene.channel.ops if op.content["op"] == "labels"][-1]
    assert texts["texts"] == ["P1", "P2", "via 1"]
    assert texts["paths"] == [f"{TAUGHT}/{k}/label" for k in range(3)]
    # Anchors only: the page writes the texts as the robot's own labels.
    for label in labels:
        assert label["object"]["object"]["type"] == "Object3D"
        assert label["object"]["geometries"] == label["object"]["materials"] == []


def test_coinciding_points_share_one_label() -> None:
    scene = paper_scene()
    points = [[70.0, 0.0, 20.0], [30.0, 30.0, 60.0], [70.0, 0.0, 20.0 + 1e-4]]
    scene.show_taught_points(points, ["P1", "P2", "P4"])
    # Equal at the labels' precision (one decimal for a robot of size 90).
    assert scene.taught_labels == ["P1, P4", "P2", ""]


def test_the_same_points_send_nothing_and_a_clear_leaves_no_trace_in_the_log() -> None:
    scene = paper_scene()
    scene.show_taught_points(POINTS)
    scene.channel.clear()
    scene.show_taught_points(POINTS.copy())
    assert scene.channel.ops == []
    replayed = [op for op in scene._replay() if TAUGHT in str(op.content)]
    assert replayed  # a reloaded page draws them too
    scene.set_robot(rc.preset("paper").with_q([0.3, 0.2, 0.1]))  # a rebuild keeps them
    assert [op for op in scene._replay() if TAUGHT in str(op.content)]
    scene.clear_taught_points()
    assert scene.channel.commands("delete")[-1] == {"type": "delete", "path": TAUGHT}
    assert not [op for op in scene._replay() if TAUGHT in str(op.content)]
    assert scene.taught_labels == []
    scene.channel.clear()
    scene.clear_taught_points()  # nothing shown: nothing sent
    scene.show_taught_points(np.zeros((0, 3)))
    assert scene.channel.ops == []


def test_new_points_replace_the_old_ones() -> None:
    scene = paper_scene()
    scene.show_taught_points(POINTS)
    scene.show_taught_points(POINTS[:1])
    assert scene.taught_labels == ["P1"]
    paths = {op.content.get("command", {}).get("path") for op in scene._replay()}
    assert f"{TAUGHT}/0/sphere" in paths and f"{TAUGHT}/1/sphere" not in paths


@pytest.mark.parametrize(
    ("arguments", "field"),
    [
        (([1.0, 2.0, 3.0],), "points"),  # one point without its row axis
        (([[np.nan, 0.0, 0.0]],), "points"),
        (([[1.0, 2.0]],), "points"),
        ((POINTS, ["P1"]), "labels"),
        ((POINTS, ["P1", 2]), "labels"),
        ((np.zeros((501, 3)),), "points"),
    ],
)
def test_bad_points_are_refused_naming_the_field(arguments: tuple, field: str) -> None:
    scene = paper_scene()
    with pytest.raises(rc.InvalidInputError) as caught:
        scene.show_taught_points(*arguments)
    assert caught.value.field == field
    assert scene.taught_labels == []
