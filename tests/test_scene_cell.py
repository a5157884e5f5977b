"""The work cell in the 3D scene: what a CellScene sends for robots, objects and frames.

Everything is read off a :class:`~robotconf.scene.RecordingChannel`: the three.js objects
(sizes in the cell's unit), the transforms (poses in the cell's frame, column-major
float32 on the wire) and the label texts, checked against numbers derived by hand.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import robotconf as rc
from robotconf.scene import CellScene, RecordingChannel
from robotconf.scene.workcell._paths import CAPSULES, FRAMES, NAMES, OBJECTS, ROBOTS, SELECTION

TETRA_VERTICES = [[0, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 10]]
TETRA_FACES = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]


def paper_cell() -> rc.Cell:
    """The paper's arm on a table with a fixture and a pick point, in mm."""
    cell = rc.Cell(unit="mm", name="paper cell")
    cell.add(rc.Box([120, 80, 10], pose=rc.pose([40, 0, -5]), name="table"))
    cell.add_robot("arm", rc.preset("paper"), mount="table")
    cell.add(rc.Box([14, 14, 30], pose=rc.pose([5, -25, 20]), name="fixture"), parent="table")
    cell.add_frame("pick", rc.pose([15, 20, 15], [0, 0, np.pi / 2]), parent="table")
    return cell


def transforms(channel: RecordingChannel) -> dict[str, np.ndarray]:
    """The last transform sent for every path (batched or single), as 4×4 matrices."""
    out: dict[str, np.ndarray] = {}
    for op in channel.ops:
        content = op.content
        if content["op"] == "transforms":
            data = np.frombuffer(op.buffers[0], dtype=np.float32).reshape(-1, 4, 4)
            for path, matrix in zip(content["paths"], data, strict=True):
                out[path] = matrix.T.astype(float)  # column-major on the wire
        elif content["op"] == "command" and content["command"]["type"] == "set_transform":
            command = content["command"]
            out[command["path"]] = np.reshape(command["matrix"], (4, 4)).T
    return out


def objects(channel: RecordingChannel) -> dict[str, dict[str, Any]]:
    """The last three.js object sent for every path."""
    return {c["path"]: c["object"] for c in channel.commands("set_object")}


def labels(channel: RecordingChannel) -> dict[str, str]:
    """The last text sent for every label anchor."""
    out: dict[str, str] = {}
    for op in channel.ops:
        if op.content["op"] == "labels":
            out.update(zip(op.content["paths"], op.content["texts"], strict=True))
    return out


def key(scene: CellScene, name: str) -> str:
    return scene._keys.key(name)


def floats(array: Any) -> np.ndarray:
    return np.frombuffer(array.data, dtype=np.float32).astype(float)


@pytest.fixture
def cell() -> rc.Cell:
    return paper_cell()


@pytest.fixture
def scene(cell: rc.Cell) -> CellScene:
    return CellScene(cell, channel=RecordingChannel())


