"""Time of ``write_report`` for the paper robot, step by step, against an earlier version.

Run: ``PYTHONPATH=. MPLBACKEND=Agg python benchmarks/bench_report.py`` (options:
``--reference REV`` the git revision to compare with, by default where this branch left
main; ``--repeat 5``; ``--cold``).

Target: the whole report of the paper robot (q3 = Simulink's default sawtooth, t_end =
10 s, dt = 0.01 s, symbolic matrices and scene included), as ``robotconf report`` and
the panel's report download write it, in ≤ 3 s on a quiet machine; ≤ 1.5 s leaves room.

Reference: the same call of the ``--reference`` revision's ``robotconf`` (extracted with
``git archive`` and imported under another name), in the same process, each repetition
run right after the current one so that both see the same load. Each step is timed by
the ``say`` progress lines; the current version also says each figure. Times are the
best of ``--repeat`` runs after a warm-up (imports, the symbolic derivation's cache), in
wall-clock seconds and in this process's CPU seconds: on a busy shared machine the CPU
time is much closer than the wall clock to what a quiet machine's wall clock shows.
``--cold`` also runs each version once in a fresh interpreter, imports included, as the
command line does.
"""

from __future__ import annotations

import argparse
import importlib
import os
import shutil
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path
from types import ModuleType

import robotconf

TARGET_S = 3.0
REFERENCE_PACKAGE = "robotconf_reference"
ROOT = Path(__file__).resolve().parent.parent

Clock = tuple[float, float]  # wall, cpu


def now() -> Clock:
    return time.perf_counter(), time.process_time()


def extract(revision: str, into: Path) -> ModuleType | None:
    """``revision``'s robotconf package, importable as :data:`REFERENCE_PACKAGE`."""
    archive = into / "reference.tar"
    try:
        with archive.open("wb") as file:
            subprocess.run(
                ["git", "archive", revision, "robotconf"],
                cwd=ROOT,
                stdout=file,
                stderr=subprocess.PIPE,
                check=True,
            )
    except (OSError, subprocess.CalledProcessError) as error:
        print(f"no reference: git archive {revision} failed ({error})")
        return None
    with tarfile.open(archive) as tar:
        tar.extractall(into, filter="data")
    (into / "robotconf").rename(into / REFERENCE_PACKAGE)
    sys.path.insert(0, str(into))
    return importlib.import_module(REFERENCE_PACKAGE)


def fork_point() -> str:
    """The commit where HEAD left main (main itself when git cannot tell)."""
    try:
        found = subprocess.run(
            ["git", "merge-base", "HEAD", "main"],
            cwd=ROOT,
            capture_output=True,
            text=True,
            check=True,
        )
    except (OSError, subprocess.CalledProcessError):
        return "main"
    return found.stdout.strip()[:10] or "main"


def one_report(package: ModuleType, out: Path) -> list[tuple[str, Clock]]:
    """Run ``write_report`` of ``package`` once: (progress line, clock when said), the
    first one at the call."""
    from_settings = importlib.import_module(f"{package.__name__}.motion").SimulationSettings
    report = importlib.import_module(f"{package.__name__}.report").write_report
    robot = package.preset("paper")
    signals = {"q3": package.signals.RepeatingSequence()}
    marks: list[tuple[str, Clock]] = [("start", now())]
    report(
        robot,
        signals,
        from_settings(10.0, dt=0.01),
        out,
        say=lambda line: marks.append((line, now())),
    )
    return marks


def steps(marks: list[tuple[str, Clock]]) -> dict[str, Clock]:
    """Time of each progress line since the one before, keyed by the step (``[3/7]``),
    a figure's line by its file (``[5/7] dva_M2.png``), the figures' step of a version
    that says it once as ``[5/7] figures``; ``total`` is the whole call."""
    out: dict[str, Clock] = {}
    for (_, before), (line, after) in zip(marks, marks[1:], strict=False):
        words = line.split()
        key = words[0]
        if key.startswith("[5/"):
            key += f" {words[1]}" if "(figure" in line else " figures"
        out[key] = (after[0] - before[0], after[1] - before[1])
    first, last = marks[0][1], marks[-1][1]
    out["total"] = (last[0] - first[0], last[1] - first[1])
    return out


