"""The numeric form of the control law (9) that every back-end prints.

    V = vr cos(e3) + k1 tanh(e1)
    W = wr + lam vr g(e1, e2) sinc(e3) + k2 tanh(e3),   g = df/de2

For a radial f = F(s), s = |(e1, e2)|, g = F'(s) e2/s, and g is evaluated in
one of three regions of m = max(|e1|, |e2|), each with a form that neither
overflows nor cancels there:

* tiny   (0 < m < TINY): F'(s) is replaced by the leading term a s**j of its
  series at 0 (the next term is below 2^-60 (float 2^-30) relative there), s**j = m**j r**j
  with r = sqrt(1 + q**2), q = min/m, and e2/s = (e2/m)/r;
* mid    (TINY <= m <= FAR): g = e2 H(rho) with rho = e1**2 + e2**2 and
  H(rho) = F'(s)/s written in rho (no square root of rho for smooth F);
  where that form cancels as rho -> 0, its Taylor polynomial below a cut
  (`near_branch`);
* far    (m > FAR): t = 1/s = (1/m)/r and g = t**k D(t) (e2/m)/r with
  D(t) t**k = F'(1/t) (the verifier's `tail_form`), k the order of F'(1/t)
  at t = 0, so that t**k, which may underflow (k > 0) or overflow (k < 0),
  enters the product as k factors 1/m, 1/r (or -k factors m, r).

m == 0 gives g = 0 (F'(0+) = 0 for a design with P1).  Piecewise profiles keep
their branch structure in each region (conditions on rho or on t).  The term
lam vr g sinc(e3) is a product of several factors, multiplied by the back-ends
with a guard against an intermediate overflow or underflow (`factors`).

`stabilize` removes the cancellation of sqrt(P) - Q (Q > 0), which would lose
every digit of sqrt(4 rho + 1) - 1 for small rho: it becomes (P - Q**2)/(sqrt(P) + Q).

A design that is not radial (only generated with force=True) gets the plain
derivative g = df/de2 (with SymPy's tanh rewriting), evaluated as written."""
from __future__ import annotations

import contextlib
import math
from dataclasses import dataclass, field
from fractions import Fraction

import sympy as sp
from sympy.codegen.cfunctions import expm1, log1p

from .. import e2 as E2
from ..profile import S
from ..timeouts import attempt
from ..univariate import T, prepare, tail_form

RHO = sp.Symbol("rho", positive=True)
#: log t = -log s on the tail, computed from the scaled norm as -(log m + log1p(q**2)/2)
LT = sp.Symbol("lt", negative=True)
#: 1/t = s on the tail, computed as min(1/t, largest finite number): beyond the
#: range (s up to sqrt(2) times it) a saturated tanh(1/t), x/cosh(x)**2, ... keeps
#: its limit instead of inf/inf (the validation checks s near that end)
ST = sp.Symbol("st", positive=True)

#: Region switches on m = max(|e1|, |e2|), per precision.  TINY keeps
#: rho >= TINY**2 a normal number; FAR keeps every mid-region form far from
#: overflow (rho <= 2 FAR**2) and makes t <= 1/FAR small in the tail forms.
THRESHOLDS = {"double": (1e-100, 1e4), "float": (1e-12, 1e4)}

#: The careful path passes a sin(e3)/e3 below the normal range (|e3| near the
#: largest number: digits lost) as sin(e3) 2^S/e3 and multiplies 2^-S in by
#: exponents (`prod_slow`): exact, and normal since |sin(x)| >= SIN_MIN for
#: every x of the type with |x| >= the series cut (doubles: Kahan/McDonald;
#: floats: 3.2e-9, at x = 1.5458358e29, by enumeration of all floats >= 2^-6).
SINC_SHIFT = {"double": 512, "float": 100}
SIN_MIN = {"double": "2^-61", "float": "2^-28.2"}


def split_boundary(b, precision: str = "double") -> tuple[float, sp.Float]:
    """(bh, bl): the boundary b of a Piecewise branch in rho rounded to the
    type, and b - bh to 40 digits, so that bh + bl is b to about twice the
    type's precision: what each back-end's exact branch test compares
    e1^2 + e2^2 with (`rho_minus_b`, the C code's `rho_cmp`)."""
    import numpy as np
    exact = sp.N(b, 80)
    hi = float(exact) if precision == "double" else float(np.float32(float(exact)))
    return hi, sp.N(exact - sp.Rational(hi), 40)


def rho_minus_b(e1, e2, bh, bl, split=134217729.0, opaque=lambda s: s):
    """e1^2 + e2^2 - (bh + bl) without the rounding of rho (its sign is
    exact unless |rho - b| is below about 2^-100 rho), in any arithmetic
    that rounds like the type: numpy arrays of doubles or floats, CasADi
    SX.  Dekker's exact squares (`split` = 2^ceil(p/2) + 1 for p bits) and
    TwoSum: the C code's `rho_cmp` without fma.  `opaque(p1 + p2)` keeps a
    symbolic back-end from rewriting (p1 + p2) - p1 as p2, which would undo
    TwoSum (CasADi does)."""
    def square(a):
        p, c = a * a, split * a
        hi = c - (c - a)
        lo = a - hi
        return p, ((hi * hi - p) + 2 * hi * lo) + lo * lo
    (p1, q1), (p2, q2) = square(e1), square(e2)
    s = opaque(p1 + p2)
    z = s - p1
    return (s - bh) + ((((p1 - (s - z)) + (p2 - z)) + q1 + q2) - bl)


