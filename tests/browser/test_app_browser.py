"""The configurator as an app (`make app`): Voilà serves app/ as `make app` does, and a
student's first minutes run in Chromium, offline.

Checked: the 3D pane draws the robot; q1 = 90° typed in its box moves p_EE to (0, 70, 20)
and the picture; Run shows the DVA table; the matrices are fixed-width; no text sends the
student to a cell; every request stays on this server; a closed tab's kernel is shut
down at once, and a vanished page's kernel is culled while an open page's is kept.
"""

from __future__ import annotations

import re
import time
from collections.abc import Iterator

import numpy as np
import psutil
import pytest

from .app_support import VoilaApp, external, open_app, record_requests, running_app
from .lab_driver import SOLID_RED_PIXELS, pixels, red_centroid, red_moved, type_number

#: Short culling for the test (the app's own is minutes): a kernel without a page goes
#: after 3 s of silence, checked every second. Long enough that a tab closed right after
#: its last action is shut down by its own request, not by the culler.
CULL_FLAGS = [
    "--MappingKernelManager.cull_idle_timeout=3",
    "--MappingKernelManager.cull_interval=1",
]
#: Every text node of the rendered notebook, hidden tabs included, scripts excluded.
TEXT_JS = """() => {
  const walker = document.createTreeWalker(
    document.querySelector('#rendered_cells'), NodeFilter.SHOW_TEXT);
  const parts = [];
  while (walker.nextNode()) {
    if (!walker.currentNode.parentElement.closest('script, style')) {
      parts.push(walker.currentNode.textContent);
    }
  }
  return parts.join(' ');
}"""


@pytest.fixture(scope="module")
def voila_app(
    tmp_path_factory: pytest.TempPathFactory, spawned: list[psutil.Process]
) -> Iterator[VoilaApp]:
    with running_app(tmp_path_factory.mktemp("app"), spawned, CULL_FLAGS) as app:
        yield app


def _tab(page, name: str):  # type: ignore[no-untyped-def]
    labels = page.locator(".lm-TabBar-tabLabel")
    return labels.filter(has_text=re.compile(f"^{re.escape(name)}$")).first


def test_student_workflow_in_the_app(voila_app: VoilaApp, page) -> None:  # type: ignore[no-untyped-def]
    urls = record_requests(page)
    kernel_id = open_app(page, voila_app)
    kernel = voila_app.kernel(kernel_id)
    assert kernel is not None
    canvas = page.locator("[data-robotconf-scene] canvas").first
    page.wait_for_timeout(1000)
    count, start = red_centroid(pixels(canvas))
    assert count >= SOLID_RED_PIXELS, "no red end-effector in the 3D pane"
    assert "p_EE = (70, 0, 20)" in page.locator(".robotconf-ee").inner_text()

    # q1 = 90° typed into module 1's q box (the number box beside its slider).
    type_number(page, "modules[0].q", 90, scope="body")
    page.wait_for_function(
        "() => document.querySelector('.robotconf-ee').innerText.includes('p_EE = (0, 70, 20)')",
        timeout=10_000,
    )
    count, after = red_moved(page, canvas, start)
    assert count >= SOLID_RED_PIXELS and np.linalg.norm(after - start) > 5, (
        f"the picture did not follow q1: {count} red pixels at {after}, from {start}"
    )

    # Run on the Motion tab: the displacement / velocity / acceleration table.
    _tab(page, "Motion").click()
    # The name starts with the icon's glyph (CSS content counts): match the word only.
    page.get_by_role("button", name=re.compile(r"\bRun$")).click()
    table = page.locator(".jupyter-widgets table.dataframe").first
    table.wait_for(timeout=30_000)
    header = table.locator("thead").inner_text()
    assert all(word in header for word in ("displacement", "velocity", "acceleration"))

    # The matrices are fixed-width with rows at text spacing, not a control row's 28 px.
    _tab(page, "Matrices").click()
    pre = page.locator(".robotconf-matrices pre").first
    pre.wait_for()
    style = pre.evaluate("e => [getComputedStyle(e).fontFamily, getComputedStyle(e).lineHeight]")
    assert style[0].replace('"', "").endswith("monospace"), style
    assert float(style[1].removesuffix("px")) < 24, style
    assert "p_EE" in pre.inner_text()

    # No text of the app sends the student to a cell or to code. A tab draws its form
    # when shown: every tab is shown once, and hidden tabs' text counts too.
    for name in ("Reach", "Program", "Save / Load"):
        _tab(page, name).click()
        page.wait_for_timeout(1000)
    text = page.evaluate(TEXT_JS)
    assert "as JSON:" in text and "the CSV holds all" in text  # the app's own wording
    assert not re.search(r"\bcells?\b", text, re.IGNORECASE), text
    assert "panel." not in text and "rc." not in text

    # Font Awesome comes from Voilà's own bundle, not the CDN the stock template names.
    fonts = page.evaluate(
        "() => [...document.fonts].filter(f => f.status === 'loaded').map(f => f.family)"
    )
    assert any("Font Awesome" in family for family in fonts), fonts
    assert external(urls, voila_app.host) == []
    assert any("/api/kernels/" in u for u in urls)  # the recording saw the websocket too
    assert not page.errors, page.errors
    # Front-end extensions of other tools installed beside the app (nbgrader, Notebook's
    # Lab extension in a developer's venv) fail in Voilà's page: the app loads none.
    assert not [line for line in page.console if line.startswith("error")], page.console

    # Closing the tab shuts its kernel down at once (Voilà's request is not refused).
    page.close(run_before_unload=True)
    voila_app.wait_kernel_gone(kernel_id, timeout=10)
    log = voila_app.log.read_text()
    assert f"Kernel shutdown: {kernel_id}" in log
    assert "403 POST" not in log
    assert not re.search(rf"Culling .*{kernel_id}", log), "culled, not shut down on close"


def test_a_vanished_page_is_culled_an_open_one_kept(voila_app: VoilaApp, page) -> None:  # type: ignore[no-untyped-def]
    urls = record_requests(page)
    kernel_id = open_app(page, voila_app)
    time.sleep(5)  # idle longer than the test's cull timeout: an open page keeps its kernel
    assert voila_app.kernel(kernel_id) is not None
    assert external(urls, voila_app.host) == []
    # A browser that dies sends nothing: no beforeunload, the socket just closes.
    page.close(run_before_unload=False)
    voila_app.wait_kernel_gone(kernel_id, timeout=15)
    assert re.search(rf"Culling .*{kernel_id}", voila_app.log.read_text())
