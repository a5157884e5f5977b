"""App mode: in Voilà (no cells) the panel leaves out its "check it in a cell" hints, and
its matrices are fixed-width on any page."""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from pathlib import Path

import ipywidgets as widgets
import pytest

import robotconf as rc
from robotconf.panel import actions as act
from robotconf.panel.support import VOILA_VARIABLES, app_mode
from robotconf.panel.support._monospace import MONOSPACE_STYLE

from .test_panel_support import make_panel, ui

APP_NOTEBOOK = Path(__file__).parents[1] / "app" / "configurator.ipynb"
#: What a hint to type code looks like: a cell, or a call on the panel object.
CODE_HINT = re.compile(r"\bcells?\b|panel\.|rc\.", re.IGNORECASE)


def _html(widget: widgets.Widget) -> Iterator[str]:
    """The text of every HTML widget and form under ``widget``, shown or not."""
    if isinstance(widget, widgets.HTML | widgets.HTMLMath):
        yield widget.value
    spec = getattr(widget, "spec", None)
    if isinstance(spec, dict):
        for row in spec.get("rows", ()):
            for line in row.get("lines", ()):
                for control in line:
                    yield from (str(control.get(k, "")) for k in ("value", "label", "title"))
    for child in getattr(widget, "children", ()):
        yield from _html(child)


def _long_chain() -> rc.Robot:
    # Too long for symbolic matrices: the panel shows its note instead.
    return rc.Robot([rc.Module(kind, a=(1, 0, 0)) for kind in ["Rz", "Ry", "Rx"] * 4])


def _hints(panel) -> list[str]:  # type: ignore[no-untyped-def]
    return [text for text in _html(panel.widget) if CODE_HINT.search(text)]


@pytest.fixture
def no_voila(monkeypatch: pytest.MonkeyPatch) -> None:
    for name in VOILA_VARIABLES:
        monkeypatch.delenv(name, raising=False)


@pytest.fixture
def in_voila(monkeypatch: pytest.MonkeyPatch, no_voila: None) -> None:
    # What Voilà puts in the environment of a kernel it starts for a page.
    monkeypatch.setenv("VOILA_BASE_URL", "/")
    monkeypatch.setenv("VOILA_PREHEAT", "False")


def _run_long_motion(panel) -> None:  # type: ignore[no-untyped-def]
    # More samples than the on-screen table shows: the note says where all of them are.
    ui(panel, "t_end").type("10")
    ui(panel, "dt").type("0.01")
    ui(panel, "run").click()
    assert panel.motion is not None
    for tab in ("matrices", "files", "program", "motion"):  # each tab draws when shown
        panel.apply(act.SelectTab(tab))


def test_notebook_panel_keeps_its_hints(no_voila: None) -> None:
    panel = make_panel(_long_chain())
    _run_long_motion(panel)
    assert panel.app is False
    hints = " ".join(_hints(panel))
    for hint in ("panel.save(path)", "panel.load(path)", "panel.motion.table", "in a cell"):
        assert hint in hints


def test_voila_kernel_is_detected_and_hints_dropped(in_voila: None) -> None:
    panel = make_panel(_long_chain())
    _run_long_motion(panel)
    assert panel.app is True
    assert _hints(panel) == []
    # What replaces them still reads as sentences.
    assert "the CSV holds all" in panel.motion_tab.results.table_note.value
    panel.apply(act.SelectTab("matrices"))
    texts = " ".join(_html(panel.matrices.widget))
    assert "Symbolic matrices are offered for shorter chains only" in texts
    panel.apply(act.SelectTab("files"))
    texts = " ".join(_html(panel.files.widget))
    assert "Save the robot, its signals, time settings and program as JSON:" in texts
    assert "<b>Load</b> a robotconf JSON file:" in texts


def test_explicit_choice_wins_over_detection(in_voila: None) -> None:
    assert make_panel(app=False).app is False
    panel = make_panel(app=False)
    panel.apply(act.SelectTab("files"))
    assert "panel.save(path)" in " ".join(_hints(panel))


def test_app_mode_without_voila(no_voila: None) -> None:
    panel = make_panel(app=True)
    assert panel.app is True
    for tab in ("matrices", "files", "program", "motion"):
        panel.apply(act.SelectTab(tab))
    assert _hints(panel) == []


def test_app_must_be_a_bool_or_none() -> None:
    with pytest.raises(rc.InvalidInputError, match="app: invalid value 'yes'"):
        make_panel(app="yes")
    with pytest.raises(rc.InvalidInputError):
        app_mode(1)  # type: ignore[arg-type]


def test_matrices_and_wizard_summary_are_fixed_width(no_voila: None) -> None:
    panel = make_panel()
    panel.apply(act.SelectTab("matrices"))  # the Matrices tab draws when it is shown
    assert f'<pre style="{MONOSPACE_STYLE}">' in panel.matrices.output.value
    assert "robotconf-matrices" in panel.matrices.output._dom_classes
    # The printout itself is unchanged: the core's text, escaped.
    assert str(rc.derivation(panel.robot)).splitlines()[0] in panel.matrices.output.value
    ui(panel, "mode").choose("wizard")
    for _ in range(50):  # every question keeps its default answer
        if panel.state.wizard.part == "summary":
            break
        ui(panel, "wizard.next").click()
    assert f'<pre style="{MONOSPACE_STYLE}">' in panel.wizard.preview.value


def test_app_notebook_is_for_students() -> None:
    notebook = json.loads(APP_NOTEBOOK.read_text("utf-8"))
    code = [c for c in notebook["cells"] if c["cell_type"] == "code"]
    assert all(not c["outputs"] and c["execution_count"] is None for c in code)
    # Voilà shows the markdown: it must not send students to cells or code.
    for cell in notebook["cells"]:
        if cell["cell_type"] == "markdown":
            assert not CODE_HINT.search("".join(cell["source"]))
    # The panel detects Voilà itself, so the same notebook in JupyterLab keeps its hints.
    assert "rc.configurator(" in "".join(code[0]["source"])
    assert "app=" not in "".join(code[0]["source"])


def test_app_settings_stay_local_and_cull_kernels() -> None:
    settings = json.loads((APP_NOTEBOOK.parent / "voila.json").read_text("utf-8"))
    assert settings["Voila"]["ip"] == "127.0.0.1"
    # The page template `make app` finds through JUPYTER_PATH: the lab one, minus CDN links.
    template = APP_NOTEBOOK.parent / "jupyter" / "voila" / "templates"
    template /= settings["VoilaConfiguration"]["template"]
    assert json.loads((template / "conf.json").read_text("utf-8")) == {"base_template": "lab"}
    assert (template / "index.html.j2").is_file()
    culling = settings["MappingKernelManager"]
    assert culling["cull_idle_timeout"] > 0 and culling["cull_interval"] > 0
    assert culling["cull_connected"] is False  # an open page keeps its kernel
