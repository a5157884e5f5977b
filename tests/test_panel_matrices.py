"""The matrices tab: the core's derivation, numeric always, symbolic only when asked and visible."""

from __future__ import annotations

import html

import robotconf as rc

from .test_panel_support import make_panel


def test_numeric_printout_is_the_core_derivation():
    panel = make_panel()
    assert panel.matrices.text == str(rc.derivation(panel.robot))
    assert "       [ 70 ]\np_EE = [  0 ]\n       [ 20 ]" in panel.matrices.text
    assert panel.matrices.numeric_text.value == ""  # drawn only when its tab is shown
    panel.results.selected_index = 1
    assert "<pre " in panel.matrices.numeric_text.value
    panel.matrices.style.value = "latex"
    latex = rc.derivation(panel.robot).latex()  # shown HTML-escaped: "&" as "&amp;"
    assert panel.matrices.numeric_math.value == "$$" + html.escape(latex, quote=False) + "$$"
    assert panel.matrices.numeric_text.layout.display == "none"


def test_q_change_updates_the_printout():
    panel = make_panel()
    panel.modules.rows[0].q.box.value = 90.0
    assert "at q = (1.5708, 0, 0)" in panel.matrices.text


def test_symbolic_view_waits_for_its_tab_and_ignores_q():
    panel = make_panel()
    view = panel.matrices
    view.symbolic.value = True
    assert view.symbolic_math.value == ""  # tab not showing: nothing computed
    panel.results.selected_index = 1
    expected = rc.derivation(panel.robot, symbolic=True).latex()
    assert view.symbolic_math.value == "$$" + html.escape(expected, quote=False) + "$$"
    cached = dict(view._symbolic_cache)
    panel.modules.rows[1].q.box.value = 30.0  # q does not change the symbolic matrices
    assert view._symbolic_cache.keys() == cached.keys()
    view.lengths.value = True
    assert "l_{1}" in view.symbolic_math.value
    panel.modules.rows[1].kind.value = "Rx"
    assert r"\sin{\left(q_{2} \right)}" in view.symbolic_math.value
