"""The Reach tab in JupyterLab + Chromium at 1280 × 900: a typed target moves the robot
(p_EE changes) and the closed-form solutions appear as ghosts in the 3D pane."""

from __future__ import annotations

import re

import numpy as np

from .conftest import Lab
from .lab_driver import NOTEBOOK, open_notebook, pixels, run_cell, wait_idle, write_notebook

#: Where the Reach tab's picture goes (looked at by hand after a change of the tab).
SCREENSHOT = "/tmp/robotconf_reach_tab.png"

CELLS = [
    "import numpy as np\nimport robotconf as rc\n"
    # Whole degrees: every q sits on a slider notch, as a student's robot would.
    'puma = rc.preset("puma560").with_q(np.radians([0, 35, -50, 0, 40, 0]))\n'
    'panel = rc.configurator(puma, length_unit="m")',
    "result = panel.reach.result\n"
    "print('ghosts', panel.scene.ghost_count, 'buttons', len(panel.reach.solutions.buttons))\n"
    "print('target', *map(repr, panel.reach.target.target()[:3, 3].tolist()))\n"
    "print('solved', result.reason, *map(repr, panel.robot.end_effector(result.q).tolist()))\n"
    "print('offset', repr(float(np.degrees(np.abs(panel.robot.q - result.q)).max())))",
]


def _output(page, cell: int) -> str:  # type: ignore[no-untyped-def]
    return page.locator(f"{NOTEBOOK} .jp-Cell").nth(cell).locator(".jp-OutputArea").inner_text()


def _click(locator) -> None:  # type: ignore[no-untyped-def]
    """Click at the bottom of the notebook's view, as a user scrolls to it: the pinned 3D
    pane covers the top (scroll_into_view_if_needed could put the element under it)."""
    locator.evaluate("element => element.scrollIntoView({ block: 'end' })")
    locator.page.wait_for_timeout(300)
    locator.click()


def _changed(before: np.ndarray, after: np.ndarray) -> int:
    """Pixels whose colour moved by more than a little (anti-aliasing aside)."""
    return int((np.abs(after - before).sum(axis=-1) > 30).sum())


def test_a_target_moves_the_robot_and_shows_the_ghosts(
    lab: Lab,
    page,  # type: ignore[no-untyped-def]
) -> None:
    write_notebook(lab.root / "reach.ipynb", CELLS)
    open_notebook(page, lab.url("reach.ipynb"))
    run_cell(page, 0)
    page.wait_for_selector("[data-robotconf-scene='ready'] canvas", timeout=60_000)
    wait_idle(page)
    ee_label = page.locator(".robotconf-ee").first
    ee_before = ee_label.inner_text()

    _click(page.locator(f"{NOTEBOOK} .lm-TabBar-tab", has_text="Reach").first)
    tab = page.locator(".robotconf-reach-tab").first
    tab.wait_for(timeout=30_000)
    # Pose mode: a 6R arm has closed-form solutions for a pose (its 8 ghosts).
    _click(tab.locator(".robotconf-reach-mode button", has_text="pose"))
    wait_idle(page)
    canvas = page.locator("[data-robotconf-scene] canvas").first
    page.wait_for_timeout(1000)
    before = pixels(canvas)

    x_box = tab.locator(".robotconf-reach-x-box input").first
    x_now = float(x_box.input_value())
    # Between two slider notches: the robot must reach exactly this, not a notch.
    x_box.fill(f"{x_now - 0.1234:.4f}")
    x_box.press("Enter")
    wait_idle(page)
    page.wait_for_function(
        "(text) => document.querySelector('.robotconf-ee').innerText !== text",
        arg=ee_before,
        timeout=30_000,
    )
    assert ee_label.inner_text() != ee_before
    page.wait_for_timeout(1500)
    with_ghosts = pixels(canvas)
    assert _changed(before, with_ghosts) > 2000  # the robot moved, the ghosts appeared

    # The ghosts alone: switching them off changes the picture, the robot stays.
    _click(tab.locator(".robotconf-reach-ghosts input"))
    wait_idle(page)
    page.wait_for_timeout(1500)
    without = pixels(canvas)
    ghost_pixels = _changed(without, with_ghosts)
    assert ghost_pixels > 500, ghost_pixels
    _click(tab.locator(".robotconf-reach-ghosts input"))
    wait_idle(page)
    page.wait_for_timeout(1000)

    run_cell(page, 1)
    text = _output(page, 1)
    assert re.search(r"ghosts 8 buttons 8", text), text
    typed = round(x_now - 0.1234, 4)
    target = [float(v) for v in re.search(r"target (.*)", text).group(1).split()]  # type: ignore[union-attr]
    assert target[0] == typed, (target, typed)  # the page's slider did not round it
    solved = re.search(r"solved (\S+) (.*)", text)
    assert solved is not None and solved.group(1) == "converged", text
    np.testing.assert_allclose([float(v) for v in solved.group(2).split()], target, atol=1e-6)
    # The robot stands exactly on that solution: the editors' q sliders show it too, and
    # the notch each page slider snaps it to and sends back is not taken as a move.
    offset = float(re.search(r"offset (\S+)", text).group(1))  # type: ignore[union-attr]
    assert offset <= 1e-9, text

    # The tab as a student sees it, for a look by eye: nothing clipped or overlapping.
    tab.evaluate("element => element.scrollIntoView({ block: 'end' })")
    page.wait_for_timeout(500)
    page.screenshot(path=SCREENSHOT)
    box = tab.bounding_box()
    output = page.locator(f"{NOTEBOOK} .jp-Cell").nth(0).locator(".jp-OutputArea").bounding_box()
    assert box is not None and output is not None
    assert box["x"] + box["width"] <= output["x"] + output["width"] + 1
    assert not page.errors, page.errors
