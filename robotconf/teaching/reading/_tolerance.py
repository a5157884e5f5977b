"""The course's rounding rule, said once: an answer with 3 significant digits is right.

Rounding a number to 3 significant digits moves it by at most half a unit of its third
digit: at most 0.5 % of the number (1.005 → 1.00 or 1.01). So every check accepts a
number within 0.5 % of the expected one, or within 0.001 of it near zero, unless an
exercise asks for more; an answer rounded further gets the rounding hint (keep 3
significant digits), never a bare "wrong". Matrices compare each entry the same way,
within ``0.005·max(0.2, |expected|)`` = ``max(0.001, 0.005·|expected|)`` (entries are
lengths and sines alike: :data:`SCALE_FLOOR`), and inverse
kinematics the end effector within 0.5 % of the robot's size (angles with 3 significant
digits reach it).

>>> abs(1.01 - 1.005) <= REL_TOL * 1.005, abs(0.00999 - 0.01) <= ABS_TOL
(True, True)
"""

from __future__ import annotations

__all__ = [
    "ABS_TOL",
    "KEEP_DIGITS",
    "REL_TOL",
    "ROUNDING_RULE",
    "SCALE_FLOOR",
    "SIGNIFICANT_DIGITS",
]

#: An answer with this many significant digits is right.
SIGNIFICANT_DIGITS = 3
#: The relative tolerance that accepts every number rounded to 3 significant digits.
REL_TOL = 0.005
#: The absolute tolerance near zero.
ABS_TOL = 0.001
#: Below this size a matrix entry is compared absolutely: ``tol·max(SCALE_FLOOR, |e|)``
#: is ``max(ABS_TOL, REL_TOL·|e|)`` at the default ``tol``.
SCALE_FLOOR = ABS_TOL / REL_TOL
#: The rule in words, as the course's how-to cells and the docs state it.
ROUNDING_RULE = "numbers with 3 significant digits pass (within 0.5 %, or 0.001 near 0)"
#: The advice for a number rounded too far.
KEEP_DIGITS = "keep 3 significant digits"
