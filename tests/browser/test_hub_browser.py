"""A class on one server: ``make hub``'s JupyterHub, two students, in Chromium.

Each student logs in at the hub, gets their own JupyterLab from the student environment,
opens the configurator, sees the robot in the 3D pane and turns q1 by 30°; every request the
browser makes (page, API, websockets) goes to the proxy's one address. One student cannot
open the other's server, and neither sees the teacher's tools: the student environment
has no nbgrader, so their JupyterLab has no nbgrader menu, Validate button or extension
(nothing is hidden for this test, unlike the JupyterLab tests' page config).
"""

from __future__ import annotations

import json
import re
import subprocess
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import psutil
import pytest

from .hub_support import STUDENTS, VENV, Hub, hub_environment, log_in, running_hub
from .lab_driver import (
    NOTEBOOK,
    SOLID_RED_PIXELS,
    pixels,
    red_centroid,
    red_moved,
    run_cell,
    type_number,
)

TEACHER_VENV_EXTENSIONS = (
    Path(__file__).parents[2] / ".venv" / "share" / "jupyter" / "labextensions"
)


@pytest.fixture(scope="module")
def hub(tmp_path_factory: pytest.TempPathFactory, spawned: list[psutil.Process]) -> Iterator[Hub]:
    hub_environment()
    with running_hub(tmp_path_factory.mktemp("hub"), spawned) as running:
        yield running


@pytest.fixture
def students(browser, hub: Hub) -> Iterator[dict[str, object]]:  # type: ignore[no-untyped-def]
    """One browser context (own cookies) and page per student, every URL recorded."""
    pages: dict[str, object] = {}
    contexts = []
    for student in STUDENTS:
        context = browser.new_context(viewport={"width": 1280, "height": 900})
        contexts.append(context)
        page = context.new_page()
        page.urls = []
        page.errors = []
        page.on("request", lambda request, urls=page.urls: urls.append(request.url))
        page.on("websocket", lambda socket, urls=page.urls: urls.append(socket.url))
        page.on("pageerror", lambda error, errors=page.errors: errors.append(str(error)))
        pages[student] = page
    yield pages
    for context in contexts:
        context.close()


def _open_configurator(page) -> None:  # type: ignore[no-untyped-def]
    """Run the configurator notebook's code cell and wait for the 3D pane."""
    page.wait_for_selector(f"{NOTEBOOK} .jp-Cell", timeout=120_000)
    page.get_by_text("Python 3 (ipykernel) | Idle").wait_for(timeout=120_000)
    run_cell(page, 1)  # cell 0 is the notebook's introduction
    page.wait_for_selector("[data-robotconf-scene='ready'] canvas", timeout=90_000)
    page.wait_for_timeout(800)


def _end_effector(page) -> np.ndarray:  # type: ignore[no-untyped-def]
    text = page.locator(".robotconf-ee").inner_text()
    numbers = re.search(r"p_EE = \(([^)]*)\)", text)
    assert numbers, text
    return np.array([float(value) for value in numbers.group(1).split(",")])


def _move_q1_to_30_degrees(page) -> None:  # type: ignore[no-untyped-def]
    canvas = page.locator("[data-robotconf-scene] canvas").first
    count, start = red_centroid(pixels(canvas))
    assert count >= SOLID_RED_PIXELS, "no red end-effector in the 3D pane"
    np.testing.assert_allclose(_end_effector(page), [70, 0, 20])  # the paper's parking pose
    type_number(page, "modules[0].q", 30)  # module 1's q box, beside its slider
    expected = [70 * np.cos(np.pi / 6), 70 * np.sin(np.pi / 6), 20]  # about z by 30°
    for _ in range(60):
        if np.allclose(_end_effector(page), expected, atol=0.01):
            break
        page.wait_for_timeout(250)
    np.testing.assert_allclose(_end_effector(page), expected, atol=0.01)
    count, after = red_moved(page, canvas, start)
    assert count >= SOLID_RED_PIXELS and np.linalg.norm(after - start) > 5, (count, after, start)


