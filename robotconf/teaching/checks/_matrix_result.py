"""The result of a homework check: verdict, wrong entries, hints, and an HTML table."""

from __future__ import annotations

import html
from dataclasses import dataclass, field
from typing import Any

from ..derivation._expected import ExpectedMatrix
from ..reading._shown import show_entry, show_expected

__all__ = ["MATRIX_DIAGNOSES", "MatrixCheck"]

#: Every diagnosis code a :class:`MatrixCheck` may carry, with what it means. A code of
#: the same slip made in every module of a kind ends in ``_all``.
MATRIX_DIAGNOSES = {
    "no_answer": "the answer is still None",
    "shape": "a matrix of another shape",
    "too_complicated": "an entry is too large for the checker to evaluate",
    "wrong_order": "the transfer matrices multiplied in the wrong order",
    "transposed_rotation": "the rotation part written transposed (axes as rows)",
    "transposed_matrix": "the whole matrix transposed",
    "rotation_direction": "a module turned the wrong way (the sines' signs)",
    "sign_error": "one entry, or one pattern of entries, with the wrong sign",
    "offset_after_rotation": "a module's offset applied after its rotation (Rot·Trans)",
    "missing_offset": "a module's offset, a DH length or the end-effector point left out",
    "dh_convention": "the other DH convention's product",
    "degrees_as_radians": "angles in degrees fed to sin and cos",
    "radians_as_degrees": "a calculator in degree mode",
    "row_swap": "two rows exchanged",
    "column_swap": "two columns exchanged",
    "swapped_d_a": "a DH row's d and a exchanged",
    "homogeneous_coordinate": "the homogeneous coordinate 0 for a point, or left out",
    "parking_pose": "the answer at q = 0 instead of the asked pose",
    "joint_left_out": "one joint's q left out",
    "swapped_joints": "two joints' q exchanged",
    "absolute_angle": "a joint angle taken against the base where it is relative to the "
    "previous parallel joint",
    "unit_slip": "a length in the wrong unit (×1000)",
    "coarse_rounding": "numbers rounded to too few digits",
    "rotation_direction_all": "every module of a kind turned the wrong way",
    "missing_offset_all": "the offsets of every module of a kind left out",
    "offset_after_rotation_all": "Rot·Trans in every module of a kind",
    "sign_error_all": "the same sign slip in every module of a kind",
    "swapped_d_a_all": "d and a exchanged in every DH row",
}


