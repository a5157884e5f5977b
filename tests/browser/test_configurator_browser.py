"""The configurator notebook in JupyterLab: change the form's controls in the browser, see
the printed end-effector and the 3D picture follow."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .conftest import Lab, copy_notebook
from .lab_driver import (
    SOLID_RED_PIXELS,
    choose,
    ee_numbers,
    open_notebook,
    pixels,
    red_centroid,
    red_moved,
    run_cell,
    shown_value,
    step_slider,
)

NOTEBOOK = Path(__file__).parents[2] / "notebooks" / "configurator.ipynb"


def _wait_ee(page, predicate, timeout_ms: int = 15_000) -> np.ndarray:  # type: ignore[no-untyped-def]
    """Poll p_EE until ``predicate(p_EE)`` holds (or time runs out); returns the last one."""
    ee = ee_numbers(page)
    for _ in range(timeout_ms // 100):
        if predicate(ee):
            break
        page.wait_for_timeout(100)
        ee = ee_numbers(page)
    return ee


def test_configurator_widgets_drive_the_robot(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    name = copy_notebook(NOTEBOOK, lab)
    open_notebook(page, lab.url(name))
    run_cell(page, 1)  # cell 0 is the explanation
    page.wait_for_selector("[data-robotconf-scene='ready']", timeout=60_000)
    canvas = page.locator("[data-robotconf-scene] canvas").first
    np.testing.assert_allclose(ee_numbers(page), [70, 0, 20])  # the paper's parking position
    page.wait_for_timeout(1200)
    count, start = red_centroid(pixels(canvas))
    assert count >= SOLID_RED_PIXELS, "no red end-effector in the 3D pane"

    # Move q2 with the keyboard on its slider (module 2's row): 30 notches of 1°.
    step_slider(page, "modules[1].q", 30)
    q2 = np.radians(30.0)
    # Ry turns the 30 + 40 arm down in the xz plane: (70 cos q2, 0, 20 − 70 sin q2).
    expected = [70 * np.cos(q2), 0, 20 - 70 * np.sin(q2)]
    moved = _wait_ee(page, lambda ee: np.allclose(ee, expected, atol=1e-3))
    np.testing.assert_allclose(moved, expected, atol=1e-3)
    assert shown_value(page, "modules[1].q") == "30"
    count, after_slider = red_moved(page, canvas, start)
    assert count >= SOLID_RED_PIXELS and np.linalg.norm(after_slider - start) > 5

    # Module 2 becomes a rotation about x: the 30 + 40 arm lies along x, so turning it
    # about x leaves the EE at the parking position while the frames in the picture turn.
    choose(page, "modules[1].kind", "1 Rx")
    back = _wait_ee(page, lambda ee: np.allclose(ee, [70, 0, 20], atol=1e-3))
    np.testing.assert_allclose(back, [70, 0, 20], atol=1e-3)
    count, after_type = red_moved(page, canvas, after_slider)
    assert count >= SOLID_RED_PIXELS and np.linalg.norm(after_type - after_slider) > 5

    # Module 3 about z instead: now y changes.
    choose(page, "modules[2].kind", "3 Rz")
    page.wait_for_timeout(500)
    step_slider(page, "modules[2].q", 30)
    turned = _wait_ee(page, lambda ee: abs(ee[1]) > 1)
    assert abs(turned[1]) > 1, turned
    assert not page.errors, page.errors
