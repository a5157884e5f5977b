"""The checker's symbolic budget: how much algebra a student's entry may cost.

The checker decides equality numerically (see :mod:`robotconf.teaching.reading._numeric_judge`).
Only an entry the numbers cannot decide (undefined, NaN, at some sample points) goes on to
``expand(expand_trig(student − expected))``, followed by ``sin² → 1 − cos²``, and only
when one walk of the expression tree (never more than :data:`MAX_SYMBOLIC_NODES` nodes)
shows that the work stays small:

(a) every power of a formula has an integer exponent of at most
    :data:`MAX_EXPAND_EXPONENT` (``(q1 + 1)**64`` would expand into 65 terms, nested
    powers into billions; a root of a formula is copied into every term);
(b) the argument of ``sin`` and ``cos`` is a plain sum (no fractions, no functions) whose
    integer multiples add up to at most :data:`MAX_TRIG_MULTIPLE`
    (``expand_trig(sin(1000000*q1))`` is a polynomial of degree 10⁶); ``tan`` only of a
    single angle (``tan(a + b)`` becomes a fraction whose powers explode);
(c) the tree has at most :data:`MAX_SYMBOLIC_NODES` nodes and depth
    :data:`MAX_SYMBOLIC_DEPTH`, and uses only ``+ * **``, numbers, symbols and the
    functions in :data:`SYMBOLIC_FUNCTIONS`;
(d) the estimated number of terms produced while expanding is at most
    :data:`MAX_EXPANDED_TERMS` (:func:`expansion_cost`, an upper bound built bottom-up:
    a sum adds, a product multiplies, numerators and denominators apart,
    ``(a + b + …)**n`` counts its monomials, ``sin(m1·x1 + …)`` doubles per unit of
    ``|m1| + …``);
(e) one check spends at most :data:`MAX_CHECK_TERMS` estimated terms on at most
    :data:`MAX_SYMBOLIC_ENTRIES` entries (:class:`Allowance`).

The bounds were measured: within them one entry costs at most about 0.8 s of sympy on a
2-core machine, and one check about as much. Everything else is "too complicated to
check", a verdict, never a hang.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

__all__ = [
    "MAX_EXPAND_EXPONENT",
    "MAX_TRIG_MULTIPLE",
    "MAX_SYMBOLIC_NODES",
    "MAX_SYMBOLIC_DEPTH",
    "MAX_EXPANDED_TERMS",
    "MAX_CHECK_TERMS",
    "MAX_SYMBOLIC_ENTRIES",
    "SYMBOLIC_FUNCTIONS",
    "Allowance",
    "Cost",
    "expansion_cost",
    "symbolic_verdict",
]

#: Largest exponent (its integer part) of a power of a non-number that may be expanded.
MAX_EXPAND_EXPONENT = 8
#: Largest sum of the integer multiples (``|numerator|``, ``|denominator|`` of a
#: coefficient) inside one ``sin``/``cos``/``tan`` argument.
MAX_TRIG_MULTIPLE = 8
#: Largest number of nodes of ``student − expected`` (a tree; shared parts count again).
MAX_SYMBOLIC_NODES = 200
#: Largest nesting depth of ``student − expected``.
MAX_SYMBOLIC_DEPTH = 20
#: Largest estimated number of terms produced while expanding one entry.
MAX_EXPANDED_TERMS = 200
#: Largest estimated number of terms for all entries of one check together.
MAX_CHECK_TERMS = 300
#: Most entries of one check that get symbolic work.
MAX_SYMBOLIC_ENTRIES = 4
#: Functions symbolic work may meet (by sympy class name).
SYMBOLIC_FUNCTIONS = ("sin", "cos", "tan")

_HUGE = 10**9  # estimates saturate here: enough to say "over budget"


@dataclass(frozen=True)
class Cost:
    """What expanding an expression would cost, or why it is not attempted.

    Attributes
    ----------
    terms : int
        Upper bound of the terms produced while expanding (saturates at 10⁹).
    problem : str or None
        Why the expression is over the budget, in words for the student; ``None`` when
        it fits.
    """

    terms: int
    problem: str | None = None

    @property
    def fits(self) -> bool:
        """Whether ``expand(expand_trig(…))`` may run."""
        return self.problem is None


@dataclass
class _Node:
    """Bottom-up facts of one node once expanded.

    ``terms`` and ``denominator`` count the monomials of its numerator and of its
    denominator (expand multiplies denominators out too), ``coefficient`` bounds the sum
    of the absolute values of its coefficients (the multiples a trigonometric argument
    would hand to ``expand_trig``), ``work`` adds up the terms produced below it.
    """

    terms: int = 1
    denominator: int = 1
    coefficient: int = 1
    work: int = 1


def _cap(value: int) -> int:
    return min(value, _HUGE)


def _product(values: Any) -> int:
    result = 1
    for value in values:
        result = _cap(result * value)
    return result


def _number_size(expr: Any) -> int:
    if expr.is_Rational:
        return _cap(max(abs(int(expr.p)), abs(int(expr.q)), 1))
    if expr.is_Float:
        value = abs(float(expr))
        return _cap(math.ceil(value)) if math.isfinite(value) and value >= 1 else 1
    return 1


def _monomials(variables: int, degree: int) -> int:
    """Monomials of ``degree`` in ``variables`` terms: C(variables + degree − 1, degree)."""
    if variables >= _HUGE or degree > 64:
        return _HUGE
    return _cap(math.comb(variables + degree - 1, degree))


def _trigonometric() -> tuple[Any, ...]:
    import sympy

    return (sympy.sin, sympy.cos, sympy.tan)


def _shape_problem(expr: Any) -> str | None:
    """Rule (c): size, depth and allowed node kinds, in one bounded walk."""
    count = 0
    stack = [(expr, 1)]
    while stack:
        node, depth = stack.pop()
        count += 1
        if count > MAX_SYMBOLIC_NODES:
            return f"it has more than {MAX_SYMBOLIC_NODES} parts"
        if depth > MAX_SYMBOLIC_DEPTH:
            return f"it is nested more than {MAX_SYMBOLIC_DEPTH} levels deep"
        if node.is_Atom:
            if not (node.is_Symbol or node.is_number):
                return f"it uses {type(node).__name__}"
            continue
        if not (node.is_Add or node.is_Mul or node.is_Pow):
            name = type(node).__name__
            if name not in SYMBOLIC_FUNCTIONS:
                return f"it uses {name}"
        stack.extend((a, depth + 1) for a in node.args)
    return None


def _power(node: Any, base: _Node, work: int) -> _Node | str:
    exponent = node.exp
    if node.base.is_number:
        return _Node(work=work)
    if not exponent.is_Integer:
        # A root of a formula: expand splits it and copies the radicand into every
        # term, at a cost no term count predicts.
        return f"it has a power with exponent {exponent}"
    degree = abs(int(exponent))
    if degree > MAX_EXPAND_EXPONENT:
        return f"it has a power with exponent {exponent}"
    if degree == 0:
        return _Node(work=work + 1)
    # (a/b + …)**n: every monomial of the numerator carries a denominator of up to
    # denominator**n monomials; 1/(a/b)**n turns the two over.
    numerator = _monomials(base.terms, degree)
    denominator = _cap(base.denominator**degree) if base.denominator > 1 else 1
    total = _cap(work + _cap(numerator * denominator))
    if exponent < 0:
        return _Node(denominator, numerator, 1, total)
    return _Node(numerator, denominator, _cap(base.coefficient**degree), total)


def _combine(node: Any, args: list[_Node]) -> _Node | str:
    """One node's facts from its arguments' (rules a, b, d), or why it is over budget."""
    work = _cap(sum(a.work for a in args))
    if node.is_Add:
        terms = _cap(sum(a.terms for a in args))
        # A constant term of a trigonometric argument (q1 + 5) is no multiple of an angle.
        coefficient = sum(
            1 if x.is_number else a.coefficient for x, a in zip(node.args, args, strict=True)
        )
        spread = _cap(sum(a.terms * a.denominator for a in args))
        denominator = max(a.denominator for a in args)
        return _Node(terms, denominator, _cap(coefficient), _cap(work + spread))
    if node.is_Mul:
        terms = _product(a.terms for a in args)
        denominator = _product(a.denominator for a in args)
        coefficient = _product(a.coefficient for a in args)
        return _Node(terms, denominator, coefficient, _cap(work + terms * denominator))
    if node.is_Pow:
        return _power(node, args[0], work)
    name = type(node).__name__
    argument = node.args[0]
    if args[0].denominator > 1 or argument.has(*_trigonometric()):
        # sympy asks assumptions about a function's argument as it builds it: a large
        # argument with fractions or functions inside can take minutes.
        return f"it has {name} of an angle that is not a plain sum of multiples"
    multiple = max(args[0].coefficient, args[0].terms)
    if name in ("sin", "cos"):
        if multiple > MAX_TRIG_MULTIPLE:
            return f"it has {name} of a multiple up to {multiple} of an angle"
        terms = 2 ** (multiple - 1)
        return _Node(terms, 1, 1, _cap(work + terms * multiple))
    if name == "tan" and multiple > 1:
        # expand_trig turns tan(a + b) into a fraction; its powers expand explosively.
        return "it has tan of a sum or of a multiple of an angle"
    return _Node(work=_cap(work + 1))


def expansion_cost(expr: Any, terms: int = MAX_EXPANDED_TERMS) -> Cost:
    """Estimate what ``expand(expand_trig(expr))`` costs, without doing any of it.

    Parameters
    ----------
    expr : sympy.Expr
    terms : int
        The most estimated terms that fit (rule d).

    Returns
    -------
    Cost
        ``fits`` when rules (a)–(d) of this module hold; otherwise ``problem`` says
        which one fails.

    Examples
    --------
    >>> import sympy
    >>> q1, q2 = sympy.symbols("q1 q2", real=True)
    >>> expansion_cost(sympy.cos(q1 + q2) - sympy.cos(q1) * sympy.cos(q2)).fits
    True
    >>> expansion_cost(sympy.sin(1000000 * q1)).problem
    'it has sin of a multiple up to 1000000 of an angle'
    >>> expansion_cost(((q1 + 1) ** 8 + 1) ** 8).problem  # C(17, 8) monomials on the way
    'its expansion would have about 10^4 terms'
    """
    problem = _shape_problem(expr)
    if problem is not None:
        return Cost(_HUGE, problem)
    facts: dict[int, _Node] = {}
    stack: list[tuple[Any, bool]] = [(expr, False)]
    while stack:  # post-order; the shape walk bounded the size already
        node, ready = stack.pop()
        if not ready and node.args:
            stack.append((node, True))
            stack.extend((a, False) for a in node.args)
            continue
        if not node.args:
            facts[id(node)] = _Node(coefficient=_number_size(node) if node.is_number else 1)
            continue
        combined = _combine(node, [facts[id(a)] for a in node.args])
        if isinstance(combined, str):
            return Cost(_HUGE, combined)
        facts[id(node)] = combined
    total = facts[id(expr)].work
    if total > terms:
        return Cost(total, f"its expansion would have about 10^{len(str(total)) - 1} terms")
    return Cost(total)


def symbolic_verdict(
    student: Any, expected: Any, terms: int = MAX_EXPANDED_TERMS
) -> tuple[bool | None, Cost]:
    """Whether ``student == expected`` symbolically, within the budget.

    Parameters
    ----------
    student, expected : sympy.Expr
    terms : int
        The estimated terms this entry may cost (at most :data:`MAX_EXPANDED_TERMS`).

    Returns
    -------
    equal : bool or None
        True when ``expand(expand_trig(student − expected))`` is 0, False when it is not
        (the numbers did not show equality either), None when over the budget.
    cost : Cost
        The estimate that allowed or refused the work.

    Examples
    --------
    >>> import sympy
    >>> q1 = sympy.Symbol("q1", real=True)
    >>> symbolic_verdict(sympy.sin(2 * q1), 2 * sympy.sin(q1) * sympy.cos(q1))[0]
    True
    >>> symbolic_verdict(sympy.sin(1000000 * q1), sympy.sin(q1))[0] is None
    True
    """
    import sympy

    difference = student - expected
    if difference == 0:
        return True, Cost(0)
    cost = expansion_cost(difference, min(terms, MAX_EXPANDED_TERMS))
    if not cost.fits:
        return None, cost
    try:
        # doit: functions the parser kept as typed (sin(-q1)) take their usual form
        expanded = sympy.expand(sympy.expand_trig(difference.doit()))
        if expanded == 0:
            return True, cost
        reduced = _without_sine_squares(expanded, min(terms, MAX_EXPANDED_TERMS))
        if reduced is None:
            return None, Cost(cost.terms, "replacing sin² by 1 − cos² would make it too long")
        return reduced == 0, cost
    except (TypeError, ValueError, RecursionError, ZeroDivisionError):  # pragma: no cover
        return None, Cost(cost.terms, "sympy could not expand it")


def _without_sine_squares(expanded: Any, terms: int) -> Any:
    """Replace ``sin(x)**n`` by ``sin(x)**(n mod 2)·(1 − cos(x)**2)**(n // 2)`` and expand.

    Once ``expand_trig`` has reduced every angle to single symbols, this is a canonical
    form of a polynomial in sines and cosines: it is 0 exactly when the polynomial is
    (``cos(q)**2 + sin(q)**2 − 1`` expands to itself, not to 0). Returns ``None``, doing
    nothing, when the result could have more than ``terms`` terms: each term multiplies
    by ``n // 2 + 1`` per such power.
    """
    import sympy

    replacements = {}
    total = 0
    for term in sympy.Add.make_args(expanded):
        growth = 1
        for factor in sympy.Mul.make_args(term):
            base, exponent = factor.as_base_exp()
            if isinstance(base, sympy.sin) and exponent.is_Integer and exponent >= 2:
                n = int(exponent)
                growth *= n // 2 + 1
                cosine = sympy.cos(base.args[0])
                replacements[factor] = base ** (n % 2) * (1 - cosine**2) ** (n // 2)
        total += growth
        if total > terms:
            return None
    if not replacements:
        return expanded
    return sympy.expand(expanded.xreplace(replacements))


class Allowance:
    """The symbolic budget of one check, shared by its entries.

    At most :data:`MAX_SYMBOLIC_ENTRIES` entries get symbolic work, and their estimated
    terms add up to at most :data:`MAX_CHECK_TERMS`: a 4×4 answer of sixteen entries
    that all need algebra cannot multiply the time of one.

    Examples
    --------
    >>> import sympy
    >>> q1 = sympy.Symbol("q1", real=True)
    >>> allowance = Allowance()
    >>> allowance.verdict(sympy.cos(q1) ** 2, 1 - sympy.sin(q1) ** 2)
    (True, None)
    >>> allowance.verdict((q1 + 1) ** 64, q1)
    (None, 'it has a power with exponent 64')
    """

    def __init__(self) -> None:
        self.terms = MAX_CHECK_TERMS
        self.entries = MAX_SYMBOLIC_ENTRIES

    def verdict(self, student: Any, expected: Any) -> tuple[bool | None, str | None]:
        """``(equal, None)``, or ``(None, why not)`` when over the budget."""
        if self.entries <= 0 or self.terms <= 0:
            return None, "the checker's algebra budget for this answer is used up"
        self.entries -= 1
        equal, cost = symbolic_verdict(student, expected, self.terms)
        if equal is None:
            return None, cost.problem
        self.terms -= max(cost.terms, 1)
        return equal, None
