"""The configurator as an app (`make app`): Voilà serves app/ as `make app` does, and a
student's first minutes run in Chromium, offline.

Checked: the 3D pane draws the robot; q1 = 90° typed in its box moves p_EE to (0, 70, 20)
and the picture; Run shows the DVA table; the matrices are fixed-width; no text sends the
student to a cell; every request stays on this server; a closed tab's kernel is shut
down at once, and a vanished page's kernel is culled while an open page's is kept.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import time
import urllib.request
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import psutil
import pytest

from .conftest import _free_port
from .lab_driver import SOLID_RED_PIXELS, pixels, red_centroid, red_moved

APP = Path(__file__).parents[2] / "app"
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


class VoilaApp:
    """The running app: its URL, server process and log."""

    def __init__(self, port: int, process: subprocess.Popen, log: Path) -> None:
        self.url = f"http://127.0.0.1:{port}/"
        self.host = f"127.0.0.1:{port}"
        self.server = psutil.Process(process.pid)
        self.log = log

    def kernel(self, kernel_id: str) -> psutil.Process | None:
        """The kernel process of ``kernel_id`` (its connection file names the id)."""
        for child in self.server.children(recursive=True):
            try:
                if any(kernel_id in part for part in child.cmdline()):
                    return child
            except psutil.NoSuchProcess:
                continue
        return None

    def wait_kernel_gone(self, kernel_id: str, timeout: float) -> float:
        """Seconds until the kernel's process ended; fails after ``timeout``."""
        start = time.monotonic()
        while self.kernel(kernel_id) is not None:
            assert time.monotonic() - start < timeout, f"kernel {kernel_id} still running"
            time.sleep(0.2)
        return time.monotonic() - start


@pytest.fixture(scope="module")
def voila_app(
    tmp_path_factory: pytest.TempPathFactory, spawned: list[psutil.Process]
) -> Iterator[VoilaApp]:
    root = tmp_path_factory.mktemp("app")
    port = _free_port()
    env = dict(
        os.environ,
        # As `make app`: the app's template; no user configuration in the way.
        JUPYTER_PATH=str(APP / "jupyter"),
        JUPYTER_CONFIG_DIR=str(root / ".jupyter-config"),
        JUPYTER_RUNTIME_DIR=str(root / ".jupyter-runtime"),
        MPLBACKEND="Agg",
    )
    log_path = root / "voila.log"
    log = open(log_path, "wb")  # noqa: SIM115 - the server writes it until the end
    process = subprocess.Popen(
        [
            str(Path(sys.executable).parent / "voila"),
            "configurator.ipynb",
            "--no-browser",
            f"--port={port}",
            *CULL_FLAGS,
        ],
        cwd=APP,  # where `make app` runs it, so app/voila.json is read
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=log,
    )
    spawned.append(psutil.Process(process.pid))
    deadline = time.monotonic() + 60
    while True:
        try:
            urllib.request.urlopen(f"http://127.0.0.1:{port}/voila/static/voila.js", timeout=2)
            break
        except OSError:
            if time.monotonic() > deadline or process.poll() is not None:
                raise RuntimeError(log_path.read_text()[-3000:]) from None
            time.sleep(0.3)
    app = VoilaApp(port, process, log_path)
    try:
        yield app
    finally:
        # Kernels are the server's children: note them before asking it to stop.
        spawned.extend(app.server.children(recursive=True))
        process.terminate()
        try:
            process.wait(timeout=20)
        except subprocess.TimeoutExpired:  # pragma: no cover
            process.kill()
            process.wait()
        log.close()


def _record_requests(page) -> list[str]:  # type: ignore[no-untyped-def]
    urls: list[str] = []
    page.on("request", lambda request: urls.append(request.url))
    page.on("websocket", lambda socket: urls.append(socket.url))
    return urls


