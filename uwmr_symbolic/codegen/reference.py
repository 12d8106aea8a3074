"""High-precision reference values of the law (9), for tests and benchmarks.

The reference is independent of the numerics of `law`: it evaluates the
plain derivative g = df/de2 of the design's f (SymPy's `diff`, with the
verifier's sinh/cosh -> tanh rewriting, an identity) in ball arithmetic
(python-flint's Arb), raising the working precision until every component is
known to 2**-90 relative (cancellation such as sqrt(4 rho + 1) - 1 at
rho = 1e-300 needs thousands of bits; Arb's radius says when it is enough).
`mp_law` evaluates the same law with mpmath at 50 digits (or more when the
two disagree), the cross-check the issue asks for.

The tolerance scale of a component is the largest magnitude among the exact
value and the terms it is the sum of (v: vr cos e3, k1 tanh e1; w: wr,
lam vr g sinc e3, k2 tanh e3), floored at the smallest normal number of the
precision: the relative error that a correct floating-point evaluation of
the sum can guarantee.  The scale of w also contains lam vr sinc(e3) times
|e . grad g|, the change of the g term under a relative change of the radius:
where g itself is ill-conditioned in s (design 4's sin(sqrt(rho+1) - 1) near
its zero at s = 4.016, which no evaluation of that formula in float can
resolve) the error is judged as a mixed forward/backward error."""
from __future__ import annotations

import math
from dataclasses import dataclass

import flint
import mpmath
import numpy as np
import sympy as sp
from sympy.codegen.cfunctions import expm1, log1p

from .. import e1 as E1, e2 as E2
from ..interval import NUMBER_SYMBOLS
from ..univariate import prepare
from .law import partial_e2

START_PREC, MAX_PREC = 128, 16384
REL = 2.0 ** -90


class NeedPrecision(Exception):
    pass


def _arb_fn(expr: sp.Expr):
    """Compile expr(e1, e2) into a function of two arbs (closures)."""
    if expr == E1:
        return lambda a, b: a
    if expr == E2:
        return lambda a, b: b
    if expr.is_Rational:
        p, q = int(expr.p), int(expr.q)
        return lambda a, b: flint.arb(p) / q
    if expr in NUMBER_SYMBOLS:          # pi, E, EulerGamma, Catalan, GoldenRatio
        return lambda a, b: NUMBER_SYMBOLS[expr]()
    if expr.is_Float:
        val = flint.arb(str(expr))
        return lambda a, b: val
    args = [_arb_fn(x) for x in expr.args] if not isinstance(expr, sp.Piecewise) else None
    if isinstance(expr, sp.Add):
        def add(a, b, fs=args):
            out = fs[0](a, b)
            for f in fs[1:]:
                out = out + f(a, b)
            return out
        return add
    if isinstance(expr, sp.Mul):
        def mul(a, b, fs=args):
            out = fs[0](a, b)
            for f in fs[1:]:
                out = out * f(a, b)
            return out
        return mul
    if isinstance(expr, sp.Pow):
        base, ex = args
        e = expr.args[1]
        if e == sp.Rational(1, 2):
            return lambda a, b: base(a, b).sqrt()
        if e == -sp.Rational(1, 2):
            return lambda a, b: 1 / base(a, b).sqrt()
        if e.is_Integer:
            n = int(e)
            return (lambda a, b: base(a, b) ** n) if n > 0 else (lambda a, b: 1 / base(a, b) ** (-n))
        return lambda a, b: base(a, b) ** ex(a, b)
    names = {sp.sin: "sin", sp.cos: "cos", sp.tan: "tan", sp.tanh: "tanh", sp.sinh: "sinh",
             sp.cosh: "cosh", sp.exp: "exp", sp.log: "log", sp.atan: "atan", sp.asinh: "asinh",
             sp.Abs: "__abs__", sp.erf: "erf", sp.erfc: "erfc", sp.gamma: "gamma", sp.acosh: "acosh",
             sp.atanh: "atanh", sp.asin: "asin", sp.acos: "acos", sp.loggamma: "lgamma",
             log1p: "log1p", expm1: "expm1"}
    if type(expr) in names:
        (f,), name = args, names[type(expr)]
        return lambda a, b: getattr(f(a, b), name)()
    if isinstance(expr, (sp.Min, sp.Max)):
        name = "min" if isinstance(expr, sp.Min) else "max"

        def minmax(a, b, fs=args):
            out = fs[0](a, b)
            for f in fs[1:]:
                out = getattr(out, name)(f(a, b))
            return out
        return minmax
    if isinstance(expr, sp.sign):
        (f,) = args
        return lambda a, b: f(a, b).sgn()
    if isinstance(expr, sp.Piecewise):
        branches = [(_arb_fn(v), _arb_cond(c)) for v, c in expr.args]

        def pw(a, b, start=0):
            for i, (val, cond) in enumerate(branches[start:], start):
                try:
                    if cond(a, b):
                        return val(a, b)
                except NeedPrecision:
                    if flint.ctx.prec < MAX_PREC:
                        raise
                    # a tie at the last precision (Max(u, v) where u = v: log 2 - log 2 never shows 0):
                    # the value is this branch's or a later one's; the union holds both, and is
                    # taken where they agree to REL (a C^1 join, as P1 has it), else undecidable
                    both = val(a, b).union(pw(a, b, i + 1))
                    if both.rad() == 0 or both.rad() <= abs(both.mid()) * REL:
                        return both
                    raise
            raise NeedPrecision
        return pw
    raise NotImplementedError(f"reference: no Arb evaluation for {expr.func.__name__}")


