"""Worst-case time of the homework checker, ``rc.check_matrix``, per class of answer.

Run: ``PYTHONPATH=. python benchmarks/bench_checker.py`` (``--quick``: one run per case).
Target: every call ≤ 2 s for a 4×4 answer (the documented bound of ``check_matrix``).

Classes, all against the paper robot (``rc.preset("paper")``, symbolic ``q1 … q3``):

- **correct**: its A1, A2, A3, M1, M2, M3 and p_EE, typed as text, written differently
  (expanded, with ``cos(q2 + q3)``, times ``sin² + cos²``) or as sympy matrices;
- **wrong**: the usual mistakes (wrong order, sign error, transposed rotation, missing
  offset, a wrong entry);
- **hostile**: answers built to make a checker hang or run out of memory, each as a 1×1
  answer and as entry (3,4) of an otherwise correct M3.

Every call runs in a forked child under a time limit (``--timeout``) and an address-space
limit, so the script also measures a checker that hangs (``timeout``) or runs out of
memory; the time printed is measured inside the child, around ``check_matrix`` alone.
"""

from __future__ import annotations

import argparse
import multiprocessing
import resource
import time
from collections.abc import Callable
from typing import Any

import robotconf as rc
from robotconf.teaching import check_matrix, expected_matrix

TARGET_SECONDS = 2.0
CHILD_MEMORY = 1536 * 1024**2  # address space a child may add to what it has mapped

M3_TEXT = (
    "[[cos(q1)*cos(q2 + q3), -sin(q1), cos(q1)*sin(q2 + q3), 30*cos(q1)*cos(q2)],"
    " [sin(q1)*cos(q2 + q3), cos(q1), sin(q1)*sin(q2 + q3), 30*sin(q1)*cos(q2)],"
    " [-sin(q2 + q3), 0, cos(q2 + q3), ENTRY],"
    " [0, 0, 0, 1]]"
)


def balanced_sum(terms: list[str]) -> str:
    """``(a+b)+(c+d)…``: a long sum whose syntax tree stays within the parser's depth."""
    while len(terms) > 1:
        pairs = [terms[i : i + 2] for i in range(0, len(terms), 2)]
        terms = [f"({'+'.join(pair)})" if len(pair) == 2 else pair[0] for pair in pairs]
    return terms[0]


#: Equals 1, but its numbers overflow (1e400 · 1e-400 is NaN in floating point): only
#: algebra can tell, and the checker does it within its budget.
ONE_BY_ALGEBRA = "(1e200*cos(q2)+1e200*sin(q2))**2/(1e200*1e200) - 2*sin(q2)*cos(q2)"


def text_cases() -> dict[str, str]:
    """Hostile answers as a student could type them (symbols of the paper robot only)."""
    terms = [f"{i}*q{i % 3 + 1}**{i % 9 + 1}" for i in range(1, 1400)]
    return {
        "sin(1000000*q1)": "sin(1000000*q1)",
        "tan(1000000*q1)": "tan(1000000*q1)",
        "((q1+1)**64+1)**64": "((q1+1)**64+1)**64",
        "1+sqrt(-1)": "1+sqrt(-1)",
        "5100-digit integer": "1" * 5100,
        "5000 hex digits": "0x" + "f" * 5000,
        "power products q1**64*…": "*".join(["q1**64"] * 8),
        "nested powers": "((((q1+1)**8+1)**8+1)**8+1)**8",
        "sin(sin(sin(…))) ×36": "sin(" * 36 + "q1" + ")" * 36,
        "2 + sqrt(sqrt(…)) ×34": "2 + " + "sqrt(" * 34 + "q1**2+1" + ")" * 34,
        "parentheses ×37": "(" * 37 + "q1" + ")" * 37,
        "trig powers": "cos(q1*(q2+q3))**64 + sin(999999*q2)**64",
        "huge rational": "(3**40)**64/(2**63)**64",
        "1e308*10": "1e308*10",
        "overflow to NaN": "(1e20*q1+1)**60/(1e300*1e300*1e300*1e300)",
        "equal by algebra only": ONE_BY_ALGEBRA,
        "algebra near the budget": f"({ONE_BY_ALGEBRA})*(1 + cos(q2+q3)**3) - cos(q2+q3)**3",
        "1/(sin²+cos²−1)": "1/(cos(q1)**2+sin(q1)**2-1)",
        "tan sums to the 8th": "tan(q1+q2+q3)**8*tan(q1-q2)**8",
        "(-8)**(1/3)": "(-8)**(1/3)",
        "sqrt(q1-100)": "sqrt(q1-100)",
        "1400-term sum": balanced_sum(terms),
    }


