"""Comparison with the reference implementation: the scene's encoding against meshcat's own.

robotconf writes meshcat's three.js JSON and msgpack bytes itself
(``robotconf/scene/_three.py``, ``_commands.py``) so that a notebook never imports the
meshcat Python package, which loads pyzmq, tornado, Pillow and IPython. Here, and only
here, meshcat's Python encoder is the reference: ``meshcat.geometry`` lowers the objects,
``meshcat.commands`` / ``meshcat.animation`` the commands, and ``umsgpack`` (meshcat's
packer) packs them. meshcat stays installed for its viewer bundle, so the reference is
always at hand.

Every object and command the scene sends must equal the reference: the same JSON text and
the same msgpack bytes, once the random uuids are renamed in order of appearance (meshcat
draws uuid1, robotconf uuid4; both are 36 characters, so renaming keeps the bytes framed).
"""

from __future__ import annotations

import json
import re
from typing import Any

import msgpack
import numpy as np
import pytest

import robotconf as rc
from robotconf.scene import ROOT, RecordingChannel, Scene, quaternions
from robotconf.scene._commands import Op, command_op, set_object_op, shape_object
from robotconf.scene._points import point_cloud_op
from robotconf.scene._three import label_anchor

# The reference implementation (imported by this test only).
g = pytest.importorskip("meshcat.geometry")
meshcat_commands = pytest.importorskip("meshcat.commands")
meshcat_animation = pytest.importorskip("meshcat.animation")
MeshcatPath = pytest.importorskip("meshcat.path").Path
umsgpack = pytest.importorskip("umsgpack")

ROBOT_PATH = f"{ROOT}/robot"
UUID = re.compile(rb"[0-9a-f]{8}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{12}")


def renamed(data: bytes) -> bytes:
    """``data`` with every uuid replaced by ``uuid-000…k`` (k = order of first appearance)."""
    names: dict[bytes, bytes] = {}

    def name(match: re.Match[bytes]) -> bytes:
        return names.setdefault(match.group(0), b"uuid-%031d" % len(names))

    return UUID.sub(name, data)


def reference_shape(shape: str, size: float, color: int) -> dict[str, Any]:
    """How the scene lowered its unit shapes through meshcat.geometry."""
    material = g.MeshLambertMaterial(color=color)
    if shape == "sphere":
        return g.Mesh(g.Sphere(size), material).lower()
    if shape == "cylinder":
        return g.Mesh(g.Cylinder(1.0, size), material).lower()
    if shape == "box":
        return g.Mesh(g.Box([2 * size, 1.0, 2 * size]), material).lower()
    if shape == "triad":
        return g.triad(size).lower()
    assert shape == "label"
    return label_anchor(size)  # robotconf's own object: the page writes the text beside it


def reference_set_object(path: str, obj: dict[str, Any]) -> Op:
    """How the scene sent ``set_object``: JSON, or umsgpack-packed when typed arrays are in."""
    command = {"type": "set_object", "path": path, "object": obj}
    if _has_umsgpack_ext(obj):
        return Op({"op": "packed", "type": "set_object", "path": path}, (umsgpack.packb(command),))
    return command_op(command)


def _has_umsgpack_ext(value: Any) -> bool:
    if isinstance(value, dict):
        return any(_has_umsgpack_ext(v) for v in value.values())
    if isinstance(value, list):
        return any(_has_umsgpack_ext(v) for v in value)
    return isinstance(value, umsgpack.Ext)


def assert_same_op(ours: Op, reference: Op) -> None:
    """Same JSON part and same binary buffers, uuids aside."""
    assert renamed(json.dumps(ours.content).encode()) == renamed(
        json.dumps(reference.content).encode()
    )
    assert len(ours.buffers) == len(reference.buffers)
    for mine, theirs in zip(ours.buffers, reference.buffers, strict=True):
        assert renamed(mine) == renamed(theirs)
    if ours.content["op"] == "command":
        # What the viewer would decode if the command travelled packed instead.
        mine_packed = msgpack.packb(ours.content["command"])
        assert renamed(mine_packed) == renamed(umsgpack.packb(reference.content["command"]))


@pytest.mark.parametrize("robot_name", ["paper", "cartesian"])
def test_every_drawn_object_matches_meshcat_geometry(robot_name: str) -> None:
    robot = rc.preset(robot_name)
    scene = Scene(robot, frames=True, channel=RecordingChannel())
    drawing = scene._robot.drawing
    assert drawing is not None
    shapes = {item.shape for item in drawing.items}
    assert {"sphere", "triad", "label"} <= shapes and shapes & {"cylinder", "box"}
    for item in drawing.items:
        path = f"{ROBOT_PATH}/{item.path}"
        ours = set_object_op(path, shape_object(item.shape, item.size, item.color))
        reference = reference_set_object(path, reference_shape(item.shape, item.size, item.color))
        assert ours.content["op"] == reference.content["op"], item
        assert_same_op(ours, reference)


def test_triad_travels_packed_with_float32_arrays() -> None:
    ours = set_object_op("/a", shape_object("triad", 0.25, 0))
    assert ours.content["op"] == "packed"
    decoded = msgpack.unpackb(ours.buffers[0])
    position = decoded["object"]["geometries"][0]["data"]["attributes"]["position"]
    assert position["array"].code == g.threejs_type(np.float32)[1]
    lines = np.frombuffer(position["array"].data, dtype=np.float32).reshape(-1, 3)
    np.testing.assert_array_equal(lines[1::2], 0.25 * np.eye(3))


