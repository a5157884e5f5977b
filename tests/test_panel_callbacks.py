"""Nothing a student does raises out of a widget callback: every event goes through the
form's answer and the panel's dispatch, or through the one guard for the few ipywidgets
the panel observes; a failure is shown beside its control and the state stays."""

from __future__ import annotations

import ast
import logging
from pathlib import Path

import pytest

import robotconf as rc
from robotconf.panel import actions as act
from robotconf.panel.support import ErrorLabel, Guarded

from .test_panel_support import make_panel, paper_robot, ui

PANEL = Path(rc.__file__).parent / "panel"
#: Attaching a widget callback: only the guard and the form widget may do it.
CONNECTING = {"observe", "on_click", "unobserve", "unobserve_all", "on_submit", "on_msg"}
ALLOWED = {"support/_callbacks.py", "form/_widget.py"}


def _bypasses(source: str) -> list[int]:
    """Lines that call a widget's ``observe``/``on_click``/… directly."""
    return [
        node.lineno
        for node in ast.walk(ast.parse(source))
        if isinstance(node, ast.Call)
        and isinstance(node.func, ast.Attribute)
        and node.func.attr in CONNECTING
    ]


def test_no_callback_bypasses_the_guard():
    files = sorted(PANEL.rglob("*.py"))
    assert len(files) > 30
    found = {
        str(path.relative_to(PANEL)): lines
        for path in files
        if str(path.relative_to(PANEL)) not in ALLOWED
        and (lines := _bypasses(path.read_text("utf-8")))
    }
    assert found == {}, "use observe()/on_click() from robotconf.panel.support"


@pytest.mark.parametrize(
    "code",
    ["button.on_click(lambda _: run())\n", "self.box.observe(self._changed, 'value')\n"],
)
def test_the_scan_catches_a_planted_bypass(code):
    assert _bypasses(code) == [1]


def test_the_guard_shows_core_messages_and_logs_only_the_unexpected(caplog):
    label = ErrorLabel()
    error = rc.InvalidInputError("dt", 0.0, "a time step > 0 (s)", "must be positive,")

    def refuse() -> None:
        raise error

    with caplog.at_level(logging.ERROR, logger="robotconf.panel"):
        Guarded(label, refuse)()
        assert label.message == str(error) and caplog.records == []
        Guarded(label, lambda: 1 / 0)()
    assert label.message == "internal error: ZeroDivisionError: division by zero"
    (record,) = caplog.records
    assert record.name == "robotconf.panel" and record.exc_info is not None


def test_an_unexpected_failure_in_an_action_is_shown_and_the_state_stays(caplog, monkeypatch):
    panel = make_panel()

    def broken(self, state):  # type: ignore[no-untyped-def]
        raise OverflowError("math range error")

    monkeypatch.setattr(act.SetQ, "apply", broken)
    with caplog.at_level(logging.ERROR, logger="robotconf.panel"):
        ui(panel, "modules[0].q").type("10")
    assert panel.errors["modules[0].q"] == "internal error: OverflowError: math range error"
    assert panel.robot == paper_robot() and caplog.records
    monkeypatch.undo()
    ui(panel, "modules[0].q").type("10")  # the next action that works clears it
    assert panel.errors == {}


def test_a_view_that_cannot_draw_says_so_and_the_others_still_draw(monkeypatch):
    panel = make_panel()

    def broken(*args):  # type: ignore[no-untyped-def]
        raise RuntimeError("no")

    monkeypatch.setattr(panel.matrices, "render", broken)
    ui(panel, "modules[0].q").type("10")
    assert panel.errors["panel"] == "matrices tab: internal error: RuntimeError: no"
    assert "p_EE" in panel.ee_label.value and panel.scene.robot == panel.robot


def test_malformed_and_stale_page_messages_change_nothing_and_are_answered():
    panel = make_panel()
    form = panel.editor.form
    sent: list[dict] = []
    form.send = sent.append  # type: ignore[method-assign]
    for message in (
        None,
        {"key": "modules[0].q", "event": "drag", "value": "x", "seq": 1},
        {"key": "modules[0].q", "event": "drag", "value": float("nan"), "seq": 2},
        {"key": "modules[0].q", "event": "explode", "value": 1.0, "seq": 3},
        {"key": "nowhere", "event": "drag", "value": 1.0, "seq": 4},
        {"key": "modules[0].q", "event": "drag", "value": 1.0, "rev": "stale", "seq": 5},
        {"key": "modules[0].q", "event": "drag", "value": True, "seq": 6},
    ):
        form.receive(message)  # type: ignore[arg-type]
    assert panel.robot == paper_robot() and panel.errors == {}
    assert [m["ack"] for m in sent] == [1, 2, 3, 4, 5, 6]
