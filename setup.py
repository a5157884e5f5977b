"""One build step beyond pyproject.toml: meshcat's three.js viewer goes into robotconf.

robotconf's 3D scene runs meshcat's viewer bundle in the browser, and only that file: the
meshcat Python package (a ZeroMQ server with pyzmq, tornado, pyngrok, PyYAML, ...) is
never run. So meshcat is a *build* requirement (pyproject.toml, pinned), not a runtime
one: building robotconf copies the bundle, its license and its third-party notices from
the meshcat package of the build environment into ``robotconf/scene/js/meshcat/``.

A wheel gets them in its build folder; an editable install gets them in the source tree
(git-ignored), so both read the viewer from robotconf itself
(:mod:`robotconf.scene._assets`). tests/test_packaging.py checks the wheel's copy is
byte for byte meshcat's.
"""

from __future__ import annotations

import shutil
from importlib.util import find_spec
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

#: Files of meshcat's package (under ``viewer/``) → names in ``robotconf/scene/js/meshcat/``.
VIEWER_FILES = {
    ("dist", "main.min.js"): "main.min.js",
    ("dist", "main.min.js.LICENSE.txt"): "main.min.js.LICENSE.txt",
    ("LICENSE",): "LICENSE",
}
TARGET = ("robotconf", "scene", "js", "meshcat")


def meshcat_viewer_folder() -> Path:
    """meshcat's ``viewer`` folder in the build environment, found without importing it."""
    spec = find_spec("meshcat")
    for folder in (spec.submodule_search_locations or []) if spec else []:
        viewer = Path(folder) / "viewer"
        if (viewer / "dist" / "main.min.js").is_file():
            return viewer
    raise RuntimeError(
        "building robotconf needs meshcat's viewer bundle: meshcat is a build requirement "
        "(pyproject.toml); with --no-build-isolation, install it first (pip install meshcat)"
    )


class BuildWithViewer(build_py):
    """setuptools' build_py, then the viewer files copied in."""

    def run(self) -> None:
        super().run()
        viewer = meshcat_viewer_folder()
        # An editable install reads the package from the source tree.
        root = Path.cwd() if self.editable_mode else Path(self.build_lib)
        target = root.joinpath(*TARGET)
        target.mkdir(parents=True, exist_ok=True)
        for source, name in VIEWER_FILES.items():
            shutil.copyfile(viewer.joinpath(*source), target / name)


setup(cmdclass={"build_py": BuildWithViewer})
