"""A cell's run, its contacts and reach maps in the 3D scene, read off a recording channel.

The contact switches are checked against an independent computation: the cell's exact
clearance at every sample of the motion (``cell.clearance(robot, motion.q)``), not the
check's intervals the scene was built from.
"""

from __future__ import annotations

import json
from typing import Any

import numpy as np
import pytest

import robotconf as rc
from robotconf.scene import CellScene, RecordingChannel
from robotconf.scene.workcell._paths import CAPSULES, CONTACTS, OBJECTS, REACH, ROBOTS

from .test_scene_cell import floats, key, labels, objects, paper_cell


def animation(channel: RecordingChannel) -> dict[str, dict[str, dict[str, Any]]]:
    """The last animation: {path: {track name: track}}."""
    command = channel.commands("set_animation")[-1]
    return {a["path"]: {t["name"]: t for t in a["clip"]["tracks"]} for a in command["animations"]}


def at(track: dict[str, Any], times: np.ndarray) -> list[Any]:
    """A discrete track's value at each time: its last keyframe at or before it."""
    keys = floats(track["times"])
    values = track["values"]
    if not isinstance(values, list):
        values = floats(values).reshape(len(keys), -1).tolist()
    # Keyframe times are float32: compare at that precision, as the page does.
    index = np.searchsorted(keys, np.float32(times).astype(float), side="right") - 1
    return [values[k] for k in index]


@pytest.fixture
def cell() -> rc.Cell:
    return paper_cell()


@pytest.fixture
def run(cell: rc.Cell) -> rc.cell.CellRun:
    # Swung from q1 = 0 to -1.5 rad, the forearm sweeps through the fixture and out again.
    return cell.run({"arm": [rc.PTP(q=[-1.5, 0, 0])]}, dt=0.01)


def test_a_contact_is_red_exactly_while_it_lasts(cell: rc.Cell, run: Any) -> None:
    scene = CellScene(cell, channel=RecordingChannel())
    scene.animate(run, play=False)
    (contact,) = run.check.contacts
    assert (contact.link, contact.other, contact.start, contact.end) == (
        "link 3",
        "fixture",
        0.52,
        1.02,
    )
    tracks = animation(scene.channel)
    motion = run.motions["arm"]
    # Independently: the exact clearance of the arm at every sample.
    inside = (cell.clearance("arm", motion.q).distance < 0).tolist()
    link = f"{CONTACTS}/links/{key(scene, 'arm')}/2"
    assert at(tracks[link][".visible"], motion.t) == inside
    red, neutral = [0xE8 / 255, 0x16 / 255, 0x1B / 255], [0xB4 / 255, 0xAC / 255, 0x9C / 255]
    fixture = tracks[f"{OBJECTS}/{key(scene, 'fixture')}/<object>"][".material.color"]
    colors = at(fixture, motion.t)
    np.testing.assert_allclose(colors, [red if hit else neutral for hit in inside], rtol=1e-6)
    # Steps, not fades, on at the first sample in contact and off at the next one after it.
    assert fixture["interpolation"] == 2300
    assert floats(fixture["times"]).tolist() == pytest.approx([0.0, 0.52, 1.03])
    # The red capsule follows link 3: at every keyframe its far ball is at the link's end.
    end = floats(tracks[f"{link}/end1"][".position"]["values"]).reshape(-1, 3)
    segments, _ = cell.link_capsules("arm", motion.q)
    np.testing.assert_allclose(end, segments[:, 2, 1], atol=1e-4)
    # The table is never red; nothing else of the arm is.
    assert f"{OBJECTS}/{key(scene, 'table')}/<object>" not in tracks
    assert not any(path.startswith(f"{CONTACTS}/links/{key(scene, 'arm')}/0") for path in tracks)


def test_a_contact_is_labelled_at_its_point(cell: rc.Cell, run: Any) -> None:
    scene = CellScene(cell, channel=RecordingChannel())
    scene.animate(run)
    (contact,) = run.check.contacts
    assert scene.contact_labels == ["link 3 ↔ fixture, 13 mm"]
    assert "13 mm deep" in contact.message  # the number of the check's own sentence
    (mark,) = scene._animation.marks
    # The point is on link 3's axis at the deepest sample, inside the fixture.
    obstacles, names = cell.obstacles()
    depth = obstacles.exact(
        mark.point[None], mark.point[None], np.zeros(1), np.array([names.index("fixture")])
    )
    assert depth[0] < 0
    anchor = f"{CONTACTS}/labels/0/text"
    assert labels(scene.channel)[anchor] == "link 3 ↔ fixture, 13 mm"
    tracks = animation(scene.channel)
    switch = tracks[f"{CONTACTS}/labels/0"][".visible"]
    assert switch["values"] == [False, True, False]
    assert floats(switch["times"]).tolist() == pytest.approx([0.0, 0.52, 1.03])
    # While the run is loaded the robot's labels are names (numbers would stand still).
    assert scene.labels()[:4] == ["M1", "M2", "M3", "EE"]
    # show() drops the run: its contacts go, the numbers come back.
    scene.show(cell)
    assert scene.playback_state.loaded is False and scene.contact_labels == []
    assert scene.channel.commands("delete")[-1]["path"] == CONTACTS
    assert scene.labels()[3] == "EE (70.0, 0.0, 20.0) mm"


