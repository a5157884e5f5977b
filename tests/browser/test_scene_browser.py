"""The 3D scene in a real JupyterLab page and as an exported HTML file, in Chromium.

The bar above the pane is the page's own (``robotconf/scene/js/bar.js``): an animation
plays to its end by itself while the time slider follows it, a drag of the slider seeks,
and the labels buttons ask the kernel. Labels are text boxes over the pane: each stays by
its point or has a leader line to it, none covers another, long ones wrap inside the pane.
"""

from __future__ import annotations

import os
import re

import numpy as np

from .conftest import Lab
from .lab_driver import (
    NOTEBOOK,
    SOLID_RED_PIXELS,
    open_notebook,
    pixels,
    red_centroid,
    red_moved,
    run_cell,
    wait_idle,
    write_notebook,
)

#: Where the pictures of the labels go (looked at by hand after a change of the scene).
SCREENSHOTS = os.environ.get("ROBOTCONF_SCENE_SHOTS", "/tmp/robotconf_scene")

CELLS = [
    "import robotconf as rc\nrobot = rc.preset('paper')\nscene = rc.view(robot, height=480)",
    "scene.update([0.0, -1.0, 1.3])",
    "scene.export_html('paper_scene.html')",
]


def _output(page, cell: int) -> str:  # type: ignore[no-untyped-def]
    return page.locator(f"{NOTEBOOK} .jp-Cell").nth(cell).locator(".jp-OutputArea").inner_text()


def _bar(page, index: int = 0):  # type: ignore[no-untyped-def]
    return page.locator(f"{NOTEBOOK} .robotconf-scene-controls").nth(index)


def _clock(bar) -> float:  # type: ignore[no-untyped-def]
    text = bar.locator(".robotconf-scene-clock").inner_text()
    match = re.fullmatch(r"t = ([\d.]+) / ([\d.]+) s", text)
    assert match, text
    return float(match.group(1))


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
    # The exported page's bar answers by itself: "names" writes the names.
    offline.locator(".robotconf-scene-label-mode button[data-mode='names']").click()
    offline.wait_for_timeout(500)
    shown = offline.locator(".robotconf-scene-label:not([hidden])").all_inner_texts()
    assert sorted(shown) == ["EE", "M1", "M2", "M3"], shown
    assert not page.errors, page.errors


ANIMATION = [
    "import robotconf as rc\nrobot = rc.preset('paper')\nscene = rc.view(robot, height=360)\n"
    "requests, reports = [], []\nscene.on_request = requests.append\n"
    "scene.on_playback = reports.append",
    "motion = rc.simulate(robot, {'q1': rc.signals.Sine(amplitude=1.2, frequency=0.25)},"
    " t_end=3.0, dt=0.01)\nscene.animate(motion)",
    "state = scene.playback_state\n"
    "print('state', state.playing, round(state.time, 3), state.duration)\n"
    "print('requests', *[r['kind'] for r in requests])\n"
    "print('reports', *[(r.playing, round(r.time, 3)) for r in reports])",
]