def _elsewhere(urls: list[str], host: str) -> list[str]:
    return [u for u in urls if not u.startswith(("data:", "blob:")) and u.split("/")[2] != host]


# The first test also waits for `make hub-env` (the student venv: minutes on a fresh CI).
@pytest.mark.timeout(1800)
def test_two_students_work_through_the_proxy_apart(hub: Hub, students) -> None:  # type: ignore[no-untyped-def]
    for student, page in students.items():
        log_in(page, hub, student)
        _open_configurator(page)
        _move_q1_to_30_degrees(page)
        assert not page.errors, page.errors
        # The class's settings keep JupyterLab's news prompt off the student's page.
        assert page.get_by_text("notified about official Jupyter news").count() == 0

    for student, page in students.items():
        # Every request, the kernel's websocket included, went to the proxy's address.
        assert any(f"/user/{student}/api/kernels/" in u for u in page.urls if u.startswith("ws"))
        assert _elsewhere(page.urls, hub.host) == [], _elsewhere(page.urls, hub.host)[:5]

    # Ada may not open Alan's server (his JupyterLab, files or API), though it is running.
    ada, alan = students["ada"], students["alan"]
    response = ada.goto(f"{hub.url}/user/alan/lab/tree/configurator.ipynb")
    assert response is not None and response.status == 403, (response.status, ada.url)
    assert "/user/alan/lab" not in ada.url or "403" in ada.locator("body").inner_text()
    for path in ("api/contents/configurator.ipynb", "files/configurator.ipynb", "api/kernels"):
        reply = ada.request.get(f"{hub.url}/user/alan/{path}", max_redirects=10)
        assert reply.status in (403, 404) or "/hub/login" in reply.url, (path, reply.status)
        assert '"cells"' not in reply.text() and "robotconf" not in reply.text(), path
    # ... while Alan reads his own notebook.
    own = alan.request.get(f"{hub.url}/user/alan/api/contents/configurator.ipynb")
    assert own.status == 200 and "rc.configurator" in own.text()


@pytest.mark.timeout(900)
def test_students_see_no_teacher_tools(hub: Hub, students) -> None:  # type: ignore[no-untyped-def]
    page = students["ada"]
    log_in(page, hub, "ada")
    page.wait_for_selector(f"{NOTEBOOK} .jp-Cell", timeout=120_000)
    config = json.loads(page.locator("#jupyter-config-data").text_content())
    extensions = {extension["name"] for extension in config["federated_extensions"]}
    assert {"anywidget", "@jupyter-widgets/jupyterlab-manager"} <= extensions, extensions
    assert not any("nbgrader" in name for name in extensions), extensions
    # The teacher's environment has nbgrader's front end (so the check above can fail).
    assert (TEACHER_VENV_EXTENSIONS / "@jupyter" / "nbgrader").is_dir()

    menus = page.locator(".lm-MenuBar-content").first.inner_text()
    assert "File" in menus and "Kernel" in menus, menus
    assert "nbgrader" not in menus.lower() and "Assignments" not in menus, menus
    toolbar = page.locator(f"{NOTEBOOK.split(' ')[0]} .jp-Toolbar").first.inner_text()
    assert "Validate" not in toolbar, toolbar
    left_tabs = page.locator(".jp-SideBar").first.inner_html()
    assert "nbgrader" not in left_tabs.lower()
    # The student environment cannot even import it.
    found = subprocess.run(
        [str(VENV / "bin" / "python"), "-c", "import nbgrader"], capture_output=True, timeout=60
    )
    assert found.returncode != 0 and b"No module named 'nbgrader'" in found.stderr
    # Nor does a student's home hold the course's solutions.
    home = hub.data / "home" / "ada"
    assert (home / "course" / "01_homogeneous_transforms").is_dir()
    assert not (home / "course" / "solutions").exists()
    assert not (home / "course" / "INSTRUCTOR.md").exists()