def test_two_robots_play_side_by_side_on_one_clock() -> None:
    duo = rc.Cell(unit="mm")
    duo.add_robot("a", rc.preset("paper"))
    duo.add_robot("b", rc.preset("paper"), base=rc.pose([125, 0, 0], [0, 0, np.pi]))
    start = rc.ik_all(duo.robot("a"), [40, 0, 20])
    q0 = start.q[start.within_limits][0]
    reach_out = rc.Program(
        duo.robot("a"), [rc.LIN(position=[52, 0, 20], speed=4, accel=8)], start=q0
    )
    run = duo.run({"a": reach_out, "b": [rc.Wait(5.0)]})
    scene = CellScene(duo, channel=RecordingChannel())
    scene.animate(run, speed=2.0)
    state = scene.playback_state
    assert (state.duration, state.speed, state.playing) == (5.0, 2.0, True)
    assert scene.contact_labels == ["a link 3 ↔ b link 3, 4.2 mm"]
    tracks = animation(scene.channel)
    a_ee = tracks[f"{ROBOTS}/{key(scene, 'a')}/ee/sphere"][".position"]
    # a's program lasts 3.5 s (its clip ends there and holds); b's Wait lasts 5 s.
    assert floats(a_ee["times"])[-1] == pytest.approx(3.5)
    np.testing.assert_allclose(floats(a_ee["values"]).reshape(-1, 3)[-1], [52, 0, 20], atol=1e-4)
    # Both links of the pair turn red, from the contact's start to the end of the run.
    for robot in ("a", "b"):
        switch = tracks[f"{CONTACTS}/links/{key(scene, robot)}/2"][".visible"]
        assert switch["values"] == [False, True]
        assert floats(switch["times"]).tolist() == pytest.approx([0.0, 2.21])
    # Each robot's TCP path is a trace under its own group (in its base frame).
    scene.show_trace(True)
    traces = [
        c["path"] for c in scene.channel.commands("set_object") if c["path"].endswith("/trace")
    ]
    assert traces == [f"{ROBOTS}/{key(scene, 'a')}/trace", f"{ROBOTS}/{key(scene, 'b')}/trace"]


def test_a_robot_left_out_of_the_run_stands_at_its_own_q() -> None:
    duo = rc.Cell(unit="mm")
    duo.add_robot("a", rc.preset("paper"))
    duo.add_robot("b", rc.preset("paper"), base=rc.pose([200, 0, 0]))
    run = duo.run({"a": [rc.PTP(q=[0.3, 0, 0])]})
    scene = CellScene(duo, {"b": [1.0, 0, 0]}, channel=RecordingChannel())
    scene.animate(run)
    ee = animation(scene.channel)[f"{ROBOTS}/{key(scene, 'b')}/ee/sphere"][".position"]
    # As the check measured it: at b's own q (0, 0, 0), not the q the pane showed.
    np.testing.assert_allclose(floats(ee["values"]).reshape(-1, 3), [[70, 0, 20]] * 2)


def test_a_run_of_another_cell_is_refused(cell: rc.Cell, run: Any) -> None:
    other = rc.Cell()
    other.add_robot("crane", rc.preset("paper"))
    scene = CellScene(other, channel=RecordingChannel())
    with pytest.raises(rc.InvalidInputError, match="a robot the cell does not have: 'arm'"):
        scene.animate(run)
    with pytest.raises(rc.InvalidInputError, match="cell_run: "):
        scene.animate("run")
    assert not scene.playback_state.loaded


