"""The Matrices tab: ``rc.derivation(panel.robot)`` step by step, as text or LaTeX,
numeric or symbolic.

The numbers are those of the robot at its q, in the panel's units (the "at q = …" line
names q in degrees in degree mode). Ticking **symbolic** shows the symbolic derivation in
place of the numeric one, where the student is looking; it does not depend on q, so it
is computed once per structure, and only while the tab shows.
"""

from __future__ import annotations

import html
from collections.abc import Callable
from typing import Any

import ipywidgets as widgets
import numpy as np

from ..._errors import InvalidInputError
from ...kinematics import Robot
from ...teaching import Derivation, derivation, format_number, symbolic_fits
from .. import actions as act
from ..form import Form, FormEvent, check, message, row, text, toggle
from ..state import PanelState, Units
from ..support._app_mode import code_hint
from ..support._monospace import preformatted

__all__ = ["MatricesView", "math_html", "too_long_note", "q_text"]

#: Shown instead of the symbolic box's effect for a chain too long to derive quickly.
TOO_LONG_NOTE = (
    "Symbolic matrices are offered for shorter chains only: their size doubles with every "
    "rotation, and this chain would keep the kernel busy for a long time.{hint}"
)
TOO_LONG_HINT = (
    " rc.derivation(panel.robot, symbolic=True) in a cell still builds them (it may take minutes)."
)


def math_html(latex: str) -> str:
    """Display-math HTML of LaTeX source, escaped so that no tag in it reaches the page.

    >>> math_html("M_1 &= <b>")
    '$$M_1 &amp;= &lt;b&gt;$$'
    """
    return "$$" + html.escape(latex, quote=False) + "$$"


def too_long_note(app: bool = False) -> str:
    """Why the symbolic box is off for a long chain (with the cell's way around it).

    >>> "in a cell" in too_long_note(app=False), "in a cell" in too_long_note(app=True)
    (True, False)
    """
    return TOO_LONG_NOTE.format(hint=code_hint(TOO_LONG_HINT, app))


def q_text(robot: Robot, units: Units) -> str:
    """The robot's q as the panel shows it: ``q = (0°, 30°, -45°)`` in degree mode.

    >>> import robotconf as rc
    >>> q_text(rc.preset("paper").with_q([0.0, np.pi / 6, 0.0]), Units("mm", True))
    'q = (0°, 30°, 0°)'
    >>> q_text(rc.Robot([rc.Module("Tz", q=2.5)]), Units("mm", False))
    'q = (2.5 mm)'
    """
    parts = []
    for link in robot.modules:
        value = units.to_shown(link.q, link.unit)
        number = format_number(value, 4)
        if link.unit == "rad":
            parts.append(f"{number}°" if units.degrees else f"{number} rad")
        elif link.unit == "length":
            parts.append(f"{number} {units.length}")
        else:
            parts.append(number)
    return f"q = ({', '.join(parts)})"


