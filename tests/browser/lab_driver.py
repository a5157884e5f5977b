"""Small helpers to drive a JupyterLab notebook page with Playwright."""

from __future__ import annotations

import contextlib
import json
import os
import re
import secrets
import socket
import subprocess
import sys
import time
import urllib.request
from collections.abc import Iterator
from pathlib import Path

import nbformat
import numpy as np

#: Front-end parts a student's JupyterLab does not show: nbgrader's menus (nbgrader comes
#: with the developer extra, for the grading tests) and the news prompt that pops up over
#: the page's corner.
QUIET_LAB = {
    "disabledExtensions": {
        "@jupyter/nbgrader": True,
        "@jupyterlab/apputils-extension:announcements": True,
    }
}


#: Debian's Chromium (Playwright downloads none) and the switches a headless run needs.
CHROMIUM = os.environ.get("ROBOTCONF_CHROMIUM", "/usr/bin/chromium")
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--enable-unsafe-swiftshader",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]


def free_port() -> int:
    """A TCP port free on 127.0.0.1 right now."""
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


class Lab:
    """A running JupyterLab: its folder, port, token and process."""

    def __init__(self, root: Path, port: int, token: str, process: subprocess.Popen) -> None:
        self.root = root
        self.port = port
        self.token = token
        self.process = process

    def url(self, notebook: str) -> str:
        """The notebook's URL, in a fresh workspace of its own (otherwise Lab restores the
        previous notebook's tabs)."""
        workspace = Path(notebook).stem
        return (
            f"http://127.0.0.1:{self.port}/lab/workspaces/{workspace}/tree/{notebook}"
            f"?reset&token={self.token}"
        )


@contextlib.contextmanager
def serve_lab(root: Path, env: dict[str, str] | None = None) -> Iterator[Lab]:
    """A JupyterLab on 127.0.0.1 serving ``root``, stopped (with its kernels) at the end;
    ``env`` adds to this process's environment (``PYTHONPATH``). Its log: ``root/lab.log``."""
    port, token = free_port(), secrets.token_hex(16)
    environment = dict(
        os.environ,
        JUPYTER_CONFIG_DIR=str(root / ".jupyter-config"),
        JUPYTER_RUNTIME_DIR=str(root / ".jupyter-runtime"),
        JUPYTERLAB_SETTINGS_DIR=str(root / ".lab-settings"),
        JUPYTERLAB_WORKSPACES_DIR=str(root / ".lab-workspaces"),
        MPLBACKEND="Agg",
        **(env or {}),
    )
    quiet_lab_config(root / ".jupyter-config")
    command = [
        sys.executable,
        "-m",
        "jupyter",
        "lab",
        "--no-browser",
        "--ip=127.0.0.1",
        f"--port={port}",
        f"--IdentityProvider.token={token}",
        f"--ServerApp.root_dir={root}",
        "--ServerApp.open_browser=False",
        "--LabApp.news_url=",
        "--LabApp.extension_manager=readonly",
        *(["--allow-root"] if os.geteuid() == 0 else []),
    ]
    with open(root / "lab.log", "wb") as log:
        server = subprocess.Popen(
            command, cwd=root, env=environment, stdout=subprocess.DEVNULL, stderr=log
        )
        try:
            deadline = time.monotonic() + 90
            while True:
                try:
                    status = f"http://127.0.0.1:{port}/api/status?token={token}"
                    urllib.request.urlopen(status, timeout=2)
                    break
                except OSError:
                    if time.monotonic() > deadline or server.poll() is not None:
                        raise RuntimeError((root / "lab.log").read_text()[-3000:]) from None
                    time.sleep(0.3)
            yield Lab(root, port, token, server)
        finally:
            server.terminate()  # the server shuts its kernels down on the way out
            try:
                server.wait(timeout=30)
            except subprocess.TimeoutExpired:  # pragma: no cover
                server.kill()
                server.wait()


def open_panel(page, lab: Lab, name: str, cells: list[str]) -> None:  # type: ignore[no-untyped-def]
    """Write notebook ``name`` of ``cells``, open it, run its first cell (the panel) and
    wait until the 3D view is ready and the kernel idle."""
    write_notebook(lab.root / name, cells)
    open_notebook(page, lab.url(name))
    run_cell(page, 0)
    page.wait_for_selector("[data-robotconf-scene='ready']", timeout=60_000)
    wait_idle(page)


def quiet_lab_config(config_dir: Path) -> None:
    """Write the page config that hides :data:`QUIET_LAB`'s parts into a Jupyter config dir."""
    labconfig = Path(config_dir) / "labconfig"
    labconfig.mkdir(parents=True, exist_ok=True)
    (labconfig / "page_config.json").write_text(json.dumps(QUIET_LAB), "utf-8")


