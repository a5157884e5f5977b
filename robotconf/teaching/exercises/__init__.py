"""Course exercises with per-student numbers: drawn, screened, checked.

An exercise whose numbers come from the student id is written once: how its numbers are
drawn (the same names and ranges as the notebook showed before), the right answer, the
check the notebook runs, and the answers its typical single slips give. Its numbers are
**screened**: a draw with which a typical slip would pass is drawn again, so every
student's numbers reveal every slip (``Variant.screened``). A check names the
exercise's own slips ("the largest move sets the time") beside the checker's.

In a notebook
    :class:`Assignment` (``task = rc.Assignment(lesson, student_id)``; ``task["d1"]``,
    ``task.assert_answer(1, answer_1)``, ``task.shows(1)``); :class:`Exam` (quizzes and
    exams: one exercise per slot drawn per student, with its numbers)
The registry
    :class:`Exercise`, :func:`registered`, :data:`EXERCISE_SLIPS`
Mistake models
    :func:`configuration_slips`, :func:`matrix_slips`, :func:`component_slips`,
    :func:`dh_table_slips`

>>> [e.number for e in registered("11_inverse_kinematics")]
[1, 2, 3, 4, 5, 6, 7]
"""

from . import _lesson_09, _lesson_10, _lesson_11, _lesson_12, _lesson_13, _lessons_02_08
from ._exam import Exam
from ._exercise import Assignment, Exercise, registered
from ._kinds import EXERCISE_SLIPS
from ._mistake_models import component_slips, configuration_slips, dh_table_slips, matrix_slips

# registered on import
del _lesson_09, _lesson_10, _lesson_11, _lesson_12, _lesson_13, _lessons_02_08

__all__ = [
    "Assignment",
    "Exam",
    "Exercise",
    "registered",
    "EXERCISE_SLIPS",
    "configuration_slips",
    "matrix_slips",
    "component_slips",
    "dh_table_slips",
]
