"""What the report's figures draw: pinned, so that making them quicker cannot change it.

The report draws its DVA figures as one :class:`MotionFigure` redrawn point after point.
Each redrawn figure must hold exactly the motion's table, with the titles, labels, units,
limits and tick labels a new figure of that point gets, and every text inside the figure
without overlapping another axes' text.
"""

from __future__ import annotations

import struct

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

import robotconf as rc  # noqa: E402
from robotconf.motion import SimulationSettings, simulate  # noqa: E402
from robotconf.plots import MotionFigure, plot_coordinates, plot_motion, plot_robot  # noqa: E402
from robotconf.report import DPI, DVA_SIZE, write_report  # noqa: E402
from robotconf.signals import RepeatingSequence, Sine  # noqa: E402

QUANTITIES = ("displacement", "velocity", "acceleration")


@pytest.fixture(scope="module")
def paper_motion() -> rc.Motion:
    return simulate(rc.preset("paper"), {"q3": RepeatingSequence()}, t_end=10.0, dt=0.01)


def drawn(fig):  # type: ignore[no-untyped-def]
    fig.canvas.draw()
    return fig.canvas.get_renderer()


def texts_of(fig):  # type: ignore[no-untyped-def]
    """(owner, text) for every visible, non-empty text of a drawn 2D figure, tick labels
    included; the owner is the text's axes, or ``None`` for the figure's own texts."""
    found = [(None, t) for t in {id(t): t for t in (fig._suptitle, *fig.texts)}.values()]
    found += [(None, t) for legend in fig.legends for t in legend.texts]
    for ax in fig.axes:
        texts = [ax.title, ax.xaxis.label, ax.yaxis.label]
        texts += [ax.xaxis.offsetText, ax.yaxis.offsetText]
        for axis in (ax.xaxis, ax.yaxis):
            texts += [tick.label1 for tick in axis._update_ticks() if tick.label1.get_visible()]
        found += [(ax, t) for t in texts]
    return [(ax, t) for ax, t in found if t is not None and t.get_visible() and t.get_text()]


def assert_nothing_cut_or_overlapping(fig) -> None:  # type: ignore[no-untyped-def]
    """Every text inside the figure, no two texts overlapping, and no text over the
    plotting area of an axes other than its own."""
    renderer = drawn(fig)
    page = fig.bbox
    boxes = [(ax, t.get_text(), t.get_window_extent(renderer)) for ax, t in texts_of(fig)]
    for _, text, box in boxes:
        assert page.x0 <= box.x0 and box.x1 <= page.x1, text
        assert page.y0 <= box.y0 and box.y1 <= page.y1, text
    for i, (_, text, box) in enumerate(boxes):
        for _, other, other_box in boxes[i + 1 :]:
            assert not box.overlaps(other_box), (text, other)
    for ax in fig.axes:
        frame = ax.bbox
        for owner, text, box in boxes:
            if owner is not ax:
                assert not box.overlaps(frame), (text, ax.get_title() or ax.get_ylabel())


def assert_pinned(fig, motion, point: str, unit: str) -> None:  # type: ignore[no-untyped-def]
    """The DVA figure of one point, as the report draws it, against the motion's table."""
    axes = np.array(fig.axes).reshape(3, 3)
    assert len(fig.axes) == 9
    assert fig._suptitle.get_text() == f"{motion.robot.name}: {point} (analytic derivatives)"
    assert [ax.get_title() for ax in axes[0]] == [f"{point}: {a}" for a in "xyz"]
    assert [ax.get_title() for ax in axes[1:].flat] == [""] * 6
    assert [ax.get_ylabel() for ax in axes[:, 0]] == [
        f"displacement [{unit}]",
        f"velocity [{unit}/s]",
        f"acceleration [{unit}/s²]",
    ]
    assert [ax.get_ylabel() for ax in axes[:, 1:].flat] == [""] * 6
    assert [ax.get_xlabel() for ax in axes.flat] == [""] * 6 + ["time (s)"] * 3
    kinks = motion.kinks()["q3"]
    for r, quantity in enumerate(QUANTITIES):
        for c, axis in enumerate("xyz"):
            ax = axes[r, c]
            curves = ax.lines[:1]
            markers = ax.lines[1:]
            (x, y), column = curves[0].get_data(), motion.table[(point, quantity, axis)]
            np.testing.assert_array_equal(x, motion.t)
            np.testing.assert_array_equal(y, column.to_numpy())
            # The limits matplotlib gives these data on a plain axes of its own.
            plain = Figure().add_subplot()
            plain.plot(motion.t, column.to_numpy())
            assert ax.get_ylim() == plain.get_ylim() and ax.get_xlim() == plain.get_xlim()
            assert curves[0].get_linestyle() == "-" and curves[0].get_color() == "C0"
            assert curves[0].get_label() == "analytic"
            if r == 2:  # the kinks of the sawtooth, dashed red on the acceleration row
                assert [m.get_xdata()[0] for m in markers] == kinks.tolist()
            else:
                assert markers == []
    note = " ".join(t.get_text() for t in fig.texts if t is not fig._suptitle).split()
    assert " ".join(note).startswith("Kinks or jumps of the input (q3 at t = 0, 2, 4, 6, 8, …")
    assert fig.legends == []


