"""User text reaches every display literally: Markdown, the scene's HTML, matplotlib text.

Names come from students' and instructors' files. Each display must show them exactly
as written and never interpret them: no HTML elements in a page, no Markdown links or
emphasis, no matplotlib mathtext (``$\\undefinedmacro{x}$`` made drawing raise).
"""

from __future__ import annotations

import html
import json
import re
from html.parser import HTMLParser
from importlib import resources

import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg

import robotconf as rc
from robotconf.cli import markdown_text
from robotconf.plots import plot_coordinates, plot_motion, plot_robot, plot_workspace
from robotconf.scene import RecordingChannel, Scene
from robotconf.signals import Sine

HOSTILE = (
    "<script>alert(1)</script>",
    "<img src=x onerror=alert(2)>",
    "$\\frac{a}{b}$",
    "$x$$",
    "$\\undefinedmacro{x}$",
    "[click](javascript:alert(3)) *b* _i_ `c` | ~~s~~",
    "a & b &amp; <!-- c",
)
ROBOT_NAME = "</title><script>steal()</script> $x$$ **bold**"
UNIT = "$m$$ <b>"


@pytest.fixture(scope="module")
def hostile_robot() -> rc.Robot:
    kinds = ("Rz", "Ry", "Tx", "Ry", "Rx", "Tz", "Rz")
    modules = [
        rc.Module(kind, a=(10, 0, 5), name=name) for kind, name in zip(kinds, HOSTILE, strict=True)
    ]
    return rc.Robot(modules, name=ROBOT_NAME, end_effector=(5, 0, 0))


@pytest.fixture(scope="module")
def hostile_motion(hostile_robot):
    return rc.simulate(hostile_robot, {"q1": Sine(amplitude=0.5)}, t_end=1.0, dt=0.05)


def render(fig) -> None:
    """Draw every artist with Agg: mathtext or LaTeX parsing would happen (and fail) here."""
    FigureCanvasAgg(fig).draw()


def user_texts(fig) -> list:
    """The Text artists robotconf fills: titles, axis labels, annotations, notes."""
    texts = [*fig.texts, fig._suptitle] if fig._suptitle is not None else [*fig.texts]
    for ax in fig.axes:
        texts += [ax.title, ax.xaxis.label, ax.yaxis.label, *ax.texts]
        if hasattr(ax, "zaxis"):
            texts.append(ax.zaxis.label)
    return [text for text in texts if text.get_text()]


# -- Markdown ---------------------------------------------------------------------------


def unescape_markdown(text: str) -> str:
    """What a CommonMark renderer shows for escaped text (backslash escapes, entities)."""
    return html.unescape(re.sub(r"\\([!-/:-@\[-`{-~])", r"\1", text))


@pytest.mark.parametrize("name", [*HOSTILE, ROBOT_NAME, "plain name", "ünïcødé θ₁"])
def test_markdown_text_shows_the_name_and_nothing_else(name):
    escaped = markdown_text(name)
    assert "<" not in escaped and ">" not in escaped
    # Every Markdown-significant character is escaped: none is left bare.
    assert re.search(r"(?<!\\)[`*_\[\]|$~]", escaped) is None, escaped
    assert unescape_markdown(escaped) == name


def test_markdown_text_keeps_one_line_and_shows_bidi_controls():
    assert markdown_text("a\nb\r\nc\u2028d\x00e") == "a b  c d e"
    assert markdown_text("left\u202eright") == "left\\\\u202eright"
    assert "\n" not in markdown_text("# heading\n- item\n| a | b |")


# -- matplotlib -------------------------------------------------------------------------


def test_robot_plot_draws_names_and_units_literally(hostile_robot):
    fig = plot_robot(hostile_robot, length_unit=UNIT, frames=True)
    ax = fig.axes[0]
    assert ax.get_title() == f"{ROBOT_NAME}: modules (green) and end-effector (red)"
    assert ax.get_xlabel() == f"x [{UNIT}]" and ax.get_zlabel() == f"z [{UNIT}]"
    labels = [text.get_text() for text in ax.texts]
    for name, text in zip(HOSTILE, labels, strict=False):
        assert text.startswith(name + " (")
    assert all(text.get_parse_math() is False for text in ax.texts)
    render(fig)


def test_robot_plot_triads_are_keyed_by_position_not_by_name(hostile_robot):
    fig = plot_robot(hostile_robot, frames=True)
    labels = {line.get_label() for line in fig.axes[0].lines}
    assert {"frame T0 x", "frame M1 x", "frame M7 z"} <= labels
    assert not any("$" in label or "<" in label for label in labels)


def test_motion_plot_titles_are_the_literal_names(hostile_robot, hostile_motion):
    for index, name in enumerate(HOSTILE):
        fig = plot_motion(hostile_motion, index, displacement=True, length_unit=UNIT)
        titles = [ax.get_title() for ax in fig.axes[:3]]
        assert titles == [f"{name}: x", f"{name}: y", f"{name}: z"]
        assert fig.get_suptitle() == f"{ROBOT_NAME}: {name} (analytic derivatives)"
        assert fig.axes[0].get_ylabel() == f"displacement [{UNIT}]"
        assert fig.axes[3].get_ylabel() == f"velocity [{UNIT}/s]"
        render(fig)