def _thin(cond) -> bool:
    """The condition holds on a set without inner points: an equation, an
    And with one, an Or of such."""
    if isinstance(cond, sp.Eq):
        return True
    if isinstance(cond, sp.And):
        return any(_thin(c) for c in cond.args)
    return isinstance(cond, sp.Or) and all(_thin(c) for c in cond.args)


def partial_e2(f: sp.Expr) -> sp.Expr:
    """g = df/de2 of a C^1 f (P1 proved): SymPy's `diff`, branch by branch,
    after leaving out the Piecewise branches taken on thin sets only (a
    value on a circle, Eq(rho, 1), or at the origin).  There df/de2 is the
    limit of its values around (f is C^1), not the derivative of that
    branch's formula, which SymPy's branch-wise diff would give (0 for a
    constant; red team 19)."""
    def keep(pw):
        return sp.Piecewise(*[(e, c) for e, c in pw.args if not _thin(c)])
    return sp.diff(f.replace(lambda x: isinstance(x, sp.Piecewise), keep), E2)


@dataclass
class Branch:
    """expr holds for lo < x < hi (x is rho or t); `hi_closed` says whether
    x = hi belongs to this branch.  lo/hi are exact SymPy numbers (0 and oo
    at the ends of the region variable's range)."""
    lo: sp.Expr
    hi: sp.Expr
    hi_closed: bool
    expr: sp.Expr
    k: int = 0                 # far region: power of t split off the expression
    dropped: sp.Expr = sp.S.Zero   # far region: terms of F'(1/t)/t**k left out (`split_vanishing`)
    bound: sp.Expr = sp.S.Zero     # near branch: |H - expr| <= bound (its Taylor remainder, `near_branch`)

    @property
    def lo_float(self) -> float:
        return float(self.lo)

    @property
    def hi_float(self) -> float:
        return math.inf if self.hi == sp.oo else float(self.hi)


@dataclass
class LawModel:
    stem: str
    name: str
    radial: bool
    params: dict                          # name -> exact SymPy number
    kf_upper: Fraction | None              # certified upper bound (None: unbounded/unknown)
    kf_text: str                           # how the verifier states kf
    reasons: list = field(default_factory=list)   # why not verified (empty: verified)
    tiny: tuple | None = None              # (a, j): F'(s) ~ a s**j as s -> 0+
    tiny_source: sp.Expr | None = None     # F'(s) on the first piece (for the series' remainder)
    mid: list = field(default_factory=list)        # Branches in rho, g = e2 H(rho)
    far: list = field(default_factory=list)        # Branches in t, F'(1/t) = t**k D(t)
    general: sp.Expr | None = None         # non-radial: df/de2 in e1, e2
    notes: list = field(default_factory=list)      # numerical choices, for the banner
    thresholds: dict = field(default_factory=lambda: dict(THRESHOLDS))   # precision -> (TINY, FAR)
    accuracy: dict = field(default_factory=dict)   # precision -> accuracy.Accuracy (set by codegen.build)
    no_float: str | None = None    # why the C code has no float variant (set by codegen.build), else None
    float_blocked: str | None = None   # why the law has no accurate float form (`near_branch`), else None
    near_missing: str | None = None    # the double form cancels near 0 and `near_branch` found no polynomial

    @property
    def verified(self) -> bool:
        return not self.reasons

    @property
    def bound_kf(self) -> Fraction | None:
        """kf_upper when bound (10) rests on it: a verified design and a
        certified bound (the generated code clamps to it, the validation
        checks it); None otherwise."""
        return self.kf_upper if self.verified else None


# --------------------------------------------------------------------------
# rewriting

def stabilize(expr: sp.Expr) -> sp.Expr:
    """Rewrite every sum a + b of one square-root term a and a rest b of the
    opposite sign (by SymPy's assumptions, variables being positive; b free
    of square roots) as (a**2 - b**2)/(a - b): the same function, without the
    cancellation when |a| ~ |b| (sqrt(4 rho + 1) - 1 -> 4 rho/(sqrt(4 rho + 1) + 1),
    2 rho + 2 - 2 sqrt(rho + 1) -> (4 rho**2 + 4 rho)/(2 rho + 2 + 2 sqrt(rho + 1)))."""
    def has_root(e):
        return any(isinstance(p, sp.Pow) and p.exp == sp.Rational(1, 2) for p in sp.preorder_traversal(e))

    def fix(node):
        if not isinstance(node, sp.Add):
            return node
        roots = [a for a in node.args
                 if any(isinstance(f, sp.Pow) and f.exp == sp.Rational(1, 2) for f in sp.Mul.make_args(a))]
        if len(roots) != 1:
            return node
        a = roots[0]
        b = node - a
        if has_root(b) or not ((a.is_positive and b.is_negative) or (a.is_negative and b.is_positive)):
            return node
        if a.is_negative and not _cancels_at_zero(a, node):
            return node       # -sqrt(P) + Q: only where the two cancel (as rho -> 0 or t -> 0)
        num = sp.expand(a ** 2 - b ** 2)
        if num == 0:
            return node
        return num / (a - b)
    return sp.bottom_up(expr, fix)


def _cancels_at_zero(a, total) -> bool:
    """Does the sum `total` (one of whose terms is a) vanish to a higher order
    than a as its variable tends to 0+?"""
    syms = list(total.free_symbols)
    if len(syms) != 1:
        return False
    la, lt = _leading(a, syms[0]), _leading(total, syms[0])
    return la is not None and lt is not None and lt[1] > la[1]


