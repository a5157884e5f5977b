"""The built wheel: what a user gets from ``pip install robotconf``, not the editable checkout.

``make lab`` and ``make test`` use an editable install, which reads every file straight from
the source tree and so hides files the wheel leaves out (the scene's JavaScript, read at run
time by :mod:`robotconf.scene._assets`, once was). These tests build a wheel from a copy of
the checkout, as a release would, and look inside it.

- :func:`test_wheel_holds_every_package_file_and_the_console_script` runs everywhere and
  takes a few seconds: a wheel built offline (``pip wheel --no-deps --no-build-isolation``,
  the dev extra provides setuptools and wheel) must hold every ``.py`` and every other file
  of ``robotconf/``, and declare the ``robotconf`` console script.
- :func:`test_wheel_installs_and_runs_in_a_fresh_venv` runs only when ``CI=true``: it installs
  the wheel with its dependencies into a new venv (minutes, needs the package index) and
  draws the paper robot's 3D scene there, outside the repository.
"""

from __future__ import annotations

import configparser
import importlib
import json
import os
import re
import shutil
import subprocess
import sys
import zipfile

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib  # type: ignore[no-redef]
from pathlib import Path, PurePosixPath

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = "robotconf"

#: Non-Python files the package reads at run time; each must also be in the source listing.
RUNTIME_FILES = (
    "robotconf/scene/js/glue.js",
    "robotconf/scene/js/loader.js",
    "robotconf/scene/js/widget.js",
    "robotconf/scene/js/labels.js",
    "robotconf/scene/js/player.js",
    "robotconf/scene/js/bar.js",
    "robotconf/scene/js/mount.js",
    "robotconf/panel/form/js/controls.js",
    "robotconf/panel/form/js/form.js",
    "robotconf/panel/form/js/form.css",
)

#: Run in the fresh venv, from a folder outside the repository: argv = venv, html path.
SMOKE_SCRIPT = """\
import sys
from pathlib import Path

import robotconf

venv, html_path = Path(sys.argv[1]).resolve(), Path(sys.argv[2])
module = Path(robotconf.__file__).resolve()
assert module.is_relative_to(venv), f"robotconf imported from {module}, not from {venv}"
robot = robotconf.preset("paper")
scene = robotconf.view(robot, display=False)
labels = scene.labels()
assert labels[-1].endswith("EE (70.0, 0.0, 20.0)"), labels
path = scene.export_html(html_path)
assert path.is_file(), path
text = path.read_text(encoding="utf-8")
size = path.stat().st_size
assert size > 500_000, f"{size} bytes: meshcat's viewer is not inlined"
assert "<script src=" not in text, "the exported page loads a script from elsewhere"
# meshcat's bundle is read as a file: its package (and its server stack) never runs.
assert "meshcat" not in sys.modules and "zmq" not in sys.modules, "meshcat's package ran"
print("smoke ok", module, size)
"""


