"""The kernel side of the answer key: what each exercise's check compared against.

:func:`~robotconf.grading.run_solutions` runs a solutions notebook with three kinds of
extra cells: one at the top that creates a :class:`KeyRun` (recording every checker
call), one before each check cell that says which exercise is being checked, and one at
the end that prints the record as a line of JSON for the caller to read. The record holds
text and numbers only: the values are described here, in the kernel.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from ..teaching import as_expected, format_number, simplify_matrix
from .rubric._recorder import CheckCall, CheckRecorder

__all__ = ["KEY_MARKER", "KeyRun", "describe_call", "describe_reference", "describe_value"]

#: Prefix of the line that carries the record.
KEY_MARKER = "robotconf-answer-key:"
#: Symbolic references with at most this many operations in all are simplified for show.
_SIMPLIFY_OPS = 400
#: Text of an answer that is neither a string nor numbers is cut at this length.
_MAX_TEXT = 2000
#: Decimals of the numbers in the key.
_DECIMALS = 6
#: Fractions in formulas with a larger denominator are shown as decimals.
_EXACT_DENOMINATOR = 12


def _text(entry: Any) -> str:
    """An entry in the checker's syntax, decimals without float noise."""
    from sympy.printing.str import StrPrinter

    class _Printer(StrPrinter):  # type: ignore[misc]
        def _print_Float(self, expr: Any) -> str:
            return format_number(float(expr), _DECIMALS)

    return str(_Printer().doprint(entry))


def _decimal(matrix: Any) -> Any:
    """Fractions that came from decimals (``2159/5000``) shown as decimals (``0.4318``).

    Small denominators stay exact (``1/2``, ``cos(q1)/3``), as the checker's hints show
    them.
    """
    import sympy

    decimals = {
        number: sympy.Float(format_number(float(number), 12), 12)
        for number in matrix.atoms(sympy.Rational)
        if number.q > _EXACT_DENOMINATOR
    }
    return matrix.xreplace(decimals) if decimals else matrix


def describe_reference(expected: Any) -> dict[str, Any]:
    """An expected value as text and numbers: what the answer key shows.

    Parameters
    ----------
    expected : ExpectedMatrix, sympy Matrix, array-like or number
        A checker reference.

    Returns
    -------
    dict
        ``kind`` (``"matrix"``), ``name`` (``"A2"``, ``"p_EE"`` or ``None``), ``q`` (the
        configuration, or ``None``), ``shape`` ``[rows, cols]``, ``symbols`` (sorted
        names), ``entries`` (rows of entry text: formulas in the checker's syntax,
        numbers with 6 decimals at most), ``values`` (rows of floats, or ``None`` when
        symbolic) and ``latex`` (a ``bmatrix``, only when symbolic).

    Examples
    --------
    >>> d = describe_reference([[0.5, 2.0]])
    >>> d["shape"], d["entries"], d["values"], d["latex"]
    ([1, 2], [['0.5', '2']], [[0.5, 2.0]], None)
    """
    import sympy

    reference = as_expected(expected)
    matrix = reference.matrix
    symbols = sorted(str(s) for s in matrix.free_symbols)
    if symbols and sum(sympy.count_ops(entry) for entry in matrix) <= _SIMPLIFY_OPS:
        matrix = simplify_matrix(matrix)
        symbols = sorted(str(s) for s in matrix.free_symbols)
    values = None
    shown = _decimal(matrix)
    entries = [[_text(entry) for entry in row] for row in shown.tolist()]
    if not symbols:
        values = [[float(entry) for entry in row] for row in matrix.tolist()]
        entries = [[format_number(v, _DECIMALS) for v in row] for row in values]
    return {
        "kind": "matrix",
        "name": reference.name,
        "q": None if reference.q is None else [float(v) for v in reference.q],
        "shape": [int(matrix.rows), int(matrix.cols)],
        "symbols": symbols,
        "entries": entries,
        "values": values,
        "latex": sympy.latex(shown, mat_str="bmatrix", mat_delim="") if symbols else None,
    }


def _dh_rows(rows: Any) -> dict[str, Any]:
    entries = [
        [v if isinstance(v, str) else format_number(float(v), _DECIMALS) for v in row]
        for row in rows
    ]
    return {
        "kind": "dh_table",
        "name": None,
        "q": None,
        "shape": [len(entries), len(entries[0]) if entries else 0],
        "symbols": [],
        "entries": entries,
        "values": None,
        "latex": None,
    }


