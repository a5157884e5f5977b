"""How instant the configurator feels in a real browser, before and after the one-state panel.

Run: ``PYTHONPATH=. .venv/bin/python benchmarks/bench_panel_browser.py [--reps 15]``.
Needs Debian's Chromium (``/usr/bin/chromium``), the ``lab`` extra and git; it prints, it
asserts nothing. Side by side in one run: "before" is the panel of commit ``--before``
(default 56216c7: ipywidgets sliders and boxes; its tree comes from ``git archive``),
"after" is this tree. Two JupyterLab servers from this venv whose kernels are told apart
by ``PYTHONPATH`` (each prints ``robotconf.__file__``), one Chromium, a 1280 × 900 page
each showing ``rc.configurator(rc.preset("paper"))``. The pages take turns at every
repetition, so the machine's load falls on both alike.

Every interaction is a trusted input from Playwright (a key, a click, a choice), timed in
the page from the input event (a capturing listener's ``performance.now()``) to the first
DOM change or frame at which the visible result is there:

- q step: ArrowRight on module 2's q slider → the p_EE text changed, and → the 3D canvas
  changed (the page's WebGL keeps its drawing buffer so that the probe can read it);
- drag: 2 s of a drag of that slider, 60 moves a second dispatched in the page → the p_EE
  text's changes per second (the old noUiSlider gets mouse events at its handle, the new
  range input the value and ``input`` event a browser gives it: the same ±40 px sweep);
- preset paper ↔ puma560 → p_EE shows the preset's; deg ↔ rad → q2's box shows the
  converted number; undo and redo of a q edit → p_EE back; add and delete a module → the
  row appears / goes; the mode switch to DH (of a module arm that converts) → the question
  shows, then convert → the DH table shows; add a program move → its row appears.

Targets (quiet machine): q step → p_EE p50 ≤ 50 ms, drag ≥ 25 updates/s, every other
median ≤ 300 ms and none above 1 s. ``uptime``'s load is printed with the numbers.
"""

from __future__ import annotations

import argparse
import re
import subprocess
import sys
import tempfile
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from tests.browser.lab_driver import (  # noqa: E402
    CHROMIUM,
    CHROMIUM_ARGS,
    NOTEBOOK,
    choose,
    click,
    control,
    open_notebook,
    output_text,
    reveal,
    run_cell,
    serve_lab,
    wait_idle,
    write_notebook,
)

CELLS = [
    'import robotconf as rc\nprint(rc.__file__)\npanel = rc.configurator(rc.preset("paper"))',
    # A module arm that a DH table holds (modified DH): the switch asks, then converts.
    "arm = rc.Robot([rc.Module('Rz', a=(0, 0, 20)), rc.Module('Rz', a=(30, 0, 0))],"
    " end_effector=(40, 0, 0))\npanel.set_robot(arm)",
    'panel.set_robot(rc.preset("paper"))',
]
#: Longest wait for one result: the old panel took seconds for some (a miss counts this).
TIMEOUT_MS = 20_000
TARGET_Q_MS, TARGET_DRAG, TARGET_MEDIAN_MS, TARGET_MAX_MS = 50.0, 25.0, 300.0, 1000.0

#: Before any page script: WebGL canvases keep their last picture for the probe.
KEEP_PICTURE = """(() => {
  const original = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function (kind, options) {
    if (kind === "webgl" || kind === "webgl2" || kind === "experimental-webgl") {
      options = Object.assign({}, options || {}, { preserveDrawingBuffer: true });
    }
    return original.call(this, kind, options);
  };
})();"""