def test_an_animation_plays_to_its_end_and_a_drag_seeks(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    write_notebook(lab.root / "animation.ipynb", ANIMATION)
    open_notebook(page, lab.url("animation.ipynb"))
    run_cell(page, 0)
    page.wait_for_selector("[data-robotconf-scene='ready']", timeout=60_000)
    wait_idle(page)
    bar = _bar(page)
    assert bar.locator(".robotconf-scene-play").is_disabled()  # nothing to play yet
    run_cell(page, 1)
    wait_idle(page)

    # The page's clock runs the motion to its end; the slider follows it, never seeking.
    times = []
    for _ in range(120):
        times.append(_clock(bar))
        if times[-1] >= 3.0:
            break
        page.wait_for_timeout(250)
    assert times[-1] == 3.0, times
    assert len(set(times)) >= 4 and times == sorted(times), times
    canvas = page.locator(f"{NOTEBOOK} [data-robotconf-scene] canvas").first
    count, at_end = red_centroid(pixels(canvas))  # q1 = 1.2 sin(2π · 0.25 · 3) = -1.2
    assert count >= SOLID_RED_PIXELS
    slider = bar.locator(".robotconf-scene-time")
    assert float(slider.input_value()) == 3.0
    assert bar.locator(".robotconf-scene-play").get_attribute("aria-label") == "play"
    page.wait_for_timeout(500)  # the end's report reaches the kernel
    run_cell(page, 2)
    wait_idle(page)
    out = _output(page, 2)
    assert "state False 3.0 3.0" in out, out
    # No student action yet: no request at all (above all no seek), and one report: the end.
    assert re.search(r"^requests\s*$", out, re.M), out
    assert "reports (False, 3.0)" in out, out

    # A drag of the slider seeks (and pauses); the kernel hears it once the drag ends.
    box = slider.bounding_box()
    y = box["y"] + box["height"] / 2
    page.mouse.move(box["x"] + 0.9 * box["width"], y)
    page.mouse.down()
    for fraction in (0.7, 0.5, 0.3):
        page.mouse.move(box["x"] + fraction * box["width"], y, steps=4)
    page.mouse.up()
    page.wait_for_timeout(500)
    dragged = _clock(bar)
    assert 0.5 < dragged < 1.4, dragged
    # The motion's frame at that time: q1 near +1.2, the end effector far from the end's.
    count, at_drag = red_centroid(pixels(canvas))
    assert count >= SOLID_RED_PIXELS and np.linalg.norm(at_drag - at_end) > 30
    run_cell(page, 2)
    wait_idle(page)
    out = _output(page, 2)
    state = re.search(r"state (\w+) ([\d.]+) 3.0", out)
    assert state and state.group(1) == "False", out
    assert abs(float(state.group(2)) - dragged) < 0.02, (out, dragged)
    assert "seek" in out.split("requests", 1)[1].splitlines()[0], out

    # ▶ plays on from there; with the keyboard's arrows the slider steps, and JupyterLab
    # keeps its hands off them (in command mode ArrowDown would select the next cell).
    bar.locator(".robotconf-scene-play").click()
    page.wait_for_timeout(700)
    assert _clock(bar) > dragged
    cells = page.locator(f"{NOTEBOOK} .jp-Cell")
    active = [
        i for i in range(cells.count()) if "jp-mod-active" in cells.nth(i).get_attribute("class")
    ]
    slider.focus()
    page.keyboard.press("ArrowDown")
    stepped = _clock(bar)
    page.wait_for_timeout(400)
    assert _clock(bar) == stepped  # a key seeks, so playback paused there
    after = [
        i for i in range(cells.count()) if "jp-mod-active" in cells.nth(i).get_attribute("class")
    ]
    assert after == active, (active, after)
    assert not page.errors, page.errors


LABELS = [
    "import robotconf as rc\nimport numpy as np\n"
    # Four frames at the origin with long names: one merged label that must wrap.
    "names = ['base yaw', 'shoulder pitch', 'upper arm roll', 'forearm pitch']\n"
    "modules = [rc.Module(k, name=n) for k, n in zip(['Rz', 'Ry', 'Rx', 'Ry'], names)]\n"
    "modules.append(rc.Module('Ry', a=(0, 0, 0.4), name='elbow'))\n"
    "arm = rc.Robot(modules + [rc.Module('Ry', a=(0.35, 0, 0))], end_effector=(0.05, 0, 0))\n"
    "scene = rc.view(arm, height=420)",
    # Taught points far from the robot and close to each other; a target out of reach.
    "scene.show_taught_points([[0.4, 0.0, 0.4], [0.41, 0.0, 0.41], [0.42, 0.0, 0.4],"
    " [1.6, 0.9, -0.3]])\nscene.show_target([-1.2, -0.8, 0.9], reachable=False)",
    "print('mode', scene.label_mode)",
]


def _label_layout(page) -> list[dict]:  # type: ignore[no-untyped-def]
    """Every shown label: its text, its box and its point (x, y, sphere radius) in the
    pane, and the leader line drawn to it (or None)."""
    return page.evaluate(
        """() => {
        const notebook = '.jp-NotebookPanel:not(.lm-mod-hidden)';
        const pane = document.querySelector(`${notebook} .robotconf-scene`);
        const origin = pane.getBoundingClientRect();
        return [...pane.querySelectorAll('.robotconf-scene-label')].filter(e => !e.hidden)
          .map(e => {
            const r = e.getBoundingClientRect();
            const line = pane.querySelector(
              `.robotconf-scene-leader[data-path="${e.dataset.path}"]`);
            const drawn = line && line.style.display !== 'none';
            return {
              text: e.textContent, path: e.dataset.path,
              box: [r.left - origin.left, r.top - origin.top, r.right - origin.left,
                    r.bottom - origin.top],
              point: e.dataset.point.split(',').map(Number),
              pane: [origin.width, origin.height],
              leader: drawn ? ['x1', 'y1', 'x2', 'y2'].map(a => Number(line.getAttribute(a)))
                            : null,
            };
          });
      }"""
    )


def _check_layout(labels: list[dict]) -> None:
    for k, label in enumerate(labels):
        left, top, right, bottom = label["box"]
        width, height = label["pane"]
        assert min(left, top) >= -1 and right <= width + 1 and bottom <= height + 1, label
        x, y, radius = label["point"]
        nx, ny = min(max(x, left), right), min(max(y, top), bottom)
        near = np.hypot(nx - x, ny - y) <= radius + 21
        if not near:  # far from its point: a leader line runs from the point to the box
            assert label["leader"] is not None, label
            x1, y1, x2, y2 = label["leader"]
            assert abs(x1 - x) < 1 and abs(y1 - y) < 1, label
            assert left - 1 <= x2 <= right + 1 and top - 1 <= y2 <= bottom + 1, label
        for other in labels[:k]:
            o = other["box"]
            apart = right <= o[0] + 1 or left >= o[2] - 1 or bottom <= o[1] + 1 or top >= o[3] - 1
            assert apart, (label["text"], other["text"])


def test_labels_stay_by_their_points_wrap_and_switch(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    os.makedirs(SCREENSHOTS, exist_ok=True)
    write_notebook(lab.root / "labels.ipynb", LABELS)
    open_notebook(page, lab.url("labels.ipynb"))
    run_cell(page, 0)
    page.wait_for_selector("[data-robotconf-scene='ready']", timeout=60_000)
    wait_idle(page)
    page.wait_for_timeout(1500)
    labels = _label_layout(page)
    merged = [label for label in labels if label["text"].startswith("base yaw, shoulder")]
    assert len(merged) == 1, [label["text"] for label in labels]
    # Names on one line (wrapped where needed), the position on its own line.
    lines = merged[0]["text"].split("\n")
    assert len(lines) >= 2 and re.fullmatch(r"\(-?[\d.]+, -?[\d.]+, -?[\d.]+\)", lines[-1])
    assert merged[0]["box"][2] - merged[0]["box"][0] <= 282
    _check_layout(labels)
    page.locator(f"{NOTEBOOK} .robotconf-scene").first.screenshot(
        path=f"{SCREENSHOTS}/labels_merged.png"
    )

    run_cell(page, 1)
    wait_idle(page)
    page.wait_for_timeout(1500)
    labels = _label_layout(page)
    taught = sorted(label["text"] for label in labels if "/taught/" in label["path"])
    # Every taught point is in the picture (the view widened for the far ones).
    assert taught == ["P1", "P2", "P3", "P4"], taught
    _check_layout(labels)
    page.screenshot(path=f"{SCREENSHOTS}/labels_taught_1280x900.png")

    bar = _bar(page)
    bar.locator(".robotconf-scene-label-mode button[data-mode='names']").click()
    page.wait_for_timeout(800)
    names = bar.locator(".robotconf-scene-label-mode button[data-mode='names']")
    assert names.get_attribute("aria-checked") == "true"
    robot_texts = [label["text"] for label in _label_layout(page) if "/robot/" in label["path"]]
    assert robot_texts and not any("(" in text for text in robot_texts), robot_texts
    run_cell(page, 2)
    wait_idle(page)
    assert "mode names" in _output(page, 2)
    bar.locator(".robotconf-scene-label-mode button[data-mode='off']").click()
    page.wait_for_timeout(800)
    assert _label_layout(page) == []  # the taught points' labels hide too
    bar.locator(".robotconf-scene-label-mode button[data-mode='positions']").click()
    page.wait_for_timeout(800)
    assert any("(" in label["text"] for label in _label_layout(page))
    assert not page.errors, page.errors
