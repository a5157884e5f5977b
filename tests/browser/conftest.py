"""Browser tests: JupyterLab on 127.0.0.1 with a token, driven in Debian's Chromium.

Playwright never downloads a browser here: it launches /usr/bin/chromium (installed by
``.ci/run``). Every process started for these tests is tracked and must be gone at the end.
"""

from __future__ import annotations

import os
import secrets
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from collections.abc import Iterator
from pathlib import Path

import psutil
import pytest

from .lab_driver import quiet_lab_config

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

if not Path(CHROMIUM).exists():  # pragma: no cover - CI installs it
    pytest.skip(f"no Chromium at {CHROMIUM} (bash .ci/run installs it)", allow_module_level=True)


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


class Lab:
    """A running JupyterLab: its URL, token, folder and process."""

    def __init__(self, root: Path, port: int, token: str, process: subprocess.Popen) -> None:
        self.root = root
        self.port = port
        self.token = token
        self.process = process

    def url(self, notebook: str) -> str:
        # One fresh workspace per notebook: otherwise Lab restores the previous test's tabs.
        workspace = Path(notebook).stem
        return (
            f"http://127.0.0.1:{self.port}/lab/workspaces/{workspace}/tree/{notebook}"
            f"?reset&token={self.token}"
        )


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
    root = tmp_path_factory.mktemp("lab")
    port, token = _free_port(), secrets.token_hex(16)
    env = dict(
        os.environ,
        JUPYTER_CONFIG_DIR=str(root / ".jupyter-config"),
        JUPYTER_RUNTIME_DIR=str(root / ".jupyter-runtime"),
        JUPYTERLAB_SETTINGS_DIR=str(root / ".lab-settings"),
        JUPYTERLAB_WORKSPACES_DIR=str(root / ".lab-workspaces"),
        MPLBACKEND="Agg",
    )
    quiet_lab_config(root / ".jupyter-config")
    log = open(root / "lab.log", "wb")  # noqa: SIM115 - the server writes it until the end
    process = subprocess.Popen(
        [
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
        ],
        cwd=root,
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=log,
    )
    server = psutil.Process(process.pid)
    spawned.append(server)
    deadline = time.monotonic() + 60
    while True:
        try:
            urllib.request.urlopen(f"http://127.0.0.1:{port}/api/status?token={token}", timeout=2)
            break
        except OSError:
            if time.monotonic() > deadline or process.poll() is not None:
                raise RuntimeError((root / "lab.log").read_text()[-3000:]) from None
            time.sleep(0.3)
    try:
        yield Lab(root, port, token, process)
    finally:
        # Kernels are the server's children: note them before asking it to stop.
        spawned.extend(server.children(recursive=True))
        process.terminate()
        try:
            process.wait(timeout=20)
        except subprocess.TimeoutExpired:  # pragma: no cover
            process.kill()
            process.wait()
        log.close()


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
