"""One-sided limits by continuity rules: a small, rigorous limit calculus.

``limit_right(expr, x)`` computes lim_{x->0+} expr.  It walks the expression
and applies only textbook limit theorems (sums, products and quotients of
limits, continuity of elementary functions at finite points, the limits of
monotone functions at +-infinity, and powers of a quantity that tends to 0
from a known side).  Every indeterminate form (inf - inf, 0 * inf, 0/0,
inf/inf, oscillation) raises `NoLimit`: the calculus never guesses, so a
returned value is a proof.  SymPy's own ``limit`` is a heuristic and is never
used to prove anything here.

Values are exact SymPy numbers or +-oo.  Each limit carries ``side``: the
eventual strict sign of the quantity near the limit (+1, -1), 0 for an exact
constant, or None when it is not known."""
from __future__ import annotations

import math
from dataclasses import dataclass

import sympy as sp

from .interval import Interval, IntervalFunction, Undefined
from .kernel.core import KernelError, _const_sign
from .timeouts import attempt


class NoLimit(Exception):
    """The limit calculus cannot decide this limit."""


@dataclass(frozen=True)
class Lim:
    value: sp.Expr      # exact number, sp.oo or -sp.oo
    side: int | None    # eventual sign (+1/-1), 0 if exactly constant, None if unknown

    @property
    def infinite(self) -> bool:
        return self.value in (sp.oo, -sp.oo)


def interval_sign(value) -> int | None:
    """Sign of a nonzero exact real constant from its Arb enclosure; None
    when the enclosure holds 0 or there is none."""
    try:
        box = Interval.point(value)
    except (Undefined, TypeError, ValueError):
        return None
    return 1 if box.is_positive() else -1 if box.is_negative() else None


def exact_sign(value) -> int | None:
    """Sign of an exact real constant: interval arithmetic, or a symbolic
    zero; None when neither decides (or there is no value: None)."""
    if value is None:
        return None
    if value == 0:
        return 0
    sign = interval_sign(value)
    if sign is not None:
        return sign
    try:                # the kernel's: Arb up to 32,768 bits, exact zeros through the primes of logarithms
        return _const_sign(value, zero=True)
    except (KernelError, Undefined, ArithmeticError, TypeError, ValueError):    # (Arb's Undefined is an ArithmeticError)
        pass
    # a symbolic zero test, only for small constants: SymPy's simplify can
    # spend minutes (minimal polynomials of nested radicals) on big ones
    if sp.count_ops(value) > 60:
        return None
    return 0 if attempt(lambda: sp.simplify(value) == 0, 2.0, False) else None


def sign_of(value: sp.Expr) -> int:
    """`exact_sign`, extended to +-oo, raising NoLimit when undecided."""
    if value == sp.oo:
        return 1
    if value == -sp.oo:
        return -1
    sgn = exact_sign(value)
    if sgn is None:
        raise NoLimit(f"cannot decide the sign of {value}")
    return sgn


def _eventual_sign(lim: Lim) -> int | None:
    s = sign_of(lim.value)
    return s if s != 0 else lim.side


_MONOTONE_AT_INF = {
    sp.tanh: (sp.Integer(1), sp.Integer(-1)),
    sp.atan: (sp.pi / 2, -sp.pi / 2),
    sp.erf: (sp.Integer(1), sp.Integer(-1)),
    sp.exp: (sp.oo, sp.Integer(0)),
    sp.sinh: (sp.oo, -sp.oo),
    sp.asinh: (sp.oo, -sp.oo),
    sp.cosh: (sp.oo, sp.oo),
}