#: The probe. ``__bench.arm({name: [test, base]})``: ``base(p)`` is read now, and the first
#: time ``test(p, base)`` holds after the next input event is noted; ``p`` reads the page.
PROBE = """() => {
  const notebook = '.jp-NotebookPanel:not(.lm-mod-hidden) .jp-Notebook';
  const ee = () => (document.querySelector(notebook + ' .robotconf-ee') || {}).innerText || '';
  const small = document.createElement('canvas');
  small.width = 96; small.height = 64;
  const context = small.getContext('2d', { willReadFrequently: true });
  const picture = () => {
    const canvas = document.querySelector(notebook + ' [data-robotconf-scene] canvas');
    if (!canvas) return 0;
    context.drawImage(canvas, 0, 0, small.width, small.height);
    const data = context.getImageData(0, 0, small.width, small.height).data;
    let hash = 0;
    for (let k = 0; k < data.length; k += 4) hash = (hash * 31 + data[k] + 7 * data[k + 1]) | 0;
    return hash;
  };
  const all = (selector) => [...document.querySelectorAll(notebook + ' ' + selector)];
  const shown = (e) => !!e && e.offsetParent !== null;
  const p = {
    ee, picture, all, shown,
    count: (selector) => all(selector).length,
    button: (text) => all('button').some((b) => shown(b) && b.textContent.trim() === text),
  };
  const bench = (window.__bench = { p, armed: null, texts: null });
  const check = () => {
    const armed = bench.armed;
    if (!armed || armed.t0 === null) return;
    const now = performance.now();
    for (const [name, test] of Object.entries(armed.tests)) {
      if (armed.done[name] === undefined && test.holds(p, test.base)) armed.done[name] = now;
    }
  };
  for (const kind of ['keydown', 'pointerdown', 'mousedown', 'input', 'change']) {
    document.addEventListener(kind, () => {
      const armed = bench.armed;
      if (armed && armed.t0 === null) {
        armed.t0 = performance.now();
        check();
      }
    }, true);
  }
  new MutationObserver(() => {
    check();
    const text = bench.texts === null ? null : ee();
    if (text !== null && text !== bench.texts.last) {
      bench.texts.last = text;
      bench.texts.changes += 1;
    }
  }).observe(document.body, { subtree: true, childList: true, characterData: true,
                              attributes: true });
  const frame = () => { check(); requestAnimationFrame(frame); };
  requestAnimationFrame(frame);
  const compile = (source) => new Function('return (' + source + ')')();
  bench.arm = (tests) => {
    const armed = { t0: null, done: {}, tests: {} };
    for (const [name, [test, base]] of Object.entries(tests)) {
      armed.tests[name] = { holds: compile(test), base: base ? compile(base)(p) : null };
    }
    bench.armed = armed;
  };
  bench.wait = async (timeout) => {
    const armed = bench.armed;
    const names = Object.keys(armed.tests);
    const begin = performance.now();
    while (performance.now() - begin < timeout) {
      if (armed.t0 !== null && names.every((n) => armed.done[n] !== undefined)) break;
      await new Promise((resolve) => setTimeout(resolve, 5));
    }
    bench.armed = null;
    const out = {};
    for (const n of names) {
      out[n] = armed.t0 === null || armed.done[n] === undefined ? null : armed.done[n] - armed.t0;
    }
    return out;
  };
}"""

#: A drag of a slider for ``seconds``: 60 moves a second, a ±40 px triangle wave (1.5
#: sweeps a second); the times the p_EE text changed meanwhile (not its distinct texts: the
#: wave's ~21 positions would cap those at ~10 a second). ``move(dx)`` is the adapter's.
DRAG = """async ([seconds, start, move, end]) => {
  const bench = window.__bench;
  const state = new Function('return (' + start + ')')()();
  const step = new Function('return (' + move + ')')();
  bench.texts = { last: bench.p.ee(), changes: 0 };
  const begin = performance.now();
  let k = 0;
  while (performance.now() - begin < seconds * 1000) {
    const phase = (k % 40) / 40;
    step(state, 40 * (phase < 0.5 ? 4 * phase - 1 : 3 - 4 * phase));
    k += 1;
    await new Promise((resolve) => setTimeout(resolve, 1000 / 60));
  }
  const texts = bench.texts.changes;
  bench.texts = null;
  new Function('return (' + end + ')')()(state);
  return [texts, k];
}"""


