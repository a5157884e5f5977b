"""The result of a homework check: verdict, wrong entries, hints, and an HTML table."""

from __future__ import annotations

import html
from dataclasses import dataclass, field
from typing import Any

from ._expected import ExpectedMatrix

__all__ = ["MatrixCheck", "show_entry"]


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
        Codes of the recognised mistakes: ``"wrong_order"``, ``"transposed_rotation"``,
        ``"transposed_matrix"``, ``"rotation_direction"``, ``"sign_error"``,
        ``"offset_after_rotation"``, ``"missing_offset"``, ``"dh_convention"``,
        ``"degrees_as_radians"``, ``"radians_as_degrees"``, ``"row_swap"``,
        ``"column_swap"``, ``"swapped_d_a"``, ``"shape"``, ``"no_answer"``,
        ``"too_complicated"``.
    student : sympy.Matrix or None
        The student's matrix as understood; ``None`` when there is no answer yet.
    expected : ExpectedMatrix
    unchecked_entries : list of (int, int)
        0-based entries too complicated to check within the checker's budget (neither
        right nor known to be wrong; ``ok`` is False while there are any).
    """

    ok: bool
    wrong_entries: list[tuple[int, int]]
    hints: list[str]
    mistakes: list[str]
    student: Any
    expected: ExpectedMatrix
    reveal: bool = field(default=True, repr=False)
    unchecked_entries: list[tuple[int, int]] = field(default_factory=list)

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
                            tip += ": expected " + show_entry(self.expected.matrix[r, c])
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


#: Entries with more nodes than this print unsorted (sorting a huge sum is slow).
_SORTED_PRINT_NODES = 200
#: Entries with more nodes than this are not printed at all, only described.
_PRINTED_NODES = 2000


def show_entry(entry: Any, limit: int = 300) -> str:
    """An entry as hints quote it: numbers rounded, long formulas cut at ``limit``.

    >>> import sympy
    >>> show_entry(sympy.Float(0.70710678)), show_entry(sympy.Symbol("q1") * 2)
    ('0.7071', '2*q1')
    """
    import sympy

    from ._formatting import format_number

    if isinstance(entry, sympy.Float) or (entry.is_Number and not entry.is_Rational):
        text = format_number(float(entry), 4)
    else:
        count, stack = 0, [entry]
        while stack and count <= _PRINTED_NODES:
            count += 1
            stack.extend(stack.pop().args)
        if count > _PRINTED_NODES:
            return f"a formula of over {_PRINTED_NODES} parts"
        text = sympy.sstr(entry, order="none" if count > _SORTED_PRINT_NODES else None)
    return text if len(text) <= limit else text[: limit - 3] + "..."
