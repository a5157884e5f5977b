"""The designer's bound cell file, its downloads and mesh uploads."""

from __future__ import annotations

import base64
import datetime
import json

import numpy as np
import pytest

import robotconf as rc
from robotconf.cell_designer import actions as act
from robotconf.cell_designer.state import CellDescription

from .test_cell_designer_support import (
    FakeCellScene,
    make_designer,
    open_tab_of,
    paper_on_table,
    row_of,
    same_cell,
    use,
)
from .test_cell_files import STL_TEXT

NOW = datetime.datetime(2026, 1, 1, tzinfo=datetime.timezone.utc)


def _upload(designer, name: str, content: bytes) -> None:
    """What the page's upload button sends."""
    entry = {"name": name, "type": "", "size": len(content), "last_modified": NOW}
    designer.mesh_upload.value = ({**entry, "content": memoryview(content)},)


def _download(designer, key: str) -> bytes:
    link = designer.files.form.control(f"{key}.link")
    return base64.b64decode(link["href"].split(",", 1)[1])


def test_a_bound_file_is_created_saved_at_every_change_and_loaded_after_a_restart(tmp_path):
    path = tmp_path / "cell.json"
    designer = make_designer(path, length_unit="mm")
    assert path.exists() and designer.state.cell.robots == ("arm",)
    use(designer, "add.box").click()
    use(designer, f"{row_of(designer, 'box1')}.pose1").type("-30")
    designer.apply(act.AddMove("arm", "PTP"))
    designer.apply(act.SetMoveNumber("arm", 0, "q", -0.6, 0))
    saved, programs = rc.load_cell(path, with_programs=True)
    assert same_cell(saved, designer.cell) and saved.unit == "mm"
    assert programs == designer.programs
    again = make_designer(path)  # a kernel restart: the cell is back, programs too
    assert again.state.document == designer.state.document
    assert "Loaded from" in again.binding.widget.value


def test_a_file_that_cannot_be_read_is_shown_and_never_overwritten(tmp_path):
    path = tmp_path / "cell.json"
    path.write_text(
        '{"format": "robotconf-cell", "version": 1, "frames": [{"name": "a", "parent": "b"}]}'
    )
    before = path.read_text()
    designer = make_designer(path)
    assert "frames[0].parent: no such parent" in designer.errors["file"]
    use(designer, "add.box").click()
    assert path.read_text() == before
    with pytest.raises(rc.InvalidInputError, match="ending in .json"):
        make_designer(tmp_path / "cell.txt")


def test_an_unbound_designer_says_how_to_keep_the_work():
    designer = make_designer()
    assert 'rc.cell_designer("my_cell.json")' in designer.binding.widget.value
    assert "configurator" not in designer.binding.widget.value


def test_the_downloaded_cell_file_reads_back_as_the_cell_on_screen(tmp_path):
    designer = make_designer(paper_on_table())
    designer.apply(act.AddMove("arm", "LIN"))
    use(designer, "save.make").click()
    raw = _download(designer, "save")
    cell, programs = rc.load_cell(raw.decode("utf-8"), with_programs=True)
    assert same_cell(cell, designer.cell) and programs == designer.programs
    link = designer.files.form.control("save.link")
    assert link["download"] == "cell.json"
    use(designer, "add.sphere").click()  # another document: the old link goes
    open_tab_of(designer, "save")
    assert "save.link" not in designer.files.form.control_keys()
    designer.save(tmp_path / "copy.json")
    assert same_cell(rc.load_cell(tmp_path / "copy.json"), designer.cell)


def test_the_scene_page_comes_from_the_view():
    designer = make_designer(paper_on_table())
    use(designer, "scene.make").click()
    page = _download(designer, "scene").decode("utf-8")
    assert page.startswith("<!doctype html>") and "fixture" in page
    assert designer.scene.count("export_html") == 1
    assert designer.files.form.control("scene.link")["download"] == "cell_scene.html"


def test_a_mesh_uploaded_to_a_bound_designer_is_kept_beside_the_file(tmp_path):
    path = tmp_path / "cell.json"
    designer = make_designer(path)
    _upload(designer, "plate.stl", STL_TEXT.encode())
    assert (tmp_path / "plate.stl").read_text() == STL_TEXT
    mesh = designer.cell.objects["plate"]
    assert mesh.triangles.shape == (1, 3, 3) and mesh.source.endswith("plate.stl")
    data = json.loads(path.read_text())
    assert data["objects"][0]["path"] == "plate.stl"  # relative to the cell file
    row = row_of(designer, "plate")
    use(designer, f"{row}.scale").type("2")
    assert designer.cell.objects["plate"].vertices.max() == 20.0
    assert same_cell(rc.load_cell(path), designer.cell)
    _upload(designer, "plate.stl", STL_TEXT.replace("10 0 0", "5 0 0").encode())
    assert (tmp_path / "plate_2.stl").exists()  # the first file is never overwritten
    assert designer.state.cell.names[-1] == "mesh1"


def test_a_mesh_uploaded_without_a_file_is_kept_inline_and_named_by_the_upload():
    designer = make_designer(rc.Cell(unit="mm"))
    _upload(designer, "bracket part.stl", STL_TEXT.encode())
    item = designer.state.cell.item("bracket_part")
    assert item.mesh_file() == "bracket part.stl" and item.shape.source is None
    texts = [
        c["value"]
        for r in designer.table.form.spec["rows"]
        for line in r["lines"]
        for c in line
        if c["type"] == "text"
    ]
    assert "file bracket part.stl" in texts
    back = rc.load_cell(designer.to_json())
    assert np.array_equal(back.objects["bracket_part"].vertices, item.shape.vertices)
    _upload(designer, "notes.txt", b"hello")
    assert "not a mesh" in designer.errors["mesh"]
    _upload(designer, "broken.stl", b"solid x\nfacet normal 0 0 1\nendsolid\n")
    assert "mesh file" in designer.errors["mesh"] and len(designer.state.cell.items) == 1


def test_loading_a_file_is_one_undo_step(tmp_path):
    path = tmp_path / "other.json"
    cell = paper_on_table()
    cell.save(path)
    designer = make_designer()
    designer.load(path)
    assert same_cell(designer.cell, cell) and designer.scene.count("fit_view") == 1
    designer.undo()
    assert designer.state.cell == CellDescription.from_cell(make_designer().cell)
    assert isinstance(designer.scene, FakeCellScene)