def use_log1p(expr: sp.Expr) -> sp.Expr:
    """log(1 + X) -> log1p(X) and c exp(X) - c -> c expm1(X) (c of either
    sign: 1 - exp(-x) is -expm1(-x)): the same
    function, accurate when X is small (log(1 + rho) loses every digit of rho
    below 1e-16).  (log(c + X) with c != 1 is left alone: it cancels only
    where c + X ~ 1, and log c + log1p(X/c) would cancel there too.)"""
    def fix(node):
        if isinstance(node, sp.log) and isinstance(node.args[0], sp.Add):
            c, rest = node.args[0].as_coeff_Add()
            if c == 1 and rest != 0:
                return log1p(rest)
        if isinstance(node, sp.Add):
            c, rest = node.as_coeff_Add()
            k, ex = rest.as_coeff_Mul()         # (1, exp(X)) for exp(X) itself
            if c != 0 and isinstance(ex, sp.exp) and k == -c:
                return k * expm1(ex.args[0])
        return node
    return sp.bottom_up(expr, fix)


def _polish(expr: sp.Expr) -> sp.Expr:
    return use_log1p(stabilize(prepare(expr)))


def _to_infinity(x, var) -> bool:
    lead = _leading(x, var)
    return lead is not None and lead[1] < 0 and lead[0].is_positive


def split_logs(expr: sp.Expr, var=T) -> sp.Expr:
    """Tail forms without t**k overflowing or underflowing inside a
    logarithm: asinh(X) and acosh(X) with X -> +oo as t -> 0+ become
    log(X) + log(1 + sqrt(1 +- 1/X**2)); every log is expanded over its
    products, quotients and powers (log((t**2 + 1)/t**2) -> log(t**2 + 1) - 2 log t)
    and log t becomes the symbol LT, which the back-ends compute from the
    scaled norm.  The same function for t > 0."""
    def hyper(node):
        if isinstance(node, (sp.asinh, sp.acosh)) and node.args[0].has(var) and _to_infinity(node.args[0], var):
            x = node.args[0]
            sign = 1 if isinstance(node, sp.asinh) else -1
            return sp.log(x) + sp.log(1 + sp.sqrt(1 + sign * x ** -2))
        return node
    def expand(node):
        split = sp.expand_log(sp.log(sp.factor_terms(sp.together(node.args[0]))), force=True)
        return node if split.has(sp.I) else split      # a negative factor: keep the log whole
    out = sp.bottom_up(expr, hyper)
    out = out.replace(lambda e: isinstance(e, sp.log) and e.has(var), expand)
    return out.subs(sp.log(var), LT)


def _t_power(expr) -> int:
    """The integer power of T among the factors of a product (0 if none)."""
    j = 0
    for f in sp.Mul.make_args(expr):
        base, ex = f.as_base_exp()
        if base == T and ex.is_Integer:
            j += int(ex)
    return j


def _polish_tail(expr: sp.Expr) -> sp.Expr:
    """The tail form for printing; a power 1/t^k that is left (inside exp(-1/t^2),
    a sum, ...: `absorb_t_powers` clears those of products) becomes s^k, which
    at most overflows to inf where t^k would underflow to 0 and be divided by."""
    polished = absorb_t_powers(use_log1p(stabilize(split_logs(prepare(expr)))))
    return polished.xreplace({p: ST ** -p.exp for p in polished.atoms(sp.Pow)
                              if p.base == T and p.exp.is_Integer and p.exp < 0})


def absorb_t_powers(expr: sp.Expr, var=T) -> sp.Expr:
    """Divide a product's negative power of t into its polynomial factors:
    (2 - 3t)^2 / t^2 becomes (2/t - 3)^2, so that t^2, which underflows to 0
    far out, is never formed and divided by (the 1/t left is s, computed
    finite).  The same function for t > 0."""
    def fix(node):
        if not isinstance(node, sp.Mul):
            return node
        k = -_t_power(node)
        if k <= 0:
            return node
        out = []
        for f in sp.Mul.make_args(node):
            base, ex = f.as_base_exp()
            if base == var:
                continue
            if k > 0 and ex.is_Integer and ex > 0 and base.is_polynomial(var) and sp.degree(base, var) >= 1:
                use = min(k, int(ex))
                out.append(sp.expand(base / var) ** use * base ** (ex - use))
                k -= use
            else:
                out.append(f)
        return sp.Mul(*out) * var ** -k
    return sp.bottom_up(expr, fix)


def plain(expr: sp.Expr) -> sp.Expr:
    """expr with log1p/expm1 written as log(1 + x)/exp(x) - 1 (the same
    function, for the interval evaluator)."""
    return expr.replace(lambda e: isinstance(e, log1p), lambda e: sp.log(1 + e.args[0])).replace(
        lambda e: isinstance(e, expm1), lambda e: sp.exp(e.args[0]) - 1)


def _leading(expr: sp.Expr, var: sp.Symbol, at_zero=True):
    """(a, j) with expr ~ a var**j as var -> 0+ (j an integer), or None."""
    try:
        lead = sp.nsimplify(expr.as_leading_term(var)) if expr.has(sp.Float) else expr.as_leading_term(var)
    except Exception:  # noqa: BLE001 - no expansion: caller falls back
        return None
    a, j = lead.as_coeff_exponent(var)
    if a.free_symbols or not j.is_integer or a == 0:
        return None
    return a, int(j)


