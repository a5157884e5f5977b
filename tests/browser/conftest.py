"""Browser tests: JupyterLab on 127.0.0.1 with a token, driven in Debian's Chromium.

Playwright never downloads a browser here: it launches /usr/bin/chromium (installed by
``.ci/run``). Every process started for these tests is tracked and must be gone at the end.
"""

from __future__ import annotations

import os
import shutil
import time
from collections.abc import Iterator
from pathlib import Path

import psutil
import pytest

from .lab_driver import CHROMIUM, CHROMIUM_ARGS, Lab, serve_lab

if not Path(CHROMIUM).exists():  # pragma: no cover - CI installs it
    pytest.skip(f"no Chromium at {CHROMIUM} (bash .ci/run installs it)", allow_module_level=True)


@pytest.fixture(scope="session")
def spawned() -> Iterator[list[psutil.Process]]:
    """Processes the browser tests started; asserted gone at the end of the session."""
    processes: list[psutil.Process] = []
    yield processes
    deadline = time.monotonic() + 15
    alive = [p for p in processes if _alive(p)]
    while alive and time.monotonic() < deadline:
        time.sleep(0.2)
        alive = [p for p in alive if _alive(p)]
    for process in alive:  # pragma: no cover - only on failure
        process.kill()
    assert not alive, f"leaked processes: {[(p.pid, p.name()) for p in alive]}"


def _alive(process: psutil.Process) -> bool:
    try:
        return process.is_running() and process.status() != psutil.STATUS_ZOMBIE
    except psutil.NoSuchProcess:
        return False


@pytest.fixture(scope="session")
def lab(tmp_path_factory: pytest.TempPathFactory, spawned: list[psutil.Process]) -> Iterator[Lab]:
    with serve_lab(tmp_path_factory.mktemp("lab")) as running:
        server = psutil.Process(running.process.pid)
        spawned.append(server)
        try:
            yield running
        finally:
            # Kernels are the server's children: note them before the server stops.
            spawned.extend(server.children(recursive=True))


# Package scope: Playwright's sync API keeps an asyncio loop running in this thread while
# it is open, which the tests after the browser folder (asyncio.run, a panel's save timer
# looking for the kernel's loop) must not see.
@pytest.fixture(scope="package")
def browser(spawned: list[psutil.Process]) -> Iterator[object]:
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        me = psutil.Process()
        spawned.extend(p for p in me.children(recursive=True) if "chrom" in p.name().lower())
        yield browser
        browser.close()


@pytest.fixture
def page(browser):  # type: ignore[no-untyped-def]
    context = browser.new_context(viewport={"width": 1280, "height": 900})
    page = context.new_page()
    page.errors = []
    page.console = []
    page.on("pageerror", lambda error: page.errors.append(str(error)))
    page.on("console", lambda message: page.console.append(f"{message.type}: {message.text}"))
    yield page
    if os.environ.get("ROBOTCONF_BROWSER_DEBUG"):
        page.screenshot(path=os.environ["ROBOTCONF_BROWSER_DEBUG"])
        print("\n".join(page.errors + page.console[-60:]))
    elif page.errors or any(line.startswith("error") for line in page.console):
        print("\n".join(page.errors + page.console[-40:]))
    context.close()


def copy_notebook(source: Path, lab: Lab, name: str | None = None) -> str:
    target = lab.root / (name or source.name)
    shutil.copy(source, target)
    return target.name