def test_every_shape_is_drawn_at_its_pose_with_its_size() -> None:
    cell = rc.Cell(unit="mm")
    cell.add(rc.Box([120, 80, 10], pose=rc.pose([40, 0, -5]), name="table"))
    # On the table: its pose is in the table's frame, so it stands at (45, -25, 15).
    cell.add(rc.Box([14, 14, 30], pose=rc.pose([5, -25, 20]), name="fixture"), parent="table")
    # Rolled a quarter turn about x: its axis (local z) points along -y.
    cell.add(rc.Cylinder(5, 20, pose=rc.pose([0, 30, 10], [np.pi / 2, 0, 0]), name="post"))
    cell.add(rc.Sphere(3, pose=rc.pose([50, 0, 30]), name="ball"))
    cell.add(rc.Mesh(TETRA_VERTICES, TETRA_FACES, pose=rc.pose([-20, 0, 0]), name="wedge"))
    scene = CellScene(cell, channel=RecordingChannel())
    sent, moved = objects(scene.channel), transforms(scene.channel)
    path = {name: f"{OBJECTS}/{key(scene, name)}" for name in cell.objects}

    table = sent[path["table"]]["geometries"][0]
    assert (table["type"], table["width"], table["height"], table["depth"]) == (
        "BoxGeometry",
        120.0,
        80.0,
        10.0,
    )
    np.testing.assert_array_equal(moved[path["table"]], rc.pose([40, 0, -5]))
    np.testing.assert_array_equal(moved[path["fixture"]][:3, 3], [45, -25, 15])
    assert sent[path["fixture"]]["geometries"][0]["depth"] == 30.0

    post = sent[path["post"]]
    geometry = post["geometries"][0]
    assert (geometry["type"], geometry["radiusTop"], geometry["height"]) == (
        "CylinderGeometry",
        5.0,
        20.0,
    )
    # three.js draws the cylinder along its y: its own matrix turns y onto the pose's z,
    # and the pose's z is -y in the cell, so the drawn axis runs along -y.
    own = np.reshape(post["object"]["matrix"], (4, 4)).T
    axis = moved[path["post"]][:3, :3] @ own[:3, :3] @ [0, 1, 0]
    np.testing.assert_allclose(axis, [0, -1, 0], atol=1e-7)
    np.testing.assert_allclose(moved[path["post"]][:3, 3], [0, 30, 10])

    ball = sent[path["ball"]]["geometries"][0]
    assert (ball["type"], ball["radius"]) == ("SphereGeometry", 3.0)
    np.testing.assert_array_equal(moved[path["ball"]][:3, 3], [50, 0, 30])

    wedge = sent[path["wedge"]]["geometries"][0]
    corners = floats(wedge["data"]["attributes"]["position"]["array"]).reshape(-1, 3, 3)
    expected = np.array(TETRA_VERTICES, dtype=float)[np.array(TETRA_FACES)]
    np.testing.assert_array_equal(corners, expected)  # 12 corners, in the mesh's frame
    np.testing.assert_array_equal(moved[path["wedge"]][:3, 3], [-20, 0, 0])
    # Every object in the neutral colour, lit.
    colors = {sent[p]["materials"][0]["color"] for p in path.values()}
    assert colors == {0xB4AC9C}
    assert scene.labels() == [
        "table (40, 0, -5) mm",
        "fixture (45, -25, 15) mm",
        "post (0, 30, 10) mm",
        "ball (50, 0, 30) mm",
        "wedge (-20, 0, 0) mm",
    ]


def test_frames_are_triads_with_their_full_names(scene: CellScene, cell: rc.Cell) -> None:
    path = f"{FRAMES}/{key(scene, 'table/pick')}"
    sent = objects(scene.channel)[path]
    assert sent["object"]["type"] == "LineSegments"  # x red, y green, z blue, unit length
    matrix = transforms(scene.channel)[path]
    length = 0.08 * scene._size
    # At the table's (40, 0, -5) plus (15, 20, 15), turned a quarter about z, triad-long.
    np.testing.assert_allclose(matrix[:3, 3], [55, 20, 10])
    np.testing.assert_allclose(matrix[:3, :3] @ [1, 0, 0], [0, length, 0], atol=1e-9)
    anchor = f"{NAMES}/{key(scene, 'table/pick')}"
    assert labels(scene.channel)[anchor] == "table/pick (55.0, 20.0, 10.0) mm"
    scene.set_label_mode("names")
    assert labels(scene.channel)[anchor] == "table/pick"
    scene.set_label_mode("off")
    hidden = [op.content for op in scene.channel.ops if op.content["op"] == "visible"][-1]
    assert hidden == {"op": "visible", "paths": [NAMES], "value": False}
    assert scene.labels() == []


