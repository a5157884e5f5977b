"""An nbgrader autograde step: exercises flagged by a test cell go to manual grading.

nbgrader scores an autograder test cell by its output alone and never asks for a
person. A released test cell that finds robotconf's own answer in the answer cell
(:mod:`robotconf.grading.rubric._shortcuts`) prints :data:`~robotconf.grading.FLAG`
and earns 0; this step, run by ``nbgrader autograde`` right after it saves the scores,
marks every such cell "needs manual grading" in the gradebook, so the formgrader lists
it for the teacher. ``nbgrader_config.py`` from ``robotconf course release`` adds it to
``c.Autograde.autograde_preprocessors``.

This module imports nbgrader, which students do not install: nothing else in robotconf
imports it.
"""

from __future__ import annotations

from typing import Any

from nbgrader.api import Gradebook
from nbgrader.preprocessors import NbGraderPreprocessor

from .rubric import FLAG

__all__ = ["FlagForManualGrading", "flagged_cells"]


def _text(output: Any) -> str:
    if output.get("output_type") == "stream":
        return str(output.get("text", ""))
    data = output.get("data", {})
    return str(data.get("text/plain", ""))


def flagged_cells(notebook: Any) -> list[str]:
    """Grade ids of the test cells whose output holds the flag.

    >>> cell = {"cell_type": "code", "source": "", "outputs": [
    ...     {"output_type": "stream", "name": "stdout", "text": FLAG + ": …"}],
    ...     "metadata": {"nbgrader": {"grade": True, "grade_id": "test_answer_1",
    ...                               "solution": False, "points": 1}}}
    >>> flagged_cells({"cells": [cell]})
    ['test_answer_1']
    """
    found = []
    for cell in notebook["cells"]:
        meta = cell.get("metadata", {}).get("nbgrader", {})
        if cell.get("cell_type") != "code" or not meta.get("grade") or meta.get("solution"):
            continue
        if any(FLAG in _text(output) for output in cell.get("outputs", [])):
            found.append(str(meta["grade_id"]))
    return found


class FlagForManualGrading(NbGraderPreprocessor):  # type: ignore[misc]
    """Mark the flagged test cells of an autograded notebook for manual grading."""

    def preprocess(self, nb: Any, resources: Any) -> tuple[Any, Any]:
        flagged = flagged_cells(nb)
        if not flagged:
            return nb, resources
        where = resources["nbgrader"]
        with Gradebook(where["db_url"]) as gradebook:
            for grade_id in flagged:
                grade = gradebook.find_grade(
                    grade_id, where["notebook"], where["assignment"], where["student"]
                )
                grade.needs_manual_grade = True
            gradebook.db.commit()
        for grade_id in flagged:
            self.log.warning("%s: %s (robotconf called in the answer cell)", grade_id, FLAG)
        return nb, resources
