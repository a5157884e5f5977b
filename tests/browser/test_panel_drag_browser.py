"""A slider drag in the browser: the page relays every position, the last one wins, and a
software-rendered 3D pane skips edge smoothing."""

from __future__ import annotations

import re

import numpy as np

from .conftest import Lab
from .lab_driver import NOTEBOOK, open_notebook, run_cell, wait_idle, write_notebook

CELLS = [
    'import robotconf as rc\npanel = rc.configurator(rc.preset("paper"))',
    "row = panel.modules.rows[1]\n"
    "print('relayed', panel.modules.drag_relay.received)\n"
    "print('q2', repr(float(panel.robot.q[1])), 'box', row.q.box.value)\n"
    "print('ee', *map(repr, panel.robot.end_effector().tolist()))",
]


def _output(page, cell: int) -> str:  # type: ignore[no-untyped-def]
    return page.locator(f"{NOTEBOOK} .jp-Cell").nth(cell).locator(".jp-OutputArea").inner_text()


def test_a_mouse_drag_is_relayed_and_the_robot_ends_where_the_handle_stops(
    lab: Lab,
    page,  # type: ignore[no-untyped-def]
) -> None:
    write_notebook(lab.root / "drag.ipynb", CELLS)
    open_notebook(page, lab.url("drag.ipynb"))
    run_cell(page, 0)
    page.wait_for_selector("[data-robotconf-scene='ready']", timeout=60_000)
    # Under Chromium's software WebGL the pane draws without multisampling.
    assert (
        page.locator("[data-robotconf-scene] canvas").first.get_attribute("data-antialias")
        == "false"
    )

    handle = page.locator(".robotconf-module-q").nth(1).locator(".noUi-handle").first
    # At the bottom of the notebook's view, as a user scrolls it: the pinned 3D pane
    # covers the top (scroll_into_view_if_needed would put the handle under it).
    handle.evaluate("element => element.scrollIntoView({ block: 'end' })")
    page.wait_for_timeout(300)
    box = handle.bounding_box()
    assert box is not None
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    for dx in range(4, 61, 4):  # a drag of 60 px in 15 moves, without pauses
        page.mouse.move(x + dx, y)
    page.mouse.up()
    wait_idle(page)
    page.wait_for_timeout(1000)
    shown = float(handle.get_attribute("aria-valuenow") or "nan")
    assert shown > 10, shown  # 60 px of a 150-px slider over ±180° is tens of degrees

    run_cell(page, 1)
    text = _output(page, 1)
    relayed = int(re.search(r"relayed (\d+)", text).group(1))  # type: ignore[union-attr]
    assert relayed >= 1, text  # the positions went through the relay, not only ipywidgets
    q2 = float(re.search(r"q2 (\S+)", text).group(1))  # type: ignore[union-attr]
    box_value = float(re.search(r"box (\S+)", text).group(1))  # type: ignore[union-attr]
    assert box_value == shown, text  # the last position won over every earlier copy
    np.testing.assert_allclose(q2, np.deg2rad(shown), rtol=1e-12)
    # The paper arm with q2 turned: the tip at (70 cos q2, 0, 20 − 70 sin q2).
    ee = [float(v) for v in re.search(r"ee (.*)", text).group(1).split()]  # type: ignore[union-attr]
    np.testing.assert_allclose(ee, [70 * np.cos(q2), 0, 20 - 70 * np.sin(q2)], atol=1e-9)
    assert not page.errors, page.errors