#: The notebook in the visible tab (another tab's cells may be in the page, hidden).
NOTEBOOK = ".jp-NotebookPanel:not(.lm-mod-hidden) .jp-Notebook"


def write_notebook(path: Path, cells: list[str]) -> None:
    notebook = nbformat.v4.new_notebook()
    notebook.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3 (ipykernel)",
        "language": "python",
    }
    notebook.cells = [nbformat.v4.new_code_cell(source) for source in cells]
    nbformat.write(notebook, path)


def open_notebook(page, url: str) -> None:  # type: ignore[no-untyped-def]
    page.goto(url)
    page.wait_for_selector(f"{NOTEBOOK} .jp-Cell", timeout=90_000)
    # The status bar says Idle once the kernel is connected and ready for code.
    page.get_by_text("Python 3 (ipykernel) | Idle").wait_for(timeout=90_000)
    page.wait_for_timeout(500)


def run_cell(page, index: int) -> None:  # type: ignore[no-untyped-def]
    """Select cell ``index`` (0-based) and run it with Shift+Enter."""
    cell = page.locator(f"{NOTEBOOK} .jp-Cell").nth(index)
    cell.locator(".jp-InputPrompt").click()
    page.keyboard.press("Shift+Enter")
    # Done when the prompt shows an execution count, e.g. "[3]:".
    prompt = cell.locator(".jp-InputArea-prompt")
    for _ in range(600):
        if any(ch.isdigit() for ch in prompt.inner_text()):
            return
        page.wait_for_timeout(100)
    raise AssertionError(f"cell {index} did not run: prompt {prompt.inner_text()!r}")


def wait_idle(page, timeout: float = 90_000) -> None:  # type: ignore[no-untyped-def]
    page.wait_for_timeout(300)
    page.wait_for_selector(".jp-Notebook-ExecutionIndicator[data-status='idle']", timeout=timeout)


def pixels(locator) -> np.ndarray:  # type: ignore[no-untyped-def]
    """RGB pixels of an element's screenshot, shape (H, W, 3)."""
    from io import BytesIO

    from PIL import Image

    return np.asarray(Image.open(BytesIO(locator.screenshot())).convert("RGB")).astype(int)


#: Solid red pixels (see :func:`solid_red`) that show the end-effector's sphere: a sphere
#: drawn about 7 px across or more; a frame's one-pixel red axis has none.
SOLID_RED_PIXELS = 20


def solid_red(image: np.ndarray) -> np.ndarray:
    """Red pixels whose 5×5 neighbourhood is all red, shape (H, W) of bool: the
    end-effector's sphere, not the one-pixel red x axis of a frame (which alone would pass
    a pixel count with no end-effector in view)."""
    r, g, b = image[..., 0], image[..., 1], image[..., 2]
    red = (r > 140) & (g < 90) & (b < 90)
    core = red.copy()
    for dy in range(-2, 3):
        for dx in range(-2, 3):
            core &= np.roll(red, (dy, dx), axis=(0, 1))
    return core


def red_centroid(image: np.ndarray) -> tuple[int, np.ndarray]:
    """Number of the end-effector's solid red pixels and their centroid (x, y)."""
    ys, xs = np.nonzero(solid_red(image))
    if len(xs) == 0:
        return 0, np.array([np.nan, np.nan])
    return len(xs), np.array([xs.mean(), ys.mean()])


def red_moved(page, canvas, start: np.ndarray, *, at_least: float = 5.0, timeout: float = 15.0):  # type: ignore[no-untyped-def]
    """Poll until the red end-effector's centroid moved ``at_least`` pixels from ``start``.

    Returns (count, centroid) of the last picture; the caller asserts on them.
    """
    count, centroid = red_centroid(pixels(canvas))
    for _ in range(int(timeout / 0.25)):
        if count >= SOLID_RED_PIXELS and np.linalg.norm(centroid - start) > at_least:
            break
        page.wait_for_timeout(250)
        count, centroid = red_centroid(pixels(canvas))
    return count, centroid


# -- the panel's forms (robotconf/panel/form/js/form.js) ------------------------------------
# Every editor of the configurator is one form: controls found by their key, the same
# string as ``panel.errors`` and the headless tests use (``modules[1].q``, ``preset``).

#: The thumb of a range input: where its value sits on the track, in page pixels.
_THUMB_JS = """(e) => {
  const r = e.getBoundingClientRect();
  const lo = Number(e.min), hi = Number(e.max), v = Number(e.value);
  const f = hi > lo ? (v - lo) / (hi - lo) : 0;
  const thumb = 16;
  return [r.left + thumb / 2 + f * (r.width - thumb), r.top + r.height / 2];
}"""


