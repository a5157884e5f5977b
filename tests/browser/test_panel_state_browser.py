"""What the one-state panel promises in a real page (JupyterLab + Chromium, 1280 × 900),
each checked against the kernel by a second cell that prints the numbers' ``repr``.

The old panel, whose widgets each held a piece of the truth, broke these:

- unit switches moved the robot: rad ↔ deg sent the sliders' rounded values back as
  edits, so q drifted off 0, the bound file followed and the preset went "— preset —";
- after the guided mode and a preset, the 3D view and p_EE showed another robot than
  ``panel.robot``, and a preset choice was followed by a stray edit (undo went nowhere);
- an animation stopped before its end, or the kernel thought it still played.

One more is not fixed yet (marked xfail): a tab clicked while the kernel works is lost.
"""

from __future__ import annotations

import re

from playwright.sync_api import expect

import robotconf as rc
from robotconf.panel.viewport import end_effector_text

from .conftest import Lab
from .lab_driver import (
    NOTEBOOK,
    choose,
    click,
    control,
    ee_text,
    open_panel,
    output_text,
    reveal,
    run_cell,
    shown_value,
    type_number,
    wait_idle,
)

#: A slow kernel (the first formula, the scene) gets this long for each answer, in ms.
WAIT = 30_000


def _values(text: str, name: str) -> str:
    """The rest of the printed line that starts with ``name``."""
    found = re.search(rf"^{re.escape(name)} (.*)$", text, re.M)
    assert found, (name, text)
    return found.group(1)


