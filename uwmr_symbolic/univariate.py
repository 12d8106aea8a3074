"""Rigorous facts about one real function of one variable on an interval of
[0, oo): strict or weak sign, and enclosures of the supremum.

Once P4 reduces f to a radial profile F(s), s = |(e1, e2)|, every property
of the paper is a statement of this kind about F, F', F'' or F'/s.  The
arguments used here, and only these, make a claim "proved":

* interval arithmetic with outward rounding (`interval.IntervalFunction`)
  over a finite cover of the compact part [lo, R];
* the substitution s = 1/t, which turns the unbounded part [R, oo) into the
  compact t-interval [0, 1/R] evaluated with extended (limit) arithmetic;
* near a point c where the function vanishes, Taylor's theorem with the
  Lagrange remainder: if E(c) = ... = E^(m-1)(c) = 0 exactly and E^(m) has a
  sign on [c, c + w] (continuous-mode interval evaluation), E has that sign
  (times (+-1)^m) on the punctured neighbourhood;
* the sign of a product is the product of the signs of its factors.

Refutations come with a point whose value is certified by interval
arithmetic at an exact rational point, or an exact zero found by SymPy and
confirmed by exact substitution.
"""
from __future__ import annotations

import heapq
import math
import sys
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache

import sympy as sp
from flint import arb

from .interval import NINF, PINF, Interval, IntervalFunction, Undefined, mean_value_form
from .kernel import core as K
from .limits import NoLimit, exact_sign, limit_right, puiseux_cancel, rational_parts, rational_poly
from .timeouts import attempt
from .verdict import Verdict, proved, refuted, unknown

T = sp.Symbol("t", positive=True)       # t = 1/s on the unbounded part
X = sp.Symbol("x", positive=True)       # distance from a boundary point

MAX_BOXES = 4000          # bisection budget for one sign proof
REGROUP_MAX_OPS = 120     # `prepare` regroups sums up to this size (sympy.count_ops)
TAYLOR_ORDER = 6          # highest derivative tried at a zero
NEAR_WIDTHS = [Fraction(1, 2 ** k) for k in range(1, 16, 2)]


# --------------------------------------------------------------------------
# expression preparation

def _hyperbolic_to_tanh(expr: sp.Expr) -> sp.Expr:
    """sinh(a)**p * cosh(a)**-p -> tanh(a)**p inside products: the quotient
    form is inf/inf for large a, tanh is bounded (also what code generation
    wants: a sinh/cosh overflows at about 710)."""
    def fix(m):
        if not isinstance(m, sp.Mul):
            return m
        powers = {}
        for factor in m.args:
            b, e = factor.as_base_exp()
            powers[b] = powers.get(b, 0) + e
        changed = False
        for b in list(powers):
            if isinstance(b, sp.sinh):
                c = sp.cosh(b.args[0])
                if c in powers and powers[c] == -powers[b]:
                    p = powers.pop(b)
                    powers.pop(c)
                    powers[sp.tanh(b.args[0])] = powers.get(sp.tanh(b.args[0]), 0) + p
                    changed = True
        if not changed:
            return m
        return sp.Mul(*[b ** e for b, e in powers.items()])
    return sp.bottom_up(expr, fix)


def _one_minus_tanh_squared(expr: sp.Expr) -> sp.Expr:
    """Write 1 - tanh(x)^2 as cosh(x)^-2 where differentiation spread it over
    a sum: the difference of two O(1) terms that is exponentially small is
    hopeless for interval arithmetic, cosh(x)^-2 is not."""
    squares = [p for p in expr.atoms(sp.Pow) if isinstance(p.base, sp.tanh) and p.exp == 2]
    if not squares or not isinstance(expr, sp.Add):
        return expr
    out = sp.expand_mul(expr.xreplace({p: 1 - sp.cosh(p.base.args[0]) ** -2 for p in squares}))
    return out if sp.count_ops(out) <= sp.count_ops(expr) + 12 else expr


#: exact points at which a rewrite or a SymPy identity is re-checked (the
#: i-th coordinate goes to the i-th variable in name order; absolute values
#: for a nonnegative variable)
_CHECK_POINTS = [(sp.Rational(3, 7), sp.Rational(-5, 11)), (sp.Rational(-13, 3), sp.Rational(2, 9)),
                 (sp.Rational(1, 1000), sp.Rational(7, 1000)), (sp.Rational(123, 4), sp.Rational(-77, 2)),
                 (sp.Rational(-2, 5), 0), (0, sp.Rational(19, 17)), (sp.Rational(1001, 10), sp.Rational(3, 10)),
                 (sp.Rational(-6, 13), sp.Rational(-9, 8))]


def numerically_equal(a, b, prec=300) -> bool:
    """No check point separates a and b (Arb at `prec` bits), and at least
    half of the points give enclosures of both narrower than 2^-200 of
    their size: the independent cross-check that a SymPy simplification
    or a rewrite must pass before it is used."""
    variables = sorted((a - b).free_symbols | a.free_symbols | b.free_symbols, key=lambda v: v.name)
    if len(variables) > 2:
        return False
    if not variables:
        return exact_sign(a - b) == 0
    try:
        fa, fb = (IntervalFunction(x, variables, mode="range", prec=prec) for x in (a, b))
    except (Undefined, TypeError, ValueError):
        return False
    tight = 0
    for point in _CHECK_POINTS:
        args = [Interval.point(abs(x) if v.is_nonnegative else x, prec=prec) for v, x in zip(variables, point)]
        try:
            ba, bb = fa(*args), fb(*args)
        except Undefined:
            continue
        if not (ba.is_finite() and bb.is_finite()):
            continue
        # exact endpoint arithmetic on the arbs (Fractions of exp(-10^30) would not fit in memory)
        if ba.hi < bb.lo or bb.hi < ba.lo:
            return False        # disjoint enclosures: a != b at this point
        size = max(abs(ba.lo), abs(ba.hi), arb(1))
        tight += all((box.hi - box.lo) < size * arb(2) ** -200 for box in (ba, bb))
    return 2 * tight >= len(_CHECK_POINTS)


def _checked_rewrite(expr, out):
    """out if it passes the numeric cross-check against expr, else expr."""
    if out == expr or numerically_equal(out, expr):
        return out
    return expr


@lru_cache(maxsize=2048)
def prepare(expr: sp.Expr) -> sp.Expr:
    """A form of expr that interval arithmetic handles well (same function):
    tanh instead of sinh/cosh, cosh^-2 instead of 1 - tanh^2, and sums
    regrouped on their transcendental factors (fewer cancelling terms).
    Each rewrite is cross-checked (`numerically_zero`) before it is kept."""
    out = _one_minus_tanh_squared(_hyperbolic_to_tanh(expr))
    # regrouping collects and factors: fast on the sizes it helps with (a few
    # dozen operations), minutes on the derivatives of deeply nested profiles
    if isinstance(out, sp.Add) and out.has(sp.Function) and sp.count_ops(out) <= REGROUP_MAX_OPS:
        syms = list(out.free_symbols)
        if len(syms) == 1:
            grouped = _regroup(out, syms[0])
            if sp.count_ops(grouped) <= sp.count_ops(out):
                out = grouped
    return _checked_rewrite(expr, out)


def _cancel_rational_part(term: sp.Expr) -> sp.Expr:
    funcs = [f for f in sp.Mul.make_args(term) if f.has(sp.Function, sp.Piecewise)]
    rest = sp.Mul(*[f for f in sp.Mul.make_args(term) if not f.has(sp.Function, sp.Piecewise)])
    return sp.cancel(sp.together(rest)) * sp.Mul(*funcs)