@dataclass(frozen=True)
class Adapter:
    """How to do each interaction on one version of the panel, and how to see its result.

    The ``*_js`` fields are page-side sources: predicates ``(p, base) => bool`` and the
    drag's ``start() → state``, ``move(state, dx)`` and ``end(state)``.
    """

    focus_q: Callable[[Any], None]
    q_box: str  # a selector of q2's number box (the second match)
    type_q: Callable[[Any, str], None]
    preset: Callable[[Any, str], None]
    angle_unit: Callable[[Any, str], None]
    undo: Callable[[Any, bool], None]  # False: redo
    module_rows: str
    add_module: Callable[[Any, bool], None]  # False: delete the last module
    mode: Callable[[Any, str], None]
    prompt_js: str
    convert: Callable[[Any], None]
    table_js: str
    move_rows: str
    add_move: Callable[[Any], None]
    drag_js: tuple[str, str, str]


def _old_button(page: Any, text: str) -> Any:
    return page.locator(f"{NOTEBOOK} button").filter(has_text=re.compile(f"^{re.escape(text)}$"))


def _old_click(page: Any, locator: Any) -> None:
    reveal(locator.first)
    locator.first.click()


def _old_q_box(page: Any) -> Any:
    return page.locator(f"{NOTEBOOK} .widget-hbox:has(> .robotconf-module-q) input").nth(1)


def _old_type_q(page: Any, text: str) -> None:
    box = _old_q_box(page)
    reveal(box)
    box.fill(text)
    box.press("Enter")


def _old_focus_q(page: Any) -> None:
    handle = page.locator(f"{NOTEBOOK} .robotconf-module-q").nth(1).locator(".noUi-handle")
    reveal(handle)
    handle.focus()


def _old_preset(page: Any, name: str) -> None:
    select = page.locator(f"{NOTEBOOK} .robotconf-panel select").first
    reveal(select)
    select.select_option(label=name)


def _old_add_module(page: Any, add: bool) -> None:
    if add:
        _old_click(page, _old_button(page, "add module"))
    else:
        _old_click(page, page.locator(f"{NOTEBOOK} .robotconf-module-delete").last)


#: The panel of ipywidgets (commit 56216c7): sliders of noUiSlider, buttons by their text.
OLD = Adapter(
    focus_q=_old_focus_q,
    q_box=".widget-hbox:has(> .robotconf-module-q) input",
    type_q=_old_type_q,
    preset=_old_preset,
    angle_unit=lambda page, unit: _old_click(page, _old_button(page, unit)),
    undo=lambda page, undo: _old_click(
        page, page.locator(f"{NOTEBOOK} .robotconf-{'undo' if undo else 'redo'}")
    ),
    module_rows=".robotconf-module-kind",
    add_module=_old_add_module,
    mode=lambda page, mode: _old_click(page, _old_button(page, mode)),
    prompt_js="(p) => p.button('convert this robot to DH rows')",
    convert=lambda page: _old_click(page, _old_button(page, "convert this robot to DH rows")),
    table_js="(p) => p.button('add row')",
    move_rows=".robotconf-program-row",
    add_move=lambda page: _old_click(page, page.locator(f"{NOTEBOOK} .robotconf-program-add")),
    drag_js=(
        """() => {
          const handle = window.__bench.p.all('.robotconf-module-q')[1]
            .querySelector('.noUi-handle');
          const box = handle.getBoundingClientRect();
          const state = { handle, x: box.left + box.width / 2, y: box.top + box.height / 2 };
          state.fire = (target, type, dx) => target.dispatchEvent(new MouseEvent(type, {
            bubbles: true, cancelable: true, composed: true, view: window,
            clientX: state.x + dx, clientY: state.y, buttons: type === 'mouseup' ? 0 : 1 }));
          state.fire(handle, 'mousedown', 0);
          return state;
        }""",
        "(state, dx) => state.fire(document.documentElement, 'mousemove', dx)",
        "(state) => state.fire(document.documentElement, 'mouseup', 0)",
    ),
)


def _new_q_focus(page: Any) -> None:
    slider = control(page, "modules[1].q").locator("input.rc-slider")
    reveal(slider)
    slider.focus()


def _new_type_q(page: Any, text: str) -> None:
    box = control(page, "modules[1].q").locator("input.rc-box")
    reveal(box)
    box.fill(text)
    box.press("Enter")


