"""``robotconf report`` end to end, in a subprocess, as a user runs it."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys

import numpy as np
import pytest

import robotconf as rc
from robotconf.cli import main
from robotconf.signals import Ramp, RepeatingSequence, Sine

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def run(*args: str, cwd=None) -> subprocess.CompletedProcess:
    env = {**os.environ, "MPLBACKEND": "Agg"}
    return subprocess.run(
        [sys.executable, "-m", "robotconf", *args],
        capture_output=True,
        text=True,
        timeout=240,
        env=env,
        cwd=cwd,
    )


def read_dva(path):
    import pandas as pd

    return pd.read_csv(path, header=[0, 1, 2], index_col=0)


@pytest.fixture(scope="module")
def paper_report(tmp_path_factory):
    """The paper's demonstration with every default: q3 = Simulink's sawtooth, 0…10 s."""
    out = tmp_path_factory.mktemp("paper")
    args = ["report", "--preset", "paper", "--out", str(out)]
    if not hasattr(rc, "view"):
        args.append("--no-scene")
    return run(*args), out


def test_paper_report_succeeds_with_progress_lines(paper_report):
    result, out = paper_report
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0].startswith("[1/") and "preset 'paper'" in lines[0]
    assert re.match(r"\[(\d+)/\1\] report.md", lines[-1])
    assert "10001 samples (analytic)" in result.stdout
    assert "q3=RepeatingSequence(times=(0.0, 2.0), values=(0.0, 2.0))" in result.stdout
    expected = {"matrices.txt", "matrices.tex", "dva.csv", "statistics.csv", "report.md"}
    expected |= {"robot.png", "q.png", "dva_EE.png", "dva_M1.png", "dva_M2.png", "dva_M3.png"}
    assert expected <= {p.name for p in out.iterdir()}


def test_paper_matrices_are_figure_13(paper_report):
    _, out = paper_report
    text = (out / "matrices.txt").read_text(encoding="utf-8")
    assert "at q = (0, 0, 0)" in text
    m3 = text[text.index("M3: M2·A3") :]
    assert "M3 = [ 0  1  0   0 ]" in m3 and "[ 1  0  0  30 ]" in m3 and "[ 0  0  1  20 ]" in m3
    assert "p_EE = [  0 ]" in text and "[ 70 ]" in text
    assert "cos(q1)*cos(q2 + q3)" in text or "cos(q2 + q3)" in text  # the symbolic part
    tex = (out / "matrices.tex").read_text(encoding="utf-8")
    assert tex.startswith("\\documentclass{article}") and tex.rstrip().endswith("\\end{document}")
    assert "\\begin{aligned}" in tex and "70" in tex


def test_paper_dva_csv_matches_the_core(paper_report, paper_robot):
    _, out = paper_report
    table = read_dva(out / "dva.csv")
    assert table.shape == (10001, 60)
    np.testing.assert_array_equal(table.loc[0.0, "EE"]["position"].to_numpy(), [70, 0, 20])
    motion = rc.simulate(paper_robot, {"q3": RepeatingSequence()}, t_end=10.0, dt=1e-3)
    np.testing.assert_allclose(table.index, motion.t, rtol=0, atol=1e-12)
    for quantity in ("position", "displacement", "velocity", "acceleration"):
        np.testing.assert_allclose(
            table["EE"][quantity].to_numpy(),
            motion.quantity(quantity)[:, -1],
            rtol=1e-12,
            atol=1e-9,
        )
    # q3 = 1 rad/s at t = 0: the EE starts down at 40 length/s (Figure 18).
    np.testing.assert_allclose(table.loc[0.0, ("EE", "velocity", "z")], -40.0)


def test_paper_statistics_match_the_core(paper_report, paper_robot):
    import pandas as pd

    _, out = paper_report
    stats = pd.read_csv(out / "statistics.csv", index_col=[0, 1, 2])
    row = stats.loc[("EE", "displacement", "z")]
    # z(t) = 20 − 40 sin q3 with q3 sweeping 0…2 rad: the minimum −40 at q3 = π/2.
    np.testing.assert_allclose(row["min"], -40.0, atol=1e-5)
    np.testing.assert_allclose(row["max"], 0.0, atol=1e-12)
    motion = rc.simulate(paper_robot, {"q3": RepeatingSequence()}, t_end=10.0, dt=1e-3)
    expected = motion.stats().loc[("EE", "displacement", "z")]
    np.testing.assert_allclose(row.to_numpy(dtype=float), expected.to_numpy(dtype=float))


def test_paper_pngs_are_valid_images(paper_report):
    from matplotlib.image import imread

    _, out = paper_report
    for name in ("robot.png", "q.png", "dva_EE.png", "dva_M2.png"):
        data = (out / name).read_bytes()
        assert data.startswith(PNG_SIGNATURE), name
        image = imread(out / name)
        assert image.ndim == 3 and image.shape[0] > 300 and image.shape[1] > 500


def test_paper_summary_lists_figure_14_points(paper_report):
    _, out = paper_report
    summary = (out / "report.md").read_text(encoding="utf-8")
    assert "- EE (70.0, 0.0, 20.0)" in summary and "- M3 (30.0, 0.0, 20.0)" in summary


def test_scene_html_is_self_contained(paper_report):
    if not hasattr(rc, "view"):
        pytest.skip("robotconf.view (the 3D scene) is not available in this checkout yet")
    _, out = paper_report
    html = (out / "scene.html").read_text(encoding="utf-8")
    assert "<html" in html.lower()
    assert not re.search(r"<script[^>]*\bsrc\s*=\s*[\"']?https?://", html, re.IGNORECASE)
    assert "<script" in html and "robotconf-scene-log" in html  # the animation is inlined


def test_json_setup_with_signals_and_override(tmp_path, paper_robot):
    setup = rc.Setup(
        paper_robot,
        {"q1": Ramp(slope=0.5), "q3": Sine(amplitude=0.2)},
        {"t_end": 1.0, "dt": 0.01},
    )
    path = setup.save(tmp_path / "robot.json")
    out = tmp_path / "report"
    result = run(
        "report",
        str(path),
        "--signal",
        "q3=constant:pi/2",
        "--out",
        str(out),
        "--no-scene",
        "--no-symbolic",
        "--method",
        "numeric",
        "--quiet",
    )
    assert result.returncode == 0, result.stderr
    assert result.stdout == ""
    table = read_dva(out / "dva.csv")
    assert table.shape[0] == 101  # t_end and dt from the file
    motion = rc.simulate(
        paper_robot, {"q1": Ramp(slope=0.5), "q3": np.pi / 2}, t_end=1.0, dt=0.01, method="numeric"
    )
    np.testing.assert_allclose(
        table["EE"]["position"].to_numpy(), motion.position[:, -1], rtol=1e-12, atol=1e-9
    )
    # q3 = π/2 points the last link down: the EE starts at (30, 0, −20).
    np.testing.assert_allclose(table.iloc[0]["EE"]["position"].to_numpy(), [30, 0, -20], atol=1e-9)
    assert "Symbolic" not in (out / "matrices.txt").read_text(encoding="utf-8")
    assert not (out / "scene.html").exists()  # --no-scene


def test_preset_with_signal_and_times(tmp_path):
    out = tmp_path / "puma"
    result = run(
        "report",
        "--preset",
        "puma560",
        "--signal",
        "q2=sine:amplitude=0.5,frequency=0.5",
        "--signal",
        "q1=ramp:slope=0.1",
        "--t-end",
        "2",
        "--dt",
        "0.05",
        "--out",
        str(out),
        "--no-scene",
        "--no-symbolic",
    )
    assert result.returncode == 0, result.stderr
    robot = rc.preset("puma560")
    table = read_dva(out / "dva.csv")
    assert table.shape == (41, 15 * (robot.n + 1))
    np.testing.assert_allclose(
        table.iloc[0]["EE"]["position"].to_numpy(), robot.end_effector(robot.q), atol=1e-12
    )
    assert (out / "q.png").read_bytes().startswith(PNG_SIGNATURE)


def bad(result: subprocess.CompletedProcess, fragment: str) -> None:
    assert result.returncode == 2, (result.stdout, result.stderr)
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert lines[0].startswith("robotconf: error: ") and fragment in lines[0], lines[0]
    assert "Traceback" not in result.stderr


def test_missing_file(tmp_path):
    bad(run("report", str(tmp_path / "nope.json"), "--out", str(tmp_path)), "no such file")


def test_bad_json(tmp_path):
    path = tmp_path / "broken.json"
    path.write_text('{"format": "robotconf", "version": 1, "robot": {', encoding="utf-8")
    bad(run("report", str(path), "--out", str(tmp_path / "o")), "robotconf: error: ")


def test_hostile_json_value(tmp_path):
    data = {
        "format": "robotconf",
        "version": 1,
        "robot": {"links": [{"type": "module", "kind": 9}]},
    }
    path = tmp_path / "hostile.json"
    path.write_text(json.dumps(data), encoding="utf-8")
    bad(run("report", str(path), "--out", str(tmp_path / "o")), "kind")


def test_unknown_preset(tmp_path):
    bad(run("report", "--preset", "r2d2", "--out", str(tmp_path)), "r2d2")


def test_bad_signal_spec(tmp_path):
    bad(
        run(
            "report",
            "--preset",
            "paper",
            "--signal",
            "q3=sine:amplitude=oops",
            "--out",
            str(tmp_path),
        ),
        "'oops' is not a number",
    )


def test_signal_for_a_missing_coordinate(tmp_path):
    bad(run("report", "--preset", "paper", "--signal", "q9=ramp", "--out", str(tmp_path)), "q9")


@pytest.mark.parametrize("dt", ["0", "-0.1"])
def test_non_positive_dt(tmp_path, dt):
    bad(
        run("report", "--preset", "paper", "--dt", dt, "--out", str(tmp_path)),
        "dt: must be positive",
    )


def test_out_is_a_file(tmp_path):
    target = tmp_path / "file.txt"
    target.write_text("x")
    bad(run("report", "--preset", "paper", "--out", str(target)), "is not a folder")


def test_usage_errors_are_one_line(tmp_path):
    bad(run("report", "--out", str(tmp_path)), "one of the arguments")
    bad(run("report", "x.json", "--preset", "paper", "--out", str(tmp_path)), "not allowed with")
    bad(run("report", "--preset", "paper"), "--out")
    bad(run("report", "--preset", "paper", "--dt", "fast", "--out", str(tmp_path)), "--dt")
    bad(run("launch"), "invalid choice")


def test_help_documents_the_signal_language():
    result = run("report", "--help")
    assert result.returncode == 0
    text = " ".join(result.stdout.split())
    assert "q3=repeating:times=0,2;values=0,2" in text and "constant" in text


def test_main_in_process_returns_codes(tmp_path, capsys):
    assert main(["report", "--preset", "nope", "--out", str(tmp_path)]) == 2
    assert capsys.readouterr().err.startswith("robotconf: error: ")
    assert main(["--help"]) == 0
