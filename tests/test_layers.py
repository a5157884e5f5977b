"""The package's layers, read from its imports: one way down, no cycles, faces only.

The rules (docs/architecture.md draws them):

- no import cycle among modules at module level (``if TYPE_CHECKING:`` imports count:
  a cycle there is a knot in the design even if Python never runs it);
- no loop between folders, counting imports inside functions too (two folders of one
  layer that import each other, even lazily, are one concept in two places); only the
  lazy accessors below may point back;
- each folder imports at module level only folders of a lower layer (or itself);
- an import that climbs a layer sits inside a function, and only in the lazy accessors
  listed in :data:`LAZY_ACCESSORS`;
- a folder reaches another folder through its public face (``robotconf.kinematics``),
  never through a private module (``robotconf.kinematics._robot``);
- nothing inside the package imports the package root (``import robotconf``);
- the core imports no third-party package but numpy at module level.
"""

from __future__ import annotations

import ast
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "robotconf"

#: Lowest first. ``_base`` is the shared ``robotconf._errors``, ``_validation``,
#: ``_json_fields`` and ``_budget``.
LAYERS: tuple[tuple[str, ...], ...] = (
    ("_base",),
    ("kinematics", "signals"),
    ("motion", "inverse_kinematics", "calibration"),
    ("teaching", "presets", "programs"),
    ("cell",),
    ("io",),
    ("plots",),
    ("scene",),
    ("panel", "cli", "grading", "report"),
    ("cell_designer",),
    ("__init__", "__main__"),
)
PRESENTATION = ("plots", "scene", "panel", "cli", "grading", "report", "cell_designer")
SHARED_BASE = (
    "robotconf._errors",
    "robotconf._validation",
    "robotconf._json_fields",
    "robotconf._budget",
)

#: The only places where the core reaches up a layer: methods that hand over to a richer
#: layer when called (a robot writes its file, a motion draws itself), named
#: ``module:function`` for the function that holds the import.
LAZY_ACCESSORS = {
    "robotconf.kinematics.robot._robot:to_json": "robotconf.io",
    "robotconf.kinematics.robot._robot:from_json": "robotconf.io",
    "robotconf.kinematics.robot._robot:save": "robotconf.io",
    "robotconf.kinematics.robot._robot:to_urdf": "robotconf.io",
    "robotconf.cell._cell:to_json": "robotconf.io",
    "robotconf.cell._cell:save": "robotconf.io",
    "robotconf.kinematics.quantities._workspace:plot": "robotconf.plots",
    "robotconf.kinematics.quantities._workspace:view": "robotconf.scene",
    "robotconf.cell._cell:view": "robotconf.scene",
    "robotconf.motion._motion:plot": "robotconf.plots",
}

STDLIB = set(sys.stdlib_module_names) | {"__future__"}


@dataclass(frozen=True)
class Import:
    """One import statement's target, as seen from the importing module."""

    source: str  # importing module, e.g. "robotconf.kinematics._robot"
    target: str  # imported module, e.g. "robotconf.io" or "numpy"
    line: int
    function: str | None  # enclosing function, None at module level
    type_only: bool  # inside ``if TYPE_CHECKING:``


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _is_package(path: Path) -> bool:
    return path.name == "__init__.py"


def _resolve(module: str, is_package: bool, level: int, name: str | None) -> str:
    base = module.split(".")
    if not is_package:
        base = base[:-1]
    if level > 1:
        base = base[: len(base) - (level - 1)]
    return ".".join(base + ([name] if name else []))


def _is_module(name: str) -> bool:
    relative = name.split(".")[1:]
    path = PACKAGE.joinpath(*relative)
    return path.with_suffix(".py").is_file() or (path / "__init__.py").is_file()