def _new_add_module(page: Any, add: bool) -> None:
    if add:
        click(page, "modules.add")
    else:
        rows = page.locator(f"{NOTEBOOK} .rc-row.robotconf-module-row").count()
        click(page, f"modules[{rows - 1}].delete")


#: The one-state panel: one form per view, controls by their key.
NEW = Adapter(
    focus_q=_new_q_focus,
    q_box=".rc-control.robotconf-module-q input.rc-box",
    type_q=_new_type_q,
    preset=lambda page, name: choose(page, "preset", name),
    angle_unit=lambda page, unit: choose(page, "angle_unit", unit),
    undo=lambda page, undo: click(page, "undo" if undo else "redo"),
    module_rows=".rc-row.robotconf-module-row",
    add_module=_new_add_module,
    mode=lambda page, mode: choose(page, "mode", mode),
    prompt_js="""(p) => p.shown(p.all('[data-key="mode.dh.convert"]')[0])""",
    convert=lambda page: click(page, "mode.dh.convert"),
    table_js="""(p) => p.shown(p.all('[data-key="dh.add"]')[0])""",
    move_rows=".rc-row.robotconf-program-row",
    add_move=lambda page: click(page, "program.add"),
    drag_js=(
        """() => {
          const slider = window.__bench.p.all('.rc-control.robotconf-module-q input.rc-slider')[1];
          const lo = Number(slider.min), hi = Number(slider.max);
          const perPixel = (hi - lo) / slider.getBoundingClientRect().width;
          slider.dispatchEvent(new PointerEvent('pointerdown', { bubbles: true }));
          return { slider, start: Number(slider.value), perPixel };
        }""",
        """(state, dx) => {
          state.slider.value = String(state.start + dx * state.perPixel);
          state.slider.dispatchEvent(new Event('input', { bubbles: true }));
        }""",
        "(state) => state.slider.dispatchEvent(new PointerEvent('pointerup', { bubbles: true }))",
    ),
)


@dataclass
class Version:
    """One side of the comparison: its page, its adapter and what was measured."""

    name: str
    page: Any
    ui: Adapter
    times: dict[str, list[float | None]] = field(default_factory=dict)
    rates: list[float] = field(default_factory=list)

    def timed(self, action: Callable[[], None], tests: dict[str, tuple[str, str]]) -> None:
        """Arm ``tests`` (name → (test, base)), do ``action()``, note each one's time."""
        self.page.evaluate("(tests) => __bench.arm(tests)", tests)
        action()
        found = self.page.evaluate("(timeout) => __bench.wait(timeout)", TIMEOUT_MS)
        for name, ms in found.items():
            self.times.setdefault(name, []).append(ms)
        self.settle(150)  # separate inputs, each on an idle kernel

    def ee(self) -> str:
        return str(self.page.evaluate("() => __bench.p.ee()"))

    def settle(self, ms: int = 1000) -> None:
        """Wait until the kernel is idle, then ``ms`` more (the page draws what came)."""
        wait_idle(self.page, timeout=120_000)
        self.page.wait_for_timeout(ms)


def open_version(browser: Any, url: str, name: str, ui: Adapter) -> Version:
    context = browser.new_context(viewport={"width": 1280, "height": 900})
    context.add_init_script(KEEP_PICTURE)
    page = context.new_page()
    open_notebook(page, url)
    run_cell(page, 0)
    page.wait_for_selector("[data-robotconf-scene='ready']", timeout=90_000)
    page.wait_for_timeout(1500)
    print(f"{name}: the kernel's robotconf is {output_text(page, 0).splitlines()[0]}")
    page.evaluate(PROBE)
    return Version(name, page, ui)


# -- one repetition of each interaction (k: the repetition's number) ----------------------

EE_CHANGED = ("(p, base) => p.ee() !== base", "(p) => p.ee()")
PICTURE_CHANGED = ("(p, base) => p.picture() !== base", "(p) => p.picture()")


def q_step(v: Version, k: int) -> None:
    v.ui.focus_q(v.page)
    tests = {"q step → p_EE": EE_CHANGED, "q step → canvas": PICTURE_CHANGED}
    v.timed(lambda: v.page.keyboard.press("ArrowRight"), tests)


