"""The cell designer's table, robots, units and undo, driven as the page drives them."""

from __future__ import annotations

import math

import numpy as np
import pytest

import robotconf as rc
from robotconf.cell_designer import actions as act
from robotconf.cell_designer.state import CellDescription, DesignerState

from .test_cell_designer_support import (
    FakeCellScene,
    make_designer,
    paper_on_table,
    row_of,
    same_cell,
    shown_value,
    use,
)


def test_the_designer_shows_the_cell_it_was_given():
    cell = paper_on_table()
    designer = make_designer(cell)
    assert same_cell(designer.cell, cell) and same_cell(designer.scene.cell, cell)
    assert designer.state.units.length == "mm"
    table = row_of(designer, "table")
    assert shown_value(designer, f"{table}.pose0") == 40.0
    assert shown_value(designer, f"{table}.pose2") == -5.0
    assert [shown_value(designer, f"{table}.size{k}") for k in range(3)] == [120.0, 80.0, 10.0]
    assert shown_value(designer, f"{row_of(designer, 'table/pick')}.name") == "pick"
    assert designer.cell is not designer.cell  # a new cell each time: changing it changes nothing


def test_adding_each_kind_of_object_and_a_frame_on_the_selected_box():
    designer = make_designer(rc.Cell(unit="mm"))
    for kind in ("box", "cylinder", "sphere"):
        use(designer, f"add.{kind}").click()
    assert designer.state.cell.names == ("box1", "cylinder1", "sphere1")
    assert designer.state.selected == "sphere1" and designer.scene.selected == "sphere1"
    use(designer, f"{row_of(designer, 'box1')}.select").click()
    use(designer, "add.frame").click()
    cell = designer.cell
    assert cell.frames == ("box1/frame1",)
    # On the box's top face: the box (size 0.2, no robot) stands on the floor at z = 0.1.
    assert np.allclose(
        cell.pose_of("box1/frame1")[:3, 3], cell.pose_of("box1")[:3, 3] + [0, 0, 0.1]
    )
    assert same_cell(designer.scene.cell, cell)


def test_a_pose_typed_in_degrees_reaches_the_cell_in_radians_and_a_switch_changes_nothing():
    designer = make_designer(paper_on_table())
    fixture = row_of(designer, "fixture")
    use(designer, f"{fixture}.pose5").type("30")
    expected = rc.pose([5, -25, 20], [0, 0, math.radians(30)])
    assert np.array_equal(designer.cell.entries["fixture"].pose, expected)
    assert shown_value(designer, f"{fixture}.pose5") == 30.0
    before = designer.cell.entries["fixture"].pose.copy()
    use(designer, "angle_unit").choose(False)
    assert shown_value(designer, f"{fixture}.pose5") == pytest.approx(0.5235987756, abs=1e-10)
    use(designer, "angle_unit").choose(True)
    use(designer, "length_unit").choose("m")
    assert designer.state.units.length == "m" and designer.cell.unit == "m"
    assert np.array_equal(designer.cell.entries["fixture"].pose, before)
    # Translations stay bit for bit when an angle is typed, and the reverse.
    use(designer, f"{fixture}.pose3").type("-90")
    pose = designer.cell.entries["fixture"].pose
    assert pose[:3, 3].tolist() == [5.0, -25.0, 20.0]
    use(designer, f"{fixture}.pose1").type("7.5")
    assert np.array_equal(designer.cell.entries["fixture"].pose[:3, :3], pose[:3, :3])


def test_sizes_by_kind_and_a_refused_size_keeps_the_cell_and_the_typed_text():
    designer = make_designer(rc.Cell(unit="mm"))
    use(designer, "add.cylinder").click()
    row = row_of(designer, "cylinder1")
    use(designer, f"{row}.radius").type("4")
    use(designer, f"{row}.length").type("12.5")
    shape = designer.cell.objects["cylinder1"]
    assert (shape.radius, shape.length) == (4.0, 12.5)
    use(designer, f"{row}.length").type("-1")
    assert (
        "length" in designer.errors[f"{row}.length"]
        and "out of range" in designer.errors[f"{row}.length"]
    )
    assert designer.cell.objects["cylinder1"].length == 12.5
    control = designer.table.form.control(f"{row}.length")
    assert control["text"] == "-1" and control["message"]["tone"] == "error"
    use(designer, f"{row}.length").type("3")  # fixed: the message goes
    assert f"{row}.length" not in designer.errors


