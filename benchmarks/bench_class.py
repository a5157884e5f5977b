"""A class on one server: N simulated students, each driving their own kernel.

Run: ``PYTHONPATH=. .venv/bin/python benchmarks/bench_class.py [--students 1 10 30]``.
Target: the largest class this machine holds with every interactive step's p95 ≤ 1 s.

Each student is a real IPython kernel (as JupyterHub gives each student one), driven
through the Jupyter kernel protocol (jupyter_client) the way a notebook front end drives
it: execute requests on the shell channel, every reply and output read. The students
arrive spread over ``--arrival`` seconds, open the configurator, then work in rounds at
a person's pace (about one action a second): move q1 ``--moves`` times, press Run on
the Motion tab (Simulink's sawtooth on q3, the DVA table and plots), check an answer
with ``rc.check_matrix``. Measured per step: p50 / p95 of the time from request to
reply (a step's first time in a kernel, which imports pandas, matplotlib or sympy, is
reported on its own; the target applies to the later ones and to every q move), errors
(an error reply, an error output or a timeout), and each kernel's memory after the work
(resident and unique set sizes).

What it leaves out: the browser (drawing the 3D pane and widgets runs on the student's
computer, not the server), JupyterLab's own server per student (measured separately for
docs/hub.md) and the network. Results go to benchmarks/results/bench_class.json.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import random
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import psutil
from jupyter_client.manager import AsyncKernelManager

TARGET_P95_S = 1.0

#: The student's actions, as code a notebook cell would run: the panel's public face only
#: (``rc.configurator``, widget values, the Run button, ``panel.robot``).
STEP_CODE = {
    "open panel": 'import robotconf as rc\npanel = rc.configurator(rc.preset("paper"))',
    # What the page sends when the student types into q1's box and picks q3's signal.
    "move q": 'panel.editor.form.user("modules[0].q").type("{angle}")',
    "run": (
        'panel.motion_tab.form.user("signals.q3").choose("RepeatingSequence")\n'
        'panel.motion_tab.form.user("run").click()\n'
        "assert panel.motion is not None and not panel.errors, panel.errors"
    ),
    "check answer": (
        "_check = rc.check_matrix(\n"
        '    "[[cos(q1), -sin(q1), 0, 0], [sin(q1), cos(q1), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",\n'
        '    rc.expected_matrix(panel.robot, "A1"),\n'
        ")\n"
        "assert _check.ok, _check"
    ),
}
INTERACTIVE = ("move q", "run", "check answer")


@dataclass
class Student:
    """One simulated student: their kernel, timings and errors."""

    name: str
    manager: AsyncKernelManager
    client: Any = None
    times: dict[str, list[float]] = field(default_factory=dict)
    errors: list[str] = field(default_factory=list)

    async def execute(self, step: str, code: str, timeout: float = 300.0) -> None:
        """Run ``code`` as a cell; time it from request to reply under ``step``."""
        start = time.perf_counter()
        msg_id = self.client.execute(code, store_history=False)
        try:
            while True:
                reply = await self.client.get_shell_msg(timeout=timeout)
                if reply["parent_header"].get("msg_id") == msg_id:
                    break
        except Exception as error:  # queue.Empty on timeout
            self.errors.append(f"{step}: no reply ({type(error).__name__})")
            return
        # A step's first time in a kernel imports what it needs (pandas, matplotlib,
        # sympy): reported on its own, as the wait a student sees once.
        first = f"{step}, first"
        key = first if step in INTERACTIVE and first not in self.times else step
        self.times.setdefault(key, []).append(time.perf_counter() - start)
        content = reply["content"]
        if content["status"] != "ok":
            self.errors.append(f"{step}: {content.get('ename')}: {content.get('evalue')}")

    async def drain_outputs(self) -> None:
        """Read the kernel's outputs (as a front end does); note error outputs."""
        while True:
            try:
                message = await self.client.get_iopub_msg(timeout=1.0)
            except Exception:  # queue.Empty: nothing published this second
                continue
            if message["msg_type"] == "error":
                self.errors.append(f"output: {message['content'].get('ename')}")


async def one_student(student: Student, delay: float, rounds: int, moves: int, seed: int) -> None:
    """A student's session: arrive, open the panel, work ``rounds`` rounds at a person's pace."""
    rng = random.Random(seed)
    await asyncio.sleep(delay)
    start = time.perf_counter()
    await student.manager.start_kernel()
    student.client = student.manager.client()
    student.client.start_channels()
    await student.client.wait_for_ready(timeout=300)
    student.times["start kernel"] = [time.perf_counter() - start]
    drain = asyncio.create_task(student.drain_outputs())
    await student.execute("open panel", STEP_CODE["open panel"])
    for _ in range(rounds):
        for _ in range(moves):
            await asyncio.sleep(rng.uniform(0.5, 1.5))  # a person looking at the result
            angle = rng.choice(range(-170, 171, 5))
            await student.execute("move q", STEP_CODE["move q"].format(angle=float(angle)))
        await asyncio.sleep(rng.uniform(1.0, 3.0))
        await student.execute("run", STEP_CODE["run"])
        await asyncio.sleep(rng.uniform(1.0, 3.0))
        await student.execute("check answer", STEP_CODE["check answer"])
    drain.cancel()


