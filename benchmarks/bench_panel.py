"""Kernel-side cost of the configurator's interactions, without a browser.

Run: ``PYTHONPATH=. python benchmarks/bench_panel.py``. Target: one q step of a 6-module
robot costs ≤ 2 ms in the kernel (p50), from the page's drag message to every message the
panel sends back (the header's p_EE, the editor's numbers, the 3D scene's snapshot).

Each interaction is sent as the page sends it (``form.user(key)``: a drag, a choice, a
click), so it runs the whole flow: the form's event → one action → the next state →
the views that changed. The scene is ``robotconf.scene.Scene`` (its Python side and its
widget messages, no page). Reference, in the same process: the bare core call a q step
needs, ``robot.with_q(q).at()`` (one validation and one kernel pass); the ratio says what
the panel adds to it. What the student feels, page included, is
``benchmarks/bench_panel_browser.py``.
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np

import robotconf as rc
from robotconf.panel import Configurator
from robotconf.panel import actions as act

TARGET_Q_STEP_MS = 2.0
SAMPLES = 400


def six_module_robot() -> rc.Robot:
    """Six modules of mixed kinds, as a lab exercise would use."""
    return rc.Robot(
        [
            rc.Module("Rz"),
            rc.Module("Ry", a=(0, 0, 20)),
            rc.Module("Ry", a=(30, 0, 0)),
            rc.Module("Rx", a=(10, 0, 0)),
            rc.Module("Ry", a=(5, 0, 0)),
            rc.Module("Tz", a=(0, 0, 3)),
        ],
        end_effector=(4, 0, 0),
    )


def percentiles(
    run: Callable[[int], object], samples: int = SAMPLES, warm: int = 20
) -> tuple[float, float]:
    """p50 and p95 of ``run(i)`` in milliseconds (after ``warm`` warm-up calls)."""
    for i in range(warm):
        run(i)
    times = np.empty(samples)
    for i in range(samples):
        start = time.perf_counter()
        run(i)
        times[i] = time.perf_counter() - start
    return float(np.percentile(times, 50) * 1e3), float(np.percentile(times, 95) * 1e3)


def user(panel: Configurator, key: str):  # type: ignore[no-untyped-def]
    """Control ``key`` as the page uses it, in whichever form shows it now."""
    for form in (
        panel.header.form,
        panel.editor.form,
        panel.program_tab.form,
    ):
        if key in form.control_keys():
            return form.user(key)
    raise KeyError(key)


def q_steps(panel: Configurator, tab: str) -> tuple[float, float]:
    """A drag of q3 through 97 angles with ``tab`` shown."""
    panel.apply(act.SelectTab(tab))
    angles = np.linspace(-170.0, 170.0, 97)
    slider = user(panel, "modules[2].q")
    return percentiles(lambda i: slider.drag(float(angles[i % angles.size])))


def interactions(panel: Configurator) -> dict[str, tuple[float, float]]:
    """Each click a student makes, alternating so every sample changes the state."""
    times: dict[str, tuple[float, float]] = {}
    presets = ("puma560", "paper")
    times["preset"] = percentiles(
        lambda i: user(panel, "preset").choose(presets[i % 2]), samples=40, warm=2
    )
    units = ("rad", "deg")  # the toggle's labels
    times["unit switch"] = percentiles(
        lambda i: user(panel, "angle_unit").choose(units[i % 2]), samples=40, warm=2
    )

    def add_delete(i: int) -> None:
        if i % 2 == 0:
            user(panel, "modules.add").click()
        else:
            user(panel, f"modules[{panel.robot.n - 1}].delete").click()

    times["add/delete module"] = percentiles(add_delete, samples=40, warm=2)

    def undo_redo(i: int) -> None:
        user(panel, "undo" if i % 2 == 0 else "redo").click()

    times["undo/redo"] = percentiles(undo_redo, samples=40, warm=2)
    user(panel, "preset").choose("puma560")  # a robot with a DH table to switch to

    def mode_switch(_: int) -> None:
        if panel.state.mode == "modules":
            user(panel, "mode").choose("dh")  # asks which convention
            user(panel, "mode.dh.convert").click()
        else:
            user(panel, "mode").choose("modules")

    times["mode switch + prompt"] = percentiles(mode_switch, samples=20, warm=2)
    panel.apply(act.SelectTab("program"))

    def add_move(i: int) -> None:
        if i % 8 == 7:
            user(panel, "program.clear").click()
        else:
            user(panel, "program.add").click()

    times["add program move"] = percentiles(add_move, samples=40, warm=2)
    return times


def main() -> None:
    robot = six_module_robot()
    panel = Configurator(robot)  # the real 3D scene, as in a notebook
    scene = type(panel.scene).__name__
    angles = np.deg2rad(np.linspace(-170.0, 170.0, 97))

    def reference(i: int) -> None:
        q = robot.q.copy()
        q[2] = angles[i % angles.size]
        robot.with_q(q).at()

    r50, r95 = percentiles(reference)
    print(f"scene: {scene}; kernel side only (no page); p50 / p95 in ms")
    print(f"{'bare core: robot.with_q(q).at()':38s} {r50:7.2f} {r95:7.2f}")
    for tab in ("motion", "matrices", "reach", "program"):
        p50, p95 = q_steps(panel, tab)
        label = f"q step, {tab} tab shown"
        print(f"{label:38s} {p50:7.2f} {p95:7.2f}   ({p50 / r50:.0f}× the core)")
        if tab == "motion":
            verdict = "OK" if p50 <= TARGET_Q_STEP_MS else "TOO SLOW"
            print(f"{'':38s} target p50 ≤ {TARGET_Q_STEP_MS:.0f} ms: {verdict}")
    for name, (p50, p95) in interactions(panel).items():
        print(f"{name:38s} {p50:7.2f} {p95:7.2f}")
    assert "panel" not in panel.errors, panel.errors


if __name__ == "__main__":
    main()
