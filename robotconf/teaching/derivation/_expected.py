"""The reference side of a homework check: an expected matrix and what it is of.

A bare matrix only allows context-free hints (a transposed block, a swapped row). An
:class:`ExpectedMatrix` also knows *which* robot, *which* matrix (``A2``, ``M3``,
``p_EE``) and at which configuration, so the checker can rebuild the usual mistakes
(wrong multiplication order, the other DH convention, degrees, …) and recognise them.

This module also samples random points and evaluates sympy expressions there (a numpy
walk of the expression tree, no code generation: see
:mod:`robotconf.teaching.reading._numeric_eval`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from ..._errors import InvalidInputError
from ._step import step_name

if TYPE_CHECKING:  # pragma: no cover
    import sympy

    from ...kinematics import Robot

__all__ = [
    "ExpectedMatrix",
    "expected_matrix",
    "as_expected",
    "evaluate",
    "sample_points",
]


@dataclass(frozen=True, eq=False)
class ExpectedMatrix:
    """A reference matrix with the context it came from.

    Attributes
    ----------
    matrix : sympy.Matrix
        The expected value, exact where possible; shape (4, 4), or (4, 1) for ``p_EE``.
    name : str or None
        ``"A<i>"``, ``"M<i>"`` or ``"p_EE"``; ``None`` for a bare matrix.
    robot : Robot or None
    q : tuple of float or None
        The configuration (radians / length) when the matrix is numeric in ``q``;
        ``None`` when ``q1 … qn`` are symbols.
    lengths : bool
        Whether lengths are the symbols ``l1, l2, …``.
    """

    matrix: Any
    name: str | None = None
    robot: Robot | None = None
    q: tuple[float, ...] | None = None
    lengths: bool = False

    @property
    def index(self) -> int | None:
        """Module number of ``A<i>``/``M<i>`` (1-based), ``n`` for ``p_EE``."""
        if self.name is None or self.robot is None:
            return None
        return self.robot.n if self.name == "p_EE" else int(self.name[1:])

    @property
    def has_context(self) -> bool:
        """Whether robot and matrix name are known (context-aware hints possible)."""
        return self.robot is not None and self.name is not None

    def symbol_names(self) -> list[str]:
        """Names a student may use: the robot's ``q``/``l`` symbols, else the matrix's."""
        names = [s.name for s in self.matrix.free_symbols]
        if self.robot is not None:
            names = list(self.robot.coordinate_names) + names
        return list(dict.fromkeys(sorted(names, key=_name_order)))


def _name_order(name: str) -> tuple[str, int, str]:
    stem = name.rstrip("0123456789")
    number = name[len(stem) :]
    return (stem, int(number) if number else 0, name)


def expected_matrix(
    robot: Robot, name: str, q: Any = None, lengths: bool = False
) -> ExpectedMatrix:
    """The reference for one matrix of a robot's derivation, with its context.

    Parameters
    ----------
    robot : Robot
    name : str
        ``"A<i>"`` (transfer matrix of module i), ``"M<i>"`` (``A1·…·Ai``) or ``"p_EE"``
        (``M_n·[Px, Py, Pz, 1]ᵀ``); 1-based as in the paper.
    q : array-like, shape (n,), optional
        Configuration (radians / length). Default: the symbols ``q1 … qn``.
    lengths : bool
        Lengths as the symbols ``l1, l2, …`` (as in :func:`~robotconf.teaching.derivation`).

    Returns
    -------
    ExpectedMatrix

    Examples
    --------
    >>> from robotconf import Module, Robot
    >>> robot = Robot([Module("Rz"), Module("Ry", a=(0, 0, 20))], end_effector=(40, 0, 0))
    >>> expected_matrix(robot, "A2").matrix[2, :]
    Matrix([[-sin(q2), 0, cos(q2), 20]])
    >>> expected_matrix(robot, "p_EE", q=[0, 0]).matrix.T
    Matrix([[40, 0, 20, 1]])
    """
    from ._derivation import derivation

    key = step_name(robot, name)
    steps = derivation(robot, q=q, symbolic=True, lengths=lengths, simplify=False)
    return as_expected(steps[key])


def as_expected(reference: Any) -> ExpectedMatrix:
    """Turn a reference (ExpectedMatrix, derivation step, sympy Matrix, array) into one.

    Parameters
    ----------
    reference : ExpectedMatrix, DerivationStep, sympy.Matrix, array-like or scalar
        A derivation step keeps its context; a bare matrix has none; a number or a
        sympy expression is a 1×1 matrix.

    Returns
    -------
    ExpectedMatrix

    Raises
    ------
    InvalidInputError
        For text, ragged or non-finite arrays.
    """
    import sympy

    from ._derivation import DerivationStep
    from ._symbolic import exact_number

    if isinstance(reference, ExpectedMatrix):
        return reference
    if isinstance(reference, DerivationStep):
        matrix = reference.matrix
        if not reference.symbolic:
            matrix = sympy.Matrix(np.asarray(matrix, dtype=float).tolist()).applyfunc(exact_number)
        return ExpectedMatrix(
            matrix, reference.name, reference.robot, reference.q, reference.lengths
        )
    if isinstance(reference, sympy.MatrixBase):
        return ExpectedMatrix(sympy.Matrix(reference))
    if isinstance(reference, sympy.Expr):  # a scalar: a 1×1 matrix
        return ExpectedMatrix(sympy.Matrix([[reference]]))
    if isinstance(reference, (str, bytes)):
        raise InvalidInputError(
            "expected",
            reference,
            "a matrix (array, sympy Matrix) or rc.expected_matrix(...)",
            problem="text is not accepted as the reference:",
        )
    try:
        array = np.asarray(reference, dtype=float)
    except (TypeError, ValueError):
        raise InvalidInputError(
            "expected",
            reference,
            "a numeric matrix, a sympy Matrix or rc.expected_matrix(...)",
            problem="not a matrix:",
        ) from None
    if array.ndim == 0:  # a scalar: a 1×1 matrix
        array = array.reshape(1, 1)
    if array.ndim == 1:
        array = array[:, np.newaxis]
    if array.ndim != 2 or array.size == 0 or not np.all(np.isfinite(array)):
        raise InvalidInputError(
            "expected",
            reference,
            "a finite 2-D matrix or a vector",
            problem=f"shape {array.shape} or non-finite entries:",
        )
    return ExpectedMatrix(sympy.Matrix(array.tolist()).applyfunc(exact_number))


def sample_points(names: list[str], samples: int, seed: int) -> dict[str, np.ndarray]:
    """Random values for symbols: angles in ±3 rad for ``q…``, 0.5–2.5 for the rest.

    Parameters
    ----------
    names : list of str
    samples : int
        Number of points K.
    seed : int

    Returns
    -------
    dict of str to ndarray, shape (K,)
    """
    rng = np.random.default_rng(seed)
    points = {}
    for name in names:
        if name.startswith("q"):
            points[name] = rng.uniform(-3.0, 3.0, samples)
        else:
            points[name] = rng.uniform(0.5, 2.5, samples)
    return points


def evaluate(expr: sympy.Expr, env: dict[str, np.ndarray], samples: int) -> np.ndarray:
    """Evaluate a sympy expression at K points by walking its tree with numpy.

    Parameters
    ----------
    expr : sympy.Expr
    env : dict of str to ndarray, shape (K,)
        Values of the symbols by name.
    samples : int
        K.

    Returns
    -------
    ndarray, shape (K,)
        ``nan`` where the expression is undefined or not real (e.g. ``sqrt`` of a
        negative number).

    Examples
    --------
    >>> import sympy
    >>> q1 = sympy.Symbol("q1", real=True)
    >>> evaluate(2 * sympy.cos(q1), {"q1": np.array([0.0, np.pi])}, 2)
    array([ 2., -2.])
    """
    from ..reading._numeric_eval import complex_values, real_or_nan

    return real_or_nan(complex_values(expr, env, samples))
