"""The app's locks (app/serve.py), tried the way a foreign page, a rebinding name, a
greedy client and a classroom server would try them.

- Another site's page that loads the app as a fetch, image, script or frame starts no
  kernel (each request is refused with 403); a link the student follows from that site
  still opens the app.
- A Host header that does not name the server is refused on every path, in Chromium
  (a name mapped to 127.0.0.1, as DNS rebinding would) and by plain HTTP.
- One client gets at most ``kernels_per_client`` pages; closing a tab frees its kernel
  (the page's closing request carries the XSRF cookie the server set), and a shutdown
  request without that cookie is refused.
- Listening beyond 127.0.0.1 without a token makes one up; a request without it starts
  nothing; an explicitly empty token is refused at start.
"""

from __future__ import annotations

import http.client
import http.server
import re
import subprocess
import sys
import threading
import time
import urllib.error
import urllib.request
from collections.abc import Iterator
from contextlib import contextmanager

import psutil
import pytest

from .app_support import APP, VoilaApp, open_app, running_app
from .lab_driver import CHROMIUM, CHROMIUM_ARGS
from .lab_driver import free_port as _free_port

#: The test's cap: two pages per client.
CAP = 2


@pytest.fixture(scope="module")
def guarded_app(
    tmp_path_factory: pytest.TempPathFactory, spawned: list[psutil.Process]
) -> Iterator[VoilaApp]:
    root = tmp_path_factory.mktemp("guarded-app")
    with running_app(root, spawned, [f"--RobotconfApp.kernels_per_client={CAP}"]) as app:
        yield app


def _status(url: str, headers: dict[str, str] | None = None, method: str = "GET") -> int:
    request = urllib.request.Request(url, headers=headers or {}, method=method)
    try:
        with urllib.request.urlopen(request, timeout=90) as response:
            response.read()  # a page view lasts until the page is sent
            return int(response.status)
    except urllib.error.HTTPError as error:
        return int(error.code)


@contextmanager
def serving(html: str) -> Iterator[int]:
    """A one-page web server on localhost (a foreign site); yields its port."""

    class Page(http.server.BaseHTTPRequestHandler):
        def do_GET(self) -> None:  # noqa: N802 - the standard library's name
            body = html.encode("utf-8")
            self.send_response(200)
            self.send_header("Content-Type", "text/html; charset=utf-8")
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            self.wfile.write(body)

        def log_message(self, *args: object) -> None:
            pass

    server = http.server.ThreadingHTTPServer(("localhost", 0), Page)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield server.server_address[1]
    finally:
        server.shutdown()
        server.server_close()
        thread.join(timeout=5)


def _refusals(app: VoilaApp) -> int:
    return len(re.findall(r"403 GET / ", app.log.read_text()))


def test_a_foreign_page_starts_no_kernel_a_followed_link_does(guarded_app: VoilaApp, page) -> None:  # type: ignore[no-untyped-def]
    # "localhost" and "127.0.0.1" are different sites to the browser, both on this machine:
    # the foreign page is served from the one, the app lives on the other. (A page on a
    # public address is stopped by Chromium itself before the request leaves: its local
    # network access check. Other browsers lack it; the server's check is what counts.)
    html = f"""<!DOCTYPE html><html><body>
      <a id="link" href="{guarded_app.url}">the configurator</a>
      <img src="{guarded_app.url}"><iframe src="{guarded_app.url}"></iframe>
      <script src="{guarded_app.url}"></script>
      <script>fetch("{guarded_app.url}", {{mode: "no-cors", credentials: "include"}});</script>
    </body></html>"""
    before = _refusals(guarded_app)
    with serving(html) as foreign:
        page.goto(f"http://localhost:{foreign}/course.html")
        deadline = time.monotonic() + 20
        while _refusals(guarded_app) - before < 4 and time.monotonic() < deadline:
            time.sleep(0.2)
        assert _refusals(guarded_app) - before >= 4, guarded_app.log.read_text()[-2000:]
        time.sleep(1)
        assert guarded_app.kernels() == [], "a foreign page's request started a kernel"

        # A student who follows the course page's link gets the app.
        page.click("#link")
        page.wait_for_selector("[data-robotconf-scene='ready'] canvas", timeout=60_000)
    assert len(guarded_app.kernels()) == 1
    page.close(run_before_unload=True)
    deadline = time.monotonic() + 10
    while guarded_app.kernels() and time.monotonic() < deadline:
        time.sleep(0.2)
    assert guarded_app.kernels() == []