def _distribute(expr: sp.Expr) -> sp.Expr:
    """expr with products distributed over the sums among their factors, and
    nothing else multiplied out: `expand_mul` also expands denominators, and a
    denominator of n factors (1 + L_k) gives 2^n terms (the derivatives of n
    nested logs)."""
    terms = []
    for term in sp.Add.make_args(expr):
        factors = sp.Mul.make_args(term)
        sums = [f for f in factors if f.is_Add]
        if not sums:
            terms.append(term)
            continue
        products = [sp.Mul(*[f for f in factors if not f.is_Add])]
        for a in sums:
            products = [p * b for p in products for b in sp.Add.make_args(a)]
        terms += [_distribute(p) for p in products]
    return sp.Add(*terms)


def tail_start(lo) -> sp.Integer:
    """Where the unbounded part [R, oo) of an interval starting at lo begins."""
    return sp.Integer(max(4, int(2 * float(lo) + 4)))


def decimal_beyond(x: Fraction, side: int, digits: int = 8) -> sp.Rational:
    """A decimal of about `digits` significant digits >= x (side 1) or <= x
    (side -1); the decimal exponent of x > 0 comes from its integers, so no
    size of x overflows or underflows a float (x <= 0: `digits` - 1 places)."""
    x = Fraction(x)
    exp10 = math.floor(math.log10(x.numerator) - math.log10(x.denominator)) if x > 0 else 0
    scale = Fraction(10) ** (digits - 1 - exp10)
    n = math.ceil(x * scale) if side > 0 else math.floor(x * scale)
    return sp.Rational(n) / sp.Rational(scale)


def far_out_trend(expr, var) -> int:
    """-1 if expr(10^6) < expr(10^3), +1 if expr(10^6) > expr(10^3), 0 if
    undecided (certified enclosures): a cheap look far out that orders the
    search's work (a limit at oo is slow), never a verdict."""
    try:
        near, far = (value_at(expr, var, sp.Integer(10) ** k, prec=64) for k in (3, 6))
    except (Undefined, OverflowError, ValueError):
        return 0
    return -1 if far.hi < near.lo else 1 if near.hi < far.lo else 0     # (Arb ends: exp(-10^12) fits no Fraction)


@lru_cache(maxsize=2048)
def limit_at_infinity(expr, var):
    """lim expr as var -> oo by the limit calculus on expr(1/t), t -> 0+,
    tried on the plain substitution and on the tail form; raises NoLimit."""
    last = None
    for form in (substitute(prepare(expr), var, 1 / T), tail_form(expr, var)):
        try:
            return limit_right(form, T).value
        except NoLimit as exc:
            last = exc
    raise last


@lru_cache(maxsize=2048)
def tail_form(expr: sp.Expr, s: sp.Symbol) -> sp.Expr:
    """expr(1/t) for t > 0, with radicals of rational functions brought over a
    common denominator so that powers of t cancel (sqrt(4/t**2 + 1) becomes
    sqrt(t**2 + 4)/t).  An identity for t > 0."""
    e = substitute(_distribute(expr), s, 1 / T)
    # radicands and function arguments over a common denominator (memoised: the
    # derivative of a nested profile repeats the same arguments many times)...
    seen = {}

    def together(a):
        if a not in seen:
            seen[a] = sp.together(a)
        return seen[a]
    e = sp.bottom_up(e, lambda node: node.func(*[together(a) if isinstance(a, sp.Add) else a
                                                 for a in node.args])
                     if isinstance(node, (sp.Pow, sp.Function)) and node.args else node)
    # ...and each term's rational factor cancelled on its own: merging the
    # terms of a sum into one fraction makes 0*oo forms such as t^3 log(1/t)
    e = sp.Add(*[_cancel_rational_part(term) for term in sp.Add.make_args(e)])
    e = prepare(e)
    e = e.replace(lambda n: isinstance(n, sp.atan) and n.args[0].is_positive and
                  (1 / n.args[0]).count_ops() < n.args[0].count_ops(),
                  lambda n: sp.pi / 2 - sp.atan(sp.cancel(1 / n.args[0])))
    if not e.has(sp.Function, sp.Piecewise) and not _stays_a_sum(e):
        parts = rational_parts(e, T)
        e = parts[0].as_expr() / parts[1].as_expr() if parts is not None else puiseux_cancel(e, T) or sp.cancel(e)
    return _checked_rewrite(substitute(expr, s, 1 / T), e)


#: a rational tail form stays a sum when its terms' distinct denominators have more
#: than this total degree (the degree of the one denominator they would share)
TERMWISE_DEGREE = 64


def _stays_a_sum(e) -> bool:
    """e is a sum of terms whose denominators, polynomials in t, do not
    vanish at t = 0 and, counted once each, have a total degree above
    TERMWISE_DEGREE.  Over one denominator such a sum has a numerator of
    high degree whose interval enclosure is too wide to sign (the derivative
    of a chain of 16 C^2 joins, degree 284: 4,000 boxes undecided; term by
    term 1.6 s), while a small one is better merged (terms that cancel to
    leading order near t = 0)."""
    dens = {sp.denom(t) for t in sp.Add.make_args(e)}
    if not all(d.is_polynomial(T) and d.subs(T, 0) != 0 for d in dens):
        return False
    return sum(sp.degree(d, T) for d in dens) > TERMWISE_DEGREE


@lru_cache(maxsize=4096)
@lru_cache(maxsize=1024)
def _compiled(expr: sp.Expr, var: sp.Symbol, mode: str, prec: int = 128) -> IntervalFunction:
    """expr compiled for interval evaluation, memoised (the chain of 16 joins
    asks 4,800 times for 447 functions)."""
    return IntervalFunction(expr, [var], mode=mode, prec=prec)


def enclose(expr, var, lo, hi, mode="range") -> Interval:
    """Enclosure of expr over var in [lo, hi] (raises Undefined)."""
    return _compiled(expr, var, mode)(Interval.of(lo, hi))


def value_at(expr, var, point, prec=256) -> Interval:
    """Tight certified enclosure of expr at an exact point."""
    return _compiled(expr, var, "range", prec)(Interval.point(point, prec))


_BINDERS = (sp.Derivative, sp.Integral, sp.Subs, sp.Lambda, sp.Sum, sp.Product)


def substitute(expr, var, value):
    """expr with the symbol var replaced by value: `xreplace` (the same result
    as `subs` for a free symbol, and 80 to 600 times faster on the chain
    family's derivatives) unless expr binds variables, where `subs` is needed."""
    expr, value = sp.sympify(expr), sp.sympify(value)
    return expr.subs(var, value) if expr.has(*_BINDERS) else expr.xreplace({var: value})


def exact_value(expr, var, point):
    """expr at an exact point, as an exact SymPy number, or None."""
    try:
        v = substitute(expr, var, point)
    except (ZeroDivisionError, TypeError, ValueError):
        return None
    if v.has(sp.nan, sp.zoo, sp.oo, -sp.oo) or v.free_symbols or isinstance(v, sp.Piecewise):
        return None
    return v


def certified_inside(c, lo, hi) -> bool:
    """The exact real number c is certified to lie in the open (lo, hi)."""
    try:
        if c.has(sp.I):
            return False
        box = Interval.point(c)
        return box.lower_fraction() > Interval.point(lo).upper_fraction() and (
            hi == sp.oo or box.upper_fraction() < Interval.point(hi).lower_fraction())
    except (TypeError, ValueError, Undefined):
        return False


