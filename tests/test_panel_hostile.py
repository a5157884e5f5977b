"""Hostile names never become markup: every string the panel sends to the page is walked.

A robot file can name the robot, its modules and DH links anything (up to 200 characters),
and the uploaded file has a name of its own. The panel is driven through every part that
shows those strings (module list, DH table, wizard, matrices as text, LaTeX and symbolic,
motion run, table and CSV, save and load, error paths), then every widget is walked
recursively and each string is checked the way the browser will treat it:

- an HTML widget's value (and HTMLMath's, and an Output's ``text/html``) is parsed: no
  element or attribute may come from a hostile string, yet the hostile text must be
  visible as text;
- HTMLMath is typeset by MathJax: a ``$`` inside it must be the core's escaped ``\\$``;
- labels and descriptions are typeset too: no user text may reach them;
- dropdown options and tab titles are set as text by ipywidgets: raw text is fine there.
"""

from __future__ import annotations

import datetime
import html
import json
import re
from collections.abc import Iterator
from html.parser import HTMLParser
from typing import Any

import ipywidgets as widgets
import pytest

import robotconf as rc
from robotconf import signals
from robotconf.panel import actions as act
from robotconf.panel.form import Form, link, row

from .test_panel_support import make_panel, shown, ui

IMG = "<img src=x onerror=alert(1)>"
SCRIPT = "<script>alert(2)</script>"
SVG = '"><svg onload=alert(3)>'
MATH = "$\\alpha$ & $$x$$"
ENTITY = "&amp; &lt;b&gt;"
ROBOT_NAME = f"{IMG} {MATH} {ENTITY}"
MODULE_NAMES = (IMG, f"{SCRIPT} {ENTITY}", f"{SVG} {MATH}")
DH_NAME = f"{SCRIPT}{IMG}"
FILE_NAME = f'{SVG}{IMG}".json'
HOSTILE = (IMG, SCRIPT, SVG, MATH, ENTITY)
#: Elements that the hostile strings would create if they reached the page as markup.
FORBIDDEN_TAGS = {"img", "script", "svg"}
NOW = datetime.datetime(2026, 1, 1, tzinfo=datetime.timezone.utc)


def hostile_robot() -> rc.Robot:
    return rc.Robot(
        [
            rc.Module("Rz", name=MODULE_NAMES[0]),
            rc.DHLink(a=10.0, alpha=0.0, name=DH_NAME),
            rc.Module("Ry", a=(0, 0, 20), name=MODULE_NAMES[1]),
            rc.Module("Ry", a=(30, 0, 0), name=MODULE_NAMES[2]),
        ],
        end_effector=(40, 0, 0),
        name=ROBOT_NAME,
    )


def hostile_file() -> bytes:
    # Signals keyed by the modules' own (hostile) names, as a file may do.
    setup = {
        MODULE_NAMES[0]: signals.Sine(amplitude=0.5),
        MODULE_NAMES[2]: signals.Ramp(),
    }
    text = hostile_robot().to_json(signals=setup, simulation={"t_end": 1.0, "dt": 0.25})
    return text.encode("utf-8")


def upload(panel: Any, content: bytes, name: str = FILE_NAME) -> None:
    entry = {"name": name, "type": "application/json", "size": len(content)}
    panel.files.upload.value = ({**entry, "content": memoryview(content), "last_modified": NOW},)


# -- walking the widgets --------------------------------------------------------------------


class _Markup(HTMLParser):
    """The elements, attributes and visible text of an HTML fragment, as a browser sees it."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.tags: list[str] = []
        self.attributes: list[str] = []
        self.text: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append(tag)
        self.attributes.extend(name for name, _ in attrs)
        self.text.extend(value or "" for _, value in attrs)  # download="…" shows as a name

    def handle_data(self, data: str) -> None:
        self.text.append(data)


def _children(widget: widgets.Widget) -> Iterator[widgets.Widget]:
    """The widgets a widget's synced traits refer to (children, layout, style …)."""
    for trait in widget.keys:
        value = getattr(widget, trait)
        items = value if isinstance(value, (list, tuple)) else [value]
        yield from (item for item in items if isinstance(item, widgets.Widget))


def walk(root: widgets.Widget) -> Iterator[widgets.Widget]:
    """Every widget reachable from ``root`` (children, tabs, layouts, outputs' widgets)."""
    seen: set[str] = set()
    stack = [root]
    while stack:
        widget = stack.pop()
        if widget.model_id in seen:
            continue
        seen.add(widget.model_id)
        yield widget
        stack.extend(_children(widget))


