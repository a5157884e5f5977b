"""The browser-only classroom (``make lite``): the JupyterLite site, checked file by file.

The site is built once per session by ``lite/build.py`` into a temporary folder (about
10 s; up to a minute more when its tools venv, ``build/lite/venv``, kept between runs,
must be made from PyPI), or taken from ``$ROBOTCONF_LITE_SITE`` (``make test-lite``
checks the ``dist/lite`` that ``make lite`` just built).
``tests/browser/test_lite_browser.py`` opens the same site in Chromium.

What no test here can show: the in-browser kernel running robotconf. That needs Pyodide's
runtime and its numpy, pandas and matplotlib, which a deployed site loads from Pyodide's
CDN, out of reach of this machine. Instead, a test resolves what the notebooks' first cell
installs against the site's wheels and Pyodide 0.27.6's package list, as micropip would.
"""

from __future__ import annotations

import ast
import asyncio
import hashlib
import importlib.util
import json
import os
import subprocess
import sys
import zipfile
from email.parser import Parser
from pathlib import Path
from types import ModuleType

import nbformat
import pytest
from packaging.markers import Marker
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name
from packaging.version import Version

from .test_packaging import RUNTIME_FILES, checkout_files, package_sources

ROOT = Path(__file__).resolve().parents[1]

# Building the site (and, on a fresh machine, its tools venv) counts toward the first test.
pytestmark = pytest.mark.timeout(900)

#: What Pyodide 0.27.6 ships (name: version) among what robotconf's dependencies ask for,
#: from its ``pyodide-lock.json`` (npm package ``pyodide@0.27.6``). micropip takes these
#: from Pyodide's distribution before any index, with their own dependencies.
PYODIDE_PACKAGES = {
    "numpy": "2.0.2",
    "pandas": "2.2.3",
    "matplotlib": "3.8.4",
    "sympy": "1.13.3",
    "tqdm": "4.66.2",
    "msgpack": "1.1.0",
    "ipython": "8.23.0",
    "traitlets": "5.14.3",
    "typing-extensions": "4.11.0",
}

#: Environment markers as Pyodide 0.27.6 evaluates them.
PYODIDE_ENV = {
    "python_version": "3.12",
    "python_full_version": "3.12.7",
    "sys_platform": "emscripten",
    "platform_system": "Emscripten",
    "platform_machine": "wasm32",
    "os_name": "posix",
    "implementation_name": "cpython",
    "platform_python_implementation": "CPython",
    "extra": "",
}

_BUILT: dict[str, Path] = {}


