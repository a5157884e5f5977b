"""Numbers that reveal the slip, for a whole class: a sweep over 200 student ids.

Every exercise with per-student numbers (``robotconf.teaching.exercises``) lists the
answers its typical single slips give; ``rc.Assignment`` redraws a student's numbers
until the check refuses each of them. The sweep draws 200 ids for every lesson and
asserts, straight against the checker's mistake models (no notebook runs):

- every id gets numbers (screening never runs out of draws);
- with them the right answer passes and no typical slip does;
- on a sample of ids, the same holds with the notebook's full check (with its
  diagnosis), not only the quick numeric rule screening uses; the check names nearly
  every slip, and a named slip earns a quarter to three quarters of the exercise's
  points by the course's rubric.

Drawn numbers come from short lists, so many ids share them; verdicts are cached per
numbers, which keeps the sweep to about a minute of CPU.
"""

from __future__ import annotations

import numpy as np
import pytest

import robotconf as rc
from robotconf.grading import award, names_a_slip, read_weights
from robotconf.teaching.exercises import registered

from .course_support import COURSE

LESSONS = sorted({exercise.lesson for exercise in registered()})
IDS = [f"student-{i:03d}" for i in range(200)]
#: Ids whose slips also go through the full check, with its diagnosis.
SAMPLED = IDS[::100]


def test_every_lesson_with_drawn_numbers_is_registered():
    assert LESSONS == [
        "02_elementary_transforms",
        "03_composing_a_chain",
        "04_module_method_classic_arms",
        "05_denavit_hartenberg",
        "06_real_arms",
        "07_velocity_acceleration",
        "08_workspace_singularities",
        "09_dh_frame_assignment",
        "10_paper_lab",
        "11_inverse_kinematics",
        "12_trajectories",
        "13_work_cell",
    ]
    for lesson in LESSONS:
        task = rc.Assignment(lesson, "demo")
        for exercise in registered(lesson):
            assert exercise.slips(task.numbers), (lesson, exercise.number)


@pytest.mark.parametrize("lesson", LESSONS)
def test_no_typical_slip_passes_for_any_of_200_ids(lesson):
    hidden = []
    for student in IDS:
        task = rc.Assignment(lesson, student)
        for exercise in registered(lesson):
            if not exercise.reveals(task.numbers):
                right = exercise.accepts(exercise.answer(task.numbers), task.numbers)
                missed = exercise.hidden_slips(task.numbers)
                hidden.append((student, exercise.number, right, missed))
    assert not hidden, hidden[:5]


@pytest.fixture(scope="module")
def weights():
    return read_weights(COURSE / "kit" / "weights.md")


@pytest.mark.parametrize("lesson", LESSONS)
def test_the_full_check_refuses_every_slip_and_the_rubric_credits_it(lesson, weights):
    """The notebook's check itself, with its diagnosis, on sampled ids: the right answer
    passes; every slip fails, and one the check names earns a quarter to three quarters
    of the points by the course's rubric (course/kit/weights.md)."""
    named, total, failures = 0, 0, []
    for student in SAMPLED:
        task = rc.Assignment(lesson, student)
        for exercise in registered(lesson):
            numbers = task.numbers
            if not exercise.accepts(exercise.answer(numbers), numbers, full=True):
                failures.append((student, exercise.number, "right answer refused"))
            points = weights.points_of(lesson, exercise.number)
            rubric = weights.rubric(lesson, exercise.number, points)
            for slip, answer in exercise.slips(numbers).items():
                result = exercise.check(_as_typed(answer), numbers)
                earned = award(result, rubric).score / points
                total += 1
                if result.ok:
                    failures.append((student, exercise.number, slip, "accepted"))
                elif names_a_slip(result.diagnosis):
                    named += 1
                    if not 0.25 <= earned <= 0.75:
                        failures.append((student, exercise.number, slip, earned))
                elif earned > 0.75:  # unnamed: what its right numbers earn, at most 3/4
                    failures.append((student, exercise.number, slip, earned))
    assert not failures, failures[:5]
    # the check names nearly every slip; the others are one IK solution of two (half by
    # the numbers), lesson 12's "no move" and "every move" (nothing)
    assert named >= 0.85 * total, (named, total)


def _as_typed(answer):
    """A slip's numbers as a student types them (plain floats, lists)."""
    if isinstance(answer, np.ndarray):
        return answer.tolist()
    return answer


def test_screening_redraws_a_draw_that_hides_a_slip():
    """Lesson 3's classic pose (90°, 0°, −90°) hides q2's sign; screening moves on."""
    exercise = registered("03_composing_a_chain")[0]
    robot = rc.Assignment("03_composing_a_chain", "demo")["robot"]
    classic = {"q_4": list(np.radians([90, 0, -90])), "robot": robot}
    assert "sign_error[q2]" in exercise.hidden_slips(classic)
    assert not exercise.reveals(classic)
    drawn = rc.Assignment("03_composing_a_chain", "demo")
    assert exercise.reveals(drawn.numbers)
