"""``robotconf report`` on untrusted files: escaped output, bounded time, one-line errors.

A report must show hostile names as text, finish quickly on the longest chains the file
format allows, and end every failure (bad settings, overflow, too much memory, an
unwritable folder, a bug) with exit status 2 and exactly one line on standard error.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import time
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import robotconf as rc
from robotconf import report
from robotconf.cli import main
from robotconf.report import MAX_MODULE_PLOTS, _steps, _write
from robotconf.signals import Sine
from robotconf.teaching import symbolic_fits

HOSTILE = {
    "robot": "</title><script>steal()</script> $x$$ **bold**",
    "modules": (
        "<script>alert(1)</script>",
        "<img src=x onerror=alert(2)>",
        "$\\frac{a}{b}$",
        "$x$$",
        "[click](javascript:alert(3)) | *b* `c` # h",
    ),
}
#: What each module name must look like in report.md.
ESCAPED = (
    "&lt;script&gt;alert(1)&lt;/script&gt;",
    "&lt;img src=x onerror=alert(2)&gt;",
    "\\$\\\\frac\\{a\\}\\{b\\}\\$",
    "\\$x\\$\\$",
    "\\[click\\](javascript:alert(3)) \\| \\*b\\* \\`c\\` \\# h",
)
HANG_GUARD = 240  # s; a report of the longest chain takes about 15 s


def run(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess:
    environment = {**os.environ, "MPLBACKEND": "Agg", **(env or {})}
    return subprocess.run(
        [sys.executable, "-m", "robotconf", "report", *args],
        capture_output=True,
        text=True,
        timeout=HANG_GUARD,
        env=environment,
    )


def one_error_line(err: str, *fragments: str, prefix: str = "robotconf: error: ") -> str:
    """The single stderr line, checked to start with ``prefix`` and hold ``fragments``."""
    assert err.endswith("\n") and err.count("\n") == 1, err
    assert "Traceback" not in err
    line = err.rstrip("\n")
    assert line.startswith(prefix), line
    for fragment in fragments:
        assert fragment in line, line
    return line


def hostile_file(folder: Path) -> Path:
    kinds = ("Rz", "Ry", "Tx", "Ry", "Rx")
    modules = [
        rc.Module(kind, a=(10, 0, 5), name=name)
        for kind, name in zip(kinds, HOSTILE["modules"], strict=True)
    ]
    robot = rc.Robot(modules, name=HOSTILE["robot"], end_effector=(5, 0, 0))
    setup = rc.Setup(robot, {"q1": Sine(amplitude=0.5)}, {"t_end": 1.0, "dt": 0.05})
    path = folder / "<i>robot $x$.json"
    path.write_text(setup.to_json(), encoding="utf-8")
    return path


def chain_file(folder: Path, n: int) -> Path:
    kinds = ("Rz", "Ry", "Rx", "Tx")
    robot = rc.Robot(
        [rc.Module(kinds[i % 4], a=(1, 0.5, 1)) for i in range(n)], name=f"chain of {n}"
    )
    setup = rc.Setup(robot, {"q1": Sine()}, {"t_end": 0.5, "dt": 0.05})
    path = folder / f"chain{n}.json"
    path.write_text(setup.to_json(), encoding="utf-8")
    return path


def overflowing_file(folder: Path) -> Path:
    """Finite inputs whose velocities overflow: huge lengths times a fast, huge sine."""
    robot = rc.Robot(
        [rc.Module("Rz", a=(1e150, 0, 0)), rc.Module("Ry", a=(1e150, 0, 0))],
        end_effector=(1e150, 0, 0),
    )
    data = json.loads(rc.Setup(robot, {}, {"t_end": 1.0, "dt": 0.1}).to_json())
    data["signals"] = {"q1": {"type": "Sine", "amplitude": 1e100, "frequency": 1e100}}
    path = folder / "overflow.json"
    path.write_text(json.dumps(data), encoding="utf-8")
    return path


@pytest.fixture(autouse=True)
def _default_budget():
    yield
    rc.set_memory_budget(None)


# -- hostile names ----------------------------------------------------------------------


@pytest.fixture(scope="module")
def hostile_report(tmp_path_factory):
    folder = tmp_path_factory.mktemp("hostile")
    out = folder / "out"
    result = run(str(hostile_file(folder)), "--out", str(out), "--length-unit", "$m$$")
    return result, out


def test_hostile_names_report_succeeds_in_a_real_process(hostile_report):
    result, out = hostile_report
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    expected = {"report.md", "scene.html", "dva.csv", "dva_EE.png"}
    expected |= {f"dva_M{i}.png" for i in range(1, 6)}
    assert expected <= {p.name for p in out.iterdir()}


def test_report_md_escapes_every_name(hostile_report):
    _, out = hostile_report
    text = (out / "report.md").read_text(encoding="utf-8")
    assert "<" not in text and ">" not in text
    title = text.splitlines()[0]
    assert title.startswith(
        "# robotconf report: &lt;/title&gt;&lt;script&gt;steal()&lt;/script&gt; "
        "\\$x\\$\\$ \\*\\*bold\\*\\* ("
    )
    assert "&lt;i&gt;robot \\$x\\$.json)" in title  # the file name
    for i, escaped in enumerate(ESCAPED, start=1):
        assert f"- {escaped} (" in text, escaped
        assert f"| dva\\_M{i}.png | DVA of module {i} ({escaped}) |" in text, escaped
    # The table has two columns on every row: no name adds a cell.
    rows = [line for line in text.splitlines() if line.startswith("|")]
    assert all(len(re.findall(r"(?<!\\)\|", row)) == 3 for row in rows), rows


def test_scene_html_carries_no_markup_from_names(hostile_report):
    _, out = hostile_report
    page = (out / "scene.html").read_text(encoding="utf-8")
    for raw in ("<img", "<script>alert", "<script>steal", "</title><script>"):
        assert raw not in page
    assert "<title>&lt;/title&gt;&lt;script&gt;steal()&lt;/script&gt; $x$$" in page


def test_plots_are_keyed_by_index_so_names_never_collide(tmp_path):
    # The old name-based file names turned both "a/b" and "a_b" into dva_a_b.png.
    robot = rc.Robot([rc.Module("Rz", name="a/b"), rc.Module("Ry", a=(1, 0, 0), name="a_b")])
    path = tmp_path / "robot.json"
    path.write_text(robot.to_json(), encoding="utf-8")
    out = tmp_path / "out"
    argv = [str(path), "--out", str(out), "--t-end", "1", "--dt", "0.1", "--no-scene"]
    assert main(["report", *argv, "--quiet"]) == 0
    pngs = sorted(p.name for p in out.glob("dva_*.png"))
    assert pngs == ["dva_EE.png", "dva_M1.png", "dva_M2.png"]
    text = (out / "report.md").read_text(encoding="utf-8")
    assert "| dva\\_M1.png | DVA of module 1 (a/b) |" in text
    assert "| dva\\_M2.png | DVA of module 2 (a\\_b) |" in text


def test_progress_lines_carry_no_control_characters(tmp_path, capsys):
    data = json.loads(rc.Robot([rc.Module("Rz")], end_effector=(1, 0, 0)).to_json())
    data["robot"]["name"] = "evil\x1b[2J\nsecond line"
    path = tmp_path / "robot.json"
    path.write_text(json.dumps(data), encoding="utf-8")
    argv = [str(path), "--out", str(tmp_path / "o"), "--t-end", "1", "--dt", "0.5", "--no-scene"]
    status = main(["report", *argv])
    captured = capsys.readouterr()
    assert "\x1b" not in captured.out + captured.err
    if status == 2:  # the core may refuse control characters in names
        one_error_line(captured.err, "name")
    else:
        assert status == 0
        assert captured.out.splitlines()[0].endswith("evil [2J second line, 1 modules")


# -- long chains: the symbolic printout is skipped, the report stays quick ----------------


@pytest.mark.parametrize("n", [12, 64])
def test_long_chain_report_finishes_quickly_with_the_symbolic_note(tmp_path, n):
    path = chain_file(tmp_path, n)
    assert not symbolic_fits(rc.load_setup(path).robot)
    out = tmp_path / "out"
    start = time.perf_counter()
    result = run(str(path), "--out", str(out))
    elapsed = time.perf_counter() - start
    assert result.returncode == 0, result.stderr
    assert elapsed < 120, f"{elapsed:.0f} s"
    assert "(symbolic: chain too long)" in result.stdout
    matrices = (out / "matrices.txt").read_text(encoding="utf-8")
    assert "No symbolic matrices: this chain is too long" in matrices
    assert "rc.derivation(robot, symbolic=True, allow_slow=True)" in matrices
    assert "Symbolic (q1" not in matrices and "l1" not in matrices
    report = (out / "report.md").read_text(encoding="utf-8")
    assert "No symbolic matrices: this chain is too long" in report
    shown = min(n, MAX_MODULE_PLOTS)
    assert (out / f"dva_M{shown}.png").is_file()
    assert not (out / f"dva_M{shown + 1}.png").exists()
    assert ("DVA figures are written for modules 1 to 16 of 64" in report) == (n == 64)


def test_short_chain_keeps_its_symbolic_matrices_unless_told(tmp_path):
    argv = ["--preset", "paper", "--t-end", "1", "--no-scene", "--quiet"]
    assert main(["report", *argv, "--out", str(tmp_path / "on")]) == 0
    assert "Symbolic (q1" in (tmp_path / "on" / "matrices.txt").read_text(encoding="utf-8")
    assert main(["report", *argv, "--no-symbolic", "--out", str(tmp_path / "off")]) == 0
    matrices = (tmp_path / "off" / "matrices.txt").read_text(encoding="utf-8")
    assert "Symbolic (q1" not in matrices
    assert "No symbolic matrices: --no-symbolic was given." in matrices
    assert "--no-symbolic was given" in (tmp_path / "off" / "report.md").read_text("utf-8")


# -- memory -----------------------------------------------------------------------------


def test_a_run_over_the_memory_budget_is_refused_before_anything_is_allocated(tmp_path, capsys):
    rc.set_memory_budget("100M")
    out = tmp_path / "out"
    argv = ["report", "--preset", "paper", "--t-end", "2000", "--out", str(out)]
    start = time.perf_counter()
    assert main(argv) == 2
    assert time.perf_counter() - start < 5
    captured = capsys.readouterr()
    one_error_line(captured.err, "dt: needs about", "of memory (budget 100 MiB)", "larger dt")
    assert "[2/" not in captured.out  # nothing was simulated
    assert not out.exists()


def test_the_memory_budget_from_the_environment_binds_in_a_real_process(tmp_path):
    out = tmp_path / "out"
    result = run(
        "--preset", "paper", "--t-end", "2000", "--out", str(out),
        env={"ROBOTCONF_MEMORY_BUDGET": "100M"},
    )  # fmt: skip
    assert result.returncode == 2
    one_error_line(result.stderr, "dt: needs about", "memory")
    assert not out.exists()


def test_a_run_within_the_budget_is_not_refused(tmp_path):
    rc.set_memory_budget("100M")
    argv = ["report", "--preset", "paper", "--t-end", "1", "--no-scene", "--quiet"]
    assert main([*argv, "--out", str(tmp_path)]) == 0


# -- overflow ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("args", "field"),
    [
        (["--dt", "5e-324"], "dt"),
        (["--t-end", "1e308"], "t_end"),
        (["--t-end=-1e308"], "t_end"),
        (["--dt", "1e308"], "dt"),
        (["--t-end", "inf"], "t_end"),
        (["--dt", "nan"], "dt"),
    ],
)
def test_extreme_time_settings_end_in_one_line(tmp_path, capsys, args, field):
    out = tmp_path / "out"
    assert main(["report", "--preset", "paper", *args, "--out", str(out)]) == 2
    one_error_line(capsys.readouterr().err, field)
    assert not out.exists()


def test_a_file_with_a_huge_time_span_ends_in_one_line(tmp_path, capsys):
    data = json.loads(rc.preset("paper").to_json())
    data["simulation"] = {"t0": -1e308, "t_end": 1e308, "dt": 1.0}
    path = tmp_path / "span.json"
    path.write_text(json.dumps(data), encoding="utf-8")
    assert main(["report", str(path), "--out", str(tmp_path / "out")]) == 2
    one_error_line(capsys.readouterr().err, "simulation.t")


def test_finite_inputs_that_overflow_write_no_table(tmp_path):
    out = tmp_path / "out"
    result = run(str(overflowing_file(tmp_path)), "--out", str(out))
    assert result.returncode == 2, result.stdout
    # The core may refuse the values on loading, or the report finds the overflow.
    one_error_line(result.stderr)
    assert not (out / "dva.csv").exists()


def test_non_finite_results_are_named_before_dva_csv_is_written():
    robot = rc.Robot([rc.Module("Rz"), rc.Module("Ry", a=(1, 0, 0))], end_effector=(1, 0, 0))
    motion = rc.simulate(robot, {"q1": Sine()}, t_end=1.0, dt=0.25)
    _steps.check_finite(motion, motion.stats())  # finite: passes
    # Row 15 + 6 + 1 is M2's velocity y (15 series per point: 5 quantities × x, y, z).
    columns = motion.columns().copy()
    columns[15 + 6 + 1, 2] = np.inf
    overflowed = SimpleNamespace(columns=lambda: columns, points=motion.points, t=motion.t)
    with pytest.raises(report.BadInput, match=r"dva.csv: the velocity \(y\) of M2 .* t = 0.5 s"):
        _steps.check_finite(overflowed, motion.stats())


def test_statistics_that_overflow_are_refused():
    robot = rc.Robot([rc.Module("Tx")], end_effector=(0, 0, 0))
    motion = rc.simulate(robot, {"q1": Sine(amplitude=1e200)}, t_end=1.0, dt=0.25)
    assert np.isfinite(motion.columns()).all()
    # The RMS squares 1e200: inf, although every value is finite.
    with pytest.raises(report.BadInput, match=r"statistics.csv: the rms of the position \(x\)"):
        _steps.check_finite(motion, motion.stats())


# -- the output folder ------------------------------------------------------------------


def test_an_out_folder_below_a_file_ends_in_one_line(tmp_path, capsys):
    blocker = tmp_path / "file.txt"
    blocker.write_text("x")
    argv = ["report", "--preset", "paper", "--t-end", "1", "--out", str(blocker / "sub")]
    assert main(argv) == 2
    one_error_line(capsys.readouterr().err, "--out: cannot create", "Not a directory")


@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="needs a read-only folder")
def test_an_unwritable_out_folder_ends_in_one_line(tmp_path):
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o500)
    # Root writes through permissions, but nobody creates folders in /proc.
    target = Path("/proc/robotconf-report") if os.geteuid() == 0 else locked / "out"
    try:
        result = run("--preset", "paper", "--t-end", "1", "--no-symbolic", "--out", str(target))
    finally:
        locked.chmod(0o700)
    assert result.returncode == 2
    one_error_line(result.stderr, f"--out: cannot create {str(target)!r}: ")
    assert not target.exists()


# -- every other failure ----------------------------------------------------------------


def _failing_step(error: BaseException):
    def step(*args, **kwargs):
        raise error

    return step


@pytest.mark.parametrize(
    ("error", "expected"),
    [
        (RuntimeError("boom\nline 2"), "robotconf: internal error: RuntimeError: boom line 2"),
        (KeyError("x"), "robotconf: internal error: KeyError: 'x'"),
        (ZeroDivisionError("division by zero"), "robotconf: error: division by zero"),
        (OverflowError("math range error"), "robotconf: error: math range error"),
        (MemoryError(), "robotconf: error: out of memory; allowed: a larger dt"),
        (PermissionError(13, "Permission denied", "x.png"), "robotconf: error: [Errno 13]"),
        (rc.InvalidInputError("f", 1, "2"), "robotconf: error: f: invalid value 1; allowed: 2"),
    ],
)  # fmt: skip
def test_every_failure_is_one_line_with_status_2(tmp_path, capsys, monkeypatch, error, expected):
    monkeypatch.setattr(_write, "write_plots", _failing_step(error))
    argv = ["report", "--preset", "paper", "--t-end", "1", "--quiet", "--no-symbolic"]
    argv += ["--out", str(tmp_path)]
    assert main(argv) == 2
    line = one_error_line(capsys.readouterr().err, prefix="robotconf: ")
    assert line.startswith(expected), line


def test_ctrl_c_ends_with_status_130(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(_write, "write_plots", _failing_step(KeyboardInterrupt()))
    argv = ["report", "--preset", "paper", "--t-end", "1", "--quiet", "--out", str(tmp_path)]
    assert main(argv) == 130
    assert capsys.readouterr().err == "robotconf: interrupted\n"


def test_long_messages_stay_one_bounded_line(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(_write, "write_plots", _failing_step(ValueError("x\n" * 5000)))
    argv = ["report", "--preset", "paper", "--t-end", "1", "--quiet", "--out", str(tmp_path)]
    assert main(argv) == 2
    line = one_error_line(capsys.readouterr().err)
    assert len(line) <= len("robotconf: ") + report.MAX_MESSAGE_CHARS


def test_warnings_do_not_reach_stderr(tmp_path, capsys, monkeypatch):
    import warnings

    write_plots = _write.write_plots

    def noisy(*args, **kwargs):
        warnings.warn("Glyph 1234 missing from font", UserWarning, stacklevel=1)
        np.float64(1e308) * 10  # numpy's overflow RuntimeWarning
        return write_plots(*args, **kwargs)

    monkeypatch.setattr(_write, "write_plots", noisy)
    argv = ["report", "--preset", "paper", "--t-end", "1", "--quiet", "--no-scene"]
    assert main([*argv, "--out", str(tmp_path)]) == 0
    assert capsys.readouterr().err == ""


# -- the symbolic limit -----------------------------------------------------------------


def test_symbolic_fits_every_preset_and_refuses_exponential_chains():
    assert all(symbolic_fits(rc.preset(name)) for name in rc.preset_names())
    rotations = [rc.Module(kind, a=(1, 1, 1)) for kind in ("Rz", "Ry", "Rx") * 4]
    assert symbolic_fits(rc.Robot(rotations[:6]))
    assert not symbolic_fits(rc.Robot(rotations[:7]))
    twisted = [rc.DHLink(a=1, d=1, alpha=0.3 + 0.2 * i) for i in range(4)]
    assert symbolic_fits(rc.Robot(twisted[:3])) and not symbolic_fits(rc.Robot(twisted))
    slides = [rc.Module(kind, a=(1, 1, 1)) for kind in ("Tx", "Ty", "Tz") * 21]
    assert symbolic_fits(rc.Robot(slides))


def test_the_longest_chain_that_fits_derives_in_seconds():
    robot = rc.Robot([rc.Module(kind, a=(1, 0.5, 2)) for kind in ("Rz", "Ry", "Rx") * 2])
    assert symbolic_fits(robot)
    start = time.perf_counter()
    rc.derivation(robot, symbolic=True, lengths=True)
    assert time.perf_counter() - start < 15  # about 1.5 s; generous for a loaded machine


def test_a_chain_over_the_limit_is_refused_at_once_with_the_reports_sentence():
    robot = rc.Robot([rc.Module(kind, a=(1, 0.5, 2)) for kind in ("Rz", "Ry", "Rx") * 4])
    start = time.perf_counter()
    with pytest.raises(rc.InvalidInputError) as refused:
        rc.derivation(robot, symbolic=True, lengths=True)
    assert time.perf_counter() - start < 1
    assert refused.value.field == "symbolic"
    assert str(refused.value) == "symbolic: no symbolic matrices: " + rc.teaching.SYMBOLIC_TOO_LONG
    assert _steps.SYMBOLIC_TOO_LONG == "No symbolic matrices: " + rc.teaching.SYMBOLIC_TOO_LONG
    assert "allow_slow=True" in str(refused.value)
