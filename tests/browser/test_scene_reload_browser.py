"""After a page reload the 3D pane shows the robot's current pose, not an old animation.

A scene that played a motion and was then moved to a pose with ``scene.update(q)`` is
reloaded in JupyterLab (saved notebook, same kernel: the views are rebuilt from the
kernel's scene log). The red end-effector must stand where a fresh view of that pose
puts it, and not where the animation ended (the parking pose); the bar shows the view
options the kernel holds (labels "names", frames on), and the labels say so.
"""

from __future__ import annotations

import numpy as np

from .conftest import Lab
from .lab_driver import (
    NOTEBOOK,
    SOLID_RED_PIXELS,
    open_notebook,
    pixels,
    red_centroid,
    run_cell,
    wait_idle,
    write_notebook,
)

POSE = "[1.2, -0.6, 0.9]"
CELLS = [
    "import robotconf as rc\nrobot = rc.preset('paper')\nscene = rc.view(robot, height=360)",
    # One second of motion that ends where it started: the parking pose.
    "motion = rc.simulate(robot, {'q1': rc.signals.Sine(amplitude=1.5, frequency=1.0)},"
    " t_end=1.0, dt=0.02)\nscene.animate(motion)",
    f"scene.update({POSE})\nscene.set_label_mode('names')\nscene.show_frames(True)",
    # References, framed like `scene` (fitted at the parking pose): the current pose …
    f"current = rc.view(robot, height=360)\ncurrent.update({POSE})",
    # … and the pose the old animation would leave behind.
    "parked = rc.view(robot, height=360)",
]


def _centroids(page) -> list[np.ndarray]:  # type: ignore[no-untyped-def]
    canvases = page.locator(f"{NOTEBOOK} [data-robotconf-scene] canvas")
    out = []
    for k in range(3):
        count, centroid = red_centroid(pixels(canvases.nth(k)))
        assert count >= SOLID_RED_PIXELS, f"no red end-effector in pane {k}"
        out.append(centroid)
    return out


def _wait_panes(page, count: int) -> None:  # type: ignore[no-untyped-def]
    ready = page.locator(f"{NOTEBOOK} [data-robotconf-scene='ready']")
    for _ in range(300):
        if ready.count() >= count:
            break
        page.wait_for_timeout(200)
    assert ready.count() >= count, f"{ready.count()} of {count} panes ready"
    page.wait_for_timeout(1500)  # replay applied and rendered


def test_reload_shows_the_current_pose_not_the_animation(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    write_notebook(lab.root / "reload.ipynb", CELLS)
    open_notebook(page, lab.url("reload.ipynb"))
    run_cell(page, 0)
    page.wait_for_selector("[data-robotconf-scene='ready']", timeout=60_000)
    run_cell(page, 1)
    wait_idle(page)
    page.wait_for_timeout(2000)  # the animation plays to its end
    for index in (2, 3, 4):
        run_cell(page, index)
    wait_idle(page)
    _wait_panes(page, 3)
    scene, current, parked = _centroids(page)
    assert np.linalg.norm(current - parked) > 30, "the two reference poses look alike"
    assert np.linalg.norm(scene - current) < 4, (scene, current)

    page.keyboard.press("Control+s")  # the outputs must be in the file to come back
    page.wait_for_timeout(1000)
    page.reload()
    page.wait_for_selector(f"{NOTEBOOK} .jp-Cell", timeout=90_000)
    _wait_panes(page, 3)
    scene, current, parked = _centroids(page)
    assert np.linalg.norm(scene - current) < 4, (scene, current, parked)
    assert np.linalg.norm(scene - parked) > 30
    bar = page.locator(f"{NOTEBOOK} .robotconf-scene-controls").first
    mode = bar.locator(".robotconf-scene-label-mode [aria-checked='true']")
    assert mode.get_attribute("data-mode") == "names"
    assert bar.locator(".robotconf-scene-frames").get_attribute("aria-pressed") == "true"
    assert bar.locator(".robotconf-scene-clock").inner_text() == "no animation"
    first = page.locator(f"{NOTEBOOK} .robotconf-scene").first
    texts = first.locator(".robotconf-scene-label:not([hidden])").all_inner_texts()
    assert sorted(texts) == ["EE", "M1", "M2", "M3"], texts
    assert not page.errors, page.errors
