"""The notebooks `make lab` opens carry the kernel's description as ipykernel gives it.

JupyterLab writes the kernel's ``kernelspec`` and ``language_info`` into a notebook as
soon as the kernel starts; a notebook that holds something else shows the unsaved-changes
dot before the student has done anything. The course's lessons, exercises and solutions
(course/) and the quizzes ``robotconf course quiz`` writes hold the same.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).parents[1]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))
COURSE_NOTEBOOKS = sorted(
    path for path in (ROOT / "course").rglob("*.ipynb") if ".ipynb_checkpoints" not in path.parts
)


def _assert_kernel_metadata(metadata: dict[str, Any]) -> None:
    from ipykernel.ipkernel import IPythonKernel

    assert metadata["kernelspec"] == {
        "display_name": "Python 3 (ipykernel)",
        "language": "python",
        "name": "python3",
    }
    reported = dict(IPythonKernel.language_info)
    shown = dict(metadata["language_info"])
    # The Python version is the machine's: the one the notebooks were last saved with.
    assert shown.pop("version").count(".") == 2
    reported.pop("version")
    assert shown == reported


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_the_notebook_holds_what_the_kernel_reports(path: Path) -> None:
    _assert_kernel_metadata(json.loads(path.read_text("utf-8"))["metadata"])


@pytest.mark.parametrize(
    "path", COURSE_NOTEBOOKS, ids=lambda p: p.relative_to(ROOT / "course").as_posix()
)
def test_a_course_notebook_holds_what_the_kernel_reports(path: Path) -> None:
    _assert_kernel_metadata(json.loads(path.read_text("utf-8"))["metadata"])


def test_the_course_has_its_notebooks() -> None:
    # 13 lessons, each a lesson, its exercises and their solutions.
    assert len(COURSE_NOTEBOOKS) == 39


def test_a_written_quiz_holds_what_the_kernel_reports(tmp_path: Path) -> None:
    from robotconf.cli import main

    assert main(["course", "quiz", str(tmp_path), "--lessons", "12"]) == 0
    written = sorted(tmp_path.rglob("*.ipynb"))
    assert len(written) == 2  # the students' copy and its solutions
    for path in written:
        _assert_kernel_metadata(json.loads(path.read_text("utf-8"))["metadata"])
