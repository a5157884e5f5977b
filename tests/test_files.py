"""robotconf JSON files: exact round trips, save/load, and a hostile corpus."""

import copy
import json

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import robotconf as rc
from robotconf import DHLink, InvalidInputError, Module, Robot
from robotconf import signals as sg
from robotconf.kinematics import MAX_PARAMETER, check_module_names


def _mixed_robot():
    return Robot(
        [
            Module("Rz", limits=(-3, 3), name="base"),
            Module("Ty", a=(0.1, 1e-300, -0.0), q=0.3, limits=(0, 2)),
            Module("fixed", a=(5e-324, 2.5, 1 / 3)),
            Module("none"),
            DHLink(0.1, 0.2, 0.3, -0.4, "P", "modified", q=1e10, name="ünïcode ✓", limits=(0, 1)),
        ],
        end_effector=(0.1 + 0.2, 0, -7),
        active=4,
        name="mixed",
    )


@pytest.mark.parametrize("name", rc.preset_names())
def test_every_preset_round_trips_exactly(name):
    robot = rc.preset(name)
    assert Robot.from_json(robot.to_json()) == robot


def test_mixed_robot_round_trips_bit_for_bit():
    robot = _mixed_robot()
    back = Robot.from_json(robot.to_json(indent=None))
    assert back == robot
    assert repr(back) == repr(robot)
    assert np.signbit(back.modules[1].a[2])  # -0.0 survives
    assert back.modules[2].a[0] == 5e-324


def test_written_form_matches_the_documented_schema():
    robot = Robot([Module("Ry", a=(0, 0, 20), limits=(-1, 1))], end_effector=(40, 0, 0))
    data = json.loads(robot.to_json(simulation={"t_end": 5}))
    assert data == {
        "format": "robotconf",
        "version": 1,
        "robot": {
            "name": None,
            "end_effector": [40.0, 0.0, 0.0],
            "active": None,
            "links": [
                {
                    "type": "module",
                    "kind": "Ry",
                    "a": [0.0, 0.0, 20.0],
                    "q": 0.0,
                    "name": None,
                    "limits": [-1.0, 1.0],
                }
            ],
        },
        "simulation": {"t_end": 5.0},
    }
    assert '"a": [0.0, 0.0, 20.0]' in robot.to_json()  # number lists stay on one line


# Every number of a robot is at most MAX_PARAMETER (1e150) in magnitude.
finite = st.floats(-MAX_PARAMETER, MAX_PARAMETER)
kinds = st.sampled_from(["none", "Rx", "Ry", "Rz", "Tx", "Ty", "Tz", "fixed"])


@st.composite
def links(draw):
    if draw(st.booleans()):
        kind = draw(kinds)
        limits = None
        if kind not in ("none", "fixed") and draw(st.booleans()):
            lo = draw(st.floats(-1e9, 1e9))
            limits = (lo, lo + draw(st.floats(1e-6, 1e9)))
        return Module(
            kind,
            a=draw(st.tuples(finite, finite, finite)),
            q=draw(finite),
            limits=limits,
            name=draw(st.none() | st.text(max_size=20)),
        )
    return DHLink(
        *draw(st.tuples(finite, finite, finite, finite)),
        joint=draw(st.sampled_from("RP")),
        convention=draw(st.sampled_from(["standard", "modified"])),
        q=draw(finite),
        name=draw(st.none() | st.text(max_size=20)),
    )


@settings(max_examples=60, deadline=None)
@given(chain=st.lists(links(), min_size=1, max_size=6), point=st.tuples(finite, finite, finite))
def test_round_trip_property(chain, point):
    try:  # random names may clash (two modules "a"); a robot refuses that
        check_module_names([link.name for link in chain])
    except rc.InvalidInputError:
        assume(False)
    robot = Robot(chain, end_effector=point, name="random")
    assert Robot.from_json(robot.to_json()) == robot


def test_setup_with_signals_and_simulation_round_trips():
    signals = {"q3": sg.RepeatingSequence() * 0.5, "q1": sg.Sine(frequency=0.5) + sg.Ramp()}
    simulation = {"t_end": 10.0, "dt": 0.01, "t0": 0.0, "method": "numeric"}
    setup = rc.Setup(rc.preset("paper"), signals, simulation)
    back = rc.load_setup(setup.to_json())
    assert back == setup
    assert back.signals["q3"] == signals["q3"]
    assert back.simulate_kwargs() == simulation
    motion = rc.simulate(back.robot, back.signals, **back.simulate_kwargs())
    assert motion.t[-1] == pytest.approx(10.0)