def rational_between(lo, hi) -> sp.Rational:
    """A simple exact rational strictly inside (lo, hi), lo < hi finite."""
    if isinstance(lo, sp.Rational) and isinstance(hi, sp.Rational):
        lo_f, hi_f = Fraction(int(lo.p), int(lo.q)), Fraction(int(hi.p), int(hi.q))
    else:
        lo_f = Interval.point(lo).upper_fraction()
        hi_f = Interval.point(hi).lower_fraction()
    mid = (lo_f + hi_f) / 2
    # prefer short rationals
    for den in (1, 2, 4, 8, 10, 16, 100, 1000, 10 ** 6):
        cand = Fraction(round(mid * den), den)
        if lo_f < cand < hi_f:
            return sp.Rational(cand.numerator, cand.denominator)
    return sp.Rational(mid.numerator, mid.denominator)


# --------------------------------------------------------------------------
# sign of E near a point (one side)

def _derivative_values(expr, var, c, order):
    """Exact values E(c), E'(c), ..., up to the first nonzero one."""
    out = []
    d = expr
    for k in range(order + 1):
        v = exact_value(d, var, c)
        if v is None:
            return out, None
        sgn = exact_sign(v)
        if sgn is None:
            return out, None
        out.append(sgn)
        if sgn != 0:
            return out, d
        d = sp.diff(d, var)
    return out, None


def _sign_near(expr, var, c, side: int, want: int, width: Fraction) -> bool:
    """True if want*expr > 0 on the punctured one-sided neighbourhood
    (c, c + width] (side=+1) or [c - width, c) (side=-1); False if not shown."""
    lo, hi = (c, c + sp.Rational(width)) if side > 0 else (c - sp.Rational(width), c)
    try:
        box = enclose(expr, var, lo, hi)
        if (box.is_positive() if want > 0 else box.is_negative()):
            return True
    except Undefined:
        pass
    # the variable itself, or a factor (var - c) with the right orientation
    if expr == var and c == 0 and side > 0:
        return want > 0
    if isinstance(expr, sp.Pow) and not expr.exp.is_integer:
        # a real power is defined and positive exactly where its base is > 0
        return want > 0 and _sign_near(expr.base, var, c, side, 1, width)
    if isinstance(expr, sp.Pow) and expr.exp.is_integer:
        # b**n and b**-n have the sign of b**|n|
        n = abs(int(expr.exp))
        if n % 2 == 0:
            return want > 0 and (_sign_near(expr.base, var, c, side, 1, width)
                                 or _sign_near(expr.base, var, c, side, -1, width))
        return _sign_near(expr.base, var, c, side, want, width)
    if isinstance(expr, sp.Mul):
        factors = expr.args
        total = 1
        for factor in factors:
            if not factor.has(var):
                sgn = exact_sign(factor)
                if not sgn:
                    return False
            elif _sign_near(factor, var, c, side, 1, width):
                sgn = 1
            elif _sign_near(factor, var, c, side, -1, width):
                sgn = -1
            else:
                return False
            total *= sgn
        return total == want
    if isinstance(expr, _SIGN_PRESERVING) and len(expr.args) == 1:
        # odd, strictly increasing, g(0) = 0: g(Y) has the sign of Y
        return _sign_near(expr.args[0], var, c, side, want, width)
    if isinstance(expr, sp.exp):
        return want > 0
    if isinstance(expr, sp.log):
        # log(Y) > 0 iff Y - 1 > 0;  log(Y) < 0 iff 0 < Y < 1
        y = expr.args[0]
        if want > 0:
            return _sign_near(y - 1, var, c, side, 1, width)
        return _sign_near(y - 1, var, c, side, -1, width) and _sign_near(y, var, c, side, 1, width)
    if isinstance(expr, sp.Add):
        if _sum_sign_near(expr, var, lo, hi, c, side, want, width):
            return True
        # regrouping is costly: only when the sum as written fails, and (as in prepare) a small sum
        form = _regroup(expr, var) if sp.count_ops(expr) <= REGROUP_MAX_OPS else expr
        if form != expr and (_sum_sign_near(form, var, lo, hi, c, side, want, width) if isinstance(form, sp.Add)
                             else _sign_near(form, var, c, side, want, width)):
            return True
    if isinstance(expr, sp.Add) and sp.count_ops(expr) <= REGROUP_MAX_OPS and \
            any(isinstance(a, sp.Pow) and a.exp.is_negative for a in expr.atoms(sp.Pow)):
        form = sp.together(expr)        # 0/0 at c: sinh(s^2)/s^2 - 1 as (sinh(s^2) - s^2)/s^2, signed factor by factor
        if isinstance(form, sp.Mul) and _sign_near(form, var, c, side, want, width):
            return True
    if _composed_sign_near(expr, var, lo, hi, c, side, want):
        return True
    # Taylor with Lagrange remainder at c
    signs, dm = _derivative_values(expr, var, c, TAYLOR_ORDER)
    if dm is None or not signs or signs[-1] == 0:
        return False
    m = len(signs) - 1
    if signs[-1] * (side ** m) != want:
        return False
    try:
        box = enclose(dm, var, lo, hi, mode="continuous")
    except Undefined:
        return False
    return box.is_positive() if signs[-1] > 0 else box.is_negative()


_SIGN_PRESERVING = (sp.tanh, sp.atan, sp.asinh, sp.sinh, sp.erf)
U = sp.Symbol("u", real=True)     # an inner expression, for the composition rule


def replaced(e, u, U):
    """e with u replaced by U, as a subterm and, for a sum u, among the terms
    of a larger sum (u - sin(u) with u = sqrt(1 + s^2) - 1).  Structural:
    SymPy's `subs` of a subterm may run `powdenest`, whose assumption
    queries can factor huge polynomials in C, where no time limit reaches."""
    if e == u:
        return U
    if not e.args:
        return e
    e = e.func(*[replaced(a, u, U) for a in e.args])
    if e.is_Add and u.is_Add:
        rest = list(e.args)
        for t in u.args:
            if t not in rest:
                return e
            rest.remove(t)
        return sp.Add(U, *rest)
    return e


def log_of(e, var):
    """L when e is built by +, * and integer powers from constants and one
    L = log(...) or asinh(...) holding var (a rational function of L: 1 -
    L/(1 + L)), else None.  Walks e's sums, products and powers only."""
    found = set()

    def walk(x):
        if not x.has(var):
            return True
        if isinstance(x, (sp.log, sp.asinh)):
            found.add(x)
            return len(found) == 1
        if x.is_Add or x.is_Mul or x.is_Pow and x.exp.is_Integer:
            return all(walk(a) for a in x.args)
        return False
    return next(iter(found)) if walk(e) and found else None


