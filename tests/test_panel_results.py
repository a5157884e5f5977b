"""One result view: tables with units, right-aligned numbers, every point plotted, the
other method overlaid; every number and curve one core call away."""

from __future__ import annotations

import base64
import html
import re

import numpy as np

import robotconf as rc
from robotconf.panel.support import STYLE, VIEW_CLASS

from .test_panel_support import make_panel, shown, ui


def _paper_run(**options):  # type: ignore[no-untyped-def]
    """The paper's workflow: the sawtooth on q3, Run."""
    panel = make_panel(t_end=4.0, dt=0.01, **options)
    ui(panel, "signals.q3").choose("RepeatingSequence")
    ui(panel, "run").click()
    assert panel.motion is not None and panel.errors == {}
    return panel, panel.motion_tab.results


def _cells(table_html: str) -> list[list[str]]:
    """The body rows of a result table as text cells."""
    body = table_html.split("<tbody>")[1]
    return [re.findall(r"<td>([^<]*)</td>", row) for row in body.split("</tr>") if "<td>" in row]


def test_the_table_starts_at_the_papers_parking_position_with_units():
    panel, results = _paper_run(length_unit="mm")
    first = _cells(results.table.value)[0]
    assert first[:4] == ["0", "70", "0", "20"]  # t [s], then EE x, y, z
    for heading in ("t [s]", "position [mm]", "velocity [mm/s]", "acceleration [mm/s²]"):
        assert heading in results.table.value
    assert "angular velocity [deg/s]" in results.table.value
    ui(panel, "length_unit").choose("cm")  # the name changes, not the numbers
    assert "position [cm]" in results.table.value and _cells(results.table.value)[0] == first


def test_angular_velocity_is_shown_in_the_chosen_angle_unit():
    panel, results = _paper_run()
    assert len(panel.motion.table) <= 500  # every row shown
    column = panel.motion.table[("EE", "angular_velocity", "y")]
    values = [row[-2] for row in _cells(results.table.value)]  # EE angular velocity y
    assert float(values[1]) == float(f"{np.rad2deg(column.iloc[1]):.6g}") == 57.2958  # 1 rad/s
    assert "deg/s" in results.table_note.value
    ui(panel, "angle_unit").choose(False)
    assert "angular velocity [rad/s]" in results.table.value
    values = [row[-2] for row in _cells(results.table.value)]
    assert float(values[1]) == column.iloc[1] == 1.0


def test_numbers_are_right_aligned_in_equal_width_digits_and_noise_is_zero():
    _, results = _paper_run()
    assert "text-align: right" in results.table.value and "tabular-nums" in results.table.value
    # The EE's y never leaves 0: float noise of sin(π)… shows as a clean 0, as in Matrices.
    assert all(row[2] == "0" for row in _cells(results.table.value))
    assert all("e-1" not in cell for row in _cells(results.table.value) for cell in row)


def test_a_quantity_that_is_noise_throughout_reads_zero():
    # Rz at q = 90° then a y offset: the EE's x is cos(90°)·… = 6e-15, never exactly 0.
    robot = rc.Robot(
        [rc.Module("Rz", q=np.pi / 2), rc.Module("Ry", a=(0, 0, 20))], end_effector=(0, 0, 10)
    )
    panel = make_panel(robot, t_end=0.5, dt=0.5)
    ui(panel, "run").click()
    assert abs(panel.motion.table[("EE", "position", "x")].iloc[0]) < 1e-13  # the core's
    assert _cells(panel.motion_tab.results.table.value)[0][1] == "0"


def test_statistics_name_the_unit_of_each_row_and_times_in_seconds():
    panel, results = _paper_run(length_unit="mm")
    ui(panel, "results.view").choose("statistics")
    stats = results.stats.value
    assert "velocity [mm/s]" in stats and "t_max [s]" in stats and "peak_<wbr>to_<wbr>peak" in stats
    rows = _cells(stats)
    assert len(rows) == 15  # one point: 5 quantities × 3 axes
    assert float(rows[0][0]) == panel.motion.stats().loc[("EE", "position", "x"), "max"] == 70