def load_build_script() -> ModuleType:
    """``lite/build.py`` as a module (``lite/`` is not a package)."""
    spec = importlib.util.spec_from_file_location("robotconf_lite_build", ROOT / "lite/build.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def site_folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The site under test, built at most once per session (see the module docstring)."""
    given = os.environ.get("ROBOTCONF_LITE_SITE")
    if given:
        site = Path(given)
        assert (site / "jupyter-lite.json").is_file(), f"no JupyterLite site in {site}"
        return site
    if "site" not in _BUILT:
        work = tmp_path_factory.mktemp("lite")
        result = subprocess.run(
            [
                sys.executable,
                str(ROOT / "lite/build.py"),
                f"--out={work / 'site'}",
                f"--stage={work / 'stage'}",
            ],
            capture_output=True,
            text=True,
            timeout=840,
        )
        assert result.returncode == 0, f"lite/build.py failed\n{result.stdout}\n{result.stderr}"
        _BUILT["site"] = work / "site"
    return _BUILT["site"]


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return site_folder(tmp_path_factory)


@pytest.fixture(scope="module")
def build_script() -> ModuleType:
    return load_build_script()


def config(site: Path) -> dict:
    return json.loads((site / "jupyter-lite.json").read_text())["jupyter-config-data"]


def test_site_has_the_pinned_kernel_and_the_widget_front_ends(site: Path) -> None:
    data = config(site)
    assert data["appName"] == "robotconf classroom"
    extensions = {e["name"] for e in data["federated_extensions"]}
    assert {
        "@jupyterlite/pyodide-kernel-extension",
        "@jupyter-widgets/jupyterlab-manager",
        "anywidget",
    } <= extensions, extensions
    # Exactly the tools venv's front ends: nothing from the project's .venv (Voila...).
    assert not {e for e in extensions if "voila" in e}, extensions

    kernel = site / "extensions/@jupyterlite/pyodide-kernel-extension/package.json"
    assert json.loads(kernel.read_text())["version"] == "0.6.1"  # see lite/requirements.txt
    anywidget = json.loads((site / "extensions/anywidget/package.json").read_text())
    assert (site / f"pypi/anywidget-{anywidget['version']}-py3-none-any.whl").is_file(), (
        "the anywidget front end and the wheel the kernel installs differ"
    )
    kernel_settings = data["litePluginSettings"]["@jupyterlite/pyodide-kernel-extension:kernel"]
    urls = kernel_settings["pipliteUrls"]
    assert urls[0].startswith("./pypi/all.json"), urls


def test_site_holds_the_notebooks_and_the_course_without_solutions(site: Path) -> None:
    files = site / "files"
    names = {p.relative_to(files).as_posix() for p in files.rglob("*") if p.is_file()}
    expected = {f"notebooks/{p.name}" for p in (ROOT / "notebooks").glob("*.ipynb")}
    for lesson in sorted(p for p in (ROOT / "course").iterdir() if p.name[:2].isdigit()):
        expected |= {f"course/{lesson.name}/{p.name}" for p in lesson.glob("*.ipynb")}
    assert "notebooks/configurator.ipynb" in expected and len(expected) > 16
    assert expected | {"course/README.md", "paper_robot_3d.html"} <= names
    assert not [n for n in names if "solutions" in n], "course/solutions/ must stay out"
    assert "course/INSTRUCTOR.md" not in names, "the instructor's notes must stay out"

    # The file browser's listing, as the site serves it.
    listing = json.loads((site / "api/contents/notebooks/all.json").read_text())
    assert "configurator.ipynb" in {item["name"] for item in listing["content"]}
    top = json.loads((site / "api/contents/all.json").read_text())
    assert {item["name"] for item in top["content"]} == {
        "notebooks",
        "course",
        "paper_robot_3d.html",
    }


def test_every_notebook_opens_with_the_install_cell(site: Path, build_script: ModuleType) -> None:
    notebooks = sorted((site / "files").rglob("*.ipynb"))
    assert notebooks
    for path in notebooks:
        notebook = nbformat.read(path, as_version=4)
        first, rest = notebook.cells[0], notebook.cells[1:]
        assert first.id == build_script.INSTALL_CELL_ID, path
        assert first.source == build_script.INSTALL_CELL, path
        assert notebook.metadata["kernelspec"]["name"] == "python", path  # the Pyodide kernel
        source = nbformat.read(ROOT / path.relative_to(site / "files"), as_version=4)
        assert [c.source for c in rest] == [c.source for c in source.cells], path


def test_install_cell_installs_robotconf_and_is_a_no_op_elsewhere(
    build_script: ModuleType,
) -> None:
    cell = build_script.INSTALL_CELL
    # robotconf's wheel carries the 3D viewer: meshcat (and its pyzmq) is not installed.
    assert 'piplite.install("robotconf")' in cell and "meshcat" not in cell
    # Valid IPython (top-level await), and nothing happens outside the browser.
    code = compile(cell, "<install cell>", "exec", flags=ast.PyCF_ALLOW_TOP_LEVEL_AWAIT)
    namespace: dict = {}
    pending = eval(code, namespace)  # our own constant, not user input
    if pending is not None:
        asyncio.run(pending)
    assert "piplite" not in namespace and "piplite" not in sys.modules


def robotconf_wheel(site: Path) -> Path:
    wheels = sorted((site / "pypi").glob("robotconf-*.whl"))
    assert len(wheels) == 1, wheels
    return wheels[0]


def wheel_metadata(path: Path) -> dict[str, list[str]]:
    """Name, Version and Requires-Dist of a wheel's METADATA."""
    with zipfile.ZipFile(path) as wheel:
        (name,) = [n for n in wheel.namelist() if n.endswith(".dist-info/METADATA")]
        message = Parser().parsestr(wheel.read(name).decode("utf-8"))
    return {key: message.get_all(key) or [] for key in ("Name", "Version", "Requires-Dist")}


def test_robotconf_wheel_in_the_site_holds_every_runtime_file(site: Path) -> None:
    python, data = package_sources(checkout_files())
    assert set(RUNTIME_FILES) <= data
    with zipfile.ZipFile(robotconf_wheel(site)) as wheel:
        names = set(wheel.namelist())
    assert not sorted(data - names), "non-Python package files missing from the site's wheel"
    assert not sorted(python - names), "Python sources missing from the site's wheel"

    requires = {
        canonicalize_name(Requirement(r).name)
        for r in wheel_metadata(robotconf_wheel(site))["Requires-Dist"]
        if not Requirement(r).marker or "extra" not in str(Requirement(r).marker)
    }
    # JupyterLab (a server) cannot install in the browser: it must be an extra, not a need.
    assert "jupyterlab" not in requires, sorted(requires)
    assert "meshcat" not in requires  # its viewer is in the wheel; its server is not needed
    assert "robotconf/scene/js/meshcat/main.min.js" in names


def site_index(site: Path) -> dict[str, dict[Version, Path]]:
    """Every wheel the kernel's installer finds in the site: name -> {version: file}.

    Both indexes the site lists, in the installer's order (its own wheels, then the
    kernel's): a name is looked up in the first index that has it. Each entry is checked
    against its file, as the installer refuses a wheel whose sha256 differs.
    """
    found: dict[str, dict[Version, Path]] = {}
    for index in (
        site / "pypi/all.json",
        site / "extensions/@jupyterlite/pyodide-kernel-extension/static/pypi/all.json",
    ):
        releases: dict[str, dict[Version, Path]] = {}
        for name, entry in json.loads(index.read_text()).items():
            for version, artifacts in entry["releases"].items():
                for artifact in artifacts:
                    wheel = index.parent / artifact["url"]
                    digest = hashlib.sha256(wheel.read_bytes()).hexdigest()
                    assert digest == artifact["digests"]["sha256"], wheel
                    releases.setdefault(canonicalize_name(name), {})[Version(version)] = wheel
        found = releases | found
    return found


def test_every_runtime_dependency_comes_from_the_site_or_pyodide(site: Path) -> None:
    """Resolve the first cell's installs as micropip does; nothing may need PyPI."""
    index = site_index(site)
    pyodide = {name: Version(v) for name, v in PYODIDE_PACKAGES.items()}
    installed: dict[str, str] = {}
    todo = [Requirement("robotconf")]
    unmet: list[str] = []
    while todo:
        req = todo.pop()
        name = canonicalize_name(req.name)
        if req.marker and not Marker(str(req.marker)).evaluate(PYODIDE_ENV):
            continue
        if name in installed:
            continue
        if name in pyodide:
            version = pyodide[name]
            installed[name] = f"Pyodide {version}"
        elif name in index:
            # The newest release that fits, as micropip picks.
            fits = [v for v in index[name] if req.specifier.contains(v, prereleases=True)]
            version = max(fits or index[name])
            wheel = index[name][version]
            installed[name] = f"site {version}"
            assert wheel.name.endswith("-none-any.whl"), f"{wheel.name} is not pure Python"
            todo += [Requirement(r) for r in wheel_metadata(wheel)["Requires-Dist"]]
        else:
            unmet.append(str(req))
            continue
        if not req.specifier.contains(version, prereleases=True):
            unmet.append(f"{req} (gets {version})")
    assert not unmet, f"would come from PyPI or not install at all: {unmet}; have {installed}"
    assert {"numpy", "anywidget", "ipywidgets", "robotconf"} <= set(installed), installed
    assert not {"meshcat", "pyzmq", "tornado"} & set(installed), installed


def test_scene_page_is_self_contained(site: Path) -> None:
    page = site / "files/paper_robot_3d.html"
    text = page.read_text(encoding="utf-8")
    assert page.stat().st_size > 500_000, "meshcat's viewer is not inlined"
    assert "http://" not in text.split("<script", 1)[0] and 'src="http' not in text
    assert "<script src=" not in text
