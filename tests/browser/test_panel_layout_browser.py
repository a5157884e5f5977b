"""The configurator's layout in JupyterLab at 1280 × 900 (file browser open) and at
1920 × 1080: nothing cut off, the robot in sight while its sliders move.

Checked on the paper's workflow (the paper's robot, lengths in mm, the sawtooth on q3,
Run): the 3D view and the last q slider are both in the viewport once the sliders are
scrolled into it, the view pinned above the editor (sticky) or beside it; the DVA figure,
the DVA table's box and the statistics fit inside the output area; the Matrices tab shows
its controls; the table's headers carry the unit and the EE starts at x = 70 mm.
"""

from __future__ import annotations

import re

from .conftest import Lab
from .lab_driver import NOTEBOOK, choose, control, open_notebook, write_notebook
from .paper_workflow import (
    PANEL_CELL,
    SCROLL_JS,
    choose_tab,
    clipped,
    dismiss_news,
    on_top,
    rects,
    run_paper_workflow,
    show_panel,
    wait_for_plot,
)

#: The q controls of the module list (module 3's is the last).
SLIDER = ".rc-control.robotconf-module-q"


def _inside(inner: list[float], outer: list[float], tolerance: float = 1.0) -> bool:
    """Whether rectangle ``inner`` lies in ``outer`` (both left, top, right, bottom)."""
    return (
        inner[0] >= outer[0] - tolerance
        and inner[1] >= outer[1] - tolerance
        and inner[2] <= outer[2] + tolerance
        and inner[3] <= outer[3] + tolerance
    )


def _view_and_slider_in_sight(page) -> str:  # type: ignore[no-untyped-def]
    """Scroll the last q slider to just below where the pinned 3D view ends; assert that
    the slider and the whole view are in sight, the slider uncovered; return how the view
    sits ("above": pinned to the top of the notebook's visible area, or "beside")."""
    found = rects(page, SLIDER, 2)
    view = rects(page, ".robotconf-view")["element"]
    assert found["element"] is not None and found["scroller"] is not None and view is not None
    # Far enough that a view scrolling with the page would be gone above the top.
    target = found["scroller"][1] + (view[3] - view[1]) + 24
    page.evaluate(SCROLL_JS, found["element"][1] - target)
    page.wait_for_timeout(500)
    found = rects(page, SLIDER, 2)
    slider, scroller = found["element"], found["scroller"]
    view = rects(page, ".robotconf-view")["element"]
    canvas = rects(page, "[data-robotconf-scene] canvas")["element"]
    assert slider is not None and scroller is not None and view is not None and canvas
    assert _inside(slider, scroller), (slider, scroller)
    assert _inside(canvas, scroller), ("3D view out of sight", canvas, scroller)
    assert on_top(page, f"{SLIDER} input.rc-slider", 2), "the view covers the q3 slider"
    if view[0] >= slider[2] - 1:
        return "beside"
    assert abs(view[1] - scroller[1]) <= 2, ("the view does not stick", view, scroller)
    return "above"


def _results_fit(page) -> None:  # type: ignore[no-untyped-def]
    """The DVA figure, the table's box and the statistics show whole in the output area."""
    choose_tab(page, "DVA table")
    assert clipped(page, ".robotconf-result") == []
    choose_tab(page, "statistics")
    assert clipped(page, ".robotconf-results-stats table") == []
    choose_tab(page, "plot")
    wait_for_plot(page)
    assert clipped(page, "img.robotconf-results-plot") == []
    figure, output = (
        rects(page, "img.robotconf-results-plot")["element"],
        rects(page, "x")["output"],
    )
    assert figure is not None and output is not None
    assert figure[2] <= output[2] + 1, ("DVA figure past the output area", figure, output)
    # Scaled as a whole, never cropped: the shown picture keeps the figure's proportions.
    natural = page.evaluate(
        "() => { const i = document.querySelector('img.robotconf-results-plot');"
        " return [i.naturalWidth, i.naturalHeight]; }"
    )
    shown = (figure[2] - figure[0], figure[3] - figure[1])
    assert abs(shown[0] / shown[1] - natural[0] / natural[1]) < 0.02, (shown, natural)


def test_paper_workflow_fits_and_keeps_the_robot_in_sight(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    write_notebook(lab.root / "layout.ipynb", [PANEL_CELL])
    open_notebook(page, lab.url("layout.ipynb"))
    dismiss_news(page)
    show_panel(page)

    # 1280 × 900 with the file browser open leaves ~850 px: the view sits above the
    # editor and sticks to the top while the sliders scroll under it.
    assert _view_and_slider_in_sight(page) == "above"

    run_paper_workflow(page, "mm")
    table = page.locator(".robotconf-results-table table").first
    headers = table.locator("thead").inner_text()
    assert "position [mm]" in headers and "acceleration [mm/s²]" in headers
    assert "angular velocity [deg/s]" in headers
    first_row = table.locator("tbody tr").first.locator("td").all_inner_texts()
    assert first_row[:4] == ["0", "70", "0", "20"]  # t, then the EE's x, y, z
    _results_fit(page)

    # The Matrices tab shows its controls for the paper's three modules.
    choose_tab(page, "Matrices")
    matrices = page.locator(".robotconf-matrices-tab")
    assert re.search(r"\bA3\b", matrices.inner_text()) and "A4" not in matrices.inner_text()
    controls = [
        *matrices.locator(".rc-toggle button.rc-choice").all(),
        *matrices.locator(".rc-check input").all(),
    ]
    assert len(controls) == 4
    for shown in controls:
        box = shown.bounding_box()
        assert box is not None and box["width"] > 0 and box["height"] > 0

    # 1920 × 1080: the view beside the editor, the results still whole.
    page.set_viewport_size({"width": 1920, "height": 1080})
    page.wait_for_timeout(1000)
    choose_tab(page, "Motion")
    assert _view_and_slider_in_sight(page) == "beside"
    _results_fit(page)
    assert not page.errors, page.errors


def test_a_sequence_row_keeps_its_title_and_its_table_heading(lab: Lab, page) -> None:  # type: ignore[no-untyped-def]
    write_notebook(lab.root / "titles.ipynb", [PANEL_CELL])
    open_notebook(page, lab.url("titles.ipynb"))
    dismiss_news(page)
    show_panel(page)
    choose(page, "signals.q3", "RepeatingSequence")
    control(page, "signals.q3.table.t1").wait_for(timeout=30_000)
    page.wait_for_timeout(500)
    lines = page.locator(f'{NOTEBOOK} .rc-row[data-key="signals.q3.row"] .rc-line')
    assert lines.nth(0).inner_text().startswith("q3 [deg]"), lines.all_inner_texts()
    assert re.sub(r"\s+", " ", lines.nth(1).inner_text()) == "time [s] value [deg]"
