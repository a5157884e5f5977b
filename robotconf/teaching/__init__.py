"""Teaching: step-by-step derivations, symbolic matrices and the homework checker.

sympy is imported inside the functions that need it, so importing this folder stays
numpy-only.

Derivations
    :func:`derivation`, :class:`Derivation`, :class:`DerivationStep`, :func:`format_number`
Symbolic chain (an independent second implementation of the matrices, in sympy)
    :func:`symbolic_chain`, :class:`SymbolicChain`, :func:`module_matrix`,
    :func:`elementary_matrix`, :func:`dh_factors`, :func:`exact_number`
Expected answers and the checker
    :func:`expected_matrix`, :class:`ExpectedMatrix`, :func:`check_matrix`,
    :func:`assert_matrix`, :class:`MatrixCheck` (codes: :data:`MATRIX_DIAGNOSES`).
    Answers are untrusted: the checker decides by numbers at seeded random points,
    refuses entries that are not real, and does algebra only within a small budget, so
    any answer is judged in ≤ 2 s for a 4×4 matrix (see :func:`check_matrix`, Notes).
Answers that are not matrices (same parser and numeric judge; 3 significant digits pass)
    :func:`check_value`, :func:`check_vector`, :func:`check_angle`, :func:`check_set`,
    :func:`check_interval`, their ``assert_*`` forms (:func:`assert_value`,
    :func:`assert_vector`, :func:`assert_angle`, :func:`assert_set`,
    :func:`assert_interval`) and :class:`AnswerCheck`.
Inverse-kinematics answers (judged by forward kinematics: any solution passes)
    :func:`check_ik_solution`, :func:`check_ik_solutions`, :func:`assert_ik_solution`,
    :func:`assert_ik_solutions`, :class:`IKCheck`
Motion-profile answers (a trapezoid's times, a duration, peaks, coefficients, samples)
    :func:`check_profile`, :func:`assert_profile`, :class:`ProfileTask`,
    :data:`PROFILE_DIAGNOSES`, :data:`PROFILE_FORMS`
DH tables (judged by the robot they describe: joint axes and end-effector at seeded q)
    :func:`check_dh_table`, :func:`assert_dh_table`, :class:`DHTableCheck`,
    :func:`parse_dh_rows`
Per-student exercise parameters (the same id gives the same numbers on every machine)
    :class:`Variant`; the course's exercises with them, screened so that every typical
    slip gives a refused answer: :class:`Assignment` (:mod:`.exercises`); quizzes and
    exams drawn per student from them: :class:`Exam`;
    :data:`EXERCISE_SLIPS`
Student text (a whitelist parser: nothing is evaluated)
    :func:`parse_expression`, :func:`parse_matrix`, :class:`ParserLimits`

>>> format_number(0.30000000000000004)
'0.3'
"""

from .checks import (
    DH_DIAGNOSES,
    DIAGNOSES,
    MATRIX_DIAGNOSES,
    AnswerCheck,
    DHTableCheck,
    MatrixCheck,
    assert_angle,
    assert_dh_table,
    assert_interval,
    assert_matrix,
    assert_set,
    assert_value,
    assert_vector,
    check_angle,
    check_dh_table,
    check_interval,
    check_matrix,
    check_set,
    check_value,
    check_vector,
    parse_dh_rows,
)
from .derivation import (
    SYMBOLIC_TOO_LONG,
    Derivation,
    DerivationStep,
    ExpectedMatrix,
    SymbolicChain,
    as_expected,
    derivation,
    dh_factors,
    elementary_matrix,
    evaluate,
    exact_number,
    expected_matrix,
    format_number,
    latex_text,
    link_factors,
    matrix_grid,
    matrix_latex,
    module_matrix,
    sample_points,
    simplify_matrix,
    sine_entries,
    symbolic_chain,
    symbolic_fits,
)
from .diagnosis import ROTATION_PATTERN, Candidate, generic_candidates, is_rotation_like
from .exercises import EXERCISE_SLIPS, Assignment, Exam
from .ik_answers import (
    IK_DIAGNOSES,
    IKCheck,
    assert_ik_solution,
    assert_ik_solutions,
    check_ik_solution,
    check_ik_solutions,
)
from .profiles import PROFILE_DIAGNOSES, PROFILE_FORMS, ProfileTask, assert_profile, check_profile
from .reading import DEFAULT_SYMBOL_NAMES, ParserLimits, parse_expression, parse_matrix
from .variants import Variant

__all__ = [
    # derivations
    "derivation",
    "Derivation",
    "DerivationStep",
    "format_number",
    "latex_text",
    "matrix_grid",
    "matrix_latex",
    # symbolic chain
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
    "SYMBOLIC_TOO_LONG",
    # expected answers and the checker
    "expected_matrix",
    "ExpectedMatrix",
    "as_expected",
    "evaluate",
    "sample_points",
    "check_matrix",
    "assert_matrix",
    "MatrixCheck",
    # answers that are not matrices
    "check_value",
    "check_vector",
    "check_angle",
    "check_set",
    "check_interval",
    "assert_value",
    "assert_vector",
    "assert_angle",
    "assert_set",
    "assert_interval",
    "AnswerCheck",
    "DIAGNOSES",
    "MATRIX_DIAGNOSES",
    "DH_DIAGNOSES",
    "Candidate",
    "generic_candidates",
    "is_rotation_like",
    "ROTATION_PATTERN",
    # inverse-kinematics answers
    "check_ik_solution",
    "check_ik_solutions",
    "assert_ik_solution",
    "assert_ik_solutions",
    "IKCheck",
    "IK_DIAGNOSES",
    # motion-profile answers
    "check_profile",
    "assert_profile",
    "ProfileTask",
    "PROFILE_DIAGNOSES",
    "PROFILE_FORMS",
    # DH tables
    "check_dh_table",
    "assert_dh_table",
    "DHTableCheck",
    "parse_dh_rows",
    # per-student variants, and the course's exercises with them
    "Variant",
    "Assignment",
    "Exam",
    "EXERCISE_SLIPS",
    # student text
    "parse_expression",
    "parse_matrix",
    "ParserLimits",
    "DEFAULT_SYMBOL_NAMES",
]