def _limit(expr: sp.Expr, x: sp.Symbol) -> Lim:
    if expr.has(sp.nan, sp.zoo):
        raise NoLimit(f"{expr} has an undefined part")
    if expr == x:
        return Lim(sp.Integer(0), 1)
    if not expr.has(x):
        if expr.is_number:
            return Lim(expr, 0)
        raise NoLimit(f"{expr} has other free symbols")
    if isinstance(expr, (sp.Add, sp.Mul)):
        limits, bounded = [], []
        for a in expr.args:
            try:
                limits.append(_limit(a, x))
            except NoLimit:
                if not _bounded_near_zero(a, x):
                    raise
                bounded.append(a)
        if bounded:
            return _with_bounded(limits, isinstance(expr, sp.Add))
        if isinstance(expr, sp.Mul):
            try:
                return _mul(limits)
            except NoLimit:     # 0 * oo in a rational function: 1/(x^2 (1 + x^-2)) is 1/(x^2 + 1);
                # else a product with a sum, distributed: (3 sqrt(x)/2 + x)/x is 3/(2 sqrt(x)) + 1
                sums = [len(a.args) for a in expr.args if isinstance(a, sp.Add)]
                cancelled = sp.cancel(expr) if expr.is_rational_function(x) else puiseux_cancel(expr, x) or (
                    sp.expand_mul(expr, deep=False) if sums and sp.prod(sums) <= 64 else expr)  # (at most 64 terms)
                if cancelled != expr:
                    return _limit(cancelled, x)
                try:
                    return _power_beats_logarithm(expr, x)
                except NoLimit:
                    return _exponential_beats_power(expr, x)
        lim = _add(limits)
        if lim.side is None and not lim.infinite and sign_of(lim.value) == 0:
            lim = Lim(lim.value, _polynomial_side(expr, x))
        return lim
    if isinstance(expr, sp.Pow):
        base, ex = expr.args
        if ex.has(x):
            return _limit(sp.exp(ex * sp.log(base)), x)
        return _pow(_limit(base, x), ex)
    if isinstance(expr, sp.Piecewise):
        for branch, cond in expr.args:
            truth = _condition(cond, x)
            if truth is True:
                return _limit(branch, x)
            if truth is None:
                raise NoLimit(f"cannot decide {cond} near the limit")
        raise NoLimit("no branch of a Piecewise applies")
    if isinstance(expr, sp.Function) and len(expr.args) == 1:
        return _function(expr.func, _limit(expr.args[0], x))
    raise NoLimit(f"no limit rule for {expr.func.__name__}")


_NEAR = sp.Rational(1, 64)
_RATES = (sp.Integer(1), sp.Rational(1, 2), sp.Rational(1, 4), sp.Rational(1, 8))


def _logarithmic(factor, x) -> bool:
    """factor = G(u)^n, n > 0, G = log or asinh, u -> +oo at most as fast
    as a power of 1/x (u x^m has a finite limit, m <= 16): then 0 < factor
    <= C log(1/x)^n near 0+ (log u <= log C' + m log(1/x); asinh u <= log(2u + 1))."""
    base, n = factor.as_base_exp()
    if not (isinstance(base, (sp.log, sp.asinh)) and n.is_Rational and n > 0):
        return False
    u = base.args[0]
    try:
        if _limit(u, x).value != sp.oo:
            return False
        return any(not _limit(u * x ** m, x).infinite for m in (1, 2, 4, 8, 16))
    except NoLimit:
        return False


def _power_beats_logarithm(expr, x) -> Lim:
    """lim of the product expr = L * R, L the factors that are `_logarithmic`
    (-> +oo, below C log(1/x)^n), R the rest: when R x^-q has a finite
    limit for some q > 0, |L R| <= C' log(1/x)^n x^q -> 0, and L R has R's
    eventual sign."""
    slow = [a for a in expr.args if _logarithmic(a, x)]
    rest = sp.Mul(*[a for a in expr.args if a not in slow])
    if not slow or not rest.has(x):
        raise NoLimit("0 * inf")
    return _vanishes_beside(rest, x, [-q for q in _RATES])


def _vanishes_beside(rest, x, powers) -> Lim:
    """0 with rest's eventual sign, when rest x^p has a finite limit for one
    of `powers` (the other factors of the product, `_power_beats_logarithm`
    and `_exponential_beats_power`, then force it to 0); else NoLimit."""
    for p in powers:
        try:
            scaled = _limit(rest * x ** p, x)
        except NoLimit:
            continue
        if not scaled.infinite:
            return Lim(sp.Integer(0), _eventual_sign(_limit(rest, x)))
    raise NoLimit("0 * inf")


