"""A candidate mistake: the wrong answer one slip produces, and the sentence naming the slip.

Every family of mistakes (:mod:`robotconf.teaching.diagnosis._mistakes` and the
``_mistakes_*`` files) describes its wrong answers as :class:`Candidate` objects; the
ranking (:mod:`robotconf.teaching.diagnosis._ranking`) compares them with the student's answer.
This file also holds the wording the families share: how a module is named in a hint and
where the sines of an elementary rotation sit.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ...kinematics import AXIS_NAMES, DH_PARAMETERS, DH_SYMBOLS, Module
from ..derivation._symbolic import sine_entries

__all__ = [
    "Candidate",
    "NAMED",
    "COMPOUND",
    "GENERIC",
    "ROTATION_PATTERN",
    "fmt",
    "module_label",
    "vector",
]

#: Specificity tiers (lower is preferred when two readings explain the same entries): one
#: slip in a named module or step, the same slip repeated in several modules, a slip of
#: layout that any matrix allows (a transpose, swapped rows).
NAMED, COMPOUND, GENERIC = 1, 2, 3


def _sine_pattern(axis: int) -> str:
    minus, plus = sine_entries(axis)
    entries = sorted([(minus, "−sin"), (plus, "+sin")])
    return " and ".join(f"{sign} in entry ({r + 1},{c + 1})" for (r, c), sign in entries)


#: Where the sines sit in an elementary rotation (1-based entries), for the hints.
ROTATION_PATTERN = {axis: _sine_pattern(k) for k, axis in enumerate(AXIS_NAMES)}


@dataclass(frozen=True)
class Candidate:
    """A wrong answer produced by one mistake.

    Attributes
    ----------
    code : str
        Mistake identifier, e.g. ``"wrong_order"``, ``"rotation_direction"``.
    message : str
        A sentence a student can act on (without the entry list), ending with a period.
    values : ndarray, shape (K, rows, cols)
        The wrong answer at the K sample points.
    reading : str
        The mistake as a short phrase ("transposing the rotation part"), used when another
        candidate gives the same numbers and this one is mentioned as an equivalent
        reading; empty: never mentioned that way.
    tier : int
        Specificity: :data:`NAMED` (1), :data:`COMPOUND` (2) or :data:`GENERIC` (3).

    Examples
    --------
    >>> wrong = Candidate("row_swap", "Rows 1 and 2 are swapped.", np.zeros((1, 2, 2)))
    >>> wrong.tier, wrong.reading
    (1, '')
    """

    code: str
    message: str
    values: np.ndarray
    reading: str = ""
    tier: int = NAMED


def fmt(value: float) -> str:
    """A robot parameter as hints print it (4 decimals, no float noise).

    >>> fmt(1.5707963), fmt(20.0)
    ('1.5708', '20')
    """
    from ..derivation._formatting import format_number

    return format_number(value, 4)


def vector(values: Any) -> str:
    """A tuple of parameters as hints print it.

    >>> vector((0, 0, 20.0))
    '(0, 0, 20)'
    """
    return "(" + ", ".join(fmt(v) for v in values) + ")"


def module_label(j: int, link: Any) -> str:
    """How hints name module ``j`` (1-based): its matrix, module and parameters.

    Parameters
    ----------
    j : int
        1-based module number.
    link : Module or DHLink

    Returns
    -------
    str

    Examples
    --------
    >>> module_label(2, Module("Ry", a=(0, 0, 20)))
    'A2 (module M2, Ry with a = (0, 0, 20))'
    """
    label = f"A{j} (module M{j}"
    if isinstance(link, Module):
        return label + f", {link.kind} with a = {vector(link.a)})"
    row = ", ".join(f"{DH_SYMBOLS[name]}={fmt(getattr(link, name))}" for name in DH_PARAMETERS)
    return label + f", DH row {row})"
