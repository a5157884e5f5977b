"""``robotconf report`` runs a setup file's robot program: its motion, moves and check."""

from __future__ import annotations

import csv

import pytest

import robotconf as rc
from robotconf.cli import main


def _times(path) -> list[float]:
    """The time column of a dva.csv (below its header rows)."""
    with open(path, newline="") as handle:
        rows = list(csv.reader(handle))
    times = []
    for row in rows:
        try:
            times.append(float(row[0]))
        except ValueError:
            continue  # a header row
    return times


def _setup_file(tmp_path, **program_options):
    robot = rc.preset("paper")
    program = rc.Program(
        robot,
        [rc.PTP(q=[0, 0.3, -0.5]), rc.Wait(0.5), rc.PTP(q=[0.2, 0.0, 0.0])],
        **program_options,
    )
    path = tmp_path / "cell.json"
    rc.Setup(robot, signals={"q3": rc.signals.Sine(amplitude=0.1)}, program=program).save(path)
    return path, program


def test_the_report_runs_the_program_and_lists_its_moves(tmp_path, capsys):
    path, program = _setup_file(tmp_path)
    out = tmp_path / "out"
    code = main(["report", str(path), "--out", str(out), "--dt", "0.01", "--no-scene"])
    assert code == 0, capsys.readouterr().err
    printed = capsys.readouterr().out
    assert "ran the program: 3 moves" in printed and "0 violations" in printed
    # The DVA table spans the program: 0 … its duration, every 0.01 s and its end.
    times = _times(out / "dva.csv")
    assert times[0] == 0.0 and times[-1] == pytest.approx(program.duration, abs=1e-12)
    again = rc.load_program(out / "program.json")
    assert again.moves == program.moves
    summary = (out / "report.md").read_text()
    assert "Program: 3 moves" in summary and "Check: no violations" in summary
    assert "program.json" in summary


def test_a_violation_is_written_into_the_report(tmp_path, capsys):
    path, _ = _setup_file(tmp_path)
    robot = rc.preset("paper")
    # Beyond q3's range (the paper arm's joints turn ±150°): the check names the move.
    setup = rc.load_setup(path)
    far = rc.Program(robot, [rc.PTP(q=[0, 0, 3.0])])
    rc.Setup(setup.robot, program=far).save(path)
    out = tmp_path / "out"
    args = ["report", str(path), "--out", str(out), "--dt", "0.01", "--quiet", "--no-scene"]
    assert main(args) == 0
    found = far.check(dt=0.01)
    assert len(found) >= 1 and found[0].kind == "joint limit"
    summary = (out / "report.md").read_text()
    s = "s" * (len(found) != 1)
    assert f"Check: {len(found)} violation{s}:" in summary
    assert "- move 1 (PTP): " in summary and "q3" in summary


def test_signals_cannot_be_mixed_with_the_program(tmp_path, capsys):
    path, _ = _setup_file(tmp_path)
    code = main(["report", str(path), "--out", str(tmp_path / "o"), "--signal", "q1=0.5"])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "--no-program" in err


def test_no_program_runs_the_files_signals(tmp_path, capsys):
    path, _ = _setup_file(tmp_path)
    out = tmp_path / "out"
    code = main(
        ["report", str(path), "--out", str(out), "--no-program", "--t-end", "1", "--quiet"]
        + ["--no-scene", "--no-symbolic"]
    )
    assert code == 0, capsys.readouterr().err
    assert not (out / "program.json").exists()
    times = _times(out / "dva.csv")
    assert times[0] == 0.0 and times[-1] == 1.0