def strings(root: widgets.Widget) -> Iterator[tuple[str, str, str]]:
    """``(how the page treats it, where, text)`` for every string sent to the page."""
    for widget in walk(root):
        where = f"{type(widget).__name__}"
        state = widget.get_state()
        for trait, value in state.items():
            if trait == "_spec_json":  # a form's spec, sent as JSON text
                value = json.loads(value)
            elif trait.startswith("_") and trait not in ("_options_labels", "_titles"):
                continue
            if isinstance(value, dict):  # a form's spec: the page writes it as text
                yield from _spec_strings(value, f"{where}.{trait}")
                continue
            values = value if isinstance(value, (list, tuple)) else [value]
            for text in values:
                if not isinstance(text, str) or text.startswith("IPY_MODEL_"):
                    continue
                yield _treatment(widget, trait), f"{where}.{trait}", text
        if isinstance(widget, widgets.Output):
            for output in widget.outputs:
                data = output.get("data", {})
                if "text/html" in data:
                    yield "html", f"{where}.outputs", data["text/html"]
                if "text/plain" in data:
                    yield "text", f"{where}.outputs", data["text/plain"]


def _spec_strings(value: Any, where: str) -> Iterator[tuple[str, str, str]]:
    """Strings of a form's spec: text (the page sets ``textContent``), except the ``src``
    of a picture and the ``href`` of a download, which must be data the kernel made."""
    if isinstance(value, dict):
        for key, item in value.items():
            if key in ("src", "href"):
                assert isinstance(item, str) and item.startswith("data:"), (where, item)
                continue
            yield from _spec_strings(item, f"{where}.{key}")
    elif isinstance(value, (list, tuple)):
        for item in value:
            yield from _spec_strings(item, where)
    elif isinstance(value, str):
        yield "text", where, value


def _treatment(widget: widgets.Widget, trait: str) -> str:
    if trait == "value" and isinstance(widget, widgets.HTMLMath):
        return "math"
    if trait == "value" and isinstance(widget, widgets.HTML):
        return "html"
    if trait == "description" and getattr(widget, "description_allow_html", False):
        return "math"  # sanitized, then typeset
    if trait == "description" or (trait == "value" and isinstance(widget, widgets.Label)):
        return "typeset"  # textContent, then MathJax
    return "text"


def check_page(panel: Any) -> str:
    """Assert that nothing hostile became markup or math; return all visible text."""
    visible: list[str] = []
    for treatment, where, text in strings(panel.widget):
        if treatment in ("html", "math"):
            parser = _Markup()
            parser.feed(text)
            parser.close()
            lowered = text.lower()
            for raw in ("<img", "<script", "<svg"):
                assert raw not in lowered, (where, text)
            assert not FORBIDDEN_TAGS & set(parser.tags), (where, text)
            handlers = [a for a in parser.attributes if a.startswith("on")]
            assert handlers == [], (where, text)
            shown = "".join(parser.text)
            visible.append(shown)
            if treatment == "math":
                body = shown.strip()
                if body.startswith("$$") and body.endswith("$$"):
                    body = body[2:-2]
                # Inside a \text{…} the core writes its own symbols as inline math ($\alpha$,
                # $\cdot$, $^{\mathsf T}$); every other "$" is a name's, escaped as "\$".
                own = re.sub(r"(?<!\\)\$(\\[A-Za-z]+|\^\{\\mathsf T\})\$", "", body)
                assert re.search(r"(?<!\\)\$", own) is None, (where, text)
                assert "$\\alpha$ &" not in body and "$$x" not in body, (where, text)
        elif treatment == "typeset":
            for piece in (*HOSTILE, *MODULE_NAMES, ROBOT_NAME):
                assert piece not in text, (where, text)
            visible.append(text)
        else:
            visible.append(text)
    return "\n".join(visible)


# -- driving the panel ----------------------------------------------------------------------


@pytest.fixture
def panel() -> Any:
    panel = make_panel()
    upload(panel, hostile_file())
    assert panel.errors == {}
    assert panel.robot.name == ROBOT_NAME
    assert panel.robot.module_names[1:] == (DH_NAME, *MODULE_NAMES[1:])
    return panel


def test_the_hostile_file_loads_and_nothing_in_it_becomes_markup(panel):
    panel.apply(act.SelectTab("matrices"))  # drawn when shown
    seen = check_page(panel)
    assert f"loaded {FILE_NAME}" in seen  # the user still sees the file's name, as text
    assert ROBOT_NAME in seen  # in the matrices' text printout
    assert repr(DH_NAME) in seen  # the read-only DH row of the module list
    assert panel.state.document.motion.driven(panel.robot.coordinate_names) == {
        "q1": signals.Sine(amplitude=0.5),
        "q4": signals.Ramp(),
    }


