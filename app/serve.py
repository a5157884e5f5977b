"""The configurator app's server: Voilà, locked down for a classroom (docs/app.md).

``make app`` runs ``python serve.py configurator.ipynb`` in this folder: Voilà's own
command line, options and ``voila.json``, plus four locks a plain ``voila`` lacks.

- **A token unless only this computer can connect.** Listening on anything but a
  loopback address (127.0.0.1, ::1, localhost) without ``--token=<secret>`` makes up a
  token and prints it in the URL; an explicitly empty token there is refused.
- **XSRF stays on.** The page's closing request (which shuts its kernel down) sends the
  ``_xsrf`` cookie's value back, but Voilà never sets that cookie: the page's handler
  sets it here, so a closed tab frees its kernel and foreign pages still cannot post.
- **The Host header is checked** on every request (DNS rebinding: a foreign site whose
  name resolves to this server would otherwise be served as if it were this server).
  Allowed: localhost and loopback addresses, this computer's names and addresses when
  it listens beyond loopback, and ``--RobotconfApp.allowed_hosts`` (a proxy's public
  name).
- **Kernels per client are capped** (``--RobotconfApp.kernels_per_client``, default 4):
  each page view starts a kernel of ~100 MB, so one client (an address; behind a
  trusted reverse proxy the address it forwards) cannot fill the server's memory. A
  page that another site loads as a resource or frame (not a link the student follows)
  starts nothing.
"""

from __future__ import annotations

import contextvars
import ipaddress
import re
import socket
import tempfile
from collections.abc import Iterable
from typing import Any

import tornado.web
from jupyter_core.utils import ensure_async
from tornado.log import app_log
from traitlets import Integer, List, Unicode
from voila.app import Voila
from voila.tornado.handler import TornadoVoilaHandler

__all__ = ["ClientKernels", "RobotconfApp", "host_allowed", "loads_as_foreign_resource"]


class _Slot:
    """A page request's reserved place among its client's kernels."""

    def __init__(self, client: str) -> None:
        self.client = client
        self.filled = False


#: The slot of the page request that is starting a kernel right now (tornado runs each
#: request in its own task, so this follows one request through Voilà's await chain).
_SLOT: contextvars.ContextVar[_Slot] = contextvars.ContextVar("robotconf_app_slot")

#: Shown instead of the app when a client has too many pages open.
TOO_MANY_PAGES = """<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>Too many open pages</title></head>
<body style="font-family: sans-serif; max-width: 40em; margin: 3em auto">
<h1>Too many open pages</h1>
<p>This computer already has {count} configurator pages open on this server, the most it
may have. Close one of them (or wait a few minutes after closing a browser), then reload
this page.</p></body></html>
"""


def is_loopback(ip: str) -> bool:
    """Whether a listening address reaches only this computer.

    >>> is_loopback("127.0.0.1"), is_loopback("localhost"), is_loopback("0.0.0.0")
    (True, True, False)
    """
    if ip == "localhost":
        return True
    try:
        return ipaddress.ip_address(ip).is_loopback
    except ValueError:
        return False


def host_name(host_header: str) -> str:
    """The name or address in a Host header, without its port and IPv6 brackets, lowercase.

    >>> host_name("Example.org:8866"), host_name("[::1]:80"), host_name("127.0.0.1")
    ('example.org', '::1', '127.0.0.1')
    """
    match = re.fullmatch(r"\[([^\]]*)\](?::\d+)?|([^:]*)(?::\d+)?", host_header.strip())
    if match is None:
        return host_header.strip().lower()  # several colons, no brackets: no name we know
    return (match.group(1) or match.group(2) or "").lower()


def host_allowed(host_header: str, allowed: Iterable[str]) -> bool:
    """Whether a request's Host header names this server.

    >>> host_allowed("127.0.0.1:8866", {"localhost"}), host_allowed("evil.test", {"localhost"})
    (True, False)
    """
    name = host_name(host_header)
    if not name:
        return False
    try:
        if ipaddress.ip_address(name).is_loopback:
            return True
    except ValueError:
        pass
    return name in {entry.lower() for entry in allowed}


