"""Motion-profile answers: a trapezoid's times, a duration, peaks, coefficients, samples.

A :class:`ProfileTask` holds a rest-to-rest move as the exercise states it; the right
numbers come from the shared time laws (:mod:`robotconf.signals`), and the usual slips
(a triangle taken for a trapezoid, ``2v/a``, the ramps left out, a forgotten
synchronization, the cubic for the quintic, …) are rebuilt and named.

    :func:`check_profile`, :func:`assert_profile`, :class:`ProfileTask`,
    :data:`PROFILE_DIAGNOSES`, :data:`PROFILE_FORMS`

>>> ProfileTask(2.0, speed=1.0, accel=2.0).duration
2.5
"""

from ._check import assert_profile, check_profile
from ._forms import PROFILE_FORMS
from ._slips import PROFILE_DIAGNOSES
from ._task import ProfileTask

__all__ = ["check_profile", "assert_profile", "ProfileTask", "PROFILE_DIAGNOSES", "PROFILE_FORMS"]
