"""A hostile robot file uploaded into the configurator in JupyterLab: no handler runs.

The file's name and the robot, module and DH link names inside it carry payloads that set
``window.__pwned`` or call ``alert`` if they ever become markup. A raw HTML widget with
the same kind of payload runs first, as a control: it proves that handlers do run on this
page, so their absence after the upload means the panel escaped the names.
"""

from __future__ import annotations

import robotconf as rc

from .conftest import Lab
from .lab_driver import (
    NOTEBOOK,
    choose,
    click,
    control,
    open_notebook,
    run_cell,
    wait_idle,
    write_notebook,
)

IMG = '<img src=x onerror="window.__pwned=1;alert(1)">'
SVG = '"><svg onload="window.__pwned=2;alert(2)">'
SCRIPT = "<script>window.__pwned=3;alert(3)</script>"
ROBOT_NAME = f"{IMG} $x$ &amp;"
MODULE_NAMES = (f"{SVG}", f"{SCRIPT} $$y$$")
DH_NAME = f"{IMG}{SVG}"
FILE_NAME = '"><img src=x onerror="window.__pwned=4;alert(4)">.json'

CELLS = [
    # The control: raw markup in an HTML widget does run its handler on this page.
    "import ipywidgets as widgets\nwidgets.HTML('<img src=x onerror=\"window.__control=1\">')",
    "import robotconf as rc\npanel = rc.configurator(rc.preset('paper'))",
]


def hostile_file() -> bytes:
    robot = rc.Robot(
        [
            rc.Module("Rz", name=MODULE_NAMES[0]),
            rc.DHLink(a=10.0, name=DH_NAME),
            rc.Module("Ry", a=(30, 0, 0), name=MODULE_NAMES[1]),
        ],
        end_effector=(40, 0, 0),
        name=ROBOT_NAME,
    )
    signals = {MODULE_NAMES[0]: rc.signals.Ramp()}
    return robot.to_json(signals=signals, simulation={"t_end": 1.0, "dt": 0.25}).encode()


def no_handler_ran(page, dialogs: list[str]) -> None:  # type: ignore[no-untyped-def]
    page.wait_for_timeout(1000)  # an image's onerror fires asynchronously
    assert (page.evaluate("window.__pwned"), dialogs) == (None, [])


def _tab(page, title: str):  # type: ignore[no-untyped-def]
    return page.locator(f"{NOTEBOOK} .lm-TabBar-tab", has_text=title).first


def test_hostile_upload_runs_no_handler_and_shows_the_names(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    dialogs: list[str] = []
    page.on("dialog", lambda dialog: (dialogs.append(dialog.message), dialog.dismiss()))
    write_notebook(lab.root / "hostile.ipynb", CELLS)
    open_notebook(page, lab.url("hostile.ipynb"))

    run_cell(page, 0)
    page.wait_for_function("window.__control === 1", timeout=30_000)
    run_cell(page, 1)
    page.locator(".robotconf-ee").first.wait_for(timeout=60_000)

    _tab(page, "Save / Load").click()
    with page.expect_file_chooser() as chooser:
        page.locator(f"{NOTEBOOK} .widget-upload").first.click()
    chooser.value.set_files(
        {"name": FILE_NAME, "mimeType": "application/json", "buffer": hostile_file()}
    )
    status = page.locator(f"{NOTEBOOK} .widget-html", has_text="loaded ").first
    status.wait_for(timeout=30_000)
    no_handler_ran(page, dialogs)
    assert status.inner_text().strip() == f"loaded {FILE_NAME}"  # the name, as text

    # The read-only DH row of the module list shows the link's repr, name included.
    assert page.get_by_text(f"name={DH_NAME!r}").count() == 1

    # Matrices as text (the header names the robot), then as LaTeX through MathJax.
    _tab(page, "Matrices").click()
    printout = page.locator(f"{NOTEBOOK} .widget-html pre", has_text="forward kinematics").first
    printout.wait_for(timeout=30_000)
    assert f"{ROBOT_NAME}: forward kinematics" in printout.inner_text()
    choose(page, "matrices.style", "LaTeX")
    page.locator(f"{NOTEBOOK} .widget-htmlmath mjx-container").first.wait_for(timeout=30_000)

    # Motion: Run, and the DVA table whose column headers are the module names.
    _tab(page, "Motion").click()
    click(page, "run")
    table = page.locator(f"{NOTEBOOK} .widget-html table").first
    table.wait_for(timeout=30_000)
    # The point dropdown lists the module names as text; "all points" puts them in the table.
    options = control(page, "results.point").locator("option").all_inner_texts()
    names = [MODULE_NAMES[1], DH_NAME, MODULE_NAMES[0]]  # tool end first, after EE
    assert options[1:4] == names
    choose(page, "results.point", "all")
    page.locator(f"{NOTEBOOK} .widget-html thead", has_text="EE").first.wait_for()
    wait_idle(page)
    headers = table.locator("thead").inner_text()
    for name in MODULE_NAMES:
        assert name in headers, headers  # an HTML widget is not typeset: "$$y$$" stays

    no_handler_ran(page, dialogs)
    assert not page.errors, page.errors
