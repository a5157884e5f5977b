"""The Denavit–Hartenberg table editor: rows θ, d, a, α, joint type, and the convention."""

from __future__ import annotations

import dataclasses
import functools
import html
from collections.abc import Callable, Iterator, Sequence
from typing import Any

import ipywidgets as widgets

from .._errors import InvalidInputError
from .._validation import check_finite_number
from ..kinematics import (
    DH_CONVENTIONS,
    DH_FACTORS,
    DH_PARAMETERS,
    DH_SYMBOLS,
    JOINT_LETTERS,
    JOINT_OF_LETTER,
    JOINT_UNITS,
    ROTATION_KINDS,
    DHLink,
    dh_formula,
)
from ._callbacks import observe, on_click
from ._choice_prompt import ChoicePrompt
from ._errors_display import ErrorLabel
from ._number_control import NumberControl
from ._ranges import length_step, q_display, q_range
from ._row_list import ChangeCallback, RowList

__all__ = ["DHTable", "DHRow"]

#: Where each convention comes from, and how its rows are read.
_CONVENTION_SOURCES = {
    "standard": ("paper eq. 9", ""),
    "modified": ("Craig", "; row i holds α(i-1), a(i-1)"),
}
_CONVENTION_TIPS = {
    name: f"{name} ({source}): A = {dh_formula(name)}{reading}"
    for name, (source, reading) in _CONVENTION_SOURCES.items()
}
#: The DH parameters that are angles (those of the rotation factors): θ and α.
_ANGLES = frozenset(name for kind, name in DH_FACTORS["standard"] if kind in ROTATION_KINDS)


def _empty_table_message() -> str:
    """The core's own message for a DH table without rows."""
    from ..kinematics import Robot

    try:
        Robot.from_dh([])
    except InvalidInputError as error:
        return str(error)
    raise AssertionError("Robot.from_dh([]) must refuse an empty table")  # pragma: no cover


class DHRow:
    """One DH row: θ, d, a, α boxes, joint type R/P, and its coordinate q."""

    FIELDS = DH_PARAMETERS

    def __init__(
        self,
        link: DHLink,
        scale: float,
        degrees: bool,
        limits: Any,
        on_change: Callable[[str], None],
        on_action: Callable[[DHRow, str], None],
    ):
        self._base = link
        self._scale = scale
        self._on_change = on_change
        self.title = widgets.HTML(layout=widgets.Layout(width="30px"))
        self.error = ErrorLabel()
        self.cells = {
            name: NumberControl(
                DH_SYMBOLS[name],
                getattr(link, name),
                -scale,
                scale,
                angle=name in _ANGLES,
                degrees=degrees,
                slider=False,
                on_change=lambda _: on_change("link"),
                label_width="14px",
                length_step=length_step(scale),
            )
            for name in self.FIELDS
        }
        self.joint = widgets.Dropdown(
            options=tuple((letter, letter) for letter in JOINT_LETTERS.values()),
            value=link.joint,
            tooltip="R: q adds to θ (revolute); P: q adds to d (prismatic)",
            layout=widgets.Layout(width="52px"),
        )
        observe(self.joint, self.error, self._joint_changed)
        lo, hi = q_range(link.unit, scale, limits, degrees)
        angle, label = q_display(link.unit)
        self.q = NumberControl(
            "q",
            link.q,
            lo,
            hi,
            angle=angle,
            degrees=degrees,
            unit=label,
            on_change=lambda _: on_change("q"),
            label_width="16px",
            length_step=length_step(scale),
        )
        buttons = []
        for icon, action in (("arrow-up", "up"), ("arrow-down", "down"), ("trash", "remove")):
            button = widgets.Button(icon=icon, layout=widgets.Layout(width="32px"))
            on_click(button, self.error, functools.partial(on_action, self, action))
            buttons.append(button)
        self.up_button, self.down_button, self.remove_button = buttons
        cells = [c.widget for c in self.cells.values()]
        self.widget = widgets.VBox(
            [
                widgets.HBox(
                    [self.title, *cells, self.joint, *buttons, self.error.widget],
                    layout=widgets.Layout(flex_flow="row wrap", align_items="center"),
                ),
                self.q.widget,
            ],
            layout=widgets.Layout(border="1px solid #ddd", padding="2px 4px", margin="2px 0"),
        )
        for cell in self.cells.values():
            cell.box.layout.width = "70px"
            cell.unit_label.layout.width = "28px"

    def set_title(self, index: int, count: int) -> None:
        """Label the row with its link number and enable sensible move buttons."""
        self.title.value = f"<b>{index + 1}</b>"
        self.up_button.disabled = index == 0
        self.down_button.disabled = index == count - 1

    def controls(self) -> Iterator[tuple[str, NumberControl]]:
        """``(field, control)`` for θ, d, a, α and q."""
        yield from self.cells.items()
        yield "q", self.q

    def set_degrees(self, degrees: bool) -> None:
        """Show θ, α and a revolute q in degrees or radians."""
        for _, control in self.controls():
            control.set_degrees(degrees)

    def link(self, convention: str) -> DHLink | None:
        """The DH link of this row, or ``None`` after showing why it is invalid."""
        valid = True
        for field, control in self.controls():
            try:
                check_finite_number(control.core_value, field)
                control.error.clear()
            except InvalidInputError as error:
                control.error.show(str(error))
                valid = False
        if not valid:
            return None
        values: dict[str, Any] = {field: c.core_value for field, c in self.controls()}
        values.update(joint=self.joint.value, convention=convention)
        if self.joint.value != self._base.joint:
            values["limits"] = None  # radians do not become lengths
        try:
            link = dataclasses.replace(self._base, **values)
        except InvalidInputError as error:
            self.error.show(str(error))
            return None
        self.error.clear()
        return link

    def _joint_changed(self, change: dict[str, Any]) -> None:
        unit = JOINT_UNITS[JOINT_OF_LETTER[change["new"]]]
        lo, hi = q_range(unit, self._scale, None, self.q.degrees)
        angle, label = q_display(unit)
        self.q.set_angle(angle, lo, hi, unit=label)
        self._on_change("link")