def drag(v: Version, seconds: float = 2.0) -> None:
    texts, _ = v.page.evaluate(DRAG, [seconds, *v.ui.drag_js])
    v.rates.append(texts / seconds)
    v.settle()


def preset(v: Version, k: int, shown: dict[str, str]) -> None:
    name = ("puma560", "paper")[k % 2]
    test = (f"(p) => p.ee() === {shown[name]!r}", "")
    v.timed(lambda: v.ui.preset(v.page, name), {"preset → p_EE": test})


def angle_unit(v: Version, k: int, shown: dict[str, str]) -> None:
    unit = ("rad", "deg")[k % 2]
    test = (f"(p) => (p.all({v.ui.q_box!r})[1] || {{}}).value === {shown[unit]!r}", "")
    v.timed(lambda: v.ui.angle_unit(v.page, unit), {"deg ↔ rad → q box": test})


def undo_redo(v: Version, k: int, shown: tuple[str, str]) -> None:
    undo = k % 2 == 0
    test = (f"(p) => p.ee() === {shown[0 if undo else 1]!r}", "")
    name = "undo → p_EE" if undo else "redo → p_EE"
    v.timed(lambda: v.ui.undo(v.page, undo), {name: test})


def module(v: Version, k: int) -> None:
    add = k % 2 == 0
    rows = f"p.count({v.ui.module_rows!r})"
    test = (f"(p, base) => {rows} {'>' if add else '<'} base", f"(p) => {rows}")
    name = "add module → row" if add else "delete module → row gone"
    v.timed(lambda: v.ui.add_module(v.page, add), {name: test})


def dh_mode(v: Version, k: int) -> None:
    v.timed(lambda: v.ui.mode(v.page, "DH table"), {"mode → DH question": (v.ui.prompt_js, "")})
    v.timed(lambda: v.ui.convert(v.page), {"convert → DH table": (v.ui.table_js, "")})
    v.ui.undo(v.page, True)  # back to the module arm, for the next repetition
    v.settle()
    v.ui.mode(v.page, "Modules")
    v.settle()


def program_move(v: Version, k: int) -> None:
    rows = f"p.count({v.ui.move_rows!r})"
    test = (f"(p, base) => {rows} > base", f"(p) => {rows}")
    v.timed(lambda: v.ui.add_move(v.page), {"add program move → row": test})


# -- the run and the table ----------------------------------------------------------------


def interleave(versions: list[Version], reps: int, step: Callable[..., None], *args: Any) -> None:
    for k in range(reps):
        for v in versions:
            step(v, k, *(a[v.name] if isinstance(a, dict) else a for a in args))


def measure(versions: list[Version], reps: int) -> None:
    interleave(versions, 3, q_step)  # warm-up: the first use of every path
    for v in versions:
        v.times.clear()
    interleave(versions, reps, q_step)
    for _ in range(3):
        for v in versions:
            drag(v)
    shown: dict[str, Any] = {}
    for v in versions:  # what each page shows for each preset and unit: the targets
        shown[v.name] = {}
        for name in ("puma560", "paper"):
            v.ui.preset(v.page, name)
            v.settle()
            shown[v.name][name] = v.ee()
    interleave(versions, 2 * reps, preset, shown)
    units: dict[str, Any] = {}
    for v in versions:
        v.ui.type_q(v.page, "30")
        v.settle()
        units[v.name] = {}
        for unit in ("rad", "deg"):
            v.ui.angle_unit(v.page, unit)
            v.settle()
            units[v.name][unit] = v.page.evaluate("(s) => __bench.p.all(s)[1].value", v.ui.q_box)
    interleave(versions, 2 * reps, angle_unit, units)
    edits: dict[str, Any] = {}
    for v in versions:
        before = v.ee()
        v.ui.type_q(v.page, "60")
        v.settle()
        edits[v.name] = (before, v.ee())
    interleave(versions, 2 * reps, undo_redo, edits)
    interleave(versions, 2 * reps, module)
    for v in versions:
        run_cell(v.page, 1)
        v.settle()
    interleave(versions, reps, dh_mode)
    for v in versions:
        run_cell(v.page, 2)
        v.settle()
        tab = v.page.locator(f"{NOTEBOOK} .lm-TabBar-tab", has_text="Program").first
        reveal(tab)
        tab.click()
        v.settle()
    interleave(versions, reps, program_move)


