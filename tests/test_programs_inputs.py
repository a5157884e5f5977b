"""Bad programs are refused with an InvalidInputError naming the move and the field."""

from __future__ import annotations

import numpy as np
import pytest

from robotconf import InvalidInputError, set_memory_budget
from robotconf.kinematics import Module, Robot
from robotconf.presets import preset
from robotconf.programs import CIRC, LIN, PTP, Program, Wait

START = PTP(q=[0, 0.3, -0.5])


@pytest.fixture(scope="module")
def paper():
    return preset("paper")


@pytest.mark.parametrize(
    ("moves", "options", "field", "words"),
    [
        ([], {}, "moves", "empty program"),
        ("PTP", {}, "moves", "not a list"),
        ([START, "LIN"], {}, "moves[1]", "not a move"),
        ([START, LIN(position=[60, 10, 30], speed=-20)], {}, "moves[1].speed", "> 0"),
        ([START, LIN(position=[60, 10, 30], accel=0)], {}, "moves[1].accel", "> 0"),
        ([START, LIN(position=[60, 10])], {}, "moves[1].position", "shape (3,)"),
        ([START, LIN(position=[60, 10, 30], pose=np.eye(4))], {}, "moves[1].pose", "more than one"),
        ([START, LIN()], {}, "moves[1].position", "no target"),
        (
            [START, LIN(position=[60, 10, 30], orientation="free")],
            {},
            "moves[1].orientation",
            "unknown",
        ),
        ([PTP(q=[0, 0.3])], {}, "moves[0].q", "shape (3,)"),
        ([PTP(q=[0, 0, 0], profile="cubic")], {}, "moves[0].profile", "unknown"),
        ([PTP(pose=np.diag([1.0, 1.0, -1.0, 1.0]))], {}, "moves[0].pose", "reflection"),
        ([PTP(pose=np.eye(3))], {}, "moves[0].pose", "shape (4, 4)"),
        ([START, Wait(-1)], {}, "moves[1].seconds", "out of range"),
        ([START, CIRC(via=[50, 20, 30])], {}, "moves[1].end", "missing"),
        ([START], {"joint_speed": [1, 2]}, "joint_speed", "shape"),
        ([START], {"joint_accel": [1, -2, 1]}, "joint_accel[1]", "> 0"),
        ([START], {"cartesian_speed": 0}, "cartesian_speed", "> 0"),
        ([START], {"cartesian_speed": 1e-308}, "cartesian_speed", "too small"),
        ([START], {"cartesian_accel": 1e155}, "cartesian_accel", "too large"),
        ([START], {"joint_speed": [1, 1e-200, 1]}, "joint_speed[1]", "too small"),
        ([START], {"angular_accel": 1e-151}, "angular_accel", "too small"),
        ([START], {"start": [0, 0]}, "start", "shape"),
    ],
)
def test_malformed_moves_and_options_name_their_field(paper, moves, options, field, words):
    with pytest.raises(InvalidInputError) as caught:
        Program(paper, moves, **options)
    assert caught.value.field == field
    assert words in str(caught.value)


@pytest.mark.parametrize(
    ("make", "field", "words"),
    [
        (lambda: LIN(position=[60, float("nan"), 30]), "position", "finite"),
        (lambda: LIN(position="60, 10, 30"), "position", "text"),
        (lambda: PTP(q=[0, True, 0]), "q", "boolean"),
        (lambda: Wait(float("inf")), "seconds", "finite"),
        (lambda: Wait(2e9), "seconds", "out of range"),
        # Program numbers are bounded like a robot's: |x| ≤ 1e150, rates 1e-150 … 1e150.
        (lambda: LIN(position=[1e155, 0, 0], speed=10), "position", "too large"),
        (lambda: PTP(position=[0, -1e151, 0]), "position", "too large"),
        (lambda: PTP(q=[0, 1e200, 0]), "q", "too large"),
        (lambda: CIRC(via=[50, 20, 1e300], end=[40, 10, 30]), "via", "too large"),
        (lambda: CIRC(via=[50, 20, 30], end=[40, 1e160, 30]), "end", "too large"),
        (lambda: LIN(pose=_pose_at([1e155, 0, 0])), "pose", "too large"),
        (lambda: LIN(position=[60, 10, 30], speed=1e-308), "speed", "too small"),
        (lambda: LIN(position=[60, 10, 30], speed=float("inf")), "speed", "finite"),
        (lambda: CIRC(via=[50, 20, 30], end=[40, 10, 30], accel=2e150), "accel", "too large"),
    ],
)
def test_a_move_checks_the_bounds_of_its_numbers_when_it_is_made(make, field, words):
    with pytest.raises(InvalidInputError) as caught:
        make()
    assert caught.value.field == field
    assert words in str(caught.value)


