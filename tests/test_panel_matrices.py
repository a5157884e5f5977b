"""The Matrices tab: the core's derivation, drawn while the tab shows; symbolic when asked,
in place of the numeric one; q in the panel's units."""

from __future__ import annotations

import html

import numpy as np

import robotconf as rc
from robotconf.panel import actions as act

from .test_panel_support import make_panel, ui


def test_the_numeric_printout_is_the_core_derivation():
    panel = make_panel()
    text = panel.matrices.text(panel.state)
    core = str(rc.derivation(panel.robot))
    assert text == core.replace("at q = (0, 0, 0)", "at q = (0°, 0°, 0°)")
    assert "       [ 70 ]\np_EE = [  0 ]\n       [ 20 ]" in text
    assert panel.matrices.output.value == ""  # drawn only when its tab is shown
    panel.apply(act.SelectTab("matrices"))
    assert "<pre " in panel.matrices.output.value
    ui(panel, "matrices.style").choose("latex")
    latex = panel.matrices.latex(panel.state)  # shown HTML-escaped: "&" as "&amp;"
    assert panel.matrices.math.value == "$$" + html.escape(latex, quote=False) + "$$"
    assert panel.matrices.output.layout.display == "none"


def test_q_is_named_in_the_panels_units():
    panel = make_panel()
    ui(panel, "modules[0].q").type("90")
    assert "at q = (90°, 0°, 0°)" in panel.matrices.text(panel.state)
    ui(panel, "angle_unit").choose(False)
    assert "at q = (1.5708 rad, 0 rad, 0 rad)" in panel.matrices.text(panel.state)
    ui(panel, "modules[2].kind").choose("Tz")
    assert "0 units)" in panel.matrices.text(panel.state)


def test_the_symbolic_view_replaces_the_numeric_one_and_ignores_q():
    panel = make_panel()
    panel.apply(act.SelectTab("matrices"))
    ui(panel, "matrices.symbolic").check(True)
    expected = rc.derivation(panel.robot, symbolic=True).latex()
    assert panel.matrices.math.value == "$$" + html.escape(expected, quote=False) + "$$"
    assert panel.matrices.output.layout.display == "none"  # where the student looks
    cached = panel.matrices._symbolic
    ui(panel, "modules[1].q").type("30")  # q does not change the symbolic matrices
    assert panel.matrices._symbolic is cached
    ui(panel, "matrices.lengths").check(True)
    assert "l_{1}" in panel.matrices.math.value
    ui(panel, "modules[1].kind").choose("Rx")
    assert r"\sin{\left(q_{2} \right)}" in panel.matrices.math.value


def test_a_chain_too_long_for_symbolic_matrices_says_so():
    robot = rc.Robot([rc.Module(kind, a=(1, 0, 0)) for kind in ["Rz", "Ry", "Rx"] * 4])
    panel = make_panel(robot)
    panel.apply(act.SelectTab("matrices"))
    assert panel.matrices.controls.control("matrices.symbolic").get("disabled")
    notes = [
        c["value"]
        for r in panel.matrices.controls.spec["rows"]
        for line in r["lines"]
        for c in line
        if c["type"] == "text"
    ]
    assert any("offered for shorter chains only" in note for note in notes)
    assert np.isfinite(panel.robot.end_effector()).all()
