"""Inverse kinematics: find joint values that put the end effector on a target.

The numeric solver :func:`ik` works for every robot (damped least squares on the
geometric Jacobian, vectorized over many targets) and always says why it stopped.

The closed forms :func:`ik_all` list every solution of the classic arms (planar 2R/3R,
SCARA, 3R elbow, spherical-wrist 6R, UR) as :class:`IKSolutions`; :func:`recognize` names
the family from the robot's joint axes. :func:`ik_all_many` lists them for many targets
at once (vectorized over the targets) as :class:`IKSolutionSets`.

The folder, one concept per subfolder (each imports only those above it in this table,
and the kinematics' public face):

================  ==========================================================================
subfolder         what it holds
================  ==========================================================================
``geometry/``     the robot as its joint lines at q = 0 (``_chain_axes``) and the
                  Paden–Kahan subproblems every closed form is made of (``_subproblems``)
``closed_form/``  :func:`ik_all` (``_ik_all``: target, wrap, check, limits), the family read
                  from the joint lines (``_recognize``), the answer (``_solutions``), and one
                  solver per family (``_planar``, ``_elbow``, ``_spherical_wrist``, ``_ur``)
``batch/``        :func:`ik_all_many`: the same closed forms over T targets at once
                  (targets, subproblems, families, the check and :class:`IKSolutionSets`)
``model/``        the problem in the numeric solver's units: its checked inputs
                  (``_targets``), the compiled chain (``_chain``), the reach shell
                  (``_reach``), the scaled problem (``_problem``), the rotation vector
                  (``_rotation``) and the Jacobian's generic rank (``_structure``)
``numeric/``      :func:`ik` (``_ik``): the starts (``_starts`` from the closed forms,
                  ``_search`` in waves), damped least squares (``_lm``), the closest
                  configuration (``_closest``), the reasons in words (``_reasons``) and the
                  answer :class:`IKResult` (``_result``)
================  ==========================================================================
"""

from __future__ import annotations

from .batch import IKSolutionSets, ik_all_many
from .closed_form import IKSolutions, ik_all, recognize
from .numeric import IKResult, ik

__all__ = ["IKResult", "ik", "IKSolutions", "ik_all", "IKSolutionSets", "ik_all_many", "recognize"]
