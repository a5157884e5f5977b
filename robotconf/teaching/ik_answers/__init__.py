"""Inverse-kinematics answers: any joint values that reach the target pass.

An IK exercise has many right answers (elbow up and down, any angle plus whole turns),
so an answer goes through the robot's forward kinematics and is compared with the
target; only a wrong answer is compared with the closed-form solutions, to name the
slip (atan for atan2, the cosine-law sign, degrees, a swapped target, the lost second
solution).

    :func:`check_ik_solution`, :func:`check_ik_solutions`, :func:`assert_ik_solution`,
    :func:`assert_ik_solutions`, :class:`IKCheck`, :data:`IK_DIAGNOSES`

>>> sorted(IK_DIAGNOSES)[:2]
['atan_quadrant', 'cosine_law_sign']
"""

from ._check import assert_ik_solution, check_ik_solution
from ._result import IK_DIAGNOSES, IKCheck
from ._sets import assert_ik_solutions, check_ik_solutions

__all__ = [
    "check_ik_solution",
    "check_ik_solutions",
    "assert_ik_solution",
    "assert_ik_solutions",
    "IKCheck",
    "IK_DIAGNOSES",
]
