"""The Motion tab: a signal per coordinate, the repeating table, time settings, Run and
its results; an animation plays to its end and a scrub is the student's only."""

from __future__ import annotations

import base64

import numpy as np
import pytest

import robotconf as rc
from robotconf import signals
from robotconf.panel import actions as act

from .test_panel_support import make_panel, paper_robot, shown, ui


def _signals(panel):
    return panel.state.document.motion.signals


def _status(panel) -> str:
    return shown(panel, "run")["label"] and next(
        c["value"]
        for r in panel.motion_tab.form.spec["rows"]
        for line in r["lines"]
        for c in line
        if c.get("class") == "robotconf-run-status"
    )


def test_one_signal_per_coordinate_with_its_unit():
    panel = make_panel()
    kinds = [k for k in panel.motion_tab.form.control_keys() if k.count(".") == 1]
    assert kinds == ["signals.q1", "signals.q2", "signals.q3"]
    titles = [r["lines"][0][0]["value"] for r in panel.motion_tab.form.spec["rows"][1:4]]
    assert titles == ["q1 [deg]", "q2 [deg]", "q3 [deg]"]  # the panel's angle unit
    ui(panel, "modules[2].kind").choose("Tz")
    assert panel.motion_tab.form.spec["rows"][3]["lines"][0][0]["value"] == "q3 [units]"


def test_signal_parameters_come_from_the_core_classes():
    panel = make_panel()
    ui(panel, "signals.q1").choose("Sine")
    keys = [k for k in panel.motion_tab.form.control_keys() if k.startswith("signals.q1.")]
    assert keys == [f"signals.q1.{p}" for p in ("amplitude", "bias", "frequency", "phase")]
    ui(panel, "signals.q1").choose("Trapezoidal")
    assert "signals.q1.accel_fraction" in panel.motion_tab.form.control_keys()
    ui(panel, "signals.q1.duration").type("3")
    assert _signals(panel)[0] == signals.Trapezoidal(duration=3.0)


def test_run_gives_the_papers_numbers():
    panel = make_panel(dt=0.01, t_end=2.0)
    ui(panel, "signals.q3").choose("RepeatingSequence")  # Simulink's default sawtooth on q3
    ui(panel, "run").click()
    motion = panel.motion
    assert motion is not None and panel.errors == {}
    table = motion.table
    assert table.shape[0] == 201
    np.testing.assert_array_equal(
        [table[("EE", "position", axis)].iloc[0] for axis in "xyz"], [70, 0, 20]
    )
    np.testing.assert_allclose(motion.velocity[0, -1], [0, 0, -40], atol=1e-12)
    expected = rc.simulate(paper_robot(), {"q3": signals.RepeatingSequence()}, 2.0, 0.01)
    np.testing.assert_array_equal(motion.columns(), expected.columns())
    results = panel.motion_tab.results
    assert "<table" in results.table.value and "70" in results.table.value
    ui(panel, "results.view").choose("statistics")
    assert "rms" in results.stats.value
    assert _status(panel) == "201 samples, analytic"


def test_the_point_choice_filters_the_table_and_plots_on_demand():
    panel = make_panel(t_end=1.0, dt=0.1)
    ui(panel, "signals.q1").choose("Ramp")
    ui(panel, "run").click()
    results = panel.motion_tab.results
    assert shown(panel, "results.point")["options"][0] == ["EE", "EE"]
    ui(panel, "results.point").choose("M2")
    assert "M2" in results.table.value and "EE" not in results.table.value
    assert results.plot.value == b""  # drawn only when its view shows
    ui(panel, "results.view").choose("plot")
    assert results.plot.value[:4] == b"\x89PNG"


def test_the_csv_download_link_is_a_data_uri_of_the_whole_table():
    panel = make_panel(t_end=1.0, dt=0.5)
    ui(panel, "run").click()
    link = panel.motion_tab.results.make_csv_link()
    href = link.split('href="')[1].split('"')[0]
    assert href.startswith("data:text/csv;base64,")
    assert base64.b64decode(href.split(",", 1)[1]).decode() == panel.motion.table.to_csv()


