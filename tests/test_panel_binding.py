"""A panel bound to a file: ``rc.configurator("my_robot.json")`` keeps the work there.

Headless: no event loop runs here, so every valid change is written at once; the
throttled writes of a kernel are driven with a fake timer and clock.
"""

from __future__ import annotations

import json
import os
import stat
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
import pytest

import robotconf as rc
from robotconf import signals
from robotconf.panel import Configurator
from robotconf.panel.files import FileBinding, _binding, flush_all

from .test_panel_hostile import hostile_file
from .test_panel_support import FakeScene, make_panel, shown, ui

IMG = "<img src=x onerror=alert(1)>"


def bound(path: Path, **options) -> Configurator:  # type: ignore[no-untyped-def]
    return Configurator(str(path), scene_factory=FakeScene, **options)


def edit(panel: Configurator) -> None:
    """Change the robot (a q, an offset), a signal and every time setting."""
    ui(panel, "modules[1].q").type("-30")
    ui(panel, "modules[2].ax").type("35")
    ui(panel, "signals.q1").choose("Sine")
    ui(panel, "signals.q1.amplitude").type("30")  # degrees, the panel's angle unit
    ui(panel, "t_end").type("3")
    ui(panel, "dt").type("0.05")
    ui(panel, "method").choose("numeric")


def tags(markup: str) -> list[str]:
    """The element names a browser would build from ``markup``."""
    found: list[str] = []

    class Parser(HTMLParser):
        def handle_starttag(self, tag, attrs):  # type: ignore[no-untyped-def]
            found.append(tag)

    Parser().feed(markup)
    return found


# -- the work survives ------------------------------------------------------------------


def test_a_new_file_is_created_at_once(tmp_path):
    path = tmp_path / "my_robot.json"
    panel = bound(path)
    assert rc.load_setup(path).robot == panel.robot == rc.preset("paper")
    assert "Every change is saved to <code>" in panel.binding.widget.value
    assert panel.errors == {}


def test_every_valid_change_is_saved_and_a_new_panel_gets_it_back(tmp_path):
    path = tmp_path / "my_robot.json"
    panel = bound(path)
    edit(panel)
    setup = rc.load_setup(path)
    assert setup.robot == panel.robot
    assert setup.robot.q[1] == pytest.approx(np.deg2rad(-30))  # q is part of the robot
    assert setup.robot.modules[2].a[0] == 35.0
    assert setup.signals == {"q1": signals.Sine(amplitude=np.deg2rad(30.0))}
    assert setup.simulate_kwargs() == {"t_end": 3.0, "dt": 0.05, "method": "numeric"}

    again = bound(path)  # a kernel restart: the same cell runs again
    assert again.robot == panel.robot
    assert again.state.document == panel.state.document
    assert shown(again, "modules[1].q")["value"] == pytest.approx(-30.0)
    assert not again.can_undo  # the loaded file is where undo starts
    assert "Loaded from <code>" in again.binding.widget.value
    assert again.errors == {}


def test_the_file_is_replaced_in_one_step_and_keeps_its_mode(tmp_path):
    path = tmp_path / "my_robot.json"
    bound(path)
    path.chmod(0o640)
    panel = bound(path)
    ui(panel, "modules[0].q").type("10")
    assert stat.S_IMODE(path.stat().st_mode) == 0o640
    assert sorted(p.name for p in tmp_path.iterdir()) == ["my_robot.json"]  # no temp file left


def test_a_refused_value_leaves_the_last_valid_setup_in_the_file(tmp_path):
    path = tmp_path / "my_robot.json"
    panel = bound(path)
    ui(panel, "modules[0].q").type("20")
    before = path.read_text()
    ui(panel, "modules[0].q").type("nan")  # refused: the state, and so the file, stay
    assert path.read_text() == before
    ui(panel, "signals.q1").choose("Sine")  # valid with its defaults: saved
    before = path.read_text()
    ui(panel, "signals.q1.frequency").type("-1")  # refused beside the box: nothing changes
    assert path.read_text() == before
    assert "Every change is saved" in panel.binding.widget.value
    ui(panel, "signals.q1.frequency").type("2")
    setup = rc.load_setup(path)
    assert setup.signals == {"q1": signals.Sine(frequency=2.0)}