def test_setup_takes_simulation_settings_and_writes_all_four_keys():
    from robotconf.motion import SimulationSettings

    settings = SimulationSettings(t_end=2.0, dt=0.01, method="numeric")
    setup = rc.Setup(rc.preset("paper"), {"q3": sg.Ramp()}, settings)
    assert setup.simulation == {"t_end": 2.0, "dt": 0.01, "t0": 0.0, "method": "numeric"}
    assert setup.settings == settings and setup.settings.samples == 201
    assert rc.load_setup(setup.to_json()) == setup
    text = rc.preset("paper").to_json(simulation=settings)
    assert json.loads(text)["simulation"] == settings.to_dict()
    assert rc.Setup(rc.preset("paper")).settings is None


def test_setup_keeps_only_the_keys_given_and_normalizes_them():
    setup = rc.Setup(rc.preset("paper"), {}, {"t_end": 3, "method": "Numeric"})
    assert setup.simulation == {"t_end": 3.0, "method": "numeric"}
    assert setup.simulate_kwargs() == {"t_end": 3.0, "method": "numeric"}
    assert setup.settings.to_dict() == {"t_end": 3.0, "dt": 0.001, "t0": 0.0, "method": "numeric"}


def test_signal_keys_resolve_like_robot_index():
    robot = rc.preset("paper")
    setup = rc.Setup(robot, {"M3": sg.Ramp(), 0: 0.5})
    assert setup.signals == {"q3": sg.Ramp(), "q1": sg.Constant(0.5)}
    with pytest.raises(InvalidInputError, match=r"signals\.Q1: q1 is given twice"):
        rc.Setup(robot, {"q1": sg.Ramp(), "Q1": sg.Step()})


def test_numbers_in_signals_mean_constants_and_keys_are_checked():
    setup = rc.Setup(rc.preset("paper"), {"Q2": 0.5})
    assert setup.signals == {"q2": sg.Constant(0.5)}
    with pytest.raises(
        InvalidInputError,
        match=r"signals\.q4: unknown module 'q4'; allowed: an index 0 to 2, .*\(q1 to q3\)",
    ):
        rc.Setup(rc.preset("paper"), {"q4": sg.Ramp()})
    with pytest.raises(InvalidInputError, match=r"robot: invalid value 'paper'; allowed: a Robot"):
        rc.Setup("paper")


def test_save_and_load(tmp_path):
    robot = _mixed_robot()
    path = robot.save(tmp_path / "robot.json", signals={"q1": sg.Step()}, simulation={"t_end": 3})
    assert path.read_text(encoding="utf-8").endswith("}\n")
    assert rc.load(path) == robot
    assert rc.load(str(path)) == robot
    setup = rc.load_setup(path)
    assert setup.signals == {"q1": sg.Step()} and setup.simulation == {"t_end": 3.0}
    assert rc.load_setup(str(path)) == setup
    assert rc.load_setup(path.read_bytes()) == setup
    setup.save(tmp_path / "again.json")
    assert rc.load_setup(tmp_path / "again.json") == setup


def test_byte_order_mark_is_accepted(tmp_path):
    path = tmp_path / "bom.json"
    path.write_bytes(b"\xef\xbb\xbf" + rc.preset("paper").to_json().encode())
    assert rc.load(path) == rc.preset("paper")


@pytest.mark.parametrize(
    ("content", "match"),
    [
        (b'{"format": "robotconf", "name": "\xff\xfe"}', r"file: invalid UTF-8 at byte 33"),
        (b" " * 1_000_001, r"file: too large.*at most 1000000 bytes"),
    ],
)
def test_hostile_files(tmp_path, content, match):
    path = tmp_path / "bad.json"
    path.write_bytes(content)
    with pytest.raises(InvalidInputError, match=match):
        rc.load(path)


def test_missing_file_and_wrong_source_type(tmp_path):
    with pytest.raises(
        InvalidInputError, match=r"file: No such file or directory: '.*nothere\.json'"
    ):
        rc.load(tmp_path / "nothere.json")
    with pytest.raises(InvalidInputError, match=r"source: not: 3"):
        rc.load_setup(3)


def _valid():
    return json.loads(
        rc.preset("paper").to_json(signals={"q3": sg.RepeatingSequence()}, simulation={"t_end": 1})
    )


def _changed(edit):
    data = _valid()
    edit(data)
    return json.dumps(data)


def _set(path, value):
    def edit(data):
        *parents, last = path
        for key in parents:
            data = data[key]
        data[last] = value

    return edit


