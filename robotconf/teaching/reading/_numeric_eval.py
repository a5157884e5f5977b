"""Numeric values of a sympy expression at K sample points, in complex arithmetic.

The homework checker decides equality by numbers first, so this walk must never hang and
must not hide anything: it runs in complex numpy arithmetic, so ``sqrt(-1)``, ``log(-2)``
or ``asin(3)`` come out imaginary (the checker then refuses them) instead of silently
becoming 0 or NaN. The walk is iterative (any depth), visits each distinct sub-expression
once, and stops after :data:`MAX_EVALUATED_NODES` of them. There is no code generation
and no symbolic work: every node is one numpy operation on K values.

In *strict* mode (a student's entry) only a whitelist of functions is evaluated; anything
else raises :class:`NotEvaluable`. Otherwise (the teacher's reference) an unknown function
falls back to sympy's ``evalf``, point by point.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from typing import Any

import numpy as np

__all__ = [
    "MAX_EVALUATED_NODES",
    "ROUND_OFF",
    "NotEvaluable",
    "TooLarge",
    "complex_values",
    "is_real",
    "real_or_nan",
]

#: Distinct sub-expressions evaluated for one entry before giving up (:class:`TooLarge`).
#: Typed answers stay far below it (the parser caps text at 20 000 characters).
MAX_EVALUATED_NODES = 20_000
#: Round-off floor of the imaginary-part test in :func:`is_real` (relative to the value).
ROUND_OFF = 1e-9


class NotEvaluable(Exception):
    """A student's entry holds something outside the numeric whitelist (``what`` names it)."""

    def __init__(self, what: str) -> None:
        super().__init__(what)
        self.what = what


class TooLarge(Exception):
    """The expression has more than :data:`MAX_EVALUATED_NODES` distinct sub-expressions."""


def _real_only(function: Callable[..., np.ndarray]) -> Callable[..., np.ndarray]:
    """A real function of complex arrays: NaN wherever an argument is not real."""

    def wrapped(*args: np.ndarray) -> np.ndarray:
        real = np.all([a.imag == 0 for a in args], axis=0)
        result = function(*(a.real for a in args))
        return np.where(real, result, np.nan).astype(complex)

    return wrapped


def _fold(function: Callable[[np.ndarray, np.ndarray], np.ndarray]) -> Callable[..., np.ndarray]:
    return lambda *args: functools.reduce(function, args)


@functools.lru_cache(maxsize=1)
def _functions() -> dict[type, Callable[..., np.ndarray]]:
    import sympy

    return {
        sympy.sin: np.sin,
        sympy.cos: np.cos,
        sympy.tan: np.tan,
        sympy.cot: lambda z: 1 / np.tan(z),
        sympy.sec: lambda z: 1 / np.cos(z),
        sympy.csc: lambda z: 1 / np.sin(z),
        sympy.asin: np.arcsin,
        sympy.acos: np.arccos,
        sympy.atan: np.arctan,
        sympy.sinh: np.sinh,
        sympy.cosh: np.cosh,
        sympy.tanh: np.tanh,
        sympy.exp: np.exp,
        sympy.log: np.log,
        sympy.Abs: lambda z: np.abs(z).astype(complex),
        sympy.re: lambda z: z.real.astype(complex),
        sympy.im: lambda z: z.imag.astype(complex),
        sympy.conjugate: np.conj,
        sympy.sign: _real_only(np.sign),
        sympy.floor: _real_only(np.floor),
        sympy.ceiling: _real_only(np.ceil),
        sympy.atan2: _real_only(np.arctan2),
        sympy.Min: _real_only(_fold(np.minimum)),
        sympy.Max: _real_only(_fold(np.maximum)),
    }


def _number(expr: Any) -> complex:
    import sympy

    if expr is sympy.I:
        return 1j
    if expr.is_Rational:
        try:  # Python divides big integers exactly and rounds once
            return complex(int(expr.p) / int(expr.q))
        except OverflowError:
            return complex(math.inf if expr.p > 0 else -math.inf)
    try:
        return complex(float(expr))
    except (OverflowError, TypeError, ValueError):
        return complex(math.nan)


def _where_real(
    args: list[np.ndarray],
    real: Callable[[list[np.ndarray]], np.ndarray],
    full: Callable[[list[np.ndarray]], np.ndarray],
) -> np.ndarray:
    """``real`` on the real parts where every argument is real, ``full`` elsewhere.

    Complex arithmetic turns an overflow into NaN (``(inf + 0j)·(2 + 0j)`` has the
    imaginary part ``inf·0``); real arithmetic keeps the ``inf`` that says "far too large".
    """
    mask = functools.reduce(np.logical_and, [a.imag == 0 for a in args])
    if mask.all():
        return real([a.real for a in args]).astype(complex)
    if not mask.any():
        return full(args)
    return np.where(mask, real([a.real for a in args]), full(args))


def _integer_power(base: np.ndarray, n: int) -> np.ndarray:
    """``base**n`` by repeated squaring: exact for real values (no spurious imaginary part)."""
    result = np.ones_like(base)
    factor = 1 / base if n < 0 else base
    n = abs(n)
    while n:
        if n & 1:
            result = result * factor
        n >>= 1
        if n:
            factor = factor * factor
    return result