def own_names(ip: str) -> set[str]:
    """The names and addresses this server may be reached by when listening on ``ip``."""
    names = {"localhost"}
    if is_loopback(ip):
        return names
    names |= {socket.gethostname().lower(), socket.getfqdn().lower()}
    if ip not in ("", "0.0.0.0", "::"):
        names.add(ip.lower())
        return names
    try:  # every interface's address: a student may type any of them
        import psutil

        for addresses in psutil.net_if_addrs().values():
            names |= {a.address.split("%")[0].lower() for a in addresses if a.family in (2, 10)}
    except ImportError:  # pragma: no cover - ipykernel (the app extra) brings psutil
        names |= {info[4][0] for info in socket.getaddrinfo(socket.gethostname(), None)}
    return names


def loads_as_foreign_resource(headers: Any) -> bool:
    """Whether another site is loading the page as a resource, frame or script.

    Browsers say who asked for a request in its ``Sec-Fetch-*`` headers. A student who
    follows a link from a course page makes a top-level navigation, which is allowed; a
    foreign page's ``fetch``, ``<img>`` or ``<iframe>`` pointed at the app is not.

    >>> loads_as_foreign_resource({"Sec-Fetch-Site": "cross-site", "Sec-Fetch-Mode": "no-cors",
    ...                            "Sec-Fetch-Dest": "empty"})
    True
    >>> loads_as_foreign_resource({"Sec-Fetch-Site": "cross-site", "Sec-Fetch-Mode": "navigate",
    ...                            "Sec-Fetch-Dest": "document"})
    False
    """
    site = headers.get("Sec-Fetch-Site")
    if site in (None, "same-origin", "none"):
        return False
    navigation = headers.get("Sec-Fetch-Mode") == "navigate"
    return not (navigation and headers.get("Sec-Fetch-Dest") == "document")


class ClientKernels:
    """The kernels each client started, and its page requests about to start one, against
    a cap.

    >>> kernels = ClientKernels(cap=1)
    >>> kernels.reserve("10.0.0.7", live=[])
    True
    >>> kernels.started("10.0.0.7", "k1")  # the reserved slot now holds kernel k1
    >>> kernels.reserve("10.0.0.7", live=["k1"]), kernels.reserve("10.0.0.7", live=[])
    (False, True)
    """

    def __init__(self, cap: int) -> None:
        self.cap = cap
        self._kernels: dict[str, set[str]] = {}
        self._pending: dict[str, int] = {}

    def count(self, client: str, live: Iterable[str]) -> int:
        """Kernels of ``client`` still running, plus its page requests starting one."""
        mine = self._kernels.get(client, set()) & set(live)
        self._kernels[client] = mine
        return len(mine) + self._pending.get(client, 0)

    def reserve(self, client: str, live: Iterable[str]) -> bool:
        """Take a slot for a page about to start a kernel; False when the cap is reached.

        The slot is held until :meth:`started` fills it or :meth:`release` gives it back.
        """
        if self.count(client, live) >= self.cap:
            return False
        self._pending[client] = self._pending.get(client, 0) + 1
        return True

    def started(self, client: str, kernel_id: str) -> None:
        """A reserved slot of ``client`` now holds the kernel ``kernel_id``."""
        self._kernels.setdefault(client, set()).add(kernel_id)
        self.release(client)

    def release(self, client: str) -> None:
        """Give back a reserved slot that started no kernel."""
        self._pending[client] = max(0, self._pending.get(client, 0) - 1)


class HostRefusedHandler(tornado.web.RequestHandler):
    """Every request whose Host header does not name this server: 403."""

    def prepare(self) -> None:
        app_log.warning("Refused a request for host %r", self.request.host)
        self.set_status(403)
        self.set_header("Content-Type", "text/plain; charset=utf-8")
        self.finish("403: the address in this request's Host header is not this server.\n")


class HostCheckingApplication(tornado.web.Application):
    """Tornado's application, refusing requests for a host this server is not."""

    def find_handler(self, request: Any, **kwargs: Any) -> Any:
        if not host_allowed(request.host or "", self.settings["robotconf_allowed_hosts"]):
            return self.get_handler_delegate(request, HostRefusedHandler)
        return super().find_handler(request, **kwargs)


