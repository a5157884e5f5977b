"""Symbolic transfer matrices with sympy: elementary rotations, modules and DH links.

This is a second, independent implementation of the kinematics: every matrix is written
from the module table (docs/conventions.md, Modules) or from the DH factor products (paper
eq. 9–10), not from the numpy kernel, so the two can check each other. Only the naming
comes from :mod:`robotconf.kinematics` (movement types, axes, the order of the DH factors).
Symbols are real:
``q1 … qn`` for the generalized coordinates and, on request, ``l1, l2, …`` for the
non-zero lengths in the order they appear along the chain (for the paper's R_zR_yR_y
robot this gives its ``l1 = 20``, ``l2 = 30``, ``l3 = 40``).

A whole robot's chain is :mod:`robotconf.teaching.derivation._symbolic_chain`. sympy is imported
inside the functions, so ``import robotconf`` stays numpy-only.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ..._errors import InvalidInputError
from ...kinematics import (
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


__all__ = [
    "exact_number",
    "elementary_matrix",
    "module_matrix",
    "dh_factors",
    "link_factors",
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
