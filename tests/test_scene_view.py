"""What the view holds and what the labels say: the fit takes in the ghosts, the target
marker, the taught points and the point clouds (and widens by itself for one outside the
view); labels are anchored at their very points, ghosts carry none."""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.scene import ROOT, RecordingChannel, Scene
from robotconf.scene._drawing import SPHERE_RADIUS
from robotconf.scene._ghosts import GHOSTS
from robotconf.scene._taught_points import TAUGHT, TAUGHT_RADIUS

ROBOT_PATH = f"{ROOT}/robot"


def _fit(scene: Scene) -> tuple[np.ndarray, float]:
    """The last fitted sphere, in length units: centre (3,) and radius."""
    size = scene._robot.drawing.size
    fits = [op.content for op in scene.channel.ops if op.content["op"] == "fit"]
    centring = [c for c in scene.channel.commands("set_transform") if c["path"] == "/meshcat"]
    shift = np.array(centring[-1]["matrix"]).reshape(4, 4).T[:3, 3]
    return -shift * size, fits[-1]["radius"] * size


def _holds(scene: Scene, points: np.ndarray) -> bool:
    centre, radius = _fit(scene)
    return bool((np.linalg.norm(np.asarray(points) - centre, axis=1) < radius).all())


@pytest.fixture
def scene(paper_robot: rc.Robot) -> Scene:
    return Scene(paper_robot, channel=RecordingChannel())


def test_an_unreachable_target_is_brought_into_view(scene: Scene) -> None:
    fits = scene.channel.kinds().count("fit")
    scene.show_target([60.0, 10.0, 20.0])  # within reach: the view stays
    assert scene.channel.kinds().count("fit") == fits
    far = np.array([400.0, -250.0, 90.0])
    assert not _holds(scene, far[None])
    scene.show_target(far, reachable=False)
    assert scene.channel.kinds().count("fit") == fits + 1
    assert _holds(scene, far[None])
    # The robot is still all in it.
    assert _holds(scene, np.vstack([scene.robot.frame_origins(scene.q), [[70.0, 0, 20]]]))


def test_taught_points_ghosts_and_clouds_are_never_clipped(scene: Scene) -> None:
    taught = np.array([[70.0, 0.0, 20.0], [-150.0, 80.0, 10.0], [30.0, 30.0, 160.0]])
    scene.show_taught_points(taught, via=[[0.0, -120.0, 40.0]])
    assert _holds(scene, np.vstack([taught, [[0.0, -120.0, 40.0]]]))
    ghosts = [[np.pi, 0.0, 0.0], [0.0, -np.pi / 2, 0.0]]
    scene.show_ghosts(scene.robot, ghosts)
    for q in ghosts:
        assert _holds(scene, scene.robot.end_effector(q)[None])
    cloud = np.random.default_rng(2).uniform(-300, 300, (500, 3))
    scene.add_point_cloud("workspace", cloud)
    assert _holds(scene, cloud)
    # fit_view itself takes them all in, from any q.
    scene.update([1.0, -1.0, 0.5])
    scene.fit_view()
    assert _holds(scene, np.vstack([taught, cloud]))
    # The sphere is no bigger than it must be: its centre is the middle of the bounding
    # box of everything (the clouds by their boxes' corners).
    low, high = cloud.min(axis=0), cloud.max(axis=0)
    corners = np.array([[(low, high)[b >> k & 1][k] for k in range(3)] for b in range(8)])
    ghost_points = [scene.robot.end_effector(q) for q in ghosts]
    everything = np.vstack([taught, [[0.0, -120.0, 40.0]], corners, ghost_points])
    centre, radius = _fit(scene)
    np.testing.assert_allclose(centre, 0.5 * (everything.min(0) + everything.max(0)), atol=1e-6)
    margin = 1.2 * SPHERE_RADIUS * scene._robot.drawing.size
    reach = np.linalg.norm(everything - centre, axis=1).max()
    assert radius <= reach + margin + 1e-9