class GuardedVoilaHandler(TornadoVoilaHandler):
    """Voilà's page (the one request that starts a kernel), with the cap and XSRF cookie."""

    def client(self) -> str:
        """The client's address; behind a trusted proxy, the address it forwards."""
        address = self.request.remote_ip or ""
        forwarded = self.request.headers.get("X-Forwarded-For", "")
        if forwarded and address in self.settings["robotconf_trusted_proxies"]:
            return forwarded.split(",")[-1].strip()
        return address

    @tornado.web.authenticated
    async def get(self, path: str | None = None) -> None:
        if loads_as_foreign_resource(self.request.headers):
            raise tornado.web.HTTPError(403, "the app is not loaded by other sites")
        client = self.client()
        kernels: ClientKernels = self.settings["robotconf_client_kernels"]
        if not kernels.reserve(client, self.kernel_manager.list_kernel_ids()):
            self.log.warning("Refused a page for %s: %d kernels open", client, kernels.cap)
            self.set_status(429)
            self.set_header("Retry-After", "60")
            self.finish(TOO_MANY_PAGES.format(count=kernels.cap))
            return
        # Setting the cookie is what reading the token does; the page sends it back with
        # its closing request (a form field, as Jupyter Server checks it).
        _ = self.xsrf_token
        slot = _Slot(client)
        token = _SLOT.set(slot)
        try:
            await super().get(path)
        finally:
            _SLOT.reset(token)
            if not slot.filled:  # no kernel started (an error, a redirect)
                kernels.release(client)


class RobotconfApp(Voila):
    """``voila`` with the locks of this module; reads ``voila.json`` like ``voila``."""

    name = "voila"
    description = Unicode(__doc__.splitlines()[0])

    kernels_per_client = Integer(
        4, config=True, help="Kernels (open pages) one client address may have at once."
    )
    allowed_hosts = List(
        Unicode(),
        config=True,
        help="Extra names the Host header may carry (a reverse proxy's public name).",
    )
    trusted_proxies = List(
        Unicode(),
        config=True,
        help="Addresses of reverse proxies whose X-Forwarded-For names the client.",
    )

    def init_settings(self) -> dict[str, Any]:
        if not is_loopback(self.ip):
            if self.token == "":
                self.log.critical(
                    "Refusing to serve on %s without a token: anyone who reaches this "
                    "address could start kernels. Give --token=<secret> (or leave it out "
                    "to have one made up).",
                    self.ip or "every address",
                )
                self.exit(1)
            if self.token is None:
                self.auto_token = True
        settings = super().init_settings()
        kernels = ClientKernels(self.kernels_per_client)
        self._note_kernel_clients(kernels)
        settings.update(
            robotconf_allowed_hosts=own_names(self.ip) | set(self.allowed_hosts),
            robotconf_trusted_proxies=set(self.trusted_proxies),
            robotconf_client_kernels=kernels,
        )
        return settings

    def _note_kernel_clients(self, kernels: ClientKernels) -> None:
        """Make the kernel manager note which client each page kernel was started for."""
        manager = self.kernel_manager
        start_kernel = manager.start_kernel

        async def start_and_note(*args: Any, **kwargs: Any) -> str:
            kernel_id = str(await ensure_async(start_kernel(*args, **kwargs)))
            slot = _SLOT.get(None)
            if slot is not None and not slot.filled:
                slot.filled = True
                kernels.started(slot.client, kernel_id)
            return kernel_id

        manager.start_kernel = start_and_note

    def start(self) -> None:
        # Voilà's own start, with the host-checking application and the guarded page.
        self.connection_dir = tempfile.mkdtemp(prefix="voila_", dir=self.connection_dir_root)
        settings = self.init_settings()
        self.app = HostCheckingApplication(**settings)
        self.app.settings.update(self.tornado_settings)
        handlers = [
            (rule[0], GuardedVoilaHandler, *rule[2:]) if rule[1] is TornadoVoilaHandler else rule
            for rule in self.init_handlers()
        ]
        self.app.add_handlers(".*$", handlers)
        self.listen()


if __name__ == "__main__":
    RobotconfApp.launch_instance()
