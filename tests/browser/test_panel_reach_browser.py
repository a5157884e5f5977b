"""The Reach tab in JupyterLab + Chromium at 1280 × 900: a typed target moves the robot
(p_EE changes) and the closed-form solutions appear as ghosts in the 3D pane."""

from __future__ import annotations

import re

import numpy as np

from .conftest import Lab
from .lab_driver import (
    NOTEBOOK,
    choose,
    click,
    control,
    ee_text,
    open_panel,
    output_text,
    pixels,
    reveal,
    run_cell,
    type_number,
    wait_idle,
)

#: Where the Reach tab's picture goes (looked at by hand after a change of the tab).
SCREENSHOT = "/tmp/robotconf_reach_tab.png"

CELLS = [
    "import numpy as np\nimport robotconf as rc\n"
    # Whole degrees: every q sits on a slider notch, as a student's robot would.
    'puma = rc.preset("puma560").with_q(np.radians([0, 35, -50, 0, 40, 0]))\n'
    'panel = rc.configurator(puma, length_unit="m")',
    "reach = panel.state.reach\n"
    "print('ghosts', panel.scene.ghost_count)\n"
    "print('target', *map(repr, reach.target[:3]))\n"
    "print('solved', reach.outcome.reason, *map(repr, panel.robot.end_effector().tolist()))\n"
    "offset = np.degrees(np.abs(panel.robot.q - reach.outcome.reached.q)).max()\n"
    "print('offset', repr(float(offset)))",
]


def _changed(before: np.ndarray, after: np.ndarray) -> int:
    """Pixels whose colour moved by more than a little (anti-aliasing aside)."""
    return int((np.abs(after - before).sum(axis=-1) > 30).sum())


def test_a_target_moves_the_robot_and_shows_the_ghosts(
    lab: Lab,
    page,  # type: ignore[no-untyped-def]
) -> None:
    open_panel(page, lab, "reach.ipynb", CELLS)
    ee_before = ee_text(page)

    tab_title = page.locator(f"{NOTEBOOK} .lm-TabBar-tab", has_text="Reach").first
    reveal(tab_title)
    tab_title.click()
    tab = page.locator(".rc-form.robotconf-reach-tab").first
    tab.wait_for(timeout=30_000)
    # Pose mode: a 6R arm has closed-form solutions for a pose (its 8 ghosts).
    choose(page, "reach.mode", "pose")
    wait_idle(page)
    canvas = page.locator("[data-robotconf-scene] canvas").first
    page.wait_for_timeout(1000)
    before = pixels(canvas)

    x_now = float(control(page, "reach.x").locator("input.rc-box").input_value())
    # Between two slider notches: the robot must reach exactly this, not a notch.
    type_number(page, "reach.x", f"{x_now - 0.1234:.4f}")
    wait_idle(page)
    page.wait_for_function(
        "(text) => document.querySelector('.robotconf-ee').innerText.trim() !== text",
        arg=ee_before,
        timeout=30_000,
    )
    assert ee_text(page) != ee_before
    page.wait_for_timeout(1500)
    with_ghosts = pixels(canvas)
    assert _changed(before, with_ghosts) > 2000  # the robot moved, the ghosts appeared
    assert tab.locator(".rc-button.robotconf-reach-solution").count() == 8

    # The ghosts alone: switching them off changes the picture, the robot stays.
    click(page, "reach.show_all")
    wait_idle(page)
    page.wait_for_timeout(1500)
    without = pixels(canvas)
    ghost_pixels = _changed(without, with_ghosts)
    assert ghost_pixels > 500, ghost_pixels
    click(page, "reach.show_all")
    wait_idle(page)
    page.wait_for_timeout(1000)

    run_cell(page, 1)
    text = output_text(page, 1)
    assert re.search(r"ghosts 8\b", text), text
    typed = round(x_now - 0.1234, 4)
    target = [float(v) for v in re.search(r"target (.*)", text).group(1).split()]  # type: ignore[union-attr]
    assert target[0] == typed, (target, typed)  # the page's slider did not round it
    solved = re.search(r"solved (\S+) (.*)", text)
    assert solved is not None and solved.group(1) == "converged", text
    np.testing.assert_allclose([float(v) for v in solved.group(2).split()], target, atol=1e-6)
    # The robot stands exactly on that solution: the editors' q sliders show it too, and
    # nothing the page shows came back as a move.
    offset = float(re.search(r"offset (\S+)", text).group(1))  # type: ignore[union-attr]
    assert offset <= 1e-9, text

    # The tab as a student sees it, for a look by eye: nothing clipped or overlapping.
    reveal(tab)
    page.wait_for_timeout(500)
    page.screenshot(path=SCREENSHOT)
    box = tab.bounding_box()
    output = page.locator(f"{NOTEBOOK} .jp-Cell").nth(0).locator(".jp-OutputArea").bounding_box()
    assert box is not None and output is not None
    assert box["x"] + box["width"] <= output["x"] + output["width"] + 1
    assert not page.errors, page.errors
