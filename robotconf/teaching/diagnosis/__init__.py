"""Diagnoses: why an answer is wrong, named once, in a sentence a student can act on.

Each usual mistake is rebuilt from the exercise (a module turned the wrong way, the
product in the wrong order, an offset forgotten, degrees for radians, a unit slip, …)
and compared with the student's answer by number; every explanation that fits is scored
and ranked, and the best one is the primary diagnosis. Answers that are numbers or
vectors are explained component by component (sign, swap, unit factor, rounding).

Candidates for matrices
    :class:`Candidate`, :func:`generic_candidates`, :func:`is_rotation_like`,
    :data:`ROTATION_PATTERN`
Slips of numbers and vectors
    :class:`Setting`, :func:`explain_components`, :func:`is_rounded`

>>> is_rounded(3.1, 3.14159)
True
"""

from ._components import Setting, explain_components, is_rounded
from ._mistakes import ROTATION_PATTERN, Candidate, generic_candidates, is_rotation_like

__all__ = [
    "Candidate",
    "generic_candidates",
    "is_rotation_like",
    "ROTATION_PATTERN",
    "Setting",
    "explain_components",
    "is_rounded",
]
