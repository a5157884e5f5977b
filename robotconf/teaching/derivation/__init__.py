"""Derivations: the forward kinematics step by step, numerically and in sympy.

The paper validated its numbers with a second tool; this folder shows the same chain of
matrices in a notebook and derives the expected answers the checker compares with.

Step by step
    :func:`derivation`, :class:`Derivation`, :class:`DerivationStep`; text and LaTeX
    helpers :func:`format_number`, :func:`latex_text`, :func:`matrix_grid`,
    :func:`matrix_latex`
Symbolic chain (an independent second implementation of the matrices, in sympy)
    :func:`symbolic_chain`, :class:`SymbolicChain`, :func:`module_matrix`,
    :func:`elementary_matrix`, :func:`dh_factors`, :func:`link_factors`,
    :func:`exact_number`, :func:`sine_entries`, :func:`simplify_matrix`
What the symbolic derivation costs
    :func:`symbolic_fits`, :func:`symbolic_cost`, :data:`SYMBOLIC_COST_LIMIT`,
    :data:`SYMBOLIC_TOO_LONG` (why a longer chain is refused)
Expected answers (an exercise's matrix, with the context the diagnoses read)
    :func:`expected_matrix`, :class:`ExpectedMatrix`, :func:`as_expected`,
    :func:`evaluate`, :func:`sample_points`

>>> format_number(0.30000000000000004)
'0.3'
"""

from ._derivation import Derivation, derivation
from ._expected import ExpectedMatrix, as_expected, evaluate, expected_matrix, sample_points
from ._formatting import format_number, latex_text, matrix_grid, matrix_latex
from ._step import DerivationStep
from ._symbolic import (
    dh_factors,
    elementary_matrix,
    exact_number,
    link_factors,
    module_matrix,
    sine_entries,
)
from ._symbolic_chain import SymbolicChain, simplify_matrix, symbolic_chain
from ._symbolic_limits import SYMBOLIC_COST_LIMIT, SYMBOLIC_TOO_LONG, symbolic_cost, symbolic_fits

__all__ = [
    "derivation",
    "Derivation",
    "DerivationStep",
    "format_number",
    "latex_text",
    "matrix_grid",
    "matrix_latex",
    "symbolic_chain",
    "SymbolicChain",
    "module_matrix",
    "elementary_matrix",
    "dh_factors",
    "link_factors",
    "simplify_matrix",
    "exact_number",
    "sine_entries",
    "symbolic_fits",
    "symbolic_cost",
    "SYMBOLIC_COST_LIMIT",
    "SYMBOLIC_TOO_LONG",
    "expected_matrix",
    "ExpectedMatrix",
    "as_expected",
    "evaluate",
    "sample_points",
]