def run(
    args: list[str | Path], *, timeout: float, cwd: Path | None = None
) -> subprocess.CompletedProcess[str]:
    """Run a command without our virtualenv's variables; fail with its output if it fails."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
    env["MPLBACKEND"] = "Agg"
    result = subprocess.run(
        [str(arg) for arg in args],
        capture_output=True,
        text=True,
        timeout=timeout,
        cwd=cwd,
        env=env,
    )
    assert result.returncode == 0, (
        f"{' '.join(str(arg) for arg in args)} exited with {result.returncode}\n"
        f"--- stdout\n{result.stdout}\n--- stderr\n{result.stderr}"
    )
    return result


def checkout_files() -> list[str]:
    """Files of the working tree as git sees them: tracked and new, not ignored, not deleted.

    Not ``git archive HEAD``: the working tree may hold uncommitted changes under review.
    """
    listing = subprocess.run(
        ["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
        cwd=ROOT,
        capture_output=True,
        check=True,
        timeout=60,
    ).stdout.decode("utf-8")
    names = sorted({name for name in listing.split("\0") if name})
    return [name for name in names if (ROOT / name).is_file()]


def package_sources(files: list[str]) -> tuple[set[str], set[str]]:
    """The ``.py`` files and the other files of ``robotconf/`` in ``files``."""
    inside = [
        name
        for name in files
        if PurePosixPath(name).parts[0] == PACKAGE
        and "__pycache__" not in PurePosixPath(name).parts
    ]
    python = {name for name in inside if name.endswith(".py")}
    return python, set(inside) - python


@pytest.fixture(scope="module")
def source_files() -> list[str]:
    """:func:`checkout_files`, once per module."""
    return checkout_files()


@pytest.fixture(scope="module")
def wheel_build(
    tmp_path_factory: pytest.TempPathFactory, source_files: list[str]
) -> tuple[Path, str]:
    """A wheel built offline from a copy of the checkout (no stale build/ or egg-info), and
    the build's log (pip's ``--verbose`` shows the backend's warnings)."""
    copy = tmp_path_factory.mktemp("checkout")
    for name in source_files:
        target = copy / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(ROOT / name, target)
    dist = tmp_path_factory.mktemp("dist")
    build = run(
        [
            sys.executable,
            "-m",
            "pip",
            "wheel",
            "--no-deps",
            "--no-build-isolation",
            "--no-index",
            "--verbose",
            "-w",
            dist,
            copy,
        ],
        timeout=300,
    )
    wheels = sorted(dist.glob(f"{PACKAGE}-*.whl"))
    assert len(wheels) == 1, f"expected one {PACKAGE} wheel in {dist}, found {wheels}"
    return wheels[0], build.stdout + build.stderr


@pytest.fixture(scope="module")
def built_wheel(wheel_build: tuple[Path, str]) -> Path:
    """The wheel of :func:`wheel_build`."""
    return wheel_build[0]


def test_wheel_builds_without_warnings_and_names_its_license(
    wheel_build: tuple[Path, str],
) -> None:
    wheel, log = wheel_build
    # setuptools announces removals (the license table, on 2027-02-18) as warnings in the
    # build log: any of them is a build that stops working on a later setuptools. (Its
    # plain "warning: ... byte-compiling is disabled" notes are not warnings classes.)
    warning = re.compile(r"deprecat|\w+Warning\b", re.IGNORECASE)
    warnings = [line for line in log.splitlines() if warning.search(line)]
    assert not warnings, "\n".join(warnings)
    with zipfile.ZipFile(wheel) as archive:
        metadata_name = next(n for n in archive.namelist() if n.endswith(".dist-info/METADATA"))
        metadata = archive.read(metadata_name).decode("utf-8")
    assert "License-Expression: MIT" in metadata.splitlines(), metadata[:800]


#: What meshcat's Python package would bring (its ZeroMQ server): robotconf never runs it,
#: so an install of robotconf must not hold any of these.
MESHCAT_SERVER_STACK = ("meshcat", "pyzmq", "tornado", "pyngrok", "pyyaml", "u-msgpack-python")


def test_wheel_carries_meshcats_viewer_byte_for_byte_and_needs_no_meshcat(
    built_wheel: Path,
) -> None:
    viewer = Path(importlib.import_module("meshcat").__file__ or "").parent / "viewer"
    with zipfile.ZipFile(built_wheel) as wheel:
        bundle = wheel.read("robotconf/scene/js/meshcat/main.min.js")
        license_text = wheel.read("robotconf/scene/js/meshcat/LICENSE").decode("utf-8")
        metadata_name = next(n for n in wheel.namelist() if n.endswith(".dist-info/METADATA"))
        metadata = wheel.read(metadata_name).decode("utf-8")
    assert bundle == (viewer / "dist" / "main.min.js").read_bytes()
    assert "MIT" in license_text or "Permission is hereby granted" in license_text
    requires = [line.split(":", 1)[1].strip() for line in metadata.splitlines()
                if line.startswith("Requires-Dist:") and "extra ==" not in line]  # fmt: skip
    names = {re.split(r"[ <>=!;\[(]", r, maxsplit=1)[0].lower() for r in requires}
    assert not names & set(MESHCAT_SERVER_STACK), sorted(names)


