"""One row of the module list: movement type, offsets ax, ay, az and coordinate q."""

from __future__ import annotations

import functools
import html
from collections.abc import Callable, Iterator
from typing import Any

import ipywidgets as widgets

from .._errors import InvalidInputError
from .._validation import check_finite_number
from ..kinematics import (
    JOINT_UNITS,
    MODULE_KINDS,
    MODULE_OFFSETS,
    Link,
    Module,
    kind_joint_type,
    kind_label,
)
from ._callbacks import observe, on_click
from ._errors_display import ErrorLabel
from ._number_control import NumberControl
from ._ranges import length_step, q_display, q_range

__all__ = ["ModuleRow", "KIND_OPTIONS"]

#: Dropdown entries: the paper's codes 0–6 with names, then ``fixed`` (no code).
KIND_OPTIONS = tuple((kind_label(kind), kind) for kind in MODULE_KINDS)


def _unit(kind: str) -> str:
    """The unit of a movement type's coordinate: ``rad``, ``length`` or none."""
    return JOINT_UNITS[kind_joint_type(kind)]


def _button(icon: str, tooltip: str) -> widgets.Button:
    return widgets.Button(icon=icon, tooltip=tooltip, layout=widgets.Layout(width="32px"))


class ModuleRow:
    """Controls for one link of the chain.

    A :class:`~robotconf.Module` gets a type dropdown and ax, ay, az, q controls; any
    other link (a DH row inside a mixed robot) is shown read-only with its q control.

    Parameters
    ----------
    link : Link
        The link to show.
    scale : float
        Half-range of the length sliders.
    degrees : bool
        Show angles in degrees.
    limits : (lo, hi) or None
        Joint limits in core units for the q slider's default range.
    on_change : callable
        Called with ``(row, reason)`` after a user change; reason ``"q"`` or ``"link"``.
    on_action : callable
        Called with ``(row, action)`` for ``"up"``, ``"down"`` and ``"remove"``.

    Examples
    --------
    >>> import robotconf as rc
    >>> row = ModuleRow(rc.Module("Ry", a=(0, 0, 20)), 100.0, True, None, print, print)
    >>> row.kind.options[2]
    ('2 Ry', 'Ry')
    >>> row.link()
    Module('Ry', a=(0.0, 0.0, 20.0))
    """

    def __init__(
        self,
        link: Link,
        scale: float,
        degrees: bool,
        limits: Any,
        on_change: Callable[[ModuleRow, str], None],
        on_action: Callable[[ModuleRow, str], None],
    ):
        self._base = link
        # A module is edited field by field; any other link (a DH row) only through its q.
        self._module: Module | None = link if isinstance(link, Module) else None
        self._scale = scale
        self._on_change = on_change
        self.is_module = self._module is not None
        self.title = widgets.HTML(layout=widgets.Layout(width="36px"))
        self.error = ErrorLabel()
        self.up_button = _button("arrow-up", "move this module up (towards the base)")
        self.down_button = _button("arrow-down", "move this module down (towards the tool)")
        self.remove_button = _button("trash", "remove this module")
        for button, action in (
            (self.up_button, "up"),
            (self.down_button, "down"),
            (self.remove_button, "remove"),
        ):
            on_click(button, self.error, functools.partial(on_action, self, action))
        self.kind = widgets.Dropdown(
            options=KIND_OPTIONS,
            value="none" if self._module is None else self._module.kind,
            description="type",
            layout=widgets.Layout(width="150px"),
            style={"description_width": "34px"},
        )
        a = (0.0, 0.0, 0.0) if self._module is None else self._module.a
        self.offsets = tuple(
            NumberControl(
                name,
                value,
                -scale,
                scale,
                unit="",
                on_change=self._link_changed,
                label_width="24px",
                length_step=length_step(scale),
            )
            for name, value in zip(MODULE_OFFSETS, a, strict=True)
        )
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
            on_change=self._q_changed,
            label_width="24px",
            length_step=length_step(scale),
        )
        # Stable hooks for browser tests and for instructors' custom CSS.
        self.kind.add_class("robotconf-module-kind")
        self.q.slider.add_class("robotconf-module-q")
        self.remove_button.add_class("robotconf-module-delete")
        for control in self.offsets:
            control.box.add_class("robotconf-module-offset")
        observe(self.kind, self.error, self._kind_changed)
        buttons = [self.up_button, self.down_button, self.remove_button]
        if self.is_module:
            head = [self.title, self.kind, *buttons, self.error.widget]
            controls = [*(c.widget for c in self.offsets), self.q.widget]
        else:
            # The repr holds the link's name, which comes from a file: text, never markup.
            summary = widgets.HTML(f"<code>{html.escape(repr(link))}</code>")
            head = [self.title, summary, *buttons, self.error.widget]
            controls = [self.q.widget]
        wrap = widgets.Layout(flex_flow="row wrap")
        self.widget = widgets.VBox(
            [
                widgets.HBox(head, layout=widgets.Layout(align_items="center")),
                widgets.HBox(controls, layout=wrap),
            ],
            layout=widgets.Layout(border="1px solid #ddd", padding="2px 4px", margin="2px 0"),
        )
        self._update_disabled()

    # -- state --------------------------------------------------------------------------

    def set_title(self, index: int, count: int) -> None:
        """Label the row ``M{index + 1}`` and enable the move buttons that make sense."""
        self.title.value = f"<b>M{index + 1}</b>"
        self.up_button.disabled = index == 0
        self.down_button.disabled = index == count - 1

    def controls(self) -> Iterator[tuple[str, NumberControl]]:
        """``(field, control)`` for the number controls of this row."""
        if self.is_module:
            yield from zip(MODULE_OFFSETS, self.offsets, strict=True)
        yield "q", self.q

    def error_items(self, prefix: str) -> Iterator[tuple[str, ErrorLabel]]:
        """``(key, label)`` for every error label, keys like ``modules[1].ax``."""
        yield prefix, self.error
        for field, control in self.controls():
            yield f"{prefix}.{field}", control.error

    def set_degrees(self, degrees: bool) -> None:
        """Show the angle coordinate in degrees or radians."""
        self.q.set_degrees(degrees)

    def link(self) -> Link | None:
        """The link the controls describe, or ``None`` after showing why it is invalid."""
        valid = True
        for field, control in self.controls():
            try:
                check_finite_number(control.core_value, field)
            except InvalidInputError as error:
                control.error.show(str(error))
                valid = False
            else:
                control.error.clear()
        if not valid:
            return None
        q = self.q.core_value
        try:
            if not self.is_module:
                link = self._base.with_q(q)
            else:
                a = tuple(c.core_value for c in self.offsets)
                link = self._changed_module(self.kind.value, a, q)
        except InvalidInputError as error:
            self.error.show(str(error))
            return None
        self.error.clear()
        return link

    def _changed_module(self, kind: str, a: tuple[float, ...], q: float) -> Module:
        assert self._module is not None  # only module rows have a kind and offsets
        # The core's with_kind keeps name and limits (dropping limits across joint types).
        return self._module.with_kind(kind).with_a(a).with_q(q)

    # -- events -------------------------------------------------------------------------

    def _update_disabled(self) -> None:
        kind = self.kind.value if self.is_module else "joint"
        for control in self.offsets:
            control.disable(kind == "none")
        self.q.disable(kind in ("none", "fixed"))

    def _kind_changed(self, change: dict[str, Any]) -> None:
        old, new = _unit(change["old"]), _unit(change["new"])
        if old != new and new:
            lo, hi = q_range(new, self._scale, None, self.q.degrees)
            angle, label = q_display(new)
            self.q.set_angle(angle, lo, hi, unit=label)
        self._update_disabled()
        self._on_change(self, "link")

    def _link_changed(self, _: NumberControl) -> None:
        self._on_change(self, "link")

    def _q_changed(self, _: NumberControl) -> None:
        self._on_change(self, "q")
