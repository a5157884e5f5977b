"""Text and LaTeX rendering of derivation steps: aligned grids and bmatrix blocks.

Numbers are shown with a configurable number of decimals; noise below half the last
decimal shows as 0 and whole numbers lose their ``.0``. Symbolic entries are printed by
sympy (``sstr`` for text, ``latex`` for LaTeX).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # pragma: no cover
    from ._derivation import DerivationStep

__all__ = ["format_number", "step_text", "step_latex", "latex_text"]


def format_number(value: float, precision: int = 4) -> str:
    """A float for display: noise below ``0.5·10^-precision`` is 0, whole numbers lose ``.0``.

    Parameters
    ----------
    value : float
    precision : int
        Decimals kept (trailing zeros dropped).

    Returns
    -------
    str

    Examples
    --------
    >>> format_number(20.0), format_number(1.2e-16), format_number(-0.70710678), format_number(2.5)
    ('20', '0', '-0.7071', '2.5')
    """
    x = float(value)
    if not np.isfinite(x):
        return str(x)
    text = f"{x:.{precision}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def latex_text(text: str) -> str:
    """Text for ``\\text{…}``: LaTeX specials escaped (unicode θ, α, · are kept).

    >>> latex_text("my_robot & 50% {x^2}")
    'my\\\\_robot \\\\& 50\\\\% \\\\{x\\\\^{}2\\\\}'
    """
    replacements = {"\\": "\\textbackslash{}", "^": "\\^{}", "~": "\\~{}"}
    replacements.update({ch: "\\" + ch for ch in "{}_&%#$"})
    return "".join(replacements.get(ch, ch) for ch in text)


# -- rendering ------------------------------------------------------------------------


def _cells(matrix: Any, symbolic: bool, precision: int, latex: bool) -> list[list[str]]:
    if symbolic:
        import sympy

        show = sympy.latex if latex else sympy.sstr
        return [[show(matrix[r, c]) for c in range(matrix.cols)] for r in range(matrix.rows)]
    array = np.asarray(matrix, dtype=float)
    return [[format_number(v, precision) for v in row] for row in array]


def _grid(cells: list[list[str]]) -> list[str]:
    widths = [max(len(row[c]) for row in cells) for c in range(len(cells[0]))]
    return [
        "[ " + "  ".join(v.rjust(w) for v, w in zip(row, widths, strict=True)) + " ]"
        for row in cells
    ]


def _side_by_side(blocks: Sequence[list[str]], separator: str) -> list[str]:
    height = max(len(b) for b in blocks)
    widths = [max(len(line) for line in b) for b in blocks]
    middle = (height - 1) // 2
    lines = []
    for r in range(height):
        parts = []
        for b, w in zip(blocks, widths, strict=True):
            offset = (height - len(b)) // 2
            parts.append(b[r - offset].ljust(w) if 0 <= r - offset < len(b) else " " * w)
        sep = separator if r == middle else " " * len(separator)
        lines.append(sep.join(parts).rstrip())
    return lines


def _step_symbol(step: DerivationStep) -> str:
    return "p_EE" if step.name == "p_EE" else step.name


def step_text(step: DerivationStep) -> list[str]:
    lines = [f"{_step_symbol(step)}: {step.description}"]
    grids = []
    if step.factors:
        grids = [_grid(_cells(m, step.symbolic, step.precision, False)) for _, m in step.factors]
        lines.append("    = " + "·".join(label for label, _ in step.factors))
        lines.extend("    " + line for line in _side_by_side(grids, " · "))
    matrix_grid = _grid(_cells(step.matrix, step.symbolic, step.precision, False))
    prefix = f"{_step_symbol(step)} = "
    pad = " " * len(prefix)
    middle = (len(matrix_grid) - 1) // 2
    lines.extend((prefix if r == middle else pad) + row for r, row in enumerate(matrix_grid))
    return lines


def _latex_matrix(matrix: Any, symbolic: bool, precision: int) -> str:
    cells = _cells(matrix, symbolic, precision, True)
    body = " \\\\ ".join(" & ".join(row) for row in cells)
    return "\\begin{bmatrix} " + body + " \\end{bmatrix}"


def _latex_name(step: DerivationStep) -> str:
    if step.name == "p_EE":
        return "p_{EE}"
    return f"{step.name[0]}_{{{step.name[1:]}}}"


def step_latex(step: DerivationStep) -> str:
    name = _latex_name(step)
    parts = [f"{name} &= \\text{{{latex_text(step.description)}}}"]
    if step.factors:
        parts.append(
            "&= "
            + " \\cdot ".join(
                _latex_matrix(m, step.symbolic, step.precision) for _, m in step.factors
            )
        )
    parts.append("&= " + _latex_matrix(step.matrix, step.symbolic, step.precision))
    return " \\\\\n".join(parts)
