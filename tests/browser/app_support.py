"""The configurator app (app/serve.py) started as `make app` starts it, for browser tests."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
import urllib.request
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import psutil

from .lab_driver import free_port as _free_port

APP = Path(__file__).parents[2] / "app"


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

    def kernels(self) -> list[psutil.Process]:
        """The server's kernel processes (one per page that started one)."""
        found = []
        for child in self.server.children(recursive=True):
            try:
                if "ipykernel_launcher" in " ".join(child.cmdline()):
                    found.append(child)
            except psutil.NoSuchProcess:
                continue
        return found

    def wait_kernel_gone(self, kernel_id: str, timeout: float) -> float:
        """Seconds until the kernel's process ended; fails after ``timeout``."""
        start = time.monotonic()
        while self.kernel(kernel_id) is not None:
            assert time.monotonic() - start < timeout, f"kernel {kernel_id} still running"
            time.sleep(0.2)
        return time.monotonic() - start


@contextmanager
def running_app(
    root: Path, spawned: list[psutil.Process], flags: list[str], *, ip: str = "127.0.0.1"
) -> Iterator[VoilaApp]:
    """app/serve.py on a free port with extra command-line ``flags``; stopped at the end."""
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
            sys.executable,
            "serve.py",
            "configurator.ipynb",
            "--no-browser",
            f"--port={port}",
            f"--Voila.ip={ip}",
            *flags,
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


def record_requests(page) -> list[str]:  # type: ignore[no-untyped-def]
    """Every request and websocket the page makes from now on (a list that grows)."""
    urls: list[str] = []
    page.on("request", lambda request: urls.append(request.url))
    page.on("websocket", lambda socket: urls.append(socket.url))
    return urls


def external(urls: list[str], host: str) -> list[str]:
    """The URLs among ``urls`` that are not on ``host``."""
    # data: and blob: URLs are made in the page itself (the 3D viewer's code, downloads).
    return [u for u in urls if not u.startswith(("data:", "blob:")) and u.split("/")[2] != host]


def open_app(page, app: VoilaApp, url: str | None = None) -> str:  # type: ignore[no-untyped-def]
    """Load the app (at ``url``, by default its plain address); returns the page's kernel id
    once the 3D pane is ready."""
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    page.goto(url or app.url)
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