def test_each_redrawn_report_figure_holds_its_points_table(paper_motion):
    dva = MotionFigure(paper_motion, displacement=True, length_unit="mm", figsize=DVA_SIZE, dpi=DPI)
    for point in ("EE", "M1", "M2", "M3"):
        fig = dva.show(point if point == "EE" else int(point[1]) - 1)
        assert fig is dva.figure  # the same figure, redrawn
        assert_pinned(fig, paper_motion, point, "mm")
        assert_nothing_cut_or_overlapping(fig)


def test_a_redrawn_figure_equals_a_new_figure_of_the_point(paper_motion):
    dva = MotionFigure(paper_motion, displacement=True, figsize=DVA_SIZE, dpi=DPI)
    dva.show("EE")
    for point in ("M2", "M1", "EE"):
        reused = dva.show(point)
        renderer = drawn(reused)
        new = plot_motion(paper_motion, point, displacement=True, figsize=DVA_SIZE)
        drawn(new)
        for old, fresh in zip(reused.axes, new.axes, strict=True):
            assert old.get_ylim() == fresh.get_ylim()
            assert old.get_xlim() == fresh.get_xlim()
            ticks = [t.get_text() for t in old.get_yticklabels()]
            assert ticks == [t.get_text() for t in fresh.get_yticklabels()]
            assert old.yaxis.offsetText.get_text() == fresh.yaxis.offsetText.get_text()
            np.testing.assert_allclose(
                old.get_position().bounds, fresh.get_position().bounds, atol=1e-9
            )
        assert [t.get_text() for t in reused.texts] == [t.get_text() for t in new.texts]
        assert reused.canvas.get_renderer() is renderer  # one renderer, warm text caches


def test_switching_between_one_and_many_points_redraws_the_lines(paper_motion):
    dva = MotionFigure(paper_motion)
    fig = dva.show("all")
    axes = np.array(fig.axes).reshape(3, 3)
    assert len(axes[0, 0].lines) == 4
    assert [t.get_text() for t in fig.legends[0].get_texts()] == ["M1", "M2", "M3", "EE"]
    dva.show("M3")
    assert len(axes[0, 0].lines) == 1 and fig.legends == []
    np.testing.assert_array_equal(axes[1, 2].lines[0].get_ydata(), paper_motion.velocity[:, 2, 2])
    assert len(axes[2, 0].lines) == 1 + len(paper_motion.kinks()["q3"])
    with pytest.raises(ValueError, match="point"):
        dva.show("M9")
    assert axes[0, 0].get_title() == "M3: x"  # an unknown point leaves the figure as it was


@pytest.mark.parametrize(
    "case",
    ["all, numeric dashed", "long name, sci offsets", "numeric note", "small figure"],
)
def test_no_text_is_cut_or_overlaps_another_axes(case):
    paper = rc.preset("paper")
    sawtooth = {"q3": RepeatingSequence()}
    if case == "all, numeric dashed":
        motion = simulate(paper, sawtooth, t_end=4.0, dt=0.01)
        other = simulate(paper, sawtooth, t_end=4.0, dt=0.01, method="numeric")
        fig = plot_motion(motion, "all", compare=other, length_unit="mm")
    elif case == "long name, sci offsets":
        robot = rc.Robot(
            [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 2e5)), rc.Module("Ty", a=(3e5, 0, 0))],
            end_effector=(1e5, 0, 0),
            name="a rather long robot name $x$ <b>",
        )
        motion = simulate(robot, {"q2": Sine(), "q3": Sine(amplitude=1e-3)}, t_end=2.0, dt=0.01)
        fig = plot_motion(motion, 2, displacement=True, length_unit="µm")
    elif case == "numeric note":
        motion = simulate(paper, sawtooth, t_end=4.0, dt=0.01, method="numeric")
        fig = plot_motion(motion, "M3", figsize=DVA_SIZE)
        assert len(fig.texts[0].get_text().splitlines()) >= 3
    else:
        motion = simulate(paper, sawtooth, t_end=4.0, dt=0.01)
        fig = plot_motion(motion, "EE", figsize=(9.0, 6.0))
    assert fig.get_layout_engine() is None  # laid out once, not at each draw
    assert_nothing_cut_or_overlapping(fig)


