"""Small helpers to drive a JupyterLab notebook page with Playwright."""

from __future__ import annotations

import json
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