def _pose_at(point):
    pose = np.eye(4)
    pose[:3, 3] = point
    return pose


def test_the_smallest_and_largest_rates_are_accepted(paper):
    # 1e-150 and 1e150 are inside the bounds: the move is made; the program then refuses
    # a LIN from (70, 0, 20) of length √300 = 17.3 that would take 1.7e151 s, naming the
    # speed.
    slow = LIN(position=[60, 10, 30], speed=1e-150)
    with pytest.raises(InvalidInputError, match="would take 1.73e[+]151 s") as caught:
        Program(paper, [slow])
    assert caught.value.field == "moves[0].speed"
    fast = Program(paper, [LIN(position=[60, 10, 30], speed=1e150, accel=1e150)])
    # A triangle: 2·√(L/a) = 2·√(17.3e-150) = 8.3e-75 s.
    assert fast.duration == pytest.approx(2 * np.sqrt(np.sqrt(300) / 1e150), rel=1e-12)


@pytest.mark.parametrize(
    ("moves", "options", "field", "words"),
    [
        # From (70, 0, 20), √300 = 17.3 long at 1e-8 per s: 1.7e9 s > MAX_TIME (1e9 s),
        # with the move's own speed …
        ([LIN(position=[60, 10, 30], speed=1e-8)], {}, "moves[0].speed", "1.73e+09 s"),
        # … or the program's, which is named without a move.
        ([LIN(position=[60, 10, 30])], {"cartesian_speed": 1e-8}, "cartesian_speed", "1.73e+09"),
        # A triangle, 2·√(17.3 / 1e-18) = 8.3e9 s.
        ([LIN(position=[60, 10, 30], accel=1e-18)], {}, "moves[0].accel", "8.32e+09 s"),
        ([PTP(q=[1, 0, 0])], {"joint_speed": 1e-12}, "joint_speed", "1e+12 s"),
        ([Wait(6e8), Wait(6e8)], {}, "moves", "the program would take 1.2e+09 s"),
        # A step of 1e-300 at 1e150 per s: the time law overflows, refused (not NaN).
        (
            [PTP(q=[1e-300, 0, 0]), Wait(1)],
            {"joint_speed": 1e150, "joint_accel": 1e150},
            "joint_speed",
            "overflow",
        ),
    ],
)
def test_a_program_longer_than_the_longest_run_is_refused_naming_the_setting(
    paper, moves, options, field, words
):
    with pytest.raises(InvalidInputError) as caught:
        Program(paper, moves, **options)
    assert caught.value.field == field
    assert words in str(caught.value)


def test_a_file_with_unbounded_numbers_names_the_move(paper, tmp_path, capsys):
    from robotconf.cli import main
    from robotconf.io import program_from_dict, program_to_dict, program_to_json

    program = Program(paper, [LIN(position=[60, 10, 30], speed=10)])
    data = program_to_dict(program)
    data["moves"][0]["position"] = [1e155, 0, 0]
    with pytest.raises(InvalidInputError) as caught:
        program_from_dict(data, paper)
    assert caught.value.field == "program.moves[0].position"
    text = program_to_json(program).replace('"speed": 10.0', '"speed": 1e-308')
    assert "1e-308" in text
    path = tmp_path / "setup.json"
    path.write_text(text, encoding="utf-8")
    code = main(["report", str(path), "--out", str(tmp_path / "out"), "--no-scene", "--quiet"])
    assert code == 2
    said = capsys.readouterr().err
    assert "program.moves[0].speed: too small (< 1e-150" in said and "division" not in said


