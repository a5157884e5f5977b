"""Symbolic transfer matrices with sympy: modules, DH links and whole robots.

This is a second, independent implementation of the kinematics: every matrix is written
from the module table (docs/conventions.md, Modules) or from the DH factor products (paper
eq. 9–10), not from the numpy kernel, so the two can check each other. Only the naming
comes from :mod:`robotconf.kinematics` (movement types, axes, the order of the DH factors).
Symbols are real:
``q1 … qn`` for the generalized coordinates and, on request, ``l1, l2, …`` for the
non-zero lengths in the order they appear along the chain (for the paper's R_zR_yR_y
robot this gives its ``l1 = 20``, ``l2 = 30``, ``l3 = 40``).

sympy is imported inside the functions, so ``import robotconf`` stays numpy-only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from .._errors import InvalidInputError
from .._validation import check_configuration
from ..kinematics import (
    AXIS_NAMES,
    DH_FACTORS,
    DH_JOINT_PARAMETER,
    MODULE_OFFSETS,
    ROTATION_KINDS,
    TRANSLATION_KINDS,
    DHLink,
    Link,
    Module,
    check_convention,
    kind_axis,
)

if TYPE_CHECKING:  # pragma: no cover
    import sympy

    from ..kinematics import Robot

__all__ = [
    "exact_number",
    "elementary_matrix",
    "module_matrix",
    "dh_factors",
    "link_factors",
    "simplify_matrix",
    "SymbolicChain",
    "symbolic_chain",
    "sine_entries",
    "dh_values",
]


def exact_number(value: Any, max_denominator: int = 1000) -> sympy.Expr:
    """A float as an exact sympy number when it plainly is one.

    Integers stay integers (``20.0 → 20``), short decimals and simple fractions become
    rationals (``0.4318 → 2159/5000``, ``1/3``) and rational multiples of π become
    ``k·pi`` (``1.5707963… → pi/2``), each only when the float is the nearest double to
    that exact value. Anything else is kept as a sympy ``Float``.

    Parameters
    ----------
    value : float
        A finite real number.
    max_denominator : int
        Largest denominator tried for fractions and fractions of π.

    Returns
    -------
    sympy.Expr

    Examples
    --------
    >>> import numpy as np
    >>> exact_number(20.0), exact_number(0.25), exact_number(np.pi / 2), exact_number(0.1234567)
    (20, 1/4, pi/2, 0.123456700000000)
    """
    import sympy

    x = float(value)
    if not math.isfinite(x):
        raise InvalidInputError("value", x, "a finite real number", problem="must be finite, got")
    if x == int(x) and abs(x) < 2**53:
        return sympy.Integer(int(x))
    text = repr(x)
    if "e" not in text and len(text.partition(".")[2]) <= 6:  # a short decimal: 0.4318
        decimal = Fraction(text)
        return sympy.Rational(decimal.numerator, decimal.denominator)
    fraction = Fraction(x).limit_denominator(max_denominator)
    if float(fraction) == x:
        return sympy.Rational(fraction.numerator, fraction.denominator)
    turns = Fraction(x / math.pi).limit_denominator(48)
    if turns != 0 and float(turns) * math.pi == x:
        return sympy.Rational(turns.numerator, turns.denominator) * sympy.pi
    return sympy.Float(x)


def sine_entries(axis: int) -> tuple[tuple[int, int], tuple[int, int]]:
    """Where the sines sit in the elementary rotation about an axis (0-based entries).

    Rotating about axis ``k`` turns axis ``i = k+1`` towards ``j = k+2`` (mod 3), so
    ``−sin`` is entry ``(i, j)`` and ``+sin`` entry ``(j, i)``.

    Parameters
    ----------
    axis : int
        0 (x), 1 (y) or 2 (z).

    Returns
    -------
    (minus, plus) : two (row, column) pairs

    Examples
    --------
    >>> sine_entries(1)  # Ry: −sin in row 3, column 1; +sin in row 1, column 3
    ((2, 0), (0, 2))
    """
    i, j = (axis + 1) % 3, (axis + 2) % 3
    return (i, j), (j, i)


def elementary_matrix(kind: str, value: Any) -> sympy.Matrix:
    """Elementary 4×4 rotation or translation about/along a principal axis.

    Part of the independent second implementation, in sympy, of the module table; tests
    compare the two.

    Parameters
    ----------
    kind : {"Rx", "Ry", "Rz", "Tx", "Ty", "Tz"}
        Rotation (radians) or translation (length) and its axis.
    value : sympy expression or number
        The angle or the distance.

    Returns
    -------
    sympy.Matrix, shape (4, 4)

    Examples
    --------
    >>> import sympy
    >>> elementary_matrix("Rz", sympy.Symbol("t"))[:2, :2]
    Matrix([
    [cos(t), -sin(t)],
    [sin(t),  cos(t)]])
    >>> elementary_matrix("Tx", 3)[:, 3].T
    Matrix([[3, 0, 0, 1]])
    """
    import sympy

    kinds = (*ROTATION_KINDS, *TRANSLATION_KINDS)
    if kind not in kinds:
        raise InvalidInputError("kind", kind, ", ".join(kinds[:-1]) + f" or {kinds[-1]}")
    matrix = sympy.eye(4)
    k = kind_axis(kind)
    assert k is not None  # every rotation and translation has an axis
    if kind in TRANSLATION_KINDS:
        matrix[k, 3] = value
        return matrix
    c, s = sympy.cos(value), sympy.sin(value)
    (i, j), _ = sine_entries(k)
    matrix[i, i] = c
    matrix[j, j] = c
    matrix[j, i] = s
    matrix[i, j] = -s
    return matrix


def module_matrix(kind: str, q: Any, a: Any) -> sympy.Matrix:
    """A module's transfer matrix ``A(q, a)``, written out from the module table.

    An independent second implementation, in sympy, of the module table
    (docs/conventions.md, Modules); tests compare the two.

    Parameters
    ----------
    kind : {"none", "Rx", "Ry", "Rz", "Tx", "Ty", "Tz", "fixed"}
        Movement type (canonical name).
    q : sympy expression or number
        Generalized coordinate (radians or length).
    a : sequence of 3 sympy expressions or numbers
        Offsets ``(ax, ay, az)`` (length).

    Returns
    -------
    sympy.Matrix, shape (4, 4)

    Examples
    --------
    >>> import sympy
    >>> q2, l1 = sympy.symbols("q2 l1", real=True)
    >>> module_matrix("Ry", q2, (0, 0, l1))  # paper eq. 18
    Matrix([
    [ cos(q2), 0, sin(q2),  0],
    [       0, 1,       0,  0],
    [-sin(q2), 0, cos(q2), l1],
    [       0, 0,       0,  1]])
    """
    import sympy

    ax, ay, az = a
    c, s = sympy.cos(q), sympy.sin(q)
    table = {
        "none": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]],
        "fixed": [[1, 0, 0, ax], [0, 1, 0, ay], [0, 0, 1, az]],
        "Rx": [[1, 0, 0, ax], [0, c, -s, ay], [0, s, c, az]],
        "Ry": [[c, 0, s, ax], [0, 1, 0, ay], [-s, 0, c, az]],
        "Rz": [[c, -s, 0, ax], [s, c, 0, ay], [0, 0, 1, az]],
        "Tx": [[1, 0, 0, q + ax], [0, 1, 0, ay], [0, 0, 1, az]],
        "Ty": [[1, 0, 0, ax], [0, 1, 0, q + ay], [0, 0, 1, az]],
        "Tz": [[1, 0, 0, ax], [0, 1, 0, ay], [0, 0, 1, q + az]],
    }
    if kind not in table:
        raise InvalidInputError("kind", kind, ", ".join(table), problem="unknown movement type")
    return sympy.Matrix([*table[kind], [0, 0, 0, 1]])


def dh_factors(
    theta: Any, d: Any, a: Any, alpha: Any, convention: str = "standard"
) -> list[tuple[str, sympy.Matrix]]:
    """The four elementary factors of a DH transfer matrix, in multiplication order.

    The order is the convention's (:data:`~robotconf.kinematics.DH_FACTORS`); each factor
    is an :func:`elementary_matrix`.

    Parameters
    ----------
    theta, d, a, alpha : sympy expressions or numbers
        Joint angle (radians, q already added for revolute joints), offset (length, q
        already added for prismatic joints), length, twist (radians).
    convention : {"standard", "modified"}
        ``standard``: ``Rz(θ)·Tz(d)·Tx(a)·Rx(α)``; ``modified`` (Craig):
        ``Rx(α)·Tx(a)·Rz(θ)·Tz(d)``.

    Returns
    -------
    list of (str, sympy.Matrix)
        ``("Rz", Rz(θ))``, ``("Tz", …)``, … ; their product is the link's matrix.

    Examples
    --------
    >>> [name for name, _ in dh_factors(0, 1, 2, 0, "modified")]
    ['Rx', 'Tx', 'Rz', 'Tz']
    """
    values = {"theta": theta, "d": d, "a": a, "alpha": alpha}
    order = DH_FACTORS[check_convention(convention)]
    return [(kind, elementary_matrix(kind, values[name])) for kind, name in order]


def dh_values(link: DHLink, parameters: dict[str, Any], q: Any) -> dict[str, Any]:
    """A DH row's four parameters with its coordinate added (θ0 + q or d0 + q).

    Works on numbers and on sympy expressions alike.

    Parameters
    ----------
    link : DHLink
        Gives the joint type.
    parameters : dict
        ``theta``, ``d``, ``a``, ``alpha`` (radians, length units).
    q : number or sympy expression
        The joint coordinate.

    Returns
    -------
    dict

    Examples
    --------
    >>> dh_values(DHLink(joint="P"), {"theta": 0.0, "d": 1.0, "a": 2.0, "alpha": 0.0}, 0.5)
    {'theta': 0.0, 'd': 1.5, 'a': 2.0, 'alpha': 0.0}
    """
    values = dict(parameters)
    key = DH_JOINT_PARAMETER[link.joint_type]
    values[key] = values[key] + q
    return values


def link_factors(
    link: Link, q: Any, lengths: dict[str, Any] | None = None
) -> tuple[list[tuple[str, sympy.Matrix]], sympy.Matrix]:
    """Factors and matrix of one link with coordinate ``q``.

    Parameters
    ----------
    link : Module or DHLink
    q : sympy expression or number
        Generalized coordinate.
    lengths : dict, optional
        Replacements for lengths by parameter name (``"ax"``, ``"ay"``, ``"az"`` of a
        module, ``"d"``, ``"a"`` of a DH row); missing ones use the link's exact numbers.

    Returns
    -------
    factors : list of (str, sympy.Matrix)
        Elementary factors with labels such as ``"Rz(q1)"``; empty for a module, whose
        matrix comes straight from the table.
    matrix : sympy.Matrix, shape (4, 4)
        The link's transfer matrix (product of the factors, unsimplified).

    Examples
    --------
    >>> import sympy
    >>> factors, matrix = link_factors(DHLink(a=1.0), sympy.Symbol("q1", real=True))
    >>> [label for label, _ in factors], matrix[0, 3]
    (['Rz(q1)', 'Tz(0)', 'Tx(1)', 'Rx(0)'], cos(q1))
    """
    import sympy

    lengths = lengths or {}
    values = {
        name: lengths.get(name, exact_number(value)) for name, value in link.parameters().items()
    }
    # The module table and the DH factor product are two different constructions.
    if isinstance(link, Module):
        return [], module_matrix(link.kind, q, [values[name] for name in MODULE_OFFSETS])
    if isinstance(link, DHLink):
        values = dh_values(link, values, q)
        factors = dh_factors(**values, convention=link.convention)
        order = DH_FACTORS[link.convention]
        labelled = [
            (f"{kind}({sympy.sstr(values[name])})", matrix)
            for (kind, name), (_, matrix) in zip(order, factors, strict=True)
        ]
        product = sympy.eye(4)
        for _, matrix in factors:
            product = product * matrix
        return labelled, product
    raise InvalidInputError("link", link, "a Module or DHLink", problem="unknown link type")


def _simplify_entry(expr: sympy.Expr) -> sympy.Expr:
    import sympy
    from sympy.simplify.fu import TR10i

    if expr.is_number:
        return expr
    expanded = sympy.expand(expr)
    if not expanded.has(sympy.sin, sympy.cos):
        return expanded
    # TR10i folds cos(a)cos(b) − sin(a)sin(b) into cos(a + b) (and the like): the one
    # identity forward kinematics needs, and far faster than a general trigsimp.
    return sympy.factor_terms(TR10i(expanded))


def simplify_matrix(matrix: sympy.Matrix) -> sympy.Matrix:
    """Entry-wise trigonometric simplification (``cos(q1)*cos(q2 + q3)``-style).

    Each entry is expanded, products of sines and cosines are folded into functions of
    sums of angles, and common factors are pulled out.

    Parameters
    ----------
    matrix : sympy.Matrix

    Returns
    -------
    sympy.Matrix
        Same shape.

    Examples
    --------
    >>> import sympy
    >>> a, b = sympy.symbols("a b", real=True)
    >>> simplify_matrix(sympy.Matrix([[sympy.cos(a) * sympy.cos(b) - sympy.sin(a) * sympy.sin(b)]]))
    Matrix([[cos(a + b)]])
    """
    return matrix.applyfunc(_simplify_entry)


@dataclass
class SymbolicChain:
    """Symbolic kinematics of one robot; built by :func:`symbolic_chain`.

    Attributes
    ----------
    robot : Robot
    q : list of sympy.Expr, length n
        The coordinates used: symbols ``q1 … qn`` or exact numbers.
    q_symbols : list of sympy.Symbol, length n
        The symbols ``q1 … qn`` (always; ``q`` may hold numbers instead).
    lengths : dict
        ``{symbol: exact value}`` for the length symbols (empty unless asked for).
    length_places : list of (str, str, sympy.Symbol)
        Where each length symbol stands: ``("M2", "az", l1)``; ``"EE"`` for the point.
    factors : list of list of (str, sympy.Matrix)
        Elementary factors of each DH link (empty for modules).
    transfer : list of sympy.Matrix, shape (4, 4)
        ``A_1 … A_n`` (identity for inactive modules).
    point : sympy.Matrix, shape (4, 1)
        ``[Px, Py, Pz, 1]ᵀ``.
    """

    robot: Robot
    q: list[Any]
    q_symbols: list[Any]
    lengths: dict[Any, Any]
    length_places: list[tuple[str, str, Any]]
    factors: list[list[tuple[str, Any]]]
    transfer: list[Any]
    point: Any
    simplify: bool = True
    _poses: list[Any] = field(default_factory=list, repr=False)

    def frame_poses(self) -> list[sympy.Matrix]:
        """``M_i = M_{i-1}·A_i`` for every module, simplified if asked; cached."""
        import sympy

        if not self._poses:
            pose = sympy.eye(4)
            for matrix in self.transfer:
                pose = pose * matrix
                if self.simplify:
                    pose = simplify_matrix(pose)
                self._poses.append(pose)
        return list(self._poses)

    def end_effector(self) -> sympy.Matrix:
        """``p_EE = M_n·[Px, Py, Pz, 1]ᵀ``, shape (4, 1)."""
        vector = self.frame_poses()[-1] * self.point
        return simplify_matrix(vector) if self.simplify else vector

    def values(self) -> dict[Any, Any]:
        """Substitutions that turn length symbols back into the robot's numbers."""
        return dict(self.lengths)


