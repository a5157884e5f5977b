"""The export buttons of the Save / Load tab: each link holds what the core's exporter makes."""

from __future__ import annotations

import base64
import io
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import pandas as pd
import pytest

import robotconf as rc
from robotconf.cli import write_report
from robotconf.panel._images import download_link

from .test_panel_hostile import SCRIPT, hostile_robot
from .test_panel_support import make_panel

FILES_TAB = 4


def link_content(link: str) -> tuple[str, bytes]:
    """``(file name, bytes)`` of a download link made by the panel."""
    assert link.startswith("<a download="), link
    name = link.split('download="')[1].split('"')[0]
    href = link.split('href="')[1].split('"')[0]
    return name, base64.b64decode(href.split(",", 1)[1])


def short_run(panel) -> None:  # type: ignore[no-untyped-def]
    panel.motion_section.t_end.value = 1.0
    panel.motion_section.dt.value = 0.1
    panel.motion_section.editors[2].kind.value = "RepeatingSequence"  # the paper's q3


def test_report_zip_is_what_robotconf_report_writes(tmp_path):
    panel = make_panel()
    short_run(panel)
    name, data = link_content(panel.exports.make("report"))
    assert name == "robot_report.zip"
    archive = zipfile.ZipFile(io.BytesIO(data))
    names = archive.namelist()
    assert all(n.startswith("robot_report/") for n in names)
    files = {n.split("/", 1)[1] for n in names}

    setup = rc.load_setup(panel.to_json())
    written = write_report(setup.robot, setup.signals, setup.settings, tmp_path, scene=True)
    assert files == set(written)
    assert {"report.md", "dva.csv", "statistics.csv", "matrices.tex", "scene.html"} <= files
    dva = archive.read("robot_report/dva.csv")
    assert dva == (tmp_path / "dva.csv").read_bytes()
    table = pd.read_csv(io.BytesIO(dva), header=[0, 1, 2], index_col=0)
    assert table[("EE", "position", "x")].iloc[0] == pytest.approx(70.0)  # the paper's Figure 14
    assert table[("EE", "position", "z")].iloc[0] == pytest.approx(20.0)
    assert "configurator panel" in archive.read("robot_report/report.md").decode()
    assert panel.errors == {}


def test_report_over_the_memory_budget_says_so_beside_its_button():
    panel = make_panel()
    panel.motion_section.t_end.value = 100.0
    panel.motion_section.dt.value = 1e-4
    rc.set_memory_budget(10_000_000)
    try:
        assert panel.exports.make("report") == ""
    finally:
        rc.set_memory_budget(None)
    message = panel.errors["export.report"]
    assert message.startswith("dt: needs about") and "memory" in message
    assert "&lt;" not in message
    assert panel.exports.make("urdf")  # the other exports still work
    assert "export.report" in panel.errors  # until the report is tried again


def test_report_results_that_overflow_say_so_beside_the_button(monkeypatch):
    from robotconf.cli import BadInput
    from robotconf.panel import _exports

    def overflowing(*args, **kwargs):  # type: ignore[no-untyped-def]
        raise BadInput("dva.csv: the velocity (x) of EE overflows to inf or NaN at t = 0 s")

    monkeypatch.setattr(_exports, "report_zip", overflowing)
    panel = make_panel()
    assert panel.exports.make("report") == ""
    assert panel.errors["export.report"].startswith("dva.csv: the velocity (x) of EE")
    monkeypatch.undo()
    panel.motion_section.t_end.value = 0.5
    assert panel.exports.make("report")  # the next report that works clears it
    assert "export.report" not in panel.errors


def test_report_refuses_an_invalid_signal():
    panel = make_panel()
    panel.motion_section.editors[0].kind.value = "Sine"
    panel.motion_section.editors[0].parameters["frequency"].value = -2.0
    assert panel.exports.make("report") == ""
    assert panel.errors["export.report"].startswith("signals:")


@pytest.mark.parametrize("fmt", ["png", "svg"])
def test_robot_figure_as_png_or_svg(fmt):
    panel = make_panel()
    panel.exports.figure_format.value = fmt
    name, data = link_content(panel.exports.make("robot_figure"))
    assert name == f"robot_robot.{fmt}"
    if fmt == "png":
        assert data.startswith(b"\x89PNG")
    else:
        assert ET.fromstring(data).tag.endswith("svg")