def test_dt_zero_is_refused_beside_dt_and_keeps_everything():
    panel = make_panel(t_end=1.0, dt=0.5)
    ui(panel, "run").click()
    motion, robot = panel.motion, panel.robot
    ui(panel, "dt").type("0")
    assert set(panel.errors) == {"dt"} and panel.errors["dt"].startswith("dt: must be positive")
    assert shown(panel, "dt")["text"] == "0"  # what was typed stays, with the message
    assert panel.state.document.motion.settings.dt == 0.5
    ui(panel, "run").click()  # runs with the last valid settings
    assert panel.motion is not motion and panel.motion.t.size == 3 and panel.robot == robot
    ui(panel, "dt").type("0.25")
    assert panel.errors == {} and panel.state.document.motion.settings.dt == 0.25


def test_t_end_before_t0_is_refused_beside_t_end():
    panel = make_panel()
    ui(panel, "t_end").type("-1")
    assert set(panel.errors) == {"t_end"} and panel.state.document.motion.settings.t_end == 10.0


def test_the_numeric_method():
    panel = make_panel(t_end=1.0, dt=0.01)
    ui(panel, "signals.q1").choose("Sine")
    ui(panel, "method").choose("numeric")
    ui(panel, "run").click()
    assert panel.motion.method == "numeric"


def test_the_repeating_table_is_editable_and_checked():
    panel = make_panel(t_end=4.0, dt=0.5)
    ui(panel, "signals.q2").choose("RepeatingSequence")
    images = [
        c
        for r in panel.motion_tab.form.spec["rows"]
        for line in r["lines"]
        for c in line
        if c["type"] == "image"
    ]
    assert images and images[0]["src"].startswith("data:image/png;base64,iVBOR")  # the preview
    ui(panel, "signals.q2.table.add").click()
    assert _signals(panel)[1].times == (0.0, 2.0, 4.0)
    ui(panel, "signals.q2.table.v2").type("0")  # a triangle 0 → 2 → 0 (values in degrees)
    ui(panel, "run").click()
    assert panel.motion.signals["q2"] == signals.RepeatingSequence((0, 2, 4), (0, 2, 0))
    ui(panel, "signals.q2.table.t2").type("1")  # not increasing
    assert panel.errors["signals.q2.table.t2"].startswith("times:")
    assert _signals(panel)[1].times == (0.0, 2.0, 4.0)


def test_an_invalid_signal_parameter_is_refused_beside_it():
    panel = make_panel()
    ui(panel, "signals.q1").choose("Sine")
    ui(panel, "signals.q1.frequency").type("-1")
    assert set(panel.errors) == {"signals.q1.frequency"}
    assert panel.errors["signals.q1.frequency"].startswith("frequency: must be ≥ 0")
    assert _signals(panel)[0] == signals.Sine()


def test_signals_move_with_their_module_when_reordered():
    panel = make_panel()
    ui(panel, "signals.q3").choose("Ramp")
    ui(panel, "modules[2].up").click()
    assert _signals(panel) == (None, signals.Ramp(), None)
    assert shown(panel, "signals.q2")["value"] == "Ramp"


def test_an_animation_plays_to_its_end_and_only_a_scrub_seeks():
    panel = make_panel(t_end=1.0, dt=0.5)
    ui(panel, "run").click()
    ui(panel, "results.animate").click()
    assert panel.scene.calls[-1] == ("animate", panel.motion)
    assert panel.state.playback.playing and panel.state.playback.source == "motion"
    scene = panel.scene
    calls = len(scene.calls)
    scene.page_reports(playing=True, time=0.5)  # the page reports where it is
    assert panel.state.playback.playing and panel.state.playback.time == 0.5
    assert len(scene.calls) == calls  # a report is mirrored, never answered with a command
    scene.page_reports(playing=False, time=1.0)  # the end: the page stopped by itself
    assert not panel.state.playback.playing and panel.state.playback.time == 1.0
    assert len(scene.calls) == calls
    panel.apply(act.Play())
    assert scene.calls[-1] == ("play", None)


def test_a_changed_robot_ends_the_animation_and_is_noted():
    panel = make_panel(t_end=1.0, dt=0.5)
    ui(panel, "run").click()
    ui(panel, "results.animate").click()
    ui(panel, "modules[0].q").type("10")
    assert panel.state.playback.source is None  # the robot moved: the pane shows it
    assert "robot changed" in _status(panel)
    assert panel.motion.robot == paper_robot()


@pytest.mark.parametrize("kind", ["Constant", "Step", "Ramp", "Sine", "Cubic", "Quintic"])
def test_every_signal_type_runs(kind):
    panel = make_panel(t_end=1.0, dt=0.25)
    ui(panel, "signals.q1").choose(kind)
    ui(panel, "run").click()
    assert type(panel.motion.signals["q1"]).__name__ == kind