def _arb_cond(cond):
    """A Piecewise condition at (a, b): a relation decided by the sign of
    lhs - rhs (NeedPrecision while the ball holds 0 but is not exactly 0),
    or And, Or, Not of such (And is false once one part is, whatever the
    others' precision; Or true once one part is)."""
    if cond in (True, sp.true, False, sp.false):
        return lambda a, b, value=bool(cond): value
    if isinstance(cond, sp.Not):
        inner = _arb_cond(cond.args[0])
        return lambda a, b: not inner(a, b)
    if isinstance(cond, (sp.And, sp.Or)):
        parts, decisive = [_arb_cond(c) for c in cond.args], isinstance(cond, sp.Or)

        def either(a, b):
            undecided = False
            for part in parts:
                try:
                    if part(a, b) == decisive:
                        return decisive
                except NeedPrecision:
                    undecided = True
            if undecided:
                raise NeedPrecision
            return not decisive
        return either
    lhs, rhs = _arb_fn(cond.lhs), _arb_fn(cond.rhs)
    # which of d > 0, d < 0, d = 0 make the relation true
    holds = {sp.StrictGreaterThan: (True, False, False), sp.GreaterThan: (True, False, True),
             sp.StrictLessThan: (False, True, False), sp.LessThan: (False, True, True),
             sp.Equality: (False, False, True), sp.Unequality: (True, True, False)}[type(cond)]

    def decide(a, b):
        d = lhs(a, b) - rhs(a, b)
        if d > 0:
            return holds[0]
        if d < 0:
            return holds[1]
        if d == 0:    # exactly zero
            return holds[2]
        raise NeedPrecision
    return decide


def adaptive(fn, *args):
    """fn(*arbs) to relative accuracy REL, raising the precision as needed."""
    prec = START_PREC
    old = flint.ctx.prec
    try:
        while True:
            flint.ctx.prec = prec
            try:
                val = fn(*[flint.arb(x) for x in args])
                if val.rad() == 0 or val.rad() <= abs(val.mid()) * REL:
                    return val
            except NeedPrecision:
                val = None
            if prec >= MAX_PREC:
                if val is None:
                    raise ArithmeticError("reference: a Piecewise condition is undecidable at these inputs")
                return val
            prec *= 2
    finally:
        flint.ctx.prec = old


def _sinc(x):
    return x.sin() / x if x != 0 else flint.arb(1)