def test_labels_stand_at_their_points_clear_of_their_spheres(scene: Scene) -> None:
    q = np.array([0.3, -0.4, 0.8])
    scene.update(q)
    sent: dict[str, np.ndarray] = {}
    for op in scene.channel.ops:
        if op.content["op"] == "transforms":
            data = np.frombuffer(op.buffers[0], dtype=np.float32).reshape(-1, 4, 4)
            sent.update(zip(op.content["paths"], data, strict=True))
    points = np.vstack([scene.robot.frame_origins(q), scene.robot.end_effector(q)])
    paths = [f"{ROBOT_PATH}/modules/{i}/label" for i in range(3)] + [f"{ROBOT_PATH}/ee/label"]
    for path, point in zip(paths, points, strict=True):
        # The anchor is the point itself: the page lifts the text on screen, so a label
        # never floats off in the scene when the view turns.
        np.testing.assert_allclose(sent[path].T[:3, 3], point, atol=1e-4)
    anchors = {
        c["path"]: c["object"]["object"]
        for c in scene.channel.commands("set_object")
        if c["path"].endswith("/label")
    }
    size = scene._robot.drawing.size
    for anchor in anchors.values():
        assert anchor["type"] == "Object3D"  # nothing drawn in 3D: the page writes the text
        # Clear of the biggest sphere drawn at a point (the end effector's).
        assert anchor["userData"]["clearance"] == pytest.approx(1.2 * SPHERE_RADIUS * size)
    scene.show_taught_points([[10.0, 10.0, 10.0]])
    taught = [c for c in scene.channel.commands("set_object") if c["path"] == f"{TAUGHT}/0/label"]
    assert taught[0]["object"]["object"]["userData"]["clearance"] == pytest.approx(
        TAUGHT_RADIUS * size
    )


def test_a_ghost_has_no_label_to_mistake_for_the_robots(scene: Scene) -> None:
    scene.channel.clear()
    scene.show_ghosts(scene.robot, [[0.5, 0.0, 0.0], [-0.5, 0.3, 0.2]])
    created = [c["path"] for c in scene.channel.commands("set_object")]
    assert created and all(path.startswith(GHOSTS) for path in created)
    assert not any(path.endswith("/label") or path.endswith("/frame") for path in created)
    assert "labels" not in scene.channel.kinds()
    # The robot's own labels still carry the robot's numbers.
    assert scene.labels()[-1] == "EE (70.0, 0.0, 20.0)"


def _robot_labels(scene: Scene) -> list[str]:
    """Every robot label's text, as a new view gets them."""
    (labels,) = [
        op.content
        for op in scene._replay()
        if op.content["op"] == "labels" and op.content["paths"][0].startswith(ROBOT_PATH)
    ]
    return list(labels["texts"])


def test_merged_labels_name_every_point_and_part_while_moving() -> None:
    puma = Scene(rc.preset("puma560"), channel=RecordingChannel())
    texts = _robot_labels(puma)
    assert texts[3].startswith("M4, M5, M6, EE (") and texts[4:] == ["", "", ""]
    puma.set_label_mode("names")
    assert _robot_labels(puma) == ["M1", "M2", "M3", "M4, M5, M6, EE", "", "", ""]
    # During an animation the points part: one name each, no merge.
    motion = rc.simulate(puma.robot, {"q5": rc.signals.Sine(amplitude=1.0)}, t_end=1, dt=0.1)
    puma.animate(motion)
    assert _robot_labels(puma) == ["M1", "M2", "M3", "M4", "M5", "M6", "EE"]


def test_labels_off_hides_the_taught_points_labels_too(scene: Scene) -> None:
    scene.show_taught_points([[10.0, 0.0, 0.0], [20.0, 0.0, 0.0]])
    scene.channel.clear()
    scene.set_label_mode("off")
    hidden = {
        path: op.content["value"]
        for op in scene.channel.ops
        if op.content["op"] == "visible"
        for path in op.content["paths"]
    }
    assert hidden[f"{TAUGHT}/0/label"] is False and hidden[f"{TAUGHT}/1/label"] is False
    assert hidden[f"{ROBOT_PATH}/ee/label"] is False
    # New points keep the mode: their labels come hidden.
    scene.show_taught_points([[30.0, 0.0, 0.0]])
    visible = [op.content for op in scene.channel.ops if op.content["op"] == "visible"][-1]
    assert visible == {"op": "visible", "paths": [f"{TAUGHT}/0/label"], "value": False}


def test_fit_takes_in_a_loaded_motion_but_animate_keeps_the_view(scene: Scene) -> None:
    motion = rc.simulate(scene.robot, {"q1": rc.signals.Sine(amplitude=2.5)}, t_end=2, dt=0.01)
    fits = scene.channel.kinds().count("fit")
    scene.animate(motion)
    assert scene.channel.kinds().count("fit") == fits  # the student's view stays
    swept = motion.position.reshape(-1, 3)
    assert not _holds(scene, swept)
    scene.fit_view()
    assert _holds(scene, swept[:: max(1, len(swept) // 2000)])