def _exponential_beats_power(expr, x) -> Lim:
    """lim of the product expr = E * R, E the factors exp(g) with g x^k ->
    L < 0 for some k > 0 (so g <= L/(2 x^k) near 0+), R the rest: when
    R x^m has a finite limit for some m >= 0, |E R| <= C x^-m exp(L/(2 x^k))
    -> 0, and E R has R's eventual sign (E > 0): exp(-1/x^2)/x -> 0+."""
    def fast(a):
        if not isinstance(a, sp.exp):
            return False
        for k in (*_RATES[::-1], 2, 4, 8):
            try:
                lim = _limit(a.args[0] * x ** k, x)
            except NoLimit:
                continue
            if not lim.infinite and sign_of(lim.value) < 0:
                return True
        return False
    quick = [a for a in expr.args if fast(a)]
    rest = sp.Mul(*[a for a in expr.args if a not in quick])
    if not quick:
        raise NoLimit("0 * inf")
    return _vanishes_beside(rest, x, (0, 1, 2, 4, 8, 16, 32))


def rational_poly(expr, x) -> sp.Poly | None:
    """expr as a nonzero polynomial in x with rational coefficients, or None."""
    poly = poly_of(expr, x)
    return None if poly is None or poly.is_zero else poly


def poly_of(e, x) -> sp.Poly | None:
    """e as a polynomial in x over Q, built along e's tree with polynomial
    arithmetic (Poly(e) would first expand e as an expression, seconds on a
    product of a dozen sums); None if e is not one."""
    if e == x:
        return sp.Poly(x, x, domain=sp.QQ)
    if e.is_Rational:
        return sp.Poly(e, x, domain=sp.QQ)
    if e.is_Add or e.is_Mul:
        parts = [poly_of(a, x) for a in e.args]
        if any(q is None for q in parts):
            return None
        out = parts[0]
        for q in parts[1:]:
            out = out + q if e.is_Add else out * q
        return out
    if e.is_Pow and e.exp.is_Integer and e.exp >= 0:
        base = poly_of(e.base, x)
        return None if base is None else base ** int(e.exp)
    return None


def rational_parts(e, x) -> tuple[sp.Poly, sp.Poly] | None:
    """(N, D) over Q, coprime, with e = N/D as rational functions of x,
    summed term by term in polynomial arithmetic (what `cancel` computes,
    without expanding e as an expression); None if e is not rational over Q."""
    num, den = sp.Poly(0, x, domain=sp.QQ), sp.Poly(1, x, domain=sp.QQ)
    for term in sp.Add.make_args(e):
        n, m = sp.fraction(sp.together(term))
        pn, pm = poly_of(n, x), poly_of(m, x)
        if pn is None or pm is None or pm.is_zero:
            return None
        num, den = num * pm + pn * den, den * pm
        g = num.gcd(den)
        num, den = num.exquo(g), den.exquo(g)
    return num, den


#: Largest denominator q of a rational exponent of a monomial-like base (rho, e1,
#: any homogeneous polynomial in e1, e2: s^d along the profile) that the search
#: takes: SymPy's polynomial algorithms then work in s^(1/q), with degrees that
#: grow with q (q = 100 outlasts the default timeout, 10^4 overflows an integer
#: conversion, and the 5*10^15 of a float 2/3 kills the process inside FLINT's
#: gcd).  (1 + rho)^(10^-20) stays one opaque generator and is decided, and so
#: is c rho^(p/q) alone.
MAX_ROOT_DEGREE = 64