def _chosen(page, key: str, label: str) -> None:  # type: ignore[no-untyped-def]
    """Wait until toggle or dropdown ``key`` shows ``label``."""
    for _ in range(WAIT // 100):
        if shown_value(page, key) == label:
            return
        page.wait_for_timeout(100)
    assert shown_value(page, key) == label, (key, shown_value(page, key), label)


# -- a. unit switches leave the robot alone ----------------------------------------------

BOUND = [
    'import robotconf as rc\npanel = rc.configurator("robot.json")',
    "print('q', repr(panel.robot.q.tolist()))\n"
    "print('ee', repr(panel.robot.end_effector().tolist()))\n"
    "print('file', repr(rc.load_setup('robot.json').robot.q.tolist()))\n"
    "print('paper', panel.robot == rc.preset('paper'), panel.can_undo)",
]


def test_ten_unit_switches_leave_q_the_file_and_the_preset_alone(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    (lab.root / "robot.json").write_text(rc.preset("paper").to_json(), "utf-8")
    open_panel(page, lab, "bound_units.ipynb", BOUND)
    expect(page.locator(f"{NOTEBOOK} .robotconf-file")).to_contain_text("robot.json")
    ee = ee_text(page)
    assert "p_EE = (70, 0, 20)" in ee, ee
    assert shown_value(page, "preset") == "paper"

    for unit in ["rad", "deg"] * 5:
        choose(page, "angle_unit", unit)
        _chosen(page, "angle_unit", unit)  # the next click is made for the new units
        assert [shown_value(page, f"modules[{i}].q") for i in range(3)] == ["0"] * 3
    wait_idle(page)
    page.wait_for_timeout(3000)  # longer than the bound file's save interval

    assert ee_text(page) == ee
    assert shown_value(page, "preset") == "paper"
    run_cell(page, 1)
    text = output_text(page, 1)
    assert _values(text, "q") == "[0.0, 0.0, 0.0]", text  # exactly, not nearly
    assert _values(text, "ee") == "[70.0, 0.0, 20.0]", text
    assert _values(text, "file") == "[0.0, 0.0, 0.0]", text
    assert _values(text, "paper") == "True False", text  # no edit in the history either
    assert not page.errors, page.errors


# -- b. the scene, p_EE and the preset follow the one robot --------------------------------

GUIDED = [
    "import robotconf as rc\npanel = rc.configurator()",
    "print('scene', panel.scene.robot == panel.robot, panel.scene.snapshot.robot == panel.robot)\n"
    "print('paper', panel.robot == rc.preset('paper'))\n"
    "print('puma', panel.robot == rc.preset('puma560'))",
]
#: The guided mode's modules: kind label, offsets a; every q = 0.
MODULES = [("3 Rz", (0, 0, 0)), ("6 Tz", (0, 0, 10)), ("4 Tx", (5, 0, 0))]


def _step(page, step: int) -> None:  # type: ignore[no-untyped-def]
    expect(page.locator(f"{NOTEBOOK} .robotconf-wizard-title")).to_contain_text(
        f"Step {step} of 12", timeout=WAIT
    )


def _guided_robot(page) -> None:  # type: ignore[no-untyped-def]
    """Rz, Tz with a = (0, 0, 10), Tx with a = (5, 0, 0), P = (2, 0, 0), through the
    guided mode's twelve steps, then Finish."""
    choose(page, "mode", "Guided")
    _step(page, 1)
    type_number(page, "wizard.count", 3)
    click(page, "wizard.next")
    for i, (label, offsets) in enumerate(MODULES):
        _step(page, 2 + 3 * i)
        choose(page, f"wizard.modules[{i}].kind", label)
        _chosen(page, f"wizard.modules[{i}].kind", label)
        click(page, "wizard.next")
        _step(page, 3 + 3 * i)
        for name, value in zip(("ax", "ay", "az"), offsets, strict=True):
            type_number(page, f"wizard.modules[{i}].{name}", value)
        click(page, "wizard.next")
        _step(page, 4 + 3 * i)
        type_number(page, f"wizard.modules[{i}].q", 0)
        click(page, "wizard.next")
    _step(page, 11)
    for name, value in zip(("Px", "Py", "Pz"), (2, 0, 0), strict=True):
        type_number(page, f"wizard.end_effector.{name}", value)
    click(page, "wizard.next")
    _step(page, 12)
    expect(page.locator(f"{NOTEBOOK} .robotconf-wizard-summary")).to_contain_text(
        "p_EE = (7, 0, 10)", timeout=WAIT
    )
    click(page, "wizard.next")  # Finish


def test_after_the_guided_mode_and_presets_every_view_shows_the_one_robot(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    open_panel(page, lab, "guided.ipynb", GUIDED)
    ee = page.locator(f"{NOTEBOOK} .robotconf-ee").first

    _guided_robot(page)
    expect(ee).to_contain_text("p_EE = (7, 0, 10)", timeout=WAIT)
    _chosen(page, "preset", "— preset —")

    choose(page, "preset", "paper")
    paper = end_effector_text(rc.preset("paper").end_effector())
    expect(ee).to_contain_text(paper, timeout=WAIT)
    choose(page, "length_unit", "mm")
    _chosen(page, "length_unit", "mm")
    choose(page, "angle_unit", "rad")
    _chosen(page, "angle_unit", "rad")
    wait_idle(page)
    page.wait_for_timeout(1000)
    assert paper in ee_text(page) and "[mm]" in ee_text(page), ee_text(page)
    assert shown_value(page, "preset") == "paper"
    run_cell(page, 1)
    text = output_text(page, 1)
    assert _values(text, "scene") == "True True", text
    assert _values(text, "paper") == "True", text

    choose(page, "preset", "puma560")
    page.wait_for_timeout(3000)  # time for any stray edit to arrive
    wait_idle(page)
    assert shown_value(page, "preset") == "puma560"
    puma = end_effector_text(rc.preset("puma560").end_effector())
    assert puma in ee_text(page), (ee_text(page), puma)
    run_cell(page, 1)
    text = output_text(page, 1)
    assert _values(text, "puma") == "True", text
    assert _values(text, "scene") == "True True", text

    click(page, "undo")  # one step back: the paper robot, so nothing came after the preset
    expect(ee).to_contain_text(paper, timeout=WAIT)
    wait_idle(page)
    run_cell(page, 1)
    text = output_text(page, 1)
    assert _values(text, "paper") == "True", text
    assert _values(text, "scene") == "True True", text
    _chosen(page, "preset", "paper")
    assert not page.errors, page.errors


# -- c. an animation plays to its end by itself ------------------------------------------

PLAYBACK = [
    'import robotconf as rc\npanel = rc.configurator(rc.preset("paper"), length_unit="mm")',
    "state, scene = panel.state.playback, panel.scene.playback_state\n"
    "print('panel', state.source, state.playing, repr(state.time))\n"
    "print('scene', scene.loaded, scene.playing, repr(scene.time), repr(scene.duration))",
]


def _sawtooth_on_q3(page, t_end: float, dt: float | None = None) -> None:  # type: ignore[no-untyped-def]
    """The Motion tab's settings: the sawtooth (RepeatingSequence) on q3, t_end and dt."""
    choose(page, "signals.q3", "RepeatingSequence")
    type_number(page, "t_end", t_end)
    if dt is not None:
        type_number(page, "dt", dt)
    wait_idle(page)


def _bar_time(page) -> float:  # type: ignore[no-untyped-def]
    return float(page.locator(f"{NOTEBOOK} .robotconf-scene-time").first.input_value())


def _plays_to_the_end(page, duration: float) -> list[float]:  # type: ignore[no-untyped-def]
    """Sample the bar's time slider every 250 ms until it shows ``duration`` (at speed 1,
    with time to spare); returns the samples."""
    times = [_bar_time(page)]
    for _ in range(int((duration + 15) / 0.25)):
        if times[-1] >= duration:
            break
        page.wait_for_timeout(250)
        times.append(_bar_time(page))
    page.wait_for_timeout(1000)  # the end's report reaches the kernel
    times.append(_bar_time(page))
    return times


def _check_ended(page, cell: int, source: str, duration: float) -> None:  # type: ignore[no-untyped-def]
    """The kernel's two accounts of the playback: stopped, at the end of the motion."""
    run_cell(page, cell)
    text = output_text(page, cell)
    panel = _values(text, "panel").split()
    scene = _values(text, "scene").split()
    assert panel[:2] == [source, "False"] and scene[:2] == ["True", "False"], text
    assert float(panel[2]) == float(scene[2]) == float(scene[3]), text  # at the very end
    assert abs(float(scene[3]) - duration) < 1e-9 * max(1.0, duration), (text, duration)


def test_a_run_and_a_program_play_to_their_end(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    open_panel(page, lab, "playback.ipynb", PLAYBACK)

    # The Motion tab: the sawtooth on q3 for 3 s, Run, animate in 3D.
    _sawtooth_on_q3(page, 3)
    click(page, "run")
    page.wait_for_selector(f"{NOTEBOOK} .robotconf-results-table table", timeout=60_000)
    click(page, "results.animate")
    times = _plays_to_the_end(page, 3.0)
    assert times[-1] == 3.0, times
    assert times == sorted(times) and len(set(times)) >= 4, times  # never back, never stuck
    _check_ended(page, 1, "motion", 3.0)

    # The Program tab: two PTP moves from q = 0 (q3 to −90°, then q1 to 90°), Run plays.
    tab = page.locator(f"{NOTEBOOK} .lm-TabBar-tab", has_text="Program").first
    reveal(tab)
    tab.click()
    control(page, "program.add").wait_for(timeout=WAIT)
    for _ in range(2):
        click(page, "program.add")
        wait_idle(page)
    type_number(page, "program.moves[0].q2", "-90")
    wait_idle(page)
    type_number(page, "program.moves[1].q2", "-90")
    wait_idle(page)
    type_number(page, "program.moves[1].q0", "90")
    wait_idle(page)
    click(page, "program.run")
    wait_idle(page)
    status = page.locator(f"{NOTEBOOK} .robotconf-program-status").first.inner_text()
    duration = float(re.search(r"([\d.]+) s, \d+ samples", status).group(1))  # type: ignore[union-attr]
    assert duration > 1.0, status
    times = _plays_to_the_end(page, duration)
    assert abs(times[-1] - duration) < 1e-5, (times, duration)  # the status rounds to 6 digits
    assert times == sorted(times) and len(set(times)) >= 4, times
    _check_ended(page, 1, "program", times[-1])
    assert not page.errors, page.errors


# -- d. a tab clicked while the kernel works ---------------------------------------------

BUSY = [
    'import robotconf as rc\npanel = rc.configurator(rc.preset("paper"))',
    "print('tab', panel.state.view.tab, panel.results.selected_index)",
]


def test_a_tab_clicked_during_a_run_shows_and_stays(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    open_panel(page, lab, "busy.ipynb", BUSY)
    # A run of 150 001 samples: a second or more of the kernel's time.
    _sawtooth_on_q3(page, 300, 0.002)
    click(page, "run")
    page.wait_for_timeout(300)
    tab = page.locator(f"{NOTEBOOK} .lm-TabBar-tab", has_text="Matrices").first
    tab.click()
    page.wait_for_timeout(1000)
    wait_idle(page)
    page.wait_for_timeout(2000)
    run_cell(page, 1)
    assert _values(output_text(page, 1), "tab") == "matrices 1", output_text(page, 1)
    expect(page.locator(f"{NOTEBOOK} .robotconf-matrices pre").first).to_be_visible()
    assert "lm-mod-current" in (tab.get_attribute("class") or "")