def test_every_view_of_the_hostile_robot_stays_text(panel):
    # Matrices: text, LaTeX, symbolic with and without lengths (a moved joint keeps the
    # robot's name, so the printouts hold it).
    ui(panel, "modules[0].q").type("20")
    panel.apply(act.SelectTab("matrices"))
    ui(panel, "matrices.style").choose("latex")
    assert "\\$" in panel.matrices.math.value  # the name's "$" as the core escaped it
    ui(panel, "matrices.symbolic").check(True)
    assert "\\$" in panel.matrices.math.value
    ui(panel, "matrices.lengths").check(True)
    assert r"\sin" in panel.matrices.math.value
    check_page(panel)
    # Motion: run, every point, the table, statistics, plot and CSV.
    panel.apply(act.SelectTab("motion"))
    ui(panel, "run").click()
    assert panel.motion is not None and panel.errors == {}
    points = [value for _, value in shown(panel, "results.point")["options"]]
    assert set(MODULE_NAMES) <= set(points)  # options: text
    for point in points:
        ui(panel, "results.point").choose(point)
    ui(panel, "results.view").choose("plot")
    ui(panel, "results.view").choose("table")
    ui(panel, "results.csv").click()
    assert panel.motion_tab.results.csv_link.value
    seen = check_page(panel)
    for name in MODULE_NAMES:
        assert name in seen  # the table's column headers show them, escaped
    assert f"{ROBOT_NAME}_motion.csv".replace(" ", "_") in seen  # the CSV's file name
    # Module list: a move, a NaN and its message.
    ui(panel, "modules[3].up").click()
    ui(panel, "modules[3].ax").type(IMG)
    assert "modules[3].ax" in panel.errors and IMG in panel.errors["modules[3].ax"]
    check_page(panel)
    ui(panel, "modules[3].ax").type("5")
    # Save: a hostile file name typed into the box.
    panel.apply(act.SelectTab("files"))
    ui(panel, "save.name").type(FILE_NAME)
    ui(panel, "save.make").click()
    assert shown(panel, "save.link")["download"] == FILE_NAME
    assert FILE_NAME in check_page(panel)
    # DH table (the core's message naming a module; then a new table) and back, undone
    # to the hostile robot; the wizard to its summary.
    hostile = panel.robot
    ui(panel, "mode").choose("dh")
    ui(panel, "mode.dh.convert").click()
    check_page(panel)
    ui(panel, "mode.dh.new").click()
    ui(panel, "dh[0].alpha").type("90")
    ui(panel, "mode").choose("modules")
    for _ in range(5):
        if panel.robot == hostile:
            break
        panel.undo()
    assert panel.robot == hostile
    check_page(panel)
    ui(panel, "mode").choose("wizard")
    for _ in range(12):
        ui(panel, "wizard.next").click()
        if panel.state.wizard.part == "summary":
            break
    check_page(panel)


def test_error_messages_quote_hostile_values_as_text(panel):
    data = json.loads(hostile_file())
    data["robot"]["links"][0]["kind"] = IMG  # the core quotes the bad value in its message
    upload(panel, json.dumps(data).encode(), name=f"{SCRIPT}.json")
    assert IMG in panel.files.upload_error.message
    seen = check_page(panel)
    assert IMG in seen  # the message shows the value as the user wrote it
    assert panel.robot.name == ROBOT_NAME  # the last valid robot stays
    data = json.loads(hostile_file())
    data["signals"] = {SVG: {"type": "Sine"}}  # no module of that name
    upload(panel, json.dumps(data).encode())
    assert SVG in panel.files.upload_error.message
    check_page(panel)
    upload(panel, b"{" + IMG.encode(), name=IMG)
    assert panel.files.upload_error.message
    check_page(panel)


def test_a_file_name_alone_can_be_hostile():
    panel = make_panel()
    upload(panel, rc.preset("paper").to_json().encode(), name=FILE_NAME)
    assert panel.errors == {}
    status = panel.files.load_status.value
    assert "<img" not in status and html.escape(FILE_NAME) in status
    assert f"loaded {FILE_NAME}" in check_page(panel)


def test_the_walker_sees_what_it_must_refuse():
    box = widgets.VBox([widgets.Tab([widgets.HTML(f"<b>{IMG}</b>")])])
    with pytest.raises(AssertionError):
        check_page(type("Panel", (), {"widget": box})())
    out = widgets.Output()
    out.outputs = ({"output_type": "display_data", "data": {"text/html": SCRIPT}, "metadata": {}},)
    with pytest.raises(AssertionError):
        check_page(type("Panel", (), {"widget": widgets.HBox([out])})())
    math = widgets.HTMLMath("$$\\text{" + MATH + "}$$")
    with pytest.raises(AssertionError):
        check_page(type("Panel", (), {"widget": widgets.HBox([math])})())
    label = widgets.Label(MODULE_NAMES[2])
    with pytest.raises(AssertionError):
        check_page(type("Panel", (), {"widget": widgets.HBox([label])})())
    form = Form()
    form.show([row("r", [link("javascript:alert(1)", "x", "x")])])
    with pytest.raises(AssertionError):
        check_page(type("Panel", (), {"widget": widgets.HBox([form])})())