def test_every_runtime_requirement_is_used_by_the_package() -> None:
    """A dependency robotconf never imports (or names, as pandas' Excel engine) is weight."""
    project = tomllib.loads((ROOT / "pyproject.toml").read_text("utf-8"))["project"]
    sources = "\n".join(p.read_text("utf-8") for p in (ROOT / PACKAGE).rglob("*.py"))
    for requirement in project["dependencies"]:
        name = re.split(r"[ <>=!;\[]", requirement, maxsplit=1)[0].replace("-", "_")
        used = rf"^\s*(import|from) {name}\b|[\"']{name}[\"']"
        assert re.search(used, sources, re.MULTILINE), f"{requirement}: never imported"


def test_the_build_backend_is_pinned() -> None:
    """A build next year gets a setuptools this project was built with, not a newer major."""
    requires = tomllib.loads((ROOT / "pyproject.toml").read_text("utf-8"))["build-system"]
    (backend,) = [r for r in requires["requires"] if r.startswith("setuptools")]
    assert re.fullmatch(r"setuptools>=7[7-9]\S*,<\d+", backend), backend


def test_wheel_holds_every_package_file_and_the_console_script(
    built_wheel: Path, source_files: list[str]
) -> None:
    python, data = package_sources(source_files)
    assert f"{PACKAGE}/__init__.py" in python and f"{PACKAGE}/scene/_widget.py" in python
    assert set(RUNTIME_FILES) <= data, "a file the package reads at run time left the tree"

    with zipfile.ZipFile(built_wheel) as wheel:
        names = set(wheel.namelist())
        entry_points = [n for n in names if n.endswith(".dist-info/entry_points.txt")]
        assert len(entry_points) == 1, sorted(n for n in names if ".dist-info/" in n)
        scripts = configparser.ConfigParser()
        scripts.read_string(wheel.read(entry_points[0]).decode("utf-8"))

    missing_data, missing_python = sorted(data - names), sorted(python - names)
    assert not missing_data, f"non-Python package files missing from the wheel: {missing_data}"
    assert not missing_python, f"Python sources missing from the wheel: {missing_python}"

    assert scripts.has_option("console_scripts", PACKAGE), scripts.sections()
    target = scripts.get("console_scripts", PACKAGE).strip()
    module_name, _, function_name = target.partition(":")
    module_path = module_name.replace(".", "/")
    assert {f"{module_path}.py", f"{module_path}/__init__.py"} & names, target
    assert callable(getattr(importlib.import_module(module_name), function_name, None)), target


@pytest.mark.skipif(
    os.environ.get("CI") != "true",
    reason="installs the wheel and its dependencies from the package index into a fresh "
    "venv (minutes): runs only when CI=true",
)
@pytest.mark.timeout(1800)
def test_wheel_installs_and_runs_in_a_fresh_venv(built_wheel: Path, tmp_path: Path) -> None:
    venv = tmp_path / "venv"
    run([sys.executable, "-m", "venv", venv], timeout=300)
    bin_dir = venv / ("Scripts" if os.name == "nt" else "bin")
    python = bin_dir / "python"
    run([python, "-m", "pip", "install", "--quiet", built_wheel], timeout=1500)

    work = tmp_path / "work"  # outside the repository: the source tree cannot be imported
    work.mkdir()
    script = work / "smoke.py"
    script.write_text(SMOKE_SCRIPT, encoding="utf-8")
    html_path = work / "robot.html"
    # -I: no PYTHONPATH, no user site-packages, not even the script's own folder.
    smoke = run([python, "-I", script, venv, html_path], timeout=300, cwd=work)
    assert smoke.stdout.startswith("smoke ok"), smoke.stdout
    assert html_path.stat().st_size > 500_000

    installed = run([python, "-m", "pip", "list", "--format=json"], timeout=120).stdout
    names = {package["name"].lower() for package in json.loads(installed)}
    assert not names & set(MESHCAT_SERVER_STACK), sorted(names & set(MESHCAT_SERVER_STACK))

    console = run([bin_dir / "robotconf", "--help"], timeout=120, cwd=work)
    assert "usage: robotconf" in console.stdout and "report" in console.stdout, console.stdout
