"""The designer's reach map and programs: what it shows is what the core computes."""

from __future__ import annotations

import math

import numpy as np
import pytest

import robotconf as rc
from robotconf.cell_designer import actions as act
from robotconf.programs import LIN, PTP

from .test_cell_designer_support import make_designer, paper_on_table, shown_value, use


def _texts(form, key_prefix: str = "") -> list[str]:
    return [
        c["value"]
        for r in form.spec["rows"]
        if r["key"].startswith(key_prefix)
        for line in r["lines"]
        for c in line
        if c["type"] == "text"
    ]


def test_the_reach_map_is_the_cores_and_its_count_is_stated():
    designer = make_designer(paper_on_table())
    use(designer, "reach.on").check(True)
    robot, low, high, step = act.reach_region(designer.state, designer.state.reach)
    assert (robot, low, high, step) == ("arm", (-100.0, -100.0, -25.0), (100.0, 100.0, 100.0), 25.0)
    direct = paper_on_table().reach_map("arm", [low, high], step)
    shown = designer.scene.reach_map
    assert shown is designer.reach_map
    assert np.array_equal(shown.points, direct.points)
    assert np.array_equal(shown.branches, direct.branches)
    count = int(direct.reachable.sum())
    assert 0 < count < len(direct.points)
    summary = shown_value(designer, "reach.summary")
    assert summary.startswith(f"arm reaches {count} of {len(direct.points)} voxels")


def test_too_many_voxels_are_refused_beside_the_step_and_the_map_stays():
    designer = make_designer(paper_on_table())
    use(designer, "reach.on").check(True)
    before = designer.reach_map
    use(designer, "reach.step").type("2")
    message = designer.errors["reach.step"]
    assert "voxels with step" in message and f"at most {act.MAX_DESIGNER_VOXELS}" in message
    assert designer.reach_map is before and designer.state.reach.step is None
    use(designer, "reach.high2").type("-50")
    assert "below the low corner" in designer.errors["reach.high2"]
    use(designer, "reach.step").type("50")
    assert "reach.step" not in designer.errors and designer.reach_map.shape == (5, 5, 3)
    use(designer, "reach.low0").type("0")
    assert designer.reach_map.points[:, 0].min() == 0.0


def test_an_edit_makes_the_map_stale_and_update_computes_it_again():
    designer = make_designer(paper_on_table())
    use(designer, "reach.on").check(True)
    first = designer.reach_map
    use(designer, "add.box").click()
    assert designer.reach_map is first
    assert "the cell changed since this map" in shown_value(designer, "reach.summary")
    use(designer, "reach.update").click()
    assert designer.reach_map is not first
    assert "changed" not in shown_value(designer, "reach.summary")
    use(designer, "reach.on").check(False)
    assert designer.scene.reach_map is None and designer.reach_map is None


def _hitting_program(designer) -> None:
    """A PTP that swings the forearm through the fixture (docs/cell.md's example)."""
    use(designer, "program[0].add").click()
    use(designer, "program[0].add").click()
    use(designer, "move[1].q0").type(f"{math.degrees(-0.6)}")


def test_run_states_the_cycle_time_and_every_contact_under_its_move():
    designer = make_designer(paper_on_table())
    _hitting_program(designer)
    use(designer, "run").click()
    run = designer.run
    cell = paper_on_table()
    moves = [PTP(q=(0.0, 0.0, 0.0)), PTP(q=(-0.6, 0.0, 0.0))]
    direct = cell.run({"arm": cell.program("arm", moves)}, dt=0.01)
    assert run.cycle_time == direct.cycle_time
    assert [c.message for c in run.check.contacts] == [c.message for c in direct.check.contacts]
    assert run.check.contacts and designer.scene.animation is run
    assert designer.scene.playback_state.playing
    under = _texts(designer.programs_tab.form, "move[1]")
    for contact in run.check.contacts:
        assert contact.message in under and "at t = " in contact.message
    assert not any(
        c.message in _texts(designer.programs_tab.form, "move[0]") for c in run.check.contacts
    )
    assert f"cycle time {direct.cycle_time:.3g} s" in shown_value(designer, "run.cycle")