@pytest.mark.parametrize("per_point_color", [False, True])
def test_point_cloud_matches_meshcat_point_cloud(per_point_color: bool) -> None:
    rng = np.random.default_rng(3)
    xyz = 50 * rng.random((37, 3))
    rgb = rng.random((37, 3)) if per_point_color else np.array([0.2, 0.4, 0.9])
    path = f"{ROOT}/clouds/workspace"
    ours = point_cloud_op(path, xyz, rgb, 0.7)
    cloud = g.PointCloud(
        xyz.T.astype(np.float32),
        np.ascontiguousarray(np.broadcast_to(rgb, xyz.shape).T, dtype=np.float32),
        size=0.7,
    )
    assert_same_op(ours, reference_set_object(path, cloud.lower()))


def test_plain_commands_match_meshcat_commands(paper_robot: rc.Robot) -> None:
    scene = Scene(paper_robot, channel=RecordingChannel())
    scene.set_robot(paper_robot.with_module(1, rc.Module("Tz", a=(0, 0, 20))))
    channel = scene.channel
    scale = 1.0 / scene._robot.drawing.size  # type: ignore[union-attr]
    expected = {
        "set_property": meshcat_commands.SetProperty(
            "position", [0.9, 0.6, 0.9], MeshcatPath().append("/Cameras/default/rotated/<object>")
        ),
        "set_transform": meshcat_commands.SetTransform(
            np.diag([scale, scale, scale, 1.0]), MeshcatPath().append(ROOT)
        ),
        "delete": meshcat_commands.Delete(MeshcatPath().append(ROBOT_PATH)),
    }
    for kind, reference in expected.items():
        ours = channel.commands(kind)[0]
        assert json.dumps(ours) == json.dumps(reference.lower()), kind
        assert msgpack.packb(ours) == umsgpack.packb(reference.lower()), kind


def _flat_tracks(clip: dict[str, Any]) -> dict[str, Any]:
    """meshcat's ``keys`` tracks as three.js's flat ``times``/``values`` form.

    This is what ``THREE.KeyframeTrack.parse`` does with ``keys`` (AnimationUtils.flattenJSON),
    so both forms give the viewer the same track.
    """
    tracks = []
    for track in clip["tracks"]:
        times = [key["time"] for key in track["keys"]]
        values = [v for key in track["keys"] for v in np.ravel(key["value"]).tolist()]
        tracks.append(
            {"name": track["name"], "type": track["type"], "times": times, "values": values}
        )
    return {"fps": clip["fps"], "name": clip["name"], "tracks": tracks}


def test_animation_holds_meshcats_keyframes(paper_robot: rc.Robot) -> None:
    motion = rc.simulate(paper_robot, {"q2": rc.signals.Sine(amplitude=1.0)}, t_end=1, dt=0.25)
    scene = Scene(paper_robot, channel=RecordingChannel())
    scene.animate(motion, speed=2.0, play=False)
    ours = scene.channel.commands("set_animation")[-1]
    drawing = scene._robot.drawing
    assert drawing is not None

    # The reference: meshcat's Animation, one keyframe per sample, times in motion seconds
    # (fps 1; the page's player applies the speed).
    times = (motion.t - motion.t[0]).tolist()
    placement = drawing.placements(motion.q)
    quats = quaternions(placement.rotation)
    animation = meshcat_animation.Animation(default_framerate=1)
    for k, item in enumerate(drawing.paths):
        path = MeshcatPath().append(f"{ROBOT_PATH}/{item}")
        for i, time in enumerate(times):
            frame = meshcat_animation.AnimationFrameVisualizer(animation, path, time)
            frame.set_property("position", "vector3", placement.position[i, k].tolist())
            frame.set_property("quaternion", "quaternion", quats[i, k].tolist())
            frame.set_property("scale", "vector3", placement.scale[i, k].tolist())
            if np.allclose(placement.scale[i, k], 1.0):
                # A rigid item: meshcat's own transform → position and quaternion.
                matrix = placement.matrices()[i, k]
                np.testing.assert_allclose(
                    meshcat_animation.js_position(matrix), placement.position[i, k], atol=1e-9
                )
                theirs = np.array(meshcat_animation.js_quaternion(matrix))
                sign = np.sign(theirs @ quats[i, k])
                np.testing.assert_allclose(sign * theirs, quats[i, k], atol=1e-9)
    reference = meshcat_commands.SetAnimation(animation, play=False, repetitions=1).lower()

    # meshcat adds "path": "" to the command; the viewer's set_animation never reads it.
    assert set(reference) - set(ours) == {"path"} and reference["path"] == ""
    assert ours["type"] == reference["type"] and ours["options"] == reference["options"]
    assert [a["path"] for a in ours["animations"]] == [a["path"] for a in reference["animations"]]
    for mine, theirs in zip(ours["animations"], reference["animations"], strict=True):
        flat = _flat_tracks(theirs["clip"])
        assert {k: v for k, v in mine["clip"].items() if k != "tracks"} == {
            k: v for k, v in flat.items() if k != "tracks"
        }
        for track, expected in zip(mine["clip"]["tracks"], flat["tracks"], strict=True):
            assert list(track) == list(expected)
            assert (track["name"], track["type"]) == (expected["name"], expected["type"])
            # Ours travel as float32 arrays (msgpack extensions the viewer decodes into the
            # Float32Array three.js keeps its keyframes in anyway); meshcat's as lists.
            times, values = (
                np.frombuffer(track[key].data, dtype=np.float32) for key in ("times", "values")
            )
            assert track["times"].code == track["values"].code == g.threejs_type(np.float32)[1]
            np.testing.assert_array_equal(times, np.float32(expected["times"]))
            np.testing.assert_array_equal(values, np.float32(expected["values"]))