def _is_type_checking(node: ast.If) -> bool:
    test = node.test
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _imports(path: Path, text: str | None = None) -> list[Import]:
    module = _module_name(path)
    package = _is_package(path)
    found: list[Import] = []

    def visit(node: ast.AST, function: str | None, type_only: bool) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
                visit(child, child.name if function is None else function, type_only)
            elif isinstance(child, ast.If) and _is_type_checking(child):
                for item in child.body:
                    visit(ast.Module(body=[item], type_ignores=[]), function, True)
                for item in child.orelse:
                    visit(ast.Module(body=[item], type_ignores=[]), function, type_only)
            elif isinstance(child, ast.Import):
                for alias in child.names:
                    found.append(Import(module, alias.name, child.lineno, function, type_only))
            elif isinstance(child, ast.ImportFrom):
                if child.level:
                    target = _resolve(module, package, child.level, child.module)
                else:
                    target = child.module or ""
                if target == "__future__":
                    continue
                for alias in child.names:
                    # ``from . import presets`` imports a module; ``from .x import y`` a name.
                    sub = f"{target}.{alias.name}"
                    name = sub if target.startswith("robotconf") and _is_module(sub) else target
                    found.append(Import(module, name, child.lineno, function, type_only))
            else:
                visit(child, function, type_only)

    source = path.read_text(encoding="utf-8") if text is None else text
    visit(ast.parse(source), None, False)
    return found


ALL_IMPORTS = [imp for path in sorted(PACKAGE.rglob("*.py")) for imp in _imports(path)]
INTERNAL = [imp for imp in ALL_IMPORTS if imp.target.split(".")[0] == "robotconf"]


def _layer_name(module: str) -> str:
    if module in SHARED_BASE:
        return "_base"
    parts = module.split(".")
    if len(parts) == 1:
        return "__init__"
    return parts[1]


def _layer(module: str) -> int:
    name = _layer_name(module)
    for rank, members in enumerate(LAYERS):
        if name in members:
            return rank
    raise AssertionError(f"{module}: its folder {name!r} is in no layer of LAYERS")


def _where(imp: Import) -> str:
    inside = f" in {imp.function}()" if imp.function else ""
    return f"{imp.source}:{imp.line}{inside} imports {imp.target}"


def test_the_scan_sees_the_package():
    modules = {imp.source for imp in ALL_IMPORTS}
    assert {"robotconf.kinematics.robot._robot", "robotconf.panel._configurator"} <= modules
    assert len(INTERNAL) > 200


def test_every_folder_has_a_layer():
    for imp in INTERNAL:
        _layer(imp.source)
        _layer(imp.target)


def test_no_module_level_import_cycle():
    graph: dict[str, set[str]] = {}
    for imp in INTERNAL:
        if imp.function is None and imp.target != imp.source:
            graph.setdefault(imp.source, set()).add(imp.target)
    # Tarjan's strongly connected components, iteratively.
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    cycles: list[list[str]] = []
    counter = 0
    for root in sorted(graph):
        if root in index:
            continue
        work = [(root, iter(sorted(graph.get(root, ()))))]
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph.get(child, ())))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    cycles.append(sorted(component))
    assert cycles == []


def _folder_loops(imports: list[Import]) -> list[list[str]]:
    """Loops in the graph of folders, from every import (lazy ones too) but the accessors."""
    graph: dict[str, set[str]] = {}
    for imp in imports:
        key = f"{imp.source}:{imp.function}"
        if LAZY_ACCESSORS.get(key) == ".".join(imp.target.split(".")[:2]):
            continue
        source, target = _layer_name(imp.source), _layer_name(imp.target)
        if source != target:
            graph.setdefault(source, set()).add(target)
    loops = []
    for start in sorted(graph):
        # Depth-first from each folder; a path back to it is a loop (folders are few).
        stack = [(start, [start])]
        while stack:
            node, path = stack.pop()
            for nxt in sorted(graph.get(node, ())):
                if nxt == start:
                    loops.append(path)
                elif nxt not in path and nxt > start:
                    stack.append((nxt, [*path, nxt]))
    return loops


def test_no_import_loop_between_folders():
    assert _folder_loops(INTERNAL) == []


def _climbing_down_violations(imports: list[Import]) -> list[str]:
    return [
        _where(imp)
        for imp in imports
        if imp.function is None and _layer(imp.target) > _layer(imp.source)
    ]