def test_an_unreachable_target_is_refused(paper):
    with pytest.raises(InvalidInputError) as caught:
        Program(paper, [START, LIN(position=[100, 0, 20])])
    assert caught.value.field == "moves[1].position"
    assert "unreachable target" in str(caught.value) and "30 beyond the reach" in str(caught.value)
    with pytest.raises(InvalidInputError, match="beyond the reach") as caught:
        Program(paper, [PTP(position=[0, 0, 95])])
    assert caught.value.field == "moves[0].position"


def test_a_lin_that_goes_nowhere_is_refused(paper):
    here = paper.end_effector([0, 0.3, -0.5])
    with pytest.raises(InvalidInputError, match="goes nowhere") as caught:
        Program(paper, [START, LIN(position=here, speed=20)])
    assert caught.value.field == "moves[1].position"


def test_circ_points_on_one_line_are_refused(paper):
    here = paper.end_effector([0, 0.3, -0.5])
    cases = [
        (here + [1, 1, 0], here + [2, 2, 0]),  # collinear
        (here, here + [2, 2, 0]),  # via at the start
        (here + [1, 0, 0], here + [1, 0, 0]),  # via at the end
        (here + [1, 0, 0], here),  # end at the start: a full circle is not one arc
    ]
    for via, end in cases:
        with pytest.raises(InvalidInputError, match="lie on one line") as caught:
            Program(paper, [START, CIRC(via=via, end=end)])
        assert caught.value.field == "moves[1].via"


def test_coordinates_of_held_modules_must_keep_their_value():
    # A constant twist is a rotation module held at its q and named "(constant)" (as
    # rc.dh_to_modules writes them); neither rc.ik nor a program moves it.
    twist = Module("Rx", a=(1, 0, 0), q=0.2, name="twist (constant)")
    held = Robot([Module("Rz"), twist, Module("Rz", a=(0, 0, 1))], end_effector=(1, 0, 0))
    q = held.q.copy()
    q[1] += 0.1
    with pytest.raises(InvalidInputError, match="not a moving joint") as caught:
        Program(held, [PTP(q=q)])
    assert caught.value.field == "moves[0].q"
    with pytest.raises(InvalidInputError, match="not a moving joint") as caught:
        Program(held, [Wait(1)], start=q)
    assert caught.value.field == "start"


def test_samples_are_bounded_by_dt_and_the_memory_budget(paper):
    prog = Program(paper, [START, Wait(10.0)])
    with pytest.raises(InvalidInputError) as caught:
        prog.simulate(dt=0.0)
    assert caught.value.field == "dt"
    with pytest.raises(InvalidInputError, match="too many samples"):
        prog.check(dt=1e-7)
    set_memory_budget("70M")
    try:
        with pytest.raises(InvalidInputError, match="memory") as caught:
            prog.simulate(dt=1e-5)  # 1.1 million samples, about 6.6 kB each
        assert caught.value.field == "dt"
    finally:
        set_memory_budget(None)
    with pytest.raises(InvalidInputError) as caught:
        prog.check(dt=1e-3, singularity_tolerance=-1)
    assert caught.value.field == "singularity_tolerance"


def test_a_program_that_takes_no_time_cannot_be_sampled(paper):
    prog = Program(paper, [PTP(q=[0, 0, 0])])
    assert prog.duration == 0.0
    with pytest.raises(InvalidInputError, match="nothing to sample") as caught:
        prog.simulate()
    assert caught.value.field == "moves"
