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
        ([START, LIN(position=[60, float("nan"), 30])], {}, "moves[1].position", "finite"),
        ([START, LIN(position=[60, 10])], {}, "moves[1].position", "shape (3,)"),
        ([START, LIN(position="60, 10, 30")], {}, "moves[1].position", "text"),
        ([START, LIN(position=[60, 10, 30], pose=np.eye(4))], {}, "moves[1].pose", "more than one"),
        ([START, LIN()], {}, "moves[1].position", "no target"),
        (
            [START, LIN(position=[60, 10, 30], orientation="free")],
            {},
            "moves[1].orientation",
            "unknown",
        ),
        ([PTP(q=[0, 0.3])], {}, "moves[0].q", "shape (3,)"),
        ([PTP(q=[0, True, 0])], {}, "moves[0].q", "boolean"),
        ([PTP(q=[0, 0, 0], profile="cubic")], {}, "moves[0].profile", "unknown"),
        ([PTP(pose=np.diag([1.0, 1.0, -1.0, 1.0]))], {}, "moves[0].pose", "reflection"),
        ([PTP(pose=np.eye(3))], {}, "moves[0].pose", "shape (4, 4)"),
        ([START, Wait(-1)], {}, "moves[1].seconds", "out of range"),
        ([START, Wait(float("inf"))], {}, "moves[1].seconds", "finite"),
        ([START, CIRC(via=[50, 20, 30])], {}, "moves[1].end", "missing"),
        ([START], {"joint_speed": [1, 2]}, "joint_speed", "shape"),
        ([START], {"joint_accel": [1, -2, 1]}, "joint_accel[1]", "> 0"),
        ([START], {"cartesian_speed": 0}, "cartesian_speed", "> 0"),
        ([START], {"start": [0, 0]}, "start", "shape"),
    ],
)
def test_malformed_moves_and_options_name_their_field(paper, moves, options, field, words):
    with pytest.raises(InvalidInputError) as caught:
        Program(paper, moves, **options)
    assert caught.value.field == field
    assert words in str(caught.value)


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