def _composed_sign_near(expr, var, lo, hi, c, side, want) -> bool:
    """expr = G(u(var)) for an inner u with u(c) = 0 and a sign beside c:
    then expr has the sign of G on the u-interval (0, max u] (or [min u, 0)),
    a one-variable problem whose derivatives are far simpler (u - sin u has
    a zero of order 6 in s but of order 3 in u)."""
    inner = {a for f in expr.atoms(sp.Function) for a in f.args if a.has(var) and a != var}
    for u in sorted(inner, key=sp.count_ops):
        at_c = exact_value(u, var, c)          # first: a substitution in a large expr costs more
        if at_c is None or exact_sign(at_c) != 0:
            continue
        G = replaced(expr, u, U)
        if G.has(var) or not G.has(U):
            continue
        for u_side in (1, -1):
            if not _sign_near(u, var, c, side, u_side, Fraction(hi - lo) if hi != lo else Fraction(0)):
                continue
            try:
                box = enclose(u, var, lo, hi)
            except Undefined:
                return False
            reach = box.upper_fraction() if u_side > 0 else -box.lower_fraction()
            if reach is None or reach <= 0:
                return False
            return _sign_near(G, U, sp.Integer(0), u_side, want, reach)
    return False


@lru_cache(maxsize=1024)
def _regroup(expr, var):
    """The same sum with terms collected on their transcendental factors and
    polynomial coefficients factored: t(t^2+4)^2 X - 4t(t^2+4) X becomes
    t^3 (t^2+4) X, whose sign the product rule can see."""
    funcs = sorted({f for f in expr.atoms(sp.Function) if f.has(var)}, key=sp.default_sort_key)
    try:
        grouped = sp.collect(expr, funcs)
    except Exception:  # noqa: BLE001
        return expr
    common = sp.factor_terms(grouped)
    if not isinstance(common, sp.Add):
        return common
    terms = []
    for term in sp.Add.make_args(grouped):
        coeff, rest = term.as_independent(*funcs, as_Add=False)
        if coeff.has(var) and not coeff.has(sp.Function, sp.Piecewise):
            coeff = sp.factor(sp.together(coeff))
        terms.append(coeff * rest)
    return sp.Add(*terms)


def _sum_sign_near(expr, var, lo, hi, c, side, want, width) -> bool:
    """A sum has sign `want` if every term has it weakly on the closed box
    (interval arithmetic) and one term has it strictly (recursively)."""
    strict_found = False
    for term in expr.args:
        try:
            box = enclose(term, var, lo, hi)
        except Undefined:
            return False
        if not (box.is_nonnegative() if want > 0 else box.is_nonpositive()):
            return False
        if not strict_found and (
                (box.is_positive() if want > 0 else box.is_negative())
                or (term.has(var) and _sign_near(term, var, c, side, want, width))):
            strict_found = True
    return strict_found


def sign_near(expr, var, c, side, want) -> Fraction | None:
    """Largest tried width on which want*expr > 0 beside c, or None."""
    for w in NEAR_WIDTHS:
        try:
            if _sign_near(expr, var, c, side, want, w):
                return w
        except Undefined:
            continue
    return None


def zero_of_denominator(expr, var, order=TAYLOR_ORDER):
    """(N, D, D^(m), m) for expr = N/D over one denominator (`sympy.together`)
    whose D vanishes at 0 to order m, 1 <= m <= `order` (`_derivative_values`:
    D^(m)(0) the first value not 0), or None."""
    num, den = map(sp.sympify, sp.fraction(sp.together(expr)))
    dsigns, dm = _derivative_values(den, var, 0, order)
    return None if dm is None or len(dsigns) < 2 else (num, den, dm, len(dsigns) - 1)


def quotient_near_zero(expr, var, width) -> Interval | None:
    """An enclosure of expr on (0, width] where it is 0/0 at 0: expr = N/D
    over one denominator, N(0) = ... = N^(m-1)(0) = D(0) = ... = D^(m-1)(0)
    = 0 with D^(m)(0) != 0 (`zero_of_denominator`): by Taylor with the
    Lagrange remainder expr(x) = N^(m)(xi)/D^(m)(eta), xi, eta in (0, x), so
    N^(m)([0, w]) / D^(m)([0, w]) encloses it (the quotient written so that
    SymPy cancels nothing: each side is enclosed on its own).  None if not so."""
    found = zero_of_denominator(expr, var)
    if found is None:
        return None
    nm, _, dm, m = found
    for _ in range(m):
        if exact_value(nm, var, 0) != 0:
            return None
        nm = sp.diff(nm, var)
    try:
        return enclose(sp.Mul(nm, sp.Pow(dm, -1, evaluate=False), evaluate=False), var, 0, width, mode="continuous")
    except Undefined:
        return None


# --------------------------------------------------------------------------
# sign of E on a whole interval

def _witness_check(expr, var, point, want, strict=True) -> bool:
    """True if want*expr(point) <= 0 (strict claim) or < 0 (weak), certified."""
    try:
        box = value_at(expr, var, point)
    except Undefined:
        return False
    if strict:
        return box.is_nonpositive() if want > 0 else box.is_nonnegative()
    return box.is_negative() if want > 0 else box.is_positive()


def _exact_zero_in(expr, var, lo, hi):
    """An exact zero of expr in (lo, hi) found by SymPy and confirmed by exact
    substitution, or None."""
    return next(iter(exact_zeros_in(expr, var, lo, hi)), None)


#: expressions larger than this (`count_ops`) get no zero proposals: solveset on the
#: derivative of a chain of 16 C^2 joins (about 1,000 operations) ran for a minute
ZERO_SEARCH_OPS = 150


#: SymPy's solveset writes exp(k u) as exp(u)**k and x**k as a polynomial of degree k:
#: beyond this k its dense polynomials fill memory (exp(-10^6 (s^2 - 3)^2): 9 GB in a minute)
SOLVESET_MAX_RATE = 1000


def small_rates(expr) -> bool:
    """No power or exponential rate in expr beyond SOLVESET_MAX_RATE, so
    that SymPy's solveset may be asked about it."""
    rates = [p.exp for p in expr.atoms(sp.Pow)]
    rates += [t.as_coeff_Mul()[0] for g in expr.atoms(sp.exp) for t in sp.Add.make_args(sp.expand(g.args[0]))
              if t.free_symbols]
    return all(not (r.is_Number and abs(r) > SOLVESET_MAX_RATE) for r in rates)


def solveset_hopeless(expr, var) -> bool:
    """A factor of expr is a sum that holds var both inside a function of a
    radical of var and outside every function: 16 s (1 - tanh(u)^2)/(4 s^2 + 1)
    - 16 s tanh(u)/(4 s^2 + 1)^(3/2), u = sqrt(4 s^2 + 1) - 1.  SymPy's
    solveset has no inverse for such a mixed equation and returns a
    ConditionSet, after half a second on design 3's F'/s (1 - cos(u) = 0
    alone it solves: u = 2 pi n)."""
    for f in sp.Mul.make_args(expr):
        apps = [g for g in f.atoms(sp.Function) if g.has(var)]
        radical = any(p.exp.is_Rational and not p.exp.is_Integer and p.has(var) for g in apps for p in g.atoms(sp.Pow))
        if radical and f.xreplace({g: sp.Dummy() for g in apps}).has(var):
            return True
    return False


def exact_zeros_in(expr, var, lo, hi) -> list:
    """The zeros of expr in (lo, hi) that SymPy proposes and exact
    substitution confirms (SymPy may miss some: a proposal, not a census;
    none for an expression of more than ZERO_SEARCH_OPS operations, without
    `small_rates` or `solveset_hopeless`)."""
    if sp.count_ops(expr) > ZERO_SEARCH_OPS or not small_rates(expr) or solveset_hopeless(expr, var):
        return []
    # within 3 s: solveset may factor a polynomial for the whole --timeout (Wang's algorithm, in an
    # order that depends on string hashes: a design took 10 s or 30 s by PYTHONHASHSEED)
    sols = attempt(lambda: sp.solveset(sp.Eq(expr, 0), var, sp.Interval.open(lo, hi)), 3.0)
    if sols is None:
        return []
    out = []
    for root in sorted(set(_set_candidates(sols)), key=sp.default_sort_key):
        if not root.is_number or not certified_inside(root, lo, hi):
            continue
        v = exact_value(expr, var, root)
        if v is not None and exact_sign(v) == 0:
            out.append(root)
    return sorted(out, key=lambda r: Interval.point(r).lower_fraction())


