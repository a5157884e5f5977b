"""Hostile names in a cell file never become markup in the designer.

A cell file names its objects, frames, robots, their modules, its unit and its mesh files
anything (a name may hold no ``/``). The designer is bound to such a file, driven through
every tab (the table, robots, the reach map, a program that runs into a hostile fixture,
refusals that quote hostile values, downloads and uploads with hostile names), and every
widget and every form spec is walked as the browser treats it
(``tests/test_panel_hostile.py``'s walker).
"""

from __future__ import annotations

import datetime
import json

import robotconf as rc
from robotconf.cell_designer import actions as act

from .test_cell_designer_support import make_designer, row_of, shown_value, use
from .test_cell_files import STL_TEXT
from .test_panel_hostile import ENTITY, IMG, MATH, MODULE_NAMES, SCRIPT, SVG, check_page

NOW = datetime.datetime(2026, 1, 1, tzinfo=datetime.timezone.utc)
#: Names a cell entry may have (no "/").
TABLE, FIXTURE, PICK, ARM, BALL = IMG, SVG, f"{MATH} {ENTITY}", f"{IMG}{MATH}", f"{SVG} ball"
UNIT = "<b>mm</b>"


def hostile_cell_file(folder) -> str:
    (folder / f"{IMG}.stl").write_text(STL_TEXT)
    robot = rc.Robot(
        [
            rc.Module("Rz", name=MODULE_NAMES[0]),
            rc.Module("Ry", a=(0, 0, 20), name=MODULE_NAMES[1]),
            rc.Module("Ry", a=(30, 0, 0), name=MODULE_NAMES[2]),
        ],
        end_effector=(40, 0, 0),
        name=f"{SCRIPT} {MATH}",
    )
    cell = rc.Cell(unit=UNIT, name=f"{SCRIPT}cell")
    cell.add(rc.Box([120, 80, 10], pose=rc.pose([40, 0, -5]), name=TABLE))
    cell.add_robot(ARM, robot, mount=TABLE)
    cell.add(rc.Box([14, 14, 30], pose=rc.pose([5, -25, 20]), name=FIXTURE), parent=TABLE)
    cell.add(rc.Sphere(3, pose=rc.pose([60, 30, 10]), name=BALL))
    cell.add(rc.Mesh.load(folder / f"{IMG}.stl", pose=rc.pose([0, 40, 0]), name=f"{IMG} mesh"))
    cell.add_frame(PICK, rc.pose([15, 20, 15]), parent=TABLE)
    program = ([rc.PTP(q=[0, 0, 0]), rc.PTP(q=[-0.6, 0, 0]), rc.LIN(frame=f"{TABLE}/{PICK}")], {})
    path = folder / f"{IMG}.json"  # the bound file's name is shown too
    rc.io.save_cell(cell, path, programs={ARM: program})
    return str(path)


def test_a_hostile_cell_file_loads_and_every_tab_stays_text(tmp_path):
    designer = make_designer(hostile_cell_file(tmp_path))
    assert designer.errors == {}
    assert set(designer.state.cell.names) >= {TABLE, FIXTURE, ARM, BALL, f"{TABLE}/{PICK}"}
    seen = check_page(designer)
    assert FIXTURE in seen and f"x, y, z [{UNIT}]" in seen  # shown, as text
    assert f"{IMG}.json" in seen  # the line that says where the work is kept
    for name in (TABLE, FIXTURE, BALL, ARM):
        use(designer, f"{row_of(designer, name)}.select").click()
        check_page(designer)
    use(designer, "capsules").check(True)
    # Refusals that quote what was typed, and names typed by the student.
    use(designer, f"{row_of(designer, FIXTURE)}.pose0").type(IMG)
    assert IMG in designer.errors[f"{row_of(designer, FIXTURE)}.pose0"]
    use(designer, f"{row_of(designer, BALL)}.name").type(f"{SVG}/{IMG}")
    assert designer.errors[f"{row_of(designer, BALL)}.name"]
    use(designer, f"{row_of(designer, BALL)}.name").type(SCRIPT.replace("/", ""))
    check_page(designer)
    # The reach map, the program (it runs into the hostile fixture) and its results.
    use(designer, "reach.on").check(True)
    assert designer.reach_map is not None
    check_page(designer)
    use(designer, "run").click()
    assert designer.run is not None and designer.run.check.contacts
    seen = check_page(designer)
    assert any(FIXTURE in c.message for c in designer.run.check.contacts)
    assert f"'{FIXTURE}'" in seen  # the contact sentence names it, as text
    options = designer.programs_tab.form.control("move[2].target")["options"]
    assert [f"frame {TABLE}/{PICK}", f"{TABLE}/{PICK}"] in options
    # Downloads with a hostile file name typed, and an upload named by an attacker.
    use(designer, "save.name").type(f"{SVG}{IMG}.json")
    use(designer, "save.make").click()
    use(designer, "scene.make").click()
    check_page(designer)
    content = STL_TEXT.encode()
    entry = {"name": f"{IMG}.stl", "type": "", "size": len(content), "last_modified": NOW}
    designer.mesh_upload.value = ({**entry, "content": memoryview(content)},)
    assert designer.errors == {} or set(designer.errors) == {f"{row_of(designer, FIXTURE)}.pose0"}
    check_page(designer)
    # The file still reads back, names and all.
    saved = rc.load_cell(designer.binding.path)
    assert FIXTURE in saved.entries and saved.unit == UNIT


def test_a_hostile_file_that_cannot_be_read_is_said_as_text(tmp_path):
    path = tmp_path / "bad.json"
    data = {
        "format": "robotconf-cell",
        "version": 1,
        "objects": [{"name": IMG, "type": "box", "size": [1, 1, 1], "parent": SVG}],
    }
    path.write_text(json.dumps(data))
    designer = make_designer(path)
    assert SVG in designer.errors["file"]
    assert SVG in check_page(designer)
    use(designer, "add.box").click()
    assert json.loads(path.read_text()) == data  # never overwritten


def test_the_unit_and_names_reach_labels_only_as_form_text(tmp_path):
    designer = make_designer(hostile_cell_file(tmp_path))
    designer.apply(act.SetAngleUnit(False))
    assert shown_value(designer, "reach.summary").startswith("Switch the map on")
    header = json.dumps(designer.header.form.spec)
    assert json.dumps(UNIT)[1:-1] in header  # an option of the unit menu, written as text
    check_page(designer)