def symbolic_chain(
    robot: Robot, q: Any = None, lengths: bool = False, simplify: bool = True
) -> SymbolicChain:
    """Build the symbolic transfer matrices of a robot.

    Parameters
    ----------
    robot : Robot
    q : array-like, shape (n,), optional
        Coordinates to use instead of the symbols ``q1 … qn`` (converted to exact numbers
        where possible: ``np.pi / 2 → pi/2``).
    lengths : bool
        Replace every non-zero length (module offsets, DH ``d`` and ``a``, end-effector
        point) by a symbol ``l1, l2, …`` in chain order.
    simplify : bool
        Trigonometric simplification of the cumulative matrices.

    Returns
    -------
    SymbolicChain

    Examples
    --------
    The paper's R_zR_yR_y robot (section 3):

    >>> from robotconf import Module, Robot
    >>> robot = Robot(
    ...     [Module("Rz"), Module("Ry", a=(0, 0, 20)), Module("Ry", a=(30, 0, 0))],
    ...     end_effector=(40, 0, 0),
    ... )
    >>> chain = symbolic_chain(robot, lengths=True)
    >>> chain.lengths
    {l1: 20, l2: 30, l3: 40}
    >>> chain.frame_poses()[2][0, 0]
    cos(q1)*cos(q2 + q3)
    >>> chain.end_effector().subs(chain.values()).subs({s: 0 for s in chain.q_symbols}).T
    Matrix([[70, 0, 20, 1]])
    """
    import sympy

    q_symbols = [sympy.Symbol(name, real=True) for name in robot.coordinate_names]
    if q is None:
        q_values: list[Any] = list(q_symbols)
    else:
        values = check_configuration(q, robot.n, robot.coordinate_names)
        q_values = [exact_number(v) for v in values]
    length_values: dict[Any, Any] = {}
    places: list[tuple[str, str, Any]] = []

    def symbol_for(place: str, name: str, number: float) -> Any:
        if not lengths or number == 0.0:
            return exact_number(number)
        symbol = sympy.Symbol(f"l{len(length_values) + 1}", real=True)
        length_values[symbol] = exact_number(number)
        places.append((place, name, symbol))
        return symbol

    factors: list[list[tuple[str, Any]]] = []
    transfer: list[Any] = []
    for i, (label, link) in enumerate(zip(robot.module_names, robot.modules, strict=True)):
        if i >= robot.active:
            factors.append([])
            transfer.append(sympy.eye(4))
            continue
        chosen = {
            name: symbol_for(label, name, link.parameters()[name])
            for name in link.length_parameters()
        }
        link_f, matrix = link_factors(link, q_values[i], chosen)
        factors.append(link_f)
        # A product of factors needs simplifying; a module's table entry is already simple.
        transfer.append(simplify_matrix(matrix) if link_f else matrix)
    point = [
        symbol_for("EE", f"P{axis}", v)
        for axis, v in zip(AXIS_NAMES, robot.end_effector_point, strict=True)
    ]
    return SymbolicChain(
        robot=robot,
        q=q_values,
        q_symbols=q_symbols,
        lengths=length_values,
        length_places=places,
        factors=factors,
        transfer=transfer,
        point=sympy.Matrix([*point, 1]),
        simplify=simplify,
    )