def test_a_program_the_robot_no_longer_fits_is_not_written_until_fixed(tmp_path):
    path = tmp_path / "my_robot.json"
    panel = bound(path)
    panel.apply(rc.panel.actions.AddMove())
    saved = path.read_text()
    panel.apply(rc.panel.actions.EditMove(0, "kind", "LIN"))  # to where it is already
    assert "the LIN goes nowhere" in panel.errors["program.moves[0]"]
    assert panel.program is None and panel.state.document.program.moves[0].kind == "LIN"
    assert path.read_text() == saved  # the draft is kept on screen, not written
    program = rc.Program(panel.robot, [rc.LIN(position=(50, 10, 30), speed=10)])
    panel.apply(rc.panel.actions.LoadSetup(panel.robot, {}, None, program))
    assert rc.load_setup(path).program == program
    before = path.read_text()
    ui(panel, "modules[2].ax").type("1")  # too short now: (50, 10, 30) is out of reach
    assert "Changes not saved: program.moves[0]" in panel.binding.widget.value
    assert path.read_text() == before
    ui(panel, "modules[2].ax").type("30")  # fixed: saved again
    assert rc.load_setup(path).robot == panel.robot


def test_an_uploaded_file_is_saved_once_whole(tmp_path, monkeypatch):
    path = tmp_path / "my_robot.json"
    panel = bound(path)
    writes: list[str] = []
    original = _binding.write_atomically
    monkeypatch.setattr(
        _binding, "write_atomically", lambda p, text: (writes.append(text), original(p, text))[1]
    )
    panel.load(hostile_file_path(tmp_path))
    assert len(writes) == 1
    assert rc.load_setup(path).robot == panel.robot


def hostile_file_path(folder: Path) -> Path:
    other = folder / "other.json"
    other.write_bytes(hostile_file())
    return other


def test_saving_to_the_bound_file_is_not_a_foreign_change(tmp_path):
    path = tmp_path / "my_robot.json"
    panel = bound(path)
    ui(panel, "modules[0].q").type("15")
    panel.save(path)
    ui(panel, "modules[0].q").type("25")
    assert rc.load_setup(path).robot.q[0] == pytest.approx(np.deg2rad(25.0))
    assert panel.errors == {}


# -- files the panel must not overwrite ---------------------------------------------------


@pytest.mark.parametrize(
    "content",
    [
        b"{not json",
        b'{"format": "robotconf", "version": 1, "robot": {"links": [{"kind": "Rw"}]}}',
        b"\xff\xfe binary",
    ],
)
def test_an_unreadable_file_is_shown_and_never_overwritten(tmp_path, content):
    path = tmp_path / "my_robot.json"
    path.write_bytes(content)
    panel = bound(path)
    assert panel.robot == rc.preset("paper")  # the default robot, so the panel still works
    assert "was not loaded, and will not be overwritten" in panel.errors["file"]
    assert panel.binding.refused
    assert "is left as it is" in panel.binding.widget.value
    edit(panel)
    panel.binding.save_now()
    flush_all()
    assert path.read_bytes() == content
    other = tmp_path / "elsewhere.json"
    panel.save(other)  # the work can still go to another file
    assert rc.load_setup(other).robot == panel.robot


def test_a_folder_is_not_a_file(tmp_path):
    path = tmp_path / "folder.json"
    path.mkdir()
    panel = bound(path)
    assert "was not loaded" in panel.errors["file"]
    ui(panel, "modules[0].q").type("5")
    assert path.is_dir()


def test_a_file_changed_by_someone_else_is_not_overwritten(tmp_path):
    path = tmp_path / "my_robot.json"
    panel = bound(path)
    theirs = rc.preset("paper").with_q([0.1, 0.2, 0.3]).to_json()
    path.write_text(theirs)  # another panel, or an editor
    ui(panel, "modules[0].q").type("40")
    assert path.read_text() == theirs
    assert "changed on disk" in panel.errors["file"]
    ui(panel, "modules[0].q").type("50")
    assert path.read_text() == theirs


def test_a_deleted_file_is_written_again_and_a_write_failure_is_shown(tmp_path):
    folder = tmp_path / "work"
    folder.mkdir()
    path = folder / "my_robot.json"
    panel = bound(path)
    path.unlink()
    ui(panel, "modules[0].q").type("10")
    assert rc.load_setup(path).robot.q[0] == pytest.approx(np.deg2rad(10.0))
    path.unlink()
    folder.rmdir()
    ui(panel, "modules[0].q").type("20")
    assert panel.errors["file"].startswith("file: cannot save to ")
    folder.mkdir()
    ui(panel, "modules[0].q").type("30")
    assert rc.load_setup(path).robot.q[0] == pytest.approx(np.deg2rad(30.0))
    assert "file" not in panel.errors