def load() -> str:
    return subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()


def _ms(v: Version, name: str) -> np.ndarray:
    return np.array([TIMEOUT_MS if t is None else t for t in v.times.get(name, [])], dtype=float)


def report(old: Version, new: Version) -> None:
    print(
        f"\n{'interaction (ms)':28s} {'before p50   p95   max':>24s} {'after p50   p95   max':>24s}"
    )
    for name in new.times:
        cells = [
            f"{np.percentile(d, 50):6.0f} {np.percentile(d, 95):5.0f} {d.max():5.0f}"
            for d in (_ms(old, name), _ms(new, name))
        ]
        ratio = np.median(_ms(new, name)) / max(np.median(_ms(old, name)), 1e-9)
        print(f"{name:28s} {cells[0]:>24s} {cells[1]:>24s}   after/before {ratio:5.2f}")
    rates = [float(np.median(v.rates)) for v in (old, new)]
    print(
        f"{'2 s drag → p_EE changes/s':28s} {rates[0]:21.1f} /s {rates[1]:21.1f} /s"
        f"   after/before {rates[1] / max(rates[0], 1e-9):5.2f}"
    )
    for v in (old, new):
        for name, found in v.times.items():
            if missed := sum(t is None for t in found):
                print(f"  {v.name}: {name}: {missed} of {len(found)} missed ({TIMEOUT_MS} ms)")
    q = float(np.median(_ms(new, "q step → p_EE")))
    others = [n for n in new.times if not n.startswith("q step")]
    median = max(float(np.median(_ms(new, n))) for n in others)
    worst = max(float(_ms(new, n).max()) for n in others)
    verdict = {True: "OK", False: "MISSED"}
    print(
        f"targets, after: q step → p_EE p50 {q:.0f} ≤ {TARGET_Q_MS:.0f} ms "
        f"{verdict[q <= TARGET_Q_MS]}; drag {rates[1]:.1f} ≥ {TARGET_DRAG:.0f}/s "
        f"{verdict[rates[1] >= TARGET_DRAG]}; other medians ≤ {TARGET_MEDIAN_MS:.0f} ms "
        f"(largest {median:.0f}) {verdict[median <= TARGET_MEDIAN_MS]}; none above "
        f"{TARGET_MAX_MS:.0f} ms (largest {worst:.0f}) {verdict[worst <= TARGET_MAX_MS]}"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reps", type=int, default=15, help="repetitions per interaction")
    parser.add_argument("--before", default="56216c7", help="the commit of the old panel")
    args = parser.parse_args()
    from playwright.sync_api import sync_playwright

    print(f"load at the start: {load()}")
    with tempfile.TemporaryDirectory(prefix="bench-panel-") as folder:
        base = Path(folder)
        old_tree = base / "before-tree"
        old_tree.mkdir()
        archive = subprocess.run(
            ["git", "-C", str(ROOT), "archive", args.before], capture_output=True, check=True
        )
        subprocess.run(["tar", "-x", "-C", str(old_tree)], input=archive.stdout, check=True)
        roots = {"before": base / "before", "after": base / "after"}
        for root in roots.values():
            root.mkdir()
            write_notebook(root / "bench.ipynb", CELLS)
        with (
            serve_lab(roots["before"], {"PYTHONPATH": str(old_tree)}) as old_lab,
            serve_lab(roots["after"], {"PYTHONPATH": str(ROOT)}) as new_lab,
            sync_playwright() as playwright,
        ):
            browser = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
            try:
                versions = [
                    open_version(browser, old_lab.url("bench.ipynb"), "before", OLD),
                    open_version(browser, new_lab.url("bench.ipynb"), "after", NEW),
                ]
                measure(versions, args.reps)
                report(*versions)
            finally:
                browser.close()
    print(f"load at the end: {load()}")


if __name__ == "__main__":
    main()
