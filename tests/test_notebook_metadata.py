"""The notebooks `make lab` opens carry the kernel's description as ipykernel gives it.

JupyterLab writes the kernel's ``kernelspec`` and ``language_info`` into a notebook as
soon as the kernel starts; a notebook that holds something else shows the unsaved-changes
dot before the student has done anything.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

NOTEBOOKS = sorted((Path(__file__).parents[1] / "notebooks").glob("*.ipynb"))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_the_notebook_holds_what_the_kernel_reports(path: Path) -> None:
    from ipykernel.ipkernel import IPythonKernel

    metadata = json.loads(path.read_text("utf-8"))["metadata"]
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
