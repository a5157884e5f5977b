"""Cell files and mesh files: exact round trips, and hostile input refused by field."""

from __future__ import annotations

import json
import struct
import time

import numpy as np
import pytest

import robotconf as rc
from robotconf.io import cell_to_dict, load_cell

STL_TEXT = """solid plate
facet normal 0 0 1
outer loop
vertex 0 0 0
vertex 10 0 0
vertex 0 10 0
endloop
endfacet
endsolid plate
"""


def _cell(tmp_path):
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "plate.stl").write_text(STL_TEXT)
    cell = rc.Cell(unit="mm", name="demo")
    cell.add(rc.Box([100, 60, 4], pose=rc.pose([50, 0, -2], [0, 0, 0.3]), name="table"))
    gripper = rc.Tool(
        tcp=rc.pose([8, 0, 0], [0.1, 0.2, 0.3]), capsules=[((0, 0, 0), (8, 0, 0), 2.5)]
    )
    cell.add_robot(
        "arm",
        rc.preset("paper"),
        rc.pose([0, 0, 0]),
        tool=gripper,
        mount="table",
        radius={"link 2": 3.0},
        parent="table",
    )
    cell.add(rc.Cylinder(3, 20, pose=rc.pose([10, 10, 12])), parent="table")
    cell.add(rc.Mesh.load(tmp_path / "meshes" / "plate.stl", pose=rc.pose([0, 20, 5]), scale=2.0))
    cell.add(rc.Sphere(1.5, name="ball"), parent="plate")
    cell.add_frame("pick", rc.pose([20, 0, 4], [np.pi, 0, 0]), parent="table")
    cell.add_frame("above", rc.pose([0, 0, -10]), parent="table/pick")
    return cell


def test_a_cell_file_round_trips_exactly(tmp_path):
    cell = _cell(tmp_path)
    path = cell.save(tmp_path / "cell.json")
    data = json.loads(path.read_text())
    assert data["format"] == "robotconf-cell" and data["version"] == 1
    mesh = next(o for o in data["objects"] if o["type"] == "mesh")
    assert mesh["path"] == "meshes/plate.stl" and mesh["scale"] == 2.0  # relative to the file
    back = load_cell(path)
    assert back.to_json(path) == cell.to_json(path)
    for name in cell.entries:
        assert np.array_equal(back.pose_of(name), cell.pose_of(name)), name
    q = np.array([[0.1, -0.2, 0.3], [0.5, 0.4, -0.6]])
    assert np.array_equal(back.link_capsules("arm", q)[0], cell.link_capsules("arm", q)[0])
    assert back.clearance("arm", q).distance.tolist() == cell.clearance("arm", q).distance.tolist()
    # Loading from elsewhere finds the mesh beside the file.
    moved = tmp_path / "copy"
    (moved / "meshes").mkdir(parents=True)
    (moved / "meshes" / "plate.stl").write_text(STL_TEXT)
    (moved / "cell.json").write_text(path.read_text())
    plate = load_cell(moved / "cell.json").objects["plate"]
    assert np.array_equal(plate.triangles, back.objects["plate"].triangles)
    assert plate.source == str(moved / "meshes" / "plate.stl")


def test_frames_move_with_their_parents(tmp_path):
    cell = _cell(tmp_path)
    before = cell.pose_of("table/pick/above")
    cell.set_pose("table", rc.pose([50, 30, -2], [0, 0, 0.3]))
    after = cell.pose_of("table/pick/above")
    assert np.allclose(after[:3, 3] - before[:3, 3], [0, 30, 0], atol=1e-12)
    assert np.allclose(cell.pose_of("arm")[:3, 3], [50, 30, -2])  # the robot stands on it
    with pytest.raises(rc.InvalidInputError, match="other entries are placed on"):
        cell.remove("table")


def _file(**changes):
    data = {"format": "robotconf-cell", "version": 1, "robots": [], "objects": [], "frames": []}
    data.update(changes)
    return json.dumps(data)


def _box(name="b", **extra):
    return {"name": name, "type": "box", "size": [1, 2, 3], **extra}


