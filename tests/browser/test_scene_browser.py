"""The 3D scene in a real JupyterLab page and as an exported HTML file, in Chromium."""

from __future__ import annotations

import numpy as np

from .conftest import Lab
from .lab_driver import (
    SOLID_RED_PIXELS,
    open_notebook,
    pixels,
    red_centroid,
    red_moved,
    run_cell,
    wait_idle,
    write_notebook,
)

CELLS = [
    "import robotconf as rc\nrobot = rc.preset('paper')\nscene = rc.view(robot, height=480)",
    "scene.update([0.0, -1.0, 1.3])",
    "scene.export_html('paper_scene.html')",
]


def test_scene_renders_moves_and_exports(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    write_notebook(lab.root / "scene.ipynb", CELLS)
    open_notebook(page, lab.url("scene.ipynb"))

    run_cell(page, 0)
    pane = page.locator("[data-robotconf-scene]").first
    page.wait_for_selector("[data-robotconf-scene='ready']", timeout=30_000)
    canvas = pane.locator("canvas").first
    assert canvas.bounding_box()["height"] > 400
    page.wait_for_timeout(1500)
    before = pixels(canvas)
    count, start = red_centroid(before)
    assert count >= SOLID_RED_PIXELS, "the red end-effector sphere is not visible"
    # Not a blank canvas: many distinct colours (background gradient, links, spheres).
    assert len(np.unique(before.reshape(-1, 3), axis=0)) > 50

    run_cell(page, 1)
    wait_idle(page)
    count_after, end = red_moved(page, canvas, start, at_least=15)
    assert count_after >= SOLID_RED_PIXELS
    assert np.linalg.norm(end - start) > 15, "scene.update did not move the end-effector"

    run_cell(page, 2)
    wait_idle(page)
    exported = lab.root / "paper_scene.html"
    assert exported.exists()
    text = exported.read_text()
    assert "http://" not in text.split("<script", 1)[0] and 'src="http' not in text

    offline = page.context.new_page()
    # Nothing may be fetched: the export must work with the network cut.
    offline.route(
        "**/*",
        lambda route: (
            route.abort() if not route.request.url.startswith("file:") else route.continue_()
        ),
    )
    offline.goto(exported.as_uri())
    offline.wait_for_selector("body[data-robotconf-scene='ready']", timeout=30_000)
    offline.wait_for_timeout(1500)
    count_html, _ = red_centroid(pixels(offline.locator("#scene canvas")))
    assert count_html >= SOLID_RED_PIXELS
    assert not page.errors, page.errors
