"""The matrices tab: A_i, M_i and p_EE step by step, numerically and (on request) symbolically.

Everything shown is :func:`robotconf.derivation`'s own text or LaTeX, so a student gets the
same printout with ``print(rc.derivation(panel.robot))`` in a cell. The printout holds the
robot's name, so it is HTML-escaped like any user text (the core's LaTeX already escapes
``$`` and backslashes in names, so a name never becomes math either).

The symbolic matrices grow exponentially with the chain: for a robot the core's
:func:`~robotconf.teaching.symbolic_fits` refuses, the box is disabled and a note says why,
instead of the kernel hanging for minutes.
"""

from __future__ import annotations

import html
from collections.abc import Iterator
from typing import Any

import ipywidgets as widgets
import numpy as np

from .._errors import InvalidInputError
from ..kinematics import Robot
from ..teaching import Derivation, derivation, format_number, symbolic_fits
from ._app_mode import code_hint
from ._callbacks import observe
from ._errors_display import ErrorLabel
from ._monospace import preformatted

__all__ = ["MatricesView", "end_effector_text", "too_long_note"]


def end_effector_text(robot: Robot, precision: int = 4) -> str:
    """``"p_EE = (70, 0, 20)"``: the end-effector at the robot's own q, as shown on screen.

    >>> import robotconf as rc
    >>> robot = rc.Robot([rc.Module("Rz", a=(0, 0, 20))], end_effector=(50, 0, 0))
    >>> end_effector_text(robot)
    'p_EE = (50, 0, 20)'
    """
    values = ", ".join(format_number(v, precision) for v in robot.end_effector())
    return f"p_EE = ({values})"


def math_html(latex: str) -> str:
    """Display-math HTML of LaTeX source, escaped so that no tag in it reaches the page.

    >>> math_html("M_1 &= <b>")
    '$$M_1 &amp;= &lt;b&gt;$$'
    """
    return "$$" + html.escape(latex, quote=False) + "$$"


#: Shown instead of the symbolic box's effect for a chain too long to derive quickly.
TOO_LONG_NOTE = (
    "<small>Symbolic matrices are offered for shorter chains only: their size doubles with "
    "every rotation, and this chain would keep the kernel busy for a long time.{hint}</small>"
)
#: The way around it, for a notebook only (the app has no cells).
TOO_LONG_HINT = (
    " <code>rc.derivation(panel.robot, symbolic=True)</code> in a cell still builds them "
    "(it may take minutes)."
)


def too_long_note(app: bool = False) -> str:
    """The note shown for a chain too long for symbolic matrices.

    >>> "in a cell" in too_long_note(app=False), "in a cell" in too_long_note(app=True)
    (True, False)
    """
    return TOO_LONG_NOTE.format(hint=code_hint(TOO_LONG_HINT, app))


