"""The diagnosis of a wrong answer: every explanation that fits, ranked, and the hints.

Candidates come from every family of mistakes (:mod:`robotconf.teaching.diagnosis._mistakes`,
context-aware, and the context-free transposes and swaps); the ones that fit become
explanations, together with the entry-level ones (a coarse rounding, a sign, a zero in
the translation column: :func:`~robotconf.teaching.diagnosis._hints.entry_groups`). They are ranked
(:mod:`robotconf.teaching.diagnosis._ranking`) and the best one is the primary diagnosis; the hints
name it once, mention an equivalent reading in the same sentence, and describe whatever
it leaves unexplained entry by entry.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..derivation._expected import ExpectedMatrix
from ._generic import generic_candidates
from ._hints import entries_text, entry_groups, entry_hints
from ._mistakes import context_candidates
from ._ranking import ENTRY_TIER, Explanation, equivalent, match, rank, sentence

__all__ = ["Diagnosis", "diagnose"]


@dataclass(frozen=True)
class Diagnosis:
    """The ranked explanations of a wrong answer and the hints they give.

    Attributes
    ----------
    ranked : tuple of Explanation
        The explanations that account for all wrong entries, or for at least half of
        them and at least two, best first; empty when none does (the hints then describe
        the entries only).
    hints : list of str
        What the student reads: the primary diagnosis (with an equivalent reading), the
        entries it leaves unexplained, and for a full diagnosis the list of wrong entries.
    mistakes : list of str
        The codes of the hints, in their order.
    """

    ranked: tuple[Explanation, ...]
    hints: list[str]
    mistakes: list[str]

    @property
    def codes(self) -> tuple[str, ...]:
        """The ranked codes, each once."""
        return tuple(dict.fromkeys(e.code for e in self.ranked))


def _names_the_mistake(explanation: Explanation, wrong: set[tuple[int, int]]) -> bool:
    """A diagnosis explains everything, or at least half of it resting on two entries."""
    count = len(explanation.entries)
    return explanation.full or (count >= 2 and 2 * count >= len(wrong))


def _entry_explanations(groups: list[Any], wrong: set[tuple[int, int]]) -> list[Explanation]:
    return [
        Explanation(g.code, "", g.entries, g.entries == wrong, g.tier, order=i)
        for i, g in enumerate(groups)
    ]


def diagnose(
    reference: ExpectedMatrix,
    env: dict[str, np.ndarray],
    k: int,
    wrong: set[tuple[int, int]],
    student: Any,
    s_values: np.ndarray,
    e_values: np.ndarray,
    tol: float,
    reveal: bool,
) -> Diagnosis:
    """Explain the wrong entries of an answer: one primary diagnosis, then the rest.

    Parameters
    ----------
    reference : ExpectedMatrix
    env : dict of str to ndarray, shape (K,)
        The sample points.
    k : int
        K.
    wrong : set of (int, int)
        The wrong entries (0-based), not empty.
    student : sympy.Matrix
        The student's answer, same shape as the reference.
    s_values, e_values : ndarray, shape (K, rows, cols)
        Both matrices at the sample points.
    tol : float
    reveal : bool
        Whether hints may quote expected entries.

    Returns
    -------
    Diagnosis

    Examples
    --------
    >>> import sympy
    >>> from robotconf.teaching import as_expected
    >>> reference = as_expected(sympy.Matrix([[1, 2], [3, 4]]))
    >>> e = np.array([[[1.0, 2.0], [3.0, 4.0]]])
    >>> swapped = sympy.Matrix([[3, 4], [1, 2]])
    >>> wrong = {(0, 0), (0, 1), (1, 0), (1, 1)}
    >>> result = diagnose(reference, {}, 1, wrong, swapped, e[:, ::-1], e, 1e-3, False)
    >>> result.codes[0], result.hints[0]
    ('row_swap', 'Rows 1 and 2 are swapped: check which coordinate (x, y, z) each row stands for.')
    """
    candidates = context_candidates(reference, env, k) + generic_candidates(e_values)
    expected = reference.matrix
    groups = entry_groups(wrong, student, expected, s_values, e_values, tol)
    fitting = match(candidates, wrong, s_values, e_values, tol, student)
    fitting += _entry_explanations(groups, wrong)
    ranked = [e for e in rank(fitting) if _names_the_mistake(e, wrong)]
    hints: list[str] = []
    mistakes: list[str] = []
    explained: set[tuple[int, int]] = set()
    primary = ranked[0] if ranked else None
    if primary is not None and primary.tier < ENTRY_TIER and primary.values is not None:
        text = sentence(primary, equivalent(ranked, tol))
        if not primary.full:
            text += f" (entries {entries_text(primary.entries)})"
        hints.append(text)
        mistakes.append(primary.code)
        explained = set(primary.entries)
    more, more_codes = entry_hints(
        wrong - explained, student, expected, s_values, e_values, tol, reveal
    )
    hints += more
    mistakes += more_codes
    if primary is not None and primary.full and primary.values is not None:
        hints.append(f"Wrong entries: {entries_text(wrong)}.")
    return Diagnosis(tuple(ranked), hints, mistakes)