def _next_term(expr, var, a, j):
    """(c, d) with |next term / leading term| = c var**d, from the series
    ((0, 1) if there is none, None if it cannot be found)."""
    try:
        ser = sp.series(expr, var, 0, j + 4).removeO()
    except Exception:  # noqa: BLE001
        return None
    rest = sp.expand(ser - a * var ** j)
    if rest == 0:
        return 0.0, 1
    b, i = _leading(rest, var) or (None, None)
    if b is None or i <= j:
        return None
    return abs(float(b / a)), i - j


# --------------------------------------------------------------------------
# the model

def _kf_fraction(report) -> tuple[Fraction | None, str]:
    """A rational upper bound of the certified kf and how to state kf."""
    kf = getattr(report, "kf", None) if report is not None else None
    if kf is None or kf.upper is None:
        return None, kf.show() if kf is not None else "not certified"
    if getattr(report, "kernel_only", False) and "kf" in (report.kernel or {}).get("search", []):
        return None, f"{kf.show()}, the search's: the kernel did not re-check it"     # as the gain checks
    upper = kf.upper
    if isinstance(upper, Fraction):
        return upper, kf.show()
    upper = sp.sympify(upper)
    if upper.is_Rational:
        return Fraction(int(upper.p), int(upper.q)), kf.show()
    # an exact irrational value: its 60-digit decimal plus a margin far above the error
    approx = Fraction(str(sp.N(upper, 60)))
    return approx + abs(approx) * Fraction(1, 10 ** 50) + Fraction(1, 10 ** 300), kf.show()


def _same(a, b) -> bool:
    """a and b are the same formula, as far as SymPy's simplify shows within
    2 s (it ran for minutes on a - b with log(1 + ((s - 100)/100)^2), raised
    to the 5000th power): False only costs a branch closed at the other end,
    and at a join of a C^1 law both formulas agree there."""
    return a == b or attempt(lambda: sp.simplify(a - b) == 0, 2.0, default=False)


def _branches(pieces, at_point, to_var, reverse):
    """Branches for the pieces in a region variable x = to_var(s), which
    increases with s (rho) or decreases (t); returned in increasing x, each
    closed at its upper end when F takes that piece's formula there."""
    out = []
    for p in pieces:
        if reverse:
            lo, hi, end = to_var(p.hi), to_var(p.lo), p.lo
        else:
            lo, hi, end = to_var(p.lo), to_var(p.hi), p.hi
        closed = end in at_point and end not in (0, sp.oo) and _same(at_point[end], p.expr)
        out.append((lo, hi, closed, p))
    return out[::-1] if reverse else out


def build_model(design, analysis, report=None, precisions=("double", "float")) -> LawModel:
    """The numeric model of the law for one design (see the module doc), for
    the C variants of `precisions` (the thresholds of the others left out)."""
    kf_upper, kf_text = _kf_fraction(report)
    model = LawModel(stem=design.stem, name=design.name, radial=False, params=dict(design.params),
                     kf_upper=kf_upper, kf_text=kf_text)
    profile = None
    if analysis.p4.proved:
        try:
            profile = analysis.profile
        except Exception:  # noqa: BLE001 - split failed: treat as general
            profile = None
    if profile is None:
        model.general = prepare(partial_e2(design.f))
        model.notes.append("f is not known to be radial: g = df/de2 is evaluated as derived, "
                           "without the overflow-safe radial forms")
        return model
    model.radial = True
    pieces = profile.pieces
    at_point = profile.at_point

    # mid region: H(rho) = F'(s)/s in rho
    tiny, far = THRESHOLDS["double"]
    for lo, hi, closed, p in _branches(pieces, at_point, lambda b: b ** 2, reverse=False):
        if float(hi) < tiny ** 2 or float(lo) > 2 * far ** 2:
            continue
        dF = prepare(sp.diff(p.expr, S))
        H = sp.powsimp(sp.expand_power_base((dF / S).subs(S, sp.sqrt(RHO))))
        H = _polish(sp.cancel(H) if not H.has(sp.Function) else H)
        model.mid.append(Branch(lo, hi, closed, H))

    dF0 = prepare(sp.diff(pieces[0].expr, S))
    if model.mid and model.mid[0].lo == 0:
        near_branch(model, dF0, precisions)
    model.thresholds = {p: th for p, th in derive_thresholds(model.mid).items() if p in precisions}

    # tiny region: leading term of F' on the first piece
    lead = _leading(dF0, S)
    tiny_ok = lead is not None and float(pieces[0].hi) > 2 * max(th[0] for th in model.thresholds.values()) * 2
    if tiny_ok:
        a, j = lead
        # the next term of the series is below 2^-60 (double) / 2^-30 (float) of the leading one
        nxt = _next_term(dF0, S, a, j) if j >= 0 else None
        model.thresholds = {prec: _series_tiny(nxt, prec, th, model.mid) for prec, th in model.thresholds.items()}
        tiny_ok = nxt is not None and all(nxt[0] * (math.sqrt(2) * th[0]) ** nxt[1] < SERIES_REL[prec]
                                          for prec, th in model.thresholds.items())
    if tiny_ok:
        model.tiny, model.tiny_source = (a, j), dF0
    else:
        model.notes.append("no usable series of F' at 0: the mid-region form is used down to s = 0")

    # far region: F'(1/t) = t**k D(t)
    far = min(th[1] for th in model.thresholds.values())
    for lo, hi, closed, p in _branches(
            pieces, at_point, lambda b: sp.Integer(0) if b == sp.oo else (sp.oo if b == 0 else 1 / b), reverse=True):
        if float(lo) > 1 / far:
            continue
        D = tail_form(prepare(sp.diff(p.expr, S)), S)
        t_far = min(float(hi), 1 / far)
        cut = split_vanishing(D, t_far) if lo == 0 else None
        if cut is None:
            model.far.append(_far_branch(lo, hi, closed, D))
        elif cut[0] == sp.Rational(t_far):         # left out on all of (0, t_far]
            model.far.append(_far_branch(lo, hi, closed, *cut[1:]))
        else:
            model.far += [_far_branch(lo, cut[0], True, *cut[1:]), _far_branch(cut[0], hi, closed, D)]
    return model