def test_robots_stand_on_their_bases_and_label_the_cell_frame() -> None:
    cell = rc.Cell(unit="mm")
    cell.add_robot("a", rc.preset("paper"))
    cell.add_robot("b", rc.preset("paper"), base=rc.pose([125, 0, 0], [0, 0, np.pi]))
    scene = CellScene(cell, {"b": [0.0, 0.0, 0.5]}, channel=RecordingChannel())
    base = transforms(scene.channel)[f"{ROBOTS}/{key(scene, 'b')}"]
    np.testing.assert_allclose(base, rc.pose([125, 0, 0], [0, 0, np.pi]), atol=1e-12)
    texts = scene.labels()
    # b's end effector: paper arm at q3 = 0.5 (65.1, 0, 0.8) in its base, turned half about
    # z and moved to x = 125: (125 - 65.1, 0, 0.8).
    assert texts[3] == "a EE (70.0, 0.0, 20.0) mm"
    assert texts[7] == "b EE (59.9, 0.0, 0.8) mm"
    assert scene.qs["b"].tolist() == [0.0, 0.0, 0.5]
    # One robot left: no names before the labels.
    cell.remove("b")
    scene.show(cell)
    assert scene.labels()[-1] == "EE (70.0, 0.0, 20.0) mm"
    assert f"{ROBOTS}/{key(scene, 'a')}" in transforms(scene.channel)
    deleted = [c["path"] for c in scene.channel.commands("delete")]
    assert any(path.startswith(f"{ROBOTS}/") for path in deleted)


def test_show_sends_only_what_changed(scene: CellScene, cell: rc.Cell) -> None:
    channel = scene.channel
    fixture = f"{OBJECTS}/{key(scene, 'fixture')}"
    channel.clear()
    cell.set_pose("fixture", rc.pose([5, -20, 20]))  # 5 mm along y, on the table
    scene.show(cell)
    assert channel.kinds() == ["transforms", "labels"]
    (op,) = [op for op in channel.ops if op.content["op"] == "transforms"]
    # The object and its label's anchor, nothing else.
    assert op.content["paths"] == [fixture, f"{NAMES}/{key(scene, 'fixture')}"]
    np.testing.assert_array_equal(transforms(channel)[fixture][:3, 3], [45, -20, 15])

    # The table moved: the fixture and the pick point on it come along.
    channel.clear()
    cell.set_pose("table", rc.pose([40, 0, -6]))
    scene.show(cell)
    moved = set(transforms(channel))
    assert {fixture, f"{FRAMES}/{key(scene, 'table/pick')}"} < moved
    assert not any(path.startswith(ROBOTS) for path in moved)  # the robot stays

    # A resized object is rebuilt alone; a new one is added, a removed one deleted.
    channel.clear()
    cell.remove("fixture")
    cell.add(rc.Box([14, 14, 40], pose=rc.pose([5, -20, 25]), name="fixture"), parent="table")
    cell.add(rc.Sphere(4, pose=rc.pose([0, 30, 10]), name="ball"))
    scene.show(cell)
    built = [c["path"] for c in channel.commands("set_object")]
    assert built[0] == f"{OBJECTS}/{key(scene, 'fixture')}"
    assert f"{OBJECTS}/{key(scene, 'ball')}" in built
    assert not any(path.startswith(ROBOTS) or "table" in path for path in built)
    assert len(built) == 3  # the two objects, and the new one's label anchor
    ball = key(scene, "ball")
    cell.remove("ball")
    channel.clear()
    scene.show(cell)
    assert channel.commands("delete") == [
        {"type": "delete", "path": f"{OBJECTS}/{ball}"},
        {"type": "delete", "path": f"{NAMES}/{ball}"},
    ]

    # A new q moves the robot's items only.
    channel.clear()
    scene.show(cell, {"arm": [0.0, 0.0, 0.4]})
    moved = set(transforms(channel))
    assert moved and all(
        path.startswith(f"{ROBOTS}/") or path.startswith(CAPSULES) for path in moved
    )
    assert scene.qs["arm"].tolist() == [0.0, 0.0, 0.4]
    # Not given again: it keeps that q.
    scene.show(cell)
    assert scene.qs["arm"].tolist() == [0.0, 0.0, 0.4]


