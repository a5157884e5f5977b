"""Numbers and matrices as text and LaTeX: aligned grids and bmatrix blocks.

Numbers are shown with a configurable number of decimals; noise below half the last
decimal shows as 0 and whole numbers lose their ``.0``. Symbolic entries are printed by
sympy (``sstr`` for text, ``latex`` for LaTeX).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

__all__ = ["format_number", "latex_text", "matrix_grid", "matrix_latex", "side_by_side"]


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


#: Characters of robotconf's own texts that pdflatex cannot typeset as they are, and the
#: LaTeX that stands for them: inline math, which works in text mode, inside ``\text{}``
#: (amsmath) and in the notebook's MathJax alike.
_LATEX_SYMBOLS = {
    "·": "$\\cdot$",
    "ᵀ": "$^{\\mathsf T}$",
    "θ": "$\\theta$",
    "α": "$\\alpha$",
    "π": "$\\pi$",
    "Δ": "$\\Delta$",
    "τ": "$\\tau$",
    "−": "-",
    "…": "$\\ldots$",
    "→": "$\\to$",
    "×": "$\\times$",
    "≤": "$\\le$",
    "≥": "$\\ge$",
    "°": "$^\\circ$",
    "²": "$^2$",
    "³": "$^3$",
}


def latex_text(text: str) -> str:
    """Text for ``\\text{…}``: LaTeX specials escaped, math symbols written in LaTeX.

    pdflatex stops on characters such as ``ᵀ`` (U+1D40) and does not typeset Greek
    letters in text: ``·``, ``ᵀ``, ``θ``, ``α``, ``π``, ``−``, ``…`` and a few more become
    inline math (``$\\cdot$``, ``$^{\\mathsf T}$``, ``$\\theta$``, …), so robotconf's own
    texts are plain ASCII (other letters, e.g. in a robot's name, are kept for
    ``inputenc``).

    >>> latex_text("my_robot & 50% {x^2}")
    'my\\\\_robot \\\\& 50\\\\% \\\\{x\\\\^{}2\\\\}'
    >>> print(latex_text("M3·[Px, Py, Pz, 1]ᵀ, θ0 = 0"))
    M3$\\cdot$[Px, Py, Pz, 1]$^{\\mathsf T}$, $\\theta$0 = 0
    """
    replacements = {"\\": "\\textbackslash{}", "^": "\\^{}", "~": "\\~{}"}
    replacements.update({ch: "\\" + ch for ch in "{}_&%#$"})
    replacements.update(_LATEX_SYMBOLS)
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


def side_by_side(blocks: Sequence[list[str]], separator: str) -> list[str]:
    """Text blocks next to each other, centred vertically, ``separator`` on the middle row.

    >>> side_by_side([["[ 1 ]"], ["[ 2 ]"]], " · ")
    ['[ 1 ] · [ 2 ]']
    """
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


def matrix_grid(matrix: Any, symbolic: bool, precision: int) -> list[str]:
    """A matrix as aligned text rows in brackets (numbers rounded, sympy entries as text).

    >>> matrix_grid([[1.0, -0.5], [0.0, 12.0]], False, 4)
    ['[ 1  -0.5 ]', '[ 0    12 ]']
    """
    return _grid(_cells(matrix, symbolic, precision, False))


def matrix_latex(matrix: Any, symbolic: bool, precision: int) -> str:
    """A matrix as a LaTeX ``bmatrix``.

    >>> matrix_latex([[1.0, 0.0]], False, 4)
    '\\\\begin{bmatrix} 1 & 0 \\\\end{bmatrix}'
    """
    cells = _cells(matrix, symbolic, precision, True)
    body = " \\\\ ".join(" & ".join(row) for row in cells)
    return "\\begin{bmatrix} " + body + " \\end{bmatrix}"
