"""Every widget callback of the panel goes through one guard: any failure is shown beside the
control that caused it, the last valid robot stays, and the panel keeps working."""

from __future__ import annotations

import ast
import datetime
import logging
from pathlib import Path

import numpy as np
import pytest

import robotconf as rc
from robotconf.panel import _configurator, _matrices_view, _motion_section
from robotconf.panel._callbacks import Guarded
from robotconf.panel._errors_display import ErrorLabel

from .test_panel_support import make_panel, paper_robot

PANEL = Path(rc.__file__).parent / "panel"
#: Attaching or detaching a widget callback: only ``_callbacks.py`` may do it.
CONNECTING = {"observe", "on_click", "unobserve", "unobserve_all", "on_submit", "on_msg"}


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
    files = sorted(PANEL.glob("*.py"))
    assert len(files) > 15
    found = {
        path.name: lines
        for path in files
        if path.name != "_callbacks.py" and (lines := _bypasses(path.read_text("utf-8")))
    }
    assert found == {}, "use observe()/on_click() from robotconf.panel._callbacks"


@pytest.mark.parametrize(
    "code",
    [
        "button.on_click(lambda _: run())\n",
        "self.box.observe(self._changed, 'value')\n",
        "w.unobserve_all('value')\n",
    ],
)
def test_the_scan_catches_a_planted_bypass(code):
    assert _bypasses(code) == [1]


# -- the guard ------------------------------------------------------------------------------


def test_guard_shows_core_messages_as_they_are_and_logs_only_the_unexpected(caplog):
    label = ErrorLabel()
    error = rc.InvalidInputError("dt", 0.0, "a time step > 0 (s)", "must be positive,")

    def refuse() -> None:
        raise error

    with caplog.at_level(logging.ERROR, logger="robotconf.panel"):
        Guarded(label, refuse)()
        assert label.message == str(error)
        assert caplog.records == []
        Guarded(label, lambda: 1 / 0)()
    assert label.message == "internal error: ZeroDivisionError: division by zero"
    (record,) = caplog.records
    assert record.name == "robotconf.panel" and record.exc_info is not None


def test_guard_clears_only_its_own_message():
    label = ErrorLabel()
    fail = [True]

    def callback() -> None:
        if fail[0]:
            raise OverflowError("math range error")

    handler = Guarded(label, callback)
    handler()
    assert label.message == "internal error: OverflowError: math range error"
    fail[0] = False
    label.show("q: must be finite, got nan")  # a check wrote since: not the guard's to clear
    handler()
    assert label.message == "q: must be finite, got nan"


def test_guard_picks_the_label_when_the_error_happens():
    labels = [ErrorLabel(), ErrorLabel()]
    current = [0]
    handler = Guarded(lambda: labels[current[0]], lambda: [].pop())
    current[0] = 1
    handler()
    assert labels[0].message == "" and labels[1].message.startswith("internal error: IndexError")


# -- beside the control, and the panel keeps working ----------------------------------------


def test_unexpected_error_in_run_is_shown_beside_run_and_the_next_run_works(monkeypatch):
    panel = make_panel(t_end=1.0, dt=0.5)

    def out_of_memory(*args, **kwargs):
        raise MemoryError("cannot allocate 80 GiB")

    monkeypatch.setattr(_motion_section, "simulate", out_of_memory)
    panel.motion_section.run_button.click()
    assert panel.errors == {"run": "internal error: MemoryError: cannot allocate 80 GiB"}
    assert panel.motion is None
    assert panel.robot == paper_robot()

    def overflow(*args, **kwargs):
        raise OverflowError("math range error")

    monkeypatch.setattr(_motion_section, "simulate", overflow)
    panel.motion_section.run_button.click()
    assert panel.errors == {"run": "internal error: OverflowError: math range error"}

    monkeypatch.undo()
    panel.motion_section.run_button.click()
    assert panel.motion is not None and panel.errors == {}


def test_the_memory_budget_refusal_is_shown_as_the_core_message(monkeypatch):
    panel = make_panel(t_end=1.0, dt=0.5)
    refusal = rc.InvalidInputError("dt", 1e-9, "a larger dt", "needs about 80 GiB of memory with")

    def over_budget(*args, **kwargs):
        raise refusal

    monkeypatch.setattr(_motion_section, "simulate", over_budget)
    panel.motion_section.run_button.click()
    assert panel.errors == {"dt": str(refusal)}  # beside dt, the input that sets the size


def test_csv_link_failure_is_shown_beside_the_csv_link(monkeypatch):
    panel = make_panel(t_end=1.0, dt=0.5)
    panel.motion_section.run_button.click()
    results = panel.motion_section.results
    motion = panel.motion
    assert motion is not None

    def out_of_memory(*args, **kwargs):
        raise MemoryError()

    monkeypatch.setattr(type(motion), "to_csv", out_of_memory)
    results.csv_button.click()
    assert panel.errors == {"csv": "internal error: MemoryError"}
    assert results.csv_link.value == ""

    refusal = rc.InvalidInputError("samples", 10**9, "a larger dt", "needs about 2 GiB with")

    def over_budget(*args, **kwargs):
        raise refusal

    monkeypatch.setattr(type(motion), "to_csv", over_budget)
    results.csv_button.click()
    assert panel.errors == {"csv": str(refusal)}

    monkeypatch.undo()
    results.csv_button.click()
    assert panel.errors == {} and "data:text/csv" in results.csv_link.value