#: Text cases equal to 1: in M3 they become ``… + 19 - 30*sin(q2)``, the right entry.
EQUAL_TO_ONE = ("equal by algebra only", "algebra near the budget")


def in_m3(name: str, entry: str) -> str:
    """M3 typed right except entry (3,4), which is ``entry``."""
    value = f"({entry}) + 19 - 30*sin(q2)" if name in EQUAL_TO_ONE else entry
    return M3_TEXT.replace("ENTRY", value)


def all_entries_need_algebra(robot: rc.Robot) -> str:
    """M3 with every entry times ONE_BY_ALGEBRA: sixteen entries the numbers cannot judge."""
    import sympy

    rows = expected_matrix(robot, "M3").matrix.tolist()
    return sympy.sstr([[f"({ONE_BY_ALGEBRA})*({e})" for e in row] for row in rows]).replace("'", "")


def at_the_cap() -> list[list[Any]]:
    """Sixteen wrong sympy entries of about 2 470 parts each: just under the whole-answer cap."""
    import sympy

    q1, q2 = sympy.symbols("q1 q2", real=True)

    def entry(j: int) -> Any:  # built unevaluated: sympy would take seconds
        angles = [sympy.Add(q1, i * q2, evaluate=False) for i in range(1, 310)]
        terms = [
            sympy.Mul(i + j, sympy.sin(a, evaluate=False), evaluate=False)
            for i, a in enumerate(angles)
        ]
        return sympy.Add(*terms, evaluate=False)

    return [[entry(4 * r + c) for c in range(4)] for r in range(4)]


def sympy_cases() -> dict[str, Callable[[], Any]]:
    """Hostile answers only a sympy object can carry (built lazily, in the child)."""
    import mpmath
    import sympy

    q1 = sympy.Symbol("q1", real=True)
    k = sympy.Symbol("k", integer=True)

    def deep() -> Any:
        expr = q1
        for _ in range(3000):  # unevaluated: sympy alone would take a minute to build it
            expr = sympy.sin(expr, evaluate=False)
        return expr

    def long_sum() -> Any:  # built unevaluated: sympy would take seconds
        terms = [
            sympy.Mul(i, sympy.Pow(q1, i, evaluate=False), evaluate=False) for i in range(1, 20_000)
        ]
        return sympy.Add(*terms, evaluate=False)

    return {
        "q1**(10**6)": lambda: q1 ** (10**6),
        "exp(exp(exp(q1)))": lambda: sympy.exp(sympy.exp(sympy.exp(q1))),
        "factorial(q1)": lambda: sympy.factorial(q1),
        "gamma(q1)": lambda: sympy.gamma(q1),
        "10**5100": lambda: sympy.Integer(10) ** 5100,
        "Integral": lambda: sympy.Integral(sympy.exp(-(q1**2)), (q1, 0, 1)),
        "Sum to 10**9": lambda: sympy.Sum(q1**k / sympy.factorial(k), (k, 0, 10**9)),
        "log(-2)": lambda: sympy.log(-2),
        "asin(3)": lambda: sympy.asin(3),
        "sin nested 3000 deep": deep,
        "20000-term sum": long_sum,
        "Float 2**3400000": lambda: sympy.Float(mpmath.mpf(2) ** 3_400_000) * q1,
        "Float of 10**5 digits": lambda: sympy.Float("1.5", 100_000) * q1,
    }


def correct_cases(robot: rc.Robot) -> list[tuple[str, Any, Any]]:
    import sympy

    out = []
    for name in ("A1", "A2", "A3", "M1", "M2", "M3", "p_EE"):
        reference = expected_matrix(robot, name)
        out.append((f"{name} as text", sympy.sstr(reference.matrix), reference))
        expanded = sympy.expand(sympy.expand_trig(reference.matrix))
        out.append((f"{name} expanded (sympy)", expanded, reference))
    m3 = expected_matrix(robot, "M3")
    out.append(("M3 with cos(q2 + q3)", M3_TEXT.replace("ENTRY", "20 - 30*sin(q2)"), m3))
    q1 = sympy.Symbol("q1", real=True)
    one = sympy.sin(q1) ** 2 + sympy.cos(q1) ** 2
    out.append(("M3 times sin²+cos²", m3.matrix.applyfunc(lambda e: e * one), m3))
    return out


