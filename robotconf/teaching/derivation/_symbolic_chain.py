"""A robot's kinematics in sympy: every A_i, M_i and p_EE, simplified for a person to read.

Built from the sympy link matrices of :mod:`robotconf.teaching.derivation._symbolic` (the
independent second implementation), never from the numpy kernel. sympy is imported inside
the functions, so ``import robotconf`` stays numpy-only.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from ..._validation import check_configuration
from ...kinematics import (
    AXIS_NAMES,
)

if TYPE_CHECKING:  # pragma: no cover
    import sympy

    from ...kinematics import Robot

from ._symbolic import exact_number, link_factors

__all__ = ["SymbolicChain", "symbolic_chain", "simplify_matrix"]


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
