"""Step-by-step forward kinematics: A_i, M_i = M_{i-1}·A_i and p_EE, as text and LaTeX.

The paper validated its numbers with a second tool (Mathcad, Figure 15); a
:class:`Derivation` shows the same chain of matrices in the notebook, numerically at one
configuration (from the numpy core) or symbolically (from
:mod:`robotconf.teaching.derivation._symbolic_chain`).
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from ..._errors import InvalidInputError
from ..._validation import check_configuration, check_integer
from ...kinematics import (
    DH_FACTORS,
    DH_JOINT_PARAMETER,
    DH_SYMBOLS,
    DHLink,
    Module,
    dh_formula,
    transfer_matrix,
)
from ._formatting import format_number, latex_text
from ._step import DerivationStep, step_name
from ._symbolic import dh_values, exact_number
from ._symbolic_chain import SymbolicChain, symbolic_chain
from ._symbolic_limits import (
    SYMBOLIC_COST_LIMIT,
    SYMBOLIC_TOO_LONG,
    symbolic_cost,
    symbolic_fits,
)

if TYPE_CHECKING:  # pragma: no cover
    from ...kinematics import Robot

__all__ = ["Derivation", "derivation"]


@dataclass(frozen=True, eq=False)
class Derivation:
    """The forward-kinematics derivation of a robot, step by step.

    Made by :func:`derivation`. Index it by step name (``steps["M3"]``), iterate over
    its steps, print it (aligned plain text), show it in a notebook (LaTeX) or take the
    LaTeX source with :meth:`latex`.
    """

    robot: Robot
    steps: tuple[DerivationStep, ...]
    symbolic: bool
    q: tuple[float, ...] | None
    lengths: dict[Any, Any] = field(default_factory=dict)
    precision: int = 4

    def __getitem__(self, name: str) -> DerivationStep:
        key = step_name(self.robot, name)
        return next(step for step in self.steps if step.name == key)

    def __iter__(self) -> Iterator[DerivationStep]:
        return iter(self.steps)

    def __len__(self) -> int:
        return len(self.steps)

    @property
    def matrices(self) -> dict[str, Any]:
        """``{step name: matrix}`` in derivation order."""
        return {step.name: step.matrix for step in self.steps}

    def _header(self) -> list[str]:
        title = self.robot.name or "Robot"
        mode = "symbolic" if self.symbolic else "numeric"
        lines = [f"{title}: forward kinematics ({mode}), {self.robot.n} modules"]
        if self.q is not None:
            values = ", ".join(format_number(v, self.precision) for v in self.q)
            lines.append(f"at q = ({values})")
        if self.lengths:
            lines.append("where " + ", ".join(f"{k} = {v}" for k, v in self.lengths.items()))
        return lines

    def __str__(self) -> str:
        lines = self._header()
        for step in self.steps:
            lines.append("")
            lines.extend(step.text_lines())
        return "\n".join(lines)

    def __repr__(self) -> str:
        names = ", ".join(step.name for step in self.steps)
        return f"<Derivation of {self.robot.name or 'Robot'}: {names}>"

    def _repr_pretty_(self, printer: Any, cycle: bool) -> None:
        printer.text(str(self) if not cycle else "Derivation(...)")

    def latex(self) -> str:
        """The derivation as LaTeX source: one ``aligned`` environment (for a handout).

        Returns
        -------
        str
        """
        header = [f"&\\text{{{latex_text(line)}}}" for line in self._header()]
        body = [step.latex() for step in self.steps]
        return "\\begin{aligned}\n" + " \\\\\n".join(header + body) + "\n\\end{aligned}"

    def _repr_latex_(self) -> str:
        return "$$" + self.latex() + "$$"


# -- construction ---------------------------------------------------------------------


def _describe_link(link: Any, i: int, shown: dict[str, str], active: bool) -> str:
    if not active:
        return f"identity (module {i} is inactive)"
    # A module and a DH row are described in their own words (kind and offsets, or the row).
    if isinstance(link, Module):
        a = "(" + ", ".join(shown[name] for name in link.parameters()) + ")"
        if link.kind == "none":
            return "none (null module): identity"
        if link.kind == "fixed":
            return f"fixed offset a = {a}"
        return f"{link.kind}(q{i}) with a = {a}"
    # θ0 and d0: the constant parts of the parameters a coordinate may add to.
    constant = DH_JOINT_PARAMETER.values()
    row = ", ".join(
        f"{DH_SYMBOLS[name]}{'0' if name in constant else ''} = {shown[name]}"
        for name in link.parameters()
    )
    joint = DH_SYMBOLS[DH_JOINT_PARAMETER[link.joint_type]]
    return (
        f"{link.convention} DH {dh_formula(link.convention)}, {row} "
        f"({link.joint_type}: {joint} = {joint}0 + q{i})"
    )


def _shown_values(link: Any, label: str, chain: SymbolicChain | None, precision: int) -> dict:
    parameters = link.parameters()
    if chain is None:
        return {name: format_number(value, precision) for name, value in parameters.items()}
    import sympy

    placed = {(place, name): symbol for place, name, symbol in chain.length_places}
    return {
        name: sympy.sstr(placed.get((label, name), exact_number(value)))
        for name, value in parameters.items()
    }


def derivation(
    robot: Robot,
    q: Any = None,
    symbolic: bool = False,
    lengths: bool = False,
    precision: int = 4,
    simplify: bool = True,
    allow_slow: bool = False,
) -> Derivation:
    """Step-by-step forward kinematics: every ``A_i``, every ``M_i`` and ``p_EE``.

    Parameters
    ----------
    robot : Robot
    q : array-like, shape (n,), optional
        Configuration (radians for rotations, length for translations). Numeric mode:
        default the robot's own ``q``. Symbolic mode: default the symbols ``q1 … qn``;
        given values are substituted exactly (``np.pi / 2`` becomes ``pi/2``).
    symbolic : bool
        sympy matrices with real symbols instead of numbers.
    lengths : bool
        Symbolic mode only: non-zero lengths become ``l1, l2, …`` in chain order.
    precision : int
        Decimals shown for numbers in numeric mode (tiny noise shows as 0).
    simplify : bool
        Symbolic mode: fold products of sines and cosines into sums of angles.
    allow_slow : bool
        Symbolic mode: build the matrices of a chain over the documented cost too
        (:func:`~robotconf.teaching.symbolic_fits`: about 3 s at the limit, doubling with
        every further rotation, minutes for a 12-module chain). By default such a chain
        is refused at once.

    Returns
    -------
    Derivation
        Steps ``A1 … An``, ``M1 … Mn``, ``p_EE`` (the homogeneous column, shape (4, 1)).

    Raises
    ------
    InvalidInputError
        On a bad ``q``, ``precision``, or ``lengths`` without ``symbolic``; with
        ``symbolic=True``, for a chain over the symbolic limit unless ``allow_slow``
        (field ``symbolic``, the message of ``robotconf report``: "no symbolic matrices:
        this chain is too long for them by default, …").

    Examples
    --------
    >>> from robotconf import Module, Robot
    >>> robot = Robot(
    ...     [Module("Rz"), Module("Ry", a=(0, 0, 20)), Module("Ry", a=(30, 0, 0))],
    ...     end_effector=(40, 0, 0),
    ... )
    >>> steps = derivation(robot, symbolic=True, lengths=True)
    >>> steps["M3"].matrix[0, 0]
    cos(q1)*cos(q2 + q3)
    >>> long_chain = Robot([Module(kind) for kind in ["Rz", "Ry", "Rx"] * 4])
    >>> derivation(long_chain, symbolic=True)
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: symbolic: no symbolic matrices: this chain is too long for ...
    >>> print(derivation(robot, q=[0, 0, 0])["p_EE"])
    p_EE: M3·[Px, Py, Pz, 1]ᵀ with P = (40, 0, 0)
          [ 70 ]
    p_EE = [  0 ]
          [ 20 ]
          [  1 ]
    """
    from ...kinematics import Robot

    if not isinstance(robot, Robot):
        raise InvalidInputError("robot", robot, "a robotconf Robot", problem="not a robot:")
    precision = check_integer(precision, "precision", 0, 15)
    if lengths and not symbolic:
        raise InvalidInputError(
            "lengths",
            lengths,
            "lengths=True together with symbolic=True",
            problem="needs symbolic:",
        )
    if symbolic:
        if not allow_slow and not symbolic_fits(robot):
            error = InvalidInputError(
                "symbolic",
                symbolic_cost(robot),
                f"allow_slow=True, or a chain whose symbolic_cost ≤ {SYMBOLIC_COST_LIMIT}",
            )
            error.args = (f"symbolic: no symbolic matrices: {SYMBOLIC_TOO_LONG}",)
            raise error
        return _symbolic_derivation(robot, q, lengths, precision, simplify)
    return _numeric_derivation(robot, q, precision)


def _numeric_derivation(robot: Robot, q: Any, precision: int) -> Derivation:
    values = robot.q if q is None else check_configuration(q, robot.n, robot.coordinate_names)
    transfer = robot.transfer_matrices(values)
    # At its own q the robot keeps one snapshot, which the 3D view draws too.
    poses = robot.at().frame_poses if q is None else robot.frame_poses(values)
    config = tuple(float(v) for v in values)
    common: dict[str, Any] = {"robot": robot, "q": config, "symbolic": False, "lengths": False}
    common["precision"] = precision
    steps = []
    for i, (label, link) in enumerate(zip(robot.module_names, robot.modules, strict=True)):
        active = i < robot.active
        shown = _shown_values(link, label, None, precision)
        factors: tuple = ()
        # Only a DH row is a product of elementary factors; a module is one table entry.
        if isinstance(link, DHLink) and active:
            amount = dh_values(link, link.parameters(), float(values[i]))
            factors = tuple(
                (
                    f"{kind}({format_number(amount[name], precision)})",
                    transfer_matrix(kind, amount[name]),
                )
                for kind, name in DH_FACTORS[link.convention]
            )
        description = _describe_link(link, i + 1, shown, active)
        steps.append(
            DerivationStep(f"A{i + 1}", i + 1, description, factors, transfer[i], **common)
        )
    steps.extend(_pose_steps(poses, common))
    point = robot.end_effector_point
    column = (poses[-1] @ np.append(point, 1.0)).reshape(4, 1)
    shown_point = ", ".join(format_number(v, precision) for v in point)
    description = f"M{robot.n}·[Px, Py, Pz, 1]ᵀ with P = ({shown_point})"
    steps.append(DerivationStep("p_EE", robot.n, description, (), column, **common))
    return Derivation(robot, tuple(steps), False, config, {}, precision)


def _pose_steps(poses: Sequence[Any] | np.ndarray, common: dict[str, Any]) -> list[DerivationStep]:
    steps = []
    for i, pose in enumerate(poses):
        description = "A1" if i == 0 else f"M{i}·A{i + 1}"
        steps.append(DerivationStep(f"M{i + 1}", i + 1, description, (), pose, **common))
    return steps


def _symbolic_derivation(
    robot: Robot, q: Any, lengths: bool, precision: int, simplify: bool
) -> Derivation:
    import sympy

    chain = symbolic_chain(robot, q=q, lengths=lengths, simplify=simplify)
    config = None if q is None else tuple(float(v) for v in np.asarray(q, dtype=float))
    common: dict[str, Any] = {"robot": robot, "q": config, "symbolic": True, "lengths": lengths}
    common["precision"] = precision
    steps = []
    for i, (label, link) in enumerate(zip(robot.module_names, robot.modules, strict=True)):
        shown = _shown_values(link, label, chain, precision)
        description = _describe_link(link, i + 1, shown, i < robot.active)
        factors = tuple(chain.factors[i])
        steps.append(
            DerivationStep(f"A{i + 1}", i + 1, description, factors, chain.transfer[i], **common)
        )
    steps.extend(_pose_steps(chain.frame_poses(), common))
    point = ", ".join(sympy.sstr(v) for v in chain.point[:3])
    description = f"M{robot.n}·[Px, Py, Pz, 1]ᵀ with P = ({point})"
    steps.append(DerivationStep("p_EE", robot.n, description, (), chain.end_effector(), **common))
    return Derivation(robot, tuple(steps), True, config, chain.values(), precision)
