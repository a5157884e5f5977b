"""A class on one computer: JupyterHub for robotconf (``make hub``, docs/hub.md).

Every student logs in at the hub's one address and gets their own JupyterLab, started
from the *student* environment (robotconf and JupyterLab, no teacher tools such as
nbgrader) with the class material copied into their home folder. Every request goes
through configurable-http-proxy; the hub and each student's server listen on 127.0.0.1
only, behind it.

Settings come from the environment (``make hub`` sets them; the defaults suit a try on
this computer):

``ROBOTCONF_HUB_PORT``
    the proxy's public port (8000), on ``ROBOTCONF_HUB_IP`` (127.0.0.1; a class on the
    network needs HTTPS in front, docs/hub.md)
``ROBOTCONF_HUB_DATA``
    the hub's database, cookie secret and the students' home folders (build/hub/data)
``ROBOTCONF_HUB_STUDENTS``
    comma-separated user names allowed to log in (``ada,alan``)
``ROBOTCONF_HUB_PASSWORD``
    the one shared password of the trial login (SharedPasswordAuthenticator, at least
    8 characters); required
``ROBOTCONF_HUB_VENV``, ``ROBOTCONF_HUB_PROXY``
    the student environment and the proxy's command (as ``make hub-env`` installs them)
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path
from typing import Any

HUB = Path(__file__).resolve().parent
ROOT = HUB.parent
BUILD = ROOT / "build" / "hub"

DATA = Path(os.environ.get("ROBOTCONF_HUB_DATA", BUILD / "data")).resolve()
VENV = Path(os.environ.get("ROBOTCONF_HUB_VENV", BUILD / "student-venv")).resolve()
PROXY = os.environ.get(
    "ROBOTCONF_HUB_PROXY", str(BUILD / "node_modules" / ".bin" / "configurable-http-proxy")
)
IP = os.environ.get("ROBOTCONF_HUB_IP", "127.0.0.1")
PORT = int(os.environ.get("ROBOTCONF_HUB_PORT", "8000"))
#: The hub's own API and the proxy's REST API: internal, on 127.0.0.1 only.
HUB_PORT = int(os.environ.get("ROBOTCONF_HUB_INTERNAL_PORT", str(PORT + 1)))
PROXY_API_PORT = int(os.environ.get("ROBOTCONF_HUB_PROXY_API_PORT", str(PORT + 2)))
STUDENTS = {
    name.strip() for name in os.environ.get("ROBOTCONF_HUB_STUDENTS", "ada,alan").split(",")
}
STUDENTS.discard("")

#: What each student finds in their home folder: the configurator, the notebooks and the
#: course's exercises (never the solutions or the instructor's notes).
CLASS_MATERIAL = {"notebooks": ROOT / "notebooks", "course": ROOT / "course"}
WITHHELD = shutil.ignore_patterns("solutions", "INSTRUCTOR.md", ".ipynb_checkpoints")


def copy_class_material(spawner: Any) -> None:
    """Before a student's first start: copy the class material into their home folder.

    A student's own copy is never overwritten: their edits survive a server restart.
    """
    home = Path(spawner.home_dir_template.format(username=spawner.user.name))
    home.mkdir(parents=True, exist_ok=True)
    configurator = home / "configurator.ipynb"
    if not configurator.exists():
        shutil.copy(ROOT / "notebooks" / "configurator.ipynb", configurator)
    for name, source in CLASS_MATERIAL.items():
        if not (home / name).exists():
            shutil.copytree(source, home / name, ignore=WITHHELD)


DATA.mkdir(parents=True, exist_ok=True)
c = get_config()  # type: ignore[name-defined]  # noqa: F821 - JupyterHub's config loader

c.JupyterHub.bind_url = f"http://{IP}:{PORT}"
c.JupyterHub.hub_bind_url = f"http://127.0.0.1:{HUB_PORT}"
c.ConfigurableHTTPProxy.command = [PROXY]
c.ConfigurableHTTPProxy.api_url = f"http://127.0.0.1:{PROXY_API_PORT}"
c.ConfigurableHTTPProxy.auth_token = (
    os.environ.get("CONFIGPROXY_AUTH_TOKEN") or os.urandom(32).hex()
)
c.ConfigurableHTTPProxy.pid_file = str(DATA / "proxy.pid")
c.JupyterHub.db_url = f"sqlite:///{DATA / 'jupyterhub.sqlite'}"
c.JupyterHub.cookie_secret_file = str(DATA / "jupyterhub_cookie_secret")
c.JupyterHub.pid_file = str(DATA / "jupyterhub.pid")
# Students' servers stop with the hub (a real class keeps them: docs/hub.md).
c.JupyterHub.cleanup_servers = True
c.JupyterHub.cleanup_proxy = True

# A trial login: the listed students, one shared password (at least 8 characters). A
# class uses the university's login instead (docs/hub.md: OAuthenticator, LTI, LDAP).
c.JupyterHub.authenticator_class = "shared-password"
c.SharedPasswordAuthenticator.user_password = os.environ["ROBOTCONF_HUB_PASSWORD"]
c.Authenticator.allowed_users = STUDENTS

# Each student's server: a process of this user, in their own home folder, from the
# student environment.
c.JupyterHub.spawner_class = "simple"
c.SimpleLocalProcessSpawner.home_dir_template = str(DATA / "home" / "{username}")
c.Spawner.cmd = [str(VENV / "bin" / "jupyterhub-singleuser")]
c.Spawner.default_url = "/lab/tree/configurator.ipynb"
c.Spawner.pre_spawn_hook = copy_class_material
c.Spawner.environment = {
    "PATH": f"{VENV / 'bin'}{os.pathsep}{os.environ.get('PATH', '/usr/bin:/bin')}",
    "VIRTUAL_ENV": str(VENV),
    "MPLBACKEND": "module://matplotlib_inline.backend_inline",
}
c.Spawner.args = [
    # No news or update checks from a class's servers (hub/overrides.json, installed into
    # the student environment, also keeps the news prompt off the student's page).
    "--LabApp.news_url=",
    "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
    *(["--allow-root"] if os.geteuid() == 0 else []),
]
c.Spawner.start_timeout = 120
c.Spawner.http_timeout = 120
