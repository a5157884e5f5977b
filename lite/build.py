"""Build the browser-only classroom: a JupyterLite site (``make lite``, docs/lite.md).

Run it with the project's Python: it builds robotconf's wheel from the working tree and
draws the paper robot's 3D page with robotconf itself. The JupyterLite tools live in their
own venv (``build/lite/venv``, from ``lite/requirements.txt``) so that the site holds
exactly the front ends pinned there, whatever else the project's ``.venv`` has installed.

The site gets: robotconf's wheel and the wheels of ``lite/wheels.txt`` (served to the
in-browser kernel, which looks there before PyPI), ``notebooks/`` and ``course/`` without
``course/solutions/`` (the course says to withhold them), each notebook opening with a cell
that installs robotconf, and ``paper_robot_3d.html``, the paper robot's 3D scene, which
needs no kernel at all.
"""

from __future__ import annotations

import argparse
import hashlib
import shutil
import subprocess
import sys
import tempfile
import uuid
import venv
from pathlib import Path

import nbformat

ROOT = Path(__file__).resolve().parents[1]
LITE = ROOT / "lite"
REQUIREMENTS = LITE / "requirements.txt"
WHEELS = LITE / "wheels.txt"

#: Python of Pyodide 0.27.6, the kernel's runtime: the bundled wheels must install there.
PYODIDE_PYTHON = "3.12"

#: The Pyodide kernel, so the notebooks open with it (``python3`` is no kernel of the site).
KERNELSPEC = {"name": "python", "display_name": "Python (Pyodide)", "language": "python"}

INSTALL_CELL_ID = "robotconf-lite-install"

#: First cell of every notebook in the site. piplite finds robotconf and its dependencies
#: among the site's wheels and Pyodide's packages (robotconf's wheel carries meshcat's 3D
#: viewer itself: meshcat's server, whose pyzmq does not exist for Pyodide, is not needed).
INSTALL_CELL = """\
# Python in the browser (JupyterLite): install robotconf from the wheels of this site.
# Elsewhere (JupyterLab, VS Code, ...) this cell does nothing.
import sys

if sys.platform == "emscripten":
    import piplite

    await piplite.install("robotconf")"""

#: The kernel-free demo page, at the top of the site's file browser.
SCENE_PAGE = "paper_robot_3d.html"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=ROOT / "dist" / "lite", help="site folder")
    parser.add_argument(
        "--venv", type=Path, default=ROOT / "build" / "lite" / "venv", help="tools venv (kept)"
    )
    parser.add_argument(
        "--stage", type=Path, default=ROOT / "build" / "lite" / "stage", help="build inputs"
    )
    args = parser.parse_args()
    build(args.out.resolve(), args.venv.resolve(), args.stage.resolve())


def build(out: Path, tools_venv: Path, stage: Path) -> None:
    """Build the site into ``out`` (replaced) from inputs gathered in ``stage`` (replaced)."""
    tools = ensure_tools(tools_venv)
    if stage.exists():
        shutil.rmtree(stage)
    stage.mkdir(parents=True)
    for name in ("jupyter-lite.json", "jupyter_lite_config.json"):
        shutil.copy(LITE / name, stage / name)
    # The build indexes every wheel in <lite dir>/pypi for the kernel's installer, and
    # serves <lite dir>/files as the site's contents.
    build_robotconf_wheel(stage / "pypi")
    download_wheels(stage / "pypi")
    stage_contents(stage / "files")

    clear_site(out)
    run([tools / "jupyter", "lite", "build", "--output-dir", out], cwd=stage)
    print(f"JupyterLite site: {out}")


def run(args: list[str | Path], cwd: Path | None = None) -> None:
    print("+", " ".join(str(a) for a in args), flush=True)
    subprocess.run([str(a) for a in args], cwd=cwd, check=True)


def ensure_tools(env: Path) -> Path:
    """A venv with lite/requirements.txt, (re)made when the pins change; its bin folder."""
    # A new Python (or new pins) needs a new venv.
    pins = REQUIREMENTS.read_bytes() + WHEELS.read_bytes() + sys.version.encode()
    digest = hashlib.sha256(pins).hexdigest()
    stamp = env / ".robotconf-lite-requirements"
    bin_dir = env / "bin"
    if stamp.exists() and stamp.read_text() == digest and (bin_dir / "jupyter").exists():
        return bin_dir
    if env.exists():
        shutil.rmtree(env)
    venv.create(env, with_pip=True)
    python = bin_dir / "python"
    run([python, "-m", "pip", "install", "--quiet", "--upgrade", "pip"])
    run([python, "-m", "pip", "install", "--quiet", "-r", REQUIREMENTS])
    stamp.write_text(digest)
    return bin_dir


