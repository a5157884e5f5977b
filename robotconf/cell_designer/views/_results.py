"""What the last Run found, as lines of the Programs tab: under each move its violations
and contacts (the core's sentences, times stated), and the run's summary under Run.

The sentences are the core's (:class:`~robotconf.cell.Contact` and
:class:`~robotconf.programs.Violation` messages) in the designer's units. A run of an
older document is not shown move by move: the summary says it is stale.
"""

from __future__ import annotations

from typing import Any

from ...panel.form import text
from ...panel.state import in_units
from ..state import DesignerState
from ._messages import Messages

__all__ = ["run_lines", "move_notes", "CONTACT_CLASS"]

#: The class of a contact's line (browser tests find it).
CONTACT_CLASS = "robotconf-cell-contact"


def _current(state: DesignerState) -> Any:
    run = state.run
    return None if run is None or run.stale(state.document) else run.run


def run_lines(state: DesignerState) -> list[list[dict[str, Any]]]:
    """The summary under Run: the cycle time, each robot's violations, the contacts that
    no move of a program causes, and the least clearance; or why there is none.

    >>> run_lines(DesignerState())[0][0]["value"][:15]
    'Run plans every'
    """
    if state.run is None:
        return [
            [
                text(
                    "Run plans every robot's program in the cell and checks every contact.",
                    tone="note",
                )
            ]
        ]
    run = _current(state)
    if run is None:
        return [
            [
                text(
                    "The cell or a program changed since this run: press Run.",
                    tone="warning",
                    key="run.stale",
                    css_class="robotconf-cell-stale",
                )
            ]
        ]
    units = state.units
    durations = ", ".join(f"{name}: {p.duration:.3g} s" for name, p in run.programs.items())
    lines = [
        [
            text(
                f"cycle time {run.cycle_time:.3g} s ({durations})",
                tone="title",
                key="run.cycle",
                css_class="robotconf-cell-cycle",
            )
        ]
    ]
    for name, report in run.reports.items():
        count = len(report.violations)
        tone = "warning" if count else "ok"
        said = f"{count} violation(s), listed under their moves" if count else "no violation"
        lines.append([text(f"{name}: {said}", tone=tone)])
    check = run.check
    contacts = len(check.contacts) + check.more
    if contacts:
        lines.append(
            [text(f"{contacts} contact(s), listed under the moves that cause them", tone="error")]
        )
    else:
        lines.append([text("no contact", tone="ok")])
    for contact in check.contacts:
        if contact.move is None or contact.robot not in run.programs:
            lines.append(
                [text(in_units(contact.message, units), tone="error", css_class=CONTACT_CLASS)]
            )
    if check.more:
        lines.append([text(f"… and {check.more} more contact intervals", tone="error")])
    sentences = check.sentences
    if sentences and sentences[-1].startswith("least clearance"):
        lines.append([text(in_units(sentences[-1], units), tone="note")])
    return lines


def move_notes(
    state: DesignerState, robot: str, index: int, key: str, messages: Messages
) -> list[list[dict[str, Any]]]:
    """Lines under move ``index`` of ``robot``: Run's refusal naming it, the violations
    it causes and its contacts (the last run's, while it is current)."""
    lines = []
    refusal = messages.text("run")
    if refusal.startswith(f"programs[{robot!r}].moves[{index}]"):
        lines.append([text(refusal, tone="error", key=f"{key}.refusal")])
    run = _current(state)
    if run is None:
        return lines
    units = state.units
    report = run.reports.get(robot)
    for violation in report.violations if report is not None else ():
        if violation.move == index:
            lines.append([text(in_units(violation.message, units), tone="warning")])
    for contact in run.check.contacts:
        if contact.robot == robot and contact.move == index + 1:
            lines.append(
                [text(in_units(contact.message, units), tone="error", css_class=CONTACT_CLASS)]
            )
    return lines