def _set_candidates(sset, depth=0):
    """Points proposed by a SymPy solution set (finite sets, unions,
    intersections, image sets over the integers for |n| <= 6).  Only a
    proposal: the caller checks each point exactly."""
    if depth > 4:
        return
    if isinstance(sset, sp.FiniteSet):
        yield from sset.args
    elif isinstance(sset, (sp.Union, sp.Intersection)):
        for part in sset.args:
            yield from _set_candidates(part, depth + 1)
    elif isinstance(sset, sp.ImageSet) and len(sset.lamda.variables) == 1:
        base = sset.base_sets[0]
        points = range(-6, 7) if base == sp.S.Integers else _set_candidates(base, depth + 1)
        for b in points:
            try:
                yield sset.lamda(b)
            except Exception:  # noqa: BLE001
                continue


def _accepts(box, want, strict):
    if strict:
        return box.is_positive() if want > 0 else box.is_negative()
    return box.is_nonnegative() if want > 0 else box.is_nonpositive()


MEAN_VALUE_MISSES = 64     # a cover stops trying the mean value form after this many failures in a row


def _mean_value_accepts(fn, expr, var, u, v, want, strict, state) -> bool:
    """The mean value form of expr on [u, v] (`interval.mean_value_form`)
    has the sign: near a small positive minimum it loses about the box width
    squared, where the range form loses about the width.  `state` (per
    cover, empty at first): the compiled expr' (None if it cannot be
    compiled) and the failures in a row; after MEAN_VALUE_MISSES of them the
    form is not tried again (a sign change, or a region it does not help)."""
    try:
        if not state:
            state += [None, 0]
            state[0] = _compiled(sp.diff(expr, var), var, "continuous")
        if state[0] is None or state[1] >= MEAN_VALUE_MISSES:
            return False
        box = mean_value_form(fn, state[0], u, v, want)
        ok = box is not None and _accepts(box, want, strict)
    except (Undefined, ValueError, TypeError):
        ok = False
    state[1] = 0 if ok else state[1] + 1
    return ok


def _cover(expr, var, lo, hi, want, left_open, right_open, budget, strict=True) -> Verdict:
    """want*expr > 0 on the finite interval between lo and hi (exact), using
    one-sided lemmas at open ends, bisection in between."""
    a, b = lo, hi
    # at an open end the function may vanish: a one-sided lemma (strict, so
    # also enough for a weak claim); a weak claim may do without it
    if left_open:
        w = sign_near(expr, var, lo, +1, want)
        if w is not None:
            a = lo + sp.Rational(w)
    if right_open:
        w = sign_near(expr, var, hi, -1, want)
        if w is not None:
            b = hi - sp.Rational(w)
    if (a >= b) == True:  # noqa: E712
        return proved("one-sided lemmas cover the interval")
    fn = _compiled(expr, var, "range")
    queue = [(a, b)]
    evaluations = 0
    stuck = None        # a spot no box could decide: keep looking for a witness elsewhere
    mean_value = []     # `_mean_value_accepts`'s state
    while queue:
        u, v = queue.pop()
        evaluations += 1
        if evaluations > budget:
            return unknown(stuck or f"undecided near {var} = {float((u + v) / 2):.6g} after {budget} boxes")
        try:
            box = fn(Interval.of(u, v))
            if _accepts(box, want, strict) or (evaluations > 1 and _mean_value_accepts(fn, expr, var, u, v,
                                                                                      want, strict, mean_value)):
                continue
        except Undefined as exc:
            if float(v - u) < 1e-12:
                stuck = stuck or f"not defined near {var} = {float(u):.6g}: {exc}"
                continue
        if float(v - u) < 1e-15:
            stuck = stuck or f"cannot decide the sign near {var} = {float(u):.6g}"
            continue
        m = rational_between(u, v)
        if _witness_check(expr, var, m, want, strict):
            return refuted(f"fails at {var} = {m}", m)
        queue.append((m, v))
        queue.append((u, m))
    if stuck:
        return unknown(stuck)
    return proved("interval arithmetic on a finite cover")


def _monotone_tail(expr, var, R, want, strict, depth) -> bool:
    """want*expr > 0 (or >= 0) on [R, oo) by monotonicity, when interval
    arithmetic on the t-form cannot see it (limits attained only at t = 0):
    (a) want*expr(R) > 0 and want*expr' >= 0 on [R, oo); or
    (b) lim_{s->oo} want*expr >= 0 and want*expr' < 0 on [R, oo) (strictly
        monotone towards a non-negative limit stays above it)."""
    d = prepare(sp.diff(expr, var))
    try:
        at_r = value_at(expr, var, R)
        if (at_r.is_positive() if want > 0 else at_r.is_negative()) and prove_sign(
                d, var, R, sp.oo, want=want, lo_open=False, strict=False, budget=1500,
                _depth=depth + 1).proved:
            return True
    except Undefined:
        pass
    try:
        lim = limit_at_infinity(expr, var)
    except NoLimit:
        return False
    sgn = 1 if lim == sp.oo else (-1 if lim == -sp.oo else exact_sign(lim))
    if sgn is None or sgn * want < 0 or (sgn == 0 and False):
        return False
    return prove_sign(d, var, R, sp.oo, want=-want, lo_open=False, strict=True, budget=1500,
                      _depth=depth + 1).proved


def prove_sign(expr, var, lo, hi, want=1, lo_open=True, hi_open=True,
               zeros=(), budget=MAX_BOXES, strict=True, _depth=0) -> Verdict:
    """See `_prove_sign`; an end point or a zero that interval arithmetic
    cannot enclose (a SymPy RootOf, say) gives an 'unknown', never an error."""
    try:
        return _prove_sign(expr, var, lo, hi, want, lo_open, hi_open, zeros, budget, strict, _depth)
    except (Undefined, TypeError, ValueError) as exc:
        return unknown(f"cannot evaluate on ({lo}, {hi}): {exc}")


def polynomial_sign(expr, var, lo, hi, want, lo_open=True, hi_open=True, strict=True) -> bool:
    """want*expr > 0 (strict) or >= 0 on the interval from lo to hi, decided
    exactly for a polynomial with rational coefficients and rational ends:
    no factor of the square-free decomposition (for a weak claim: no factor
    of odd multiplicity) has a real root inside (Sturm's count), and the
    sign at one inner point is right.  False when not shown."""
    if not all(isinstance(c, sp.Rational) for c in (lo, hi) if c != sp.oo):
        return False
    poly = rational_poly(expr, var)
    if poly is None:
        return False
    coeff, factors = poly.sqf_list()
    sign = 1 if coeff > 0 else -1
    inner = rational_between(lo, hi) if hi != sp.oo else lo + 1
    for p, mult in factors:
        if p.degree() == 0:
            continue
        if not strict and mult % 2 == 0:
            continue            # p**mult >= 0 never changes the sign
        roots = p.count_roots(lo, None if hi == sp.oo else hi)
        roots -= int(lo_open and p.eval(lo) == 0)
        roots -= int(hi != sp.oo and hi_open and p.eval(hi) == 0)
        if roots:
            return False
        sign *= 1 if p.eval(inner) > 0 else -1
    return sign == want


