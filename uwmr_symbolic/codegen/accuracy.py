"""Certified accuracy of the generated law (9): a rigorous floating-point
error analysis of the operations the back-ends print, region by region.

Model (the one of FPTaylor and Daisy, first-order-free): every IEEE
operation returns op(x) (1 + d) with |d| <= u (u = 2^-53 double, 2^-24
float) while its exact result is a normal number; sqrt is correctly
rounded; a math-library function phi returns phi(x) (1 + d) with
|d| <= LIBM_U[phi] u, an *assumption* about the library (stated in every
header).  A value x^ carries a relative error bound E: |x^ - x| <= E |x|.
The rules below propagate E through a SymPy expression exactly as the
printers print it (`printers`: a power is a product of copies of its base,
one square root, or one `pow`; a constant is one rounded literal; a
product of n factors is n - 1 roundings in any order; a sum of n terms
is within gamma_{n-1} sum |terms| of the exact sum of its rounded terms,
in any order), with every value enclosed by Arb intervals (the kernel's
`arb` evaluator) over a box of the region variable:

* sum:      E = (sum |x_i| E_i + gamma_{n-1} sum |x_i| (1 + E_i)) / min |sum|;
* product:  E = prod (1 + E_i) (1 + u)^(n-1) - 1;
* x**p:     E = ((1 - E_x)^-|p| (1 + u)^ops - 1), ops the printed operations;
* phi(x):   (1 + sup |phi'| sup |x| E_x / min |phi(x)|)(1 + LIBM_U u) - 1,
            phi' enclosed over x (1 +- E_x) (mean value theorem).

Every intermediate value of a product, power or function must stay in
the normal range over the box (else the box is not certified); sums are
exact below the normal range, so only their overflow is excluded.

`certify(model, precision)` covers each region of `law.LawModel` with
boxes in geometric steps (split in two while a box's bound is above the
goal), including the rounding of the region variable itself (rho = e1^2 +
e2^2, t = 1/s, s, log t), the Piecewise branch chosen from a rounded rho
or t (the two branches' difference over the sliver where the choice may
be wrong), the tiny region's truncated series (Lagrange remainder bounded
in Arb) and the guarded product lam vr sinc(e3) g.  The result states a
relative bound on g and on the term lam vr g sinc(e3) per region, and the
bounds on v and w (the template's fixed operations) relative to the
right-hand sides of bound (10).  A region, or part of one, that cannot be
certified is named, never silently promised."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from decimal import ROUND_CEILING, ROUND_FLOOR, Decimal

import flint
import sympy as sp
from flint import arb, fmpq
from sympy.codegen.cfunctions import expm1, log1p

from ..kernel.arb import (Iv, Undefined, _abs_like, _add, _increasing, _inv, _log, _mul, _point, _pow,
                          precision as arb_precision)
from ..univariate import T
from .law import LT, RHO, ST, LawModel, _taylor, plain, series_terms

__all__ = ["Accuracy", "RegionAccuracy", "certify", "LIBM_U", "UNIT"]

UNIT = {"double": 2.0 ** -53, "float": 2.0 ** -24}
MIN_NORMAL = {"double": 2.0 ** -1022, "float": 2.0 ** -126}
MAX_FINITE = {"double": 1.7976931348623157e308, "float": 3.4028234663852886e38}
SUBNORMAL = {"double": 2.0 ** -1074, "float": 2.0 ** -149}
#: A literal is printed from a 40-digit value rounded to double, and the
#: float literal from that double: beyond u, the first rounding adds this.
LITERAL_EXTRA = {"double": arb(2.0 ** -120), "float": arb(2.0 ** -52)}
#: Goal for g's relative error per precision (float: w then within 1e-5): a box above it is split.
GOAL = {"double": 1e-9, "float": 4e-6}

#: Assumed accuracy of the math library, in units of u (one ulp is at most
#: 2u relative): 4 ulps for the elementary functions (glibc's documented
#: maxima are 1-2 ulps on x86-64, NumPy's SIMD loops claim at most 4),
#: 10 ulps for erfc and gamma.  tanh also covers the fast path's tanh_fast,
#: -t/(t + 2) with t = expm1(-2|x|) (at most 2 x 8u + 2u).
LIBM_U = {"exp": 8, "log": 8, "log1p": 8, "expm1": 8, "sin": 8, "cos": 8, "atan": 8, "asinh": 8,
          "acosh": 8, "atanh": 8, "sinh": 8, "cosh": 8, "erf": 8, "erfc": 20, "gamma": 20,
          "pow": 8, "tanh": 20}

_FUNCS = {sp.exp: ("exp", arb.exp, 1), sp.log: ("log", None, 1), log1p: ("log1p", arb.log1p, 1),
          expm1: ("expm1", arb.expm1, 1), sp.tanh: ("tanh", arb.tanh, 1), sp.atan: ("atan", arb.atan, 1),
          sp.asinh: ("asinh", arb.asinh, 1), sp.sinh: ("sinh", arb.sinh, 1), sp.erf: ("erf", arb.erf, 1),
          sp.erfc: ("erfc", arb.erfc, -1), sp.cosh: ("cosh", None, 0), sp.sin: ("sin", None, 0),
          sp.cos: ("cos", None, 0), sp.acosh: ("acosh", arb.acosh, 1), sp.atanh: ("atanh", arb.atanh, 1)}
_Z = sp.Dummy("z")
#: phi' written so that Arb encloses it tightly far out (1/cosh^2, not 1 - tanh^2)
_DERIVATIVE = {sp.exp: sp.exp(_Z), sp.log: 1 / _Z, log1p: 1 / (1 + _Z), expm1: sp.exp(_Z),
               sp.tanh: sp.sech(_Z) ** 2, sp.atan: 1 / (1 + _Z ** 2), sp.asinh: (1 + _Z ** 2) ** sp.Rational(-1, 2),
               sp.sinh: sp.cosh(_Z), sp.cosh: sp.sinh(_Z), sp.erf: 2 / sp.sqrt(sp.pi) * sp.exp(-_Z ** 2),
               sp.erfc: -2 / sp.sqrt(sp.pi) * sp.exp(-_Z ** 2), sp.sin: sp.cos(_Z), sp.cos: -sp.sin(_Z),
               sp.acosh: (_Z ** 2 - 1) ** sp.Rational(-1, 2), sp.atanh: 1 / (1 - _Z ** 2)}
#: z phi'(z)/phi(z) with z in one place where the quotient would take it from
#: two (cosh: z sinh(z)/cosh(z) over [16, 25] is 2e5 enclosed that way, 25 as z tanh z)
_LOG_DERIVATIVE = {sp.exp: _Z, sp.cosh: _Z * sp.tanh(_Z), sp.sinh: _Z / sp.tanh(_Z)}


class Uncertified(ArithmeticError):
    """No bound on this box (a value may leave the normal range, a sum may
    vanish, an unsupported operation)."""


class MayVanish(Uncertified):
    """No relative bound: the enclosure of the value contains 0 (often only
    the box's width: a smaller box may exclude it)."""


def _up(x: arb) -> float:
    """A float >= every point of the ball x."""
    v = x.upper()
    f = float(v)
    return math.nextafter(f, math.inf) if f < math.inf else f


def _mag(x: Iv) -> tuple[arb, arb]:
    """(min |x|, max |x|) over the interval."""
    if x.positive():
        return x.lo.lower(), x.hi.upper()
    if x.negative():
        return (-x.hi).lower(), (-x.lo).upper()
    return arb(0), (-x.lo).upper().max(x.hi.upper())


def _is_zero(x: Iv) -> bool:
    return x.lo.is_zero() and x.hi.is_zero()


def _representable(c: sp.Expr, precision: str) -> bool:
    if not c.is_Rational:
        return False
    q = sp.Rational(c)
    if precision == "float":
        import numpy as np
        with np.errstate(over="ignore"):        # beyond the float range: inf, refused below
            v = np.float32(float(q))
        return bool(np.isfinite(v)) and sp.Rational(float(v)) == q
    return math.isfinite(float(q)) and sp.Rational(float(q)) == q


def _ipow(b: arb, n: int) -> arb:
    out = b
    for _ in range(n - 1):
        out = out * b
    return out


def _int_pow(x: Iv, n: int) -> Iv:
    """x**n by products (Arb's b**n is NaN for a ball around 0)."""
    if n % 2 == 0:
        return _abs_like(x, lambda b: _ipow(b, n))
    return _increasing(lambda b: _ipow(b, n), x)


class Analysis:
    """Error propagation over one box.  env maps each input symbol to
    (Iv of its exact values, relative error bound, absolute error bound);
    every node gets (E, A): |x^ - x| <= E |x| + A.  A value that may fall
    below the normal range gets the absolute error of one rounding there
    (half the smallest subnormal per IEEE operation, LIBM_U of it per
    library call) instead of a relative one."""

    def __init__(self, precision: str, env: dict):
        self.p = precision
        self.u = arb(fmpq(1, 2 ** (53 if precision == "double" else 24)))
        self.min = arb(MIN_NORMAL[precision])
        self.max = arb(MAX_FINITE[precision])
        self.sub = arb(SUBNORMAL[precision])
        self.env = env
        self.values = {}

    # exact values ------------------------------------------------------
    def value(self, e: sp.Expr) -> Iv:
        if e in self.values:
            return self.values[e]
        if e in self.env:
            v = self.env[e][0]
        elif e.is_number:
            v = _point(arb(fmpq(int(e.p), int(e.q))) if e.is_Rational else self._constant(e))
        elif e.is_Add:
            v = self.value(e.args[0])
            for a in e.args[1:]:
                v = _add(v, self.value(a))
        elif e.is_Mul:
            v = self.value(e.args[0])
            for a in e.args[1:]:
                v = _mul(v, self.value(a))
        elif e.is_Pow:
            if not e.exp.is_Rational:
                raise Uncertified(f"power with a non-rational exponent: {e}")
            base = self.value(e.base)
            if e.exp.is_Integer:
                n = int(e.exp)
                v = _point(arb(1)) if n == 0 else (_int_pow(base, n) if n > 0 else _inv(_int_pow(base, -n)))
            else:
                v = _pow(base, e.exp)
        else:
            v = self._function_value(type(e), self.value(e.args[0])) if len(e.args) == 1 else None
            if v is None:
                raise Uncertified(f"unsupported operation {type(e).__name__}")
        self.values[e] = v
        return v

    @staticmethod
    def _constant(e):
        from ..kernel.arb import evaluate
        try:
            return evaluate(e, bits=int(flint.ctx.prec)).hull()
        except Undefined as exc:
            raise Uncertified(f"constant {e}: {exc}") from None

    @staticmethod
    def _function_value(f, x: Iv) -> Iv | None:
        if f is sp.log:
            return _log(x)
        if f is sp.Abs:
            return _abs_like(x, lambda b: b)
        if f is sp.cosh:
            return _abs_like(x, arb.cosh)
        if f is sp.sech:                  # even, decreasing on [0, oo), at most 1
            c = _abs_like(x, lambda b: b)
            return Iv(c.hi.sech(), c.lo.sech())
        if f in (sp.sin, sp.cos):
            b = (arb.sin if f is sp.sin else arb.cos)(x.hull())
            return Iv(b, b)
        if f in _FUNCS:
            _, g, direction = _FUNCS[f]
            if f is log1p and not (x.lo > -1):
                raise Undefined("log1p of values <= -1")
            if f is sp.acosh and not (x.lo >= 1):
                raise Undefined("acosh below 1")
            if f is sp.atanh and not (x.lo > -1 and x.hi < 1):
                raise Undefined("atanh outside (-1, 1)")
            if direction < 0:
                return Iv(g(x.hi), g(x.lo))
            return _increasing(g, x)
        return None

    # helpers -------------------------------------------------------------
    def _no_overflow(self, hi: arb, what) -> None:
        if not hi * (1 + self.u) <= self.max:
            raise Uncertified(f"{what} may overflow")

    def _underflow(self, x: Iv, E: arb, ops) -> arb:
        """Absolute error of `ops` roundings of a value that may be below the normal range."""
        if _is_zero(x):
            return arb(0)
        return self.sub * ops if not (_mag(x)[0] * (1 - E) >= self.min) else arb(0)

    def relative(self, e: sp.Expr) -> arb:
        """One relative bound for e (absolute errors divided by min |e|)."""
        E, A = self.error(e)
        if A.is_zero():
            return E
        lo = _mag(self.value(e))[0]
        if not lo > 0:
            raise MayVanish(f"{sp.sstr(e)[:60]} may vanish: no relative bound")
        return E + A / lo

    # propagation -----------------------------------------------------------
    def error(self, e: sp.Expr) -> tuple[arb, arb]:
        """(E, A) for e as printed (raises Uncertified)."""
        try:
            return self._error(e)
        except Undefined as exc:
            raise Uncertified(str(exc)) from None

    def _error(self, e: sp.Expr):
        if e in self.env:
            return self.env[e][1], self.env[e][2]
        x = self.value(e)
        if e.is_number:          # one literal: 40 digits rounded to double (then to float)
            return (arb(0) if _representable(e, self.p) else self.u + LITERAL_EXTRA[self.p]), arb(0)
        if e.is_Add:
            return self._sum(e, x)
        E, A = self._product(e, x) if e.is_Mul else self._power(e, x) if e.is_Pow else self._call(e, x)
        self._no_overflow(_mag(x)[1] * (1 + E) + A, "a result")      # the value itself, rounded
        return E, A

    def _sum(self, e, x: Iv):
        """gamma_{n-1} sum |x_i^| plus the terms' own errors (sums are exact below the normal range)."""
        gamma = (1 + self.u) ** (len(e.args) - 1) - 1
        total, worst_E, total_A, sum_abs = arb(0), arb(0), arb(0), arb(0)
        signs = set()
        for a in e.args:
            E, A = self._error(a)
            v = self.value(a)
            hi = _mag(v)[1]
            total += hi * E + A + gamma * (hi * (1 + E) + A)
            worst_E, total_A, sum_abs = worst_E.max(E), total_A + A, sum_abs + hi * (1 + E) + A
            signs.add(1 if v.nonnegative() else (-1 if v.nonpositive() else 0))
        lo, hi = _mag(x)
        self._no_overflow(sum_abs * (1 + self.u) ** len(e.args), "a partial sum")
        general = (total / lo, arb(0)) if lo > 0 else (arb(0), total)
        if len(signs) == 1 and 0 not in signs:
            # terms of one sign: sum |x_i| = |sum x_i|, no cancellation
            same = (worst_E * (1 + gamma) + gamma, total_A * (1 + gamma))
            if not (lo > 0 and general[0] < same[0] + same[1] / lo):
                return same
        return general

    def _product(self, e, x: Iv):
        """Printed as (numerator product)/(denominator product), n - 1
        roundings in all; every partial product of either side stays below
        the product of max(1, |factor|) of that side."""
        coeff, rest = e.as_coeff_Mul()
        factors = list(sp.Mul.make_args(rest)) + ([] if abs(coeff) == 1 else [abs(coeff)])
        rel, core, mag = arb(1), arb(1), arb(1)
        high_num, high_den, low_num, low_den, any_abs = arb(1), arb(1), arb(1), arb(1), False
        if coeff.is_Rational and coeff.q != 1:     # SymPy prints p x / q: p joins the numerator, q the denominator
            high_num *= max(1, abs(int(coeff.p)))
            high_den *= int(coeff.q)
        for f in factors:
            E, A = self._error(f)
            lo, hi = _mag(self.value(f))
            rel *= 1 + E
            core *= hi * (1 + E)
            mag *= hi * (1 + E) + A
            any_abs = any_abs or not A.is_zero()
            if f.is_Pow and f.exp.is_negative:       # the denominator holds base**k = 1/f
                if not lo > 0:
                    raise Uncertified("a denominator may be infinite")
                high_den *= (2 / lo).max(arb(1))
                low_den *= (1 / (2 * hi)).min(arb(1))
            else:
                high_num *= (hi * (1 + E) + A).max(arb(1))
                low_num *= (lo * (1 - E)).min(arb(1))
        self._no_overflow(high_num * (1 + self.u) ** len(factors), "a partial product")
        self._no_overflow(high_den * (1 + self.u) ** len(factors), "a partial denominator")
        if not low_den >= self.min:
            raise Uncertified("a partial denominator may fall below the normal range")
        n = len(factors) - 1
        E = rel * (1 + self.u) ** n - 1
        # |prod x^ - prod x (1 + e_i)| <= prod(|x_i|(1+E_i) + A_i) - prod |x_i|(1+E_i), largest at the top
        A = (mag - core).abs_upper() if any_abs else arb(0)
        # a rounding below the normal range (of a partial product or of the result): half a
        # subnormal, times the later factors
        partial_low = not (low_num >= self.min)
        A_r = arb(0)
        if n > 0 and (partial_low or not self._underflow(x, E, 1).is_zero()):
            A_r = self.sub * n * high_num / low_den
        return E, A * (1 + self.u) ** n + A_r

    def _power(self, e, x: Iv):
        base, p = e.base, e.exp
        P = abs(p)
        Pa = arb(fmpq(int(P.p), int(P.q)))
        blo, bhi = _mag(self.value(base))
        if p.is_Integer and abs(p) <= 8 and p > 0:             # (b*b*...): a product
            Eb0, Ab0 = self._error(base)
            k = int(P)
            rel = (1 + Eb0) ** k
            mag = (bhi * (1 + Eb0) + Ab0) ** k
            A = (mag - _mag(x)[1] * rel).abs_upper() if Ab0 > 0 else arb(0)
            E = rel * (1 + self.u) ** (k - 1) - 1
            self._no_overflow(bhi.max(arb(1)) ** k * (1 + E) + A, "a power")
            return E, A * (1 + self.u) ** (k - 1) + self._underflow(x, E, k - 1) * bhi.max(arb(1)) ** k
        Eb = self.relative(base)
        if not Eb < 1:
            raise Uncertified("relative error of a base >= 1")
        dev = (1 - Eb) ** (-Pa) - 1
        if p.is_Integer and abs(p) <= 8:                        # (1/(b*...))
            ops, k = int(P), int(P)
        elif p.q == 2 and abs(p) <= 17:                         # b*...*sqrt(b) (1/(...) if p < 0)
            ops, k = int(P.p) // 2 + 1 + (1 if p < 0 else 0), int(P.p) // 2 + 1
        else:                                                  # pow(b, p)
            if not blo > 0:
                raise Uncertified("pow of a base that may be <= 0")
            if not _representable(p, self.p):          # the exponent is a rounded literal
                lmax = _mag(Iv(blo.log(), bhi.log()))[1]
                dev = (1 + dev) * (Pa * self.u * lmax).exp() - 1
            E = (1 + dev) * (1 + LIBM_U["pow"] * self.u) - 1
            self._no_overflow(_mag(x)[1] * (1 + E), "a power")
            return E, self._underflow(x, E, LIBM_U["pow"])
        # every partial power b**i (i <= k) and the reciprocal of the denominator
        if not blo > 0:
            raise Uncertified(f"a power of {sp.sstr(base)[:40]} that may be 0")
        if not (blo.min(arb(1)) ** k >= self.min):
            raise Uncertified(f"a partial power of {sp.sstr(base)[:40]} may fall below the normal range")
        self._no_overflow(bhi.max(arb(1)) ** k * (1 + dev) * 2, "a power")
        E = (1 + dev) * (1 + self.u) ** ops - 1
        return E, self._underflow(x, E, ops)

    def _call(self, e, x: Iv):
        f = type(e)
        if f is sp.Abs:
            return self._error(e.args[0])
        if f not in _FUNCS:
            raise Uncertified(f"no accuracy model for {f.__name__}")
        name = _FUNCS[f][0]
        a = e.args[0]
        Ea, Aa = self._error(a)
        xa = self.value(a)
        err = _mag(xa)[1] * Ea + Aa              # |a^ - a| <= err
        # phi' over every value the rounded argument can take (mean value theorem):
        # a^ lies in [a - |a| E - A, a + |a| E + A], increasing in a for E < 1
        if not Ea < 1:
            raise Uncertified(f"relative error of the argument of {name} >= 1")
        rel = Iv(xa.lo - abs(xa.lo) * Ea, xa.hi + abs(xa.hi) * Ea)      # a (1 + e), |e| <= Ea
        wide = Iv(rel.lo - Aa, rel.hi + Aa)
        d = _mag(Analysis(self.p, {_Z: (wide, arb(0), arb(0))}).value(_DERIVATIVE[f]))[1]
        lo, hi = _mag(x)
        lib = LIBM_U[name] * self.u
        self._no_overflow(hi * (1 + lib) + d * err, f"{name}(...)")
        if not lo > 0:
            return lib, d * err * (1 + lib) + self.sub * LIBM_U[name]
        # the argument's relative part gives a relative change, its absolute part an absolute one
        E = (1 + d * _mag(xa)[1] * Ea / lo) * (1 + lib) - 1
        log_rule = self._log_change(f, rel, Ea)
        if log_rule is not None:
            E = E.min((1 + log_rule) * (1 + lib) - 1)
        if not E < 1:
            # no useful relative bound (exp(-x) with x ~ 1e36 and x's error): |phi^ - phi| <= |phi^| + |phi|,
            # harmless where the value is negligible in a sum (3/2 + e exp(-(2 st - 3)^2))
            far = _mag(Analysis(self.p, {_Z: (wide, arb(0), arb(0))}).value(f(_Z)))[1]
            return arb(0), far * (1 + lib) + hi + self.sub * LIBM_U[name]
        return E, d * Aa * (1 + lib) + self._underflow(x, E, LIBM_U[name])

    def _log_change(self, f, wide: Iv, Ea) -> arb | None:
        """The relative part through log|phi|: |log|phi(a (1 + e))| - log|phi(a)|| <=
        sup |z phi'(z)/phi(z)| |e|/(1 - |e|) over z between a and a (1 + e), so the
        relative change is at most exp(that) - 1 (None when z or phi may
        vanish there).  Tight on wide boxes where the rule above is not
        (exp over [100, 200])."""
        zlo = _mag(wide)[0]
        if not (zlo > 0 and Ea < 1):
            return None
        try:
            kappa = _mag(Analysis(self.p, {_Z: (wide, arb(0), arb(0))}).value(
                _LOG_DERIVATIVE.get(f, _Z * _DERIVATIVE[f] / f(_Z))))[1]
        except (Uncertified, Undefined):
            return None
        if not kappa.is_finite():
            return None
        return (kappa * Ea / (1 - Ea)).exp() - 1


# --------------------------------------------------------------------------
# regions

@dataclass(frozen=True)
class RegionAccuracy:
    """A part of the plane (`where`, in m = max(|e1|, |e2|)) and the
    certified relative error of g there (None: not certified, `reason`)."""
    region: str
    where: str
    g: float | None
    term: float | None = None
    reason: str = ""
    m_range: tuple = (0.0, math.inf)       # (lo, hi) of m covered by this entry


@dataclass
class Accuracy:
    """What `certify` proved for one precision.  v, w: bounds relative to
    |vr| + k1 and |wr| + lam |vr| KF + k2 (plus `absolute` for underflow),
    valid for inputs outside the uncertified regions."""
    precision: str
    regions: list = field(default_factory=list)
    v: float | None = None
    w: float | None = None
    absolute: float = 0.0

    @property
    def certified(self) -> list:
        return [r for r in self.regions if r.g is not None]

    @property
    def uncertified(self) -> list:
        return [r for r in self.regions if r.g is None]

    @property
    def g(self) -> float | None:
        return max((r.g for r in self.certified), default=None)

    def lines(self) -> list[str]:
        """Header text (plain sentences, wrapped by the template)."""
        name = "double" if self.precision == "double" else "float (_f32)"
        if not self.certified:
            return [f"{name}: no accuracy certified ({self.regions[0].reason if self.regions else 'f is not radial'})."]
        where = " outside the ranges marked NOT CERTIFIED" if self.uncertified else ""
        out = [f"{name}{where}: |g^ - g| <= {_above(self.g)} |g| and |term^ - term| <= "
               f"{_above(max(r.term for r in self.certified))} |term| where the term is a normal number; "
               f"|v^ - v| <= {_above(self.v)} (|vr| + k1) + {_above(self.absolute)}, |w^ - w| <= {_above(self.w)} "
               f"(|wr| + lam |vr| KF + k2) + {_above(self.absolute)} (the absolute terms: underflow)."]
        for r in self.certified:
            out.append(f"  {r.where}: g within {_above(r.g)}.")
        for r in self.uncertified:
            out.append(f"  NOT CERTIFIED for {r.where}: {r.reason}.")
        return out


def _fmt(x) -> str:
    return f"{float(x):.3g}"


def _above(x, digits: int = 2, rounding=ROUND_CEILING) -> str:
    """x > 0 with `digits` significant digits, rounded up (`rounding`
    ROUND_FLOOR: down): a printed bound is never below the certified one
    (3.34e-15 prints as 3.4e-15, not 3.3e-15)."""
    d = Decimal(float(x))
    if d <= 0 or not d.is_finite():
        return f"{float(x):.{digits}g}"
    e = d.adjusted() - (digits - 1)
    return f"{float(d.scaleb(-e).to_integral_value(rounding=rounding).scaleb(e)):.{digits}g}"


def _geometric_boxes(lo: float, hi: float, ratio: float = 16.0):
    if not 0 < lo:
        raise ValueError("geometric boxes need lo > 0")
    x = lo
    while x < hi:
        y = min(x * ratio, hi)
        yield x, y
        x = y


def _cover(lo, hi, analyse, goal, bad: list, depth=6) -> float:
    """max of analyse(a, b) over geometric boxes of [lo, hi], each split in
    two (geometric mean) while its bound is above goal; a box that cannot be
    bounded is appended to `bad` as (a, b, reason)."""
    worst = 0.0
    stack = [(a, b, depth) for a, b in _geometric_boxes(lo, hi)][::-1]
    while stack:
        a, b, d = stack.pop()
        try:
            E, why, vanish = analyse(a, b), "", False
        except Uncertified as exc:
            E, why, vanish = math.inf, str(exc), isinstance(exc, MayVanish)
        if E > goal and d > 0 and b > a * (1 + 1e-9):
            mid = math.sqrt(a) * math.sqrt(b)
            d = min(d, 2) if why and not vanish else d     # no bound at all (overflow...): split little
            stack += [(mid, b, d - 1), (a, mid, d - 1)]
        elif E <= goal:
            worst = max(worst, E)
        else:
            bad.append((a, b, why or f"the error bound {E:.2g} is above the goal {goal:g}"))
    return worst


def _merge(ranges):
    """Union of (lo, hi, reason) ranges of m; the first reason of each run."""
    out = []
    for lo, hi, why in sorted(ranges):
        if out and lo <= out[-1][1] * (1 + 1e-12):
            out[-1] = (out[-1][0], max(out[-1][1], hi), out[-1][2])
        else:
            out.append((lo, hi, why))
    return out


def _covers(ranges, lo: float, hi: float) -> bool:
    """Whether the merged (a, b, reason) ranges of m cover [lo, hi]."""
    x = lo
    for a, b, _ in ranges:
        if a > x:
            return False
        x = max(x, b)
    return x >= hi


def _iv(a: float, b: float) -> Iv:
    return Iv(arb(a), arb(b))


class _Region:
    """Shared per-precision quantities of the template's fixed operations."""

    def __init__(self, precision):
        self.p = precision
        self.u = arb(fmpq(1, 2 ** (53 if precision == "double" else 24)))
        u = self.u
        # q = min/m (one division), 1 + q*q (q^2 rounded twice, one addition, absolute underflow
        # errors below 2^-1000 against a sum >= 1), r = sqrt, ir = 1/r
        one_q2 = (1 + u) ** 4 - 1 + arb(SUBNORMAL[precision]) * 4
        self.E_r = (1 - one_q2) ** (-arb(fmpq(1, 2))) * (1 + u) - 1
        self.E_ir = (1 - self.E_r) ** -1 * (1 + u) - 1
        self.E_im = u
        self.E_tt = (1 + self.E_im) * (1 + self.E_ir) * (1 + u) - 1
        self.E_st = (1 - self.E_tt) ** -1 * (1 + u) - 1
        # lt = -(log m + log1p(q*q)/2): two non-negative terms
        lib = lambda n: LIBM_U[n] * u  # noqa: E731
        self.E_lt = ((1 + lib("log")) * (1 + lib("log1p")) * (1 + u) ** 3) * (1 + u) - 1


def _products(E_factors, n_ops, u) -> arb:
    total = arb(1)
    for E in E_factors:
        total *= 1 + E
    return total * (1 + u) ** n_ops - 1


def _branch_boxes(branches, region_lo, region_hi, E_var):
    """(branch, lo, hi) with the branch's range widened by the rounding of
    its variable (a rounded rho or t may select it slightly outside)."""
    for br in branches:
        lo = max(region_lo, br.lo_float * (1 - 2 * E_var))
        hi = min(region_hi, br.hi_float * (1 + 2 * E_var))
        if lo < hi:
            yield br, lo, hi


def _mismatch(branches, var, region_lo, region_hi, E_var, precision, bad: list) -> float:
    """Relative difference of two neighbouring branches over the sliver
    around their boundary where the rounded variable may pick either (a
    sliver that cannot be bounded goes to `bad`)."""
    worst = 0.0
    for left, right in zip(branches, branches[1:]):
        b = left.hi_float
        if not (region_lo < b < region_hi):
            continue
        lo_b, hi_b = b * (1 - 4 * E_var), b * (1 + 4 * E_var)
        env = {var: (_iv(lo_b, hi_b), arb(0), arb(0))}
        if var == T:                            # a far branch may hold st = 1/t and lt = log t
            env |= {ST: (Iv(1 / arb(hi_b), 1 / arb(lo_b)), arb(0), arb(0)),
                    LT: (Iv(arb(lo_b).log(), arb(hi_b).log()), arb(0), arb(0))}
        try:
            with arb_precision(256):
                diff = Analysis(precision, env).value(plain(left.expr + left.dropped - right.expr - right.dropped))
                lo_left, lo_right = (_mag(Analysis(precision, env).value(plain(br.expr)))[0] for br in (left, right))
                lo = lo_left.min(lo_right)
        except (Uncertified, Undefined) as exc:
            bad.append((lo_b, hi_b, f"branch switch at {var} = {_fmt(b)}: {exc}"))
            continue
        if not lo > 0:
            bad.append((lo_b, hi_b, f"branch switch at {var} = {_fmt(b)}: the law may vanish there"))
            continue
        E = _up(_mag(diff)[1] / lo)
        if E > GOAL[precision]:
            bad.append((lo_b, hi_b, f"the branches differ by {E:.2g} (relative) where the rounded {var} "
                                    f"may pick the wrong one at {_fmt(b)}"))
        else:
            worst = max(worst, E)
    return worst


def _mid_box(expr, prec, a, b, bound=sp.S.Zero) -> float:
    """Relative bound on g = e2 H(rho) for rho in [a, b], H printed as expr,
    rho = e1*e1 + e2*e2 rounded (absolute underflow of the squares against
    rho >= a); `bound` >= |H - expr| when expr is a truncated series (a near
    branch: `law.near_branch`)."""
    u = arb(fmpq(1, 2 ** (53 if prec == "double" else 24)))
    E_rho = (1 + u) ** 2 - 1 + arb(SUBNORMAL[prec]) * 2 / arb(a)
    E_H = Analysis(prec, {RHO: (_iv(a, b), E_rho, arb(0))}).relative(expr)
    if bound != 0:                      # H = expr + r, |r| <= bound: (1 + E) / (1 - sup bound / min |expr|)
        exact = Analysis(prec, {RHO: (_iv(a, b), arb(0), arb(0))})
        trunc = _mag(exact.value(bound))[1] / _mag(exact.value(expr))[0]
        if not trunc < 1:
            raise Uncertified(f"the Taylor remainder may reach {_up(trunc):.2g} of the polynomial")
        E_H = (1 + E_H) / (1 - trunc) - 1
    return _up(_products([E_H], 1, u))          # g = e2 H: one product


def cancels_at_zero(expr, rho: float = 2.0 ** -60, ratio: float = 2.0 ** 10) -> bool:
    """For `law.near_branch`: does a sum in expr (a mid form H) lose more
    than `ratio` in magnitude at rho, sum |terms| > ratio |sum|, in exact
    (Arb) values?  Unlike an error bound, which underflow inflates as
    well (rho^4 in float at 2^-60), this is the cancellation a series
    removes."""
    with arb_precision(256):
        an = Analysis("double", {RHO: (_iv(rho, rho), arb(0), arb(0))})
        try:
            for node in sp.preorder_traversal(expr):
                if node.is_Add and node.has(RHO):
                    total = sum((_mag(an.value(t))[1] for t in node.args), arb(0))
                    if not _mag(an.value(node))[0] * ratio > total:
                        return True
        except (Uncertified, Undefined):
            return False
    return False


def accurate_from(expr, precision: str, top: float, goal: float) -> float | None:
    """For `law.near_branch`: the least rho = x 2^-k below the highest
    x = top 2^-j at which g = e2 H, H printed as expr, is within goal
    (`_mid_box`) on [x/2, x], such that it is within goal on every box
    [y, 2y] from rho to x; None when there is no such x above 2^-60."""
    def ok(a, b):                       # (boxes split as `_mid` splits them)
        bad = []
        try:
            return _cover(a, b, lambda x, y: _mid_box(expr, precision, x, y), goal, bad) <= goal and not bad
        except Undefined:
            return False
    with arb_precision(128):
        lo = top
        while lo > 2.0 ** -60 and not ok(lo / 2, lo):     # (above it a form may overflow: not this concern)
            lo /= 2
        if lo <= 2.0 ** -60:
            return None
        while lo > 2.0 ** -60 and ok(lo / 2, lo):
            lo /= 2
    return lo


def _mid(model, prec, reg, tiny, far):
    """tiny <= m <= far: g = e2 H(rho) (`_mid_box`).  Returns (bound, bad
    ranges of m)."""
    rho_lo = tiny ** 2 if model.tiny is not None else MIN_NORMAL[prec] * 2.0 ** 60
    rho_hi = 2 * far ** 2
    E_var = _up((1 + reg.u) ** 2 - 1) + 2 ** -60

    bad, worst = [], 0.0
    for br, lo, hi in _branch_boxes(model.mid, rho_lo, rho_hi, E_var):
        worst = max(worst, _cover(lo, hi, lambda a, b, br=br: _mid_box(br.expr, prec, a, b, br.bound), GOAL[prec], bad))
    worst += _mismatch(model.mid, RHO, rho_lo, rho_hi, E_var, prec, bad)
    if model.tiny is None:
        bad.append((0.0, rho_lo, "no series at 0: rho may be subnormal"))
    # rho = m^2 (1 + q^2), q in [0, 1]
    return worst, [(math.sqrt(a / 2), math.sqrt(b), why) for a, b, why in bad]


def _far(model, prec, reg, far):
    """m > far: g = t^k D(t) (e2/m)(1/r), t = im ir, st = min(1/t, MAX),
    lt = log t from the scaled norm.  Returns (bound, bad ranges of m)."""
    u = reg.u
    big = MAX_FINITE[prec]
    t_lo, t_hi = 1 / math.sqrt(2) / big * (1 - 1e-15), 1 / far
    E_var = _up(reg.E_tt) + 2 ** -60

    def analyse_branch(br):
        def analyse(a, b):
            inv_a, inv_b = 1 / arb(a), 1 / arb(b)
            beyond = not (inv_a * (1 + reg.E_st) < big)     # s may exceed the range: st = MAX there
            env = {T: (_iv(a, b), reg.E_tt, arb(0)),
                   ST: (Iv(inv_b, inv_a), arb(0.3) if beyond else reg.E_st, arb(0)),
                   LT: (Iv(arb(a).log(), arb(b).log()), reg.E_lt, arb(0))}
            E_D = Analysis(prec, env).relative(br.expr)
            if br.dropped != 0:                 # D = printed + dropped: (1 + E_D) / (1 - |dropped / D|)
                exact = {x: (v[0], arb(0), arb(0)) for x, v in env.items()}
                trunc = _mag(Analysis(prec, exact).value(plain(br.dropped)))[1] / \
                    _mag(Analysis(prec, exact).value(plain(br.expr)))[0]
                if not trunc < 2 ** -60:
                    raise Uncertified(f"the terms left out of the tail form may reach {_up(trunc):.2g} of it")
                E_D = (1 + E_D) / (1 - trunc) - 1
            k = abs(br.k)
            split = [reg.E_im, reg.E_ir] if br.k > 0 else [arb(0), reg.E_r]
            # e2 * im * ir * D * (im * ir)^k  (or (m * r)^k): 2k + 4 factors
            return _up(_products([E_D, reg.E_im, reg.E_ir] + split * k, 2 * k + 3, u))
        return analyse

    bad, worst = [], 0.0
    for br, lo, hi in _branch_boxes(model.far, t_lo, t_hi, E_var):
        worst = max(worst, _cover(lo, hi, analyse_branch(br), GOAL[prec], bad))
    worst += _mismatch(model.far, T, t_lo, t_hi, E_var, prec, bad)
    # t = 1/s, s = m sqrt(1 + q^2)
    return worst, [(1 / b / math.sqrt(2), min(1 / a, big), why) for a, b, why in bad]


def _series_error(dF, a, j, delta, prec) -> arb:
    """sup |F'(s)/(a s^j) - 1| over (0, delta], rigorously: Arb encloses
    q = F'(s)/s^j over [0, delta] when q, simplified, is defined at 0
    (s^9/(1 + s^10) -> 1/(1 + s^10)); otherwise Lagrange's remainder,
    |F'(s) - a s^j| <= sup|F'^(j+1)| s^(j+1)/(j+1)!, given F'^(i)(0) = 0
    exactly for i < j and F'^(j)(0)/j! near a, from Arb's Taylor series of
    F' at 0 and over the ball [0, delta] (`law._taylor`)."""
    from ..profile import S
    aj = Analysis(prec, {}).value(sp.sympify(a)).hull()
    if not aj.abs_lower() > 0:
        raise Uncertified("leading coefficient not bounded away from 0")
    box = {S: (_iv(0.0, delta), arb(0), arb(0))}
    q = dF / S ** j
    q = sp.cancel(q) if not q.has(sp.Function) else sp.powsimp(sp.expand_power_base(q))
    try:
        Q = Analysis(prec, box).value(plain(q))
        return _mag(Iv(Q.lo - aj, Q.hi - aj))[1] / abs(aj)
    except (Uncertified, Undefined):
        pass
    try:
        with series_terms(j + 2):
            at0 = _taylor(dF, S, arb(0)).coeffs() + [arb(0)] * (j + 2)
            rem = (_taylor(dF, S, arb(delta / 2, delta / 2)).coeffs() + [arb(0)] * (j + 2))[j + 1]
    except ValueError as exc:
        raise Uncertified(f"no series of F' at 0: {exc}") from None
    if not all(c.is_zero() for c in at0[:j]):
        raise Uncertified("the series' first terms are not exactly 0 in Arb")
    # |F'(s) - a s^j| <= |F'^(j)(0)/j! - a| s^j + sup |F'^(j+1)/(j+1)!| s^(j+1) (Lagrange), over |a| s^j
    return (_mag(Iv(at0[j] - aj, at0[j] - aj))[1] + abs(rem).abs_upper() * arb(delta)) / abs(aj)


def _tiny(model, prec, reg, tiny):
    """m < TINY: F'(s) replaced by a s^j, s^j = m^j r^j, e2/s = (e2/m)/r;
    the truncation from `_series_error`."""
    a, j = model.tiny
    if model.tiny_source is None:
        raise Uncertified("no expression of F' to bound the series")
    if SUBNORMAL[prec] / tiny < MIN_NORMAL[prec]:
        raise Uncertified("e2/m may be subnormal")
    with arb_precision(256):
        trunc = _series_error(model.tiny_source, a, j, math.sqrt(2) * tiny * (1 + 1e-12), prec)
        trunc = trunc / (1 - trunc)          # relative to F'(s), not to a s^j
        u = reg.u
        E_c = (1 + u) * (1 + reg.E_ir) * (1 + u) - 1
        E_a = arb(0) if _representable(sp.sympify(a), prec) else u + LITERAL_EXTRA[prec]
        E = _products([E_c, E_a] + [reg.E_r] * j, 2 * j + 1, u)
        return _up((1 + E) * (1 + trunc) - 1), []


def _template(prec, reg, E_term):
    """v = vr cos(e3) + k1 tanh(e1), w = wr + term + k2 tanh(e3), each
    sum of rounded terms bounded by the right-hand side of bound (10)."""
    u = reg.u
    lib = lambda n: LIBM_U[n] * u  # noqa: E731
    E_cos, E_tanh = lib("cos"), lib("tanh")
    gamma1, gamma2 = u, (1 + u) ** 2 - 1
    E_v = (1 + E_cos.max(E_tanh)) * (1 + u) * (1 + gamma1) - 1
    E_w = (1 + arb(E_term).max(E_tanh * (1 + u) + u)) * (1 + gamma2) - 1
    # the overflow retry halves terms: each half may lose one subnormal unit
    return _up(E_v), _up(E_w), SUBNORMAL[prec] * 8 + MIN_NORMAL[prec] * 4


def sinc_error(prec, cut) -> arb:
    """sin(e3)/e3 (|e3| >= cut) or 1 - z (1/6 - z/120), z = e3^2 (|e3| < cut).
    Where sin(e3)/e3 would be below the normal range the code divides sin(e3)
    2^S instead (exact, normal: `law.SINC_SHIFT`) and multiplies 2^-S in by
    exponents, exactly: the same two roundings, on a normal number."""
    u = arb(fmpq(1, 2 ** (53 if prec == "double" else 24)))
    direct = (1 + LIBM_U["sin"] * u) * (1 + u) - 1
    z = arb(cut) ** 2
    series = 6 * u + z ** 3 / 5040 / (1 - z / 6)
    return direct.max(series)


def certify(model: LawModel, precision: str, sinc_cut: float) -> Accuracy:
    """The certified accuracy of the law as the back-ends print it (module doc)."""
    acc = Accuracy(precision)
    if not model.radial:
        acc.regions.append(RegionAccuracy("general", "the plane", None,
                                          reason="f is not known to be radial: no error analysis of df/de2"))
        return acc
    reg = _Region(precision)
    tiny, far = model.thresholds[precision]
    E_sinc = sinc_error(precision, sinc_cut)
    parts = [("tiny", 0.0, tiny, lambda: _tiny(model, precision, reg, tiny))] if model.tiny is not None else []
    parts += [("mid", tiny if model.tiny is not None else 0.0, far, lambda: _mid(model, precision, reg, tiny, far)),
              ("far", far, MAX_FINITE[precision], lambda: _far(model, precision, reg, far))]
    with arb_precision(128):
        for name, lo, hi, run in parts:
            try:
                E, bad = run()
            except Uncertified as exc:
                acc.regions.append(RegionAccuracy(name, _range(lo, hi, widen=True), None, reason=str(exc),
                                                  m_range=(lo, hi)))
                continue
            term = _up(_products([arb(E), E_sinc], 3, reg.u))
            bad = _merge(bad)
            where = _range(lo, hi) + (" (except as listed)" if bad else "")
            if not _covers(bad, lo, hi):    # (where the exceptions cover it all, nothing is certified)
                acc.regions.append(RegionAccuracy(name, where, E, term, m_range=(lo, hi)))
            acc.regions += [RegionAccuracy(name, _range(max(a, lo), min(b, hi), widen=True), None, reason=why,
                                           m_range=(max(a, lo), min(b, hi))) for a, b, why in bad]
        worst = max((r.term for r in acc.regions if r.term is not None), default=0.0)
        acc.v, acc.w, acc.absolute = _template(precision, reg, worst)
    return acc


def lam_vr_kf(a, kf: float):
    """lam |vr| KF for rows of |inputs| (lam = a[:, 7], vr = a[:, 3]) as
    (largest * smallest) * middle, so no partial product underflows or
    overflows where the result is a normal number (lam vr = 1e-359 is 0 in
    double, with KF = 1e300); two roundings."""
    import numpy as np
    f = np.sort(np.stack([a[:, 7], a[:, 3], np.full(len(a), kf)]), axis=0)
    return f[0] * f[2] * f[1]


def first_violation(acc: Accuracy, x, ref: dict, v, w, st, kf: float):
    """The first row (index) where outputs with status 0 break the certified
    bounds on v or w, skipping rows whose m lies in a NOT CERTIFIED range
    (None if none): the translation validation checks the certificate too.
    x: rows (e1, e2, e3, vr, wr, k1, k2, lam); ref: `reference.table`."""
    import numpy as np
    if acc.v is None or acc.w is None or not math.isfinite(kf):
        return None
    x = np.asarray(x, dtype=float)
    m = np.maximum(np.abs(x[:, 0]), np.abs(x[:, 1]))
    skip = np.zeros(len(x), dtype=bool)
    for r in acc.uncertified:
        lo, hi = r.m_range
        skip |= (m >= lo * (1 - 1e-9)) & (m <= hi * (1 + 1e-9))
    a = np.abs(x)
    with np.errstate(all="ignore"):
        bv = acc.v * (a[:, 3] + a[:, 5]) + acc.absolute
        bw = acc.w * (a[:, 4] + lam_vr_kf(a, kf) + a[:, 6]) + acc.absolute
        ev = np.abs((np.asarray(v, dtype=float) - ref["v_hi"]) - ref["v_lo"])
        ew = np.abs((np.asarray(w, dtype=float) - ref["w_hi"]) - ref["w_lo"])
        # the reference is double-double: allow for its own rounding (2^-100 relative)
        slack_v, slack_w = np.abs(ref["v_hi"]) * 2.0 ** -100, np.abs(ref["w_hi"]) * 2.0 ** -100
        bad = (np.asarray(st) == 0) & ~skip & np.isfinite(ref["v_hi"]) & np.isfinite(ref["w_hi"]) \
            & ((ev > bv + slack_v) | (ew > bw + slack_w))
    idx = np.flatnonzero(bad)
    return int(idx[0]) if len(idx) else None


def _range(lo, hi, widen=False) -> str:
    """The range lo..hi of m as printed; `widen` (a range NOT CERTIFIED):
    its ends rounded outwards, so that the printed range holds it."""
    low, high = (_above(lo, 3, ROUND_FLOOR), _above(hi, 3)) if widen else (_fmt(lo), _fmt(hi))
    if lo == 0:
        return f"0 < m < {high}"
    if hi >= 1e38:
        return f"m > {low}"
    return f"{low} <= m <= {high}"


def contract_lines(accuracies: list, width: int = 72) -> list[str]:
    """The certified-accuracy paragraph of a generated header, wrapped."""
    import textwrap
    libm = ", ".join(f"{n} {LIBM_U[n] // 2}" for n in sorted(LIBM_U))
    intro = ("Accuracy, certified (uwmr_symbolic/codegen/accuracy.py): a rigorous error analysis of "
             "the operations this code performs, in interval arithmetic over every region of "
             "m = max(|e1|, |e2|), proves for finite inputs with status 0 the bounds below.  It "
             "assumes IEEE arithmetic rounded to nearest without extended intermediates "
             "(FLT_EVAL_METHOD 0) and math-library functions within these ulps: " + libm + ".  "
             "g = df/de2(e1, e2) as computed, term = lam vr g sin(e3)/e3.")
    out = textwrap.wrap(intro, width)
    for acc in accuracies:
        for i, line in enumerate(acc.lines()):
            indent = "  " if i == 0 else "      "
            out += textwrap.wrap(line.strip(), width, initial_indent=indent, subsequent_indent=indent + "  ")
    return out