def test_renaming_a_table_renames_the_frames_on_it_and_the_moves_that_go_there():
    designer = make_designer(paper_on_table())
    designer.apply(act.AddMove("arm", "LIN"))
    assert designer.programs["arm"][0][0].frame == "table/pick"
    use(designer, f"{row_of(designer, 'table')}.name").type("bench")
    assert designer.cell.frames == ("bench/pick",)
    assert designer.cell.parent_of("fixture") == "bench"
    assert designer.cell.robot_entry("arm").mount == ("bench",)
    assert designer.programs["arm"][0][0].frame == "bench/pick"
    use(designer, f"{row_of(designer, 'bench/pick')}.name").type("place")
    assert designer.programs["arm"][0][0].frame == "bench/place"
    use(designer, f"{row_of(designer, 'fixture')}.name").type("bench/x")
    assert "'/'" in designer.errors[f"{row_of(designer, 'fixture')}.name"]


def test_a_new_parent_keeps_the_entry_where_it_is():
    designer = make_designer(paper_on_table())
    before = designer.cell.pose_of("table/pick")
    use(designer, f"{row_of(designer, 'table/pick')}.parent").choose("fixture")
    cell = designer.cell
    assert cell.frames == ("fixture/pick",) and cell.parent_of("fixture/pick") == "fixture"
    assert np.allclose(cell.pose_of("fixture/pick"), before, atol=1e-12)
    pick = row_of(designer, "fixture/pick")
    options = [
        o[1]
        for o in designer.table.form.control(f"{row_of(designer, 'fixture')}.parent")["options"]
    ]
    assert "fixture/pick" not in options and "fixture" not in options  # no cycles offered
    use(designer, f"{pick}.parent").choose("")
    assert designer.cell.frames == ("pick",) and np.allclose(designer.cell.pose_of("pick"), before)


def test_removing_is_refused_while_something_stands_on_it_or_a_move_goes_there():
    designer = make_designer(paper_on_table())
    use(designer, f"{row_of(designer, 'table')}.remove").click()
    assert "other entries are placed on" in designer.errors[f"{row_of(designer, 'table')}.remove"]
    designer.apply(act.AddMove("arm", "LIN"))
    pick = row_of(designer, "table/pick")
    use(designer, f"{pick}.remove").click()
    assert "the target of arm's move 1" in designer.errors[f"{pick}.remove"]
    use(designer, f"{row_of(designer, 'fixture')}.remove").click()
    assert "fixture" not in designer.cell.entries and same_cell(designer.scene.cell, designer.cell)
    designer.undo()
    assert "fixture" in designer.cell.entries


def test_robots_are_added_from_presets_and_their_q_and_base_are_edited_in_units():
    designer = make_designer(paper_on_table())
    use(designer, "add.robot.preset").choose("puma560")
    use(designer, "add.robot").click()
    assert designer.state.cell.robots == ("arm", "puma560")
    assert designer.cell.robot("puma560") == rc.preset("puma560")
    puma = row_of(designer, "puma560")
    assert designer.robots.form.control(f"{puma}.q0")["value"] == 0.0
    use(designer, f"{puma}.q1").type("-45")
    assert designer.cell.robot("puma560").q[1] == math.radians(-45)
    use(designer, f"{puma}.pose1").type("150")
    assert designer.cell.pose_of("puma560")[1, 3] == 150.0
    arm = row_of(designer, "arm")
    texts = [
        c["value"] for c in designer.robots.form.spec["rows"][0]["lines"][0] if c["type"] == "text"
    ]
    assert "paper" in texts  # what the robot is, at any q
    use(designer, f"{arm}.q2").type("abc")
    assert "arm.q3: not a number" in designer.errors[f"{arm}.q2"]