def puiseux_cancel(e, x):
    """e over one denominator in lowest terms when its only non-rational
    parts are powers x^(p/q): rational in u = x^(1/q), q the least common
    denominator up to MAX_ROOT_DEGREE; None otherwise.  (4 x^(5/2) + 3 x^3)/(2 x^(7/2) + 2 x^(3/2)
    + 2 x^2), the tail form of log(1 + s^2 + s^(3/2))', becomes (4 x + 3 x^(3/2))/(2 x^2 + 2 x^(1/2) + 2),
    defined at x = 0; 2 x/(x^(5/2) + x^3 + x) becomes 2/(x^(3/2) + x^2 + 1)."""
    powers = [p for p in e.atoms(sp.Pow) if p.base == x and p.exp.is_Rational and not p.exp.is_Integer]
    q, u = math.lcm(*[int(p.exp.q) for p in powers]), sp.Dummy("u", positive=True)
    if not powers or q > MAX_ROOT_DEGREE:
        return None
    parts = rational_parts(sp.powsimp(e.xreplace({x: u ** q})), u)
    return None if parts is None else (parts[0].as_expr() / parts[1].as_expr()).xreplace({u: x ** sp.Rational(1, q)})


def _polynomial_side(expr, x) -> int | None:
    """Sign of a polynomial p with rational coefficients and p(0) = 0 on
    (0, eps): the sign of its lowest nonzero coefficient; None otherwise."""
    poly = rational_poly(expr, x)
    if poly is None:
        return None
    lowest = poly.terms()[-1][1]       # terms() lists the highest degree first
    return 1 if lowest > 0 else -1


def _bounded_near_zero(expr, x) -> bool:
    """expr is bounded for 0 < x <= 1/64 (interval arithmetic)."""
    try:
        box = IntervalFunction(expr, [x], mode="range")(Interval.of(0, _NEAR))
    except (Undefined, ValueError):
        return False
    return box.is_finite()


def _with_bounded(limits: list[Lim], is_sum: bool) -> Lim:
    """Terms (factors) without a limit but bounded near 0: a sum with an
    infinite part still tends to that infinity; a product with a part that
    tends to 0 (and nothing infinite) tends to 0."""
    part = _add(limits) if is_sum else (_mul(limits) if limits else None)
    if part is None:
        raise NoLimit("bounded factors without a limit")
    if is_sum and part.infinite:
        return part
    if not is_sum and not part.infinite and sign_of(part.value) == 0:
        return Lim(sp.Integer(0), None)
    raise NoLimit("a bounded term without a limit")


def _add(terms: list[Lim]) -> Lim:
    infs = {t.value for t in terms if t.infinite}
    if len(infs) == 2:
        raise NoLimit("inf - inf")
    if infs:
        v = infs.pop()
        return Lim(v, 1 if v == sp.oo else -1)
    value = sp.Add(*[t.value for t in terms])
    if sign_of(value) != 0:
        return Lim(value, None)
    sides = {t.side for t in terms if t.side != 0}
    if not sides:
        return Lim(value, 0)
    return Lim(value, sides.pop() if len(sides) == 1 and None not in sides else None)


def _mul(factors: list[Lim]) -> Lim:
    zero = any(sign_of(f.value) == 0 for f in factors)
    inf = any(f.infinite for f in factors)
    if zero and inf:
        raise NoLimit("0 * inf")
    signs = [_eventual_sign(f) for f in factors]
    sign = None if None in signs else int(sp.prod(signs))
    if inf:
        if sign is None or sign == 0:
            raise NoLimit("sign of an infinite product unknown")
        return Lim(sp.oo if sign > 0 else -sp.oo, sign)
    value = sp.Mul(*[f.value for f in factors])
    if all(f.side == 0 for f in factors):
        return Lim(value, 0)
    return Lim(value, sign if sign_of(value) == 0 else None)


def _pow(base: Lim, ex: sp.Expr) -> Lim:
    e_sign = sign_of(ex)
    if e_sign == 0:
        return Lim(sp.Integer(1), 0)
    integer = ex.is_integer is True
    b_sign = _eventual_sign(base)
    if b_sign is None:
        if integer and e_sign > 0 and not base.infinite:
            return Lim(base.value ** ex, None)      # continuity of x**n
        raise NoLimit("power of a quantity of unknown sign")
    if b_sign < 0 and not integer:
        raise NoLimit("non-integer power of a negative quantity")
    odd = integer and int(ex) % 2 != 0
    out_sign = -1 if (b_sign < 0 and odd) else 1
    if base.infinite:
        if e_sign > 0:
            return Lim(sp.oo if out_sign > 0 else -sp.oo, out_sign)
        return Lim(sp.Integer(0), out_sign)
    if sign_of(base.value) == 0:
        if base.side == 0:
            if e_sign < 0:
                raise NoLimit("0 to a negative power")
            return Lim(sp.Integer(0), 0)
        if e_sign > 0:
            return Lim(sp.Integer(0), out_sign)
        return Lim(sp.oo if out_sign > 0 else -sp.oo, out_sign)
    return Lim(base.value ** ex, 0 if base.side == 0 else None)


