"""The cell designer in JupyterLab + Chromium at 1280 × 900, driven as a student drives it.

The paper's arm on a table with a fixture and a pick frame, bound to a cell file: a box
is added and typed to (60, 10, 20) mm, a LIN to ``table/pick`` added and **Run** lists
"link 3 enters 'box1' at t = 0.43 s" under its move (the core's own sentence, checked in
the kernel); a pose edit marks the run stale, ↶ takes it back, the angle switch shows the
roll in radians without changing the cell, and a page reload shows the same designer.
The file on disk holds the box and the program. When ``robotconf.scene.CellScene`` is
there, a second test looks at the 3D view: the added box changes its pixels, the
contact turns the box red at t = 1.0 s (not at t = 0.2 s), and the scene exported as HTML
opens from disk with the network cut. Set ``ROBOTCONF_DESIGNER_SHOTS`` to keep the
screenshots elsewhere than /tmp/robotconf_designer.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import numpy as np
import pytest

from robotconf import scene

from .conftest import Lab
from .lab_driver import (
    NOTEBOOK,
    open_notebook,
    pixels,
    run_cell,
    solid_red,
    wait_idle,
    write_notebook,
)

#: Where the pictures go (looked at by hand after a change of the designer).
SHOTS = Path(os.environ.get("ROBOTCONF_DESIGNER_SHOTS", "/tmp/robotconf_designer"))

SETUP = (
    "import robotconf as rc\n"
    "cell = rc.Cell(unit='mm')\n"
    "cell.add(rc.Box([120, 80, 10], pose=rc.pose([40, 0, -5]), name='table'))\n"
    "cell.add_robot('arm', rc.preset('paper'), mount='table')\n"
    "cell.add(rc.Box([14, 14, 30], pose=rc.pose([5, -25, 20]), name='fixture'), parent='table')\n"
    "cell.add_frame('pick', rc.pose([15, 20, 15]), parent='table')\n"
    "cell.save('work.json')\n"
    "designer = rc.cell_designer('work.json')"
)
#: What the kernel and the file hold after the clicks.
CHECK = (
    "saved, programs = rc.load_cell('work.json', with_programs=True)\n"
    "print('box', *saved.pose_of('box1')[:3, 3].tolist())\n"
    "moves, options = programs['arm']\n"
    "print('program', type(moves[0]).__name__, moves[0].frame)\n"
    "print('contact', designer.run.check.contacts[0].message)"
)
#: The row of the added box: the cell's entries are table, arm, fixture, table/pick, box1.
BOX = "entry[4]"
#: The contact the LIN makes with the box (the core's sentence).
CONTACT = "move 1 (LIN): link 3 enters 'box1' at t = 0.43 s, 7.48 mm deep, until t = 1.70 s"


def _in(page, selector: str):  # type: ignore[no-untyped-def]
    return page.locator(f"{NOTEBOOK} {selector}").first


def _type(page, key: str, value: str) -> None:  # type: ignore[no-untyped-def]
    """Type into a number box and press Enter (the kernel gets the text)."""
    box = _in(page, f"[data-key='{key}'] input.rc-box")
    box.fill(value)
    box.press("Enter")
    wait_idle(page)


def _click(page, key: str) -> None:  # type: ignore[no-untyped-def]
    _in(page, f"button[data-key='{key}']").click()
    wait_idle(page)


def _tab(page, title: str) -> None:  # type: ignore[no-untyped-def]
    _in(page, f".robotconf-cell-designer .lm-TabBar-tab:has-text('{title}')").click()
    wait_idle(page)


def _output(page, cell: int) -> str:  # type: ignore[no-untyped-def]
    return page.locator(f"{NOTEBOOK} .jp-Cell").nth(cell).locator(".jp-OutputArea").inner_text()


def _shot(page, name: str) -> None:  # type: ignore[no-untyped-def]
    SHOTS.mkdir(parents=True, exist_ok=True)
    page.screenshot(path=str(SHOTS / name))


def _build_the_program(page) -> None:  # type: ignore[no-untyped-def]
    """Add box1 at (60, 10, 20) mm, a LIN to table/pick, and Run."""
    _click(page, "add.box")
    _in(page, f"[data-key='{BOX}.name'] input").wait_for(timeout=30_000)
    for k, value in enumerate(("60", "10", "20")):
        _type(page, f"{BOX}.pose{k}", value)
    _tab(page, "Programs")
    _in(page, "[data-key='program[0].add_kind'] select").select_option("LIN")
    wait_idle(page)
    _click(page, "program[0].add")
    _in(page, "[data-key='move[0].target'] select").select_option(label="frame table/pick")
    wait_idle(page)
    _click(page, "run")


def test_designer_in_the_page(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    write_notebook(lab.root / "designer.ipynb", [SETUP, CHECK])
    open_notebook(page, lab.url("designer.ipynb"))
    run_cell(page, 0)
    _in(page, ".robotconf-cell-table").wait_for(timeout=60_000)
    wait_idle(page)
    _shot(page, "designer_start.png")

    _build_the_program(page)
    contact = _in(page, ".robotconf-cell-contact")
    contact.wait_for(timeout=30_000)
    assert contact.inner_text() == CONTACT
    assert "cycle" in _in(page, ".robotconf-cell-cycle").inner_text()
    _shot(page, "designer_run.png")

    run_cell(page, 1)
    wait_idle(page)
    out = _output(page, 1)
    assert "box 60.0 10.0 20.0" in out and "program LIN table/pick" in out, out
    assert f"contact {CONTACT}" in out, out

    # An edit after the run: the run is stale; undo brings the run back as it was.
    _tab(page, "Cell")
    _type(page, f"{BOX}.pose0", "80")
    _tab(page, "Programs")
    assert _in(page, ".robotconf-cell-stale").is_visible()
    _in(page, ".robotconf-undo").click()
    wait_idle(page)
    _in(page, ".robotconf-cell-contact").wait_for(timeout=30_000)
    assert page.locator(f"{NOTEBOOK} .robotconf-cell-stale").count() == 0

    # Degrees to radians: the yaw box shows radians, the cell does not change.
    _tab(page, "Cell")
    _type(page, f"{BOX}.pose5", "90")
    _in(page, ".robotconf-angle-unit button:has-text('rad')").click()
    wait_idle(page)
    yaw = float(_in(page, f"[data-key='{BOX}.pose5'] input.rc-box").input_value())
    assert yaw == pytest.approx(np.pi / 2, abs=1e-3), yaw
    _shot(page, "designer_radians.png")

    # The reach map: switched on, its count stated (the view draws it).
    _tab(page, "Reach map")
    _in(page, ".robotconf-reach-on input").check()
    wait_idle(page)
    summary = _in(page, ".robotconf-reach-summary").inner_text()
    assert re.match(r"arm reaches \d+ of \d+ voxels", summary), summary
    _shot(page, "designer_reach.png")
    _tab(page, "Cell")

    # A reload of the page (notebook saved, same kernel) shows the same designer, drawn
    # from the kernel's state.
    page.locator(f"{NOTEBOOK} .jp-Cell").nth(1).locator(".jp-InputPrompt").click()
    page.keyboard.press("Control+s")  # the outputs must be in the file to come back
    page.wait_for_timeout(1000)
    page.reload()
    page.wait_for_selector(f"{NOTEBOOK} .robotconf-cell-table", timeout=90_000)
    wait_idle(page)
    assert _in(page, f"[data-key='{BOX}.name'] input").input_value() == "box1"
    _shot(page, "designer_reloaded.png")
    assert not page.errors, page.errors


@pytest.mark.skipif(
    not hasattr(scene, "CellScene"), reason="the 3D view of a cell (robotconf.scene.CellScene)"
)
def test_designer_view_shows_the_box_and_the_contact(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    write_notebook(
        lab.root / "view.ipynb",
        [
            SETUP.replace("work.json", "view.json"),
            "designer.scene.pause()\ndesigner.scene.seek(0.2)",
            "designer.scene.seek(1.0)",
            "designer.export_html('designer.html')",
        ],
    )
    open_notebook(page, lab.url("view.ipynb"))
    run_cell(page, 0)
    page.wait_for_selector(f"{NOTEBOOK} [data-robotconf-scene='ready'] canvas", timeout=60_000)
    wait_idle(page)
    page.wait_for_timeout(1500)
    canvas = _in(page, "[data-robotconf-scene] canvas")
    before = pixels(canvas)
    _click(page, "add.box")
    page.wait_for_timeout(1000)
    after = pixels(canvas)
    h, w = min(before.shape[0], after.shape[0]), min(before.shape[1], after.shape[1])
    changed = int((np.abs(after[:h, :w] - before[:h, :w]).sum(axis=-1) > 30).sum())
    assert changed > 100, changed  # the new box is drawn

    for k, value in enumerate(("60", "10", "20")):
        _type(page, f"{BOX}.pose{k}", value)
    _tab(page, "Programs")
    _in(page, "[data-key='program[0].add_kind'] select").select_option("LIN")
    wait_idle(page)
    _click(page, "program[0].add")
    _in(page, "[data-key='move[0].target'] select").select_option(label="frame table/pick")
    wait_idle(page)
    _click(page, "run")
    run_cell(page, 1)
    wait_idle(page)
    page.wait_for_timeout(1000)
    clear = int(solid_red(pixels(canvas)).sum())
    run_cell(page, 2)
    wait_idle(page)
    hit = clear
    for _ in range(40):
        hit = int(solid_red(pixels(canvas)).sum())
        if hit > clear + 200:
            break
        page.wait_for_timeout(250)
    assert hit > clear + 200, (clear, hit)  # the box is red while link 3 is inside it
    _shot(page, "designer_view_contact.png")

    run_cell(page, 3)
    wait_idle(page)
    offline = page.context.new_page()
    offline.route(
        "**/*",
        lambda route: (
            route.abort() if not route.request.url.startswith("file:") else route.continue_()
        ),
    )
    offline.goto((lab.root / "designer.html").as_uri())
    offline.wait_for_selector("body[data-robotconf-scene='ready']", timeout=30_000)
    assert offline.locator("#scene canvas").count() == 1
    assert not page.errors, page.errors