class MatricesView:
    """Numeric derivation always up to date; the symbolic one only when visible and asked for.

    The symbolic derivation does not depend on q, so it is cached per robot structure and a
    q slider never recomputes it.

    Parameters
    ----------
    precision : int
        Significant digits of the numeric printout.
    app : bool
        The panel runs without cells around it (Voilà): no hint to type code in a cell.

    Examples
    --------
    >>> import robotconf as rc
    >>> view = MatricesView()
    >>> view.show(rc.Robot([rc.Module("Tz", q=2.0)], end_effector=(1, 0, 0)))
    >>> "p_EE" in view.text
    True
    """

    def __init__(self, precision: int = 4, *, app: bool = False):
        self.precision = precision
        self.app = app
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
        # Items of a scrolling column keep their height: a long printout must scroll, not
        # shrink the rows above it until the printout covers them.
        self.numeric_text = widgets.HTML(layout=widgets.Layout(flex="0 0 auto"))
        self.numeric_text.add_class("robotconf-matrices")
        self.numeric_math = widgets.HTMLMath(layout=widgets.Layout(display="none", flex="0 0 auto"))
        self.symbolic_math = widgets.HTMLMath(layout=widgets.Layout(flex="0 0 auto"))
        self.symbolic_note = widgets.HTML()
        self.error = ErrorLabel()
        self.widget = widgets.VBox(
            [
                widgets.HBox(
                    [self.style, self.symbolic, self.lengths, self.error.widget],
                    layout=widgets.Layout(flex="0 0 auto", flex_flow="row wrap"),
                ),
                self.symbolic_note,
                widgets.VBox(
                    [self.numeric_text, self.numeric_math, self.symbolic_math],
                    layout=widgets.Layout(overflow="auto", max_height="640px"),
                ),
            ]
        )
        self.visible = True
        self._derivation: Derivation | None = None
        self._robot: Robot | None = None
        self._numeric_shown: tuple[Robot, str] | None = None
        self._symbolic_cache: dict[Any, Derivation] = {}
        self._symbolic_shown: Any = None
        observe(self.style, self.error, lambda _: self._render_numeric())
        observe(self.symbolic, self.error, lambda _: self._render_symbolic())
        observe(self.lengths, self.error, lambda _: self._render_symbolic())

    @property
    def derivation(self) -> Derivation | None:
        """The numeric derivation of the robot shown, computed when first asked for."""
        if self._derivation is None and self._robot is not None:
            self._derivation = derivation(self._robot, precision=self.precision)
        return self._derivation

    @property
    def text(self) -> str:
        """The numeric printout as plain text (what the text view shows)."""
        return "" if self.derivation is None else str(self.derivation)

    def show(self, robot: Robot) -> None:
        """Show the derivation of ``robot`` at its own q (drawn when the tab is showing)."""
        self._robot = robot
        self._derivation = None
        fits = symbolic_fits(robot)
        self.symbolic.disabled = self.lengths.disabled = not fits
        self.symbolic_note.value = "" if fits else too_long_note(self.app)
        # A hidden tab is drawn when it is opened: while a slider is dragged, every message
        # the kernel sends delays the next slider value by a round trip.
        if self.visible:
            self._render_numeric()
            self._render_symbolic()

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)``: ``matrices``."""
        yield "matrices", self.error

    def set_visible(self, visible: bool) -> None:
        """Tell the view whether its tab is showing (it draws only while it is)."""
        self.visible = visible
        if visible:
            self._render_numeric()
        self._render_symbolic()

    def _render_numeric(self) -> None:
        if self.derivation is None or self._robot is None:
            return
        latex = self.style.value == "latex"
        shown = (self._robot, self.style.value)
        if shown == self._numeric_shown:
            return
        self._numeric_shown = shown
        if latex:
            self.numeric_math.value = math_html(self.derivation.latex())
        else:
            self.numeric_text.value = preformatted(str(self.derivation))
        self.numeric_text.layout.display = "none" if latex else None
        self.numeric_math.layout.display = None if latex else "none"

    def _render_symbolic(self) -> None:
        robot = self._robot
        wanted = self.symbolic.value and robot is not None and symbolic_fits(robot)
        self.symbolic_math.layout.display = None if wanted else "none"
        if not wanted or not self.visible:
            return
        assert robot is not None
        key = (robot.with_q(np.zeros(robot.n)), bool(self.lengths.value))
        if key == self._symbolic_shown:
            return
        steps = self._symbolic_cache.get(key)
        if steps is None:
            # Never another structure's matrices, even if this derivation fails.
            self.symbolic_math.value, self._symbolic_shown = "", None
            try:
                steps = derivation(robot, symbolic=True, lengths=bool(self.lengths.value))
            except InvalidInputError as error:
                self.error.show(str(error))
                return
            self._symbolic_cache = {key: steps}  # one structure at a time: bounded memory
        self.error.clear()
        self.symbolic_math.value = math_html(steps.latex())
        self._symbolic_shown = key
