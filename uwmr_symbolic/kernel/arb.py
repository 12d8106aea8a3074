"""The kernel's own interval evaluator: SymPy expressions on python-flint Arb.

An interval is a pair of Arb balls ``Iv(lo, hi)`` meaning: every value x of
the set satisfies  lower(lo) <= x <= upper(hi)  (lower/upper: the ends of a
ball).  Arb rounds outward, so each operation below keeps this invariant:

* x + y: [lo1 + lo2, hi1 + hi2];  -x: [-hi, -lo];
* x * y: min and max of the four corner products (Arb's min/max of balls),
  or [lo1 lo2, hi1 hi2] when lower(lo1), lower(lo2) >= 0;
* 1/x only if 0 < lower(x) or upper(x) < 0 is *certified*;
* an increasing function g: [g(lo), g(hi)] (g(ball) contains g of every point
  of the ball, in particular of its lower end); decreasing: swapped;
* anything else (sin, cos): g of the hull ball, which contains g of every
  point in between.

"Range" semantics: ``evaluate(e, x, lo, hi)`` encloses {e(x) : lo <= x <= hi}
and raises `Undefined` unless e is defined (real, finite) at *every* point of
[lo, hi]: log needs lower(arg) > 0, x**r (r not an integer) needs lower >= 0
(> 0 for r < 0), 1/x needs 0 excluded.  Nothing is clipped: sqrt of an
interval straddling 0 is undefined, not sqrt of its non-negative part.
Every supported function is continuous on the interior of its domain, so a
successful evaluation also shows that e is continuous on [lo, hi].

No extended arithmetic at infinity or at t = 0 of s = 1/t: the tail of
[R, oo) is handled by the `sign_on_tail` rule from theorems about a
rewritten t-form (see docs/kernel.md).
"""
from __future__ import annotations

import functools

import flint
import sympy as sp
from flint import arb, fmpq


class Undefined(ArithmeticError):
    """The expression is (or may be) undefined somewhere on the box, or uses
    something this evaluator does not support."""


precision = flint.ctx.workprec       # `with precision(bits):` Arb's working precision, restored after


class Iv:
    """lower(lo) <= x <= upper(hi) for every value x of the set."""
    __slots__ = ("lo", "hi")

    def __init__(self, lo: arb, hi: arb):
        if not (lo.is_finite() and hi.is_finite()):
            raise Undefined("not finite")
        self.lo, self.hi = lo, hi

    # certified comparisons with 0 ----------------------------------------
    def positive(self) -> bool:
        return bool(self.lo > 0)

    def negative(self) -> bool:
        return bool(self.hi < 0)

    def nonnegative(self) -> bool:
        return bool(self.lo >= 0)

    def nonpositive(self) -> bool:
        return bool(self.hi <= 0)

    def hull(self) -> arb:
        return arb.union(self.lo, self.hi)

    def __repr__(self):
        return f"Iv({self.lo}, {self.hi})"


def _point(b: arb) -> Iv:
    return Iv(b, b)


def _add(x: Iv, y: Iv) -> Iv:
    return Iv(x.lo + y.lo, x.hi + y.hi)


def _mul(x: Iv, y: Iv) -> Iv:
    if x.lo >= 0 and y.lo >= 0:     # both sets >= 0: the products of the lower ends and of the upper ends
        return Iv(x.lo * y.lo, x.hi * y.hi)
    p = [x.lo * y.lo, x.lo * y.hi, x.hi * y.lo, x.hi * y.hi]
    return Iv(functools.reduce(arb.min, p), functools.reduce(arb.max, p))


def _inv(x: Iv) -> Iv:
    if not (x.positive() or x.negative()):
        raise Undefined("division by an interval that may contain 0")
    return Iv(1 / x.hi, 1 / x.lo)


def _increasing(g, x: Iv) -> Iv:
    return Iv(g(x.lo), g(x.hi))


