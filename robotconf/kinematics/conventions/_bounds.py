"""How large a robot's numbers may be, so that its kinematics never overflow.

Every number that describes a robot — module offsets ``a``, DH parameters ``θ, d, a, α``,
a link's stored coordinate ``q``, joint limits and the end-effector point — must satisfy
``|x| ≤`` :data:`MAX_PARAMETER` (``1e150``), and a robot has at most
:data:`MAX_MODULES` (64) links. Why these bounds:

* a frame position is a sum of at most 65 terms ``R · v`` with ``|R v| ≤ √3 · 1e150``, so
  no chain of constants can overflow (the limit of a float is about ``1.8e308``);
* squares stay finite too (``(1e150)² = 1e300``), so lengths ``|a|``, norms and the
  default prismatic stroke never overflow;
* ``θ + q`` of a revolute DH row stays finite for every finite ``q``, because ``1e150``
  is far below the spacing of floats near ``1e308``.

No real robot comes anywhere near these numbers, in any unit. Coordinates passed at run
time (``robot.frame_poses(q)``) need only be finite: a prismatic ``q`` near ``1e308`` can
still push a frame past the float range, and the kinematics kernel refuses that result,
naming the coordinate.
"""

from __future__ import annotations

from typing import Any

from ..._errors import InvalidInputError
from ..._validation import check_finite_number, check_vector3

__all__ = ["MAX_PARAMETER", "MAX_MODULES", "check_parameter", "check_parameter_vector"]

#: Largest magnitude of a link parameter, stored coordinate, joint limit or end-effector
#: coordinate (length units or radians).
MAX_PARAMETER = 1e150

#: Most links in one robot (the file format has the same limit).
MAX_MODULES = 64

_ALLOWED = f"a finite number with |x| ≤ {MAX_PARAMETER:.0e}"


def check_parameter(value: Any, field: str) -> float:
    """A finite real number with ``|value| ≤ MAX_PARAMETER``, as a Python float.

    Parameters
    ----------
    value : real number
        A length (length units) or an angle (radians).
    field : str
        Name used in the error message.

    Returns
    -------
    float

    Raises
    ------
    InvalidInputError
        For anything :func:`~robotconf._validation.check_finite_number` refuses, or a
        magnitude above :data:`MAX_PARAMETER`.

    Examples
    --------
    >>> check_parameter(20, "d")
    20.0
    >>> check_parameter(1e308, "d")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: d: too large (|x| > 1e+150): 1e+308; allowed: a finite ...
    """
    number = check_finite_number(value, field)
    if abs(number) > MAX_PARAMETER:
        raise InvalidInputError(
            field, number, _ALLOWED, problem=f"too large (|x| > {MAX_PARAMETER:.0e}):"
        )
    return number


def check_parameter_vector(value: Any, field: str) -> tuple[float, float, float]:
    """Three finite numbers with ``|x| ≤ MAX_PARAMETER`` each (an offset or a point).

    Examples
    --------
    >>> check_parameter_vector([0, 0, 20], "a")
    (0.0, 0.0, 20.0)
    >>> check_parameter_vector([1e308, 0, 0], "a")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: a: entry 0 is too large (|x| > 1e+150): (1e+308, 0.0, 0.0); ...
    """
    vector = check_vector3(value, field)
    for k, number in enumerate(vector):
        if abs(number) > MAX_PARAMETER:
            raise InvalidInputError(
                field,
                vector,
                f"3 numbers with |x| ≤ {MAX_PARAMETER:.0e}",
                problem=f"entry {k} is too large (|x| > {MAX_PARAMETER:.0e}):",
            )
    return vector
