"""A taught PTP whose joint is then set to none, in JupyterLab + Chromium at 1280 × 900:
the row shows a dash for that joint (no raw radians under a degree heading), and the
bound file goes on saving with the robot's own value in the move."""

from __future__ import annotations

import json

from .conftest import Lab
from .lab_driver import NOTEBOOK, choose, click, control, open_panel, reveal, type_number, wait_idle

CELLS = ['import robotconf as rc\npanel = rc.configurator("held.json")']


def test_a_joint_set_to_none_shows_a_dash_and_the_file_keeps_saving(
    lab: Lab,
    page,  # type: ignore[no-untyped-def]
) -> None:
    (lab.root / "held.json").unlink(missing_ok=True)
    open_panel(page, lab, "held.ipynb", CELLS)
    type_number(page, "modules[1].q", 20)
    wait_idle(page)
    tab = page.locator(f"{NOTEBOOK} .lm-TabBar-tab", has_text="Program").first
    reveal(tab)
    tab.click()
    wait_idle(page)
    click(page, "program.add")  # taught at q2 = 20°
    wait_idle(page)
    type_number(page, "modules[1].q", 40)
    wait_idle(page)
    choose(page, "modules[1].kind", "0 none")
    wait_idle(page)

    box = control(page, "program.moves[0].q1").locator("input.rc-box")
    page.wait_for_function(
        "(e) => e.value === '—' && e.disabled", arg=box.element_handle(), timeout=15_000
    )
    assert control(page, "program.moves[0].q0").locator("input.rc-box").input_value() == "0"
    notebook = page.locator(NOTEBOOK).inner_text()
    assert "Changes not saved" not in notebook and "Every change is saved to held.json" in notebook
    saved = json.loads((lab.root / "held.json").read_text("utf-8"))
    q2 = saved["robot"]["links"][1]["q"]
    assert saved["program"]["moves"][0]["q"][1] == q2  # the robot's own value (40°)
    assert abs(q2 - 0.6981317007977318) < 1e-12