def _far_branch(lo, hi, closed, D, dropped=sp.S.Zero) -> Branch:
    """The far-region branch F'(1/t) = t**k D(t) (+ the terms `dropped`) for lo < t < hi."""
    k = 0
    lead = _leading(D, T)
    if lead is not None and lead[1] != 0:
        cand = sp.cancel(D / T ** lead[1]) if not D.has(sp.Function) else \
            attempt(lambda: sp.simplify(D / T ** lead[1]), 5.0, default=sp.nan)     # (nan: no split)
        if not cand.has(sp.zoo, sp.nan) and cand.subs(T, 0).is_finite and cand.subs(T, 0) != 0:
            D, k = cand, lead[1]
    D = _polish_tail(D)
    if k == 0:
        # no series at t = 0 (log t in D): still split off a factor t**j of the
        # numerator or denominator, so that D itself does not underflow with t
        num, den = sp.fraction(sp.factor_terms(D))
        j = _t_power(num) - _t_power(den)
        if j != 0:
            D, k = D / T ** j, j
    return Branch(lo, hi, closed, D, k, dropped / T ** k)


def split_vanishing(D: sp.Expr, t_far: float):
    """(t0, kept, dropped), D = kept + dropped, where the terms `dropped` of
    the tail form D(t) (those with an exp, cosh or sinh that vanish faster
    than t^40 as t -> 0+: exp(-1/t^2)/t^3, 1/(t cosh(1/t^2)^2)) are below
    2^-80 of the others for 0 < t <= t0 by Arb on boxes [2^-(i+4), 2^-i]
    down to 2^-1080 (below every t a double takes), t0 <= t_far as large as
    that allows; None if there is no such t0.  Printed, such a term is
    P exp(-X) with exp(-X) = 0 and P overflowing as s nears the largest
    double: inf * 0 = NaN.  Left out, it is part of the error that
    `accuracy` bounds box by box."""
    from ..kernel.arb import Undefined, evaluate

    def vanishing(term):
        try:
            return term.has(sp.exp, sp.cosh, sp.sinh) and sp.limit(term / T ** 40, T, 0, "+") == 0
        except (NotImplementedError, ValueError, TypeError):
            return False

    def small(a, b):                            # |dropped| < 2^-80 |kept| on [a, b]
        try:
            d, k = (evaluate(e, T, a, b, bits=128) for e in (dropped, kept))
        except (Undefined, ValueError, TypeError, ZeroDivisionError):
            return False
        k_min = k.lo if k.positive() else -k.hi if k.negative() else None
        return k_min is not None and bool(abs(d.lo).max(abs(d.hi)) < k_min * 2 ** -80)
    terms = sp.Add.make_args(sp.expand(D, deep=False, power_base=False, power_exp=False, log=False,
                                       multinomial=False))
    gone = [vanishing(a) for a in terms]       # (one limit per term)
    dropped = sp.Add(*[a for a, g in zip(terms, gone) if g])
    kept = sp.Add(*[a for a, g in zip(terms, gone) if not g])
    # 1/cosh(X)^n = (2 exp(-X)/(1 + exp(-2X)))^n (sinh: 1 - exp(-2X)), so that Arb
    # never forms exp(X) for X near 1/t^2 = 2^2000 (the same function: only bounded)
    dropped = dropped.replace(lambda p: p.is_Pow and isinstance(p.base, (sp.cosh, sp.sinh)) and p.exp.is_negative,
                              lambda p: (2 * sp.exp(-p.base.args[0]) / (
                                  1 + (1 if isinstance(p.base, sp.cosh) else -1) * sp.exp(-2 * p.base.args[0])))
                              ** -p.exp)
    if dropped == 0 or kept == 0:
        return None
    for j in range(161):
        t0 = sp.Rational(t_far * 2.0 ** (-j / 4))
        if small(t0, t0):
            i = math.ceil(-math.log2(t0))
            boxes = [(sp.Rational(1, 2 ** i), t0)] + [(sp.Rational(1, 2 ** (n + 4)), sp.Rational(1, 2 ** n))
                                                     for n in range(i, 1080, 4)]
            return (t0, kept, dropped) if all(small(a, b) for a, b in boxes) else None
    return None


SERIES_REL = {"double": 2.0 ** -60, "float": 2.0 ** -30}
FORMAT = {"double": (2.2250738585072014e-308, 1.7976931348623157e308, 53),
          "float": (1.1754943508222875e-38, 3.4028234663852886e38, 24)}
#: the lowest TINY `_series_tiny` takes: rho >= TINY**2 stays 2^60 (float 2^20) above the smallest normal number
TINY_FLOOR = {"double": 1e-142, "float": 1e-15}


