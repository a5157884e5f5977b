"""robotconf's numpy-free modules in Pyodide's Python, under Node (docs/lite.md).

The JupyterLite site's kernel is Pyodide 0.27.6 (Python 3.12 compiled to WebAssembly).
Its numpy, pandas and matplotlib come only from Pyodide's full distribution, which these
machines cannot fetch; its core (the interpreter and the standard library) is on npm. So
this test runs what the core can: every module of robotconf that imports none of those
at module level (found from the sources, so the list follows the code), imported in
Pyodide and its doctests run with the standard library's doctest.

The package ``__init__`` files are left empty in the copy Pyodide sees (they import the
numpy core); everything else is the source as it is. Skipped without Node and npm.
"""

from __future__ import annotations

import ast
import hashlib
import importlib
import json
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "robotconf"
CHECK = ROOT / "lite" / "pyodide"
TOOLS = ROOT / "build" / "pyodide"

#: Libraries Pyodide's core lacks (compiled ones come with its full distribution only) or
#: that robotconf's runtime installs from the site's wheels: a module importing any of
#: them at module level is not checked here.
NOT_IN_THE_CORE = frozenset(
    {
        *("numpy", "pandas", "sympy", "mpmath", "matplotlib", "scipy", "PIL", "yaml", "psutil"),
        *("ipywidgets", "anywidget", "traitlets", "IPython", "msgpack", "meshcat"),
        *("openpyxl", "tqdm", "nbformat", "nbgrader"),
    }
)

DRIVER = """\
import doctest, importlib, json, re, sys, traceback

sys.path.insert(0, "/src")
# A docstring whose examples reach for numpy (or a package emptied here) is skipped:
# those examples cannot run on Pyodide's core. Any other failure is a failure.
needs_absent = re.compile(
    r"No module named '({absent})|cannot import name .* from '({emptied})'"
    r"|module '({emptied})' has no attribute".format(
        absent="|".join(NOT_IN_THE_CORE), emptied="|".join(re.escape(p) for p in EMPTIED)
    )
)
finder = doctest.DocTestFinder()
flags = doctest.NORMALIZE_WHITESPACE | doctest.ELLIPSIS
results = {}
for name in MODULES:
    try:
        module = importlib.import_module(name)
    except BaseException:
        results[name] = {"error": traceback.format_exc()}
        continue
    counts = {"passed": 0, "skipped": 0, "failed": 0, "failures": []}
    for test in finder.find(module):
        if not test.examples:
            continue
        output = []
        runner = doctest.DocTestRunner(optionflags=flags)
        outcome = runner.run(test, out=output.append)
        text = "".join(output)
        if not outcome.failed:
            counts["passed"] += 1
        elif needs_absent.search(text):
            counts["skipped"] += 1
        else:
            counts["failed"] += 1
            counts["failures"].append(text[-2000:])
    results[name] = counts
absent = set(NOT_IN_THE_CORE) - {"sympy", "mpmath"}
heavy = sorted(name for name in sys.modules if name.split(".")[0] in absent)
print("RESULTS " + json.dumps({"modules": results, "heavy": heavy, "version": sys.version,
                               "platform": sys.platform}))
"""