def test_all_points_shows_every_point_in_table_statistics_and_plot():
    panel, results = _paper_run(length_unit="mm")
    ui(panel, "results.point").choose("all")
    for point in ("M1", "M2", "M3", "EE"):
        assert f">{point}</th>" in results.table.value
        assert f">{point}</th>" in results.stats.value
    assert len(_cells(results.stats.value)) == 4 * 15
    ui(panel, "results.view").choose("plot")
    figure = results.figure(panel.state)
    axes = np.array(figure.axes).reshape(3, 3)
    assert [line.get_label() for line in axes[0, 0].lines] == ["M1", "M2", "M3", "EE"]
    for index, line in enumerate(axes[1, 2].lines):  # velocity z of every point
        np.testing.assert_array_equal(line.get_ydata(), panel.motion.velocity[:, index, 2])
    assert axes[0, 0].get_ylabel() == "position [mm]"
    assert results.plot.value[:4] == b"\x89PNG"


def test_the_overlay_draws_the_other_method_dashed_and_the_call_reproduces_it():
    panel, results = _paper_run(length_unit="mm")
    ui(panel, "results.view").choose("plot")
    ui(panel, "results.overlay").check(True)
    assert shown(panel, "results.overlay")["label"] == "overlay numeric"
    figure = results.figure(panel.state)
    lines = figure.axes[0].lines
    assert [line.get_linestyle() for line in lines[:2]] == ["-", "--"]
    assert [line.get_label() for line in lines[:2]] == ["analytic", "numeric"]
    numeric = rc.simulate(
        panel.motion.robot, panel.motion.signals, t_end=4.0, dt=0.01, method="numeric"
    )
    np.testing.assert_array_equal(lines[1].get_ydata(), numeric.position[:, -1, 0])
    # The note above the plot is the one core call that draws it.
    call = html.unescape(re.search(r"<code>(.*)</code>", results.plot_note.value).group(1))
    again = eval(call, {"rc": rc, "panel": panel})  # noqa: S307 - our own note
    for drawn, remade in zip(figure.axes, again.axes, strict=True):
        for a, b in zip(drawn.lines, remade.lines, strict=True):
            np.testing.assert_array_equal(a.get_ydata(), b.get_ydata())
    assert figure._suptitle.get_text() == again._suptitle.get_text()


def test_the_figure_fits_its_column_and_is_drawn_only_when_shown():
    panel, results = _paper_run()
    assert results.plot.value == b""
    assert results.plot.layout.max_width == "100%" and results.plot.layout.height == "auto"
    ui(panel, "results.view").choose("plot")
    png = results.plot.value
    width, height = int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")
    assert (width, height) == (1000, 650)
    ui(panel, "results.displacement").check(True)
    assert results.plot.value != png and "displacement=True" in results.plot_note.value


def test_the_app_names_no_code():
    panel = make_panel(t_end=1.0, dt=0.5, app=True)
    ui(panel, "run").click()
    ui(panel, "results.view").choose("plot")
    results = panel.motion_tab.results
    for text in (results.table_note, results.stats_note, results.plot_note):
        assert "panel." not in text.value


def test_the_exported_dva_figure_is_the_one_shown():
    panel, _ = _paper_run(length_unit="mm")
    ui(panel, "results.point").choose("all")
    panel.apply(rc.panel.actions.SelectTab("files"))
    ui(panel, "export.format").choose("svg")
    ui(panel, "export.dva_figure").click()
    link = shown(panel, "dva_figure.link")
    svg = base64.b64decode(link["href"].split("base64,")[1]).decode()
    assert link["download"] == "robot_dva_all.svg" and "position [mm]" in html.unescape(svg)


def test_a_programs_run_has_no_overlay():
    panel = make_panel()
    panel.apply(rc.panel.actions.SelectTab("program"))
    ui(panel, "program.add").click()
    ui(panel, "program.moves[0].q2").type("30")
    ui(panel, "program.run").click()
    panel.apply(rc.panel.actions.SelectTab("motion"))
    assert shown(panel, "results.overlay").get("disabled")


def test_the_view_column_sticks_and_the_results_are_below_it():
    panel = make_panel()
    assert VIEW_CLASS in panel.view._dom_classes
    assert panel.scene.widget in panel.view.children and panel.ee_label in panel.view.children
    assert "position: sticky" in STYLE and ".jp-OutputArea-output:has" in STYLE
    assert panel.results.titles == ("Motion", "Matrices", "Reach", "Program", "Save / Load")
    assert panel.results in panel.widget.children