def test_hostile_content_and_file_names_are_shown_as_text(tmp_path):
    path = tmp_path / f"{IMG}.json"
    path.write_bytes(hostile_file())
    panel = bound(path)
    assert panel.errors == {}
    assert "img" not in tags(panel.binding.widget.value)
    assert "&lt;img src=x" in panel.binding.widget.value
    broken = tmp_path / f"{IMG}broken.json"
    broken.write_text(json.dumps({"format": IMG, "version": 1, "robot": {}}))
    refused = bound(broken)
    shown = refused.binding.error.widget.value + refused.binding.widget.value
    assert IMG in refused.errors["file"]  # the message names the value…
    assert "img" not in tags(shown)  # …as text
    assert broken.read_text() == json.dumps({"format": IMG, "version": 1, "robot": {}})


# -- without a file -------------------------------------------------------------------------


def test_an_unbound_panel_says_how_to_keep_the_work():
    panel = make_panel()
    assert panel.binding.path is None
    hint = panel.binding.widget.value
    assert 'rc.configurator("my_robot.json")' in hint and "<b>Save</b>" in hint
    assert "rc." not in make_panel(app=True).binding.widget.value  # no code in the app


def test_only_json_files_are_taken():
    with pytest.raises(rc.InvalidInputError, match="ending in .json"):
        Configurator("paper", scene_factory=FakeScene)
    with pytest.raises(rc.InvalidInputError, match="a robotconf Robot"):
        Configurator(42, scene_factory=FakeScene)  # type: ignore[arg-type]


# -- cheap: a dragged slider is not a write per value -----------------------------------------


class FakeTimer:
    """Stands in for the kernel's event loop: ``call_later`` is recorded, fired by hand."""

    def __init__(self) -> None:
        self.now = 100.0
        self.pending: list[tuple[float, object]] = []

    def call_later(self, delay: float, callback) -> None:  # type: ignore[no-untyped-def]
        self.pending.append((delay, callback))

    def fire(self) -> None:
        (_, callback), *self.pending = self.pending
        callback()  # type: ignore[operator]


def test_changes_are_written_at_most_every_interval_and_the_last_always(tmp_path):
    timer = FakeTimer()
    state = {"text": "0"}
    path = tmp_path / "b.json"
    binding = FileBinding(
        path, lambda: state["text"], scheduler=lambda: timer.call_later, clock=lambda: timer.now
    )
    assert binding.load() is None
    binding.start()
    assert path.read_text() == "0"  # created at once
    timer.now += 1.0
    state["text"] = "1"
    binding.changed()
    assert path.read_text() == "1"  # idle for longer than the interval: written at once
    for value in range(2, 30):  # a dragged slider
        timer.now += 0.01
        state["text"] = str(value)
        binding.changed()
    assert path.read_text() == "1"
    assert len(timer.pending) == 1  # one timer for the whole drag
    assert timer.pending[0][0] == pytest.approx(0.49)  # from the first change of the drag
    timer.now += 0.5
    timer.fire()
    assert path.read_text() == "29"
    state["text"] = "30"
    binding.changed()  # within the interval again: waits…
    assert path.read_text() == "29"
    flush_all()  # …unless the kernel shuts down first
    assert path.read_text() == "30"


def test_the_kernel_event_loop_is_the_default_timer():
    import asyncio

    async def inside_a_kernel():  # type: ignore[no-untyped-def]
        return _binding.event_loop_scheduler()

    assert asyncio.run(inside_a_kernel()) is not None
    assert _binding.event_loop_scheduler() is None


def test_a_panel_in_a_folder_it_cannot_write_says_so(tmp_path):
    if os.geteuid() == 0:
        pytest.skip("root writes anywhere")
    folder = tmp_path / "read_only"
    folder.mkdir()
    folder.chmod(0o500)
    try:
        panel = bound(folder / "my_robot.json")
        assert "cannot save" in panel.errors["file"]
    finally:
        folder.chmod(0o700)