def test_coordinates_figure_keeps_its_text_inside():
    robot = rc.preset("puma560")
    motion = simulate(robot, {"q2": Sine(), "q3": RepeatingSequence()}, t_end=2.0, dt=0.01)
    fig = plot_coordinates(motion, "m")
    assert [ax.get_ylabel() for ax in fig.axes] == ["q2 [rad]", "q3 [rad]"]
    assert [ax.get_title() for ax in fig.axes] == [
        f"q2(t) = {motion.signals['q2']!r}",
        f"q3(t) = {motion.signals['q3']!r}",
    ]
    np.testing.assert_array_equal(fig.axes[1].lines[0].get_ydata(), motion.q[:, 2])
    assert_nothing_cut_or_overlapping(fig)


def test_robot_figure_axes_carry_the_unit_and_long_labels_turn_left():
    fig = plot_robot(rc.preset("puma560"), digits=3, length_unit="m")
    ax = fig.axes[0]
    assert (ax.get_xlabel(), ax.get_ylabel(), ax.get_zlabel()) == ("x [m]", "y [m]", "z [m]")
    by_text = {t.get_text().split(" (")[0]: t for t in ax.texts}
    # The wrist's merged label is long and its point is on the right: it goes left.
    assert by_text["M4, M5, M6, EE"].get_horizontalalignment() == "right"
    assert by_text["M1"].get_horizontalalignment() == "left"
    x, y, _ = ax.get_position().bounds[:3]
    assert x > 0 and y > 0 and ax.get_position().x1 < 1 and ax.get_position().y1 < 1


def png_size(path) -> tuple[int, int]:  # type: ignore[no-untyped-def]
    width, height = struct.unpack(">II", path.read_bytes()[16:24])
    return width, height


def test_report_says_each_figure_as_it_is_written(tmp_path):
    out = tmp_path / "out"
    lines: list[str] = []

    def say(line: str) -> None:
        if line.startswith("[5/7]"):  # the file a line names is on disk when it is said
            assert (out / line.split()[1]).is_file(), line
        lines.append(line)

    write_report(
        rc.preset("paper"),
        {"q3": RepeatingSequence()},
        SimulationSettings(2.0, dt=0.01),
        out,
        symbolic=False,
        say=say,
    )
    figures = [line for line in lines if line.startswith("[5/7]")]
    names = ["robot.png", "q.png", "dva_EE.png", "dva_M1.png", "dva_M2.png", "dva_M3.png"]
    assert figures == [f"[5/7] {name} (figure {i} of 6)" for i, name in enumerate(names, 1)]
    assert [line[:5] for line in lines] == ["[1/7]", "[2/7]", "[3/7]", "[4/7]"] + ["[5/7]"] * 6 + [
        "[6/7]",
        "[7/7]",
    ]
    assert all(png_size(out / name) == (1000, 650) for name in names[2:])
    assert png_size(out / "robot.png") == (700, 600)


def test_point_names_in_the_legend_are_drawn_literally():
    robot = rc.Robot(
        [rc.Module("Rz", name="$x$$"), rc.Module("Ry", a=(0, 0, 1), name="$\\frac{a}{b}$")],
        end_effector=(1, 0, 0),
    )
    motion = simulate(robot, {"q1": Sine()}, t_end=1.0, dt=0.1)
    fig = plot_motion(motion, "all")
    assert [t.get_text() for t in fig.legends[0].get_texts()] == list(motion.points)
    assert all(not t.get_parse_math() for t in fig.legends[0].get_texts())
    drawn(fig)  # "$x$$" as mathtext would raise here