def module_names() -> dict[str, Path]:
    """Every module of the package: dotted name → file."""
    names = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = list(path.relative_to(ROOT).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        names[".".join(parts)] = path
    return names


def module_level_imports(name: str, path: Path, modules: dict[str, Path]) -> set[str]:
    """What a module imports when it is loaded (not inside functions), as dotted names."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found: set[str] = set()
    for node in _loaded_with_the_module(ast.parse(path.read_text("utf-8")).body):
        if isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - node.level + 1]
                source = ".".join(base + ([node.module] if node.module else []))
            else:
                source = node.module or ""
            submodules = {f"{source}.{a.name}" for a in node.names} & set(modules)
            found |= submodules
            if len(submodules) < len(node.names):  # names defined by the module itself
                found.add(source)
    return found


def _loaded_with_the_module(body: list[ast.stmt]) -> list[ast.stmt]:
    """The statements of ``body`` that run on import: not function bodies, not
    ``if TYPE_CHECKING:`` blocks; class bodies and other blocks are entered."""
    found: list[ast.stmt] = []
    for node in body:
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            continue
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            found += _loaded_with_the_module(node.orelse)
            continue
        found.append(node)
        for name in ("body", "orelse", "finalbody", "handlers"):
            children = getattr(node, name, [])
            found += _loaded_with_the_module([c for c in children if isinstance(c, ast.stmt)])
        for handler in getattr(node, "handlers", []):
            found += _loaded_with_the_module(handler.body)
    return found


def core_only_modules() -> tuple[list[str], list[Path]]:
    """Modules whose module-level imports (followed through robotconf) avoid
    :data:`NOT_IN_THE_CORE`, and the package ``__init__`` files that do not (emptied in
    the copy Pyodide sees, so the modules under them can be imported)."""
    modules = module_names()
    verdict: dict[str, bool] = {}

    def clean(name: str, stack: tuple[str, ...] = ()) -> bool:
        if name in verdict:
            return verdict[name]
        if name in stack:
            return True
        ok = True
        for imported in module_level_imports(name, modules[name], modules):
            top = imported.split(".")[0]
            if top in NOT_IN_THE_CORE:
                ok = False
            elif top == "robotconf" and imported in modules:
                ok = clean(imported, (*stack, name)) and ok
        verdict[name] = ok
        return ok

    names = [n for n, p in modules.items() if p.name != "__init__.py" and clean(n)]
    emptied = [p for n, p in modules.items() if p.name == "__init__.py" and not clean(n)]
    return names, emptied


def pyodide_tools() -> Path:
    """``npm ci`` of lite/pyodide into build/pyodide, redone when the lock changes."""
    for tool in ("node", "npm"):
        if shutil.which(tool) is None:
            pytest.skip(
                f"no {tool} on PATH: Pyodide's core comes from npm (bash .ci/run installs it)"
            )
    lock = (CHECK / "package-lock.json").read_bytes()
    stamp = TOOLS / ".robotconf-lock"
    digest = hashlib.sha256(lock).hexdigest()
    if not (stamp.exists() and stamp.read_text() == digest):
        if TOOLS.exists():
            shutil.rmtree(TOOLS)
        TOOLS.mkdir(parents=True)
        for name in ("package.json", "package-lock.json", "run.mjs"):
            shutil.copy(CHECK / name, TOOLS / name)
        subprocess.run(
            ["npm", "ci", "--no-audit", "--no-fund", "--loglevel=error"],
            cwd=TOOLS, check=True, capture_output=True, timeout=600,
        )  # fmt: skip
        stamp.write_text(digest)
    shutil.copy(CHECK / "run.mjs", TOOLS / "run.mjs")
    return TOOLS


def test_the_module_list_follows_the_imports() -> None:
    names, emptied = core_only_modules()
    assert PACKAGE / "__init__.py" in emptied  # `import robotconf` loads the numpy core
    assert "robotconf._errors" in names and "robotconf.teaching.reading._budget_rules" in names
    assert "robotconf.kinematics.kernel._kernel" not in names  # the numpy core
    assert len(names) >= 15, names


@pytest.mark.timeout(600)
def test_numpy_free_modules_import_and_pass_their_doctests_in_pyodide(tmp_path: Path) -> None:
    tools = pyodide_tools()
    names, emptied = core_only_modules()
    source = tmp_path / "src"
    shutil.copytree(PACKAGE, source / "robotconf", ignore=shutil.ignore_patterns("__pycache__"))
    for init in emptied:
        copy = source / init.relative_to(ROOT)
        copy.write_text('"""Emptied for the Pyodide check: it imports numpy."""\n', "utf-8")
    # Beside the package, as in a checkout: the course (the grading tools list its lessons).
    shutil.copytree(ROOT / "course", source / "course")
    # sympy (and its mpmath) are pure Python: several checks use them inside functions.
    # Pyodide ships sympy 1.13.3 in its full distribution; here, the test's own copy.
    for name in ("sympy", "mpmath"):
        folder = Path(importlib.import_module(name).__file__ or "").parent
        shutil.copytree(folder, source / name, ignore=shutil.ignore_patterns("__pycache__"))
    script = tmp_path / "driver.py"
    packages = [".".join(p.relative_to(ROOT).parent.parts) for p in emptied]
    script.write_text(
        f"MODULES = {names!r}\nNOT_IN_THE_CORE = {sorted(NOT_IN_THE_CORE)!r}\n"
        f"EMPTIED = {packages!r}\n" + DRIVER,
        encoding="utf-8",
    )
    run = subprocess.run(
        ["node", str(tools / "run.mjs"), str(source), str(script)],
        cwd=tools, capture_output=True, text=True, timeout=540,
    )  # fmt: skip
    lines = [line for line in run.stdout.splitlines() if line.startswith("RESULTS ")]
    assert run.returncode == 0 and lines, run.stdout[-3000:] + run.stderr[-3000:]
    report = json.loads(lines[-1].removeprefix("RESULTS "))
    assert report["platform"] == "emscripten" and report["version"].startswith("3.12"), report
    assert report["heavy"] == [], report["heavy"]
    broken = {n: r for n, r in report["modules"].items() if "error" in r or r["failed"]}
    # (a module's "failures" hold each failing docstring's doctest report)
    assert not broken, json.dumps(broken, indent=1)[:4000] + run.stdout[-3000:]
    assert set(report["modules"]) == set(names)
    passed = sum(r["passed"] for r in report["modules"].values())
    skipped = sum(r["skipped"] for r in report["modules"].values())
    print(f"Pyodide: {len(names)} modules imported, {passed} docstrings passed, {skipped} skipped")
    assert passed >= 20 and passed > skipped, report["modules"]
