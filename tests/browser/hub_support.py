"""The class server of ``make hub`` (hub/jupyterhub_config.py), started for browser tests.

:func:`hub_environment` runs ``make hub-env`` (the student venv and the proxy from npm,
both cached in build/hub/ and redone only when their pins change); :func:`running_hub`
starts JupyterHub from the student venv on free ports with a fresh data folder.
"""

from __future__ import annotations

import os
import secrets
import shutil
import subprocess
import time
import urllib.request
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import psutil
import pytest

from .lab_driver import free_port as _free_port

ROOT = Path(__file__).parents[2]
BUILD = ROOT / "build" / "hub"
VENV = BUILD / "student-venv"
PROXY = BUILD / "node_modules" / ".bin" / "configurable-http-proxy"
CONFIG = ROOT / "hub" / "jupyterhub_config.py"
STUDENTS = ("ada", "alan")


def hub_environment() -> float:
    """Install (or check) the student venv and the proxy with ``make hub-env``; seconds taken.

    Skips the calling test when npm is missing (the proxy comes from npm).
    """
    for tool in ("npm", "node", "make"):
        if shutil.which(tool) is None:
            pytest.skip(
                f"no {tool} on PATH: the hub's proxy comes from npm (bash .ci/run installs it)"
            )
    version = subprocess.run(["node", "--version"], capture_output=True, text=True).stdout
    if int(version.strip().lstrip("v").split(".")[0] or 0) < 20:
        pytest.skip(f"Node {version.strip()}: configurable-http-proxy 5 needs Node 20 or newer")
    start = time.monotonic()
    result = subprocess.run(
        ["make", "-s", "hub-env"], cwd=ROOT, capture_output=True, text=True, timeout=1500
    )
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    return time.monotonic() - start


class Hub:
    """A running hub: its public URL (the proxy's), password, data folder and process."""

    def __init__(self, port: int, password: str, data: Path, process: subprocess.Popen) -> None:
        self.port = port
        self.url = f"http://127.0.0.1:{port}"
        self.host = f"127.0.0.1:{port}"
        self.password = password
        self.data = data
        self.process = process
        self.server = psutil.Process(process.pid)

    @property
    def log(self) -> str:
        return (self.data / "hub.log").read_text(errors="replace")


@contextmanager
def running_hub(data: Path, spawned: list[psutil.Process]) -> Iterator[Hub]:
    """JupyterHub as ``make hub`` runs it, on free ports; stopped (with its students'
    servers and the proxy) at the end."""
    port, password = _free_port(), secrets.token_urlsafe(12)
    keep = ("PATH", "LANG", "LC_ALL", "HOME", "TMPDIR")
    env = {name: os.environ[name] for name in keep if name in os.environ}
    env.update(
        ROBOTCONF_HUB_PORT=str(port),
        ROBOTCONF_HUB_INTERNAL_PORT=str(_free_port()),
        ROBOTCONF_HUB_PROXY_API_PORT=str(_free_port()),
        ROBOTCONF_HUB_DATA=str(data),
        ROBOTCONF_HUB_PASSWORD=password,
        ROBOTCONF_HUB_STUDENTS=",".join(STUDENTS),
    )
    log = open(data / "hub.log", "wb")  # noqa: SIM115 - the hub writes it until the end
    process = subprocess.Popen(
        [str(VENV / "bin" / "jupyterhub"), "-f", str(CONFIG)],
        cwd=data,
        env=env,
        stdout=log,
        stderr=subprocess.STDOUT,
    )
    spawned.append(psutil.Process(process.pid))
    hub = Hub(port, password, data, process)
    deadline = time.monotonic() + 90
    while True:
        try:
            urllib.request.urlopen(f"{hub.url}/hub/health", timeout=2)
            break
        except OSError:
            if time.monotonic() > deadline or process.poll() is not None:
                log.flush()
                raise RuntimeError(hub.log[-4000:]) from None
            time.sleep(0.3)
    try:
        yield hub
    finally:
        # The proxy, the students' servers and their kernels are the hub's descendants.
        spawned.extend(hub.server.children(recursive=True))
        process.terminate()
        try:
            process.wait(timeout=60)
        except subprocess.TimeoutExpired:  # pragma: no cover
            process.kill()
            process.wait()
        log.close()


def log_in(page, hub: Hub, student: str) -> None:  # type: ignore[no-untyped-def]
    """Log ``student`` in through the hub's login form; waits for their JupyterLab."""
    page.goto(f"{hub.url}/hub/login")
    page.fill("#username_input", student)
    page.fill("#password_input", hub.password)
    page.click("#login_submit")
    # The hub starts the student's server, then sends the browser to its JupyterLab.
    page.wait_for_url(f"{hub.url}/user/{student}/lab/**", timeout=150_000)