@dataclass
class Law:
    """The exact law (9) of one design."""
    g_expr: sp.Expr

    @classmethod
    def of(cls, design) -> "Law":
        return cls(prepare(partial_e2(design.f)))

    def __post_init__(self):
        self._g = _arb_fn(self.g_expr)
        # e . grad g: the change of g under a relative change of the radius
        self._dg = _arb_fn(prepare(E1 * sp.diff(self.g_expr, E1) + E2 * sp.diff(self.g_expr, E2)))

    def radial_sensitivity(self, e1: float, e2: float) -> float:
        """A lower bound of |e . grad g| (128-bit Arb, no refinement: only a
        tolerance scale, never inflated by a wide ball)."""
        old = flint.ctx.prec
        flint.ctx.prec = 128
        try:
            val = abs(self._dg(flint.arb(e1), flint.arb(e2)))
            lo = val.lower()
            return 0.0 if not lo.is_finite() or not lo > 0 else _to_float(lo)
        except (NeedPrecision, ZeroDivisionError, ValueError):
            return 0.0
        finally:
            flint.ctx.prec = old

    def g(self, e1: float, e2: float):
        """g(e1, e2); at the origin, where the derivative as derived may be
        0/0 (a norm sqrt(rho) in f), g(0, 0) = 0: g is continuous (P1) and
        g(e1, 0) -> 0 (P8), so this is the value for every design with P1
        and P8 (the generated code returns 0 there for every design)."""
        try:
            val = adaptive(self._g, e1, e2)
        except (ZeroDivisionError, ValueError, ArithmeticError):
            if e1 == 0 and e2 == 0:
                return flint.arb(0)
            raise
        if e1 == 0 and e2 == 0 and not val.is_finite():
            return flint.arb(0)
        return val

    def evaluate(self, x, cache=None):
        """Reference for one input row x = (e1, e2, e3, vr, wr, k1, k2, lam) of
        floats: (v, w, scale_v, scale_w) as arbs at 256 bits, the scales being
        the largest magnitude of the result and its terms."""
        e1, e2, e3, vr, wr, k1, k2, lam = (float(t) for t in x)
        cache = cache if cache is not None else {}
        key = ("g", e1, e2)
        if key not in cache:
            cache[key] = self.g(e1, e2)
        g = cache[key]
        if ("dg", e1, e2) not in cache:
            cache[("dg", e1, e2)] = flint.arb(self.radial_sensitivity(e1, e2))
        for name, arg, fn in (("sinc", e3, _sinc), ("cos", e3, lambda a: a.cos()),
                              ("th", e3, lambda a: a.tanh()), ("th", e1, lambda a: a.tanh())):
            if (name, arg) not in cache:
                cache[(name, arg)] = adaptive(fn, arg)
        old = flint.ctx.prec
        flint.ctx.prec = 256
        try:
            A = flint.arb
            tv1, tv2 = A(vr) * cache[("cos", e3)], A(k1) * cache[("th", e1)]
            tw1, tw2, tw3 = A(wr), A(lam) * A(vr) * g * cache[("sinc", e3)], A(k2) * cache[("th", e3)]
            v, w = tv1 + tv2, tw1 + tw2 + tw3
            sv = max(abs(v).mid(), abs(tv1).mid(), abs(tv2).mid())
            tw4 = A(lam) * A(vr) * cache[("dg", e1, e2)] * cache[("sinc", e3)]
            sw = max(abs(w).mid(), abs(tw1).mid(), abs(tw2).mid(), abs(tw3).mid(), abs(tw4).mid())
            return v, w, A(sv), A(sw)
        finally:
            flint.ctx.prec = old


LIMITS = {"double": (2.2250738585072014e-308, 1.7976931348623157e308),
          "float": (1.1754943508222875e-38, 3.4028234663852886e38)}


#: Where rounding to nearest overflows, as a double: inf for double (its
#: threshold 2^1024 - 2^970, the largest double plus half its ulp, is no
#: double: `_to_float` applies it), 2^128 - 2^103 for float (an exact double).
OVERFLOW = {"double": math.inf, "float": 2.0 ** 127 * (2 - 2.0 ** -24)}
_DOUBLE_TOP = 2 ** 1024 - 2 ** 970


def _to_float(x) -> float:
    """Nearest double of an arb's midpoint, rounded as IEEE does: +-inf from
    2^1024 - 2^970 on, the largest double between that and the largest double."""
    m = x.mid()
    if not m.is_finite():                       # (a tolerance scale of |e . grad g| beyond every number)
        return math.copysign(math.inf, float(m)) if not m.is_nan() else math.nan
    if abs(m) > flint.arb(1.7976931348623157e308):
        man, exp = m.man_exp()                  # the exact dyadic midpoint
        mag = abs(int(man))
        beyond = (mag << exp) >= _DOUBLE_TOP if exp >= 0 else mag >= _DOUBLE_TOP << -exp
        return math.copysign(math.inf if beyond else 1.7976931348623157e308, int(man))
    return float(m)


def table(law: Law, inputs: np.ndarray, cache: dict | None = None) -> dict:
    """Reference for rows of 8 inputs: exact v and w as double-double
    (v_hi + v_lo; v_hi = +-inf beyond the double range) and the magnitudes of
    the terms (the tolerance scales before the floor, see `errors`).  `cache`
    (a dict) may be shared between calls for the same law."""
    n = len(inputs)
    out = {k: np.zeros(n) for k in ("v_hi", "v_lo", "w_hi", "w_lo", "scale_v", "scale_w")}
    cache = {} if cache is None else cache
    old = flint.ctx.prec
    for i in range(n):
        V, W, sv, sw = law.evaluate(inputs[i], cache)
        flint.ctx.prec = 256
        try:
            for name, val in (("v", V), ("w", W)):
                hi = _to_float(val)
                out[f"{name}_hi"][i] = hi
                out[f"{name}_lo"][i] = float((val - flint.arb(hi)).mid()) if math.isfinite(hi) else 0.0
            out["scale_v"][i] = _to_float(sv)
            out["scale_w"][i] = _to_float(sw)
        finally:
            flint.ctx.prec = old
    return out


def _table_job(args):
    design_path, inputs = args
    from ..design import load_design
    return table(Law.of(load_design(design_path)), inputs)


