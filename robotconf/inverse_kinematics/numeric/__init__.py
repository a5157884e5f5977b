"""The numeric solver :func:`ik`: starts, damped least squares, and a reason per target.

:func:`ik` runs the damped least squares of a :mod:`robotconf.inverse_kinematics.model`
problem from several starts per target — ``q0``, the closed-form solutions of a
recognized arm (:func:`closed_form_starts`), random ones — scheduled in waves
(:func:`search`), and answers with :class:`IKResult`: the joint values and why it stopped.
"""

from ._ik import ik
from ._result import IKResult
from ._search import search
from ._starts import closed_form_starts

__all__ = ["ik", "IKResult", "search", "closed_form_starts"]
