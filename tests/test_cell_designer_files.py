"""A robot's program in the cell file: written with its frames, read back exactly, old files
still read, and bad programs refused naming the JSON path."""

from __future__ import annotations

import json

import numpy as np
import pytest

import robotconf as rc
from robotconf.io import cell_from_dict, cell_to_dict, cell_to_json, load_cell, save_cell
from robotconf.programs import CIRC, LIN, PTP, Wait

from .test_cell_designer_support import paper_on_table

MOVES = (
    PTP(q=(0.0, 0.3, -0.5)),
    LIN(frame="table/pick", speed=10.0, accel=20.0),
    CIRC(via=(50.0, 10.0, 30.0), end=(40.0, 0.0, 30.0), speed=5.0),
    PTP(frame="table/pick", profile="quintic"),
    Wait(0.5),
)


def test_a_program_with_frames_round_trips_exactly(tmp_path):
    cell = paper_on_table()
    programs = {"arm": (MOVES, {"joint_speed": 2.0, "cartesian_speed": 8.0})}
    path = save_cell(cell, tmp_path / "cell.json", programs=programs)
    data = json.loads(path.read_text())
    entry = data["robots"][0]["program"]
    assert entry["moves"][1] == {
        "type": "LIN",
        "position": None,
        "pose": None,
        "speed": 10.0,
        "accel": 20.0,
        "orientation": "slerp",
        "frame": "table/pick",
    }
    assert entry["joint_speed"] == 2.0 and entry["start"] is None  # every option written
    back, read = load_cell(path, with_programs=True)
    assert read == {"arm": (MOVES, {"joint_speed": 2.0, "cartesian_speed": 8.0})}
    assert cell_to_json(back, path, programs=read) == cell_to_json(cell, path, programs=programs)
    # The frame resolves in the cell as it was written: the LIN ends on the pick point.
    program = back.program("arm", list(read["arm"][0][:2]), **read["arm"][1])
    motion = program.simulate(0.01)
    base = back.pose_of("arm")
    end = base[:3, :3] @ motion.trace[-1] + base[:3, 3]
    assert np.allclose(end, back.pose_of("table/pick")[:3, 3], atol=1e-9)


def test_a_program_object_and_plain_moves_are_written_alike(tmp_path):
    cell = paper_on_table()
    program = rc.Program(cell.robot("arm"), [PTP(q=(0.0, 0.3, -0.5)), Wait(1.0)], joint_speed=2.0)
    as_program = cell_to_dict(cell, programs={"arm": program})
    as_moves = cell_to_dict(cell, programs={"arm": (program.moves, {"joint_speed": 2.0})})
    assert as_program == as_moves
    assert as_program["robots"][0]["program"]["joint_speed"] == 2.0


def test_no_moves_no_program_and_old_files_still_read(tmp_path):
    cell = paper_on_table()
    data = cell_to_dict(cell, programs={"arm": []})
    assert "program" not in data["robots"][0]  # the file is what version 1 always wrote
    back, programs = cell_from_dict(data, with_programs=True)
    assert programs == {} and back.robot("arm") == cell.robot("arm")
    assert isinstance(load_cell(cell_to_json(cell)), rc.Cell)  # one value as before
    assert cell_to_json(cell) == cell.to_json()


def test_programs_for_robots_the_cell_lacks_are_refused():
    with pytest.raises(rc.InvalidInputError, match=r"programs: .*'ghost'.*robots of the cell"):
        cell_to_dict(paper_on_table(), programs={"ghost": [Wait(1.0)]})
    with pytest.raises(rc.InvalidInputError, match=r"programs\['arm'\]"):
        cell_to_dict(paper_on_table(), programs={"arm": "PTP"})


def _file_with(program: object) -> dict:
    data = cell_to_dict(paper_on_table())
    data["robots"][0]["program"] = program
    return data


@pytest.mark.parametrize(
    ("program", "field", "words"),
    [
        (
            {"moves": [{"type": "LIN", "frame": "nowhere"}]},
            "robots[0].program.moves[0].frame",
            "no such frame",
        ),
        ({"moves": [{"type": "PTP", "q": [0, 0]}]}, "robots[0].program.moves[0].q", ""),
        ({"moves": [{"type": "Jump"}]}, "robots[0].program.moves[0].type", "unknown move type"),
        ({"moves": []}, "robots[0].program.moves", "1 to 200"),
        ({"moves": [{"type": "Wait", "seconds": 1}], "joint_speed": -1}, "robots[0].program", ""),
        (
            {"moves": [{"type": "LIN", "frame": "table/pick", "speed": 1e300}]},
            "robots[0].program.moves[0].speed",
            "",
        ),
        ({"moves": [{"type": "Wait", "seconds": 1}], "extra": 1}, "robots[0].program", "extra"),
        ({"moves": [{"type": "Wait", "seconds": True}]}, "robots[0].program.moves[0].seconds", ""),
        ("PTP", "robots[0].program", ""),
    ],
)
def test_bad_programs_are_refused_naming_the_json_path(program, field, words):
    with pytest.raises(rc.InvalidInputError) as caught:
        cell_from_dict(_file_with(program))
    assert caught.value.field.startswith(field), caught.value.field
    assert words in str(caught.value)


def test_a_program_naming_an_object_is_read_as_the_cell_resolves_it():
    data = _file_with({"moves": [{"type": "PTP", "frame": "fixture"}]})
    _, programs = cell_from_dict(data, with_programs=True)
    assert programs["arm"][0][0].frame == "fixture"
