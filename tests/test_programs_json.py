"""Programs as JSON: exact round trips, the "program" section of setup files, errors by path."""

from __future__ import annotations

import json

import numpy as np
import pytest

import robotconf as rc
from robotconf import InvalidInputError
from robotconf.io import Setup, load_program, load_setup, program_to_json
from robotconf.presets import preset
from robotconf.programs import CIRC, LIN, PTP, Program, Wait

pytestmark = pytest.mark.filterwarnings("ignore:the program has:UserWarning")


@pytest.fixture(scope="module")
def paper_program():
    return Program(
        preset("paper"),
        [
            PTP(q=[0, 0.3, -0.5]),
            LIN(position=[60, 10, 30], speed=20),
            CIRC(via=[50, 20, 30], end=[40, 10, 30], accel=30.0),
            Wait(0.5),
            PTP(position=[30, 30, 40], profile="quintic"),
        ],
        joint_speed=[1.0, 2.0, 1.5],
        cartesian_accel=40,
        start=[0.0, -0.0, 0.1],
    )


def test_json_round_trip_is_exact(paper_program):
    text = program_to_json(paper_program)
    back = load_program(text)
    assert back == paper_program
    assert program_to_json(back) == text
    assert back.settings["start"] == (0.0, -0.0, 0.1)
    assert str(back.settings["start"][1]) == "-0.0"  # the sign of zero survives
    first, second = paper_program.simulate(dt=5e-3), back.simulate(dt=5e-3)
    for name in ("t", "q", "qd", "qdd", "position", "velocity", "acceleration"):
        assert np.array_equal(getattr(first, name), getattr(second, name)), name
    data = json.loads(text)
    assert data["format"] == "robotconf" and set(data) == {"format", "version", "robot", "program"}
    assert data["program"]["moves"][1] == {
        "type": "LIN",
        "position": [60.0, 10.0, 30.0],
        "pose": None,
        "speed": 20.0,
        "accel": None,
        "orientation": "slerp",
    }


def test_pose_targets_round_trip_bit_for_bit():
    puma = preset("puma560")
    q0 = np.array([0.2, 0.7, -2.6, 0.1, 0.8, 0.3])
    goal = puma.end_effector_pose(q0 + [0.05, -0.1, 0.1, 0.2, -0.1, 0.3])
    prog = Program(puma, [PTP(q=q0), LIN(pose=goal), PTP(pose=puma.end_effector_pose(q0))])
    back = load_program(program_to_json(prog, indent=None))
    assert back == prog
    assert np.array_equal(np.array(back.moves[1].pose), goal)
    assert np.array_equal(back.segments[2].q_end, prog.segments[2].q_end)


def test_setup_files_carry_a_program(tmp_path, paper_program):
    setup = Setup(paper_program.robot, simulation={"t_end": 2.0}, program=paper_program)
    path = setup.save(tmp_path / "cell.json")
    loaded = load_setup(path)
    assert loaded == setup and loaded.program == paper_program
    assert rc.load(path) == paper_program.robot  # the robot alone, program validated
    assert load_setup(rc.preset("paper").to_json()).program is None
    with pytest.raises(InvalidInputError, match="missing") as caught:
        load_program(rc.preset("paper").to_json())
    assert caught.value.field == "program"


def test_a_setup_refuses_a_program_of_another_robot(paper_program):
    with pytest.raises(InvalidInputError) as caught:
        Setup(preset("planar_2r"), program=paper_program)
    assert caught.value.field == "program"


def _file(program_section):
    robot = json.loads(preset("paper").to_json())["robot"]
    return json.dumps(
        {"format": "robotconf", "version": 1, "robot": robot, "program": program_section}
    )


@pytest.mark.parametrize(
    ("section", "field", "words"),
    [
        ({"moves": [{"type": "PTP", "q": [0, 0.3]}]}, "program.moves[0].q", "shape (3,)"),
        ({"moves": [{"type": "PTP", "q": [0, True, 0]}]}, "program.moves[0].q[1]", "boolean"),
        ({"moves": [{"type": "Jump"}]}, "program.moves[0].type", "unknown move type"),
        ({"moves": [{"type": "Wait", "sec": 1}]}, "program.moves[0].sec", "unknown key"),
        (
            {"moves": [{"type": "LIN", "position": [50, 10, 30], "speed": "fast"}]},
            "program.moves[0].speed",
            "text",
        ),
        ({"moves": []}, "program.moves", "empty program"),
        ({"moves": {}}, "program.moves", "not a list"),
        ({}, "program.moves", "missing"),
        (
            {"moves": [{"type": "Wait", "seconds": 1}], "joint_speed": -1},
            "program.joint_speed",
            "> 0",
        ),
        (
            {"moves": [{"type": "LIN", "position": [100, 0, 20]}]},
            "program.moves[0].position",
            "unreachable",
        ),
    ],
)
def test_file_errors_name_the_json_path(section, field, words):
    with pytest.raises(InvalidInputError) as caught:
        load_setup(_file(section))
    assert caught.value.field == field
    assert words in str(caught.value)


def test_nan_in_a_file_is_refused_by_path():
    text = _file({"moves": [{"type": "Wait", "seconds": 1}]}).replace(
        '"seconds": 1', '"seconds": NaN'
    )
    with pytest.raises(InvalidInputError, match="NaN is not allowed") as caught:
        load_setup(text)
    assert caught.value.field == "program.moves[0].seconds"


def test_the_documented_program_example_loads():
    from pathlib import Path

    doc = (Path(__file__).parent.parent / "docs" / "file-format.md").read_text(encoding="utf-8")
    block = doc.split("## Programs", 1)[1].split("```json\n", 1)[1].split("```", 1)[0]
    setup = load_setup(block)
    assert [m.kind for m in setup.program.moves] == ["PTP", "LIN", "CIRC", "Wait"]
    np.testing.assert_allclose(setup.program.segments[1].point_end, [60, 10, 30], atol=1e-9)
