"""Answers that ask robotconf for themselves: found in the answer cell, flagged for a teacher.

robotconf computes every answer of the course (that is its job): ``rc.ik_all(robot,
target)``, ``rc.derivation(robot).matrix``, ``rc.jacobian(robot, q)``,
``arm.end_effector(q)``. In a graded copy an answer cell that calls it hands in the
library's work, not the student's. At grading time the hidden part of the test cell
reads the answer cell back from IPython's input history (``In``), parses it (it is
never run again) and lists every call whose function is robotconf's: a robotconf
module's function or class, a function imported from robotconf, or a method of a
robotconf object. Such an exercise earns no automatic credit; the test cell prints
:data:`FLAG` with the calls, and autograde marks the cell for manual grading
(:class:`robotconf.grading.nbgrader_flags.FlagForManualGrading`).

This finds the shortcut as students take it; code written to hide a call
(``getattr(__import__("robotconf"), …)``) is not found. docs/grading.md says so.
"""

from __future__ import annotations

import ast
import types
from collections.abc import Mapping
from typing import Any

__all__ = ["FLAG", "answer_cell_source", "own_work_calls", "robotconf_calls"]

#: The words that start the note of a flagged exercise (read back by autograde).
FLAG = "Flagged for manual grading"

_PACKAGE = "robotconf"
_MAX_SHOWN = 60


def _is_ours(value: Any) -> bool:
    """A robotconf module, function, class, method or object."""
    if isinstance(value, types.ModuleType):
        module = value.__name__
    else:  # a function's or class's own module; an object's is its class's
        module = getattr(value, "__module__", None) or type(value).__module__
    return isinstance(module, str) and module.split(".")[0] == _PACKAGE


def _root(node: ast.AST) -> ast.AST:
    """The innermost object of ``a.b.c`` (a name, or a call such as ``f(x)`` in ``f(x).y``)."""
    while isinstance(node, (ast.Attribute, ast.Subscript)):
        node = node.value
    return node


def robotconf_calls(source: str, namespace: Mapping[str, Any]) -> list[str]:
    """The calls of robotconf in ``source``, as written, each once.

    Parameters
    ----------
    source : str
        Python code (an answer cell); it is parsed, never run.
    namespace : mapping
        The globals the code ran in: names are looked up there to see whether they are
        robotconf's.

    Returns
    -------
    list of str
        E.g. ``["rc.ik_all", "arm.end_effector"]``; empty when there is none or the code
        does not parse.

    Examples
    --------
    >>> import numpy as np
    >>> import robotconf as rc
    >>> arm = rc.preset("planar_2r")
    >>> names = {"rc": rc, "np": np, "arm": arm}
    >>> robotconf_calls("answer_1 = [float(q) for q in rc.ik_all(arm, [1, 1, 0]).q[0]]", names)
    ['rc.ik_all']
    >>> robotconf_calls("answer_2 = arm.end_effector([0, 1])[:2]", names)
    ['arm.end_effector']
    >>> robotconf_calls("answer_3 = np.arctan2(2.5, -1.0) - 0.3", names)
    []
    """
    try:
        tree = ast.parse(source)
    except (SyntaxError, ValueError):
        return []
    found: list[str] = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        base = _root(node.func)
        if not isinstance(base, ast.Name) or base.id not in namespace:
            continue
        value = namespace[base.id]
        if _is_ours(value):
            text = ast.unparse(node.func)
            text = text if len(text) <= _MAX_SHOWN else text[: _MAX_SHOWN - 3] + "..."
            if text not in found:
                found.append(text)
    return found


def _assigns(source: str, variable: str) -> bool:
    try:
        body = ast.parse(source).body
    except (SyntaxError, ValueError):
        return False
    for node in body:
        targets = node.targets if isinstance(node, ast.Assign) else []
        if isinstance(node, (ast.AnnAssign, ast.AugAssign)):
            targets = [node.target]
        if any(isinstance(t, ast.Name) and t.id == variable for t in targets):
            return True
    return False


def answer_cell_source(variable: str, history: list[str]) -> str | None:
    """The last input in ``history`` that assigns ``variable`` at its top level.

    >>> answer_cell_source("answer_1", ["", "x = 1", "answer_1 = x + 1", "print(answer_1)"])
    'answer_1 = x + 1'
    """
    for source in reversed(history):
        if isinstance(source, str) and _assigns(source, variable):
            return source
    return None


def own_work_calls(variable: str, namespace: Mapping[str, Any] | None = None) -> list[str]:
    """The robotconf calls of the answer cell that assigned ``variable`` last.

    Parameters
    ----------
    variable : str
        The answer variable.
    namespace : mapping, optional
        The notebook's globals, holding IPython's input history ``In``; by default the
        running IPython kernel's. Outside IPython (no history) nothing is found.

    Returns
    -------
    list of str

    Examples
    --------
    >>> import robotconf as rc
    >>> history = ["", "answer_4 = rc.jacobian(robot, [0, 0])[:2]"]
    >>> own_work_calls("answer_4", {"In": history, "rc": rc})
    ['rc.jacobian']
    """
    if namespace is None:
        try:
            from IPython import get_ipython
        except ImportError:  # pragma: no cover (IPython comes with Jupyter)
            return []
        shell = get_ipython()
        if shell is None:
            return []
        namespace = shell.user_ns
    history = namespace.get("In")
    if not isinstance(history, list):
        return []
    source = answer_cell_source(variable, history)
    return [] if source is None else robotconf_calls(source, namespace)