def _climbing(imports: list[Import]) -> dict[str, str]:
    return {
        f"{imp.source}:{imp.function}": ".".join(imp.target.split(".")[:2])
        for imp in imports
        if imp.function is not None and _layer(imp.target) > _layer(imp.source)
    }


def _face_violations(imports: list[Import]) -> list[str]:
    wrong = []
    for imp in imports:
        target = imp.target.split(".")
        # a private module anywhere below the folder (kinematics.robot._robot too)
        if imp.target in SHARED_BASE or not any(part.startswith("_") for part in target[2:]):
            continue
        if _layer_name(imp.source) != target[1]:
            wrong.append(_where(imp))
    return wrong


def _root_violations(imports: list[Import]) -> list[str]:
    return [_where(imp) for imp in imports if imp.target == "robotconf"]


def _third_party_violations(imports: list[Import]) -> list[str]:
    wrong = []
    for imp in imports:
        top = imp.target.split(".")[0]
        if top in ("robotconf", "numpy") or top in STDLIB or imp.function or imp.type_only:
            continue
        if _layer_name(imp.source) not in PRESENTATION:
            wrong.append(_where(imp))
    return wrong


def test_module_level_imports_go_down_the_layers():
    assert _climbing_down_violations(INTERNAL) == []


def test_imports_that_climb_are_the_listed_lazy_accessors():
    assert _climbing(INTERNAL) == LAZY_ACCESSORS


def test_folders_use_each_others_public_faces():
    assert _face_violations(INTERNAL) == []


def test_nothing_imports_the_package_root():
    assert _root_violations(INTERNAL) == []


def test_the_core_imports_only_numpy_at_module_level():
    assert _third_party_violations(ALL_IMPORTS) == []


@pytest.mark.parametrize(
    ("code", "check"),
    [
        ("from ..kinematics._robot import Robot\n", _face_violations),
        ("from ..kinematics.robot._robot import Robot\n", _face_violations),
        ("import robotconf\n", _root_violations),
        ("from ..panel import configurator\n", _climbing_down_violations),
        ("def plot():\n    from ..scene import view\n", lambda found: list(_climbing(found))),
        ("import matplotlib.pyplot\n", _third_party_violations),
    ],
)
def test_each_rule_catches_a_planted_import(code, check):
    probe = PACKAGE / "motion" / "_probe.py"  # read as text only; never written
    assert check(_imports(probe, code))


def test_a_loop_between_folders_of_one_layer_is_caught():
    # programs and presets share a layer; a lazy import each way is a loop.
    there = _imports(
        PACKAGE / "programs" / "_probe.py", "def f():\n    from ..presets import preset\n"
    )
    back = _imports(PACKAGE / "presets" / "_probe.py", "def g():\n    from ..programs import PTP\n")
    assert _folder_loops(there + back) == [["presets", "programs"]]
    assert _folder_loops(there) == []


#: Inside the panel, the state and its actions are plain values: they import no widget
#: library and no view of the panel, so every action can be applied and tested alone.
PANEL_PURE = ("robotconf.panel.state", "robotconf.panel.actions")
PANEL_PURE_MAY_IMPORT = (*PANEL_PURE, "robotconf.panel._ranges", "robotconf.panel._numbers")
WIDGET_LIBRARIES = ("ipywidgets", "anywidget", "traitlets", "IPython")


def _panel_purity_violations(imports: list[Import]) -> list[str]:
    wrong = []
    for imp in imports:
        if not imp.source.startswith(PANEL_PURE):
            continue
        widget = imp.target.split(".")[0] in WIDGET_LIBRARIES
        view = imp.target.startswith("robotconf.panel")
        if widget or (view and not imp.target.startswith(PANEL_PURE_MAY_IMPORT)):
            wrong.append(_where(imp))
    return wrong


def test_the_panels_state_and_actions_import_no_widgets_and_no_views():
    assert _panel_purity_violations(ALL_IMPORTS) == []


def test_the_purity_rule_catches_a_planted_import():
    probe = PACKAGE / "panel" / "actions" / "_probe.py"  # read as text only; never written
    assert _panel_purity_violations(_imports(probe, "import ipywidgets\n"))
    assert _panel_purity_violations(_imports(probe, "from ..editor import EditorView\n"))