class MatricesView:
    """Numeric derivation, or the symbolic one, of the panel's robot.

    Parameters
    ----------
    dispatch : callable
        ``dispatch(action, key)``.
    precision : int
        Significant digits of the numeric printout.
    app : bool
        No notebook around the panel: no hints to type code.
    """

    def __init__(self, dispatch: Callable[..., None], precision: int = 4, app: bool = False):
        self._dispatch = dispatch
        self.precision = precision
        self.app = app
        self.controls = Form(self._event, css_class="robotconf-matrices-controls")
        # Text in an HTML widget (MathJax never sees a name with "$" in it), LaTeX in a
        # math widget; one of them shows.
        self.output = widgets.HTML(layout=widgets.Layout(flex="0 0 auto"))
        self.output.add_class("robotconf-matrices")
        self.math = widgets.HTMLMath(layout=widgets.Layout(flex="0 0 auto", display="none"))
        self.math.add_class("robotconf-matrices-latex")
        self.widget = widgets.VBox(
            [
                self.controls,
                widgets.Box([self.output, self.math], layout=widgets.Layout(overflow="auto")),
            ]
        )
        self.widget.add_class("robotconf-matrices-tab")
        self._derivation: tuple[Robot, Derivation] | None = None
        self._symbolic: tuple[Any, Derivation] | None = None
        self._shown: Any = None

    def derivation(self, robot: Robot) -> Derivation:
        """The numeric derivation of ``robot`` at its q (made once per robot)."""
        if self._derivation is None or self._derivation[0] is not robot:
            self._derivation = (robot, derivation(robot, precision=self.precision))
        return self._derivation[1]

    def text(self, state: PanelState) -> str:
        """The numeric printout as the text view shows it: the core's, its "at q = …"
        line in the panel's units."""
        return _in_units(str(self.derivation(state.robot)), state)

    def latex(self, state: PanelState) -> str:
        """The numeric derivation's LaTeX as the LaTeX view shows it (q in the panel's
        units)."""
        return _in_units(self.derivation(state.robot).latex(), state)

    def render(self, state: PanelState, feedback: Any, rev: str, visible: bool) -> None:
        """Draw the derivation (only while the tab shows: a q drag sends nothing here)."""
        if not visible:
            return
        robot, view = state.robot, state.view
        fits = symbolic_fits(robot)
        symbolic = view.symbolic and fits
        note = "" if fits else too_long_note(self.app)
        self.controls.show(
            [
                row(
                    "matrices",
                    [
                        toggle(
                            "matrices.style",
                            "latex" if view.latex else "text",
                            [
                                ("text", "text", "aligned number grids (fast)"),
                                ("LaTeX", "latex", "typeset matrices"),
                            ],
                            rev=rev,
                        ),
                        check(
                            "matrices.symbolic",
                            view.symbolic,
                            "symbolic (sympy)",
                            rev=rev,
                            disabled=not fits,
                            css_class="robotconf-matrices-symbolic",
                        ),
                        check(
                            "matrices.lengths",
                            view.lengths,
                            "lengths as l1, l2, …",
                            rev=rev,
                            disabled=not fits or not view.symbolic,
                        ),
                    ],
                    # The printout says "at q = …" itself (in the panel's units).
                    [text(note, tone="note")] if note else [],
                    note=message(feedback.message("matrices")),
                )
            ]
        )
        shown = (
            robot if not symbolic else _structure(robot),
            view.latex,
            symbolic,
            view.lengths,
            state.units,
        )
        if shown == self._shown:
            return
        if symbolic:
            steps = self._symbolic_steps(robot, view.lengths)
            if steps is None:
                return
            self._show(math=math_html(steps.latex()))
        elif view.latex:
            self._show(math=math_html(self.latex(state)))
        else:
            self._show(text=preformatted(self.text(state)))
        self._shown = shown

    def _show(self, *, text: str = "", math: str = "") -> None:
        if math:
            self.math.value = math
        else:
            self.output.value = text
        self.output.layout.display = "none" if math else None
        self.math.layout.display = None if math else "none"

    def _symbolic_steps(self, robot: Robot, lengths: bool) -> Derivation | None:
        key = (_structure(robot), lengths)
        if self._symbolic is not None and self._symbolic[0] == key:
            return self._symbolic[1]
        try:
            steps = derivation(robot, symbolic=True, lengths=lengths)
        except InvalidInputError as error:
            self._show(text="")  # never another structure's matrices
            self._dispatch(error, "matrices")
            return None
        self._symbolic = (key, steps)  # one structure at a time: bounded memory
        return steps

    def _event(self, event: FormEvent) -> None:
        key = event.key
        if key == "matrices.style":
            self._dispatch(act.SetViewOption("latex", event.value == "latex"), "matrices")
        elif key == "matrices.symbolic":
            self._dispatch(act.SetViewOption("symbolic", bool(event.value)), "matrices")
        elif key == "matrices.lengths":
            self._dispatch(act.SetViewOption("lengths", bool(event.value)), "matrices")


def _in_units(printout: str, state: PanelState) -> str:
    """The core's printout with its "at q = (…)" line (radians, lengths) shown in the
    panel's units, as every other number on screen."""
    robot = state.robot
    values = ", ".join(format_number(v, 4) for v in robot.q)
    return printout.replace(f"at q = ({values})", f"at {q_text(robot, state.units)}", 1)


def _structure(robot: Robot) -> Robot:
    return robot.with_q(np.zeros(robot.n))
