"""The checker's budget: hostile answers end quickly, imaginary answers are refused, and
every correct answer still passes.

Each hostile answer is checked as a 1×1 answer and as entry (3,4) of the paper robot's
A1 and M3 (otherwise right). It must end within 3× the documented bound of
``check_matrix`` (2 s for a 4×4 answer) either refused with an ``InvalidInputError``
naming the entry (``student[2][3]``; ``student`` when the parser refuses the text) or
with a verdict that is not ok and flags exactly that entry (wrong, or too complicated to
check). The risky ones run in a forked child with a hard timeout and an address-space
limit (``tests/hostile_harness.py``), so a regression fails instead of hanging the suite.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import mpmath
import numpy as np
import pytest
import sympy

import robotconf as rc
from robotconf.teaching import (
    MatrixCheck,
    assert_matrix,
    check_matrix,
    expected_matrix,
    module_matrix,
    parse_expression,
)
from robotconf.teaching.reading._budget_rules import (
    MAX_CHECK_TERMS,
    MAX_EXPAND_EXPONENT,
    MAX_SYMBOLIC_ENTRIES,
    MAX_TRIG_MULTIPLE,
    expansion_cost,
    symbolic_verdict,
)

from .course_support import SOLUTIONS, exercise_cells, read_notebook
from .hostile_harness import Case, Refused, Returns, run_case

BOUND = 2.0  # seconds: the documented worst case of check_matrix for a 4×4 answer
LIMIT = 3 * BOUND

PAPER = rc.preset("paper")
A1 = expected_matrix(PAPER, "A1")
M3 = expected_matrix(PAPER, "M3")
q1, q2, q3 = sympy.symbols("q1 q2 q3", real=True)

A1_TEXT = "[[cos(q1), -sin(q1), 0, 0], [sin(q1), cos(q1), 0, 0], [0, 0, 1, ENTRY], [0, 0, 0, 1]]"
M3_TEXT = (
    "[[cos(q1)*cos(q2 + q3), -sin(q1), cos(q1)*sin(q2 + q3), 30*cos(q1)*cos(q2)],"
    " [sin(q1)*cos(q2 + q3), cos(q1), sin(q1)*sin(q2 + q3), 30*sin(q1)*cos(q2)],"
    " [-sin(q2 + q3), 0, cos(q2 + q3), ENTRY],"
    " [0, 0, 0, 1]]"
)
#: Entry (3,4) of each reference, and how to turn an answer equal to 1 into it.
RIGHT_ENTRY = {"A1": "0", "M3": "20 - 30*sin(q2)"}
FROM_ONE = {"A1": "({}) - 1", "M3": "({}) + 19 - 30*sin(q2)"}
#: 1 in exact arithmetic; in floating point 1e400·1e-400 is NaN, so only algebra can tell.
ONE_BY_ALGEBRA = "(1e200*cos(q2)+1e200*sin(q2))**2/(1e200*1e200) - 2*sin(q2)*cos(q2)"

# How a hostile answer must end.
VERDICT = "a verdict that is not ok, flagging the entry"
RIGHT = "ok: equal to the expected entry"
ENTRY = "refused, naming the entry"
PARSER = "refused by the parser"


def _balanced_sum(terms: list[str]) -> str:
    while len(terms) > 1:
        pairs = [terms[i : i + 2] for i in range(0, len(terms), 2)]
        terms = [f"({'+'.join(pair)})" if len(pair) == 2 else pair[0] for pair in pairs]
    return terms[0]


HOSTILE_TEXT: dict[str, tuple[str, str]] = {
    # measured failures of the previous checker
    "sin(1000000*q1)": ("sin(1000000*q1)", VERDICT),
    "tan(1000000*q1)": ("tan(1000000*q1)", VERDICT),
    "((q1+1)**64+1)**64": ("((q1+1)**64+1)**64", VERDICT),
    "1+sqrt(-1)": ("1+sqrt(-1)", ENTRY),
    "5100-digit integer": ("1" * 5100, PARSER),
    # more of the same kind
    "5000 hex digits": ("0x" + "f" * 5000, PARSER),
    "q1**64 eight times": ("*".join(["q1**64"] * 8), VERDICT),
    "nested powers": ("((((q1+1)**8+1)**8+1)**8+1)**8", VERDICT),
    "q1**100": ("q1**100", PARSER),
    "9**9**9": ("9**9**9", PARSER),
    "numbers over 4096 bits": ("(2**63)**64*(2**63)**64", PARSER),
    "1e300 five times": ("*".join(["1e300"] * 5), PARSER),
    "sin(sin(…)) 36 deep": ("sin(" * 36 + "q1" + ")" * 36, VERDICT),
    "2 + sqrt(sqrt(…)) 34 deep": ("2 + " + "sqrt(" * 34 + "q1**2+1" + ")" * 34, VERDICT),
    "parentheses 37 deep": ("(" * 37 + "q1" + ")" * 37, VERDICT),
    "trigonometric powers": ("cos(q1*(q2+q3))**64 + sin(999999*q2)**64", VERDICT),
    "huge rational": ("(3**40)**64/(2**63)**64", VERDICT),
    "1e308*10": ("1e308*10", VERDICT),
    "overflow to NaN": ("(1e20*q1+1)**60/(1e300*1e300*1e300*1e300)", VERDICT),
    "equal by algebra only": (ONE_BY_ALGEBRA, RIGHT),
    "1/(cos²+sin²−1)": ("1/(cos(q1)**2+sin(q1)**2-1)", VERDICT),
    "tan of sums to the 8th": ("tan(q1+q2+q3)**8*tan(q1-q2)**8", VERDICT),
    "(-8)**(1/3)": ("(-8)**(1/3)", ENTRY),
    "sqrt(q1-100)": ("sqrt(q1-100)", ENTRY),
    "1400-term sum": (
        _balanced_sum([f"{i}*q{i % 3 + 1}**{i % 9 + 1}" for i in range(1, 1400)]),
        VERDICT,
    ),
}


def _deep_sine() -> Any:
    expr = q1
    for _ in range(3000):  # unevaluated: sympy alone would take a minute to build it
        expr = sympy.sin(expr, evaluate=False)
    return expr


def _long_sum() -> Any:
    terms = [
        sympy.Mul(i, sympy.Pow(q1, i, evaluate=False), evaluate=False) for i in range(1, 20_000)
    ]
    return sympy.Add(*terms, evaluate=False)  # built unevaluated: sympy would take seconds


_k = sympy.Symbol("k", integer=True)
HOSTILE_SYMPY: dict[str, tuple[Callable[[], Any], str]] = {
    "q1**(10**6)": (lambda: q1 ** (10**6), VERDICT),
    "exp(exp(exp(q1)))": (lambda: sympy.exp(sympy.exp(sympy.exp(q1))), VERDICT),
    "Float 1e300 times q1": (lambda: sympy.Float("1e300") * q1, VERDICT),
    "factorial(q1)": (lambda: sympy.factorial(q1), ENTRY),
    "gamma(q1)": (lambda: sympy.gamma(q1), ENTRY),
    "sympy 10**5100": (lambda: sympy.Integer(10) ** 5100, ENTRY),
    "Python int 10**5100": (lambda: 10**5100, ENTRY),
    "Integral": (lambda: sympy.Integral(sympy.exp(-(q1**2)), (q1, 0, 1)), ENTRY),
    "Sum to 10**9": (lambda: sympy.Sum(q1**_k / sympy.factorial(_k), (_k, 0, 10**9)), ENTRY),
    "log(-2)": (lambda: sympy.log(-2), ENTRY),
    "asin(3)": (lambda: sympy.asin(3), ENTRY),
    "sin nested 3000 deep": (_deep_sine, ENTRY),
    "20000-term sum": (_long_sum, ENTRY),
    "Float 2**3400000": (lambda: sympy.Float(mpmath.mpf(2) ** 3_400_000) * q1, ENTRY),
    "Float of 10**5 digits": (lambda: sympy.Float("1.5", 100_000) * q1, ENTRY),
}

FORMS = ("1×1", "A1", "M3")
REFERENCES = {"1×1": 1, "A1": A1, "M3": M3}
WHERE = {"1×1": (0, 0), "A1": (2, 3), "M3": (2, 3)}


def _text_answer(form: str, text: str, expect: str) -> str:
    if form == "1×1":
        return text
    value = FROM_ONE[form].format(text) if expect == RIGHT else text
    return (A1_TEXT if form == "A1" else M3_TEXT).replace("ENTRY", value)


def _sympy_answer(form: str, build: Callable[[], Any]) -> Any:
    if form == "1×1":
        return [[build()]]
    matrix = REFERENCES[form].matrix.tolist()
    matrix[2][3] = build()
    return matrix  # nested lists: sympy entries and, for one case, a Python int


def _expectation(form: str, expect: str) -> Refused | Returns:
    r, c = WHERE[form]
    if expect == PARSER:
        return Refused("student", "student: ")
    if expect == ENTRY:
        return Refused(f"student[{r}][{c}]")
    if expect == RIGHT:
        return Returns(lambda result: result.ok, "ok")

    def flags_the_entry(result: MatrixCheck) -> bool:
        flagged = set(result.wrong_entries) | set(result.unchecked_entries)
        return not result.ok and flagged == {(r, c)}

    return Returns(flags_the_entry, VERDICT)


def _cases() -> list[Case]:
    cases = []
    for form in FORMS:
        reference = REFERENCES[form]
        for name, (text, expect) in HOSTILE_TEXT.items():
            answer = _text_answer(form, text, expect)
            cases.append(
                Case(
                    form,
                    name,
                    lambda a=answer, ref=reference: check_matrix(a, ref),
                    _expectation(form, expect),
                    risky=expect != PARSER,  # parser refusals are immediate and harmless
                    seconds=LIMIT,
                )
            )
        for name, (build, expect) in HOSTILE_SYMPY.items():
            cases.append(
                Case(
                    form,
                    name,
                    lambda f=form, b=build, ref=reference: check_matrix(_sympy_answer(f, b), ref),
                    _expectation(form, expect),
                    risky=True,
                    seconds=LIMIT,
                )
            )
    return cases


CASES = _cases()


def test_there_are_enough_hostile_cases():
    own = len(HOSTILE_TEXT) + len(HOSTILE_SYMPY) - 5  # besides the five measured failures
    assert own >= 15 and len(CASES) == 3 * (len(HOSTILE_TEXT) + len(HOSTILE_SYMPY))


@pytest.mark.parametrize("case", CASES, ids=[case.id for case in CASES])
def test_hostile_answer_ends_within_the_budget(case):
    kind, name, text, ok, seconds = run_case(case)
    assert ok, f"{case.id}: {kind} {name}: {text}"
    assert seconds <= LIMIT, f"{case.id}: {seconds:.2f} s"


def test_too_complicated_is_a_clear_verdict():
    result = check_matrix(HOSTILE_TEXT["overflow to NaN"][0], 1)
    assert not result.ok and result.wrong_entries == [] and result.unchecked_entries == [(0, 0)]
    assert result.mistakes == ["too_complicated"]
    assert result.hints == [
        "entry (1,1) is too complicated to check: simplify it first "
        "(it has a power with exponent 60)."
    ]
    assert str(result) == f"the matrix: 1 entry too complicated to check.\n- {result.hints[0]}"
    assert "? " in result._repr_html_() and "too complicated" in result._repr_html_()
    with pytest.raises(AssertionError, match="too complicated to check: simplify it first"):
        assert_matrix(HOSTILE_TEXT["overflow to NaN"][0], 1)


def test_numbers_decide_wrong_entries_without_algebra(monkeypatch):
    def no_algebra(*args, **kwargs):
        raise AssertionError("symbolic work on an entry the numbers decide")

    monkeypatch.setattr(sympy, "expand", no_algebra)
    monkeypatch.setattr(sympy, "expand_trig", no_algebra)
    monkeypatch.setattr(sympy, "simplify", no_algebra)
    result = check_matrix(M3_TEXT.replace("ENTRY", "sin(1000000*q1)"), M3)
    assert result.wrong_entries == [(2, 3)]
    assert check_matrix(M3_TEXT.replace("ENTRY", RIGHT_ENTRY["M3"]), M3).ok


def test_the_algebra_budget_is_shared_by_the_whole_answer():
    # Sixteen entries that only algebra can judge: at most MAX_SYMBOLIC_ENTRIES get it.
    rows = [[f"({ONE_BY_ALGEBRA})*({sympy.sstr(e)})" for e in row] for row in M3.matrix.tolist()]
    answer = "[" + ", ".join("[" + ", ".join(row) + "]" for row in rows) + "]"
    result = check_matrix(answer, M3)
    nonzero = sum(1 for e in M3.matrix if e != 0)  # a zero entry stays 0: the numbers agree
    assert not result.ok and result.wrong_entries == []
    assert nonzero - MAX_SYMBOLIC_ENTRIES <= len(result.unchecked_entries) < nonzero
    assert "algebra budget for this answer is used up" in " ".join(result.hints)


def test_a_whole_sympy_answer_is_capped():
    def entry(j: int) -> Any:  # about 3 800 parts; sixteen of them are over the cap
        angles = [sympy.Add(q1, i * q2, evaluate=False) for i in range(1, 480)]
        terms = [
            sympy.Mul(i + j, sympy.sin(a, evaluate=False), evaluate=False)
            for i, a in enumerate(angles)
        ]
        return sympy.Add(*terms, evaluate=False)

    answer = [[entry(4 * r + c) for c in range(4)] for r in range(4)]
    with pytest.raises(rc.InvalidInputError, match="student: the answer is too large to check"):
        check_matrix(answer, M3)
    result = check_matrix([row[:] for row in M3.matrix.tolist()[:3]] + [[0, 0, 0, entry(0)]], M3)
    assert result.wrong_entries == [(3, 3)] and "a formula of over 2000 parts" in result.hints[-1]


# -- the rules of the symbolic budget ---------------------------------------------------


@pytest.mark.parametrize(
    ("expr", "words"),
    [
        ((q1 + 1) ** (MAX_EXPAND_EXPONENT + 1), "power with exponent 9"),
        ((q1 + 1) ** sympy.Rational(3, 2), "power with exponent 3/2"),
        (sympy.sin((MAX_TRIG_MULTIPLE + 1) * q1), "sin of a multiple up to 9"),
        (sympy.cos(3 * q1 + 4 * q2 + 2 * q3), "cos of a multiple up to 9"),
        (sympy.tan(q1 + q2), "tan of a sum"),
        (sympy.sin(sympy.cos(q1)), "not a plain sum of multiples"),
        (sympy.exp(q1), "it uses exp"),
        (sympy.Abs(q1), "it uses Abs"),
        (sympy.Add(*[q1**i for i in range(1, 300)]), "more than 200 parts"),
        ((q1 + q2 + q3 + q1 * q2 + 1) ** 8, "expansion would have about"),
        (1 / ((q1 + q2 + q3 + 1) ** 4 * (q1 - q2 + q3 - 1) ** 4), "expansion would have about"),
    ],
)
def test_budget_refuses_unbounded_algebra(expr, words):
    cost = expansion_cost(expr)
    assert not cost.fits and words in cost.problem


def test_budget_allows_what_kinematics_needs():
    m3 = M3.matrix
    for entry in m3:
        assert expansion_cost(sympy.expand(sympy.expand_trig(entry)) - entry).fits
    assert symbolic_verdict(sympy.cos(q2 + q3) * sympy.cos(q1), m3[0, 0])[0] is True
    assert symbolic_verdict(sympy.sin(q2) ** 2 + sympy.cos(q2) ** 2, sympy.Integer(1))[0] is True
    assert symbolic_verdict(sympy.sin(q2 - q3), m3[2, 0])[0] is False
    assert max(expansion_cost(e).terms for e in m3) <= MAX_CHECK_TERMS


# -- imaginary answers are refused ------------------------------------------------------

IMAGINARY_TEXT = [
    "sqrt(-1)",
    "1 + sqrt(-1)",
    "cos(q1) + 0.0001*sqrt(-1)",
    "(-1)**(1/2)",
    "(-1)**0.5",
    "2*(-8)**(1/3)",
    "sqrt(q1 - 100)",
    "sqrt(q1)",  # not real where the sampled q1 is negative
    "sqrt(-q1**2 - 1)",
]
IMAGINARY_SYMPY = [
    sympy.I,
    1 + 2 * sympy.I,
    sympy.log(-2),
    sympy.asin(3),
    sympy.acos(2),
    sympy.log(q1 - 10),
    (-1) ** sympy.Rational(1, 3),
    sympy.sqrt(q1 - 10),
]


@pytest.mark.parametrize("text", IMAGINARY_TEXT)
@pytest.mark.parametrize("form", FORMS)
def test_imaginary_text_is_refused(form, text):
    r, c = WHERE[form]
    answer = _text_answer(form, text, ENTRY)
    with pytest.raises(rc.InvalidInputError, match="must be real") as caught:
        check_matrix(answer, REFERENCES[form])
    assert caught.value.field == f"student[{r}][{c}]"
    assert f"entry ({r + 1},{c + 1})" in str(caught.value)
    with pytest.raises(rc.InvalidInputError, match="must be real"):
        assert_matrix(answer, REFERENCES[form])  # never graded, right or wrong


@pytest.mark.parametrize("value", IMAGINARY_SYMPY, ids=str)
@pytest.mark.parametrize("form", FORMS)
def test_imaginary_sympy_entries_are_refused(form, value):
    r, c = WHERE[form]
    with pytest.raises(rc.InvalidInputError, match="must be real") as caught:
        check_matrix(_sympy_answer(form, lambda: value), REFERENCES[form])
    assert caught.value.field == f"student[{r}][{c}]"


def test_imaginary_entry_in_a_list_answer_is_refused():
    answer = [["cos(q1)", "-sin(q1)", 0, 0], ["sin(q1)", "cos(q1)", 0, 0], [0, 0, 1, 0]]
    answer.append([0, 0, "sqrt(-1)", 1])
    with pytest.raises(rc.InvalidInputError, match="entry \\(4,3\\).*must be real"):
        check_matrix(answer, A1)


def test_a_reference_outside_the_reals_is_compared_as_complex():
    # The teacher's reference decides: a student may match a non-real reference, not beat it.
    assert check_matrix("sqrt(q1 - 10)", sympy.sqrt(q1 - 10)).ok
    assert not check_matrix("sqrt(q1 - 11)", sympy.sqrt(q1 - 10)).ok


def test_round_off_is_not_imaginary():
    # 1 - sin² - cos² is ±1e-16, its square root a tiny imaginary number: still real.
    assert check_matrix("sqrt(1 - sin(q1)**2 - cos(q1)**2) + 1", 1).ok


# -- large numbers ----------------------------------------------------------------------


def test_integer_literals_are_capped_in_the_parser():
    for text in ("1" * 5100, "0x" + "f" * 5000, "0b" + "1" * 200, "0o" + "7" * 100):
        with pytest.raises(rc.InvalidInputError, match="a number with more than 40 digits"):
            parse_expression(text)
    assert parse_expression("0x10") == 16  # small ones are fine
    with pytest.raises(rc.InvalidInputError, match="student: number too large"):
        parse_expression("*".join(["1e300"] * 5))


# -- every correct answer still passes --------------------------------------------------

# From tests/test_checking.py and tests/test_checking_hints.py, against their robot.
_A1 = module_matrix("Rz", q1, (0, 0, 0))
_A2 = module_matrix("Ry", q2, (0, 0, sympy.Symbol("l1", real=True)))
TESTS_ROBOT = rc.Robot(
    [rc.Module("Rz"), rc.Module("Ry", a=(0, 0, 20)), rc.Module("Ry", a=(30, 0, 0))],
    end_effector=(40, 0, 0),
)
CHECKING_M3 = (
    "[[cos(q1)*(cos(q2)*cos(q3) - sin(q2)*sin(q3)), -sin(q1), "
    "cos(q1)*(sin(q2)*cos(q3) + cos(q2)*sin(q3)), l2*cos(q1)*cos(q2)],"
    " [sin(q1)*cos(q2 + q3), cos(q1), sin(q1)*sin(q2 + q3), l2*sin(q1)*cos(q2)],"
    " [-sin(q2)*cos(q3) - cos(q2)*sin(q3), 0, cos(q2 + q3), l1 - l2*sin(q2)],"
    " [0, 0, 0, 1]]"
)


def _correct_answers() -> list[tuple[str, Any, Any]]:
    lengths = {n: expected_matrix(TESTS_ROBOT, n, lengths=True) for n in ("A2", "M2", "M3")}
    one = sympy.sin(q3) ** 2 + sympy.cos(q3) ** 2
    q = [np.pi / 2, np.pi / 6, np.pi / 4]
    cases: list[tuple[str, Any, Any]] = [
        ("M3 text", CHECKING_M3, lengths["M3"]),
        ("M3 expanded", sympy.expand(sympy.expand_trig(lengths["M3"].matrix)), lengths["M3"]),
        ("M2 times sin²+cos²", lengths["M2"].matrix.applyfunc(lambda e: e * one), lengths["M2"]),
        (
            "A2 text",
            "[[cos(q2), 0, sin(q2), 0], [0, 1, 0, 0], [-sin(q2), 0, cos(q2), l1], [0, 0, 0, 1]]",
            lengths["A2"],
        ),
        ("A2 sympy", _A2, lengths["A2"]),
        (
            "M3 numeric",
            np.round(TESTS_ROBOT.frame_poses(q)[2], 4),
            expected_matrix(TESTS_ROBOT, "M3", q=q),
        ),
        ("p_EE list", [70, 0, 20], expected_matrix(TESTS_ROBOT, "p_EE", q=[0, 0, 0])),
        ("p_EE text", "[70, 0, 20]", expected_matrix(TESTS_ROBOT, "p_EE", q=[0, 0, 0])),
        ("scalar 1/2", "1/2", 0.5),
        ("scalar 2*sin(q2)", "  (2*sin(q2))", 2 * sympy.sin(q2)),
        ("identity", [[1, 0], [0, 1]], np.eye(2)),
        ("rounded", [[0.7071, 70.71]], np.array([[np.sqrt(2) / 2, 70.71068]])),
        (
            "sqrt(q1 - 10)",
            "[[cos(q1)*cos(q2) - sin(q1)*sin(q2), sqrt(q1 - 10)]]",
            sympy.Matrix([[sympy.cos(q1 + q2), sympy.sqrt(q1 - 10)]]),
        ),
    ]
    for name in ("A1", "A2", "A3", "M1", "M2", "M3", "p_EE"):
        reference = expected_matrix(PAPER, name)
        cases.append((f"paper {name} text", sympy.sstr(reference.matrix), reference))
        cases.append(
            (
                f"paper {name} sin(-q)",
                sympy.sstr(reference.matrix).replace("-sin(q", "sin(-q"),
                reference,
            )
        )
    cases.append(("paper M3 with cos(q2 + q3)", M3_TEXT.replace("ENTRY", RIGHT_ENTRY["M3"]), M3))
    cases.append(("paper A1 text", A1_TEXT.replace("ENTRY", RIGHT_ENTRY["A1"]), A1))
    return cases


CORRECT = _correct_answers()


@pytest.mark.parametrize(("name", "student", "reference"), CORRECT, ids=[c[0] for c in CORRECT])
def test_correct_answers_still_pass(name, student, reference):
    result = check_matrix(student, reference)
    assert result.ok, result.hints
    assert result.hints == [] and result.unchecked_entries == []


def _solution_notebooks() -> list[Path]:
    return sorted(SOLUTIONS.glob("*/exercises.ipynb"))


@pytest.mark.parametrize("path", _solution_notebooks(), ids=lambda p: p.parent.name)
def test_course_solutions_still_pass(path, monkeypatch):
    """Run each solutions notebook's code in-process; every check it makes must pass."""
    monkeypatch.setenv("MPLBACKEND", "Agg")
    monkeypatch.setenv("ROBOTCONF_FAST", "1")
    monkeypatch.chdir(path.parent)
    results: list[MatrixCheck] = []
    original = rc.check_matrix

    def recording(*args: Any, **kwargs: Any) -> MatrixCheck:
        result = original(*args, **kwargs)
        results.append(result)
        return result

    monkeypatch.setattr(rc, "check_matrix", recording)
    monkeypatch.setattr(rc.teaching, "check_matrix", recording)
    monkeypatch.setattr("robotconf.teaching.checks._matrix.check_matrix", recording)
    namespace: dict[str, Any] = {"__name__": "__solutions__"}
    with np.printoptions():  # the notebooks set numpy's print options; put them back
        for cell in read_notebook(path).cells:
            if cell.cell_type == "code" and not cell.source.lstrip().startswith(("%", "!")):
                exec(compile(cell.source, str(path), "exec"), namespace)  # our own notebook
    # Every check cell ran above (a failed assert_* raises); the matrix checks are counted
    # too, so a notebook whose checks stopped reaching the checker is caught.
    checks = [e for e in exercise_cells(path) if "_matrix(" in e.check_source]
    assert exercise_cells(path) and len(results) >= len(checks)
    assert all(result.ok for result in results), [r.hints for r in results if not r.ok]
