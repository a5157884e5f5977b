"""The paper's workflow in the configurator, driven in JupyterLab, and the geometry checks
on what it shows; shared by the layout browser test and docs/screenshots.py.

The workflow: the paper's robot (the panel's default preset), lengths in mm, Simulink's
sawtooth (Repeating Sequence) on q3, Run; then the DVA table, statistics and plot.
"""

from __future__ import annotations

import re
from typing import Any

from .lab_driver import NOTEBOOK, choose, click, wait_idle

#: The Motion tab's result views, a toggle of the results form (not tabs of the panel).
RESULT_VIEWS = {"DVA table": "table", "statistics": "statistics", "plot": "plot"}

#: The notebook in the visible tab (its scrolling area is inside it).
_PANEL = NOTEBOOK.split(" ")[0]
#: The notebook cell that shows the panel.
PANEL_CELL = "import robotconf as rc\n\npanel = rc.configurator(rc.preset('paper'))"

#: Rectangles (left, top, right, bottom) of the ``index``-th element matching a selector,
#: of the notebook's scrolling area and of the output area holding the panel.
RECTS_JS = """([selector, index]) => {
  const box = (e) => { if (!e) return null; const r = e.getBoundingClientRect();
    return [r.left, r.top, r.right, r.bottom]; };
  const notebook = document.querySelector('@NOTEBOOK@');
  const scroller = notebook.querySelector('.jp-WindowedPanel-outer') || notebook;
  const output = document.querySelector('.robotconf-panel').closest('.jp-OutputArea-output');
  return {element: box(document.querySelectorAll(selector)[index]), scroller: box(scroller),
          output: box(output)};
}""".replace("@NOTEBOOK@", _PANEL)

#: Is the element at the centre of the ``index``-th match of a selector that element (or
#: inside it), i.e. not covered by something else?
ON_TOP_JS = """([selector, index]) => {
  const e = document.querySelectorAll(selector)[index]; const r = e.getBoundingClientRect();
  const hit = document.elementFromPoint((r.left + r.right) / 2, (r.top + r.bottom) / 2);
  return !!hit && (e === hit || e.contains(hit));
}"""

#: What cuts off part of the ``index``-th match of a selector horizontally: every
#: ancestor that clips its overflow (not ``visible``) and does not hold all of it, and
#: the window if the element reaches past it. Empty when the element shows whole.
CLIPPED_JS = """([selector, index]) => {
  const e = document.querySelectorAll(selector)[index]; const r = e.getBoundingClientRect();
  const cut = [];
  if (r.width === 0 || r.left < -1 || r.right > window.innerWidth + 1) cut.push('window');
  for (let a = e.parentElement; a; a = a.parentElement) {
    if (getComputedStyle(a).overflowX === 'visible') continue;
    const b = a.getBoundingClientRect();
    if (r.left < b.left - 1 || r.right > b.right + 1) {
      const name = a.className.toString().slice(0, 60);
      cut.push(name + ' ' + [b.left, b.right] + ' vs ' + [r.left, r.right]);
    }
  }
  return cut;
}"""

#: Scroll the notebook by ``delta`` pixels.
SCROLL_JS = """(delta) => {
  const notebook = document.querySelector('@NOTEBOOK@');
  (notebook.querySelector('.jp-WindowedPanel-outer') || notebook).scrollTop += delta;
}""".replace("@NOTEBOOK@", _PANEL)


def dismiss_news(page: Any) -> None:
    """Answer JupyterLab's "notified about news?" toast, which covers the corner."""
    button = page.get_by_role("button", name="No", exact=True)
    if button.count():
        button.first.click()
        page.wait_for_timeout(200)


def show_panel(page: Any) -> None:
    """Run the panel's cell (the notebook's first) and wait for the 3D view."""
    cell = page.locator(f"{NOTEBOOK} .jp-Cell").nth(0)
    cell.locator(".jp-InputPrompt").click()
    page.keyboard.press("Shift+Enter")
    page.wait_for_selector("[data-robotconf-scene='ready']", timeout=90_000)
    page.wait_for_timeout(800)


def choose_tab(page: Any, title: str) -> None:
    """Show the panel's tab called ``title``, or the Motion tab's result view of that
    name ("DVA table", "statistics", "plot")."""
    # A tab clicked while the kernel still works on a form's event can be lost (see
    # test_panel_state_browser.py): a student waits for the last answer, so do we.
    wait_idle(page)
    if title in RESULT_VIEWS:
        choose(page, "results.view", title)
    else:
        tab = page.locator(".jupyter-widget-TabPanel .lm-TabBar-tab").filter(
            has_text=re.compile(f"^{re.escape(title)}$")
        )
        tab.first.click()
    page.wait_for_timeout(400)
    wait_idle(page)


def choose_length_unit(page: Any, length_unit: str) -> None:
    """Pick the panel's length unit in the header row."""
    choose(page, "length_unit", length_unit)
    page.wait_for_timeout(300)


def run_paper_workflow(page: Any, length_unit: str = "mm") -> None:
    """Lengths in ``length_unit``, the sawtooth on q3, Run; waits for the DVA table."""
    choose_length_unit(page, length_unit)
    choose_tab(page, "Motion")
    choose(page, "signals.q3", "RepeatingSequence")
    page.wait_for_timeout(300)
    click(page, "run")
    page.wait_for_selector(".robotconf-results-table table", timeout=60_000)
    page.wait_for_timeout(300)


def wait_for_plot(page: Any) -> None:
    """Wait until the DVA figure has arrived and been laid out."""
    page.wait_for_function(
        "() => { const i = document.querySelector('img.robotconf-results-plot');"
        " return i && i.complete && i.naturalWidth > 0 && i.getBoundingClientRect().width > 0; }",
        timeout=60_000,
    )
    page.wait_for_timeout(300)


def rects(page: Any, selector: str, index: int = 0) -> dict[str, list[float] | None]:
    """``{"element", "scroller", "output"}`` rectangles (see :data:`RECTS_JS`)."""
    return page.evaluate(RECTS_JS, [selector, index])  # type: ignore[no-any-return]


def clipped(page: Any, selector: str, index: int = 0) -> list[str]:
    """What hides part of that element's width (see :data:`CLIPPED_JS`); ``[]`` if nothing."""
    return page.evaluate(CLIPPED_JS, [selector, index])  # type: ignore[no-any-return]


def on_top(page: Any, selector: str, index: int = 0) -> bool:
    """Whether the centre of that element is not covered by another (see :data:`ON_TOP_JS`)."""
    return bool(page.evaluate(ON_TOP_JS, [selector, index]))
