"""The Program tab in JupyterLab + Chromium at 1280 × 900: two moves taught and edited in
the table, Run plays the program in the 3D pane with the end effector's trace, and the
violations show under the move that causes them."""

from __future__ import annotations

import numpy as np

from .conftest import Lab
from .lab_driver import (
    NOTEBOOK,
    choose,
    click,
    open_panel,
    output_text,
    pixels,
    reveal,
    run_cell,
    type_number,
    wait_idle,
)

#: Where the Program tab's picture goes (looked at by hand after a change of the tab).
SCREENSHOT = "/tmp/robotconf_program_tab.png"

CELLS = [
    'import robotconf as rc\npanel = rc.configurator(rc.preset("paper"), length_unit="mm")',
    "run = panel.state.program_run\n"
    "print('moves', *[move.kind for move in panel.program.moves])\n"
    "print('kinds', *sorted(set(run.report.kinds)))\n"
    "print('trace', panel.scene.trace_shown, 'points', *panel.scene.taught_labels)\n"
    "print('shown', panel.motion is run.motion, round(panel.motion.t[-1], 6))",
]


def _changed(before: np.ndarray, after: np.ndarray) -> int:
    """Pixels whose colour moved by more than a little (anti-aliasing aside)."""
    return int((np.abs(after - before).sum(axis=-1) > 30).sum())


def _type(page, key: str, value: str) -> None:  # type: ignore[no-untyped-def]
    type_number(page, key, value)
    wait_idle(page)


def test_taught_moves_run_with_the_trace_and_the_violations(
    lab: Lab,
    page,  # type: ignore[no-untyped-def]
) -> None:
    open_panel(page, lab, "program.ipynb", CELLS)

    tab_title = page.locator(f"{NOTEBOOK} .lm-TabBar-tab", has_text="Program").first
    reveal(tab_title)
    tab_title.click()
    tab = page.locator(".rc-form.robotconf-program-tab").first
    tab.wait_for(timeout=30_000)
    # Two moves taught where the robot stands (q = 0), both edited to q3 = −90° (the end
    # effector at (30, 0, 60) mm); P2 made a line from there: refused until it goes
    # somewhere, then 30 mm along y, far too fast for the joints.
    for _ in range(2):
        click(page, "program.add")
        wait_idle(page)
    rows = tab.locator(".rc-row.robotconf-program-row")
    assert rows.count() == 2
    first, second = rows.nth(0), rows.nth(1)
    _type(page, "program.moves[0].q2", "-90")
    _type(page, "program.moves[1].q2", "-90")
    choose(page, "program.moves[1].kind", "LIN")
    wait_idle(page)
    assert "the LIN goes nowhere" in second.inner_text()
    _type(page, "program.moves[1].point1", "30")
    assert "goes nowhere" not in second.inner_text()
    _type(page, "program.moves[1].speed", "200")
    _type(page, "program.cartesian_accel", "1000")
    canvas = page.locator("[data-robotconf-scene] canvas").first
    page.wait_for_timeout(1000)
    before = pixels(canvas)

    click(page, "program.run")
    wait_idle(page)
    page.wait_for_timeout(1500)  # the animation plays: the robot moves, the trace is drawn
    during = pixels(canvas)
    assert _changed(before, during) > 1000
    violations = second.locator(".robotconf-program-violation")
    assert "faster than its limit" in " ".join(violations.all_inner_texts())
    assert first.locator(".robotconf-program-violation").count() == 0
    assert "violation(s), at P2" in tab.locator(".robotconf-program-status").inner_text()

    run_cell(page, 1)
    text = output_text(page, 1)
    assert "moves PTP LIN" in text, text
    assert "kinds joint accel joint speed" in text, text
    assert "trace True points P1 P2" in text, text
    assert "shown True" in text, text

    # The tab as a student sees it, for a look by eye: nothing clipped or overlapping.
    reveal(tab)
    page.wait_for_timeout(500)
    page.screenshot(path=SCREENSHOT)
    box = tab.bounding_box()
    output = page.locator(f"{NOTEBOOK} .jp-Cell").nth(0).locator(".jp-OutputArea").bounding_box()
    assert box is not None and output is not None
    assert box["x"] + box["width"] <= output["x"] + output["width"] + 1
    for k in range(2):
        row = rows.nth(k).bounding_box()
        assert row is not None and row["x"] + row["width"] <= box["x"] + box["width"] + 1
    assert not page.errors, page.errors