def _abs_like(x: Iv, g) -> Iv:
    """g even with g increasing on [0, oo): |x|, x**(2k), cosh."""
    if x.nonnegative():
        return Iv(g(x.lo), g(x.hi))
    if x.nonpositive():
        return Iv(g(-x.hi), g(-x.lo))
    return Iv(g(arb(0)), g(-x.lo).max(g(x.hi)))


def _ipow(b: arb, n: int) -> arb:
    """b**n for n >= 1 by products (Arb's b**n is NaN when the ball b holds 0)."""
    out = None
    while n:
        if n & 1:
            out = b if out is None else out * b
        n >>= 1
        if n:
            b = b * b
    return out


def _pow(x: Iv, e: sp.Rational) -> Iv:
    if e < 0:                       # 1/x**(-e); x > 0 asked first for a root (1/x asks x != 0 of a power)
        if not (e.is_Integer or x.positive()):
            raise Undefined(f"x**({e}) needs x > 0")
        return _inv(_pow(x, -e))
    if e.is_Integer:
        n = int(e)
        if n == 0:
            return _point(arb(1))
        if n % 2 == 0:
            return _abs_like(x, lambda b: _ipow(b, n))
        return _increasing(lambda b: _ipow(b, n), x)
    r = arb(fmpq(int(e.p), int(e.q)))
    if not x.nonnegative():
        raise Undefined(f"x**({e}) needs x >= 0")

    def g(b: arb) -> arb:           # b**r for a ball b >= 0, increasing
        if b.is_zero():
            return arb(0)
        if b > 0:
            return (r * b.log()).exp()
        u = b.upper()               # the set is >= 0: [0, upper(b)**r] holds b**r
        if not u > 0:
            raise Undefined("power of a ball that cannot be bounded")
        return arb.union(arb(0), (r * u.log()).exp())
    return _increasing(g, x)


def _log(x: Iv) -> Iv:
    if not x.positive():
        raise Undefined("log of an interval that may contain values <= 0")
    return _increasing(arb.log, x)


_INCREASING = {sp.exp: arb.exp, sp.tanh: arb.tanh, sp.atan: arb.atan,
               sp.asinh: arb.asinh, sp.sinh: arb.sinh, sp.erf: arb.erf}
_BOUNDED = {sp.sin: arb.sin, sp.cos: arb.cos}


_NAMED = {sp.pi: arb.pi, sp.E: arb.const_e, sp.EulerGamma: arb.const_euler, sp.Catalan: arb.const_catalan,
          sp.GoldenRatio: lambda: (1 + arb(5).sqrt()) / 2}


def _constant(e: sp.Expr) -> arb:
    if e.is_Rational:
        return arb(fmpq(int(e.p), int(e.q)))
    if e in _NAMED:
        return _NAMED[e]()
    raise Undefined(f"unsupported constant {e}")


#: Expression nodes evaluated so far in this process: a measure of work that
#: does not depend on the machine (the proposer's budget, `certify.Budget`).
nodes = 0


def _eval(e: sp.Expr, env: dict) -> Iv:
    """The enclosure of e, each distinct subexpression evaluated once per
    `evaluate` (env holds the variable's interval and the enclosures so far:
    a subexpression has one range over the box wherever it occurs)."""
    global nodes
    if e not in env:
        nodes += 1
        env[e] = _node(e, env)
    return env[e]