def test_coordinate_and_workspace_plots_draw_units_literally(hostile_robot, hostile_motion):
    fig = plot_coordinates(hostile_motion, UNIT)
    assert fig.axes[0].get_title() == "q1(t) = Sine(amplitude=0.5)"
    render(fig)
    prismatic = rc.Robot([rc.Module("Tx", name="$x$$")], name=ROBOT_NAME)
    fig = plot_coordinates(rc.simulate(prismatic, {"q1": Sine()}, t_end=1.0, dt=0.1), UNIT)
    assert fig.axes[0].get_ylabel() == f"q1 [{UNIT}]"
    render(fig)
    ws = rc.workspace(hostile_robot, 200, seed=0)
    fig = plot_workspace(ws, length_unit=UNIT)
    assert fig.get_suptitle().startswith(f"{ROBOT_NAME}: end-effector workspace")
    assert fig.axes[1].get_xlabel() == f"x [{UNIT}]"
    render(fig)


def test_drawing_a_dollar_name_would_fail_with_mathtext():
    """The guard above is real: matplotlib's default parsing raises on this name."""
    from matplotlib.figure import Figure

    fig = Figure()
    fig.suptitle(HOSTILE[4])
    with pytest.raises(ValueError, match="undefinedmacro"):
        render(fig)


def test_no_user_text_in_any_figure_is_parsed_as_math(hostile_robot, hostile_motion):
    figures = [
        plot_robot(hostile_robot, length_unit=UNIT, frames=True),
        plot_motion(hostile_motion, "EE", length_unit=UNIT),
        plot_coordinates(rc.simulate(rc.Robot([rc.Module("Tz")]), {}, t_end=1.0), UNIT),
        plot_workspace(rc.workspace(hostile_robot, 100, seed=0), length_unit=UNIT),
    ]
    for fig in figures:
        texts = user_texts(fig)
        assert any("$" in text.get_text() for text in texts), "names and units are shown"
        user = [t for t in texts if "$" in t.get_text() or "<" in t.get_text()]
        assert [t.get_text() for t in user if t.get_parse_math() or t.get_usetex()] == []


# -- the scene's HTML -------------------------------------------------------------------


class _Tags(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.tags: list[str] = []
        self.scripts: list[str] = []
        self.title = ""
        self._in: str | None = None

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        self._in = tag

    def handle_endtag(self, tag):
        self._in = None

    def handle_data(self, data):
        if self._in == "script":
            self.scripts.append(data)
        elif self._in == "title":
            self.title += data


@pytest.fixture(scope="module")
def scene_page(hostile_robot, hostile_motion, tmp_path_factory) -> str:
    scene = Scene(hostile_robot, channel=RecordingChannel())
    scene.animate(hostile_motion)
    path = scene.export_html(tmp_path_factory.mktemp("scene") / "scene.html")
    return path.read_text(encoding="utf-8")


def test_scene_page_has_only_its_own_elements(scene_page):
    parser = _Tags()
    parser.feed(scene_page)
    assert set(parser.tags) == {"html", "head", "meta", "title", "style", "body", "div", "script"}
    assert parser.tags.count("script") == 2
    assert html.unescape(parser.title) == ROBOT_NAME
    for raw in ("<img", "<script>alert", "<script>steal", "<!-- c", "</title><script>"):
        assert raw not in scene_page


def test_scene_labels_arrive_as_the_literal_names(scene_page):
    parser = _Tags()
    parser.feed(scene_page)
    log = json.loads(parser.scripts[0])
    texts = [text for op in log["ops"] if op.get("op") == "labels" for text in op["texts"]]
    assert [*HOSTILE, "EE"] == texts[-len(HOSTILE) - 1 :]


def test_scene_labels_are_written_as_text_not_parsed_as_html():
    folder = resources.files("robotconf.scene").joinpath("js")
    labels = folder.joinpath("labels.js").read_text(encoding="utf-8")
    assert 'entry.el.textContent = entry.lines.join("\\n")' in labels
    sources = "".join(
        folder.joinpath(name).read_text(encoding="utf-8")
        for name in sorted(p.name for p in folder.iterdir() if p.name.endswith(".js"))
    )
    # The only HTML ever assigned is the empty string (clearing a pane).
    assignments = re.findall(r"(?:innerHTML|outerHTML)\s*=\s*([^;]*);", sources)
    assert assignments == ['""']
    assert "insertAdjacentHTML" not in sources and "document.write" not in sources


def test_scene_animation_labels_keep_names_with_parentheses():
    robot = rc.Robot([rc.Module("Rz", name="arm (left)"), rc.Module("Ry", a=(1, 0, 0))])
    channel = RecordingChannel()
    scene = Scene(robot, channel=channel)
    channel.clear()
    scene.animate(rc.simulate(robot, {"q1": Sine()}, t_end=1.0, dt=0.1))
    labels = [op.content["texts"] for op in channel.ops if op.content["op"] == "labels"]
    assert labels == [["arm (left)", "M2", "EE"]]