def build_robotconf_wheel(dest: Path) -> None:
    """robotconf's wheel from a copy of the working tree's sources.

    A copy, not the tree: setuptools' build/ and egg-info in the tree could put stale
    files into the wheel. Offline, as tests/test_packaging.py builds it.
    """
    with tempfile.TemporaryDirectory() as tmp:
        source = Path(tmp) / "robotconf-src"
        junk = shutil.ignore_patterns("__pycache__", "*.pyc", ".ipynb_checkpoints")
        shutil.copytree(ROOT / "robotconf", source / "robotconf", ignore=junk)
        for name in ("pyproject.toml", "setup.py", "README.md"):
            shutil.copy(ROOT / name, source / name)
        run(
            [
                sys.executable,
                "-m",
                "pip",
                "wheel",
                "--quiet",
                "--no-deps",
                "--no-build-isolation",
                "--no-index",
                "-w",
                dest,
                source,
            ]
        )


def download_wheels(dest: Path) -> None:
    """The pure-Python wheels of lite/wheels.txt, as a Python 3.12 browser would pick them."""
    run(
        [
            sys.executable,
            "-m",
            "pip",
            "download",
            "--quiet",
            "--no-deps",
            "--only-binary=:all:",
            # Pure wheels only: a platform wheel (psygnal has compiled ones) cannot run there.
            "--platform=any",
            "--implementation=py",
            "--abi=none",
            f"--python-version={PYODIDE_PYTHON}",
            "-d",
            dest,
            "-r",
            WHEELS,
        ]
    )


def stage_contents(files: Path) -> None:
    """notebooks/ and course/ (no solutions), each notebook opening with INSTALL_CELL."""
    junk = shutil.ignore_patterns(".ipynb_checkpoints", "__pycache__", "*.pyc")
    shutil.copytree(ROOT / "notebooks", files / "notebooks", ignore=junk)
    # The instructor's notes quote the hints and the lab's facts: a student site leaves
    # them out with the solutions.
    without_solutions = shutil.ignore_patterns(
        "solutions", "INSTRUCTOR.md", ".ipynb_checkpoints", "__pycache__"
    )
    shutil.copytree(ROOT / "course", files / "course", ignore=without_solutions)
    for path in sorted(files.rglob("*.ipynb")):
        add_install_cell(path)
    write_scene_page(files / SCENE_PAGE)


def add_install_cell(path: Path) -> None:
    notebook = nbformat.read(path, as_version=4)
    if notebook.nbformat_minor < 5:  # cell ids, needed for ours, came with 4.5
        notebook.nbformat_minor = 5
        for other in notebook.cells:
            other.setdefault("id", uuid.uuid4().hex[:12])
    cell = nbformat.v4.new_code_cell(INSTALL_CELL)
    cell.id = INSTALL_CELL_ID
    cell.metadata["tags"] = [INSTALL_CELL_ID]
    notebook.cells.insert(0, cell)
    notebook.metadata["kernelspec"] = dict(KERNELSPEC)
    nbformat.validate(notebook)
    nbformat.write(notebook, path)


def write_scene_page(path: Path) -> None:
    """The paper robot's scene as one self-contained page: it opens without a kernel."""
    import robotconf as rc
    from robotconf.scene import RecordingChannel, Scene

    scene = Scene(rc.preset("paper"), channel=RecordingChannel())
    scene.export_html(path)


def clear_site(out: Path) -> None:
    """Empty ``out``, refusing to delete a folder that is not a previous site."""
    if out.exists():
        if any(out.iterdir()) and not (out / "jupyter-lite.json").exists():
            raise SystemExit(f"{out} is not empty and holds no JupyterLite site: not replacing it")
        shutil.rmtree(out)
    out.parent.mkdir(parents=True, exist_ok=True)


if __name__ == "__main__":
    main()
