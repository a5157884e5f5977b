"""The closed forms over many targets at once.

:func:`ik_all_many` does for T targets what :func:`~robotconf.inverse_kinematics.ik_all`
does for one — the same families, branches, labels, forward-kinematics check, joint
limits and reasons — with numpy over the targets; it answers with
:class:`IKSolutionSets`, one table of rows for all targets (``sets[k]`` is target
``k``'s :class:`~robotconf.inverse_kinematics.IKSolutions`). The numeric solver takes its
closed-form starts from it (:mod:`robotconf.inverse_kinematics.numeric`).
"""

from ._many import ik_all_many
from ._sets import IKSolutionSets

__all__ = ["ik_all_many", "IKSolutionSets"]