def _prove_sign(expr, var, lo, hi, want=1, lo_open=True, hi_open=True,
                zeros=(), budget=MAX_BOXES, strict=True, _depth=0) -> Verdict:
    """Prove want*expr > 0 on the interval from lo to hi (hi may be oo),
    open or closed at each end, except at the exact points ``zeros`` where
    expr vanishes (they are excluded from the strict claim; the caller has
    checked expr = 0 there).  Returns a proved / refuted (witness: a point of
    the variable) / unknown verdict."""
    expr = prepare(sp.sympify(expr))
    if not (strict and zeros) and polynomial_sign(expr, var, lo, hi, want, lo_open, hi_open, strict):
        return proved("Sturm's theorem: no real root of the polynomial inside, right sign at one point")
    points = sorted(set(zeros), key=lambda z: float(z))
    if hi == sp.oo:
        R = tail_start(lo)
        while points and float(points[-1]) >= float(R) - 1:
            R = 2 * R
        finite_parts = [lo, *points, R]
    else:
        R = None
        finite_parts = [lo, *points, hi]
    for i in range(len(finite_parts) - 1):
        a, b = finite_parts[i], finite_parts[i + 1]
        left_open = (i > 0) or lo_open
        right_open = (i < len(finite_parts) - 2) or (R is None and hi_open)
        if R is not None and i == len(finite_parts) - 2:
            right_open = False
        if not left_open and _witness_check(expr, var, a, want, strict):
            return refuted(f"fails at {var} = {a}", a)
        if not right_open and R is None and _witness_check(expr, var, b, want, strict):
            return refuted(f"fails at {var} = {b}", b)
        v = _cover(expr, var, a, b, want, left_open, right_open, budget, strict)
        if strict and not v.proved and not v.refuted:
            root = _exact_zero_in(expr, var, a, b)
            if root is not None:
                return refuted(f"vanishes at {var} = {root} (exact)", root)
        if not v.proved:
            return v
    if R is not None:
        tail = tail_form(expr, var)
        v = _cover(tail, T, sp.Integer(0), 1 / R, want, True, False, budget, strict)
        if not v.proved and not v.refuted and _depth < 2 and _monotone_tail(expr, var, R, want, strict, _depth):
            v = proved("monotone on the unbounded part")
        if strict and not v.proved and not v.refuted:
            root = _exact_zero_in(expr, var, R, sp.oo)
            if root is not None:
                return refuted(f"vanishes at {var} = {root} (exact)", root)
        if v.refuted:
            return refuted(f"fails at {var} = {1 / v.witness}", 1 / v.witness)
        if not v.proved:
            return unknown(f"on [{R}, oo) via s = 1/t: {v.reason}")
    return proved("interval arithmetic on a finite cover, s = 1/t on the unbounded part, "
                  "Taylor's theorem at zeros")


# --------------------------------------------------------------------------
# supremum

@dataclass
class SupEnclosure:
    """sup of expr over the interval lies in [lower, upper] (upper None: no
    finite upper bound was found).  ``at_infinity`` tells whether the best
    box at the end was the one touching s = oo."""
    lower: Fraction | None
    upper: Fraction | None
    at_infinity: bool
    near: float | None
    point: sp.Rational | None = None    # an s > 0 where expr >= lower (the kernel's `sup_lower_by_point`)


def _lo(box: Interval) -> Fraction | None:
    """Lower end rounded down to a double (keeps the arithmetic cheap: exact
    endpoints of exp(-1/t^2) have million-bit denominators)."""
    x = box.lower_float()
    return Fraction(x) if math.isfinite(x) else None


def _hi(box: Interval) -> Fraction | None:
    x = box.upper_float()
    return Fraction(x) if math.isfinite(x) else None


def _rounded(x, down: bool) -> Fraction | None:
    """The exact arb x rounded to 53 bits toward -oo (down) or +oo, at any
    scale from 2^-4000 to 2^4000 (below, 0 or +-2^-4000; above, None): the
    bounds of `enclose_sup`, where a double had flushed a kf of 10^-400 to
    [0, 5e-324] and left one of 10^-320 to 3e-4 of its size."""
    if not x.is_finite():
        return None
    m, e = (int(v) for v in x.mid().man_exp())
    shift = max(m.bit_length() - 53, -4000 - e, 0)
    if shift:
        q = m >> shift                              # floor
        exact = m == 0 if shift >= m.bit_length() else q << shift == m   # (no 2^shift for a tiny x)
        m, e = (q if down or exact else q + 1), e + shift
    return None if e > 4000 else Fraction(m) * Fraction(2) ** e


def _lo53(box: Interval) -> Fraction | None:
    return None if box.lo is NINF else _rounded(box.lo, True)


def _hi53(box: Interval) -> Fraction | None:
    return None if box.hi is PINF else _rounded(box.hi, False)


def _mean_value_upper(fn, dfn, u, v):
    """Upper bound of E on [u, v] from the mean-value form
    E(x) = E(m) + E'(xi) (x - m), tighter than the natural enclosure near a
    smooth maximum (the overestimate is quadratic in the width)."""
    m = rational_between(u, v)
    em = fn(Interval.point(m))
    d = dfn(Interval.of(u, v))
    if not (em.is_finite() and d.is_finite()):
        return None
    mf = Fraction(int(m.p), int(m.q))
    ends = (_hi53(d), _lo53(d), _hi53(em), _hi53(Interval.point(v)), _lo53(Interval.point(u)))
    if any(x is None for x in ends):       # beyond 2^4000: no bound here
        return None
    d_hi, d_lo, em_hi, v_hi, u_lo = ends
    right = max(Fraction(0), d_hi) * (v_hi - mf)
    left = max(Fraction(0), -d_lo) * (mf - u_lo)
    return em_hi + max(right, left)


def _ordering(x: Fraction) -> float:
    """x as a double for ordering the boxes only (x scaled by `enclose_sup`):
    +-DBL_MAX beyond the doubles, so that a box without a bound (-inf in the
    heap) always comes first."""
    try:
        return max(min(float(x), sys.float_info.max), -sys.float_info.max)
    except OverflowError:
        return sys.float_info.max if x > 0 else -sys.float_info.max


