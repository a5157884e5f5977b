"""The matrices tab: A_i, M_i and p_EE step by step, numerically and (on request) symbolically.

Everything shown is :func:`robotconf.derivation`'s own text or LaTeX, so a student gets the
same printout with ``print(rc.derivation(panel.robot))`` in a cell.
"""

from __future__ import annotations

import html
from typing import Any

import ipywidgets as widgets
import numpy as np

from .._errors import InvalidInputError
from ..kinematics import Robot
from ..teaching import Derivation, derivation, format_number

__all__ = ["MatricesView", "end_effector_text"]


def end_effector_text(robot: Robot, precision: int = 4) -> str:
    """``"p_EE = (70, 0, 20)"``: the end-effector at the robot's own q, as shown on screen.

    >>> import robotconf as rc
    >>> robot = rc.Robot([rc.Module("Rz", a=(0, 0, 20))], end_effector=(50, 0, 0))
    >>> end_effector_text(robot)
    'p_EE = (50, 0, 20)'
    """
    values = ", ".join(format_number(v, precision) for v in robot.end_effector())
    return f"p_EE = ({values})"


class MatricesView:
    """Numeric derivation always up to date; the symbolic one only when visible and asked for.

    The symbolic derivation does not depend on q, so it is cached per robot structure and a
    q slider never recomputes it.

    Examples
    --------
    >>> import robotconf as rc
    >>> view = MatricesView()
    >>> view.show(rc.Robot([rc.Module("Tz", q=2.0)], end_effector=(1, 0, 0)))
    >>> "p_EE" in view.text
    True
    """

    def __init__(self, precision: int = 4):
        self.precision = precision
        self.style = widgets.ToggleButtons(
            options=(("text", "text"), ("LaTeX", "latex")),
            value="text",
            tooltips=["aligned number grids (fast)", "typeset matrices"],
            style={"button_width": "70px"},
        )
        self.symbolic = widgets.Checkbox(value=False, description="symbolic (sympy)", indent=False)
        self.lengths = widgets.Checkbox(
            value=False, description="lengths as l1, l2, …", indent=False
        )
        self.numeric_text = widgets.HTML()
        self.numeric_math = widgets.HTMLMath(layout=widgets.Layout(display="none"))
        self.symbolic_math = widgets.HTMLMath()
        self.symbolic_error = widgets.HTML()
        self.widget = widgets.VBox(
            [
                widgets.HBox([self.style, self.symbolic, self.lengths]),
                self.numeric_text,
                self.numeric_math,
                self.symbolic_error,
                self.symbolic_math,
            ],
            layout=widgets.Layout(overflow="auto", max_height="640px"),
        )
        self.visible = True
        self.derivation: Derivation | None = None
        self._robot: Robot | None = None
        self._symbolic_cache: dict[Any, Derivation] = {}
        self._symbolic_shown: Any = None
        self.style.observe(lambda _: self._render_numeric(), "value")
        self.symbolic.observe(lambda _: self._render_symbolic(), "value")
        self.lengths.observe(lambda _: self._render_symbolic(), "value")

    @property
    def text(self) -> str:
        """The numeric printout as plain text (what the text view shows)."""
        return "" if self.derivation is None else str(self.derivation)

    def show(self, robot: Robot) -> None:
        """Show the derivation of ``robot`` at its own q."""
        self._robot = robot
        self.derivation = derivation(robot, precision=self.precision)
        self._render_numeric()
        self._render_symbolic()

    def set_visible(self, visible: bool) -> None:
        """Tell the view whether its tab is showing (the symbolic view waits until it is)."""
        self.visible = visible
        self._render_symbolic()

    def _render_numeric(self) -> None:
        if self.derivation is None:
            return
        latex = self.style.value == "latex"
        if latex:
            self.numeric_math.value = "$$" + self.derivation.latex() + "$$"
        else:
            self.numeric_text.value = f"<pre>{html.escape(str(self.derivation))}</pre>"
        self.numeric_text.layout.display = "none" if latex else None
        self.numeric_math.layout.display = None if latex else "none"

    def _render_symbolic(self) -> None:
        wanted = self.symbolic.value and self._robot is not None
        self.symbolic_math.layout.display = None if wanted else "none"
        if not wanted or not self.visible:
            return
        robot = self._robot
        assert robot is not None
        key = (robot.with_q(np.zeros(robot.n)), bool(self.lengths.value))
        if key == self._symbolic_shown:
            return
        steps = self._symbolic_cache.get(key)
        if steps is None:
            try:
                steps = derivation(robot, symbolic=True, lengths=bool(self.lengths.value))
            except InvalidInputError as error:
                self.symbolic_error.value = f'<span style="color:#b00020">{error}</span>'
                return
            self._symbolic_cache = {key: steps}  # one structure at a time: bounded memory
        self.symbolic_error.value = ""
        self.symbolic_math.value = "$$" + steps.latex() + "$$"
        self._symbolic_shown = key