def _power(base: np.ndarray, exponent: Any, exponent_values: np.ndarray) -> np.ndarray:
    if exponent.is_Integer:
        n = int(exponent)
        # beyond a float's range, x**n is 0, ±1 or infinite all the same
        as_float = float(n) if abs(n) < 2**1000 else (math.inf if n > 0 else -math.inf)
        return _where_real(
            [base],
            lambda x: np.power(x[0], as_float),
            lambda z: _integer_power(z[0], n),
        )
    # A non-negative real base with a real exponent stays real (no round-off imaginary part);
    # otherwise the principal branch, as sympy defines (-8)**(1/3).
    real = (base.imag == 0) & (base.real >= 0) & (exponent_values.imag == 0)
    real_part = np.power(np.where(real, base.real, 1.0), np.where(real, exponent_values.real, 1.0))
    return np.where(real, real_part, np.power(base, exponent_values))


def _fallback(expr: Any, env: dict[str, np.ndarray], k: int) -> np.ndarray:
    """The teacher's reference may hold other functions: sympy's evalf, point by point."""
    symbols = list(expr.free_symbols)
    values = []
    for i in range(k):
        try:
            values.append(complex(expr.evalf(subs={s: float(env[s.name][i]) for s in symbols})))
        except (TypeError, ValueError):
            values.append(complex(math.nan))
    return np.array(values, dtype=complex)


def complex_values(
    expr: Any, env: dict[str, np.ndarray], k: int, *, strict: bool = False
) -> np.ndarray:
    """Evaluate a sympy expression at K points in complex arithmetic.

    Parameters
    ----------
    expr : sympy.Expr
    env : dict of str to ndarray, shape (K,)
        Real values of the symbols by name.
    k : int
        K.
    strict : bool
        A student's entry: refuse functions outside the numeric whitelist instead of
        falling back to sympy's ``evalf``.

    Returns
    -------
    ndarray of complex, shape (K,)
        Non-finite (inf or NaN) where the expression overflows or is undefined.

    Raises
    ------
    NotEvaluable
        In strict mode, for a function or object outside the whitelist.
    TooLarge
        For more than :data:`MAX_EVALUATED_NODES` distinct sub-expressions.
    robotconf.InvalidInputError
        For a symbol without a value in ``env``.

    Examples
    --------
    >>> import sympy
    >>> q1 = sympy.Symbol("q1", real=True)
    >>> complex_values(sympy.sqrt(q1 - 1), {"q1": np.array([5.0, -3.0])}, 2)
    array([2.+0.j, 0.+2.j])
    """
    from ..._errors import InvalidInputError

    functions = _functions()
    cache: dict[Any, np.ndarray] = {}
    stack: list[tuple[Any, bool]] = [(expr, False)]
    seen = 0
    with np.errstate(all="ignore"):
        while stack:
            node, ready = stack.pop()
            if ready:
                args = [cache[a] for a in node.args]
                cache[node] = _operation(node, args, functions)
                continue
            if node in cache:
                continue
            seen += 1
            if seen > MAX_EVALUATED_NODES:
                raise TooLarge
            if node.is_Symbol:
                if node.name not in env:
                    raise InvalidInputError(
                        "symbols", node.name, ", ".join(env), problem="no value for"
                    )
                cache[node] = np.asarray(env[node.name], dtype=float).astype(complex)
            elif not node.args and node.is_number:  # numbers, pi, E, I, oo, zoo, nan
                cache[node] = np.full(k, _number(node), dtype=complex)
            elif node.is_Add or node.is_Mul or node.is_Pow or type(node) in functions:
                stack.append((node, True))
                stack.extend((a, False) for a in node.args)
            elif strict:
                raise NotEvaluable(type(node).__name__)
            else:
                cache[node] = _fallback(node, env, k)
    return cache[expr]


def _operation(
    node: Any, args: list[np.ndarray], functions: dict[type, Callable[..., np.ndarray]]
) -> np.ndarray:
    """One operation or function, its arguments' values being known."""
    if node.is_Add:
        return functools.reduce(np.add, args)
    if node.is_Mul:
        return _where_real(
            args,
            lambda x: functools.reduce(np.multiply, x),
            lambda z: functools.reduce(np.multiply, z),
        )
    if node.is_Pow:
        return _power(args[0], node.exp, args[1])
    return np.asarray(functions[type(node)](*args), dtype=complex)


def is_real(values: np.ndarray, tol: float = 0.0) -> np.ndarray:
    """Where values are real: ``|Im z| ≤ max(tol, ROUND_OFF)·max(1, |Re z|)``.

    An imaginary part that small is round-off (``sqrt`` of ``-1e-17``) or lies within the
    checker's tolerance anyway; anything larger is a value that is not real.

    Parameters
    ----------
    values : ndarray of complex
    tol : float
        The checker's relative tolerance.

    Returns
    -------
    ndarray of bool
        Same shape; False where a value is not finite.

    Examples
    --------
    >>> is_real(np.array([1 + 1e-12j, 1j, np.inf]))
    array([ True, False, False])
    """
    limit = max(tol, ROUND_OFF) * np.maximum(1.0, np.abs(values.real))
    with np.errstate(invalid="ignore"):
        return np.isfinite(values) & (np.abs(values.imag) <= limit)


def real_or_nan(values: np.ndarray, tol: float = 0.0) -> np.ndarray:
    """The real parts where :func:`is_real`, NaN elsewhere (float array, same shape).

    >>> real_or_nan(np.array([2 + 0j, 1j]))
    array([ 2., nan])
    """
    return np.where(is_real(values, tol), values.real, np.nan)