def _series_tiny(next_term, prec, thresholds, mid):
    """(TINY, FAR) with TINY lowered by decades, to TINY_FLOOR at most, while
    the series' next term (`next_term` = (c, d): c s**d of the leading one)
    is not below SERIES_REL at sqrt(2) TINY (F' = tanh(1e8 s): 7e-9 at the
    float default 1e-12) and interval arithmetic shows the mid-region forms
    neither overflow nor underflow on the range added (`_magnitude_risks`)."""
    tiny, far = thresholds
    if next_term is None:
        return tiny, far
    c, d = next_term
    while c * (math.sqrt(2) * tiny) ** d >= SERIES_REL[prec] and tiny / 10 >= TINY_FLOOR[prec]:
        lower = tiny / 10
        if any(any(_magnitude_risks(_risk_form(br), max(lower ** 2, br.lo_float), min(tiny ** 2, br.hi_float),
                                    FORMAT[prec]))
               for br in mid if br.lo_float < tiny ** 2):
            break
        tiny = lower
    return tiny, far


#: The near branch (`near_branch`): where the mid form cancels at 0, it must
#: reach NEAR_GOAL (the validation allows 1e-12 (double) / 1e-5 (float) of the
#: result) from the cut up, and the Taylor remainder, relative to H, NEAR_TRUNC below it.
NEAR_GOAL = {"double": 2.0 ** -44, "float": 2.0 ** -18}
NEAR_TRUNC = {"double": 2.0 ** -52, "float": 2.0 ** -26}
#: longest Taylor polynomial of F' (terms in s) tried, and the balls covering [0, sqrt(cut)] for its remainder
NEAR_TERMS, NEAR_BALLS = 128, 32


def _taylor(expr, var, x):
    """expr as a power series in var about the ball x (flint's arb_series,
    flint.ctx.cap terms): coefficient i encloses expr^(i)(y)/i! for every y
    in x; with x None, about 0 exactly (fmpq_series: rational constants and
    the functions whose value at the series' first term is rational only).
    ValueError for a construct it does not take or a value it cannot bound
    (a division by a series whose first term may be 0)."""
    from flint import arb, arb_series, fmpq, fmpq_series

    exact = x is None
    series = fmpq_series if exact else arb_series

    def const(q):
        return series([fmpq(int(q.p), int(q.q)) if exact else arb(fmpq(int(q.p), int(q.q)))])

    def go(e):
        if e == var:
            return series([0 if exact else x, 1])
        if e.is_Rational or e.is_Float:
            return const(sp.Rational(e))
        if (e is sp.pi or e is sp.E) and not exact:
            return series([arb.pi() if e is sp.pi else arb(1).exp()])
        args = [go(a) for a in e.args]
        if e.is_Add or e.is_Mul:
            out = args[0]
            for a in args[1:]:
                out = out + a if e.is_Add else out * a
            return out
        if e.is_Pow:
            b, p = args[0], e.exp
            if p.is_Integer:
                out = const(sp.Integer(1))
                for _ in range(abs(int(p))):
                    out = out * b
                return 1 / out if p < 0 else out
            if p == sp.Rational(1, 2):
                return b.sqrt()
            if p == -sp.Rational(1, 2):
                return b.rsqrt()
            if p.is_Rational:
                return (b.log() * const(p)).exp()
        names = {sp.exp: "exp", sp.log: "log", sp.sin: "sin", sp.cos: "cos", sp.atan: "atan", sp.erf: "erf",
                 sp.tanh: "tanh", sp.sinh: "sinh", sp.cosh: "cosh", sp.asinh: "asinh"}
        name = names.get(type(e))
        if name is not None and len(args) == 1:
            a = args[0]
            if exact or name not in ("tanh", "sinh", "cosh", "asinh"):
                if not hasattr(a, name):
                    raise ValueError(f"no exact series for {name}")
                return getattr(a, name)()
            if name == "tanh":
                return 1 - 2 / ((2 * a).exp() + 1)
            if name == "asinh":
                return (a + (a * a + 1).sqrt()).log()
            return ((a.exp() - (-a).exp()) if name == "sinh" else (a.exp() + (-a).exp())) * arb(0.5)
        raise ValueError(f"no series for {type(e).__name__}")
    try:
        out = go(expr)
    except ZeroDivisionError as exc:
        raise ValueError(str(exc)) from None
    if not exact and not all(c.is_finite() for c in out.coeffs()):
        raise ValueError("a coefficient is not bounded")
    return out


@contextlib.contextmanager
def series_terms(n: int):
    """`with series_terms(n):` flint's power series length (ctx.cap) is n,
    restored after (as `kernel.arb.precision` does for Arb's precision)."""
    import flint
    saved = flint.ctx.cap
    flint.ctx.cap = n
    try:
        yield
    finally:
        flint.ctx.cap = saved