def _node(e: sp.Expr, env: dict) -> Iv:
    if e.is_Symbol:
        raise Undefined(f"free symbol {e}")
    if e.is_Number or e.is_NumberSymbol:
        if isinstance(e, sp.Float) or not e.is_real or not e.is_finite:
            raise Undefined(f"not an exact real constant: {e}")
        return _point(_constant(e))
    if e.is_Add or e.is_Mul:
        return functools.reduce(_add if e.is_Add else _mul, [_eval(a, env) for a in e.args])
    if e.is_Pow:
        if not e.exp.is_Rational:
            if e.base is sp.E:
                return _increasing(arb.exp, _eval(e.exp, env))
            raise Undefined(f"only rational exponents: {e}")
        return _pow(_eval(e.base, env), e.exp)
    f = type(e)
    if len(e.args) != 1:
        raise Undefined(f"unsupported: {f.__name__}")
    if f is sp.log:
        return _log(_eval(e.args[0], env))
    if f in _INCREASING:
        return _increasing(_INCREASING[f], _eval(e.args[0], env))
    if f in _BOUNDED:
        b = _BOUNDED[f](_eval(e.args[0], env).hull())
        return Iv(b, b)
    if f is sp.cosh:
        return _abs_like(_eval(e.args[0], env), arb.cosh)
    if f is sp.Abs:
        return _abs_like(_eval(e.args[0], env), lambda b: b)
    if f is sp.sign and (_eval(e.args[0], env).positive() or _eval(e.args[0], env).negative()):
        return _point(arb(1 if env[e.args[0]].positive() else -1))      # (constant, so continuous, on the box)
    raise Undefined(f"unsupported function {f.__name__}")


def centered(e: sp.Expr, d: sp.Expr, var: sp.Symbol, lo, hi, bits: int = 128) -> Iv:
    """The mean value form on [lo, hi], m its midpoint: e(m) + d([lo, hi])
    ([lo, hi] - m), an enclosure of {e(x)} when d = e' on the box (the caller's
    premise).  Tighter than `evaluate` on a narrow box: the overestimate is
    of the order of the width squared."""
    m = (sp.sympify(lo) + sp.sympify(hi)) / 2
    with precision(bits):
        return _add(evaluate(e, var, m, m, bits), _mul(evaluate(d, var, lo, hi, bits),
                                                      evaluate(var - m, var, lo, hi, bits)))


def evaluate(e: sp.Expr, var: sp.Symbol | None = None, lo=None, hi=None, bits: int = 128) -> Iv:
    """Enclosure of {e(x) : lo <= x <= hi} (lo, hi exact SymPy numbers with
    lo <= hi), or of the constant e when var is None.  Raises `Undefined`."""
    with precision(bits):
        env = {}
        if var is not None:
            a, b = evaluate(sp.sympify(lo), bits=bits), evaluate(sp.sympify(hi), bits=bits)
            env[var] = Iv(a.lo, b.hi)
        return _eval(sp.sympify(e), env)


# SymPy decides the sign of a number from a 2-digit evalf, and with it Abs, sign, sqrt(u^2), Max, Min and
# relations: log(1 + 10^-40) minus its Taylor polynomial of degree 4, about 10^-201, came out negative (red
# teams 23, 24).  Both of its places that do so ask `_sign` first; SymPy's own answer only where it is None.
_SYMPY_SIGN, _SYMPY_N2 = sp.Expr._eval_is_extended_positive_negative, sp.core.relational._n2
SIGN_BITS = (256, 2048, 32768)      # a number's sign is tried at these precisions (here and `core._const_sign`)
_asking = []


def _sign(c) -> int | None:
    """The number c's sign at 256, 2,048, then 32,768 bits, 0 where no ball
    excludes 0 (SymPy is then told nothing), None for what this evaluator
    does not take (complex numbers, gamma, ...) or while it evaluates."""
    if _asking or not getattr(c, "is_number", False):
        return None
    _asking.append(c)
    try:
        signs = (1 if v.positive() else -1 if v.negative() else 0 for v in (evaluate(c, bits=b) for b in SIGN_BITS))
        return next((s for s in signs if s), 0)
    except (Undefined, TypeError, ValueError, AttributeError):
        return None
    finally:
        _asking.pop()


def _sign_by_arb(self, positive):
    s = _sign(self)
    return _SYMPY_SIGN(self, positive) if s is None else s == (1 if positive else -1) if s else None


def _difference_by_arb(a, b):
    s = _sign(a - b) if a.is_comparable and b.is_comparable else None
    return _SYMPY_N2(a, b) if s is None else sp.Integer(s) if s else None


sp.Expr._eval_is_extended_positive_negative, sp.core.relational._n2 = _sign_by_arb, _difference_by_arb