def enclose_sup(expr, var, lo, hi, rel_tol=1e-8, budget=6000, floor=None) -> SupEnclosure:
    """Rigorous enclosure of sup expr over [lo, hi] (hi may be oo) by interval
    branch and bound: every box keeps an upper bound, every evaluated value a
    lower bound, until they agree to rel_tol.  `floor`: a value the caller
    knows the sup elsewhere reaches; once every box's bound is below it this
    interval cannot hold the sup and the search stops (the upper bound
    returned is then below floor, the lower bound whatever was seen)."""
    expr = prepare(sp.sympify(expr))
    parts = []   # (variable, expression, derivative) per region
    tail_bound = None       # a c >= expr on [R, oo) shown exactly: no tail form needed
    if hi == sp.oo:
        R = tail_start(lo)
        parts.append(("s", expr, lo, R))
        tail_bound = _bound_on_tail(expr, var, R, floor)
    if hi == sp.oo and tail_bound is None:
        tail = tail_form(expr, var)
        blind = tail_box(expr, var, R) is None
        # expr non-increasing on [R', oo): sup there is expr(R'), in the first part, now [lo, R']
        # (a peak beyond R, as of s exp(-s^4/10^4) at s = 7.07: a later R')
        later = R if blind and prove_sign(sp.diff(expr, var), var, R, sp.oo, want=-1, lo_open=False,
                                          strict=False, budget=1500).proved else None
        if blind and later is None:
            # the kernel's sign rules: a peak beyond R (s exp(-s^4/10^4) at s = 7.07), or an
            # exp(-s^2) factor that interval covers of the tail in t = 1/s cannot enclose at t = 0
            from .certify import exploring, sign_theorems
            with exploring():
                later = next((r for r in (R, 4 * R, 16 * R, 64 * R) if _seen_falling(expr, var, r) and sign_theorems(
                    -sp.diff(expr, var), var, r, sp.oo, lo_open=False, strict=False, work=TAIL_WORK // 2)[0]
                    is not None), None)
        if blind and later is None and len(split_terms(expr)) > 1:
            later, tail_bound = _termwise_tail(expr, var, lo, R)
        if later is not None:
            parts[0] = ("s", expr, lo, later)
        else:
            parts.append(("t", tail, sp.Integer(0), 1 / R))
    if hi != sp.oo:
        parts.append(("s", expr, lo, hi))
    fns = {}
    # the mean-value bound needs E' to enclose every slope: no jumps inside
    smooth = {kind: not e.has(sp.Piecewise, sp.sign, sp.Heaviside, sp.floor, sp.ceiling, sp.frac)
              for kind, e, _, _ in parts}
    for kind, e, _, _ in parts:
        v = var if kind == "s" else T
        fns[kind] = (_compiled(e, v, "range"), _compiled(prepare(sp.diff(e, v)), v, "range"))
    lower = point = None
    heap = []
    counter = 0
    size = _size(expr, var, lo, hi)
    # the heap orders boxes by doubles: scaled near 1 (a kf of 10^-320 is subnormal)
    unit = Fraction(2) ** (size.denominator.bit_length() - size.numerator.bit_length())

    def raise_lower(box, kind, u, v):   # expr >= _lo53(box) on [u, v]
        nonlocal lower, point
        lf = _lo53(box)
        if lf is not None and (lower is None or lf > lower):
            at = u if u == v else rational_between(u, v)
            lower, point = lf, (at if kind == "s" else 1 / at)

    def push(kind, u, v):
        nonlocal counter
        fn, dfn = fns[kind]
        up = None
        try:
            box = fn(Interval.of(u, v))
            raise_lower(box, kind, u, v)
            up = _hi53(box)
        except Undefined:
            pass
        if not (kind == "t" and u == 0) and smooth[kind]:
            try:
                mv = _mean_value_upper(fn, dfn, u, v)
                if mv is not None and (up is None or mv < up):
                    up = mv
            except Undefined:
                pass
        counter += 1
        heapq.heappush(heap, (float("-inf") if up is None else -_ordering(up * unit), counter, kind, u, v, up))

    for kind, _, a, b in parts:
        push(kind, a, b)
    for count in range(budget):
        key, _, kind, u, v, up = heap[0]
        if floor is not None and up is not None and -key < _ordering(floor * unit):
            top = max(h[-1] for h in heap)      # the exact largest bound (the heap orders by float)
            if top < floor and (tail_bound is None or tail_bound < floor):
                top = top if tail_bound is None else max(top, tail_bound)
                return SupEnclosure(lower, top, at_infinity=False, near=None, point=point)
        # relative to a positive lower bound, however small (kf = 1e-18 had been enclosed in [0.97e-18,
        # 4e-18]); where the sup may be 0 or below, to 10^-9 of expr's size
        if up is not None and lower is not None and \
                (up if tail_bound is None else max(up, tail_bound)) - lower <= \
                Fraction(rel_tol) * (lower if lower > 0 else max(-lower, size / 10 ** 9)):
            near = float((u + v) / 2) if kind == "s" else None
            # the heap orders by float(up): take the exact largest bound
            upper = max([h[-1] for h in heap] + ([] if tail_bound is None else [tail_bound]))
            return SupEnclosure(lower, upper, at_infinity=(kind == "t" and u == 0), near=near, point=point)
        heapq.heappop(heap)
        m = rational_between(u, v)
        try:
            raise_lower(fns[kind][0](Interval.point(m)), kind, m, m)
        except Undefined:
            pass
        push(kind, u, m)
        push(kind, m, v)
    ups = [h[-1] for h in heap] + ([tail_bound] if tail_bound is not None else [])
    upper = None if (not ups or any(u is None for u in ups)) else max(ups)
    return SupEnclosure(lower, upper, at_infinity=False, near=None, point=point)


def _size(expr, var, lo, hi) -> Fraction:
    """The largest |expr| at lo + 2^k (k = -3 ... 6) inside (lo, hi), or 1
    when none is a nonzero number: the scale of `enclose_sup`'s tolerance
    where the sup may be 0 (an absolute 10^-16 had left the sup of an F' of
    size 10^-20 in [-10^-11, 9e-20])."""
    top = Fraction(0)
    for k in range(-3, 7):
        x = lo + sp.Rational(2) ** k
        if hi == sp.oo or x < hi:
            try:
                box = value_at(expr, var, x, prec=64)
            except (Undefined, ValueError, ZeroDivisionError):
                continue
            top = max([top] + [abs(b) for b in (_lo53(box), _hi53(box)) if b is not None])
    return top or Fraction(1)


def _termwise_tail(expr, var, lo, R):
    """(R', c) with expr <= c on [R', oo), R' one of R, 4R, 16R, 64R, c the
    sum of its terms' bounds there (`term_bound_on_tail`: 2 s sech(s^2)^2
    beside 2 s/(s^2 + 1) in F' of tanh(s^2) + log(1 + s^2), whose tail form
    no interval cover encloses at t = 0), taken only when c is below a value
    expr reaches on [lo, R'] (then the sup is not in the tail); (None, None)
    if there is none."""
    known = {}      # term -> its bound on the tail of an earlier r
    for r in (R, 4 * R, 16 * R, 64 * R):
        steps = [sp.Rational(k, 16) for k in range(1, 16)] + [sp.Rational(1, 2 ** k) for k in range(5, 12)]
        try:        # (evenly, and closer and closer to lo, where a peak of F' often is)
            reached = max(v for v in (_lo(value_at(expr, var, lo + (r - lo) * x, prec=64)) for x in steps)
                          if v is not None)
        except (Undefined, ValueError):
            return None, None
        total = Fraction(0)     # (a product with a factor rational in a log: whole, its sum bounded, not its terms)
        for term in (expr,) if expr.is_Mul and log_factors(expr, var, r) else split_terms(expr):
            bound = term_bound_on_tail(term, var, r) or known.get(term)     # (a bound on [R, oo) holds beyond R too)
            if bound is None:
                break
            known[term] = bound
            total += bound[0]
        else:
            if total < reached:
                return r, total
    return None, None


def tail_box(expr, var, R) -> Interval | None:
    """An interval cover of expr on [R, oo), through its tail form in t =
    1/s on [0, 1/R] (`tail_form` is memoised); None where that is not
    bounded (2/(t cosh(t^-2)^2): 0 times oo at t = 0, or an end of oo)."""
    try:
        box = _compiled(tail_form(expr, var), T, "range")(Interval.of(0, 1 / R))
    except Undefined:
        return None
    return box if _hi(box) is not None and _lo(box) is not None else None     # (to doubles: exp(-10^30/t^2))


def split_terms(e) -> tuple:
    """The terms of e, a product's one sum multiplied out (2 s (sech(s^2)^2
    + 1/(s^2 + 1)), as `prepare` writes F')."""
    sums = [a for a in sp.Mul.make_args(e) if a.is_Add]
    if e.is_Mul and len(sums) == 1:
        return tuple(e / sums[0] * a for a in sums[0].args)
    return sp.Add.make_args(e)


def bounded_factors(term, var, R):
    """(A, B, b) with term = A B on [R, oo), B the product of term's factors
    whose tail forms have interval covers there with lower ends > 0 (atan(s^2)
    in 2 s sech(s^2)^2 atan(s^2): bounded, and not what makes the product
    fall), 0 <= B <= b, b the power of 2 at or above B's bound (room for the
    kernel: 1 - tanh(tanh(s^2)) > 0 is one rule, 0.76160 - tanh(tanh(s^2))
    no proof at all), and A the others, among them a factor in s; None where
    there is no such split."""
    if not term.is_Mul:
        return None
    inside, rest = [], []
    for f in term.args:
        box = tail_box(f, var, R) if f.has(var) else None
        (inside if box is not None and _lo(box) > 0 else rest).append(f)
    if not inside or not any(f.has(var) for f in rest):
        return log_factors(term, var, R)
    B = sp.Mul(*inside)
    box = tail_box(B, var, R)
    if box is None or _lo(box) < 0 or _hi(box) <= 0:
        return None
    return sp.Mul(*rest), B, sp.Integer(2) ** math.ceil(math.log2(_hi(box)))


def log_groups(parts, var) -> dict:
    """{L: the parts that are rational functions of that one L} (`log_of`);
    a part rational in no single log is in no group."""
    out = {}
    for p in parts:
        g = log_of(p, var)
        if g is not None:
            out.setdefault(g, []).append(p)
    return out


def log_factors(term, var, R):
    """`bounded_factors`' (A, B, b) with B the factors of term that are a
    rational function G of one L = log(...) (or asinh): L/(1 + L) in
    4 s L/((1 + s^2)(1 + L)), whose tail form is oo/oo at t = 0.  0 <= G(U)
    <= b for U >= a, a rational at or below L(R) (the kernel's Sturm rule,
    as the proof will; L taken increasing: the proof shows L >= a)."""
    for g, group in log_groups(term.args, var).items():
        rest = [f for f in term.args if f not in group]
        G = sp.Mul(*group).xreplace({g: U})
        if not any(f.has(var) for f in rest) or not K._rational_over_q(G, U):
            continue
        try:
            a = K._rational_beyond(g.subs(var, R), -1)
            top = max(value_at(G, U, a + x, prec=64).upper_fraction() for x in (0, 1, 16, 10 ** 6))
        except (K.KernelError, Undefined, ValueError, TypeError):
            continue
        b = sp.Integer(2) ** max(0, math.ceil(math.log2(top))) if top > 0 else sp.Integer(1)
        if _sturm_nonnegative(G, U, a) and _sturm_nonnegative(b - G, U, a):
            return sp.Mul(*rest), sp.Mul(*group), b
    return None


def term_bound_on_tail(term, var, R) -> tuple[Fraction, str] | None:
    """(c, how) with c >= term on [R, oo), `how` saying by what: "box", the
    upper end of an interval cover of its tail form in t = 1/s; "product",
    A's bound times b where term = A B with 0 <= B <= b (`bounded_factors`)
    and the sign rules show A >= 0; "falls", its value at R where the
    kernel's sign rules show it non-increasing (2 s sech(s^2)^2); "below",
    0 where they show it <= 0.  None if neither."""
    from .certify import exploring, sign_theorems
    box = tail_box(term, var, R)
    if box is not None:
        return _hi(box), "box"
    split = bounded_factors(term, var, R)
    if split is not None:
        A, _, b = split
        a = term_bound_on_tail(A, var, R)
        if a is not None and a[0] >= 0 and _sturm_nonnegative(A, var, R):      # (rational: no pool spent)
            return a[0] * Fraction(b.p, b.q), "product"
        with exploring():
            if a is not None and a[0] >= 0 and \
                    sign_theorems(A, var, R, sp.oo, lo_open=False, strict=False, work=TAIL_WORK)[0] is not None:
                return a[0] * Fraction(b.p, b.q), "product"
    try:
        at_r = value_at(term, var, R, prec=64)
    except Undefined:
        return None
    with exploring():       # (only what its values allow is tried: a hopeless lemma spends the pool all the same)
        if _seen_falling(term, var, R) and sign_theorems(
                -sp.diff(term, var), var, R, sp.oo, lo_open=False, strict=False, work=TAIL_WORK)[0] is not None \
                and _hi(at_r) is not None:
            return _hi(at_r), "falls"
        if at_r.lower_float() <= 0 and sign_theorems(-term, var, R, sp.oo, lo_open=False, strict=False,
                                                     work=TAIL_WORK)[0] is not None:
            return Fraction(0), "below"
    return None


def _sturm_nonnegative(e, var, R) -> bool:
    """e >= 0 on [R, oo) by the kernel's Sturm rule (e rational over Q)."""
    if not K._rational_over_q(e, var):
        return False
    try:
        K.sign_by_sturm(expr=e, var=var, lo=R, hi=sp.oo, lo_open=False, hi_open=True, want=1, strict=False)
        return True
    except K.KernelError:
        return False


def _seen_falling(e, var, R) -> bool:
    """e(2R) is not seen above e(R) (Arb at both points): a proof that e
    falls on [R, oo) is worth trying."""
    try:
        return value_at(e, var, 2 * R, prec=64).lower_float() <= value_at(e, var, R, prec=64).upper_float()
    except Undefined:
        return False


TAIL_DEGREE = 400      # `_bound_on_tail` leaves larger rational functions to the tail form (root isolation slows)


#: the work (`certify` units) of each sign lemma `enclose_sup` asks the kernel's
#: rules for on a tail it cannot enclose, from a pool of their own
#: (`certify.exploring`), so that a design's budget is left to its properties'
#: own lemmas: a third of a lemma's for one term of a sum (s exp(-s^4/10^4)
#: log(1 + s^2/4) falling beyond 16: 16k units), half that for the whole sum,
#: which is tried first at four starts
TAIL_WORK = 20_000


def _bound_on_tail(expr, var, R, floor) -> Fraction | None:
    """A c with expr <= c on [R, oo), by the kernel's exact rule for a
    rational function over Q (`sign_by_sturm` on c - expr): c just below
    `floor`, a value the sup reaches elsewhere, else just above expr(R)
    (where expr falls beyond R); None when neither is shown (then the tail
    form)."""
    if not K._rational_over_q(expr, var):
        return None
    try:
        if max(q.degree() for q in K._fraction_over_q(expr, var)) > TAIL_DEGREE:
            return None
        at_R = value_at(expr, var, R, prec=128).upper_fraction()
    except (K.KernelError, Undefined):
        return None
    below = None if floor is None else floor - max(abs(floor), Fraction(1, 10 ** 30)) / 10 ** 9
    for c, side, digits in ((below, -1, 10), (at_R, 1, 14)):    # short decimals: long ones slow the polynomials
        if c is None:
            continue
        c = decimal_beyond(c, side, digits)
        if _sturm_nonnegative(c - expr, var, R):
            return Fraction(c.p, c.q)
    return None
