"""Where the panel's parts sit: the 3D view beside the editor when there is room, and
above it, pinned to the top of the notebook's scrolling area, when there is not.

Either way the robot stays in sight while its sliders move. The row wraps (CSS flexbox)
at about 960 px: JupyterLab at 1280 px with its file browser open leaves ~850 px to an
output, so there the view sits above the editor and sticks (``position: sticky``) while
the editor scrolls under it. Pinned, the 3D pane is at most 36 % of the window high
(a CSS container query on the row's width: the row wraps exactly when it is narrower than
editor and view together), so the sliders under it stay in sight too.

``position: sticky`` pins an element inside its nearest scrolling ancestor, and every box
with ``overflow`` other than ``visible`` counts as one: ipywidgets' boxes and JupyterLab's
output area have ``overflow: auto``/``hidden``, which would pin the view inside a box that
never scrolls, i.e. not at all. The panel's stylesheet therefore lets overflow through on
the boxes between the view and the notebook's scroller (only around a robotconf panel).
A box with ``overflow: auto`` also never grows wider than its column (a flex item's
minimum width is then 0, not its content's); with ``visible`` it would, so the same rule
sets ``min-width: 0``: a wide table scrolls in its own box instead of widening the panel
past the notebook's edge.
"""

from __future__ import annotations

from collections.abc import Sequence

import ipywidgets as widgets

__all__ = ["PANEL_CLASS", "VIEW_CLASS", "STYLE", "stylesheet", "view_column", "workspace"]

#: Classes the stylesheet keys on.
PANEL_CLASS, VIEW_CLASS = "robotconf-panel", "robotconf-view"
WORKSPACE_CLASS = "robotconf-workspace"
#: Widths (px) at which the editor and the view start to share a row.
EDITOR_WIDTH, VIEW_WIDTH = 560, 400
#: The 3D pane's height while it is pinned above the editor: the scene's own height, but
#: at most about a third of the window, so the sliders under it keep room to be seen.
PINNED_MAX_HEIGHT = "max(36vh, 220px)"

#: The panel's stylesheet. ``:has`` limits the output-area rules to outputs that hold a
#: panel (JupyterLab and Voilà both use these classes; elsewhere the rules match nothing
#: and the view simply scrolls with the page). The view's opaque background and z-index
#: keep the editor's sliders from showing through while they scroll under it.
STYLE = f"""
.jp-OutputArea:has(.{VIEW_CLASS}), .jp-OutputArea-child:has(.{VIEW_CLASS}),
.jp-OutputArea-output:has(.{VIEW_CLASS}), .{PANEL_CLASS}, .{WORKSPACE_CLASS} {{
  overflow: visible !important; min-width: 0;
}}
.{VIEW_CLASS} {{
  position: sticky; top: 0; z-index: 20; align-self: flex-start;
  background: var(--jp-layout-color0, #fff);
}}
.{WORKSPACE_CLASS} {{ container-type: inline-size; }}
@container (max-width: {EDITOR_WIDTH + VIEW_WIDTH - 0.02}px) {{
  .{VIEW_CLASS} .robotconf-scene {{ max-height: {PINNED_MAX_HEIGHT}; }}
}}
"""


def stylesheet() -> widgets.HTML:
    """A hidden widget that carries :data:`STYLE` onto the page.

    >>> "position: sticky" in stylesheet().value
    True
    """
    # A <style> element applies to the whole page wherever it sits, even inside a hidden box.
    return widgets.HTML(f"<style>{STYLE}</style>", layout=widgets.Layout(display="none"))


def view_column(children: Sequence[widgets.Widget]) -> widgets.VBox:
    """The 3D view's column (the end-effector line and the scene): it sticks.

    >>> VIEW_CLASS in view_column([widgets.HTML("scene")])._dom_classes
    True
    """
    column = widgets.VBox(
        list(children),
        layout=widgets.Layout(flex=f"1 1 {VIEW_WIDTH}px", min_width="0", overflow="visible"),
    )
    column.add_class(VIEW_CLASS)
    return column


def workspace(editor: widgets.Widget, view: widgets.Widget) -> widgets.Box:
    """Editor and view in a row that wraps: editor left and view right when both fit,
    else the view on top (``row-reverse``: the view comes first in the page order, so a
    wrapped row puts it above the editor).

    >>> row = workspace(widgets.HTML("editor"), view_column([widgets.HTML("scene")]))
    >>> row.layout.flex_flow, [c.value for c in row.children[1].children]
    ('row-reverse wrap', ['editor'])
    """
    editor_column = widgets.Box(
        [editor], layout=widgets.Layout(flex=f"1 1 {EDITOR_WIDTH}px", min_width="0")
    )
    row = widgets.Box(
        [view, editor_column],
        layout=widgets.Layout(
            flex_flow="row-reverse wrap", align_items="flex-start", overflow="visible"
        ),
    )
    row.add_class(WORKSPACE_CLASS)
    return row