@pytest.mark.parametrize(
    ("text", "field", "words"),
    [
        ("{", "file", "not valid JSON"),
        ("[" * 100_000 + "]" * 100_000, "file", "too deep"),
        ("{" + " " * 2_000_000 + "}", "file", "too large"),
        (_file(version=2), "version", "newer robotconf"),
        (_file(format="robotconf"), "format", "not a robotconf cell file"),
        (_file(extra=1), "file.extra", "unknown key"),
        (_file(objects=[_box(size=[1, 0, 3])]), "objects[0].size[1]", "out of range"),
        (
            '{"format": "robotconf-cell", "version": 1, "objects": [{"name": "b", "type": "box", '
            '"size": [1, NaN, 3]}]}',
            "objects[0].size[1]",
            "NaN is not allowed",
        ),
        (_file(objects=[_box(), _box()]), "objects[1].name", "also the name of objects[0]"),
        (_file(objects=[_box()], frames=[{"name": "b"}]), "frames[0].name", "also the name"),
        (_file(frames=[{"name": "p", "parent": "table"}]), "frames[0].parent", "no such parent"),
        (
            _file(objects=[_box("a", parent="c"), _box("c", parent="a")]),
            "parent",
            "a cycle of parents",
        ),
        (
            _file(objects=[_box(pose=[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1]])]),
            "objects[0].pose",
            "reflection",
        ),
        (_file(objects=[{"name": "b", "type": "cone"}]), "objects[0].type", "unknown object type"),
        (
            _file(objects=[{"name": "m", "type": "mesh", "path": "missing.stl"}]),
            "objects[0].path",
            "not found",
        ),
        (_file(frames=[{"name": "a/b"}]), "frames[0].name", "without '/'"),
        (_file(robots=[{"name": "r", "robot": {"links": []}}]), "robots[0].robot.links", ""),
        (
            '{"format": "robotconf-cell", "format": "robotconf-cell", "version": 1}',
            "file.format",
            "duplicate key",
        ),
    ],
)
def test_hostile_cell_files_are_refused_by_field(text, field, words):
    started = time.perf_counter()
    with pytest.raises(rc.InvalidInputError) as caught:
        load_cell(text)
    assert caught.value.field.endswith(field) and words in str(caught.value)
    assert time.perf_counter() - started < 5  # generous: the checks come before the work


def test_a_cycle_names_the_loop():
    text = _file(
        frames=[
            {"name": "a", "parent": "b/c"},
            {"name": "b", "parent": "a"},
            {"name": "c", "parent": "a/b"},
        ]
    )
    with pytest.raises(rc.InvalidInputError) as caught:
        load_cell(text)
    assert "no such parent" in str(caught.value) or "cycle" in str(caught.value)


@pytest.mark.parametrize(
    ("content", "words"),
    [
        (b"", "empty"),
        (
            b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\nendloop\nendfacet\nendsolid\n",
            "no triangles",
        ),
        (b"\0" * 80 + struct.pack("<I", 10**6) + b"\0" * 100, "malformed binary STL"),
        (b"\0" * 80 + struct.pack("<I", 300_000) + b"\0" * (50 * 300_000), "too many triangles"),
        (b"solid x\nendsolid x\n", "no triangles"),
        (
            b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 nan\nvertex 1 0 0\nvertex 0 1 0\n"
            b"endloop\nendfacet\nendsolid x\n",
            "not finite",
        ),
    ],
)
def test_hostile_meshes_are_refused_naming_the_file(tmp_path, content, words):
    path = tmp_path / "part.stl"
    path.write_bytes(content)
    with pytest.raises(rc.InvalidInputError) as caught:
        rc.Mesh.load(path)
    assert caught.value.field == "mesh file" and words in str(caught.value)
    assert str(path) in str(caught.value)


def test_mesh_files_of_the_wrong_kind_or_size(tmp_path):
    with pytest.raises(rc.InvalidInputError, match="not a mesh file type"):
        rc.Mesh.load(tmp_path / "part.step")
    big = tmp_path / "big.obj"
    with big.open("wb") as handle:
        handle.truncate(rc.cell.MAX_MESH_BYTES + 1)
    with pytest.raises(rc.InvalidInputError, match="too large"):
        rc.Mesh.load(big)


def test_an_obj_mesh_and_its_distance(tmp_path):
    path = tmp_path / "wall.obj"
    path.write_text("v 0 -5 0\nv 0 5 0\nv 0 5 10\nv 0 -5 10\nf 1 2 3 4\n")
    wall = rc.Mesh.load(path, pose=rc.pose([50, 0, 0]))
    assert wall.triangles.shape == (2, 3, 3)
    cell = rc.Cell()
    cell.add_robot("arm", rc.preset("paper"))
    cell.add(wall)
    # The arm at q = 0 runs along x at z = 20, above the wall's top edge (z = 10).
    assert cell.clearance("arm", [0, 0, 0]).distance == pytest.approx(10 - 3.6, abs=1e-12)
    assert cell_to_dict(cell)["objects"][0]["path"].endswith("wall.obj")


def test_bad_cell_input_names_the_field():
    cell = rc.Cell()
    cell.add(rc.Sphere(1, name="ball"))
    with pytest.raises(rc.InvalidInputError) as caught:
        cell.add(rc.Sphere(2, name="ball"))
    assert caught.value.field == "name"
    with pytest.raises(rc.InvalidInputError) as caught:
        cell.add_frame("p", parent="nothing")
    assert caught.value.field == "parent"
    with pytest.raises(rc.InvalidInputError) as caught:
        rc.Box([1, -1, 1])
    assert caught.value.field == "size[1]"
    with pytest.raises(rc.InvalidInputError) as caught:
        rc.pose([0, 0, float("nan")])
    assert caught.value.field.startswith("xyz")


@pytest.mark.parametrize("q", [[["x", 1, 2]], [[True, 0, 0]], [[1, 2]], [[np.nan, 0, 0]], [1, 2]])
def test_bad_coordinates_name_q(q):
    cell = rc.Cell()
    cell.add_robot("arm", rc.preset("paper"))
    with pytest.raises(rc.InvalidInputError) as caught:
        cell.clearance("arm", q)
    assert caught.value.field.startswith("q")
