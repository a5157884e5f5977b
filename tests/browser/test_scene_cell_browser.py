"""The work cell in a real JupyterLab page and as an exported HTML file, in Chromium.

``rc.view(cell)`` draws the table (its neutral colour fills much of the pane) and the
robot (its red end effector); a run whose forearm sweeps through the fixture turns the
fixture red while the time is inside the contact interval — the page's player switches
it, no message to the kernel — and a label names the contact there. The exported file
does the same opened from disk with the network cut.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from .conftest import Lab
from .lab_driver import (
    NOTEBOOK,
    SOLID_RED_PIXELS,
    open_notebook,
    pixels,
    run_cell,
    solid_red,
    wait_idle,
    write_notebook,
)

#: Where the pictures go (looked at by hand after a change of the cell's scene).
SCREENSHOTS = Path(os.environ.get("ROBOTCONF_SCENE_SHOTS", "/tmp/robotconf_scene"))

CELLS = [
    "import robotconf as rc\n"
    "cell = rc.Cell(unit='mm', name='paper cell')\n"
    "cell.add(rc.Box([120, 80, 10], pose=rc.pose([40, 0, -5]), name='table'))\n"
    "cell.add_robot('arm', rc.preset('paper'), mount='table')\n"
    "cell.add(rc.Box([14, 14, 30], pose=rc.pose([5, -25, 20]), name='fixture'), parent='table')\n"
    "scene = rc.view(cell, height=480)",
    # From q1 = 0 to -1.5 rad the forearm sweeps through the fixture (0.52 s to 1.02 s).
    "run = cell.run({'arm': [rc.PTP(q=[-1.5, 0, 0])]}, dt=0.01)\n"
    "scene.animate(run, play=False)\nscene.seek(0.3)\nprint(run.check.contacts[0].message)",
    "scene.seek(0.8)",
    "scene.export_html('cell.html')",
]

#: The contact's label, as the check's sentence gives its depth.
CONTACT = "link 3 ↔ fixture, 13 mm"


def table_pixels(image: np.ndarray) -> int:
    """Pixels of the objects' warm grey (0xB4AC9C, lit): red over green over blue, a little
    apart, neither dark nor white; the sky's blues and the robot's greens are not."""
    r, g, b = image[..., 0], image[..., 1], image[..., 2]
    return int(((r >= g) & (g >= b) & (r - b > 8) & (r - b < 45) & (r > 80) & (r < 235)).sum())


def shown_labels(page) -> list[str]:  # type: ignore[no-untyped-def]
    return [
        text.replace("\n", " ")
        for text in page.locator(".robotconf-scene-label:not([hidden])").all_inner_texts()
    ]


def wait_for_red(page, canvas, more_than: int) -> int:  # type: ignore[no-untyped-def]
    """Solid red pixels, once more than ``more_than`` (or after 10 s)."""
    count = int(solid_red(pixels(canvas)).sum())
    for _ in range(40):
        if count > more_than:
            break
        page.wait_for_timeout(250)
        count = int(solid_red(pixels(canvas)).sum())
    return count


def test_cell_shows_a_contact_in_red_and_exports(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    write_notebook(lab.root / "cell.ipynb", CELLS)
    open_notebook(page, lab.url("cell.ipynb"))

    run_cell(page, 0)
    page.wait_for_selector("[data-robotconf-scene='ready']", timeout=60_000)
    wait_idle(page)
    page.wait_for_timeout(1500)
    canvas = page.locator(f"{NOTEBOOK} [data-robotconf-scene] canvas").first
    image = pixels(canvas)
    # The table fills a good part of the pane; the end effector's red sphere is there.
    assert table_pixels(image) > 0.05 * image.shape[0] * image.shape[1], table_pixels(image)
    assert int(solid_red(image).sum()) >= SOLID_RED_PIXELS
    texts = shown_labels(page)
    assert "fixture (45.0, -25.0, 15.0) mm" in texts and "EE (70.0, 0.0, 20.0) mm" in texts, texts
    page.screenshot(path=str(SCREENSHOTS / "cell_view.png"))

    run_cell(page, 1)
    wait_idle(page)
    page.wait_for_timeout(1000)
    before = int(solid_red(pixels(canvas)).sum())
    assert CONTACT not in shown_labels(page)
    run_cell(page, 2)
    wait_idle(page)
    during = wait_for_red(page, canvas, before + 400)
    # The fixture's faces turned red (hundreds of pixels more than the sphere alone).
    assert during > before + 400, (before, during)
    assert CONTACT in shown_labels(page), shown_labels(page)
    page.screenshot(path=str(SCREENSHOTS / "cell_contact.png"))

    # The bar's capsules button: the kernel shows them and the button says so.
    bar = page.locator(f"{NOTEBOOK} .robotconf-scene-controls").first
    capsules = bar.locator(".robotconf-scene-capsules")
    assert capsules.is_visible() and capsules.get_attribute("aria-pressed") == "false"
    capsules.click()
    page.wait_for_timeout(800)
    assert capsules.get_attribute("aria-pressed") == "true"
    page.screenshot(path=str(SCREENSHOTS / "cell_capsules.png"))

    run_cell(page, 3)
    wait_idle(page)
    exported = lab.root / "cell.html"
    offline = page.context.new_page()
    offline.route(
        "**/*",
        lambda route: (
            route.abort() if not route.request.url.startswith("file:") else route.continue_()
        ),
    )
    offline.goto(exported.as_uri())
    offline.wait_for_selector("body[data-robotconf-scene='ready']", timeout=30_000)
    scene = offline.locator("#scene canvas")
    offline.evaluate("window.robotconfViewer.rcPlayer.seek(0.3)")
    offline.wait_for_timeout(1000)
    clear = int(solid_red(pixels(scene)).sum())
    assert CONTACT not in shown_labels(offline)
    offline.evaluate("window.robotconfViewer.rcPlayer.seek(0.8)")
    hit = wait_for_red(offline, scene, clear + 400)
    assert hit > clear + 400, (clear, hit)
    assert CONTACT in shown_labels(offline)
    offline.screenshot(path=str(SCREENSHOTS / "cell_export.png"))
    assert not page.errors, page.errors
