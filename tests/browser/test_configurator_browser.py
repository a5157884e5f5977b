"""The configurator notebook in JupyterLab: change widgets in the browser, see the
printed end-effector and the 3D picture follow."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from .conftest import Lab, copy_notebook
from .lab_driver import SOLID_RED_PIXELS, open_notebook, pixels, red_centroid, red_moved, run_cell

NOTEBOOK = Path(__file__).parents[2] / "notebooks" / "configurator.ipynb"


def _ee(page) -> np.ndarray:  # type: ignore[no-untyped-def]
    text = page.locator(".robotconf-ee").first.inner_text()
    numbers = re.search(r"p_EE = \(([^)]*)\)", text)
    assert numbers, text
    return np.array([float(v) for v in numbers.group(1).split(",")])


def test_configurator_widgets_drive_the_robot(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    name = copy_notebook(NOTEBOOK, lab)
    open_notebook(page, lab.url(name))
    run_cell(page, 1)  # cell 0 is the explanation
    page.wait_for_selector("[data-robotconf-scene='ready']", timeout=60_000)
    canvas = page.locator("[data-robotconf-scene] canvas").first
    np.testing.assert_allclose(_ee(page), [70, 0, 20])  # the paper's parking position
    page.wait_for_timeout(1200)
    count, start = red_centroid(pixels(canvas))
    assert count >= SOLID_RED_PIXELS, "no red end-effector in the 3D pane"

    # Move q2 with the keyboard on its slider (module 2's row).
    handle = page.locator(".robotconf-module-q").nth(1).locator(".noUi-handle").first
    handle.focus()
    for _ in range(30):
        handle.press("ArrowRight")
    page.wait_for_timeout(500)
    moved = _ee(page)
    assert np.linalg.norm(moved - [70, 0, 20]) > 1, moved
    assert abs(moved[1]) < 1e-9  # Ry keeps the arm in the xz plane
    count, after_slider = red_moved(page, canvas, start)
    assert count >= SOLID_RED_PIXELS and np.linalg.norm(after_slider - start) > 5

    # Module 2 becomes a rotation about x: the 30 + 40 arm lies along x, so turning it
    # about x leaves the EE at the parking position while the frames in the picture turn.
    page.locator(".robotconf-module-kind select").nth(1).select_option(label="1 Rx")
    page.wait_for_timeout(500)
    np.testing.assert_allclose(_ee(page), [70, 0, 20], atol=1e-3)
    count, after_type = red_moved(page, canvas, after_slider)
    assert count >= SOLID_RED_PIXELS and np.linalg.norm(after_type - after_slider) > 5

    # Module 3 about z instead: now y changes.
    page.locator(".robotconf-module-kind select").nth(2).select_option(label="3 Rz")
    handle3 = page.locator(".robotconf-module-q").nth(2).locator(".noUi-handle").first
    handle3.focus()
    for _ in range(30):
        handle3.press("ArrowRight")
    page.wait_for_timeout(500)
    assert abs(_ee(page)[1]) > 1
    assert not page.errors, page.errors
