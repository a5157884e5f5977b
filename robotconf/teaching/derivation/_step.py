"""One step of a derivation: a named matrix, how it is obtained, and its value."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ..._errors import InvalidInputError
from ._formatting import latex_text, matrix_grid, matrix_latex, side_by_side

if TYPE_CHECKING:  # pragma: no cover
    from ...kinematics import Robot

__all__ = ["DerivationStep", "step_name"]


@dataclass(frozen=True, eq=False)
class DerivationStep:
    """One line of a derivation: a named matrix, how it is obtained, and its value.

    Attributes
    ----------
    name : str
        ``"A1" … "An"``, ``"M1" … "Mn"`` or ``"p_EE"``.
    index : int
        Module number (1-based); ``n`` for ``p_EE``.
    description : str
        What the matrix is, e.g. ``"Ry(q2) with a = (0, 0, l1)"`` or ``"M1·A2"``.
    factors : tuple of (str, matrix)
        Elementary factors of a DH link in multiplication order (else empty).
    matrix : sympy.Matrix or ndarray
        Shape (4, 4); ``p_EE`` is the homogeneous column, shape (4, 1).
    robot : Robot
    q : tuple of float or None
        The configuration (radians / length) of a numeric derivation, or of a symbolic
        one evaluated at given values; ``None`` for symbols.
    symbolic : bool
    lengths : bool
        Whether lengths are the symbols ``l1, l2, …``.
    """

    name: str
    index: int
    description: str
    factors: tuple[tuple[str, Any], ...]
    matrix: Any
    robot: Robot
    q: tuple[float, ...] | None
    symbolic: bool
    lengths: bool
    precision: int = 4

    @property
    def kind(self) -> str:
        """``"transfer"`` (A_i), ``"pose"`` (M_i) or ``"end_effector"`` (p_EE)."""
        return {"A": "transfer", "M": "pose"}.get(self.name[0], "end_effector")

    def text_lines(self) -> list[str]:
        """The step as aligned plain-text lines: name, description, factors, matrix."""
        lines = [f"{self.name}: {self.description}"]
        if self.factors:
            grids = [matrix_grid(m, self.symbolic, self.precision) for _, m in self.factors]
            lines.append("    = " + "·".join(label for label, _ in self.factors))
            lines.extend("    " + line for line in side_by_side(grids, " · "))
        grid = matrix_grid(self.matrix, self.symbolic, self.precision)
        prefix = f"{self.name} = "
        pad = " " * len(prefix)
        middle = (len(grid) - 1) // 2
        lines.extend((prefix if r == middle else pad) + row for r, row in enumerate(grid))
        return lines

    def latex(self) -> str:
        """The step as rows of a LaTeX ``aligned`` environment."""
        name = "p_{EE}" if self.name == "p_EE" else f"{self.name[0]}_{{{self.name[1:]}}}"
        parts = [f"{name} &= \\text{{{latex_text(self.description)}}}"]
        if self.factors:
            factors = (matrix_latex(m, self.symbolic, self.precision) for _, m in self.factors)
            parts.append("&= " + " \\cdot ".join(factors))
        parts.append("&= " + matrix_latex(self.matrix, self.symbolic, self.precision))
        return " \\\\\n".join(parts)

    def __str__(self) -> str:
        return "\n".join(self.text_lines())

    def __repr__(self) -> str:
        return f"<DerivationStep {self.name}: {self.description}>"

    def _repr_latex_(self) -> str:
        return "$$\\begin{aligned}\n" + self.latex() + "\n\\end{aligned}$$"


def step_name(robot: Robot, name: Any) -> str:
    """The canonical name of a step of a robot's derivation: ``A<i>``, ``M<i>`` or ``p_EE``.

    Case, spaces and underscores do not matter; ``EE`` and ``P`` also name ``p_EE``.

    Examples
    --------
    >>> from robotconf.kinematics import Module, Robot
    >>> robot = Robot([Module("Rz"), Module("Ry")])
    >>> step_name(robot, "m2"), step_name(robot, "A_1"), step_name(robot, "EE")
    ('M2', 'A1', 'p_EE')
    >>> step_name(robot, "M3")
    Traceback (most recent call last):
    ...
    robotconf.InvalidInputError: name: unknown matrix name 'M3'; allowed: A1 … A2, M1 … M2 or p_EE
    """
    allowed = f"A1 … A{robot.n}, M1 … M{robot.n} or p_EE"
    if not isinstance(name, str):
        raise InvalidInputError("name", name, allowed, problem="not a matrix name:")
    key = name.replace("_", "").replace(" ", "").upper()
    if key in ("PEE", "EE", "P"):
        return "p_EE"
    if len(key) >= 2 and key[0] in "AM" and key[1:].isdigit() and 1 <= int(key[1:]) <= robot.n:
        return key[0] + str(int(key[1:]))
    raise InvalidInputError("name", name, allowed, problem="unknown matrix name")