def test_a_failing_scene_is_shown_beside_the_slider_and_the_next_move_clears_it(monkeypatch):
    panel = make_panel()

    def broken(q):
        raise ZeroDivisionError("division by zero")

    monkeypatch.setattr(panel.scene, "update", broken)
    panel.modules.rows[0].q.box.value = 30.0
    assert panel.errors == {"modules[0].q": "internal error: ZeroDivisionError: division by zero"}
    monkeypatch.undo()
    panel.modules.rows[0].q.box.value = 40.0
    assert panel.errors == {}
    assert panel.robot.q[0] == pytest.approx(np.deg2rad(40.0))
    np.testing.assert_allclose(panel.scene.q, panel.robot.q)


def test_a_core_crash_while_building_keeps_the_last_valid_robot(monkeypatch):
    panel = make_panel()
    robot = panel.robot

    def crash(*args, **kwargs):
        raise OverflowError("int too large to convert to float")

    monkeypatch.setattr(_configurator, "Robot", crash)
    panel.modules.rows[2].offsets[0].box.value = 35.0
    assert panel.errors == {
        "modules[2].ax": "internal error: OverflowError: int too large to convert to float"
    }
    assert panel.robot is robot
    monkeypatch.undo()
    panel.modules.rows[2].offsets[0].box.value = 36.0
    assert panel.errors == {} and panel.robot.modules[2].a[0] == 36.0


def test_an_unexpected_upload_failure_is_shown_beside_the_upload(monkeypatch):
    panel = make_panel()

    def deep(content):
        raise RecursionError("maximum recursion depth exceeded")

    monkeypatch.setattr(_configurator, "setup_from", deep)
    panel.files.upload.value = (
        {
            "name": "robot.json",
            "type": "application/json",
            "size": 2,
            "content": memoryview(b"{}"),
            "last_modified": datetime.datetime(2026, 1, 1, tzinfo=datetime.timezone.utc),
        },
    )
    message = "internal error: RecursionError: maximum recursion depth exceeded"
    assert panel.errors == {"load": message}
    assert panel.files.load_status.value == ""
    assert panel.robot == paper_robot()


def test_header_controls_have_their_own_error_labels(monkeypatch):
    panel = make_panel()

    def broken(degrees):
        raise KeyError("degrees")

    monkeypatch.setattr(panel.wizard, "set_degrees", broken)
    panel.angle_unit.value = False
    assert panel.errors == {"angle_unit": "internal error: KeyError: 'degrees'"}


# -- mode switch with a pending bad value ----------------------------------------------------


def test_mode_switch_with_a_pending_bad_value_keeps_the_robot_and_the_mark():
    panel = make_panel()
    panel.modules.rows[1].q.box.value = 30.0
    shown = panel.robot
    panel.modules.rows[2].q.box.value = float("nan")  # pending, refused
    assert panel.robot == shown
    panel.mode.value = "dh"  # asks first: nothing is replaced yet
    assert panel.mode.value == "modules" and panel.dh_entry.prompt.visible
    assert panel.robot == shown
    panel.dh_entry.prompt.cancel_button.click()
    assert panel.robot == shown
    np.testing.assert_allclose(panel.scene.q, shown.q)
    assert [row.kind.value for row in panel.modules.rows] == ["Rz", "Ry", "Ry"]
    assert len(panel.motion_section.editors) == 3
    assert "modules[2].q" in panel.errors  # the NaN is still marked
    panel.modules.rows[2].q.box.value = 10.0
    assert panel.robot.q[2] == pytest.approx(np.deg2rad(10.0)) and panel.errors == {}


def test_leaving_the_dh_table_with_a_pending_bad_row_converts_the_last_valid_robot():
    panel = make_panel(rc.Robot.from_dh([(0, 0, 7.0, 0, "R")], end_effector=(1, 0, 0)))
    dh_robot = panel.robot
    panel.dh.rows[0].cells["d"].box.value = float("nan")
    panel.mode.value = "modules"
    assert panel.mode.value == "modules"
    np.testing.assert_allclose(panel.robot.end_effector(), dh_robot.end_effector())
    panel.undo()
    assert panel.robot == dh_robot and panel.mode.value == "dh"


# -- symbolic matrices only where they are quick -------------------------------------------


def test_symbolic_box_is_disabled_with_a_note_for_a_long_chain(monkeypatch):
    long_chain = rc.Robot(
        [rc.Module(kind, a=(1, 0, 0)) for kind in ["Rz", "Ry", "Rx"] * 4], end_effector=(1, 0, 0)
    )
    assert not rc.teaching.symbolic_fits(long_chain)
    panel = make_panel(long_chain)
    view = panel.matrices
    assert view.symbolic.disabled and "shorter chains" in view.symbolic_note.value

    def hang(robot, **options):
        assert not options.get("symbolic"), "the symbolic derivation must not start"
        return rc.derivation(robot, **options)

    monkeypatch.setattr(_matrices_view, "derivation", hang)
    view.symbolic.value = True  # even if ticked from code, it refuses
    panel.results.selected_index = 1
    assert view.symbolic_math.value == "" and view.symbolic_math.layout.display == "none"
    assert panel.errors == {}

    monkeypatch.undo()
    panel.set_robot(paper_robot())  # a short chain: offered again
    assert not view.symbolic.disabled and view.symbolic_note.value == ""
    assert r"\sin" in view.symbolic_math.value
