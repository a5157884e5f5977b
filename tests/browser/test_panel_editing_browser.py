"""Editing in the page as a student would: the paper's robot through the guided wizard, then
a module deleted with its trash button and brought back with ↶.

In JupyterLab the panel starts on another robot (one Tz module), so every check below
sees a change: the wizard's twelve steps (3 modules: Rz, Ry with a = (0, 0, 20), Ry with
a = (30, 0, 0), P = (40, 0, 0)) end in the summary's p_EE = (70, 0, 20), and Finish puts
R_zR_yR_y in the module list, its p_EE in the panel and its red end-effector in the 3D
pane. Deleting module 2 drops the arm to (70, 0, 0); undo brings the row and its offsets
back. Set ``ROBOTCONF_BROWSER_SHOTS`` to a folder to keep screenshots of the summary
(``wizard_summary.png``) and of the finished robot (``finished.png``).
"""

from __future__ import annotations

import os
import time
from pathlib import Path

from playwright.sync_api import expect

from .conftest import Lab
from .lab_driver import (
    NOTEBOOK,
    choose,
    click,
    control,
    open_notebook,
    pixels,
    run_cell,
    shown_value,
    solid_red,
    type_number,
    write_notebook,
)

CELLS = [
    "import robotconf as rc\n"
    'panel = rc.configurator(rc.Robot([rc.Module("Tz", a=(0, 0, 10))], end_effector=(10, 0, 0)))'
]
#: The count, three questions per module, the end-effector and the summary.
STEPS = 1 + 3 * 3 + 1 + 1
#: A slow kernel (sympy's first formula, the scene) gets this long for each answer, in ms.
WAIT = 30_000


def _in_panel(page, css_class: str):  # type: ignore[no-untyped-def]
    return page.locator(f"{NOTEBOOK} .{css_class}")


def _kinds(page) -> list[str]:  # type: ignore[no-untyped-def]
    """The module list's types as shown, module by module."""
    rows = page.locator(f"{NOTEBOOK} .robotconf-editor .rc-row.robotconf-module-row")
    return [shown_value(page, f"modules[{i}].kind") for i in range(rows.count())]


def _offsets(page, index: int) -> list[str]:  # type: ignore[no-untyped-def]
    """Module ``index``'s offset boxes (ax, ay, az) as shown."""
    return [shown_value(page, f"modules[{index}].{name}") for name in ("ax", "ay", "az")]


def _red_end_effector(page, canvas) -> int:  # type: ignore[no-untyped-def]
    """The end-effector's red pixels in the 3D pane, polled until drawn (or 15 s passed)."""
    count = 0
    for _ in range(60):
        count = int(solid_red(pixels(canvas)).sum())
        if count > 10:
            break
        page.wait_for_timeout(250)
    return count


def _answer_step(page, step: int, question: str) -> None:  # type: ignore[no-untyped-def]
    """Wait until the wizard shows step ``step`` (1-based) asking ``question``."""
    expect(_in_panel(page, "robotconf-wizard-title")).to_contain_text(
        f"Step {step} of {STEPS}", timeout=WAIT
    )
    expect(page.locator(NOTEBOOK).get_by_text(question).first).to_be_visible(timeout=WAIT)


def _next(page) -> None:  # type: ignore[no-untyped-def]
    click(page, "wizard.next")


def _module(page, index: int, kind: str, offsets: tuple[float, float, float]) -> None:  # type: ignore[no-untyped-def]
    """Module ``index`` (0-based): its type, its offsets and q = 0, step by step."""
    first = 2 + 3 * index
    number = index + 1
    _answer_step(page, first, f"Module {number}: which movement?")
    labels = {"Rz": "3 Rz", "Ry": "2 Ry"}
    choose(page, f"wizard.modules[{index}].kind", labels[kind])
    axis = kind[1]
    _answer_step(page, first, f"the module's own {axis} axis")
    _next(page)
    _answer_step(page, first + 1, f"Module {number} ({kind}): where is its frame origin")
    expect(_in_panel(page, "rc-control.robotconf-wizard-offset")).to_have_count(3, timeout=WAIT)
    for name, value in zip(("ax", "ay", "az"), offsets, strict=True):
        type_number(page, f"wizard.modules[{index}].{name}", value)
    # The numeric A_i follows the boxes: its last column is the typed offsets.
    preview = _in_panel(page, "robotconf-wizard-preview")
    for value in offsets:
        expect(preview).to_contain_text(f"{value:g} ]", timeout=WAIT)
    _next(page)
    _answer_step(page, first + 2, f"Module {number} ({kind}): its coordinate q")
    type_number(page, f"wizard.modules[{index}].q", 0.0)
    expect(preview).to_contain_text(f"A_{number} at q{number} = 0°", timeout=WAIT)
    _next(page)