def kernel_memory(manager: AsyncKernelManager) -> tuple[float, float, float]:
    """Resident, unique and proportional set sizes of a kernel's process, in MiB (the
    proportional size shares each library page among the kernels that map it)."""
    process = psutil.Process(manager.provisioner.process.pid)  # type: ignore[union-attr]
    info = process.memory_full_info()
    return info.rss / 2**20, info.uss / 2**20, getattr(info, "pss", info.rss) / 2**20


async def run_class(n: int, arrival: float, rounds: int, moves: int) -> dict[str, Any]:
    """Simulate a class of ``n``; returns the figures for the report."""
    students = [Student(f"s{i}", AsyncKernelManager(kernel_name="python3")) for i in range(n)]
    load_before = os.getloadavg()
    start = time.perf_counter()
    delays = np.linspace(0.0, arrival, n) if n > 1 else [0.0]
    try:
        await asyncio.gather(
            *(
                one_student(s, float(d), rounds, moves, seed=i)
                for i, (s, d) in enumerate(zip(students, delays, strict=True))
            )
        )
        wall = time.perf_counter() - start
        memory = np.array([kernel_memory(s.manager) for s in students])
        load_after = os.getloadavg()
    finally:
        for s in students:
            if s.client is not None:
                s.client.stop_channels()
        await asyncio.gather(*(s.manager.shutdown_kernel(now=True) for s in students))

    steps: dict[str, dict[str, float]] = {}
    firsts = [f"{step}, first" for step in INTERACTIVE]
    for step in ("start kernel", "open panel", *firsts, *INTERACTIVE):
        values = np.concatenate([s.times.get(step, []) for s in students])
        if values.size:
            steps[step] = {
                "count": int(values.size),
                "p50_s": float(np.percentile(values, 50)),
                "p95_s": float(np.percentile(values, 95)),
                "max_s": float(values.max()),
            }
    errors = [f"{s.name} {e}" for s in students for e in s.errors]
    return {
        "students": n,
        "wall_s": wall,
        "steps": steps,
        "errors": errors,
        "kernel_rss_mib_mean": float(memory[:, 0].mean()),
        "kernel_uss_mib_mean": float(memory[:, 1].mean()),
        "kernel_pss_mib_mean": float(memory[:, 2].mean()),
        "load_average_before": load_before,
        "load_average_after": load_after,
        "interactive_p95_ok": all(
            steps.get(step, {"p95_s": np.inf})["p95_s"] <= TARGET_P95_S for step in INTERACTIVE
        )
        and not errors,
    }


def report(result: dict[str, Any]) -> None:
    n = result["students"]
    load = ", ".join(f"{x:.2f}" for x in result["load_average_before"])
    print(f"\n{n} student(s): {result['wall_s']:.0f} s, load average before: {load}")
    print(f"  {'step':<20}{'count':>7}{'p50 s':>9}{'p95 s':>9}{'max s':>9}")
    for step, figures in result["steps"].items():
        print(
            f"  {step:<20}{figures['count']:>7}{figures['p50_s']:>9.3f}"
            f"{figures['p95_s']:>9.3f}{figures['max_s']:>9.3f}"
        )
    print(
        f"  memory per kernel: {result['kernel_rss_mib_mean']:.0f} MiB resident, "
        f"{result['kernel_uss_mib_mean']:.0f} MiB its own (USS), "
        f"{result['kernel_pss_mib_mean']:.0f} MiB with its share of libraries (PSS)"
    )
    print(f"  errors: {len(result['errors'])} {result['errors'][:5]}")
    verdict = "yes" if result["interactive_p95_ok"] else "no"
    print(f"  every interactive step p95 <= {TARGET_P95_S:g} s, no errors: {verdict}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--students", type=int, nargs="+", default=[1, 10, 30])
    parser.add_argument("--arrival", type=float, default=30.0, help="s over which they arrive")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--moves", type=int, default=5, help="q moves per round")
    parser.add_argument(
        "--out", type=Path, default=Path(__file__).parent / "results" / "bench_class.json"
    )
    args = parser.parse_args()
    machine = f"{psutil.cpu_count()} CPUs, {psutil.virtual_memory().total / 2**30:.0f} GiB"
    print(f"Python {sys.version.split()[0]}, {machine}; students arrive over {args.arrival:g} s, "
          f"{args.rounds} rounds of {args.moves} q moves, Run, check")  # fmt: skip
    results = []
    for n in args.students:
        result = asyncio.run(run_class(n, args.arrival, args.rounds, args.moves))
        report(result)
        results.append(result)
    held = [r["students"] for r in results if r["interactive_p95_ok"]]
    print(f"\nLargest class measured with every interactive p95 <= {TARGET_P95_S:g} s: "
          f"{max(held) if held else 'none'}")  # fmt: skip
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(results, indent=2), encoding="utf-8")


if __name__ == "__main__":
    main()