@dataclass(frozen=True, eq=False)
class MatrixCheck:
    """The verdict on one student matrix.

    Attributes
    ----------
    ok : bool
        Every entry right (and the shape).
    wrong_entries : list of (int, int)
        0-based ``(row, col)`` of wrong entries, as numpy indexes them. Hints count from
        1 as textbooks do: entry (1,3) is ``wrong_entries`` item ``(0, 2)``.
    hints : list of str
        What the mistake most likely is, in sentences a student can act on.
    mistakes : list of str
        Codes of the hints, in their order (the primary diagnosis first, then the
        entry-level ones): ``"wrong_order"``, ``"transposed_rotation"``,
        ``"transposed_matrix"``, ``"rotation_direction"``, ``"sign_error"``,
        ``"offset_after_rotation"``, ``"missing_offset"``, ``"dh_convention"``,
        ``"degrees_as_radians"``, ``"radians_as_degrees"``, ``"row_swap"``,
        ``"column_swap"``, ``"swapped_d_a"``, ``"homogeneous_coordinate"``,
        ``"parking_pose"``, ``"joint_left_out"``, ``"swapped_joints"``, ``"unit_slip"``,
        ``"coarse_rounding"``, the same slip in every module of a kind
        ``"<code>_all"`` (``"rotation_direction_all"``, ``"missing_offset_all"``,
        ``"offset_after_rotation_all"``, ``"sign_error_all"``, ``"swapped_d_a_all"``),
        ``"shape"``, ``"no_answer"``, ``"too_complicated"``.
    student : sympy.Matrix or None
        The student's matrix as understood; ``None`` when there is no answer yet.
    expected : ExpectedMatrix
    unchecked_entries : list of (int, int)
        0-based entries too complicated to check within the checker's budget (neither
        right nor known to be wrong; ``ok`` is False while there are any).
    complete : bool
        The primary diagnosis explains every wrong entry (one slip, nothing else wrong).
    diagnoses : tuple of str
        Every explanation that fits the wrong entries, ranked best first, each code once
        (see :mod:`robotconf.teaching.diagnosis._ranking`); empty when the answer is right or
        nothing fits. ``("no_answer",)``, ``("shape",)`` or ``("transposed_matrix",)``
        when there is no answer or it has another shape.

    Examples
    --------
    >>> import numpy as np
    >>> from robotconf.teaching import check_matrix
    >>> result = check_matrix([[3, 4], [1, 2]], np.array([[1, 2], [3, 4]]))
    >>> result.diagnosis, result.diagnoses
    ('row_swap', ('row_swap',))
    >>> check_matrix([[1, 2], [3, 4]], np.array([[1, 2], [3, 4]])).diagnosis is None
    True
    """

    ok: bool
    wrong_entries: list[tuple[int, int]]
    hints: list[str]
    mistakes: list[str]
    student: Any
    expected: ExpectedMatrix
    reveal: bool = field(default=False, repr=False)
    unchecked_entries: list[tuple[int, int]] = field(default_factory=list)
    diagnoses: tuple[str, ...] = ()
    complete: bool = False

    @property
    def kind(self) -> str:
        """``"matrix"``: which check made the verdict."""
        return "matrix"

    @property
    def diagnosis(self) -> str | None:
        """The primary diagnosis: the best-ranked mistake code, or ``None``."""
        return self.diagnoses[0] if self.diagnoses else None

    def __bool__(self) -> bool:
        return self.ok

    def __str__(self) -> str:
        name = self.expected.name or "the matrix"
        if self.ok:
            return f"{name}: correct."
        count = len(self.wrong_entries)
        head = f"{name}: {count} wrong entr{'y' if count == 1 else 'ies'}." if count else f"{name}:"
        if self.unchecked_entries:
            unchecked = len(self.unchecked_entries)
            head += f" {unchecked} entr{'y' if unchecked == 1 else 'ies'} too complicated to check."
        return "\n".join([head, *(f"- {hint}" for hint in self.hints)])

    def __repr__(self) -> str:
        return f"<MatrixCheck ok={self.ok} wrong_entries={self.wrong_entries}>"

    def _repr_html_(self) -> str:
        rows = []
        wrong = set(self.wrong_entries)
        unchecked = set(self.unchecked_entries)
        student = self.student
        if student is not None:
            for r in range(student.rows):
                cells = []
                for c in range(student.cols):
                    text = html.escape(show_entry(student[r, c]))
                    if (r, c) in wrong:
                        tip = f"entry ({r + 1},{c + 1}) is wrong"
                        if self.reveal and self.expected.matrix.shape == student.shape:
                            tip += ": expected " + show_expected(self.expected.matrix[r, c])
                        cells.append(
                            f'<td style="background:#fdd;border:2px solid #c00" '
                            f'title="{html.escape(tip)}">✗ {text}</td>'
                        )
                    elif (r, c) in unchecked:
                        tip = f"entry ({r + 1},{c + 1}) is too complicated to check"
                        cells.append(
                            f'<td style="background:#ffe9b3;border:2px solid #b80" '
                            f'title="{html.escape(tip)}">? {text}</td>'
                        )
                    else:
                        cells.append(f'<td style="background:#efe">{text}</td>')
                rows.append("<tr>" + "".join(cells) + "</tr>")
        verdict = "✔ correct" if self.ok else html.escape(str(self).split("\n")[0])
        hints = "".join(f"<li>{html.escape(h)}</li>" for h in self.hints)
        return (
            f"<div><b>{verdict}</b>"
            f'<table style="font-family:monospace;border-collapse:collapse">{"".join(rows)}</table>'
            + (f"<ul>{hints}</ul>" if hints else "")
            + "</div>"
        )
