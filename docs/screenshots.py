"""Screenshots of the configurator for docs/panel.md, taken from the real thing.

Starts JupyterLab on 127.0.0.1 in a temporary folder, drives Debian's Chromium
(``/usr/bin/chromium``, or ``$ROBOTCONF_CHROMIUM``; Playwright downloads nothing) at
1280 × 900 with the file browser open, runs the paper's workflow (the paper's robot,
lengths in mm, the sawtooth on q3, Run) and writes ``docs/img/panel_*.png``, each reduced
to 256 colours so that it stays small; the last one at 1920 × 1080. Run it again
whenever the panel changes::

    .venv/bin/python docs/screenshots.py

(``--out FOLDER`` writes the pictures there instead, to look at them first.)

Every process it starts is stopped at the end, also when a step fails.
"""

from __future__ import annotations

import contextlib
import sys
import tempfile
from collections.abc import Callable, Iterator
from io import BytesIO
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the browser tests' helpers drive the same workflow

from tests.browser.lab_driver import (  # noqa: E402
    CHROMIUM,
    CHROMIUM_ARGS,
    choose,
    control,
    open_notebook,
    serve_lab,
    wait_idle,
    write_notebook,
)
from tests.browser.paper_workflow import (  # noqa: E402
    PANEL_CELL,
    SCROLL_JS,
    choose_length_unit,
    choose_tab,
    dismiss_news,
    rects,
    run_paper_workflow,
    show_panel,
    wait_for_plot,
)

OUT = ROOT / "docs" / "img"
VIEWPORT, WIDE = {"width": 1280, "height": 900}, {"width": 1920, "height": 1080}
#: Largest PNG written (bytes): the docs stay light to clone.
MAX_BYTES = 200_000
#: The Motion tab's Run button: the pictures of a run start there (its status beside it,
#: the results' controls under it).
RUN = ".rc-button.robotconf-run"


@contextlib.contextmanager
def jupyter_lab(root: Path) -> Iterator[str]:
    """A JupyterLab serving ``root``; yields the URL of ``panel.ipynb`` in a fresh layout."""
    with serve_lab(root) as running:
        yield running.url("panel.ipynb")


def save(page: Any, name: str, out: Path = OUT) -> Path:
    """The visible page as ``out``/``name``.png (default docs/img), in 256 colours."""
    from PIL import Image

    image = Image.open(BytesIO(page.screenshot())).convert("RGB")
    small = image.quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    path = out / f"{name}.png"
    small.save(path, optimize=True)
    size = path.stat().st_size
    print(f"{path}: {size / 1000:.0f} kB")
    if size > MAX_BYTES:
        raise RuntimeError(f"{path.name} is {size} bytes, more than {MAX_BYTES}")
    return path


def scroll_to(page: Any, selector: str, margin: float = 8.0) -> None:
    """Scroll the notebook so that ``selector``'s top is ``margin`` below the scroller's."""
    found = rects(page, selector)
    element, scroller = found["element"], found["scroller"]
    assert element is not None and scroller is not None, selector
    page.evaluate(SCROLL_JS, element[1] - scroller[1] - margin)
    page.wait_for_timeout(400)


def scroll_until_bottom(page: Any, selector: str, index: int = 0, margin: float = 12.0) -> None:
    """Scroll so that the ``index``-th ``selector``'s bottom is ``margin`` above the
    scroller's bottom."""
    found = rects(page, selector, index)
    element, scroller = found["element"], found["scroller"]
    assert element is not None and scroller is not None, selector
    page.evaluate(SCROLL_JS, element[3] - scroller[3] + margin)
    page.wait_for_timeout(400)


def shots(page: Any) -> list[tuple[str, Callable[[], None]]]:
    """``(name, what to do before it)`` for every screenshot, in order."""

    def plot_all_points() -> None:
        choose(page, "results.point", "all")
        wait_idle(page)
        control(page, "results.overlay").locator("input").click()
        wait_idle(page)
        page.wait_for_timeout(1000)
        wait_for_plot(page)
        scroll_to(page, RUN, margin=4)

    def statistics_ee() -> None:
        choose(page, "results.point", "EE")
        choose_tab(page, "statistics")
        page.locator(".robotconf-results-stats table").first.wait_for(timeout=60_000)
        scroll_to(page, RUN, margin=4)

    def plot_ee() -> None:
        choose_tab(page, "plot")
        wait_for_plot(page)
        scroll_to(page, RUN, margin=4)

    def matrices() -> None:
        choose_tab(page, "Matrices")
        page.locator(".robotconf-matrices pre").first.wait_for(timeout=60_000)
        scroll_to(page, ".robotconf-tabs")

    return [
        ("panel_overview", lambda: None),
        (
            "panel_sticky_view",
            lambda: scroll_until_bottom(page, ".rc-control.robotconf-module-q", 2),
        ),
        ("panel_dva_table", lambda: scroll_to(page, RUN, margin=4)),
        ("panel_dva_plot", plot_ee),
        ("panel_all_points", plot_all_points),
        ("panel_statistics", statistics_ee),
        ("panel_matrices", matrices),
    ]


def main() -> None:
    import argparse

    from playwright.sync_api import sync_playwright

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=OUT, help="folder for the PNGs")
    out = parser.parse_args().out
    out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="robotconf-shots-") as folder:
        root = Path(folder)
        write_notebook(root / "panel.ipynb", [PANEL_CELL])
        with jupyter_lab(root) as url, sync_playwright() as playwright:
            browser = playwright.chromium.launch(
                executable_path=CHROMIUM,
                args=CHROMIUM_ARGS,
            )
            try:
                page = browser.new_page(viewport=VIEWPORT)
                open_notebook(page, url)
                dismiss_news(page)
                show_panel(page)
                choose_length_unit(page, "mm")
                steps = shots(page)
                for name, before in steps[:2]:
                    before()
                    save(page, name, out)
                page.evaluate(SCROLL_JS, -10_000)
                run_paper_workflow(page, "mm")
                for name, before in steps[2:]:
                    before()
                    save(page, name, out)
                # A wide screen: the editor and the view side by side.
                page.set_viewport_size(WIDE)
                choose_tab(page, "Motion")
                page.evaluate(SCROLL_JS, -10_000)
                scroll_to(page, ".robotconf-panel", margin=0)
                save(page, "panel_wide", out)
            finally:
                browser.close()


if __name__ == "__main__":
    main()