def _taylor_polynomial(dF, cut, rel):
    """(P, bound, degree) for 0 < rho <= cut, or None: P the Taylor polynomial
    of H = F'(s)/s in rho (Horner form), from the series of F' at 0 with
    coefficients enclosed in Arb (F' odd: its even coefficients enclose 0,
    those below the leading one are exactly 0), and `bound` >= |H - P| as a
    function of rho: the coefficients' enclosure widths (and the even ones)
    plus Lagrange's remainder M s^K, M >= |F'^(K)(y)/K!| over balls covering
    [0, sqrt(cut) (1 + 2^-40)].  K grows until the bound at sqrt(cut) is below `rel` of
    the polynomial there."""
    from flint import arb, fmpq

    from ..kernel.arb import precision
    cut_q = sp.Rational(cut)
    with precision(256):
        # s up to sqrt(cut), and a little beyond: a rounded rho may pick this branch just above the cut
        d = (arb(fmpq(int(cut_q.p), int(cut_q.q))).sqrt() * (1 + arb(2) ** -40)).abs_upper()
        dq = _sup(d)
        balls = [arb(d * (2 * i + 1) / (2 * NEAR_BALLS), d / (2 * NEAR_BALLS)) for i in range(NEAR_BALLS)]
        for K in range(16, NEAR_TERMS + 1, 8):
            try:
                with series_terms(K + 1):
                    remainder = [_taylor(dF, S, b).coeffs() for b in balls]
                    try:                # exact coefficients where flint has them: an exact 0 is decided
                        c = [arb(q) for q in _taylor(dF, S, None).coeffs()]
                    except (ValueError, TypeError):
                        c = _taylor(dF, S, arb(0)).coeffs()
            except ValueError:
                return None
            c += [arb(0)] * (K + 1 - len(c))
            j = next((i for i, ci in enumerate(c[:K]) if not ci.is_zero()), None)
            if j is None or j % 2 == 0 or not abs(c[j]) > 0 or any(abs(ci) > 0 for ci in c[j + 1:K:2]):
                return None             # no leading term, F'(0) != 0, or F' not odd
            kept = {i: sp.Rational(c[i].mid().str(30, radius=False, more=False)) for i in range(j, K, 2)}
            width = {i: _sup(c[i] - arb(fmpq(int(q.p), int(q.q)))) for i, q in kept.items()}
            width.update({i: _sup(c[i]) for i in range(j + 1, K, 2)})
            width[K] = max(_sup(r[K]) if len(r) > K else sp.S.Zero for r in remainder)
            at_d = abs(sum(q * dq ** i for i, q in kept.items()))     # |P| at the cut (`accuracy` checks every box)
            if sum(w * dq ** i for i, w in width.items()) < at_d * sp.Rational(rel):
                break
        else:
            return None
    order = sorted(kept)
    poly = kept[order[-1]]
    for i in order[-2::-1]:
        poly = kept[i] + RHO * poly
    poly = RHO ** ((j - 1) // 2) * poly
    bound = sp.Add(*[w * RHO ** sp.Rational(i - 1, 2) for i, w in width.items() if w != 0])
    return poly, bound, K - 1


def _sup(x) -> sp.Rational:
    """sup |x| over an arb ball, exactly (|midpoint| + radius, binary numbers)."""
    if not x.is_finite():
        return sp.oo
    (m, e), (n, f) = x.mid().man_exp(), x.rad().man_exp()
    return abs(sp.Integer(int(m)) * sp.Integer(2) ** int(e)) + sp.Integer(int(n)) * sp.Integer(2) ** int(f)


def near_branch(model: LawModel, dF, precisions) -> None:
    """Where the mid form H of the first piece loses digits as rho -> 0
    (1/(1 + rho) - exp(-rho), atan(s)/s - 1/(1 + rho): a difference of
    terms near 1), split its branch at a cut: below it, H is its Taylor
    polynomial (`_taylor_polynomial`, remainder `bound` for `accuracy`).
    It is needed when a sum of the mid form loses more than 2^10 in
    magnitude at rho = 2^-60 (`accuracy.cancels_at_zero`); the cut, per
    precision, is then the least rho = 2^-k from which the mid form is
    within NEAR_GOAL on every box [x, 2x] (`accuracy.accurate_from`).
    The polynomial, which every precision uses, must reach NEAR_TRUNC of
    the strictest at the largest cut.  When only float cannot have one (it
    needs a larger cut, beyond the series' reach), the model says so
    (`float_blocked`): the code is then written without the float variant."""
    from .accuracy import accurate_from, cancels_at_zero      # (accuracy imports this module)
    first = model.mid[0]
    if not cancels_at_zero(first.expr):
        return
    top = min(first.hi_float / 2, 2.0 ** 26)     # (a scaled law, atan(s/100): its cancellation reaches rho ~ 10^4)
    needed = {p: accurate_from(first.expr, p, top, NEAR_GOAL[p]) for p in precisions}

    def attempt(precs):                 # (the branch serves every precision: the remainder suits them all)
        if not precs or any(needed[p] is None for p in precs):
            return None
        cut = max(needed[p] for p in precs)
        poly = _taylor_polynomial(dF, cut, min(NEAR_TRUNC[p] for p in precisions))
        return None if poly is None else (cut, poly)
    found = attempt(list(needed))
    if found is None and "float" in needed:
        found = attempt([p for p in needed if p != "float"])
        if found is not None or "double" not in needed:
            model.float_blocked = "f' cancels near e = 0 beyond what a Taylor polynomial at 0 covers in float"
    if found is None:
        if "double" in needed:
            model.near_missing = ("df/de2 as written loses digits near e = 0, and no Taylor polynomial "
                                  "with a bounded remainder was found to replace it there")
        return
    cut, (poly, bound, degree) = found
    cut = sp.Rational(cut)
    model.mid[0:1] = [Branch(first.lo, cut, True, poly, bound=bound),
                      Branch(cut, first.hi, first.hi_closed, first.expr)]
    model.notes.append(f"for rho <= {float(cut):.6g}, where the form of df/de2 loses digits, it is its "
                       f"Taylor polynomial at 0 (degree {degree} in s; remainder bounded in Arb)")


def _risk_form(br: Branch) -> sp.Expr:
    """What `_magnitude_risks` walks for a mid branch: a near branch's
    polynomial rho^k (q + rho (...)) as rho^k q (whose rho^k may underflow),
    sparing the walk through its nested sums, a quadratic cost; their sizes
    are bounded box by box in `accuracy`."""
    if br.bound == 0:
        return br.expr
    factors = sp.Mul.make_args(br.expr)
    sums = [f for f in factors if f.is_Add]
    return sp.Mul(*[f for f in factors if not f.is_Add]) * (sums[0].as_coeff_Add()[0] if sums else 1)


def _magnitude_risks(expr, rho_lo, rho_hi, fmt):
    """(overflow, underflow) risk of evaluating expr in the format over
    [rho_lo, rho_hi], by interval arithmetic on every subexpression: some
    subexpression may exceed max/2^10, or a factor on a multiplicative path
    from the root (through products, powers and function values, not into
    the terms of a sum, where a small term is harmless) may fall below
    16 min_normal without being zero."""
    from ..interval import Interval, IntervalFunction, Undefined
    small, big, bits = fmt
    box = Interval.of(sp.Rational(rho_lo), sp.Rational(rho_hi))
    over = under = False

    def walk(node, on_path):
        nonlocal over, under
        if not node.has(RHO) or node.is_Atom:
            return
        try:
            val = IntervalFunction(plain(node), [RHO], "range", 64)(box)
        except (Undefined, ValueError, TypeError, NotImplementedError, ZeroDivisionError):
            return
        if not val.is_finite() or max(abs(val.lower_float()), abs(val.upper_float())) > big / 2 ** 10:
            over = True
        if on_path and not val.contains_zero() and min(abs(val.lower_float()), abs(val.upper_float())) < small * 16:
            under = True
        for a in node.args:
            walk(a, on_path and not isinstance(node, sp.Add))
    walk(expr, True)
    return over, under


def derive_thresholds(mid) -> dict:
    """Per precision, (TINY, FAR) for the mid-region forms: the defaults of
    THRESHOLDS, TINY raised and FAR lowered by powers of ten until interval
    arithmetic shows that no subexpression of H overflows, and no factor of
    H underflows, for rho in [TINY^2, 2 FAR^2] (log(1 + rho^5)/10: rho^5
    overflows float above rho ~ 5e7, so FAR_float = 1e3)."""
    out = {}
    for prec, (tiny, far) in THRESHOLDS.items():
        fmt = FORMAT[prec]
        lo_k, hi_k = 2 * round(math.log10(tiny)), 2 * round(math.log10(far))
        bad_low, bad_high = None, None
        for k in range(lo_k, hi_k + 1):     # decades [10^k, 10^(k+1)] of rho (the last one to 2 FAR^2)
            a, b = 10.0 ** k, (10.0 ** (k + 1) if k < hi_k else 2 * far ** 2)
            risky = False
            for br in mid:
                blo, bhi = br.lo_float, br.hi_float
                if bhi < a or blo > b:
                    continue
                over, under = _magnitude_risks(_risk_form(br), max(a, blo), min(b, bhi), fmt)
                risky = risky or over or under
            if risky and k < 0:
                bad_low = k
            if risky and k >= 0 and bad_high is None:
                bad_high = k
        if bad_low is not None:
            tiny = 10.0 ** math.ceil((bad_low + 1) / 2)
        if bad_high is not None:
            far = 10.0 ** math.floor((bad_high - math.log10(2)) / 2)
        out[prec] = (tiny, far)
    return out


def mid_h_bounds(model: LawModel, rho_lo: float, rho_hi: float, ratio: int = 16):
    """(lo, hi) with lo <= |H(rho)| <= hi for every rho in [rho_lo, rho_hi],
    H the mid-region form (all its branches), rigorously (interval
    arithmetic on subintervals [x, ratio x]); None when no such bound with
    lo > 0 and hi finite is found (H may vanish or be unbounded there).
    The fast path uses it to decide, before any libm call, that the products
    lam vr H stay within range."""
    from ..interval import Interval, IntervalFunction, Undefined

    if not model.radial or not model.mid:
        return None
    lo_all, hi_all = math.inf, 0.0
    cuts = [Fraction(rho_lo)]
    while cuts[-1] < Fraction(rho_hi):
        cuts.append(min(cuts[-1] * ratio, Fraction(rho_hi)))
    for br in model.mid:
        fn = IntervalFunction(plain(br.expr), [RHO], "range", 128)
        # the branch's ends, widened outwards by 1e-25 (they may be irrational)
        b_lo = Fraction(0) if br.lo == 0 else Fraction(str(sp.N(br.lo, 40))) * (1 - Fraction(1, 10 ** 25))
        b_hi = None if br.hi == sp.oo else Fraction(str(sp.N(br.hi, 40))) * (1 + Fraction(1, 10 ** 25))
        for a, b in zip(cuts, cuts[1:]):
            a2, b2 = max(a, b_lo), b if b_hi is None else min(b, b_hi)
            if a2 > b2:
                continue
            try:
                box = fn(Interval.of(sp.Rational(a2.numerator, a2.denominator),
                                     sp.Rational(b2.numerator, b2.denominator)))
            except Undefined:
                return None
            if box.contains_zero() or not box.is_finite():
                return None
            lo, hi = box.lower_float(), box.upper_float()
            mag_lo, mag_hi = (lo, hi) if lo > 0 else (-hi, -lo)
            lo_all, hi_all = min(lo_all, mag_lo), max(hi_all, mag_hi)
    if not (0 < lo_all <= hi_all < math.inf):
        return None
    return lo_all, hi_all