def test_a_host_that_is_not_this_server_is_refused(guarded_app: VoilaApp, browser) -> None:  # type: ignore[no-untyped-def]
    port = guarded_app.url.rsplit(":", 1)[1].strip("/")
    # As after DNS rebinding: a foreign name that now resolves to this machine.
    rebound = browser.browser_type.launch(
        executable_path=CHROMIUM,
        args=[*CHROMIUM_ARGS, "--host-resolver-rules=MAP rebind.test 127.0.0.1"],
    )
    try:
        page = rebound.new_page()
        response = page.goto(f"http://rebind.test:{port}/")
        assert response is not None and response.status == 403, response
        assert "not this server" in page.locator("body").inner_text()
    finally:
        rebound.close()
    for path in ("", "voila/static/voila.js", "api/kernels", "voila/api/shutdown/x"):
        assert _status(f"{guarded_app.url}{path}", {"Host": f"rebind.test:{port}"}) == 403, path
    assert _status(f"{guarded_app.url}voila/static/voila.js", {"Host": f"localhost:{port}"}) == 200
    assert guarded_app.kernels() == []


def test_kernels_per_client_are_capped_and_a_closed_tab_frees_one(  # type: ignore[no-untyped-def]
    guarded_app: VoilaApp, page
) -> None:
    kernel_id = open_app(page, guarded_app)
    cookies = {c["name"]: c["value"] for c in page.context.cookies()}
    assert "_xsrf" in cookies, cookies
    # Without the cookie's token, a page elsewhere cannot shut the kernel down.
    shutdown = f"{guarded_app.url}voila/api/shutdown/{kernel_id}"
    assert _status(shutdown, method="POST") == 403
    assert guarded_app.kernel(kernel_id) is not None

    # A plain GET is a page view too: it starts (and keeps) a kernel.
    assert _status(guarded_app.url) == 200
    assert len(guarded_app.kernels()) == CAP
    connection = http.client.HTTPConnection(guarded_app.host, timeout=90)
    connection.request("GET", "/")
    refused = connection.getresponse()
    body = refused.read().decode("utf-8")
    assert refused.status == 429 and "Too many open pages" in body, (refused.status, body)
    assert len(guarded_app.kernels()) == CAP

    # Closing the tab frees its kernel at once, so the next page is served.
    page.close(run_before_unload=True)
    seconds = guarded_app.wait_kernel_gone(kernel_id, timeout=10)
    assert seconds < 5, seconds
    # The server forgets the kernel just after its process ends.
    deadline = time.monotonic() + 5
    while f"Kernel shutdown: {kernel_id}" not in guarded_app.log.read_text():
        assert time.monotonic() < deadline, "the server did not note the shutdown"
        time.sleep(0.1)
    # The one refused shutdown is the test's own cookie-less request above.
    refused_posts = re.findall(
        rf"403 POST /voila/api/shutdown/{kernel_id} \S+ [\d.]+ms", guarded_app.log.read_text()
    )
    assert len(refused_posts) == 1, refused_posts
    # The cap counts the kernels the server still lists; on a busy machine it may list the
    # closed one a moment after its process ended. A refused page starts nothing, so ask
    # again until the place is free.
    deadline = time.monotonic() + 5
    while (status := _status(guarded_app.url)) == 429 and time.monotonic() < deadline:
        time.sleep(0.2)
    assert status == 200, status
    assert len(guarded_app.kernels()) == CAP


def test_beyond_loopback_a_token_is_required(tmp_path, spawned: list[psutil.Process]) -> None:  # type: ignore[no-untyped-def]
    # An explicitly empty token on every address: refused before anything is served.
    refused = subprocess.run(
        [sys.executable, "serve.py", "configurator.ipynb", "--no-browser",
         f"--port={_free_port()}", "--Voila.ip=0.0.0.0", "--token="],
        cwd=APP, capture_output=True, text=True, timeout=60,
    )  # fmt: skip
    assert refused.returncode == 1 and "without a token" in refused.stderr, refused.stderr

    with running_app(tmp_path, spawned, [], ip="0.0.0.0") as app:
        printed = re.search(r"\?token=([0-9a-f]{32,})", app.log.read_text())
        assert printed, app.log.read_text()
        with urllib.request.urlopen(app.url, timeout=60) as response:  # follows the redirect
            assert "/login" in response.url, response.url
        assert app.kernels() == []
        assert _status(f"{app.url}?token={printed.group(1)}") == 200
        assert len(app.kernels()) == 1