def wrong_cases(robot: rc.Robot) -> list[tuple[str, Any, Any]]:
    import sympy

    a = [expected_matrix(robot, f"A{i}").matrix for i in (1, 2, 3)]
    m3 = expected_matrix(robot, "M3")
    transposed = m3.matrix.copy()
    transposed[:3, :3] = transposed[:3, :3].T
    sign = m3.matrix.copy()
    sign[0, 2] = -sign[0, 2]
    offset = m3.matrix.copy()
    offset[2, 3] = 0
    return [
        ("wrong order A3·A2·A1", a[2] * a[1] * a[0], m3),
        ("transposed rotation", transposed, m3),
        ("sign error", sign, m3),
        ("missing offset", offset, m3),
        ("one wrong entry (text)", M3_TEXT.replace("ENTRY", "20 + 30*sin(q2)"), m3),
        ("A2 of the other direction", sympy.sstr(a[1].subs("q2", "-q2")), m3),
    ]


def _child(make: Callable[[], tuple[Any, Any]], conn: Any) -> None:
    import sys

    with open("/proc/self/statm", encoding="ascii") as statm:
        mapped = int(statm.read().split()[0]) * resource.getpagesize()
    resource.setrlimit(resource.RLIMIT_AS, (mapped + CHILD_MEMORY,) * 2)
    sys.setrecursionlimit(10_000)
    student, reference = make()
    start = time.perf_counter()
    try:
        result = check_matrix(student, reference)
        outcome = "ok" if result.ok else "not ok"
    except rc.InvalidInputError as error:
        outcome = f"refused ({error.field})"
    except BaseException as error:  # noqa: BLE001 - every other exception is a finding
        outcome = type(error).__name__
    conn.send((outcome, time.perf_counter() - start))


def run(make: Callable[[], tuple[Any, Any]], timeout: float) -> tuple[str, float]:
    """``(outcome, seconds)`` of one ``check_matrix`` call in a forked child."""
    context = multiprocessing.get_context("fork")
    receive, send = context.Pipe(duplex=False)
    child = context.Process(target=_child, args=(make, send), daemon=True)
    child.start()
    send.close()
    if receive.poll(timeout):
        try:
            outcome, seconds = receive.recv()
        except EOFError:
            outcome, seconds = f"died (exit code {child.exitcode})", float("nan")
    else:
        outcome, seconds = "timeout", float(timeout)
    child.kill()
    child.join(5)
    return outcome, seconds


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="one run per case")
    parser.add_argument("--timeout", type=float, default=20.0, help="seconds per call")
    args = parser.parse_args()
    repeats = 1 if args.quick else 3
    robot = rc.preset("paper")
    m3 = expected_matrix(robot, "M3")
    classes: dict[str, list[tuple[str, Callable[[], tuple[Any, Any]]]]] = {
        "correct": [(n, lambda s=s, r=r: (s, r)) for n, s, r in correct_cases(robot)],
        "wrong": [(n, lambda s=s, r=r: (s, r)) for n, s, r in wrong_cases(robot)],
        "hostile 1×1": [],
        "hostile in M3": [],
    }
    for name, text in text_cases().items():
        classes["hostile 1×1"].append((name, lambda t=text: (t, 1)))
        classes["hostile in M3"].append((name, lambda n=name, t=text: (in_m3(n, t), m3)))
    algebra = all_entries_need_algebra(robot)
    classes["hostile in M3"].append(("16 entries need algebra", lambda: (algebra, m3)))
    classes["hostile in M3"].append(("16 sympy entries, 40000 parts", lambda: (at_the_cap(), m3)))
    for name, build in sympy_cases().items():
        classes["hostile 1×1"].append((name, lambda b=build: ([[b()]], 1)))

        def sympy_in_m3(b: Callable[[], Any] = build) -> tuple[Any, Any]:
            matrix = m3.matrix.copy()
            matrix[2, 3] = b()
            return matrix, m3

        classes["hostile in M3"].append((name, sympy_in_m3))
    summary = []
    for label, cases in classes.items():
        print(f"\n{label}:")
        worst, worst_name = 0.0, ""
        for name, make in cases:
            runs = [run(make, args.timeout) for _ in range(repeats)]
            seconds = max(s for _, s in runs)
            outcomes = sorted({o for o, _ in runs})
            print(f"  {seconds:7.3f} s  {name:<30} {', '.join(outcomes)}")
            if seconds > worst or seconds != seconds:
                worst, worst_name = seconds, name
        summary.append((label, worst, worst_name))
    print("\nworst case per class (target ≤ 2 s):")
    for label, worst, name in summary:
        verdict = "OK" if worst <= TARGET_SECONDS else "TOO SLOW"
        print(f"  {label:<14} {worst:7.3f} s  ({name}) {verdict}")


if __name__ == "__main__":
    main()