def test_an_edit_after_a_run_says_it_is_stale_and_undo_brings_it_back():
    designer = make_designer(paper_on_table())
    _hitting_program(designer)
    use(designer, "run").click()
    use(designer, "move[1].q0").type("-20")
    assert "changed since this run" in shown_value(designer, "run.stale")
    assert not any("enters" in t for t in _texts(designer.programs_tab.form, "move[1]"))
    designer.undo()
    assert "run.stale" not in designer.programs_tab.form.control_keys()
    assert designer.scene.animation is designer.run  # loaded again, not played
    assert not designer.scene.playback_state.playing


def test_a_refused_program_is_said_under_the_move_and_runs_nothing():
    designer = make_designer(paper_on_table())
    use(designer, "program[0].add_kind").choose("LIN")
    use(designer, "program[0].add").click()
    use(designer, "move[0].target").choose("point")
    for k, value in enumerate((200, 0, 20)):
        use(designer, f"move[0].point{k}").type(str(value))
    use(designer, "run").click()
    message = designer.errors["run"]
    assert message.startswith("programs['arm'].moves[0]") and designer.run is None
    assert message in _texts(designer.programs_tab.form, "move[0]")
    use(designer, "move[0].point0").type("50")  # an edit: the refusal was about the old one
    assert "run" not in designer.errors


def test_move_kinds_targets_and_rows():
    designer = make_designer(paper_on_table())
    for kind in ("PTP", "LIN", "CIRC", "Wait"):
        use(designer, "program[0].add_kind").choose(kind)
        use(designer, "program[0].add").click()
    moves = designer.programs["arm"][0]
    assert [m.kind for m in moves] == ["PTP", "LIN", "CIRC", "Wait"]
    assert moves[1].frame == "table/pick" and moves[2].frame == "table/pick"
    options = [o[1] for o in designer.programs_tab.form.control("move[1].target")["options"]]
    assert options == ["point", "table/pick"]
    use(designer, "move[1].target").choose("point")
    pick = act.frame_point(designer.state, "arm", "table/pick")
    assert designer.programs["arm"][0][1] == LIN(position=pick)  # it still ends there
    use(designer, "move[1].kind").choose("PTP")
    assert designer.programs["arm"][0][1] == PTP(position=pick)
    use(designer, "move[3].seconds").type("2.5")
    use(designer, "move[3].up").click()
    assert [m.kind for m in designer.programs["arm"][0]] == ["PTP", "PTP", "Wait", "CIRC"]
    use(designer, "move[0].delete").click()
    assert len(designer.programs["arm"][0]) == 3
    use(designer, "program[0].joint_speed").type("90")
    assert designer.programs["arm"][1] == {"joint_speed": pytest.approx(math.pi / 2)}
    designer.apply(act.SetQ("arm", 0, 0.4))
    use(designer, "move[0].target").choose("q")
    assert designer.programs["arm"][0][0].q == (0.4, 0.0, 0.0)


def test_two_robots_run_side_by_side():
    cell = rc.Cell(unit="mm")
    cell.add_robot("a", rc.preset("paper"))
    cell.add_robot("b", rc.preset("paper"), base=rc.pose([125, 0, 0], [0, 0, np.pi]))
    designer = make_designer(cell)
    designer.apply(act.AddMove("a", "Wait"))
    designer.apply(act.AddMove("b", "Wait"))
    designer.apply(act.SetMoveNumber("b", 0, "seconds", 3.0))
    designer.apply(act.Run())
    assert designer.run.cycle_time == 3.0 and set(designer.run.programs) == {"a", "b"}
    assert designer.program("b").duration == 3.0
