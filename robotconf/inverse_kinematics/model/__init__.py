"""One inverse-kinematics problem as the numeric solver sees it, for a batch of targets.

:func:`make_problem` builds a :class:`Problem` in the solver's scaled units from the
checked targets (:func:`check_targets`, :class:`Targets`; the other inputs have their
checks beside it), the robot folded into constant transforms between the moving joints
(:func:`compile_chain`, :class:`Chain`) and its reach shell (:func:`reach_shell`,
:class:`Reach`). :func:`rotation_vector_last` measures orientation errors;
:func:`generic_rank` says what the robot can move at all.
"""

from ._chain import Chain, compile_chain
from ._problem import Problem, make_problem
from ._reach import Reach, reach_shell
from ._rotation import rotation_vector_last
from ._structure import generic_rank
from ._targets import Targets, check_targets

__all__ = [
    "Problem",
    "make_problem",
    "Targets",
    "check_targets",
    "Chain",
    "compile_chain",
    "Reach",
    "reach_shell",
    "rotation_vector_last",
    "generic_rank",
]