def _function(func, arg: Lim) -> Lim:
    if arg.infinite:
        if func in _MONOTONE_AT_INF:
            at_pos, at_neg = _MONOTONE_AT_INF[func]
            v = at_pos if arg.value == sp.oo else at_neg
            if v in (sp.oo, -sp.oo):
                return Lim(v, 1 if v == sp.oo else -1)
            # tanh, atan, erf approach their finite limits from inside
            return Lim(v, 1 if v == 0 else None)
        if func is sp.log and arg.value == sp.oo:
            return Lim(sp.oo, 1)
        if func is sp.Abs:
            return Lim(sp.oo, 1)
        raise NoLimit(f"{func.__name__} at infinity")
    s = sign_of(arg.value)
    if func is sp.log:
        if s > 0:
            return Lim(sp.log(arg.value), None if arg.side != 0 else 0)
        if s == 0 and arg.side == 1:
            return Lim(-sp.oo, -1)
        raise NoLimit("log of a non-positive quantity")
    if func is sp.sign:
        e = _eventual_sign(arg)
        if e is None:
            raise NoLimit("sign of a quantity of unknown sign")
        return Lim(sp.Integer(e), 0)
    if func is sp.Abs:
        if s == 0:
            return Lim(sp.Integer(0), 1 if arg.side in (1, -1) else (0 if arg.side == 0 else None))
        return Lim(abs(arg.value), None if arg.side != 0 else 0)
    if func in (sp.exp, sp.sin, sp.cos, sp.tanh, sp.sinh, sp.cosh, sp.atan, sp.asinh, sp.erf):
        value = func(arg.value)
        if arg.side == 0:
            return Lim(value, 0)
        if s == 0 and func in (sp.sin, sp.tanh, sp.sinh, sp.atan, sp.asinh, sp.erf):
            return Lim(value, arg.side)    # odd, increasing through 0
        return Lim(value, None)
    raise NoLimit(f"no limit rule for {func.__name__}")


def _condition(cond, x) -> bool | None:
    if cond is sp.true or cond is True:
        return True
    if cond is sp.false or cond is False:
        return False
    if isinstance(cond, sp.And):
        vals = [_condition(c, x) for c in cond.args]
        return False if False in vals else (None if None in vals else True)
    if isinstance(cond, sp.Or):
        vals = [_condition(c, x) for c in cond.args]
        return True if True in vals else (None if None in vals else False)
    if isinstance(cond, sp.Not):
        v = _condition(cond.args[0], x)
        return None if v is None else not v
    if isinstance(cond, sp.core.relational.Relational):
        d = _limit(cond.lhs - cond.rhs, x)
        sgn = _eventual_sign(d)
        if sgn is None or (sgn == 0 and d.side is None):
            return None
        if isinstance(cond, (sp.StrictGreaterThan, sp.GreaterThan)):
            return sgn > 0 or (sgn == 0 and isinstance(cond, sp.GreaterThan))
        if isinstance(cond, (sp.StrictLessThan, sp.LessThan)):
            return sgn < 0 or (sgn == 0 and isinstance(cond, sp.LessThan))
        if isinstance(cond, sp.Eq):
            return sgn == 0
        if isinstance(cond, sp.Ne):
            return sgn != 0
    return None


def limit_right(expr: sp.Expr, x: sp.Symbol) -> Lim:
    """lim_{x -> 0+} expr, proved by the rules above, or `NoLimit`."""
    return _limit(sp.sympify(expr), x)
