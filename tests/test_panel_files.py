"""Save / load through the core's file format, the exports (each link holds what the core's
exporter makes), lazy import and display."""

from __future__ import annotations

import base64
import datetime
import io
import json
import subprocess
import sys
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import robotconf as rc
from robotconf.panel import actions as act
from robotconf.report import write_report

from .test_panel_hostile import SCRIPT, hostile_robot
from .test_panel_support import FakeScene, make_panel, paper_robot, shown, ui

NOW = datetime.datetime(2026, 1, 1, tzinfo=datetime.timezone.utc)


def edited_panel():
    panel = make_panel(t_end=3.0, dt=0.05)
    ui(panel, "modules[1].q").type("-30")
    ui(panel, "end_effector.Py").type("5")
    ui(panel, "signals.q3").choose("RepeatingSequence")
    ui(panel, "signals.q1").choose("Sine")
    ui(panel, "signals.q1.amplitude").type("30")  # degrees
    ui(panel, "method").choose("numeric")
    return panel


def make(panel, key: str) -> tuple[str, bytes]:
    """Click export ``key`` on the Save / Load tab: ``(file name, content)`` of its link."""
    panel.apply(act.SelectTab("files"))
    ui(panel, key).click()
    link = key.split(".", 1)[1] if key.startswith("export.") else "save"
    spec = shown(panel, f"{link}.link")
    assert spec["href"].startswith("data:")
    return spec["download"], base64.b64decode(spec["href"].split(",", 1)[1])


def short_run(panel) -> None:  # type: ignore[no-untyped-def]
    ui(panel, "t_end").type("1")
    ui(panel, "dt").type("0.1")
    ui(panel, "signals.q3").choose("RepeatingSequence")  # the paper's q3


# -- save and load --------------------------------------------------------------------------


def test_save_then_load_round_trip(tmp_path):
    panel = edited_panel()
    path = tmp_path / "robot.json"
    panel.save(path)
    assert json.loads(path.read_text(encoding="utf-8"))["format"] == "robotconf"
    other = make_panel()
    other.load(path)
    assert other.state.document == panel.state.document
    assert other.state.document.motion.settings.to_dict() == {
        "t_end": 3.0,
        "dt": 0.05,
        "t0": 0.0,
        "method": "numeric",
    }
    assert [shown(other, f"modules[{i}].q")["value"] for i in range(3)] == [0, -30, 0]
    assert other.scene.robot == other.robot
    assert rc.load_setup(path).robot == panel.robot  # one core call away


def test_the_download_link_holds_the_same_json():
    panel = edited_panel()
    name, content = make(panel, "save.make")
    assert name == "robot.json" and content.decode() == panel.to_json()
    ui(panel, "save.name").type("lab1")
    name, _ = make(panel, "save.make")
    assert name == "lab1.json"
    ui(panel, "modules[0].q").type("5")  # a link is never left for an older state
    assert "save.link" not in panel.files.form.control_keys()


def test_an_upload_loads_the_file():
    text = edited_panel().to_json().encode()
    panel = make_panel()
    upload = {"name": "robot.json", "type": "application/json", "size": len(text)}
    panel.files.upload.value = ({**upload, "content": memoryview(text), "last_modified": NOW},)
    assert panel.robot.q[1] == pytest.approx(np.deg2rad(-30))
    assert "loaded robot.json" in panel.files.load_status.value and panel.errors == {}


def test_a_corrupt_upload_shows_the_core_message_and_keeps_everything():
    panel = make_panel()
    ui(panel, "modules[0].q").type("20")
    robot = panel.robot
    data = {"format": "robotconf", "version": 1, "robot": {"links": [{"kind": "Rw"}]}}
    data["robot"]["links"][0]["type"] = "module"
    bad = json.dumps(data).encode()
    upload = {"name": "bad.json", "type": "application/json", "size": len(bad)}
    panel.files.upload.value = ({**upload, "content": memoryview(bad), "last_modified": NOW},)
    assert panel.robot is robot and "kind" in panel.errors["load"]
    assert shown(panel, "modules[0].q")["value"] == 20.0


