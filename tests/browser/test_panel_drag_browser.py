"""A slider drag in the browser: the form sends the positions on the way, the last one
wins, and a software-rendered 3D pane skips edge smoothing."""

from __future__ import annotations

import re

import numpy as np

from .conftest import Lab
from .lab_driver import (
    control,
    drag_slider,
    open_notebook,
    output_text,
    run_cell,
    wait_idle,
    write_notebook,
)

CELLS = [
    'import robotconf as rc\npanel = rc.configurator(rc.preset("paper"))',
    "print('received', panel.editor.form.received)\n"
    "print('q2', repr(float(panel.robot.q[1])))\n"
    "print('ee', *map(repr, panel.robot.end_effector().tolist()))",
]


def test_a_mouse_drag_reaches_the_kernel_and_the_robot_ends_where_the_handle_stops(
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

    # A drag of 60 px in 15 moves, without pauses: several positions on the way.
    shown = drag_slider(page, "modules[1].q", 60)
    assert shown > 10, shown  # 60 px of a 150-px slider over ±180° is tens of degrees
    wait_idle(page)
    page.wait_for_timeout(1000)
    q = control(page, "modules[1].q")
    slider = float(q.locator("input.rc-slider").input_value())
    box = float(q.locator("input.rc-box").input_value())
    assert slider == box == shown, (slider, box, shown)  # the last position won

    run_cell(page, 1)
    text = output_text(page, 1)
    received = int(re.search(r"received (\d+)", text).group(1))  # type: ignore[union-attr]
    assert received >= 3, text  # the positions on the way reached the kernel, not only the last
    q2 = float(re.search(r"q2 (\S+)", text).group(1))  # type: ignore[union-attr]
    np.testing.assert_allclose(q2, np.deg2rad(shown), rtol=1e-12)
    # The paper arm with q2 turned: the tip at (70 cos q2, 0, 20 − 70 sin q2).
    ee = [float(v) for v in re.search(r"ee (.*)", text).group(1).split()]  # type: ignore[union-attr]
    np.testing.assert_allclose(ee, [70 * np.cos(q2), 0, 20 - 70 * np.sin(q2)], atol=1e-9)
    assert not page.errors, page.errors