def control(page, key: str, scope: str = NOTEBOOK):  # type: ignore[no-untyped-def]
    """The form control with ``key`` (its ``.rc-control`` element) in ``scope``."""
    return page.locator(f'{scope} .rc-control[data-key="{key}"]').first


def reveal(locator) -> None:  # type: ignore[no-untyped-def]
    """Scroll ``locator`` to the bottom of the notebook's view, as a user scrolls to it:
    the pinned 3D pane covers the top (``scroll_into_view_if_needed`` could put the
    element under it)."""
    locator.evaluate("element => element.scrollIntoView({ block: 'end' })")
    locator.page.wait_for_timeout(200)


def drag_slider(page, key: str, dx: float, steps: int = 15, scope: str = NOTEBOOK) -> float:  # type: ignore[no-untyped-def]
    """Drag the slider of number control ``key`` by ``dx`` pixels with the mouse, in
    ``steps`` moves without pauses; returns the value the slider shows when let go."""
    slider = control(page, key, scope).locator("input.rc-slider")
    reveal(slider)
    x, y = slider.evaluate(_THUMB_JS)
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(1, steps + 1):
        page.mouse.move(x + dx * k / steps, y)
    page.mouse.up()
    return float(slider.input_value())


def step_slider(  # type: ignore[no-untyped-def]
    page, key: str, presses: int, arrow: str = "ArrowRight", scope: str = NOTEBOOK
) -> None:
    """Press ``arrow`` ``presses`` times on number control ``key``'s slider (one notch
    each, as fast as the keyboard repeats: a burst of values, as a drag sends)."""
    slider = control(page, key, scope).locator("input.rc-slider")
    reveal(slider)
    slider.focus()
    for _ in range(presses):
        slider.press(arrow)


def type_number(page, key: str, value: float | str, scope: str = NOTEBOOK) -> None:  # type: ignore[no-untyped-def]
    """Type ``value`` into number control ``key``'s box; Enter sends it."""
    box = control(page, key, scope).locator("input.rc-box")
    reveal(box)
    box.fill(value if isinstance(value, str) else f"{value:g}")
    box.press("Enter")


def choose(page, key: str, label: str, scope: str = NOTEBOOK) -> None:  # type: ignore[no-untyped-def]
    """Pick the option shown as ``label`` in dropdown or toggle ``key``."""
    found = control(page, key, scope)
    reveal(found)
    select = found.locator("select")
    if select.count():
        select.select_option(label=label)
        return
    found.locator("button.rc-choice").filter(has_text=re.compile(f"^{re.escape(label)}$")).click()


def click(page, key: str, scope: str = NOTEBOOK) -> None:  # type: ignore[no-untyped-def]
    """Click form button ``key`` (or tick checkbox control ``key``)."""
    found = control(page, key, scope)
    reveal(found)
    found.click()


def shown_value(page, key: str, scope: str = NOTEBOOK) -> str:  # type: ignore[no-untyped-def]
    """What control ``key`` shows: a number's box, a dropdown's chosen option, a toggle's
    chosen button."""
    found = control(page, key, scope)
    return str(
        found.evaluate(
            """(e) => {
              const box = e.querySelector('input.rc-box');
              if (box) return box.value;
              const select = e.querySelector('select');
              if (select) {
                const option = select.options[select.selectedIndex];
                return option ? option.text : '';
              }
              const chosen = e.querySelector('button.rc-chosen');
              return chosen ? chosen.textContent : e.textContent;
            }"""
        )
    )


def ee_text(page, scope: str = NOTEBOOK) -> str:  # type: ignore[no-untyped-def]
    """The panel's end-effector line, ``"p_EE = (70, 0, 20)"``."""
    return str(page.locator(f"{scope} .robotconf-ee").first.inner_text()).strip()


def ee_numbers(page, scope: str = NOTEBOOK) -> np.ndarray:  # type: ignore[no-untyped-def]
    """The numbers of :func:`ee_text`, shape (3,)."""
    text = ee_text(page, scope)
    numbers = re.search(r"p_EE = \(([^)]*)\)", text)
    assert numbers, text
    return np.array([float(v) for v in numbers.group(1).split(",")])


def output_text(page, cell: int) -> str:  # type: ignore[no-untyped-def]
    """What cell ``cell`` (0-based) printed."""
    return str(
        page.locator(f"{NOTEBOOK} .jp-Cell").nth(cell).locator(".jp-OutputArea").inner_text()
    )