def table_parallel(design_path, inputs: np.ndarray, procs: int = 2) -> dict:
    """`table` computed by `procs` worker processes (chunks of rows)."""
    import multiprocessing as mp
    chunks = np.array_split(np.asarray(inputs, dtype=float), max(1, procs))
    jobs = [(str(design_path), c) for c in chunks if len(c)]
    if procs <= 1:
        parts = [_table_job(j) for j in jobs]
    else:
        from ..timeouts import quiet_on_interrupt
        with mp.get_context("fork").Pool(procs, initializer=quiet_on_interrupt) as pool:
            parts = pool.map(_table_job, jobs)
    return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}


def errors(ref: dict, v, w, precision: str = "double"):
    """(err_v, err_w, over): relative errors |computed - exact| / scale with
    the scale floored at the precision's smallest normal number, and `over`
    where an exact |v| or |w| rounds to infinity in the precision (`OVERFLOW`:
    the code must then report a range error; the errors there are set to 0)."""
    floor, _ = LIMITS[precision]
    v = np.asarray(v, dtype=float)
    w = np.asarray(w, dtype=float)
    top = OVERFLOW[precision]
    over = ~(np.abs(ref["v_hi"]) < top) | ~(np.abs(ref["w_hi"]) < top)
    with np.errstate(all="ignore"):
        ev = np.abs((v - ref["v_hi"]) - ref["v_lo"]) / np.maximum(ref["scale_v"], floor)
        ew = np.abs((w - ref["w_hi"]) - ref["w_lo"]) / np.maximum(ref["scale_w"], floor)
    ev[over] = 0.0
    ew[over] = 0.0
    return ev, ew, over


def mp_g(design, e1: float, e2: float, dps: int = 50):
    """g = df/de2 with mpmath at 50 digits plus the digits that the
    cancellation of rho = e1^2 + e2^2 against 1 costs (1e-300 -> 650 digits)."""
    expr = prepare(partial_e2(design.f))
    fn = sp.lambdify((E1, E2), expr, "mpmath")
    rho = mpmath.mpf(e1) ** 2 + mpmath.mpf(e2) ** 2
    if rho != 0:
        dps += max(0, int(-mpmath.log10(rho)) + 1)
    with mpmath.workdps(dps):
        return +fn(mpmath.mpf(e1), mpmath.mpf(e2))


ERRORS_PREC = 200


def tracking_errors(rows, turns=None, limit: float = LIMITS["double"][1], prec: int = ERRORS_PREC) -> dict:
    """Errors (7) of rows (x, y, th, xr, yr, thr), e3 = (thr - th) + 2 pi n
    with n = turns (0 by default), in mpmath at `prec` bits from the rows'
    exact binary values (mpmath reduces huge headings with the extra
    precision they need).  Arrays of shape (N, 3): `hi` + `lo` the exact
    value as a double-double (hi = inf beyond the double range), `over`
    where |exact| > limit, `edge` where it is within 1e-9 of limit (either
    status is right there); `scale` (N, 3): |x| + |y| + |xr| + |yr| for e1
    and e2, |th| + |thr| + 2 pi |n| for e3, capped at the largest double."""
    rows = np.asarray(rows, dtype=float)
    n = np.zeros(len(rows)) if turns is None else np.asarray(turns, dtype=float)
    hi = np.zeros((len(rows), 3))
    lo = np.zeros((len(rows), 3))
    over = np.zeros((len(rows), 3), dtype=bool)
    edge = np.zeros((len(rows), 3), dtype=bool)
    with mpmath.workprec(prec):
        two_pi = 2 * mpmath.pi
        lim = mpmath.mpf(limit)
        for i, (r, k) in enumerate(zip(rows, n)):
            x, y, th, xr, yr, thr = (mpmath.mpf(float(v)) for v in r)
            c, s = mpmath.cos(th), mpmath.sin(th)
            xt, yt = xr - x, yr - y
            for j, e in enumerate((c * xt + s * yt, c * yt - s * xt, (thr - th) + mpmath.mpf(float(k)) * two_pi)):
                h = float(e)
                hi[i, j] = h
                lo[i, j] = float(e - h) if math.isfinite(h) else 0.0
                over[i, j] = abs(e) > lim
                edge[i, j] = abs(abs(e) - lim) <= lim * mpmath.mpf(1e-9)
    a = np.abs(rows)
    with np.errstate(over="ignore"):
        sp_ = np.minimum(a[:, 0] + a[:, 1] + a[:, 3] + a[:, 4], np.finfo(float).max)
        sh = np.minimum(a[:, 2] + a[:, 5] + 2 * math.pi * np.abs(n), np.finfo(float).max)
    return dict(hi=hi, lo=lo, over=over, edge=edge, scale=np.column_stack([sp_, sp_, sh]))