def test_one_history_for_the_cell_and_the_programs_and_typing_in_one_box_is_one_step():
    clock = [0.0]
    designer = make_designer(paper_on_table())
    designer._history._clock = lambda: clock[0]
    row = row_of(designer, "fixture")
    for text in ("1", "12", "-12"):
        clock[0] += 0.2
        use(designer, f"{row}.pose0").type(text)
    clock[0] += 5
    designer.apply(act.AddMove("arm", "PTP"))
    clock[0] += 5
    use(designer, "length_unit").choose("cm")
    assert designer.cell.pose_of("fixture")[0, 3] == 40 - 12
    designer.undo()
    assert designer.cell.unit == "mm"
    designer.undo()
    assert designer.programs == {}
    designer.undo()
    assert designer.cell.pose_of("fixture")[0, 3] == 45.0  # the three typings: one step
    assert not designer.can_undo
    for _ in range(3):
        designer.redo()
    assert designer.cell.unit == "cm" and len(designer.programs["arm"][0]) == 1
    assert same_cell(designer.scene.cell, designer.cell)


def test_a_stale_event_of_an_older_layout_is_dropped():
    designer = make_designer(paper_on_table())
    row = row_of(designer, "fixture")
    rev = designer.table.form.control(f"{row}.pose0")["rev"]
    use(designer, "add.box").click()  # the rows' meaning changes
    designer.table.form.receive({"key": f"{row}.pose0", "event": "type", "rev": rev, "text": "99"})
    assert designer.cell.pose_of("fixture")[0, 3] == 45.0


def test_the_capsules_and_the_selection_go_to_the_view_once():
    designer = make_designer(paper_on_table())
    scene: FakeCellScene = designer.scene
    use(designer, "capsules").check(True)
    use(designer, f"{row_of(designer, 'fixture')}.select").click()
    use(designer, f"{row_of(designer, 'fixture')}.pose0").type("3")
    assert scene.capsules and scene.selected == "fixture"
    assert scene.count("show_capsules") == 1 and scene.count("select") == 1
    classes = [r.get("class") for r in designer.table.form.spec["rows"]]
    assert "robotconf-cell-selected" in classes
    use(designer, f"{row_of(designer, 'fixture')}.select").click()
    assert scene.selected is None


def test_actions_alone_need_no_widget():
    state = act.AddRobot("paper").apply(DesignerState())
    state = act.SetQ("paper", 0, 0.25).apply(state)
    state = act.AddObject("sphere").apply(state)
    assert state.cell.item("paper").robot.q.tolist() == [0.25, 0.0, 0.0]
    assert CellDescription.from_cell(state.cell.build()) == state.cell
    with pytest.raises(rc.InvalidInputError, match="a size field"):
        act.SetSize("sphere1", "length", 2.0).apply(state)
    with pytest.raises(rc.InvalidInputError, match="not in the cell"):
        act.SetPose("ghost", 0, 1.0).apply(state)


def test_the_state_and_the_actions_import_no_widget_and_no_view():
    from .test_layers import ALL_IMPORTS, WIDGET_LIBRARIES

    pure = ("robotconf.cell_designer.state", "robotconf.cell_designer.actions")
    found = [
        (imp.source, imp.target)
        for imp in ALL_IMPORTS
        if imp.source.startswith(pure)
        and (
            imp.target.split(".")[0] in WIDGET_LIBRARIES
            or imp.target.startswith(("robotconf.cell_designer.views", "robotconf.cell_designer._"))
            or (
                imp.target.startswith("robotconf.panel")
                and not imp.target.startswith(("robotconf.panel.state", "robotconf.panel.actions"))
            )
        )
    ]
    assert found == []
    assert any(imp.source.startswith(pure) for imp in ALL_IMPORTS)