def _shoot_below_the_view(page, path: Path) -> None:  # type: ignore[no-untyped-def]
    """Screenshot with the wizard scrolled up to the sticky 3D view's lower edge, as a
    student scrolls to read it (scrolled into view, it would sit under the view)."""
    wizard = _in_panel(page, "robotconf-wizard").first
    wizard.scroll_into_view_if_needed()
    view = page.locator(f"{NOTEBOOK} .robotconf-view").first.bounding_box()
    top = wizard.bounding_box()
    assert view is not None and top is not None
    page.mouse.move(view["x"] + 10, view["y"] + view["height"] + 20)
    page.mouse.wheel(0, top["y"] - (view["y"] + view["height"]))
    page.wait_for_timeout(500)
    page.screenshot(path=str(path))


def test_the_papers_robot_through_the_wizard_and_a_delete_undone(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    write_notebook(lab.root / "editing.ipynb", CELLS)
    open_notebook(page, lab.url("editing.ipynb"))
    started = time.monotonic()
    run_cell(page, 0)
    page.wait_for_selector("[data-robotconf-scene='ready']", timeout=60_000)
    ee = _in_panel(page, "robotconf-ee").first
    expect(ee).to_contain_text("p_EE = (10, 0, 10)", timeout=WAIT)
    canvas = page.locator(f"{NOTEBOOK} [data-robotconf-scene] canvas").first

    # -- the paper's questionnaire, clicked through ---------------------------------------
    choose(page, "mode", "Guided")
    _answer_step(page, 1, "How many modules")
    type_number(page, "wizard.count", 3)
    _next(page)
    _module(page, 0, "Rz", (0, 0, 0))
    _module(page, 1, "Ry", (0, 0, 20))
    _module(page, 2, "Ry", (30, 0, 0))
    _answer_step(page, STEPS - 1, "The end-effector point P")
    expect(_in_panel(page, "rc-control.robotconf-wizard-point")).to_have_count(3, timeout=WAIT)
    for name, value in zip(("Px", "Py", "Pz"), (40, 0, 0), strict=True):
        type_number(page, f"wizard.end_effector.{name}", value)
    _next(page)  # at once, as a student would: the summary shows whether Px arrived first
    _answer_step(page, STEPS, "The robot you described")
    summary = _in_panel(page, "robotconf-wizard-summary")
    expect(summary).to_contain_text("p_EE = (70, 0, 20)", timeout=WAIT)
    finish = control(page, "wizard.next")
    expect(finish).to_have_text("Finish")
    if shots := os.environ.get("ROBOTCONF_BROWSER_SHOTS"):
        _shoot_below_the_view(page, Path(shots) / "wizard_summary.png")
    click(page, "wizard.next")

    # The list editor shows the robot, the panel its p_EE and the scene its end-effector.
    expect(ee).to_contain_text("p_EE = (70, 0, 20)", timeout=WAIT)
    rows = _in_panel(page, "rc-row.robotconf-module-row")
    expect(rows).to_have_count(3, timeout=WAIT)
    assert _kinds(page) == ["3 Rz", "2 Ry", "2 Ry"]
    # The wizard's preview grew the robot a module at a time, and the scene reframes only
    # when the size changes more than twofold: the last step (P, 50 → 90 long) kept the
    # camera and the end-effector outside the pane. "fit" frames it, as a student would.
    page.locator(f"{NOTEBOOK} .robotconf-scene-controls button", has_text="fit").click()
    assert _red_end_effector(page, canvas) > 10, "no red end-effector in the 3D pane"
    if shots:
        page.screenshot(path=str(Path(shots) / "finished.png"))

    # -- module 2 deleted with its trash button, and undone --------------------------------
    assert _offsets(page, 1) == ["0", "0", "20"]
    click(page, "modules[1].delete")
    expect(ee).to_contain_text("p_EE = (70, 0, 0)", timeout=WAIT)  # l1 = 20 went with it
    expect(rows).to_have_count(2, timeout=WAIT)
    assert _kinds(page) == ["3 Rz", "2 Ry"]
    click(page, "undo")
    expect(ee).to_contain_text("p_EE = (70, 0, 20)", timeout=WAIT)
    expect(rows).to_have_count(3, timeout=WAIT)
    assert _kinds(page) == ["3 Rz", "2 Ry", "2 Ry"]
    assert _offsets(page, 1) == ["0", "0", "20"]
    assert _offsets(page, 2) == ["30", "0", "0"]
    assert not page.errors, page.errors
    assert time.monotonic() - started < 60
