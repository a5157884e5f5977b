"""A notebook's 3D scene loads only what a browser kernel (Pyodide, JupyterLite) has.

robotconf reads meshcat's viewer bundle as a file and encodes meshcat's commands itself,
so drawing and moving a robot never runs the meshcat package, whose ``__init__`` loads its
server stack (pyzmq, tornado, Pillow, IPython's terminal). JupyterLab and its server are
the ``lab`` extra, never imported by the package. Each check runs in a fresh interpreter:
modules this test process imported (pytest, meshcat for the encoding comparison) would
otherwise hide what robotconf itself loads.

The widget libraries (anywidget, ipywidgets, traitlets, comm, psygnal) are allowed, and
ipywidgets imports ``IPython`` for ``IPython.display``: only IPython's terminal machinery
is banned, and only where ``import IPython`` does not load it by itself.
"""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

#: Never loaded by import, scene, update: meshcat's package and its server dependencies,
#: meshcat's own packer, and the JupyterLab front end and server.
BANNED = (
    "zmq",
    "tornado",
    "PIL",
    "meshcat",
    "umsgpack",
    "pyngrok",
    "jupyterlab",
    "jupyter_server",
)

#: What a notebook does: import, draw the paper robot in a widget, move it; then the
#: calls that read the viewer bundle and pack typed arrays.
NOTEBOOK = """\
import json, sys
import robotconf as rc

robot = rc.preset("paper")
scene = rc.Scene(robot)
scene.update([0.3, -0.5, 0.8])
scene.update([0.0, -1.0, 1.3])
assert scene.widget is not None and scene.labels()[-1].startswith("EE (")
assert len(scene.pane.code.source) > 500_000, "meshcat's viewer bundle was not read"
scene.show_frames(True)
scene.add_point_cloud("workspace", [[0, 0, 0], [10, 0, 0], [0, 10, 0]])
print(json.dumps(sorted(sys.modules)))
"""


def loaded_modules(code: str) -> set[str]:
    """The names in ``sys.modules`` after ``code`` runs in a fresh interpreter."""
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=120
    )
    assert result.returncode == 0, result.stderr
    return set(json.loads(result.stdout.splitlines()[-1]))


def loaded(modules: set[str], name: str) -> bool:
    """Whether ``name`` or any of its submodules is in ``modules``."""
    return any(m == name or m.startswith(name + ".") for m in modules)


@pytest.fixture(scope="module")
def notebook_modules() -> set[str]:
    return loaded_modules(NOTEBOOK)


def test_scene_loads_no_server_stack_and_no_jupyterlab(notebook_modules: set[str]) -> None:
    found = [name for name in BANNED if loaded(notebook_modules, name)]
    assert not found, f"a notebook's scene loaded: {found}"
    # The scene did run, through the widget transport and robotconf's encoder.
    assert {"anywidget", "msgpack", "robotconf.scene._three"} <= notebook_modules


def test_scene_loads_no_ipython_terminal(notebook_modules: set[str]) -> None:
    if loaded(
        loaded_modules("import IPython, json, sys; print(json.dumps(list(sys.modules)))"),
        "IPython.terminal",
    ):
        pytest.skip("this IPython loads its terminal on `import IPython` (ipywidgets needs it)")
    found = sorted(m for m in notebook_modules if loaded({m}, "IPython.terminal"))
    assert not found, f"a notebook's scene loaded: {found[:5]}"