class DHTable(RowList):
    """DH-table mode: rows, add button and the standard/modified selector.

    Choosing the other convention asks first, in a row under the selector: **convert
    (same robot)** hands the convention to ``on_convert`` (the panel converts the robot
    with the core's ``convert_dh``); **reinterpret (same numbers)** keeps every number
    and reads the rows in the other convention (another robot).

    Parameters
    ----------
    on_change : callable
        ``on_change(reason, order)`` after every user edit.
    on_convert : callable, optional
        ``on_convert(convention)`` for "convert (same robot)"; without it that answer
        is disabled.

    Examples
    --------
    >>> import robotconf as rc
    >>> table = DHTable(lambda reason, order: None)
    >>> table.load([rc.DHLink(a=1.0), rc.DHLink(a=1.0)], scale=2.0)
    >>> table.convention.value = "modified"  # asks: convert or reinterpret?
    >>> table.convention.value, table.convention_prompt.visible
    ('standard', True)
    >>> table.convention_prompt.buttons["reinterpret"].click()
    >>> {link.convention for link in table.links()}
    {'modified'}
    """

    def __init__(self, on_change: ChangeCallback, on_convert: Callable[[str], None] | None = None):
        super().__init__(on_change, widgets.Button(description="add row", icon="plus"))
        self._on_convert = on_convert
        self._pending_convention = ""
        self.convention = widgets.ToggleButtons(
            options=DH_CONVENTIONS,
            value="standard",
            description="convention",
            tooltips=[_CONVENTION_TIPS[name] for name in DH_CONVENTIONS],
            style={"button_width": "90px"},
        )
        self.convention_note = widgets.HTML()
        self.convention_error = ErrorLabel()
        self._convention_handler = observe(
            self.convention, self.convention_error, self._convention_changed
        )
        self.convention_prompt = ChoicePrompt(
            [
                (
                    "convert",
                    "convert (same robot)",
                    "rewrite the rows so that every frame and the end-effector stay put",
                ),
                (
                    "reinterpret",
                    "reinterpret (same numbers)",
                    "keep every number and read the rows in the other convention",
                ),
            ],
            self._convention_answered,
        )
        self.convention_prompt.buttons["convert"].disabled = on_convert is None
        self.widget = widgets.VBox(
            [
                widgets.HBox([self.convention, self.convention_error.widget]),
                self.convention_prompt.widget,
                self.convention_note,
                self._rows_box,
                widgets.HBox([self.add_button, self.error.widget]),
            ]
        )
        self._show_note()

    def _show_note(self) -> None:
        tip = _CONVENTION_TIPS[self.convention.value]
        self.convention_note.value = f"<small>{html.escape(tip)}</small>"

    def _row(self, link: DHLink, limits: Any = None) -> DHRow:
        return DHRow(link, self._scale, self.degrees, limits, self._row_changed, self._action)

    def load(
        self,
        links: Sequence[DHLink],
        scale: float,
        degrees: bool | None = None,
        limits: Any = None,
    ) -> None:
        """Replace the rows (no change callback); the convention is the first link's.

        ``limits`` is an (n, 2) array of joint limits in core units, or ``None``.
        """
        self.convention_prompt.close()
        if links:
            self._set_convention(links[0].convention)
        self._load_rows(links, scale, degrees, limits)

    def links(self) -> list[DHLink] | None:
        """The rows as DH links in the selected convention, or ``None`` if one is invalid."""
        if not self.rows:
            self.error.show(_empty_table_message())
            return None
        links = [row.link(self.convention.value) for row in self.rows]
        if any(link is None for link in links):
            return None
        self.error.clear()
        return links  # type: ignore[return-value]

    def error_items(self) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)`` pairs: ``dh`` and ``dh[i].<field>``."""
        yield "dh", self.error
        yield "dh.convention", self.convention_error
        yield "dh.convention.convert", self.convention_prompt.error
        for i, row in enumerate(self.rows):
            yield f"dh[{i}]", row.error
            for field, control in row.controls():
                yield f"dh[{i}].{field}", control.error

    def _new_link(self) -> DHLink:
        # Revolute, with a = a tenth of the slider range so the new link is visible.
        return DHLink(a=self._scale / 10.0, convention=self.convention.value)

    def _last_row_message(self) -> str:
        return _empty_table_message()

    def _row_changed(self, reason: str) -> None:
        self._on_change(reason, None)

    def _set_convention(self, convention: str) -> None:
        with self._convention_handler.paused():
            self.convention.value = convention
        self._show_note()

    def _convention_changed(self, change: dict[str, Any]) -> None:
        # The selector shows the table's convention until the user says what switching means.
        self._pending_convention = change["new"]
        self._set_convention(change["old"])
        self.convention_prompt.ask(f"Switch the table to {change['new']} DH:")

    def _convention_answered(self, answer: str) -> None:
        convention = self._pending_convention
        if answer == "convert" and self._on_convert is not None:
            self._on_convert(convention)  # the panel loads the converted robot
            return
        self._set_convention(convention)
        self._on_change("link", None)
