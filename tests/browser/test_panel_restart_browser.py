"""A panel bound to a file survives a kernel restart, and an export downloads in the page.

In JupyterLab: ``rc.configurator("bound.json")``, move q1 with the keyboard on its slider
(a burst of values, as a drag sends), restart the kernel, run the cell again: the panel
comes back with q1 where it was. Then the URDF export's link downloads the robot.
"""

from __future__ import annotations

import math
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

import robotconf as rc

from .conftest import Lab
from .lab_driver import NOTEBOOK, ee_numbers, open_notebook, run_cell, step_slider, write_notebook

CELLS = ['import robotconf as rc\npanel = rc.configurator("bound.json")']
#: q1 after 30 presses of → on its slider (1° steps): the paper's arm turned about z.
Q1 = 30.0
EE = [70 * math.cos(math.radians(Q1)), 70 * math.sin(math.radians(Q1)), 20.0]


def _saved_q1(path: Path) -> float | None:
    try:
        return float(rc.load_setup(path).robot.q[0])
    except (OSError, ValueError):
        return None


def _is_q1(value: float | None) -> bool:
    return value is not None and math.isclose(value, math.radians(Q1), abs_tol=1e-9)


def _restart_kernel(page) -> None:  # type: ignore[no-untyped-def]
    """Restart the kernel as a student does: the notebook toolbar's ⟳, then confirm.

    Not through the server's REST API: JupyterLab sends widget messages to a kernel
    subshell it made, and a restart it did not ask for leaves it sending them to the old
    kernel's subshell, which the new kernel drops (the page would look alive but deaf).
    """
    page.get_by_role("button", name="Restart the kernel", exact=True).first.click()
    page.get_by_role("button", name="Confirm Kernel Restart").click()


def test_bound_panel_survives_a_kernel_restart_and_exports(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    started = time.monotonic()
    write_notebook(lab.root / "bound.ipynb", CELLS)
    bound = lab.root / "bound.json"
    open_notebook(page, lab.url("bound.ipynb"))
    run_cell(page, 0)
    status = page.locator(f"{NOTEBOOK} .robotconf-file").first
    status.wait_for(timeout=60_000)
    assert "Every change is saved to bound.json" in status.inner_text()
    np.testing.assert_allclose(ee_numbers(page), [70, 0, 20])

    step_slider(page, "modules[0].q", int(Q1))
    for _ in range(50):
        if np.allclose(ee_numbers(page), EE, atol=1e-3):
            break
        page.wait_for_timeout(100)
    np.testing.assert_allclose(ee_numbers(page), EE, atol=1e-3)
    # The last value of the burst reaches the file within the save interval.
    deadline = time.monotonic() + 10
    while not _is_q1(_saved_q1(bound)) and time.monotonic() < deadline:
        page.wait_for_timeout(100)
    assert _is_q1(_saved_q1(bound)), _saved_q1(bound)

    _restart_kernel(page)
    page.get_by_text("Python 3 (ipykernel) | Idle").wait_for(timeout=60_000)
    cell = page.locator(f"{NOTEBOOK} .jp-Cell").first
    cell.locator(".jp-InputPrompt").click()
    page.keyboard.press("Shift+Enter")
    # Only the new panel says it loaded the file (the old one said it saved to it).
    loaded = page.locator(f"{NOTEBOOK} .robotconf-file", has_text="Loaded from bound.json")
    loaded.wait_for(timeout=60_000)
    assert page.locator(f"{NOTEBOOK} .robotconf-ee").count() == 1
    np.testing.assert_allclose(ee_numbers(page), EE, atol=1e-3)

    page.locator(f"{NOTEBOOK} .lm-TabBar-tab", has_text="Save / Load").first.click()
    page.locator(f"{NOTEBOOK} .robotconf-export-urdf").first.click()
    link = page.locator(f'{NOTEBOOK} a[download$=".urdf"]').first
    link.wait_for(timeout=30_000)
    with page.expect_download(timeout=30_000) as download:
        link.click()
    # The robot's name, "paper (RzRyRy)", made a safe file name.
    assert download.value.suggested_filename == "paper_RzRyRy.urdf"
    root = ET.fromstring(Path(download.value.path()).read_bytes())
    moving = [j.get("name") for j in root.iter("joint") if j.get("type") != "fixed"]
    assert moving == ["q1", "q2", "q3"]
    assert not page.errors, page.errors
    assert time.monotonic() - started < 60