def _external(urls: list[str], host: str) -> list[str]:
    # data: and blob: URLs are made in the page itself (the 3D viewer's code, downloads).
    return [u for u in urls if not u.startswith(("data:", "blob:")) and u.split("/")[2] != host]


def _open(page, app: VoilaApp) -> str:  # type: ignore[no-untyped-def]
    """Load the app; returns the page's kernel id once the 3D pane is ready."""
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    page.goto(app.url)
    try:
        page.wait_for_selector("[data-robotconf-scene='ready'] canvas", timeout=60_000)
    except PlaywrightTimeout:
        shown = page.locator("body").inner_text()[-1500:]
        raise AssertionError(
            f"no 3D pane; page shows:\n{shown}\nconsole:\n"
            + "\n".join(page.console[-20:])
            + f"\nVoilà log:\n{app.log.read_text()[-3000:]}"
        ) from None
    config = page.locator("#jupyter-config-data").first.text_content()
    return str(json.loads(config)["kernelId"])


def _tab(page, name: str):  # type: ignore[no-untyped-def]
    labels = page.locator(".lm-TabBar-tabLabel")
    return labels.filter(has_text=re.compile(f"^{re.escape(name)}$")).first


def test_student_workflow_in_the_app(voila_app: VoilaApp, page) -> None:  # type: ignore[no-untyped-def]
    urls = _record_requests(page)
    kernel_id = _open(page, voila_app)
    kernel = voila_app.kernel(kernel_id)
    assert kernel is not None
    canvas = page.locator("[data-robotconf-scene] canvas").first
    page.wait_for_timeout(1000)
    count, start = red_centroid(pixels(canvas))
    assert count >= SOLID_RED_PIXELS, "no red end-effector in the 3D pane"
    assert "p_EE = (70, 0, 20)" in page.locator(".robotconf-ee").inner_text()

    # q1 = 90° typed into module 1's q box (the number box beside its slider).
    q1_row = page.locator(".robotconf-module-q").first.locator("xpath=..")
    box = q1_row.locator("input[type=number]").first
    box.fill("90")
    box.press("Enter")
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

    # No text of the app (hidden tabs included) sends the student to a cell or to code.
    text = page.evaluate(TEXT_JS)
    assert "as JSON:" in text and "the CSV holds all" in text  # the app's own wording
    assert not re.search(r"\bcells?\b", text, re.IGNORECASE), text
    assert "panel." not in text and "rc." not in text

    # Font Awesome comes from Voilà's own bundle, not the CDN the stock template names.
    fonts = page.evaluate(
        "() => [...document.fonts].filter(f => f.status === 'loaded').map(f => f.family)"
    )
    assert any("Font Awesome" in family for family in fonts), fonts
    assert _external(urls, voila_app.host) == []
    assert any("/api/kernels/" in u for u in urls)  # the recording saw the websocket too
    assert not page.errors, page.errors

    # Closing the tab shuts its kernel down at once (Voilà's request is not refused).
    page.close(run_before_unload=True)
    voila_app.wait_kernel_gone(kernel_id, timeout=10)
    log = voila_app.log.read_text()
    assert f"Kernel shutdown: {kernel_id}" in log
    assert "403 POST" not in log
    assert not re.search(rf"Culling .*{kernel_id}", log), "culled, not shut down on close"


def test_a_vanished_page_is_culled_an_open_one_kept(voila_app: VoilaApp, page) -> None:  # type: ignore[no-untyped-def]
    urls = _record_requests(page)
    kernel_id = _open(page, voila_app)
    time.sleep(5)  # idle longer than the test's cull timeout: an open page keeps its kernel
    assert voila_app.kernel(kernel_id) is not None
    assert _external(urls, voila_app.host) == []
    # A browser that dies sends nothing: no beforeunload, the socket just closes.
    page.close(run_before_unload=False)
    voila_app.wait_kernel_gone(kernel_id, timeout=15)
    assert re.search(rf"Culling .*{kernel_id}", voila_app.log.read_text())