def _delete(path):
    def edit(data):
        *parents, last = path
        for key in parents:
            data = data[key]
        del data[last]

    return edit


LINK0 = ("robot", "links", 0)
VALID = json.dumps(_valid())

HOSTILE = {
    "not json": ("{robot: 1}", r"file: not valid JSON \(Expecting property name .*line 1 column 2"),
    "truncated": (VALID[:-5], r"file: not valid JSON"),
    "top-level list": ("[1, 2]", r"file: expected an object, got \[1, 2\]; allowed: a JSON object"),
    "top-level string": ('"robot"', r"file: expected an object, got 'robot'"),
    "wrong format tag": (
        _changed(_set(("format",), "urdf")),
        r"format: not a robotconf file: 'urdf'",
    ),
    "missing format": (_changed(_delete(("format",))), r"format: not a robotconf file: None"),
    "future version": (
        _changed(_set(("version",), 2)),
        r"version: written by a newer robotconf: file format version 2; "
        r"allowed: versions up to 1: update robotconf",
    ),
    "version zero": (
        _changed(_set(("version",), 0)),
        r"version: invalid value 0; allowed: an integer 1…1",
    ),
    "version as text": (_changed(_set(("version",), "1")), r"version: invalid value '1'"),
    "version as bool": (_changed(_set(("version",), True)), r"version: invalid value True"),
    "unknown top key": (
        _changed(_set(("macro",), "rm -rf")),
        r"file\.macro: unknown key, value 'rm -rf'",
    ),
    "missing robot": (_changed(_delete(("robot",))), r"file\.robot: missing"),
    "unknown robot key": (
        _changed(_set(("robot", "base"), [0, 0, 0])),
        r"robot\.base: unknown key",
    ),
    "missing links": (_changed(_delete(("robot", "links"))), r"robot\.links: missing"),
    "empty links": (_changed(_set(("robot", "links"), [])), r"robot\.links: not a non-empty list"),
    "links not a list": (
        _changed(_set(("robot", "links"), {"0": 1})),
        r"robot\.links: not a non-empty list",
    ),
    "100000 links": (
        '{"format": "robotconf", "version": 1, "robot": {"links": ['
        + ",".join(['{"type":"module","kind":"Rz"}'] * 65)
        + "]}}",
        r"robot\.links: too many links: '<65 links>'; allowed: a list of 1 to 64 links",
    ),
    "unknown kind": (
        _changed(_set(LINK0 + ("kind",), "Rw")),
        r"robot\.links\[0\]\.kind: unknown value 'Rw'; allowed: 'none' or 'Rx'",
    ),
    "kind as code": (
        _changed(_set(LINK0 + ("kind",), 3)),
        r"robot\.links\[0\]\.kind: expected text, got 3",
    ),
    "missing kind": (_changed(_delete(LINK0 + ("kind",))), r"robot\.links\[0\]\.kind: missing"),
    "unknown link type": (
        _changed(_set(LINK0 + ("type",), "joint")),
        r"robot\.links\[0\]\.type: unknown link type 'joint'",
    ),
    "link not object": (
        _changed(_set(("robot", "links"), [7])),
        r"robot\.links\[0\]: unknown link type 7",
    ),
    "unknown link key": (
        _changed(_set(LINK0 + ("mass",), 1)),
        r"robot\.links\[0\]\.mass: unknown key, value 1",
    ),
    "bool q": (
        _changed(_set(LINK0 + ("q",), True)),
        r"robot\.links\[0\]\.q: expected a number, got a boolean: True",
    ),
    "string q": (
        _changed(_set(LINK0 + ("q",), "__import__('os')")),
        r"robot\.links\[0\]\.q: expected a number, got \"__import__\('os'\)\"",
    ),
    "null q": (
        _changed(_set(LINK0 + ("q",), None)),
        r"robot\.links\[0\]\.q: expected a number, got None",
    ),
    "NaN": (
        VALID.replace('"q": 0.0', '"q": NaN', 1),
        r"robot\.links\[0\]\.q: NaN is not allowed: NaN",
    ),
    "Infinity": (
        VALID.replace('"end_effector": [40.0', '"end_effector": [Infinity', 1),
        r"robot\.end_effector\[0\]: Infinity is not allowed",
    ),
    "-Infinity": (
        VALID.replace('"q": 0.0', '"q": -Infinity', 1),
        r"robot\.links\[0\]\.q: -Infinity is not allowed",
    ),
    "overflowing float": (
        VALID.replace('"q": 0.0', '"q": 1e400', 1),
        r"robot\.links\[0\]\.q: too large for a float: 1e400",
    ),
    "huge integer": (
        VALID.replace('"q": 0.0', '"q": ' + "9" * 5000, 1),
        r"robot\.links\[0\]\.q: number with too many digits",
    ),
    "a with 2 entries": (
        _changed(_set(LINK0 + ("a",), [0, 0])),
        r"robot\.links\[0\]\.a: expected 3 numbers: \[0, 0\]",
    ),
    "a nested": (
        _changed(_set(LINK0 + ("a",), [[0], 0, 0])),
        r"robot\.links\[0\]\.a\[0\]: expected a number, got \[0\]",
    ),
    "end_effector text": (
        _changed(_set(("robot", "end_effector"), "0,0,0")),
        r"robot\.end_effector: expected 3 numbers",
    ),
    "reversed limits": (
        _changed(_set(LINK0 + ("limits",), [1, -1])),
        r"robot\.links\[0\]\.limits: lower limit must be below upper limit",
    ),
    "limits on fixed": (
        _changed(_set(LINK0, {"type": "module", "kind": "fixed", "limits": [0, 1]})),
        r"robot\.links\[0\]\.limits: a 'fixed' module has no joint",
    ),
    "active out of range": (
        _changed(_set(("robot", "active"), 9)),
        r"robot\.active: out of range: 9; allowed: an integer from 1 to 3",
    ),
    "active float": (
        _changed(_set(("robot", "active"), 2.0)),
        r"robot\.active: expected an integer, got 2.0",
    ),
    "name number": (_changed(_set(("robot", "name"), 5)), r"robot\.name: expected text, got 5"),
    "name too long": (
        _changed(_set(LINK0 + ("name",), "x" * 201)),
        r"robot\.links\[0\]\.name: too long",
    ),
    "dh missing convention": (
        _changed(_set(LINK0, {"type": "dh", "theta": 0, "d": 0, "a": 1, "alpha": 0, "joint": "R"})),
        r"robot\.links\[0\]\.convention: missing",
    ),
    "dh guessed convention": (
        _changed(
            _set(
                LINK0,
                {
                    "type": "dh",
                    "theta": 0,
                    "d": 0,
                    "a": 1,
                    "alpha": 0,
                    "joint": "R",
                    "convention": "craig",
                },
            )
        ),
        r"robot\.links\[0\]\.convention: unknown value 'craig'; allowed: 'standard' or 'modified'",
    ),
    "dh bad joint": (
        _changed(
            _set(
                LINK0,
                {
                    "type": "dh",
                    "theta": 0,
                    "d": 0,
                    "a": 1,
                    "alpha": 0,
                    "joint": "revolute",
                    "convention": "standard",
                },
            )
        ),
        r"robot\.links\[0\]\.joint: unknown value 'revolute'; allowed: 'R' or 'P'",
    ),
    "duplicate key": (
        VALID.replace('"kind": "Rz"', '"kind": "Rz", "kind": "Tz"', 1),
        r"robot\.links\[0\]\.kind: duplicate key 'kind'",
    ),
    "duplicate top key": (VALID[:-1] + ', "robot": {}}', r"file\.robot: duplicate key"),
    "deep nesting": (
        '{"format": "robotconf", "version": 1, "robot": ' + "[" * 100_000 + "]" * 100_000 + "}",
        r"file: too deep",
    ),
    "nested garbage in name": (
        _changed(_set(("robot", "name"), [[[[["x"]]]]])),
        r"robot\.name: expected text",
    ),
    "signals not object": (_changed(_set(("signals",), [1])), r"signals: not: \[1\]"),
    "signal for unknown coordinate": (
        _changed(_set(("signals", "q9"), {"type": "Ramp"})),
        r"signals\.q9: unknown module 'q9'",
    ),
    "signal unknown type": (
        _changed(_set(("signals", "q3"), {"type": "Eval", "code": "1"})),
        r"signals\.q3\.type: unknown signal type 'Eval'",
    ),
    "signal bool parameter": (
        _changed(_set(("signals", "q3"), {"type": "Ramp", "slope": False})),
        r"signals\.q3\.slope: expected a number, got bool False",
    ),
    "repeating table too long": (
        _changed(
            _set(
                ("signals", "q3"),
                {"type": "RepeatingSequence", "times": list(range(20_000)), "values": [0] * 20_000},
            )
        ),
        r"signals\.q3\.times: table too long",
    ),
    "signal NaN": (
        VALID.replace('"values": [0.0, 2.0]', '"values": [NaN, 2.0]', 1),
        r"signals\.q3\.values\[0\]: NaN is not allowed",
    ),
    "simulation dt zero": (
        _changed(_set(("simulation", "dt"), 0)),
        r"simulation\.dt: must be positive, got 0.0; allowed: a time step > 0",
    ),
    "simulation too many samples": (
        _changed(_set(("simulation", "dt"), 1e-9)),
        r"simulation\.dt: too many samples at 1e-09",
    ),
    "simulation t_end before t0": (
        _changed(_set(("simulation", "t0"), 5)),
        r"simulation\.t_end: must be later than t0, got 1.0; allowed: a time after t0 = 5.0 s",
    ),
    "simulation unknown method": (
        _changed(_set(("simulation", "method"), "euler")),
        r"simulation\.method: unknown method 'euler'; allowed: 'analytic' .* or 'numeric'",
    ),
    "simulation missing t_end": (
        _changed(_delete(("simulation", "t_end"))),
        r"simulation\.t_end: missing",
    ),
    "simulation unknown key": (
        _changed(_set(("simulation", "solver"), "ode45")),
        r"simulation\.solver: unknown key",
    ),
    "simulation dt boolean": (
        _changed(_set(("simulation", "dt"), True)),
        r"simulation\.dt: expected a number, got a boolean: True",
    ),
    "simulation dt text": (
        _changed(_set(("simulation", "dt"), "0.01")),
        r"simulation\.dt: expected a number, got '0\.01'",
    ),
    "simulation t_end NaN": (
        VALID.replace('"t_end": 1.0', '"t_end": NaN', 1),
        r"simulation\.t_end: NaN is not allowed",
    ),
    "simulation method not text": (
        _changed(_set(("simulation", "method"), 1)),
        r"simulation\.method: expected text, got 1",
    ),
    "simulation not an object": (
        _changed(_set(("simulation",), [1.0])),
        r"simulation: expected an object, got \[1\.0\]",
    ),
    "simulation duplicate key": (
        VALID.replace('"t_end": 1.0', '"t_end": 1.0, "t_end": 2.0', 1),
        r"simulation\.t_end: duplicate key",
    ),
    "signal given twice": (
        VALID.replace('"signals": {', '"signals": {"Q3": 1.0, ', 1),
        r"signals\.q3: q3 is given twice: 'q3'; allowed: each coordinate once",
    ),
    "too large text": (
        VALID + " " * 1_000_000,
        r"file: too large: '<\d+ characters>'; allowed: at most 1000000 bytes",
    ),
}