def test_bad_input_is_refused_before_anything_is_drawn(scene: CellScene, cell: rc.Cell) -> None:
    scene.channel.clear()
    with pytest.raises(rc.InvalidInputError, match=r"qs\['arm'\].q"):
        scene.show(cell, {"arm": [0.0, float("nan"), 0.0]})
    with pytest.raises(rc.InvalidInputError, match="qs: not a robot of the cell: 'crane'"):
        scene.show(cell, {"crane": [0.0]})
    with pytest.raises(rc.InvalidInputError, match="qs: "):
        scene.show(cell, [0, 0, 0])
    with pytest.raises(rc.InvalidInputError, match="cell: not a cell"):
        scene.show(rc.preset("paper"))
    with pytest.raises(rc.InvalidInputError, match="name: not in the cell: 'lamp'"):
        scene.select("lamp")
    with pytest.raises(rc.InvalidInputError, match="visible: not True or False"):
        scene.show_capsules("yes")  # type: ignore[arg-type]
    with pytest.raises(rc.InvalidInputError, match="height"):
        CellScene(cell, height=10, channel=RecordingChannel())
    assert scene.channel.ops == []


def test_capsules_are_the_cells_own(scene: CellScene, cell: rc.Cell) -> None:
    root = f"{CAPSULES}/{key(scene, 'arm')}"
    # Hidden, they are built but not moved at each q step: no transform of theirs yet.
    assert scene.capsules_shown is False
    assert not any(path.startswith(CAPSULES) for path in transforms(scene.channel))
    visible = [op.content for op in scene.channel.ops if op.content["op"] == "visible"]
    assert {"op": "visible", "paths": [CAPSULES], "value": False} in visible
    scene.show(cell, {"arm": [0.5, 0.0, 0.0]})
    # The bar's capsules button: the kernel places and shows them, and says so.
    scene.receive_from_page({"kind": "request", "request": {"kind": "capsules", "value": True}})
    assert scene.capsules_shown is True
    assert scene.channel.ops[-1].content["capsules"] is True
    segments, radii = cell.link_capsules("arm", [0.5, 0.0, 0.0])
    sent, moved = objects(scene.channel), transforms(scene.channel)
    for k, ((a, b), radius) in enumerate(zip(segments, radii, strict=True)):
        body = sent[f"{root}/{k}/body"]
        assert body["geometries"][0]["radiusTop"] == radius == 3.6
        assert body["materials"][0]["transparent"] is True
        np.testing.assert_allclose(moved[f"{root}/{k}/end0"][:3, 3], a, atol=1e-5)
        np.testing.assert_allclose(moved[f"{root}/{k}/end1"][:3, 3], b, atol=1e-5)
        # The unit cylinder stretched to the link's length, along it.
        along = moved[f"{root}/{k}/body"][:3, :3] @ [0, 1, 0]
        np.testing.assert_allclose(along, b - a, atol=1e-4)
    # Link 3, the forearm, (30, 0, 20) → (70, 0, 20) turned 0.5 rad about z: hand-derived.
    turn = np.array([np.cos(0.5), np.sin(0.5), 0.0])
    np.testing.assert_allclose(segments[2], [30 * turn + [0, 0, 20], 70 * turn + [0, 0, 20]])
    # Shown, they follow each new q.
    scene.show(cell, {"arm": [0.0, 0.0, 0.0]})
    np.testing.assert_allclose(
        transforms(scene.channel)[f"{root}/2/end1"][:3, 3], [70, 0, 20], atol=1e-5
    )