def test_dva_figure_needs_a_run_then_follows_the_chosen_point():
    panel = make_panel()
    assert panel.exports.make("dva_figure") == ""
    assert "press Run" in panel.errors["export.dva_figure"]
    short_run(panel)
    panel.motion_section.run_button.click()
    panel.motion_section.results.point.value = "M3"
    panel.exports.figure_format.value = "svg"
    name, data = link_content(panel.exports.make("dva_figure"))
    assert name == "robot_dva_M3.svg"
    assert ET.fromstring(data).tag.endswith("svg")
    assert "export.dva_figure" not in panel.errors


def test_scene_page_is_self_contained_and_animates_the_last_run():
    panel = make_panel()
    name, data = link_content(panel.exports.make("scene_html"))
    page = data.decode()
    assert name == "robot_scene.html"
    assert page.startswith("<!DOCTYPE html>") and "<script src=" not in page
    short_run(panel)
    panel.motion_section.run_button.click()
    _, animated = link_content(panel.exports.make("scene_html"))
    assert len(animated) > len(data)  # the animation's frames travel with the page
    assert "<script src=" not in animated.decode()


def test_urdf_of_the_paper_robot_has_its_three_joints():
    panel = make_panel()
    name, data = link_content(panel.exports.make("urdf"))
    assert name == "robot.urdf"
    root = ET.fromstring(data)
    moving = [j.get("name") for j in root.iter("joint") if j.get("type") != "fixed"]
    assert moving == ["q1", "q2", "q3"]
    assert data.decode() == rc.to_urdf(panel.robot)


def test_latex_of_one_matrix_follows_the_robot_when_its_tab_shows():
    panel = make_panel()
    view = panel.exports.latex
    assert view.text.value == ""  # nothing computed while the tab is hidden
    panel.results.selected_index = FILES_TAB
    assert view.step.value == "p_EE"
    assert "\\begin{bmatrix} 70 \\\\ 0 \\\\ 20 \\\\ 1 \\end{bmatrix}" in view.text.value
    view.step.value = "A2"
    expected = rc.derivation(panel.robot)["A2"].latex()
    assert view.text.value == "\\begin{aligned}\n" + expected + "\n\\end{aligned}"
    panel.modules.rows[1].q.box.value = 90.0  # the robot moves: the matrix follows
    assert view.text.value.count("\\begin{bmatrix}") == 1
    assert rc.derivation(panel.robot)["A2"].latex() in view.text.value
    view.symbolic.value = True
    assert "\\cos{\\left(q_{2} \\right)}" in view.text.value
    view.lengths.value = True
    assert "l_{1}" in view.text.value
    assert panel.errors == {}


def test_hostile_names_stay_text_in_every_export():
    panel = make_panel(hostile_robot())
    for key in ("urdf", "scene_html", "robot_figure"):
        link = panel.exports.make(key)
        assert SCRIPT not in link and "<img" not in link.split(">", 1)[1]
    _, urdf = link_content(panel.exports.make("urdf"))
    ET.fromstring(urdf)  # names are escaped: still well-formed XML
    _, page = link_content(panel.exports.make("scene_html"))
    assert SCRIPT not in page.decode().split("<body>")[0]  # the title is escaped
    panel.exports.figure_format.value = "svg"
    _, svg = link_content(panel.exports.make("robot_figure"))
    root = ET.fromstring(svg)
    assert not [e for e in root.iter() if e.tag.endswith("script")]
    panel.results.selected_index = FILES_TAB
    panel.exports.latex.step.value = "A1"
    assert "<script>" not in panel.exports.latex.text.value.split("\\text{")[0]
    assert panel.errors == {}


def test_link_names_are_safe_file_names():
    panel = make_panel(hostile_robot())
    name, _ = link_content(panel.exports.make("urdf"))
    assert Path(name).name == name and name.endswith(".urdf")
    assert set(name) <= set("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.-")
    assert download_link("x", name, "text/plain", name).count("<a ") == 1


def test_app_mode_exports_name_no_code():
    panel = make_panel(app=True)
    header = panel.exports.widget.children[0].value
    assert "robotconf report" not in header and header.startswith("<b>Export</b>")