def test_reach_map_colours_say_how_many_branches(cell: rc.Cell) -> None:
    scene = CellScene(cell, channel=RecordingChannel())
    rmap = cell.reach_map("arm", [(0, 0, 20), (80, 0, 20)], 20)
    assert rmap.branches.tolist() == [0, 0, 1, 1, 0]  # elbow down hits the table
    few = rc.cell.ReachMap(
        rmap.points, rmap.shape, np.array([0, 1, 2, 4, 0]), rmap.manipulability, rmap.reach
    )
    scene.show_reach_map(few)
    sent = objects(scene.channel)
    reached = sent[f"{REACH}/reached"]["geometries"][0]["data"]["attributes"]
    points = floats(reached["position"]["array"]).reshape(-1, 3)
    colors = floats(reached["color"]["array"]).reshape(-1, 3)
    np.testing.assert_array_equal(points[:, 0], [20, 40, 60])
    # 1 branch: light green (0.74, 0.93, 0.66); 4: dark green (0, 0.42, 0.13); 2: a third.
    np.testing.assert_allclose(colors[0], [0.74, 0.93, 0.66], rtol=1e-6)
    np.testing.assert_allclose(colors[2], [0.0, 0.42, 0.13], atol=1e-7)
    np.testing.assert_allclose(
        colors[1], [0.74 * 2 / 3, 0.93 - 0.51 / 3, 0.66 - 0.53 / 3], rtol=1e-6
    )
    grey = sent[f"{REACH}/unreached"]
    assert floats(grey["geometries"][0]["data"]["attributes"]["position"]["array"]).reshape(-1, 3)[
        :, 0
    ].tolist() == [0, 80]
    assert grey["materials"][0]["opacity"] == 0.25
    assert (
        reached.get("color") and sent[f"{REACH}/reached"]["materials"][0]["size"] == 10.0
    )  # half a voxel
    assert scene.reach_map_legend == (
        "reach map: 3 of 5 voxels reachable; branches 1 (light green) … 4 (dark green); grey: none"
    )
    assert labels(scene.channel)[f"{REACH}/legend"] == scene.reach_map_legend
    scene.show_reach_map(rmap, color_by="manipulability")
    assert "manipulability" in scene.reach_map_legend and "yellow" in scene.reach_map_legend
    scene.clear_reach_map()
    assert scene.channel.commands("delete")[-1]["path"] == REACH and scene.reach_map_legend == ""
    with pytest.raises(rc.InvalidInputError, match="reach_map: "):
        scene.show_reach_map(rmap.points)
    with pytest.raises(rc.InvalidInputError, match="color_by: "):
        scene.show_reach_map(rmap, color_by="speed")


def test_export_html_plays_the_run_offline(cell: rc.Cell, run: Any, tmp_path: Any) -> None:
    scene = CellScene(cell, channel=RecordingChannel())
    scene.animate(run)
    path = scene.export_html(tmp_path / "cell.html", title="Cell <1>")
    text = path.read_text()
    assert "<title>Cell &lt;1&gt;</title>" in text
    assert "http://" not in text.split("<script", 1)[0] and 'src="http' not in text
    written = text.split('id="robotconf-scene-log" type="application/json">')[1]
    log = json.loads(written.split("</script>")[0])  # "<" is written \u003c: JSON reads it
    kinds = [op.get("type", op["op"]) for op in log["ops"]]
    # The animation after everything it moves, then the player, loaded from the start.
    assert kinds.index("set_animation") > kinds.index("set_object")
    assert log["ops"][-1] == {**log["ops"][-1], "op": "playback", "action": "load", "time": 0.0}
    assert set(log["choices"]) == {"labels", "frames", "trace", "capsules", "fit"}
    assert (
        scene.export_html(tmp_path / "plain.html").read_text().count("<title>paper cell</title>")
        == 1
    )
    with pytest.raises(rc.InvalidInputError, match="title: "):
        scene.export_html(tmp_path / "x.html", title=3)  # type: ignore[arg-type]


def test_a_new_view_replays_the_cell(cell: rc.Cell, run: Any) -> None:
    scene = CellScene(cell, capsules=True, channel=RecordingChannel())
    scene.animate(run, play=False)
    scene.seek(0.7)
    replay = RecordingChannel()
    replay.send(scene._replay())
    built = {c["path"] for c in replay.commands("set_object")}
    assert f"{OBJECTS}/{key(scene, 'fixture')}" in built
    assert f"{CAPSULES}/{key(scene, 'arm')}/2/body" in built
    assert f"{CONTACTS}/labels/0/text" in built
    load = replay.ops[-1].content
    assert (load["action"], load["time"], load["playing"]) == ("load", 0.7, False)
    options = [op.content for op in replay.ops if op.content["op"] == "options"][-1]
    assert options["capsules"] is True