def best(runs: list[dict[str, Clock]]) -> dict[str, Clock]:
    keys = {key: None for run in runs for key in run}
    return {
        key: (
            min(run[key][0] for run in runs if key in run),
            min(run[key][1] for run in runs if key in run),
        )
        for key in keys
    }


def cold(package_dir: Path, name: str) -> Clock:
    """One report in a fresh interpreter, imports included (wall, cpu of the child)."""
    code = (
        "import time, tempfile\n"
        "t0 = time.perf_counter(); c0 = time.process_time()\n"
        f"import {name} as rc\n"
        f"from {name}.report import write_report\n"
        f"from {name}.motion import SimulationSettings\n"
        "with tempfile.TemporaryDirectory() as out:\n"
        "    write_report(rc.preset('paper'), {'q3': rc.signals.RepeatingSequence()},\n"
        "                 SimulationSettings(10.0, dt=0.01), out)\n"
        "print(time.perf_counter() - t0, time.process_time() - c0)\n"
    )
    env = {**os.environ, "PYTHONPATH": str(package_dir), "MPLBACKEND": "Agg"}
    result = subprocess.run(
        [sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True
    )
    wall, cpu = (float(word) for word in result.stdout.split())
    return wall, cpu


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--reference",
        default=None,
        help="git revision to compare with (default: where HEAD left main)",
    )
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--cold", action="store_true", help="also time fresh interpreters")
    args = parser.parse_args()
    if args.reference is None:
        args.reference = fork_point()
    work = Path(tempfile.mkdtemp(prefix="bench_report_"))
    try:
        reference = extract(args.reference, work)
        packages = {"current": robotconf} | ({} if reference is None else {"reference": reference})
        runs: dict[str, list[dict[str, Clock]]] = {name: [] for name in packages}
        for repetition in range(args.repeat + 1):  # the first one warms up
            for name, package in packages.items():
                out = work / f"{name}{repetition}"
                marks = one_report(package, out)
                shutil.rmtree(out)
                if repetition:
                    runs[name].append(steps(marks))
        load = os.getloadavg()
        print(
            f"write_report, paper robot, q3 sawtooth, t_end 10 s, dt 0.01 s; best of "
            f"{args.repeat}; load average {load[0]:.2f} on {os.cpu_count()} cores"
        )
        report(best(runs["current"]), best(runs["reference"]) if reference else None, args)
        if args.cold:
            current = cold(ROOT, "robotconf")
            line = f"cold (fresh interpreter, imports included): current {fmt(current)}"
            if reference is not None:
                line += f", reference {fmt(cold(work, REFERENCE_PACKAGE))}"
            print(line)
    finally:
        shutil.rmtree(work, ignore_errors=True)


def fmt(clock: Clock) -> str:
    return f"{clock[0]:6.3f} s wall {clock[1]:6.3f} s cpu"


def report(
    current: dict[str, Clock], reference: dict[str, Clock] | None, args: argparse.Namespace
) -> None:
    header = f"{'step':<22}{'current (wall, cpu)':>28}"
    if reference is not None:
        header += f"{args.reference + ' (wall, cpu)':>30}{'ratio (cpu)':>13}"
    print(header)
    for key, clock in current.items():
        row = f"{key:<22}{fmt(clock):>28}"
        if reference is not None and key in reference:
            before = reference[key]
            ratio = before[1] / clock[1] if clock[1] > 0 else float("inf")
            row += f"{fmt(before):>30}{ratio:>12.1f}×"
        print(row)
    figures = [key for key in current if key.startswith("[5/")]
    wall = sum(current[key][0] for key in figures)
    cpu = sum(current[key][1] for key in figures)
    row = f"{'[5/7] figures, all':<22}{fmt((wall, cpu)):>28}"
    before = next((reference[key] for key in reference or {} if key.startswith("[5/")), None)
    if before is not None:
        row += f"{fmt(before):>30}{before[1] / cpu:>12.1f}×"
    print(row)
    total = current["total"]
    status = "OK" if total[1] <= TARGET_S else "OVER TARGET"
    print(f"total cpu {total[1]:.2f} s (target ≤ {TARGET_S:.0f} s on a quiet machine) {status}")


if __name__ == "__main__":
    main()
