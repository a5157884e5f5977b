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
from robotconf.panel._app_mode import VOILA_VARIABLES, app_mode
from robotconf.panel._monospace import MONOSPACE_STYLE

from .test_panel_support import make_panel

APP_NOTEBOOK = Path(__file__).parents[1] / "app" / "configurator.ipynb"
#: What a hint to type code looks like: a cell, or a call on the panel object.
CODE_HINT = re.compile(r"\bcells?\b|panel\.|rc\.", re.IGNORECASE)


def _html(widget: widgets.Widget) -> Iterator[str]:
    """The HTML of every HTML widget under ``widget``, shown or not."""
    if isinstance(widget, widgets.HTML | widgets.HTMLMath):
        yield widget.value
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
    panel.motion_section.t_end.value = 10.0
    panel.motion_section.dt.value = 0.01
    panel.motion_section.run_button.click()
    assert panel.motion is not None


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
    assert "the CSV holds all" in panel.motion_section.results.table_note.value
    assert "Symbolic matrices are offered for shorter chains only" in (
        panel.matrices.symbolic_note.value
    )
    texts = " ".join(_html(panel.files.widget))
    assert "<b>Save</b> the robot, its signals and time settings as JSON:" in texts
    assert "<b>Load</b> a robotconf JSON file:" in texts


def test_explicit_choice_wins_over_detection(in_voila: None) -> None:
    assert make_panel(app=False).app is False
    assert "panel.save(path)" in " ".join(_hints(make_panel(app=False)))


def test_app_mode_without_voila(no_voila: None) -> None:
    panel = make_panel(app=True)
    assert panel.app is True
    assert _hints(panel) == []


def test_app_must_be_a_bool_or_none() -> None:
    with pytest.raises(rc.InvalidInputError, match="app: invalid value 'yes'"):
        make_panel(app="yes")
    with pytest.raises(rc.InvalidInputError):
        app_mode(1)  # type: ignore[arg-type]


def test_matrices_and_wizard_summary_are_fixed_width(no_voila: None) -> None:
    panel = make_panel()
    panel.results.selected_index = 1  # the Matrices tab draws when it is shown
    assert f'<pre style="{MONOSPACE_STYLE}">' in panel.matrices.numeric_text.value
    assert "robotconf-matrices" in panel.matrices.numeric_text._dom_classes
    # The printout itself is unchanged: the core's text, escaped.
    assert str(rc.derivation(panel.robot)).splitlines()[0] in panel.matrices.numeric_text.value
    panel.mode.value = "wizard"
    wizard = panel.wizard
    for _ in range(50):  # every question keeps its default answer
        if wizard.step_name == "summary":
            break
        wizard.next_button.click()
    assert f'<pre style="{MONOSPACE_STYLE}">' in wizard.body.children[0].value


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
