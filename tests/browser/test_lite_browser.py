"""The JupyterLite site (``make lite``) in Chromium, served from 127.0.0.1 only.

Every request to another host is aborted and recorded. The Lab app must render its file
browser with the classroom's notebooks, open the configurator with the Pyodide kernel and
the install cell, and ask nothing of the outside world except Pyodide's runtime (which a
deployed site loads from Pyodide's CDN; this machine cannot reach it, so no kernel runs
here). The paper robot's 3D page must draw the robot with no kernel and no network.
"""

from __future__ import annotations

import functools
import http.server
import socket
import threading
from collections.abc import Iterator

import numpy as np
import pytest

from ..course_support import COURSE
from ..test_lite import site_folder
from .lab_driver import SOLID_RED_PIXELS, pixels, red_centroid

pytestmark = pytest.mark.timeout(900)  # the first test may build the site


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format: str, *args: object) -> None:  # noqa: A002 - base signature
        pass


@pytest.fixture(scope="module")
def served(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    """The site over http on 127.0.0.1 (a thread, not a process); its base URL."""
    handler = functools.partial(_Quiet, directory=str(site_folder(tmp_path_factory)))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/"
    finally:
        server.shutdown()
        server.server_close()
        thread.join(timeout=10)


@pytest.fixture
def offline(browser, served: str):  # type: ignore[no-untyped-def]
    """A page that reaches only the served site; ``page.aborted`` lists what it asked for.

    The route aborts and records what the page and its workers ask of other hosts. A
    service worker's own requests pass no route, so the context's proxy is a port that
    refuses connections: nothing gets out even then (the site itself bypasses it).
    """
    with socket.socket() as dead:
        dead.bind(("127.0.0.1", 0))  # bound, never listening
        context = browser.new_context(
            viewport={"width": 1280, "height": 900},
            proxy={"server": f"http://127.0.0.1:{dead.getsockname()[1]}", "bypass": "127.0.0.1"},
        )
        page = context.new_page()
        page.aborted, page.errors, page.warnings = [], [], []

        def route(route) -> None:  # type: ignore[no-untyped-def]
            if route.request.url.startswith(served):
                route.continue_()
            else:
                page.aborted.append(route.request.url)
                route.abort()

        context.route("**/*", route)
        page.on("pageerror", lambda error: page.errors.append(str(error)))
        page.on("console", lambda m: page.warnings.append(m.text) if m.type == "warning" else None)
        yield page
        context.close()


def listing(page) -> set[str]:  # type: ignore[no-untyped-def]
    page.wait_for_timeout(500)
    return {item.inner_text() for item in page.locator(".jp-DirListing-itemName").all()}


def open_folder(page, name: str) -> set[str]:  # type: ignore[no-untyped-def]
    page.locator(".jp-DirListing-item", has_text=name).first.dblclick()
    page.locator(".jp-BreadCrumbs", has_text=name).wait_for(timeout=30_000)
    return listing(page)


def test_lab_lists_the_classroom_and_opens_the_configurator(offline, served: str) -> None:  # type: ignore[no-untyped-def]
    page = offline
    page.goto(f"{served}lab/index.html")
    page.wait_for_selector(".jp-DirListing-item", timeout=90_000)
    assert listing(page) == {"course", "notebooks", "paper_robot_3d.html"}

    notebooks = open_folder(page, "notebooks")
    assert {"configurator.ipynb", "quickstart.ipynb", "paper_reproduction.ipynb"} <= notebooks
    page.locator(".jp-BreadCrumbs-home").click()
    page.wait_for_timeout(500)
    course = open_folder(page, "course")
    lessons = {name for name in course if name[:2].isdigit()}
    taught = {p.name for p in COURSE.iterdir() if p.is_dir() and p.name[:2].isdigit()}
    assert lessons == taught and "README.md" in course, course
    assert "solutions" not in course and "INSTRUCTOR.md" not in course, course
    assert {"lesson.ipynb", "exercises.ipynb"} <= open_folder(page, "01_homogeneous")

    page.goto(f"{served}lab/index.html?path=notebooks/configurator.ipynb")
    first = page.locator(".jp-NotebookPanel .jp-Cell").first
    first.wait_for(timeout=90_000)
    # A loaded machine shows the cell before its editor fills in: wait for the text.
    first.get_by_text("piplite.install", exact=False).first.wait_for(timeout=60_000)
    assert 'piplite.install("robotconf")' in first.inner_text()
    page.get_by_text("Python (Pyodide)").first.wait_for(timeout=30_000)
    page.wait_for_timeout(2000)  # let the kernel ask for Pyodide

    assert not page.errors, page.errors
    # Every front end fits the app's JupyterLab (a mismatch loads second copies of its parts).
    mismatched = [w for w in page.warnings if "atisf" in w and "version" in w]
    assert not mismatched, mismatched
    outside = {url.split("/")[2] for url in page.aborted}
    assert outside <= {"cdn.jsdelivr.net"}, page.aborted  # Pyodide's CDN, nothing else
    assert any(url.endswith("/pyodide.js") for url in page.aborted), page.aborted


def test_scene_page_draws_the_robot_without_a_kernel(offline, served: str) -> None:  # type: ignore[no-untyped-def]
    page = offline
    page.goto(f"{served}files/paper_robot_3d.html")
    page.wait_for_selector("body[data-robotconf-scene='ready']", timeout=30_000)
    page.wait_for_timeout(1500)
    picture = pixels(page.locator("#scene canvas"))
    count, _ = red_centroid(picture)
    assert count >= SOLID_RED_PIXELS, "the red end-effector sphere is not visible"
    assert len(np.unique(picture.reshape(-1, 3), axis=0)) > 50  # not a blank canvas
    assert not page.aborted and not page.errors, (page.aborted, page.errors)
