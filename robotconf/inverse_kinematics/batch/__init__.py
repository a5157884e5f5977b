"""The closed forms over many targets at once, and what the numeric solver takes from them.

:func:`ik_all_many` does for T targets what :func:`~robotconf.inverse_kinematics.ik_all`
does for one — the same families, branches, labels, forward-kinematics check, joint
limits and reasons — with numpy over the targets; it answers with
:class:`IKSolutionSets`, one table of rows for all targets (``sets[k]`` is target
``k``'s :class:`~robotconf.inverse_kinematics.IKSolutions`).

:func:`closed_form_starts` gives :func:`~robotconf.inverse_kinematics.ik` the closed-form
solutions of a recognized arm as starts, nearest the first start first.
"""

from ._many import ik_all_many
from ._sets import IKSolutionSets
from ._starts import closed_form_starts

__all__ = ["ik_all_many", "IKSolutionSets", "closed_form_starts"]
