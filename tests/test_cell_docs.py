"""docs/cell.md's examples run in order, in one namespace, and say what the page says."""

from __future__ import annotations

import pathlib
import re

import numpy as np
import pytest

DOC = pathlib.Path(__file__).resolve().parents[1] / "docs" / "cell.md"

pytestmark = pytest.mark.filterwarnings("ignore:the program has:UserWarning")


def test_every_example_of_the_cell_page_runs(capsys):
    blocks = re.findall(r"```python\n(.*?)```", DOC.read_text(encoding="utf-8"), flags=re.S)
    assert len(blocks) >= 10
    namespace: dict = {}
    for block in blocks:
        # Our own documentation file, not user input.
        exec(compile(block, str(DOC), "exec"), namespace)  # noqa: S102
    printed = capsys.readouterr().out
    assert "clearance 14.4 mm: arm link 3 – box1" in printed
    assert (
        "move 2 (PTP): link 3 enters 'box1' at t = 1.02 s, 13 mm deep, until t = 1.60 s" in printed
    )
    assert "a: move 1 (LIN): link 3 meets robot 'b' link 3 at t = 2.21 s" in printed
    assert (
        "(50, 0, 2): not reachable: only with the shoulder front, elbow up, which hits 'table'"
        in printed
    )
    assert "cycle time 3.5 s (a: 3.5 s, b: 3.1 s)" in printed and "no contact" in printed
    cell, again = namespace["cell"], namespace["again"]
    assert np.array_equal(again.pose_of("table/pick"), cell.pose_of("table/pick"))
    assert namespace["rmap"].shape == (8, 8, 4) and int(namespace["rmap"].reachable.sum()) == 110
    assert namespace["plan"].best is not None