def describe_call(call: CheckCall) -> dict[str, Any] | None:
    """What a checker call compared against, described as :func:`describe_reference` does.

    A DH table is described by the rows of the table that passed (θ and d as offsets of
    the joint variable), or ``None`` when the call did not pass.

    Examples
    --------
    >>> from robotconf.grading.rubric._recorder import CheckRecorder
    >>> from robotconf import teaching
    >>> with CheckRecorder() as recorder:
    ...     _ = teaching.check_vector([0, 35, -40], [0, 35, -40], name="the velocity")
    >>> d = describe_call(recorder.calls[0])
    >>> d["kind"], d["name"], d["entries"]
    ('vector', 'the velocity', [['0'], ['35'], ['-40']])
    """
    if call.kind == "matrix":
        return describe_reference(call.result.expected)
    if call.kind == "dh_table":
        return _dh_rows(call.result.rows) if call.result.ok else None
    described = describe_reference(np.asarray(call.result.expected, dtype=float))
    return {**described, "kind": call.kind, "name": call.result.name}


def describe_value(value: Any) -> dict[str, Any] | None:
    """A solution's answer as the key shows it: text as written, numbers as numbers.

    Examples
    --------
    >>> describe_value("[[1, 0]]"), describe_value([1, 2.5]), describe_value(None)
    ({'text': '[[1, 0]]'}, {'values': [1.0, 2.5], 'text': '[1, 2.5]'}, None)
    """
    if value is None:
        return None
    if isinstance(value, str):
        return {"text": value[:_MAX_TEXT]}
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return {"text": repr(value)[:_MAX_TEXT]}
    if array.size > 10_000 or not np.all(np.isfinite(array)):
        return {"text": repr(value)[:_MAX_TEXT]}
    return {"values": array.tolist(), "text": _nested_text(array)}


def _nested_text(array: np.ndarray) -> str:
    if array.ndim == 0:
        return format_number(float(array))
    return "[" + ", ".join(_nested_text(part) for part in array) + "]"


class KeyRun:
    """Records the checks of a running solutions notebook, exercise by exercise.

    Examples
    --------
    >>> import numpy as np
    >>> from robotconf import teaching
    >>> run = KeyRun()
    >>> run.label = "answer_1"
    >>> answer_1 = [[1, 0], [0, 1]]
    >>> _ = teaching.assert_matrix(answer_1, np.eye(2))
    >>> run.label = None
    >>> record = run.record({"answer_1": answer_1}, ["answer_1"])
    >>> run.close()
    >>> record["answer_1"]["expected"]["values"], record["answer_1"]["passed"]
    ([[1.0, 0.0], [0.0, 1.0]], True)
    """

    def __init__(self) -> None:
        self._recorder = CheckRecorder().install()

    @property
    def label(self) -> str | None:
        """The exercise whose check cell runs next (its answer variable)."""
        return self._recorder.label

    @label.setter
    def label(self, value: str | None) -> None:
        self._recorder.label = value

    def close(self) -> None:
        """Stop recording."""
        self._recorder.uninstall()

    def record(self, namespace: Mapping[str, Any], variables: Sequence[str]) -> dict[str, Any]:
        """For each answer variable: the reference its check used, and the solution.

        The reference is that of the exercise's last ``assert_*`` call (the check's
        verdict; ``check_*`` calls before it may only choose a hint), else of its last
        passing checker call, else of its last call. Without any checker call,
        ``expected_<k>`` from the notebook (``answer_<k>`` → ``expected_<k>``), else the
        answer itself, stands in.
        """
        record: dict[str, Any] = {}
        for variable in variables:
            calls: list[CheckCall] = [c for c in self._recorder.calls if c.label == variable]
            asserted = [c for c in calls if c.asserted]
            passed = [c for c in calls if c.result.ok]
            chosen = (asserted or passed or calls)[-1] if calls else None
            expected, source = None, "check"
            if chosen is not None:
                expected = describe_call(chosen)
            else:
                stand_in = f"expected_{variable.removeprefix('answer_')}"
                for origin, name in (("variable", stand_in), ("answer", variable)):
                    try:
                        expected = describe_reference(namespace[name])
                    except (KeyError, ValueError, TypeError):
                        continue
                    source = origin
                    break
            record[variable] = {
                "expected": expected,
                "expected_from": source if expected is not None else None,
                "solution": describe_value(namespace.get(variable)),
                "checks": len(calls),
                "passed": chosen is not None and bool(chosen.result.ok),
            }
        return record

    def dump(self, namespace: Mapping[str, Any], variables: Sequence[str]) -> None:
        """Print the record as one line: :data:`KEY_MARKER` followed by JSON."""
        self.close()
        print(KEY_MARKER + json.dumps(self.record(namespace, variables), default=str))