def test_select_outlines_an_entry_and_follows_it(scene: CellScene, cell: rc.Cell) -> None:
    scene.select("fixture")
    assert scene.selected == "fixture"
    outline = transforms(scene.channel)[SELECTION]
    # The fixture's box 14 × 14 × 30 at (45, -25, 15), 6 % wider.
    np.testing.assert_allclose(np.diag(outline)[:3], [14.84, 14.84, 31.8], atol=1e-6)
    np.testing.assert_allclose(outline[:3, 3], [45, -25, 15])
    lines = objects(scene.channel)[SELECTION]
    assert lines["object"]["type"] == "LineSegments" and lines["materials"][0]["depthTest"] is False
    cell.set_pose("table", rc.pose([40, 10, -5]))
    scene.show(cell)
    np.testing.assert_allclose(transforms(scene.channel)[SELECTION][:3, 3], [45, -15, 15])
    scene.select("arm")  # the robot's drawn points at its q, in its base frame
    assert scene.selected == "arm"
    scene.select(None)
    assert scene.selected is None
    assert scene.channel.commands("delete")[-1]["path"] == SELECTION


def test_view_and_the_cells_accessor_show_a_cell(cell: rc.Cell) -> None:
    scene = rc.view(cell, {"arm": [0, 0, 0.5]}, display=False, channel=RecordingChannel())
    assert isinstance(scene, CellScene)
    assert scene.labels()[3] == "EE (65.1, 0.0, 0.8) mm"
    again = cell.view(display=False, channel=RecordingChannel(), labels="names")
    assert again.labels()[:4] == ["M1", "M2", "M3", "EE"]
    assert repr(again) == "<CellScene of Cell(1 robots, 2 objects, 1 frames, unit='mm')>"


def test_the_view_holds_the_whole_cell(scene: CellScene) -> None:
    fit = [op.content for op in scene.channel.ops if op.content["op"] == "fit"][-1]
    centre, radius = scene._fitted
    # Every table corner is inside the fitted sphere (the table is the largest thing).
    corners = np.array([[x, y, z] for x in (-20, 100) for y in (-40, 40) for z in (-10, 0)])
    assert (np.linalg.norm(corners - centre, axis=1) <= radius).all()
    assert fit["radius"] == pytest.approx(radius / scene._size)


def test_a_cell_grown_past_its_scale_rescales_triads_and_label_clearances(
    scene: CellScene, cell: rc.Cell
) -> None:
    before = scene._size
    # A floor ten times the table: the cell's size grows past RESIZE_FACTOR.
    cell.add(rc.Box([1200, 800, 10], pose=rc.pose([40, 0, -20]), name="floor"))
    scene.show(cell)
    assert scene._size > 2 * before
    moved = transforms(scene.channel)
    triad = 0.08 * scene._size
    pick = moved[f"{FRAMES}/{key(scene, 'table/pick')}"]
    np.testing.assert_allclose(np.linalg.norm(pick[:3, 0]), triad, rtol=1e-6)
    # Every label anchor (the fixture's, which did not move, too) stands off by 0.15 triad.
    for name in ("fixture", "table", "table/pick", "floor"):
        anchor = moved[f"{NAMES}/{key(scene, name)}"]
        np.testing.assert_allclose(anchor[0, 0], 0.15 * triad, rtol=1e-6)


@pytest.mark.parametrize("kind", ["robot", "cell"])
def test_a_view_shown_by_rc_view_is_not_shown_twice_in_its_cell(kind, monkeypatch) -> None:
    import IPython.display

    from robotconf.scene import _view

    shown: list[object] = []
    monkeypatch.setattr(IPython.display, "display", lambda obj: shown.append(obj))
    monkeypatch.setattr(_view, "execution_count", lambda: 7)
    scene = (
        rc.view(rc.preset("paper"), display=False)
        if kind == "robot"
        else rc.view(paper_cell(), display=False)
    )
    scene._shown_in_cell = 7  # as rc.view(..., display=True) leaves it in cell 7
    scene._ipython_display_()  # IPython's display of the returned value: skipped
    assert shown == []
    scene._ipython_display_()  # shown again later in the same cell: displayed
    assert len(shown) == 1