def test_import_robotconf_does_not_load_ipywidgets_but_configurator_is_there():
    code = (
        "import sys, robotconf as rc\n"
        "assert 'ipywidgets' not in sys.modules\n"
        "assert 'configurator' in rc.__all__ and rc.Configurator.__name__ == 'Configurator'\n"
        "assert 'ipywidgets' in sys.modules\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True, timeout=120)


def test_the_state_and_actions_import_no_widgets():
    code = (
        "import sys\n"
        "import robotconf.panel.actions, robotconf.panel.state\n"
        "assert not {'ipywidgets', 'anywidget'} & set(sys.modules)\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True, timeout=120)


def test_configurator_displays_and_returns_the_panel(capsys):
    panel = rc.configurator(paper_robot(), scene_factory=FakeScene)
    assert isinstance(panel, rc.Configurator)
    assert "Configurator" in capsys.readouterr().out  # plain-text display outside Jupyter
    bundle = panel._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle
    assert bundle["text/plain"] == repr(panel)


def test_the_default_scene_keeps_up():
    panel = rc.Configurator(paper_robot())
    assert panel.scene.widget in panel.view.children  # beside the editor, no tab
    ui(panel, "modules[0].q").type("45")
    np.testing.assert_allclose(np.asarray(panel.scene.q, dtype=float), panel.robot.q)


# -- exports ------------------------------------------------------------------------------


def test_the_report_zip_is_what_robotconf_report_writes(tmp_path):
    panel = make_panel()
    short_run(panel)
    name, data = make(panel, "export.report")
    assert name == "robot_report.zip"
    archive = zipfile.ZipFile(io.BytesIO(data))
    names = archive.namelist()
    assert all(n.startswith("robot_report/") for n in names)
    setup = rc.load_setup(panel.to_json())
    written = write_report(setup.robot, setup.signals, setup.settings, tmp_path, scene=True)
    assert {n.split("/", 1)[1] for n in names} == set(written)
    dva = archive.read("robot_report/dva.csv")
    assert dva == (tmp_path / "dva.csv").read_bytes()
    table = pd.read_csv(io.BytesIO(dva), header=[0, 1, 2], index_col=0)
    assert table[("EE", "position", "x")].iloc[0] == pytest.approx(70.0)  # the paper's Fig. 14
    assert "configurator panel" in archive.read("robot_report/report.md").decode()
    assert panel.errors == {}


def test_a_preset_names_its_files_by_its_key():
    panel = make_panel(rc.preset("paper"))
    assert make(panel, "export.urdf")[0] == "paper.urdf"


def test_a_report_over_the_memory_budget_says_so_beside_its_button():
    panel = make_panel()
    ui(panel, "t_end").type("100")
    ui(panel, "dt").type("1e-4")
    rc.set_memory_budget(10_000_000)
    try:
        panel.apply(act.SelectTab("files"))
        ui(panel, "export.report").click()
    finally:
        rc.set_memory_budget(None)
    message = panel.errors["export.report"]
    assert message.startswith("dt: needs about") and "memory" in message
    assert "report.link" not in panel.files.form.control_keys()
    assert make(panel, "export.urdf")  # the other exports still work


@pytest.mark.parametrize("fmt", ["png", "svg"])
def test_the_robot_figure_as_png_or_svg_with_its_unit(fmt):
    panel = make_panel(length_unit="mm")
    panel.apply(act.SelectTab("files"))
    ui(panel, "export.format").choose(fmt)
    name, data = make(panel, "export.robot_figure")
    assert name == f"robot_robot.{fmt}"
    if fmt == "png":
        assert data.startswith(b"\x89PNG")
    else:
        assert ET.fromstring(data).tag.endswith("svg") and b"mm" in data


def test_the_dva_figure_needs_a_run_then_follows_the_chosen_point():
    panel = make_panel()
    panel.apply(act.SelectTab("files"))
    ui(panel, "export.dva_figure").click()
    assert "press Run" in panel.errors["export.dva_figure"]
    short_run(panel)
    ui(panel, "run").click()
    ui(panel, "results.point").choose("M3")
    panel.apply(act.SelectTab("files"))
    ui(panel, "export.format").choose("svg")
    name, data = make(panel, "export.dva_figure")
    assert name == "robot_dva_M3.svg" and ET.fromstring(data).tag.endswith("svg")
    assert "export.dva_figure" not in panel.errors


def test_the_scene_page_is_self_contained_and_animates_the_last_run():
    panel = make_panel()
    name, data = make(panel, "export.scene_html")
    page = data.decode()
    assert name == "robot_scene.html"
    assert page.startswith("<!DOCTYPE html>") and "<script src=" not in page
    short_run(panel)
    ui(panel, "run").click()
    _, animated = make(panel, "export.scene_html")
    assert len(animated) > len(data)  # the animation's frames travel with the page


def test_the_urdf_is_in_metres_from_the_panels_length_unit():
    panel = make_panel(length_unit="mm")
    name, data = make(panel, "export.urdf")
    assert name == "robot.urdf"
    root = ET.fromstring(data)
    moving = [j.get("name") for j in root.iter("joint") if j.get("type") != "fixed"]
    assert moving == ["q1", "q2", "q3"]
    assert data.decode() == rc.to_urdf(panel.robot, scale=0.001)  # mm → m
    plain = make_panel()  # "units": no scale known, the numbers as they are
    assert make(plain, "export.urdf")[1].decode() == rc.to_urdf(plain.robot)


def test_the_latex_of_one_matrix_follows_the_robot_when_its_tab_shows():
    panel = make_panel()
    assert panel.files.latex.value == ""  # nothing computed while the tab is hidden
    panel.apply(act.SelectTab("files"))
    assert shown(panel, "latex.step")["value"] == "p_EE"
    assert "\\begin{bmatrix} 70 \\\\ 0 \\\\ 20 \\\\ 1 \\end{bmatrix}" in panel.files.latex.value
    ui(panel, "latex.step").choose("A2")
    expected = rc.derivation(panel.robot)["A2"].latex()
    assert panel.files.latex.value == "\\begin{aligned}\n" + expected + "\n\\end{aligned}"
    ui(panel, "modules[1].q").type("90")  # the robot moves: the matrix follows
    assert rc.derivation(panel.robot)["A2"].latex() in panel.files.latex.value
    ui(panel, "latex.symbolic").check(True)
    assert "\\cos{\\left(q_{2} \\right)}" in panel.files.latex.value
    ui(panel, "latex.lengths").check(True)
    assert "l_{1}" in panel.files.latex.value and panel.errors == {}


def test_hostile_names_stay_text_in_every_export():
    panel = make_panel(hostile_robot())
    _, urdf = make(panel, "export.urdf")
    ET.fromstring(urdf)  # names are escaped: still well-formed XML
    _, page = make(panel, "export.scene_html")
    assert SCRIPT not in page.decode().split("<body>")[0]  # the title is escaped
    ui(panel, "export.format").choose("svg")
    _, svg = make(panel, "export.robot_figure")
    assert not [e for e in ET.fromstring(svg).iter() if e.tag.endswith("script")]
    ui(panel, "latex.step").choose("A1")
    assert "<script>" not in panel.files.latex.value.split("\\text{")[0]
    assert panel.errors == {}


def test_link_names_are_safe_file_names():
    name, _ = make(make_panel(hostile_robot()), "export.urdf")
    assert Path(name).name == name and name.endswith(".urdf")
    assert set(name) <= set("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.-")


def test_app_mode_names_no_code():
    panel = make_panel(app=True)
    panel.apply(act.SelectTab("files"))
    texts = [
        c["value"]
        for r in panel.files.form.spec["rows"]
        for line in r["lines"]
        for c in line
        if c["type"] == "text"
    ]
    assert not any("robotconf report" in t or "panel.save" in t for t in texts)
