"""Save / load (JSON through the core's file format), lazy import and display."""

from __future__ import annotations

import base64
import datetime
import json
import subprocess
import sys

import numpy as np
import pytest

import robotconf as rc
from robotconf import signals

from .test_panel_support import make_panel, paper_robot

NOW = datetime.datetime(2026, 1, 1, tzinfo=datetime.timezone.utc)


def edited_panel():
    panel = make_panel(t_end=3.0, dt=0.05)
    panel.modules.rows[1].q.box.value = -30.0
    panel.extras.point[1].box.value = 5.0
    panel.motion_section.editors[2].kind.value = "RepeatingSequence"
    panel.motion_section.editors[0].kind.value = "Sine"
    panel.motion_section.editors[0].parameters["amplitude"].value = 30.0  # degrees
    panel.motion_section.method.value = "numeric"
    return panel


def test_save_then_load_round_trip(tmp_path):
    panel = edited_panel()
    path = tmp_path / "robot.json"
    panel.save(path)
    data = json.loads(path.read_text(encoding="utf-8"))
    assert data["format"] == "robotconf"
    other = make_panel()
    other.load(path)
    assert other.robot == panel.robot
    assert other.motion_section.settings() == {"t_end": 3.0, "dt": 0.05, "method": "numeric"}
    assert other.motion_section.signals() == {
        "q1": signals.Sine(amplitude=np.deg2rad(30.0)),
        "q3": signals.RepeatingSequence(),
    }
    assert [row.q.box.value for row in other.modules.rows] == pytest.approx([0, -30, 0])
    assert other.scene.names()[-1] == "set_robot"
    setup = rc.load_setup(path)  # one core call away
    assert setup.robot == panel.robot


def test_download_link_holds_the_same_json():
    panel = edited_panel()
    link = panel.files.make_save_link()
    href = link.split('href="')[1].split('"')[0]
    assert href.startswith("data:application/json;base64,")
    assert base64.b64decode(href.split(",", 1)[1]).decode() == panel.to_json()


def test_upload_loads_the_file():
    text = edited_panel().to_json().encode()
    panel = make_panel()
    upload = {"name": "robot.json", "type": "application/json", "size": len(text)}
    panel.files.upload.value = ({**upload, "content": memoryview(text), "last_modified": NOW},)
    assert panel.robot.q[1] == pytest.approx(np.deg2rad(-30))
    assert "loaded robot.json" in panel.files.load_status.value
    assert panel.errors == {}


def test_corrupt_upload_shows_the_core_message_and_keeps_everything():
    panel = make_panel()
    panel.modules.rows[0].q.box.value = 20.0
    robot = panel.robot
    data = {"format": "robotconf", "version": 1, "robot": {"links": [{"kind": "Rw"}]}}
    data["robot"]["links"][0]["type"] = "module"
    bad = json.dumps(data).encode()
    upload = {
        "name": "bad.json",
        "type": "application/json",
        "size": len(bad),
        "last_modified": NOW,
    }
    panel.files.upload.value = ({**upload, "content": memoryview(bad)},)
    assert panel.robot == robot
    assert "kind" in panel.errors["load"]
    assert panel.modules.rows[0].q.box.value == 20.0


def test_saving_with_an_invalid_signal_says_so():
    panel = make_panel()
    panel.motion_section.editors[0].kind.value = "Sine"
    panel.motion_section.editors[0].parameters["frequency"].value = -2.0
    assert panel.files.make_save_link() == ""
    assert panel.errors["save"].startswith("signals:")


def test_import_robotconf_does_not_load_ipywidgets_but_configurator_is_there():
    code = (
        "import sys, robotconf as rc\n"
        "assert 'ipywidgets' not in sys.modules\n"
        "assert 'configurator' in rc.__all__ and rc.Configurator.__name__ == 'Configurator'\n"
        "assert 'ipywidgets' in sys.modules\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True, timeout=120)


def test_configurator_function_displays_and_returns_the_panel(capsys):
    from .test_panel_support import FakeScene

    panel = rc.configurator(paper_robot(), scene_factory=FakeScene)
    assert isinstance(panel, rc.Configurator)
    assert "Configurator" in capsys.readouterr().out  # plain-text display outside Jupyter
    bundle = panel._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle
    assert bundle["text/plain"] == repr(panel)  # also where an IPython shell formats it


def test_default_scene_is_the_real_scene_or_a_clear_placeholder():
    panel = rc.Configurator(paper_robot())
    assert panel.scene.widget in panel.view.children  # beside the editor, no tab
    panel.modules.rows[0].q.box.value = 45.0  # whatever the scene is, it keeps up
    np.testing.assert_allclose(np.asarray(panel.scene.q, dtype=float), panel.robot.q)


def test_unknown_attribute_still_raises():
    with pytest.raises(AttributeError):
        rc.no_such_thing  # noqa: B018
