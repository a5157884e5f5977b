"""The 3D scene against a recording fake viewer: what it creates, what an update sends,
and that every number it shows is the core's."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

import robotconf as rc
from robotconf.scene import (
    ROOT,
    RecordingChannel,
    RobotDrawing,
    Scene,
    SceneLog,
    WidgetChannel,
    align_y,
    coalesce_ops,
    compose,
    pack_ops,
    quaternions,
    robot_size,
    transforms_op,
)

from .conftest import L1, L2, L3

ROBOT_PATH = f"{ROOT}/robot"


@pytest.fixture
def scene(paper_robot: rc.Robot) -> Scene:
    return Scene(paper_robot, channel=RecordingChannel())


def _transforms(scene: Scene) -> dict[str, np.ndarray]:
    """The last transform sent for every path, as 4×4 matrices."""
    out: dict[str, np.ndarray] = {}
    for op in scene.channel.ops:
        if op.content["op"] == "transforms":
            data = np.frombuffer(op.buffers[0], dtype=np.float32).reshape(-1, 4, 4)
            for path, matrix in zip(op.content["paths"], data, strict=True):
                out[path] = matrix.T  # column-major on the wire
    return out


def test_paper_robot_labels_carry_the_core_numbers(scene: Scene) -> None:
    assert scene.labels() == [
        "M1 (0.0, 0.0, 0.0)",
        f"M2 (0.0, 0.0, {L1:.1f})",
        f"M3 ({L2:.1f}, 0.0, {L1:.1f})",
        f"EE ({L2 + L3:.1f}, 0.0, {L1:.1f})",
    ]
    labels = [op for op in scene.channel.ops if op.content["op"] == "labels"][-1]
    assert labels.content["texts"][-1] == "EE (70.0, 0.0, 20.0)"


def test_spheres_sit_at_the_core_positions(scene: Scene, paper_robot: rc.Robot) -> None:
    q = np.array([0.4, -0.7, 1.1])
    scene.update(q)
    sent = _transforms(scene)
    origins = paper_robot.frame_origins(q)
    for i in range(3):
        np.testing.assert_allclose(
            sent[f"{ROBOT_PATH}/modules/{i}/sphere"][:3, 3], origins[i], atol=1e-4
        )
    ee = sent[f"{ROBOT_PATH}/ee/sphere"][:3, 3]
    np.testing.assert_allclose(ee, paper_robot.end_effector(q), atol=1e-4)
    # Independent check of the EE by hand: R_z(q1)·(l2 cos q2 + l3 cos(q2+q3), 0, ...).
    q1, q2, q3 = q
    reach = L2 * np.cos(q2) + L3 * np.cos(q2 + q3)
    height = L1 - L2 * np.sin(q2) - L3 * np.sin(q2 + q3)
    np.testing.assert_allclose(ee, [reach * np.cos(q1), reach * np.sin(q1), height], atol=1e-4)


def test_objects_are_created_once_and_update_sends_only_transforms(scene: Scene) -> None:
    created = [c["path"] for c in scene.channel.commands("set_object")]
    assert len(created) == len(set(created)) == len(scene._robot.drawing.items)
    scene.channel.clear()
    for k in range(5):
        scene.update([0.1 * k, 0.2, -0.3])
    assert set(scene.channel.kinds()) == {"transforms", "labels"}
    assert len(scene.channel.messages) == 5
    assert all(len(message) <= 2 for message in scene.channel.messages)


def test_labels_are_not_resent_when_unchanged(scene: Scene) -> None:
    scene.update([0.0, 0.0, 0.0])
    scene.channel.clear()
    scene.update([1e-6, 0.0, 0.0])  # labels round to the same text
    assert scene.channel.kinds() == ["transforms"]


def test_drawn_items_follow_the_paper_figure(paper_robot: rc.Robot) -> None:
    drawing = RobotDrawing(paper_robot, robot_size(paper_robot))
    colors = {item.path: item.color for item in drawing.items}
    assert colors["ee/sphere"] == 0xD62728  # red end-effector
    assert all(colors[f"modules/{i}/sphere"] == 0x2CA02C for i in range(3))  # green joints
    assert {item.shape for item in drawing.items if item.path.endswith("/joint")} == {"cylinder"}
    assert robot_size(paper_robot) == pytest.approx(L1 + L2 + L3)


def test_prismatic_joints_are_boxes_and_grow_with_q() -> None:
    robot = rc.preset("cartesian")
    scene = Scene(robot, channel=RecordingChannel())
    shapes = {item.path: item.shape for item in scene._robot.drawing.items}
    assert [shapes[f"modules/{i}/joint"] for i in range(3)] == ["box", "box", "box"]
    scene.update([0.0, 0.0, 0.0])
    short = _transforms(scene)[f"{ROBOT_PATH}/modules/2/joint"]
    scene.update([0.0, 0.0, 0.5 * robot_size(robot)])
    long = _transforms(scene)[f"{ROBOT_PATH}/modules/2/joint"]
    # A unit box scaled along its length: the column norm is the drawn length.
    assert np.linalg.norm(long[:3, 1]) > np.linalg.norm(short[:3, 1])


def test_zero_length_links_draw_nothing_and_no_nan(paper_robot: rc.Robot) -> None:
    # M1 sits at the base: the first link has zero length.
    scene = Scene(paper_robot, channel=RecordingChannel())
    sent = _transforms(scene)
    first = sent[f"{ROBOT_PATH}/links/0"]
    assert np.all(np.isfinite(np.concatenate(list(sent.values()))))
    assert np.abs(first[:3, :3]).max() < 1e-6
    robot = rc.Robot([rc.Module("none"), rc.Module("Rz")], end_effector=(0, 0, 0))
    empty = Scene(robot, channel=RecordingChannel())
    assert all(np.all(np.isfinite(m)) for m in _transforms(empty).values())


def test_structure_change_rebuilds_and_value_change_does_not(scene: Scene, paper_robot) -> None:
    scene.channel.clear()
    scene.set_robot(paper_robot.with_q([0.3, 0.2, 0.1]))
    assert "set_object" not in scene.channel.kinds()
    scene.channel.clear()
    scene.set_robot(paper_robot.with_module(1, rc.Module("Tz", a=(0, 0, L1))))
    kinds = scene.channel.kinds()
    assert kinds[0] == "delete" and "set_object" in kinds
    assert scene.labels()[-1] == "EE (70.0, 0.0, 20.0)"


def test_frames_and_labels_toggle_visibility(scene: Scene) -> None:
    scene.channel.clear()
    scene.show_frames(True)
    scene.show_labels(False)
    ops = [op for op in scene.channel.ops if op.content["op"] == "visible"]
    assert [op.content["value"] for op in ops] == [True, False]
    assert all(p.endswith("/frame") for p in ops[0].content["paths"])
    assert all(p.endswith("/label") for p in ops[1].content["paths"])
    # The page's bar shows what the kernel holds now.
    options = [op.content for op in scene.channel.ops if op.content["op"] == "options"]
    assert options[-1] == {
        "op": "options",
        "labels": "off",
        "frames": True,
        "trace": False,
        "controls": True,
    }
    assert (scene.label_mode, scene.frames_shown) == ("off", True)


def test_scene_log_replays_compactly(scene: Scene) -> None:
    for k in range(50):
        scene.update([0.01 * k, 0.0, 0.0])
    ops = scene._outbox.log.ops()
    assert sum(op.content["op"] == "transforms" for op in ops) == 1
    assert sum(op.content["op"] == "labels" for op in ops) == 1
    replayed = _transforms_from(ops)
    np.testing.assert_allclose(
        replayed[f"{ROBOT_PATH}/ee/sphere"][:3, 3], scene.robot.end_effector(scene.q), atol=1e-4
    )


def test_scene_log_keeps_every_packed_object(scene: Scene) -> None:
    # Triads and point clouds travel packed; a replay (new view, reload, export) needs all.
    scene.add_point_cloud("first", np.zeros((3, 3)))
    scene.add_point_cloud("second", np.ones((3, 3)))
    replay = RecordingChannel()
    replay.send(scene._outbox.log.ops())
    created = {c["path"] for c in replay.commands("set_object")}
    assert {f"{ROOT}/clouds/first", f"{ROOT}/clouds/second"} <= created
    assert created >= {f"{ROBOT_PATH}/{item.path}" for item in scene._robot.drawing.items}


def _transforms_from(ops) -> dict[str, np.ndarray]:  # type: ignore[no-untyped-def]
    channel = RecordingChannel()
    channel.send(ops)
    holder = type("Holder", (), {"channel": channel})
    return _transforms(holder)  # type: ignore[arg-type]


def test_log_forgets_a_deleted_subtree() -> None:
    log = SceneLog()
    log.record(("set_object", "/a/b"), transforms_op(["/a/b"], np.eye(4)[None]))
    log.record(("set_object", "/ab"), transforms_op(["/ab"], np.eye(4)[None]))
    log.forget("/a")
    assert len(log) == 1


def test_widget_channel_replays_to_a_new_view_and_coalesces(paper_robot: rc.Robot) -> None:
    scene = rc.view(paper_robot, display=False, max_rate=None)
    channel = scene.channel
    assert isinstance(channel, WidgetChannel)
    sent: list[tuple[dict, list]] = []
    scene.pane.send = lambda content, buffers=None: sent.append((content, buffers))
    channel._on_message(scene.pane, {"kind": "hello", "view": "v1"}, [])
    content, buffers = sent[-1]
    assert content["kind"] == "replay" and content["view"] == "v1"
    assert len(buffers) >= 1
    json.dumps(content)  # the comm sends JSON plus binary buffers
    a = transforms_op(["/x"], np.eye(4)[None])
    b = transforms_op(["/x"], 2 * np.eye(4)[None])
    assert coalesce_ops([a, b]) == [b]


def test_update_rejects_bad_q_and_keeps_the_pose(scene: Scene) -> None:
    scene.update([0.1, 0.2, 0.3])
    with pytest.raises(rc.InvalidInputError, match=r"q.*finite"):
        scene.update([0.1, np.nan, 0.3])
    with pytest.raises(rc.InvalidInputError, match=r"q"):
        scene.update([0.1, 0.2])
    with pytest.raises(rc.InvalidInputError, match="one configuration"):
        scene.update(np.zeros((4, 3)))
    np.testing.assert_allclose(scene.q, [0.1, 0.2, 0.3])


def test_bad_constructor_arguments_are_named(paper_robot: rc.Robot) -> None:
    with pytest.raises(rc.InvalidInputError, match="robot"):
        Scene("not a robot", channel=RecordingChannel())  # type: ignore[arg-type]
    with pytest.raises(rc.InvalidInputError, match="height: out of range: 5"):
        Scene(paper_robot, height=5, channel=RecordingChannel())
    with pytest.raises(rc.InvalidInputError, match="height: not an integer: 420.0"):
        Scene(paper_robot, height=420.0, channel=RecordingChannel())  # type: ignore[arg-type]
    with pytest.raises(rc.InvalidInputError, match="labels: invalid value 'no'; allowed: True"):
        Scene(paper_robot, labels="no", channel=RecordingChannel())  # type: ignore[arg-type]


def test_visibility_switches_take_only_true_or_false(scene: Scene) -> None:
    with pytest.raises(rc.InvalidInputError, match="visible: not True or False: 1"):
        scene.show_frames(1)  # type: ignore[arg-type]
    with pytest.raises(rc.InvalidInputError, match="visible: not True or False: 'off'"):
        scene.show_labels("off")  # type: ignore[arg-type]


def test_animation_tracks_follow_the_motion(scene: Scene, paper_robot: rc.Robot) -> None:
    motion = rc.simulate(paper_robot, {"q3": rc.signals.RepeatingSequence()}, t_end=2, dt=0.5)
    scene.animate(motion, speed=2.0)
    command = scene.channel.commands("set_animation")[-1]
    by_path = {a["path"]: a["clip"] for a in command["animations"]}
    tracks = {t["name"]: t for t in by_path[f"{ROBOT_PATH}/ee/sphere"]["tracks"]}
    # Motion seconds (float32 bytes, as the viewer decodes them into a Float32Array): the
    # page's player plays them at speed 2.
    times = np.frombuffer(tracks[".position"]["times"].data, dtype=np.float32)
    assert times.tolist() == [0.0, 0.5, 1.0, 1.5, 2.0]
    assert command["options"] == {"play": False, "repetitions": 1}  # the page plays it
    (load,) = [op.content for op in scene.channel.ops if op.content["op"] == "playback"]
    assert (load["action"], load["speed"], load["duration"], load["playing"]) == (
        "load",
        2.0,
        2.0,
        True,
    )
    positions = np.frombuffer(tracks[".position"]["values"].data, dtype=np.float32)
    np.testing.assert_allclose(positions.reshape(-1, 3), motion.position[:, -1], rtol=1e-6)
    labels = [op.content for op in scene.channel.ops if op.content["op"] == "labels"]
    assert labels[-1]["texts"] == ["M1", "M2", "M3", "EE"]
    with pytest.raises(rc.InvalidInputError, match="speed: must be positive: 0.0"):
        scene.animate(motion, speed=0)
    with pytest.raises(rc.InvalidInputError, match="speed: a boolean is not a number"):
        scene.animate(motion, speed=True)
    with pytest.raises(rc.InvalidInputError, match="play: not True or False: 'yes'"):
        scene.animate(motion, play="yes")  # type: ignore[arg-type]
    with pytest.raises(rc.InvalidInputError, match="motion"):
        scene.animate("not a motion")


def test_point_cloud_is_packed_and_validated(scene: Scene) -> None:
    import msgpack

    points = np.random.default_rng(1).random((20, 3))
    scene.add_point_cloud("workspace", points)
    (op,) = [op for op in scene.channel.ops if op.content["op"] == "packed"][-1:]
    command = msgpack.unpackb(op.buffers[0])
    assert command["type"] == "set_object" and command["path"].endswith("clouds/workspace")
    position = command["object"]["geometries"][0]["data"]["attributes"]["position"]
    assert position["array"].code == 0x17  # the viewer's Float32Array
    sent = np.frombuffer(position["array"].data, dtype=np.float32).reshape(-1, 3)
    np.testing.assert_allclose(sent, points, rtol=1e-6)
    with pytest.raises(rc.InvalidInputError, match="points"):
        scene.add_point_cloud("w", np.zeros((4, 2)))
    with pytest.raises(rc.InvalidInputError, match="color"):
        scene.add_point_cloud("w", np.zeros((4, 3)), color=(2, 0, 0))
    with pytest.raises(rc.InvalidInputError, match="name"):
        scene.add_point_cloud("../x", np.zeros((4, 3)))


def test_export_html_is_self_contained(scene: Scene, tmp_path) -> None:  # type: ignore[no-untyped-def]
    motion = rc.simulate(scene.robot, {"q1": rc.signals.Sine(amplitude=1.0)}, t_end=1, dt=0.1)
    scene.animate(motion)
    path = scene.export_html(tmp_path / "robot.html")
    text = path.read_text()
    assert re.search(r"<script[^>]+src=", text) is None
    assert "set_animation" in text and "rcLoadMeshcat" in text
    assert len(text) > 800_000  # meshcat's viewer is inlined
    log = text.split('id="robotconf-scene-log" type="application/json">')[1].split("</script>")[0]
    assert json.loads(log)["ops"]


def test_viewer_bundle_is_robotconfs_copy_else_meshcats_else_says_how_to_get_it(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    from robotconf.scene import _assets

    # The build's copy (an installed wheel, or this editable checkout once built).
    copy = tmp_path / "main.min.js"
    copy.write_text("// viewer", encoding="utf-8")
    monkeypatch.setattr(_assets, "PACKAGED", copy)
    assert _assets.meshcat_bundle() == copy

    # A source tree that was not built: an installed meshcat package, read as a file.
    monkeypatch.setattr(_assets, "PACKAGED", tmp_path / "absent.js")
    bundle = _assets.meshcat_bundle()
    assert bundle.parts[-4:] == ("meshcat", "viewer", "dist", "main.min.js")
    assert bundle.stat().st_size > 500_000

    monkeypatch.setattr(_assets, "find_spec", lambda name: None)
    with pytest.raises(RuntimeError, match=r"not built.*Reinstall robotconf.*pip install meshcat"):
        _assets.meshcat_bundle()


def test_placement_helpers_match_hand_values() -> None:
    for d in np.array([[1, 0, 0], [0, 0, 1], [0, -1, 0], [0.6, 0.0, 0.8]]):
        r = align_y(d)
        np.testing.assert_allclose(r @ [0, 1, 0], d, atol=1e-12)
        np.testing.assert_allclose(r @ r.T, np.eye(3), atol=1e-12)
        assert np.linalg.det(r) == pytest.approx(1.0)
    half = np.sqrt(0.5)
    rz90 = np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1]], dtype=float)
    np.testing.assert_allclose(quaternions(rz90), [0, 0, half, half], atol=1e-12)
    rx180 = np.diag([1.0, -1, -1])
    np.testing.assert_allclose(np.abs(quaternions(rx180)), [1, 0, 0, 0], atol=1e-12)
    m = compose(np.array([1.0, 2, 3]), rz90, np.array([1.0, 2, 1]))
    np.testing.assert_allclose(m @ [0, 1, 0, 1], [-2 + 1, 0 + 2, 3, 1])


def test_pack_ops_indexes_buffers() -> None:
    a = transforms_op(["/a"], np.eye(4)[None])
    contents, buffers = pack_ops([a, a])
    assert [c["buffers"] for c in contents] == [[0], [1]] and len(buffers) == 2


def test_view_shows_one_pane_per_cell_in_a_kernel(tmp_path) -> None:  # type: ignore[no-untyped-def]
    import nbclient
    import nbformat

    notebook = nbformat.v4.new_notebook()
    notebook.cells = [
        nbformat.v4.new_code_cell(source)
        for source in (
            "import robotconf as rc\nrc.view(rc.preset('paper'))",  # last line: no double
            "scene = rc.view(rc.preset('paper'))",
            "scene",  # a second view of the same scene, on purpose
        )
    ]
    nbclient.NotebookClient(notebook, kernel_name="python3", timeout=120).execute(cwd=str(tmp_path))
    views = [
        sum("application/vnd.jupyter.widget-view+json" in o.get("data", {}) for o in cell.outputs)
        for cell in notebook.cells
    ]
    assert views == [1, 1, 1]


# -- what a view shows after a reload, and what an update sends ----------------------------


def _replayed(scene: Scene) -> RecordingChannel:
    """What a new view (a reloaded page, a second output) applies, in order."""
    replay = RecordingChannel()
    replay.send(scene._replay())
    return replay


def _motion(robot: rc.Robot):  # type: ignore[no-untyped-def]
    return rc.simulate(robot, {"q2": rc.signals.Sine(amplitude=1.0)}, t_end=2, dt=0.1)


def test_reload_after_animation_and_update_shows_the_current_pose(scene: Scene) -> None:
    scene.animate(_motion(scene.robot))
    scene.channel.clear()
    q = np.array([0.5, -0.9, 1.2])
    scene.update(q)
    # The live views drop the animation before taking the new transforms.
    kinds = [op.content["op"] for op in scene.channel.ops]
    assert kinds[0] == "playback" and scene.channel.ops[0].content["action"] == "clear"
    assert kinds.index("transforms") > 0
    live = _transforms(scene)
    assert len(live) == len(scene._robot.drawing.paths)  # every item: the animation moved them all
    # A new view gets no animation at all, and ends with the current transforms.
    replay = _replayed(scene)
    assert "set_animation" not in replay.kinds()
    np.testing.assert_allclose(
        _transforms(type("H", (), {"channel": replay}))[f"{ROBOT_PATH}/ee/sphere"][:3, 3],
        scene.robot.end_effector(q),
        atol=1e-4,
    )
    assert replay.ops[-1].content["texts"][-1] == scene.labels()[-1]


def test_reload_during_an_animation_loads_it_after_the_pose(scene: Scene) -> None:
    scene.animate(_motion(scene.robot), play=True)
    replay = _replayed(scene)
    kinds = replay.kinds()
    animation = replay.commands("set_animation")[0]
    assert animation["options"]["play"] is False
    # The current transforms first, then the animation and where its player stands: the
    # new view shows the motion's frame, at the time the others show.
    assert kinds.index("transforms") < kinds.index("set_animation") < kinds.index("playback")
    load = replay.ops[-1].content
    assert load["action"] == "load" and load["playing"] is True
    assert 0.0 <= load["time"] < 0.5


def test_update_sends_only_what_moved(scene: Scene) -> None:
    scene.update([0.0, 0.0, 0.0])
    scene.channel.clear()
    scene.update([0.0, 0.0, 0.4])  # the last joint: nothing before it moves
    (op,) = [op for op in scene.channel.ops if op.content["op"] == "transforms"]
    moved = set(op.content["paths"])
    assert f"{ROBOT_PATH}/ee/sphere" in moved and f"{ROBOT_PATH}/links/1" not in moved
    assert f"{ROBOT_PATH}/modules/0/sphere" not in moved
    (labels,) = [op for op in scene.channel.ops if op.content["op"] == "labels"]
    assert labels.content["paths"] == [f"{ROBOT_PATH}/ee/label"]  # M1…M3 kept their text
    scene.channel.clear()
    scene.update([0.0, 0.0, 0.4])
    assert scene.channel.ops == []  # nothing changed, nothing sent
    # The log still holds the full state for a new view.
    replay = _replayed(scene)
    assert set(_transforms(type("H", (), {"channel": replay}))) == {
        f"{ROBOT_PATH}/{p}" for p in scene._robot.drawing.paths
    }


def test_coalescing_merges_partial_transforms_and_labels() -> None:
    a = transforms_op(["/a", "/b"], np.stack([np.eye(4), np.eye(4)]))
    b = transforms_op(["/b"], 3 * np.eye(4)[None])
    from robotconf.scene._commands import command_op, labels_op

    delete = command_op({"type": "delete", "path": "/c"})
    merged = coalesce_ops([a, labels_op(["/l"], ["x"]), b, labels_op(["/l"], ["y"]), delete, b])
    assert [op.content["op"] for op in merged] == ["transforms", "labels", "command", "transforms"]
    data = np.frombuffer(merged[0].buffers[0], dtype=np.float32).reshape(-1, 4, 4)
    assert merged[0].content["paths"] == ["/a", "/b"] and data[1, 0, 0] == 3
    assert merged[1].content == {"op": "labels", "paths": ["/l"], "texts": ["y"]}


def test_labels_have_the_robots_precision_and_merge_where_points_coincide() -> None:
    ur5 = Scene(rc.preset("ur5"), channel=RecordingChannel())
    # UR5 (1.19 m of links): centimetres, three significant digits of its size.
    assert re.fullmatch(r"EE \(-?\d\.\d\d, -?\d\.\d\d, -?\d\.\d\d\)", ur5.labels()[-1])
    scara = Scene(rc.preset("scara"), channel=RecordingChannel())
    labels = [op for op in scara.channel.ops if op.content["op"] == "labels"][-1].content
    # Coincident frames share one label; the others are empty (drawn as nothing). Where
    # the texts stand on screen (apart, with leader lines) is the page's work.
    assert labels["texts"] == [
        "M1 (40.0, 0.0, 40.0)",
        "M2, M3 (70.0, 0.0, 40.0)",
        "",
        "M4, EE (70.0, 0.0, 30.0)",
        "",
    ]
    puma = Scene(rc.preset("puma560"), channel=RecordingChannel())
    texts = [op for op in puma.channel.ops if op.content["op"] == "labels"][-1].content["texts"]
    assert texts[3].startswith("M4, M5, M6, EE (")


def test_fit_view_centres_the_robot_and_sets_the_distance(scene: Scene) -> None:
    fits = [op.content for op in scene.channel.ops if op.content["op"] == "fit"]
    assert len(fits) == 1  # fitted at creation
    scene.update([0.0, -1.2, 0.3])
    scene.channel.clear()
    scene.fit_view()
    ops = scene.channel.ops
    centring = {
        c["path"]: np.array(c["matrix"]).reshape(4, 4).T
        for c in scene.channel.commands("set_transform")
    }
    assert set(centring) == {"/meshcat", "/Grid", "/Axes"}
    points = np.vstack(
        [[0, 0, 0], scene.robot.frame_origins(scene.q), scene.robot.end_effector(scene.q)]
    )
    size = scene._robot.drawing.size
    centre = -centring["/meshcat"][:3, 3] * size
    radius = ops[-1].content["radius"] * size
    reach = np.linalg.norm(points - centre, axis=1).max()
    assert reach < radius < 1.3 * reach