@pytest.mark.parametrize(("text", "match"), list(HOSTILE.values()), ids=list(HOSTILE))
def test_hostile_corpus(text, match):
    with pytest.raises(InvalidInputError, match=match):
        rc.load_setup(text)


def test_the_corpus_base_is_valid_and_large():
    assert rc.load_setup(VALID).robot == rc.preset("paper")
    assert len(HOSTILE) >= 20


def test_from_json_validates_signals_too():
    bad = json.loads(VALID)
    bad["signals"]["q3"]["type"] = "Nope"
    with pytest.raises(InvalidInputError, match=r"signals\.q3\.type"):
        Robot.from_json(json.dumps(bad))


def test_writing_an_unknown_link_type_is_refused():
    class Strange(rc.Link):
        q = 0.0
        name = None
        joint_type = "revolute"

        def geometry(self):
            return rc.LinkGeometry(axis=2, joint="R")

        def with_q(self, q):
            return self

    robot = Robot([Strange()])
    with pytest.raises(InvalidInputError, match=r"modules\[0\]: cannot be written to a file"):
        robot.to_json()


def test_copy_of_valid_document_is_not_shared():
    data = _valid()
    copy.deepcopy(data)["robot"]["links"].clear()
    assert len(data["robot"]["links"]) == 3


def test_the_documented_example_loads():
    from pathlib import Path

    doc = (Path(__file__).parent.parent / "docs" / "file-format.md").read_text(encoding="utf-8")
    example = doc.split("```json\n", 1)[1].split("```", 1)[0]
    setup = rc.load_setup(example)
    assert setup.robot.module_names == ("M1", "M2", "elbow")
    np.testing.assert_allclose(setup.robot.end_effector([0, 0, 0]), [70, 0, 20])
    assert setup.signals["q3"].value(1.0) == 0.5
    assert setup.simulation == {"t_end": 10.0, "dt": 0.001, "t0": 0.0, "method": "analytic"}
