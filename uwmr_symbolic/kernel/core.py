"""Theorems and the rules that alone can make them (LCF style).

A `Theorem` holds a `Claim` (canonical, JSON-able) plus the rule that made
it, its premises and the rule's data.  Its constructor demands a
module-private token: outside this module, the only way to obtain a Theorem
is to call one of the rule functions below, each of which re-checks its
premises and raises `KernelError` when one fails.  (Python cannot make the
token truly secret; the convention is that nothing outside `kernel/` touches
names starting with an underscore.)

Claim semantics (I: an interval of the real line, ends exact):
* sign:       for every x in I, E(x) is defined (real, finite) and
              want*E(x) > 0 (strict) or >= 0 (weak);
* identity:   for every x in I at which both sides are defined, lhs = rhs;
* value_sign: the exact real constant E has sign want (-1, 0 or 1);
* sup_upper:  E is defined on I and E(x) <= bound there (so sup_I E <= bound);
* sup_lower:  sup of E over the points of I where it is defined is >= bound
              (for every eps > 0 some x in I has E(x) > bound - eps);
* identity_plane: lhs(x, y) = rhs(x, y) where both are defined (var: (x, y));
* limit:      E -> other as x -> lo+, E defined on (lo, hi]: E continuous on
              [lo, hi] with E(lo) = other (`continuous_at_end`), or E(lo)
              undefined, a removable 0/0 (`limit_by_taylor`);
* limit_oo:   E is defined on some [X, oo) and E(x) -> other as x -> oo;
* continuous: E is defined and continuous at every point of (lo, hi), or
              of the plane when var is (x, y);
* pieces:     on each open interval between lo, the cut points listed in
              other and hi, E equals an expression defined and continuous
              on the interval's closure in (0, oo);
* diverges:   E is defined on [lo, oo) and E(x) -> +oo as x -> oo.

Assumptions a theorem rests on are named strings: "arb" (python-flint's
outward rounding), "sympy-core" (automatic evaluation, substitution, srepr),
"sympy-diff" (symbolic derivatives), "sympy-polys" (cancel, real-root isolation),
"sympy-simplify" (an identity that only `simplify` could show), "flint-polys"
(FLINT's exact arithmetic of polynomials over Q).
"""
from __future__ import annotations

import contextlib
import dataclasses
import functools
import json
from dataclasses import dataclass, field

import sympy as sp
from flint import arb, fmpq, fmpq_poly
from sympy.polys.rings import PolyRing
from sympy.printing.repr import ReprPrinter

from .arb import SIGN_BITS, Iv, Undefined, centered, evaluate
from .parse import ParseError, parse

_TOKEN = object()
RULES: dict = {}
OO = sp.oo


class KernelError(ValueError):
    """A rule's premise does not hold: no theorem is made."""


def _need(cond, msg):
    """Raise KernelError(msg) unless cond; msg may be a function making the
    text (so that printing large expressions costs nothing on success)."""
    if not cond:
        raise KernelError(msg() if callable(msg) else msg)


@dataclass(frozen=True)
class Claim:
    kind: str
    expr: str                   # srepr of E (identity: lhs)
    var: str = ""               # srepr of the variable ("" for constants)
    lo: str = ""                # srepr of the exact ends; hi may be "oo"
    hi: str = ""
    lo_open: bool = False
    hi_open: bool = False
    want: int = 0
    strict: bool = False
    other: str = ""             # identity: rhs; sup_*: the bound

    def to_json(self) -> dict:
        return {k: getattr(self, k) for k in self.__dataclass_fields__}

    # parsed views
    def e(self):
        return parse(self.expr)

    def x(self):
        return parse(self.var)

    def ends(self):
        return parse(self.lo), parse(self.hi)


@dataclass(frozen=True)
class Theorem:
    claim: Claim
    rule: str
    premises: tuple
    data: str                   # JSON of the rule's arguments
    assumptions: frozenset
    _token: object = field(default=None, repr=False, compare=False)

    def __post_init__(self):
        if self._token is not _TOKEN:
            raise KernelError("theorems are made only by kernel rules")
        object.__setattr__(self, "_token", None)    # so dataclasses.replace cannot forge one


def _s(e) -> str:
    return _srepr(_sym(e))


class _SharedRepr(ReprPrinter):
    """SymPy's srepr printer with each subtree printed once: SymPy objects
    are immutable, and since SymPy 1.13 equal (hence same-key) objects have
    the same srepr (Float(2) != Integer(2)).  The branches of a Piecewise
    share most of their terms (a chain of 16 joins: 0.4 s -> 0.05 s)."""
    def __init__(self):
        super().__init__()
        self.memo = {}

    def _print(self, expr, **kw):
        if kw or not isinstance(expr, sp.Basic):
            return super()._print(expr, **kw)
        if expr not in self.memo:
            if len(self.memo) > 200_000:
                self.memo.clear()
            self.memo[expr] = super()._print(expr)
        return self.memo[expr]


_PRINTER = _SharedRepr()
_srepr = _PRINTER.doprint


def _encode(v):
    if isinstance(v, sp.Basic):     # the text of what SymPy reads back (2 (a + b) built undistributed reads 2 a + 2 b)
        text = _srepr(v)
        with contextlib.suppress(ParseError):   # (a text the parser refuses is refused when applied)
            text = _srepr(parse(text))
        return {"$": text}
    if isinstance(v, (list, tuple)):
        return [_encode(u) for u in v]
    if v is None or isinstance(v, (bool, int, str)):
        return v
    raise KernelError(f"rule data must be SymPy objects, numbers, strings or lists: {v!r}")


def _encoded(v) -> bool:
    """v has the shape `_encode` gives (rule data read from a certificate)."""
    if isinstance(v, dict):
        return set(v) == {"$"} and isinstance(v["$"], str)
    if isinstance(v, list):
        return all(_encoded(u) for u in v)
    return v is None or isinstance(v, (bool, int, str))


def decode(v):
    if isinstance(v, dict):
        e = parse(v["$"])
        _PRINTER.memo.setdefault(e, v["$"])     # printed as read (as `_encode` wrote it: SymPy's own srepr)
        return e
    if isinstance(v, list):
        return [decode(u) for u in v]
    return v


def rule(*assumes):
    """Register a rule: ``fn(*premises, **data)`` returns a Claim (or a
    (Claim, extra assumptions) pair) after checking everything.  Applied
    to every rule by the table `_RULE_ASSUMPTIONS` at the end of this
    module, rather than as a decorator, so that mutation testing (mutmut
    skips decorated functions) reaches the rule bodies."""
    def deco(fn):
        @functools.wraps(fn)
        def apply(*premises, **data):
            return _apply(fn, assumes, premises, {k: _encode(v) for k, v in data.items()})
        # a certificate's step: its data already encoded (no srepr of what was just parsed)
        apply.from_json = lambda *premises, data: _apply(fn, assumes, premises, data)
        RULES[fn.__name__] = apply
        return apply
    return deco


def _apply(fn, assumes, premises, enc: dict) -> Theorem:
    """One application of the rule fn (see `rule`) to its encoded data."""
    _need(all(isinstance(p, Theorem) for p in premises), lambda: f"{fn.__name__}: a premise is not a theorem")
    _need(isinstance(enc, dict) and all(_encoded(v) for v in enc.values()),
          lambda: f"{fn.__name__}: rule data must be SymPy objects, numbers, strings or lists")
    try:
        data = {k: decode(v) for k, v in enc.items()}     # exactly what a checker sees
    except ParseError as exc:
        raise KernelError(f"{fn.__name__}: {exc}") from None
    out = fn(*premises, **data)
    claim, extra = out if isinstance(out, tuple) else (out, ())
    assumptions = frozenset(assumes).union(("sympy-core",), extra, *[p.assumptions for p in premises])
    return Theorem(claim, fn.__name__, tuple(premises), json.dumps(enc, sort_keys=True), assumptions, _token=_TOKEN)


# ---------------------------------------------------------------- helpers

def _sym(v) -> sp.Basic:
    """A SymPy object or a Python int, never a string (sympify would eval it)."""
    if isinstance(v, sp.Basic):
        return v
    _need(type(v) is int, lambda: f"expected a SymPy object or an int, got {type(v).__name__}")
    return sp.Integer(v)


def _number(c) -> sp.Expr:
    """An exact real constant (no Float, no symbol) or oo."""
    c = _sym(c)
    if c.is_Rational:
        return c
    _need(c in (OO, -OO) or (c.is_number and not c.has(sp.Float)), lambda: f"not an exact number: {c}")
    if c not in (OO, -OO):
        _enclose(c, None, None, None, lambda: f"not a real constant: {c}")
    return c


def derivative(e, x):
    """dE/dx by the sum, product, power and chain rules, each with SymPy's own
    formula (`Add`/`Mul`/`Pow._eval_derivative`, a function's `fdiff`),
    but with no assumption queries (SymPy asks `is_zero` of every derivative
    it builds): the result is `sympy.diff(e, x)` except where SymPy drops a
    term it proves zero.  |u|, sign, Piecewise, Max, Min and the like keep
    `sympy.diff`.  The prover and the checker both call this, so claims
    about a derivative match."""
    e = _sym(e)
    if x not in e.free_symbols or e == x:
        return sp.Integer(e == x)
    if e.is_Pow:
        (b, p), dp = e.args, derivative(e.exp, x)
        return e * ((dp * sp.log(b) if dp != 0 else 0) + derivative(b, x) * p / b)
    if not (e.is_Add or e.is_Mul or isinstance(e, sp.Function) and type(e)._eval_derivative is sp.Function._eval_derivative):
        return sp.diff(e, x)
    ds = [derivative(a, x) for a in e.args]
    if e.is_Add:
        return sp.Add(*ds)
    if e.is_Mul:
        return sp.Add(*[sp.Mul(*e.args[:i], d, *e.args[i + 1:]) for i, d in enumerate(ds) if d != 0])
    return sp.Add(*[e.fdiff(i) * d for i, d in enumerate(ds, 1) if d != 0])


def _lt(a, b) -> bool:
    """a < b, certified (exactly for rationals and oo, else by Arb)."""
    a, b = _sym(a), _sym(b)
    if a == b or a == OO or b == -OO:
        return False
    if a == -OO or b == OO:
        return True
    if a.is_Rational and b.is_Rational:
        return bool(a < b)
    try:
        d = evaluate(b - a, bits=256)
    except Undefined:
        return False
    return d.positive()


def _const_sign(c, zero=False) -> int:
    """The sign of an exact constant: an Arb enclosure that excludes 0, or
    exactly 0: SymPy's literal 0, and with `zero` also 0 by
    `_zero_when_generalized` (which reads log(p/q) as a sum of logarithms of
    primes; without it such a 0 is undecided, for the rules that need a
    nonzero constant beside a factor SymPy did not cancel); KernelError otherwise."""
    c = _number(c)
    if c == 0:
        return 0
    for bits in SIGN_BITS:      # (2,048 bits tell 10^-300 from 0; 32,768 log(1 + 2^-14000) - 10^-4300)
        v = evaluate(c, bits=bits)
        if v.positive() or v.negative():
            return 1 if v.positive() else -1
    _need(zero and _zero_when_generalized(c), lambda: f"sign of {c} not decided")     # 0 as in `identity`
    return 0


def _enclose(e, var, a, b, what, bits=128):
    """Arb's enclosure of e on [a, b]; KernelError "what(): why" where the
    evaluation does not show e defined there."""
    try:
        return evaluate(e, var, a, b, bits=bits)
    except Undefined as exc:
        raise KernelError(f"{what()}: {exc}") from None


def _expr(e, var) -> sp.Expr:
    """e, exact (no Float), with no symbol but the variable var."""
    _need(isinstance(var, sp.Symbol), lambda: f"not a variable: {var!r}")
    e = _sym(e)
    _need(not e.has(sp.Float), lambda: f"floats are not exact: {e}")
    _need(e.free_symbols <= {var}, lambda: f"{e} has symbols other than {var}")
    return e


def _interval(var, lo, hi, lo_open, hi_open, at_zero=False):
    """Checked interval: lo < hi, infinite ends open, and the variable's
    SymPy assumptions (positive / nonnegative) hold on all of it.  A rule
    that only *evaluates* the expression tree (no diff, subs or simplify
    relying on the assumption) may pass at_zero=True: a positive variable
    may then have the closed end 0 too."""
    _need(isinstance(var, sp.Symbol), lambda: f"not a variable: {var!r}")
    _need(isinstance(lo_open, bool) and isinstance(hi_open, bool), "open/closed flags are booleans")
    lo, hi = _number(lo), _number(hi)
    _need(_lt(lo, hi), lambda: f"empty interval ({lo}, {hi})")
    _need((lo != -OO or lo_open) and (hi != OO or hi_open), "infinite ends are open")
    kind = next((k for k in _VAR_KINDS if var.assumptions0 == sp.Symbol("_", **{k: True}).assumptions0), None)
    _need(kind is not None, lambda: f"{var}: a variable is declared real, positive or nonnegative, nothing else")
    if kind == "positive" and not at_zero:
        _need(lo == 0 and lo_open or lo != -OO and _lt(0, lo), lambda: f"{var} > 0 assumed: interval must lie in (0, oo)")
    elif kind != "real":
        _need(lo == 0 or _lt(0, lo), lambda: f"{var} >= 0 assumed")
    return lo, hi


_VAR_KINDS = ("real", "positive", "nonnegative")


def _sign_claim(e, var, lo, hi, lo_open, hi_open, want, strict) -> Claim:
    return Claim("sign", _s(e), _s(var), _s(lo), _s(hi), bool(lo_open), bool(hi_open), int(want), bool(strict))


def _sign_on(c: Claim, e, want, strict) -> Claim:
    """A sign claim about e on the interval of the claim c."""
    return Claim("sign", _s(e), c.var, c.lo, c.hi, c.lo_open, c.hi_open, int(want), bool(strict))


def _is_sign(t: Theorem):
    """The claim of the sign theorem t and its variable."""
    return _of_kind(t, "sign", f"premise is a {t.claim.kind} theorem, not a sign theorem")


def _of_kind(t: Theorem, kind: str, msg: str):
    """The claim of the premise t, of this kind (else KernelError msg), and its variable."""
    _need(t.claim.kind == kind, msg)
    return t.claim, t.claim.x()


def _signs_on_one_interval(premises) -> Claim:
    """Every premise is a sign theorem about the same interval; the first claim."""
    _need(premises, "no premises")
    c = premises[0].claim
    for p in premises:
        _is_sign(p)
        _need((p.claim.var, p.claim.lo, p.claim.hi, p.claim.lo_open, p.claim.hi_open) ==
              (c.var, c.lo, c.hi, c.lo_open, c.hi_open), "premises on different intervals")
    return c


def _box_ok(v: Iv, want, strict) -> bool:
    return (v.positive() if want > 0 else v.negative()) if strict else (v.nonnegative() if want > 0 else v.nonpositive())


def _cuts(var, cuts):
    _need(isinstance(cuts, list) and len(cuts) >= 2, "a cover needs a list of at least two cut points")
    cuts = [_number(c) for c in cuts]
    _need(all(c not in (OO, -OO) for c in cuts), "cut points are finite")
    for a, b in zip(cuts, cuts[1:]):
        _need(_lt(a, b), lambda: f"cut points not increasing: {a}, {b}")
    return cuts


# ------------------------------------------------------------------ rules

def sign_by_cover(*, expr, var, cuts, want, strict=True, mean_value=False):
    """want*E > 0 (>= 0 if not strict) on the closed [c0, cn], where
    c0 < c1 < ... < cn are exact and, for each i, the Arb range enclosure of
    E over [ci, c(i+1)] has that sign.  The closed boxes share their ends,
    so they tile [c0, cn] with no gap; range evaluation shows E defined on each.
    `mean_value`: a box whose range enclosure has no sign may show it by the
    mean value form E(m) + E'(B)(B - m) (`arb.centered`), E' = `derivative`(E)
    evaluable on the closed box B.  Every function the evaluator supports is
    differentiable, with SymPy's derivative, wherever that derivative's
    formula is evaluable (that of |u|, sign(u) u', only where u has one
    strict sign on the box; that of sign(u), a DiracDelta, never), so E
    is C^1 on B and E(x) = E(m) + E'(xi)(x - m)."""
    _need(want in (1, -1) and isinstance(strict, bool) and isinstance(mean_value, bool),
          "want is +1 or -1, strict and mean_value booleans")
    cuts = _cuts(var, cuts)
    _interval(var, cuts[0], cuts[-1], False, False, at_zero=True)
    e = _expr(expr, var)
    d = derivative(e, var) if mean_value else None
    for a, b in zip(cuts, cuts[1:]):
        try:
            v = evaluate(e, var, a, b)
            if d is not None and not _box_ok(v, want, strict):
                v = centered(e, d, var, a, b)
        except Undefined as exc:
            raise KernelError(f"{e} not evaluable on [{a}, {b}]: {exc}") from None
        _need(_box_ok(v, want, strict), lambda: f"sign not shown on [{a}, {b}]: {v}")
    claim = _sign_claim(e, var, cuts[0], cuts[-1], False, False, want, strict)
    return (claim, ("sympy-diff",)) if d is not None else claim


def sign_by_taylor(*, expr, var, c, side, width, order, cuts=None):
    """Taylor with the Lagrange remainder, one-sided.  Premises: E(c) = E'(c)
    = ... = E^(m-1)(c) = 0 exactly (`_const_sign`, confirmed by an Arb
    enclosure containing 0); E, ..., E^(m)
    (`derivative` applied k times) are all defined, hence continuous, on the
    closed box B = [c, c+w] (side +1) or [c-w, c] (side -1); E^(m) has one
    strict sign sigma on every closed sub-box of B (cut at the optional exact
    increasing `cuts` from one end of B to the other).  Then for x in B,
    x != c: E(x) = E^(m)(xi) (x-c)^m / m! with xi between c and x, so E has
    the sign sigma*side^m on (c, c+w] resp. [c-w, c)."""
    _need(side in (1, -1), "side is +1 or -1")
    _need(isinstance(order, int) and 1 <= order <= 12, "order m is 1..12")
    c, w = _number(c), _number(width)
    _need(_lt(0, w), "width > 0")
    a, b = (c, c + w) if side > 0 else (c - w, c)
    _interval(var, a, b, side > 0, side < 0)
    cuts = _cuts(var, cuts if cuts is not None else [a, b])
    _need(cuts[0] == a and cuts[-1] == b, "the cuts must run from one end of the box to the other")
    e = _expr(expr, var)
    sigma = _vanishing_to_order(e, var, c, cuts, order)[1]
    _need(sigma != 0, lambda: f"derivative {order} has no strict sign on [{a}, {b}]")
    return _sign_claim(e, var, a, b, side > 0, side < 0, sigma * side ** order, True)


def _vanishing_to_order(e, var, c, cuts, m):
    """(E^(m), its strict sign on every closed box between the `cuts`, or 0)
    once E, ..., E^(m) (`derivative` applied k times) are shown defined,
    hence continuous, on [cuts[0], cuts[-1]] and E(c) = ... = E^(m-1)(c) =
    0 exactly (`_const_sign`, confirmed by an Arb enclosure containing 0)."""
    for k in range(m + 1):
        d = derivative(d, var) if k else e
        try:                # (defined on each closed box of a tiling: defined on all of it)
            boxes = [evaluate(d, var, u, v) for u, v in zip(cuts, cuts[1:])]
        except Undefined as exc:
            raise KernelError(f"derivative {k} not defined on [{cuts[0]}, {cuts[-1]}]: {exc}") from None
        if k < m:
            at_c = d.xreplace({var: c})
            _need(at_c == 0 or _const_sign(at_c, zero=True) == 0, lambda: f"derivative {k} at {c} is {at_c}, not exactly 0")
            _need(evaluate(d, var, c, c, bits=256).hull().contains(0), "Arb disagrees with exact 0")
    return d, 1 if all(v.positive() for v in boxes) else -1 if all(v.negative() for v in boxes) else 0


def limit_by_taylor(*, expr, num, den, var, order, width):
    """E(x) -> L as x -> 0+, for 0/0: E(0) is undefined (SymPy's value has
    nan or zoo: else `continuous_at_end`), E D = N exactly where defined
    (`_exact_zero`: E over one denominator), E defined on (0, w]
    (`_defined`); N and D vanish at 0 to order m >= 1 (`_vanishing_to_order`
    on [0, w]) and D^(m) has one strict sign on [0, w].  By Taylor with the
    Lagrange remainder N(x) = N^(m)(xi) x^m/m!, D(x) = D^(m)(eta) x^m/m!
    with xi, eta in (0, x): D != 0 on (0, w], and E(x) = N^(m)(xi)/D^(m)(eta)
    -> N^(m)(0)/D^(m)(0) = L (exact, SymPy's value; Arb agrees).  Claim kind
    "limit" on [0, w] with other = L."""
    w = _number(width)
    _need(isinstance(order, int) and 1 <= order <= 12 and _lt(0, w) and w != OO, "order 1..12 and a finite w > 0")
    _interval(var, 0, w, False, False, at_zero=True)
    e, n, d = (_expr(x, var) for x in (expr, num, den))
    _need(e.xreplace({var: sp.Integer(0)}).has(sp.nan, sp.zoo) and _exact_zero(e * d, n, (var,)),
          "E(0) defined, or E D - N not 0")
    extra = _defined(e, var, 0, w, lo_open=True, hi_open=False)
    (dn, _), (dd, sigma) = (_vanishing_to_order(p, var, 0, [sp.Integer(0), w], order) for p in (n, d))
    _need(sigma != 0, lambda: f"derivative {order} of D has no strict sign on [0, {w}]")
    L = _number(dn.xreplace({var: sp.Integer(0)}) / dd.xreplace({var: sp.Integer(0)}))
    _need(evaluate(dn / dd - L, var, 0, 0, bits=256).hull().contains(0), "Arb disagrees with L")
    return Claim("limit", _s(e), _s(var), _s(0), _s(w), other=_s(L)), extra


def sign_by_sturm(*, expr, var, lo, hi, lo_open, hi_open, want, strict=True):
    """A rational function e over Q (a polynomial included), exact (or
    infinite) ends.  `_fraction_over_q` gives polynomials N, D, G with e
    defined and equal to N/D wherever G != 0; G has no root in I, so D has
    one sign d there, that at an inner point x0, and the claim is that of
    d*N.  A polynomial p's sign: with p = a * prod q_i^(m_i) its square-free
    factorization, if no q_i has a root in I (`_roots_in`; weak claim: no
    q_i of odd m_i has a root in the interior of I), then the sign of p on
    I is that of p at one rational inner point where no q_i vanishes.
    (Descartes' rule of signs on p itself first: no sign change, no root
    in I at all.)"""
    _need(want in (1, -1) and isinstance(strict, bool), "want is +1 or -1, strict a boolean")
    lo, hi = _interval(var, lo, hi, lo_open, hi_open, at_zero=True)
    e = _expr(expr, var)
    _rational_sign(e, var, lo, hi, lo_open, hi_open, want, strict)
    return _sign_claim(e, var, lo, hi, lo_open, hi_open, want, strict)


def _rational_sign(e, var, lo, hi, lo_open, hi_open, want, strict):
    """`sign_by_sturm`'s check of a rational function e over Q, without a
    theorem (also `defined_for_positive`'s)."""
    N, D, G = _fraction_over_q(e, var)
    x0 = _inner_point(lo, hi, [])
    at = fmpq(int(x0.p), int(x0.q))
    _polynomial_sign(G, var, lo, hi, lo_open, hi_open, 1 if G(at) > 0 else -1, True, x0)
    _need(D(at) != 0, "D vanishes where G does not")
    _polynomial_sign(N, var, lo, hi, lo_open, hi_open, want * (1 if D(at) > 0 else -1), strict, x0)


MAX_DEGREE = 2000       # `_fraction_over_q` refuses beyond (exact arithmetic in such degrees takes minutes)


def _fraction_over_q(e, var):
    """(N, D, G), polynomials over Q (FLINT's fmpq_poly): wherever G != 0,
    every subterm of e is defined, D != 0 and e = N/D.  Fractions are added
    over the lcm of their denominators and never reduced, and G is the lcm
    of every denominator met (a negative power's base included), so the
    zeros of D are among those of G."""
    one, memo = fmpq_poly([1]), {}

    def lcm(ps):
        out = one
        for q in ps:
            out = out * (q // out.gcd(q))
        return out

    def walk(u):
        if u not in memo:
            if u == var:
                memo[u] = fmpq_poly([0, 1]), one, one
            elif u.is_Rational:
                memo[u] = fmpq_poly([fmpq(int(u.p), int(u.q))]), one, one
            elif u.is_Add or u.is_Mul:
                parts = [walk(a) for a in u.args]
                G = lcm(g for _, _, g in parts)
                if u.is_Mul:
                    memo[u] = functools.reduce(lambda a, b: (a[0] * b[0], a[1] * b[1]), parts)[:2] + (G,)
                else:
                    D = lcm(d for _, d, _ in parts)
                    memo[u] = sum((n * (D // d) for n, d, _ in parts), fmpq_poly([0])), D, G
            elif u.is_Pow and u.exp.is_Integer:
                N, D, G = walk(u.base)
                k = int(u.exp)
                _need(abs(k) * max(N.degree(), D.degree(), 1) <= MAX_DEGREE, "degree too high")
                memo[u] = (N ** k, D ** k, G) if k > 0 else (D ** -k, N ** -k, lcm([G, N]))
            else:
                raise KernelError(f"not a rational function over Q: {u}")
            _need(max(q.degree() for q in memo[u]) <= MAX_DEGREE, "degree too high")
        return memo[u]
    return walk(e)


def _polynomial_sign(q, var, lo, hi, lo_open, hi_open, want, strict, x0):
    """`sign_by_sturm`'s check of a polynomial q over Q (FLINT's fmpq_poly),
    without a theorem: where Descartes' rule shows no root in I, the sign
    at the inner point x0; else as a SymPy Poly, by its square-free factors."""
    if q.is_zero():                             # 0 >= 0 and 0 <= 0 everywhere, never > 0
        _need(not strict, "the zero polynomial has no strict sign")
        return
    if _rootless_by_descartes(q, lo, hi, lo_open, hi_open):
        _need(q(fmpq(int(x0.p), int(x0.q))) * want > 0, lambda: f"p({x0}) has the wrong sign")
        return
    poly = sp.Poly([sp.Rational(int(c.p), int(c.q)) for c in reversed(q.coeffs())], var, domain=sp.QQ)
    factors = poly.sqf_list()[1]
    for f, m in factors:                        # weak: roots of even multiplicity, and at the ends, do no harm
        if strict or m % 2:
            _need(_roots_in(f, lo, hi, lo_open or not strict, hi_open or not strict) == 0,
                  lambda: f"factor {f.as_expr()} has a root in the interval")
    x0 = _inner_point(lo, hi, factors)
    _need(sp.sign(poly.eval(x0)) == want, lambda: f"p({x0}) has the wrong sign")


def _inner_point(lo, hi, factors):
    """A rational point inside (lo, hi) where no q of `factors` [(q, m)] vanishes."""
    lo_q, hi_q = _rational_beyond(lo, 1), _rational_beyond(hi, -1)
    base = lo_q if lo_q != -OO else (hi_q - 1 if hi_q != OO else sp.Integer(0))
    step = (hi_q - lo_q) if lo_q != -OO and hi_q != OO else sp.Integer(1)
    points = (base + step / (k + 1) if lo_q != -OO else base - k for k in range(1, 60))
    x0 = next((x for x in points if all(q.eval(x) != 0 for q, _ in factors)), None)
    _need(x0 is not None and x0.is_Rational and _lt(lo, x0) and _lt(x0, hi), "no inner point found")
    return x0


def _roots_in(q, lo, hi, lo_open, hi_open) -> int:
    """The number of distinct real roots of the square-free q (over Q) in
    <lo, hi>: each root's exact isolating interval [a, b] (rational;
    SymPy's real-root isolation, far cheaper than a Sturm sequence at high
    degree) is refined until a finite end lies outside it, or the end is
    that root (`_side_of_root`)."""
    def inside(a, b, end, sign, is_open):
        side = _side_of_root(q, sp.Rational(a), sp.Rational(b), end)
        return side * sign > 0 or (side == 0 and not is_open)
    if _rootless_by_descartes(q, lo, hi, lo_open, hi_open):
        return 0
    return sum(all(inside(a, b, end, sign, op) for end, sign, op in ((lo, 1, lo_open), (hi, -1, hi_open))
                   if end not in (OO, -OO)) for (a, b), _ in q.intervals())


def _rootless_by_descartes(q, lo, hi, lo_open, hi_open) -> bool:
    """True if Descartes' rule of signs shows q has no root in <lo, hi>: on a
    rational (a, b) containing it, the positive roots of q(a + y) (b = oo)
    or of (1 + y)^d q((a + b y)/(1 + y)) are q's roots in (a, b), and with
    no sign change among its coefficients it has none.  (A milli-second
    test; false when it cannot tell.)"""
    if lo == -OO:
        return False
    a, b = (end if is_open and end.is_Rational or end == OO else
            end + side * sp.Rational(1, 2 ** 24) if end.is_Rational else _rational_beyond(end, side)
            for end, side, is_open in ((lo, -1, lo_open), (hi, 1, hi_open)))
    f = q if isinstance(q, fmpq_poly) else fmpq_poly([fmpq(int(c.p), int(c.q)) for c in reversed(q.all_coeffs())])
    Q = lambda c: fmpq(int(c.p), int(c.q))     # noqa: E731
    # b finite: y -> a + (b - a) y, reversed, y -> 1 + y
    g = f(fmpq_poly([Q(a), 1])) if b == OO else \
        fmpq_poly(list(reversed(f(fmpq_poly([Q(a), Q(b - a)])).coeffs())))(fmpq_poly([1, 1]))
    signs = [c > 0 for c in g.coeffs() if c]
    return all(x == signs[0] for x in signs)


def _side_of_root(q, a, b, end) -> int:
    """+1 if the root r of q isolated in [a, b] lies above `end`, -1 below, 0
    if r = end: q(end) = 0 exactly with end = a = b, or with end strictly
    inside (a, b), where r is q's only root.  (An end of a wider [a, b] may
    be another root of q, isolated in [end, end]: refined until outside.)"""
    for _ in range(200):
        if _lt(b, end):
            return -1
        if _lt(end, a):
            return 1
        if (a == b or (_lt(a, end) and _lt(end, b))) and sp.expand(q.as_expr().xreplace({q.gen: end})) == 0:
            return 0
        _need(a != b, lambda: f"cannot place the root {a} against {end}")
        a, b = (sp.Rational(v) for v in q.refine_root(a, b, eps=(b - a) / 16))
    raise KernelError(f"cannot place a root of {q.as_expr()} against {end}")


def sign_of_product(*premises, expr):
    """E = c * f1 * ... * fk (SymPy Mul or Pow).  Each non-constant factor f
    is covered by a premise on the common interval I: about f itself (sign
    s_f), or, for f = b**n (integer n), about b (sign s_b^n; n < 0 needs b
    strict; even n: any sign theorem gives >= 0), or, for f = b**r (r not an
    integer), b > 0 (gives f > 0) or b >= 0 with r > 0 (gives f >= 0).
    Constant factors have an exact nonzero sign.  E then has the product
    sign; strict iff every premise used is strict."""
    var = _signs_on_one_interval(premises).x()
    e = _expr(expr, var)
    factors = sp.Mul.make_args(e)
    by_expr = {p.claim.expr: p for p in premises}
    used, sign, strict = set(), 1, True
    for f in factors:
        if not f.has(var):
            s = _const_sign(f)
            _need(s != 0, "a zero factor")
            sign *= s
            continue
        p, n = by_expr.get(_s(f)), sp.Integer(1)       # a premise about f = f^1, else about the base b of f = b^n
        if p is None:
            _need(f.is_Pow and f.exp.is_Rational, lambda: f"no premise for factor {f}")
            p, n = by_expr.get(_s(f.base)), f.exp
            _need(p is not None, lambda: f"no premise for factor {f} nor its base")
        used.add(p.claim.expr)
        if n.is_Integer:
            _need(n > 0 or p.claim.strict, lambda: f"{f}: a negative power needs a strict sign of its base")
            if n % 2 == 0 and not p.claim.strict:
                strict = False          # b**(2k) >= 0 whatever the sign of b
            else:
                sign, strict = sign * p.claim.want ** int(n % 2), strict and p.claim.strict
        else:
            _need(p.claim.want > 0 and (p.claim.strict or n > 0), lambda: f"{f}: needs base > 0 (>= 0 if r > 0)")
            strict = strict and p.claim.strict
    _need(used == set(by_expr), "a premise matches no factor")
    return _sign_on(premises[0].claim, e, sign, strict)


def sign_of_sum(*premises, expr, want):
    """E = t1 + ... + tk.  The premises (same interval I) have sign want and
    are about disjoint groups of the terms: each premise's expression is a
    term of E or a sum of terms of E, plus constants c_p.  Every term in no
    group is a constant; E = (sum of the premises) + r with r = (those
    constants) - (sum of the c_p), and r has sign want or is 0 (exact /
    Arb).  E has sign want, strictly if some premise or r does strictly."""
    _need(want in (1, -1), "want = +-1 needed")
    var = _signs_on_one_interval(premises).x()
    _need(all(p.claim.want == want for p in premises), "a premise has the other sign")
    e = _expr(expr, var)
    _need(e.is_Add, lambda: f"not a sum: {e}")
    grouped, taken = set(), sp.Integer(0)
    for p in premises:
        for t in sp.Add.make_args(p.claim.e()):
            if not t.has(var):
                taken += t
                continue
            _need(t not in grouped, "premises share a term")
            grouped.add(t)
    _need(set(grouped) <= set(e.args), "a premise matches no term")
    rest = [t for t in e.args if t not in grouped]
    _need(not any(t.has(var) for t in rest), lambda: f"no premise for the terms {[t for t in rest if t.has(var)]}")
    s = _const_sign(sp.Add(*rest) - taken)
    _need(s in (0, want), lambda: f"the constant terms {sp.Add(*rest) - taken} have the wrong sign")
    strict = s == want or any(p.claim.strict for p in premises)
    return _sign_on(premises[0].claim, e, want, strict)


_ODD_INCREASING = (sp.tanh, sp.atan, sp.asinh, sp.sinh, sp.erf)
_UNARY = (sp.sinh, sp.cosh, sp.exp, sp.log, sp.sin, sp.cos, sp.atan, sp.asinh, sp.erf)


def sign_through_increasing(*premises, expr):
    """G(Y) with G odd, strictly increasing, G(0) = 0 (tanh, atan, asinh,
    sinh, erf): the sign (and strictness) of Y on I.  exp(Y), cosh(Y): > 0
    wherever Y is defined (any sign theorem about Y on I shows that).
    log(Y): from Y - 1 > 0 (>= 0) on I, log Y > 0 (>= 0); from Y - 1 < 0
    (<= 0) and a second premise Y > 0, log Y < 0 (<= 0)."""
    c = _signs_on_one_interval(premises)
    e = _expr(expr, c.x())
    _need(isinstance(e, (*_ODD_INCREASING, sp.exp, sp.cosh, sp.log)) and len(e.args) == 1, lambda: f"not G(Y): {e}")
    y = e.args[0]
    if not isinstance(e, sp.log):              # G odd increasing: Y's sign; exp, cosh: > 0
        _need(len(premises) == 1 and c.expr == _s(y), "premise must be about the argument")
        odd = isinstance(e, _ODD_INCREASING)
        return _sign_on(c, e, c.want if odd else 1, c.strict or not odd)
    _need(c.expr == _s(y - 1), "first premise must be about Y - 1")
    if c.want > 0:
        _need(len(premises) == 1, "one premise for log Y > 0")
    else:
        _need(len(premises) == 2, "log Y < 0 needs Y > 0 too")
        q = premises[1].claim
        _need(q.expr == _s(y) and q.want > 0 and q.strict, "second premise must be Y > 0")
    return _sign_on(c, e, c.want, c.strict)


_SUP = {sp.tanh: sp.Integer(1), sp.erf: sp.Integer(1), sp.atan: sp.pi / 2}   # sup over R, never attained
_MAX = {sp.sin: sp.Integer(1), sp.cos: sp.Integer(1)}                       # max over R, attained


def sign_below_sup(arg, *, expr, bounded, want=1):
    """w (a + m G(Y)) > 0 on I (w = `want`, +-1) for exact constants a, m != 0
    with w a - |m| sup G >= 0, G = tanh or erf (sup 1) or atan (sup pi/2),
    each odd: -sup G < G(y) < sup G for every real y, so w (a + m G(Y)) >
    w a - |m| sup G.  For G = sin or cos (|G| <= 1, attained) only >=, so
    the claim is strict only when w a - |m| > 0, else weak.  `bounded` is
    G(Y); the premise, any sign theorem about Y on I, shows Y defined there."""
    _need(want in (1, -1), "want is +1 or -1")
    c, var = _is_sign(arg)
    e, g = _expr(expr, var), _expr(bounded, var)
    top = {**_SUP, **_MAX}.get(type(g))
    _need(top is not None and c.expr == _s(g.args[0]), "bounded must be G(Y) and the premise about Y")
    a = e.xreplace({g: 0})
    m = e.xreplace({g: 1}) - a
    _need(not (a.has(var) or m.has(var)) and a + m * g == e, lambda: f"{e} is not a + m {g}")
    sign = _const_sign(m)
    margin = _const_sign(want * a - sign * m * top)
    _need(sign != 0 and margin >= 0, "needs m != 0 and w a - |m| sup G >= 0")
    return _sign_on(c, e, want, type(g) in _SUP or margin > 0)


def sign_by_log_bound(bound, coeff, positive, *, expr, term, p):
    """E = A + M G(Y) with T = M G(Y) one term of the sum E (`term`), A the
    others, G = log or exp.  For Y > 0 and rational p, 0 < |p| <= 1,
    l(Y) = (Y^p - 1)/p bounds log Y = log(Y^p)/p: from above for p > 0,
    from below for p < 0 (log z <= z - 1).  For -Y >= 0 and an integer p,
    1 <= p <= 16, l(Y) = 1/T(-Y), T(z) = sum z^k/k! (k <= p), bounds exp(Y)
    from above (exp(z) >= T(z) >= 1 for z >= 0), as for p > 0.  Premises on
    one interval I: `positive` Y > 0 (log), -Y >= 0 (exp); `coeff` M with
    the sign -w sign(p) (weak); `bound` B = A + M l(Y) with the sign w.
    Then M G(Y) - M l(Y) has the sign w, so E does too, strict as `bound`
    is.  (E is defined on I: A's terms are B's, M and G(Y) are.)  A log
    tail such as s log(1 + s^2)/(1 + s^2), or an exp tail such as
    (s - s^3) exp(-s^2), whose form in t = 1/s is not defined at t = 0,
    becomes algebraic.  M asinh(X) is M log(Y) with Y = X + sqrt(X^2 + 1)
    (asinh's definition, for every real X)."""
    c = _signs_on_one_interval([bound, coeff, positive])
    var = c.x()
    e, t, p = _expr(expr, var), _expr(term, var), _number(p)
    split = _log_term(t)
    _need(e.is_Add and t in e.args and split is not None, lambda: f"{t} is not a term M log(Y) or M exp(Y) of {e}")
    m, y, g = split
    ok = p.is_Integer and 1 <= p <= 16 if g is sp.exp else p.is_Rational and p != 0 and -1 <= p <= 1
    _need(ok, "p is rational, 0 < |p| <= 1 (log), an integer 1 <= p <= 16 (exp)")
    z, l = _log_bound_of(y, g, p)
    b = sp.Add(*[a for a in e.args if a != t], m * l)
    _need(positive.claim.expr == _s(z) and positive.claim.want == 1 and (positive.claim.strict or g is sp.exp),
          lambda: f"premise must be {z} > 0" + (" (or >= 0)" if g is sp.exp else ""))
    _need(coeff.claim.expr == _s(m) and coeff.claim.want == -c.want * _const_sign(p),
          lambda: f"premise must be the sign {-c.want * _const_sign(p)} of {m}")
    _need(c.expr == _s(b), lambda: f"premise must be about {b}")
    return _sign_on(c, e, c.want, c.strict)


def _log_bound_of(y, g, p):
    """(Z, l(Y)) of `sign_by_log_bound`: the premise's Z (Y for log, -Y for
    exp) and the bound l(Y) of G(Y) (the prover builds its premise with it)."""
    return (-y, 1 / sum((-y) ** k / sp.factorial(k) for k in range(p + 1))) if g is sp.exp else (y, (y ** p - 1) / p)


def _log_term(t):
    """(M, Y, G) for a product t = M G(Y) with one log or exp among its
    factors (G = log, exp), M asinh(X) read as M log(X + sqrt(X^2 + 1))
    (asinh's definition, for every real X); None for any other t."""
    logs = [a for a in sp.Mul.make_args(t) if isinstance(a, (sp.log, sp.asinh, sp.exp))]
    if len(logs) != 1:
        return None
    g, x = logs[0], logs[0].args[0]
    m = sp.Mul(*[a for a in sp.Mul.make_args(t) if a != g])
    return m, x + sp.sqrt(x ** 2 + 1) if isinstance(g, sp.asinh) else x, sp.exp if isinstance(g, sp.exp) else sp.log


def sign_of_increasing_difference(arg, *, expr, inner, c):
    """k (G(Y) - G(c)) has the sign of k (Y - c) on I, strict as the premise
    (the sign of Y - c on I), for G strictly increasing on R (tanh, atan,
    asinh, sinh, erf, exp), an exact constant c and an exact constant k != 0
    (e/2 - e exp(-Y^2)/2 is k = -e/2, c = 0).  `inner` is k G(Y)."""
    p, var = _is_sign(arg)
    e, (k, g), c = _expr(expr, var), _expr(inner, var).as_independent(var, as_Add=False), _number(c)
    _need(type(g) in (*_ODD_INCREASING, sp.exp) and c not in (OO, -OO), "inner must be k G(Y), c finite")
    sk = _const_sign(k)                     # not 0: SymPy makes 0 G(Y) the number 0
    _need(e == k * g - k * g.func(c) and p.expr == _s(g.args[0] - c),
          lambda: f"{e} is not k (G(Y) - G(c)) with the premise Y - c")
    return _sign_on(p, e, sk * p.want, p.strict)


def sign_below_product(bound_a, sign_b, bound_b, *, expr, a, b):
    """E = c - A B on I with A B a product and c exact: from a - A >= 0,
    B >= 0 and b - B >= 0 on I (exact a >= 0, b), A B <= a B <= a b, so
    E >= c - a b; E >= 0 if c - a b >= 0, > 0 if c - a b > 0 (exact / Arb).
    A and B are read off the premises (A = a - the first's E)."""
    c0 = _signs_on_one_interval([bound_a, sign_b, bound_b])
    _need(all(t.claim.want == 1 for t in (bound_a, sign_b, bound_b)), "premises must be >= 0 claims")
    var = c0.x()
    e, a, b = _expr(expr, var), _number(a), _number(b)
    A, B = a - bound_a.claim.e(), sign_b.claim.e()
    _need(bound_b.claim.expr == _s(b - B), lambda: f"third premise must be about {b - B}")
    c = e + A * B
    _need(not c.has(var), lambda: f"{e} is not c - ({A}) ({B})")
    _need(_const_sign(a) >= 0, "needs a >= 0")
    margin = _const_sign(c - a * b)
    _need(margin >= 0, "needs c - a b >= 0")
    return _sign_on(c0, e, 1, margin > 0)


def _adjacent(left, right):
    """The claims of two sign theorems about one E, variable and sign on <a, m> and <m, b>."""
    (l, _), (r, _) = _is_sign(left), _is_sign(right)
    _need((l.expr, l.var, l.want) == (r.expr, r.var, r.want), "different claims")
    _need(l.hi == r.lo, "not adjacent")
    return l, r


def join(left, right):
    """Same E, variable and sign on I1 = <a, m> and I2 = <m, b> (m the same
    exact point, closed in at least one): E has the sign on <a, b>; strict
    iff both are."""
    l, r = _adjacent(left, right)
    _need(not (l.hi_open and r.lo_open), lambda: f"shared end point {l.hi} is covered by neither")
    return Claim("sign", l.expr, l.var, l.lo, r.hi, l.lo_open, r.hi_open, l.want, l.strict and r.strict)


def join_at_point(left, right):
    """Same E, variable and sign on <a, m) and (m, b>, and the value of E at
    m: for a Piecewise E the branch that applies at m (`_branch`, each
    condition decided by the sign of its constant r - l at m), E defined
    at m (Arb).  E(m) exactly 0 (SymPy's literal 0, or polynomial
    arithmetic over Q with its radicals and other subterms as symbols,
    `_zero_when_generalized`; Arb enclosing 0) gives want*E >= 0 on <a, b>
    (weak); E(m) with the premises' sign (Arb) keeps them: strict iff both are."""
    l, r = _adjacent(left, right)
    e, var, m = l.e(), l.x(), parse(l.hi)
    if e.has(sp.Piecewise):
        e = _branch(_folded(e), lambda d, want, strict: _sign_ok(_const_sign(d.xreplace({var: m})), want, strict))
    v = e.xreplace({var: m})
    box = _enclose(e, var, m, m, lambda: f"E undefined at {m}", bits=256)        # also: E defined at m
    claim = Claim("sign", l.expr, l.var, l.lo, r.hi, l.lo_open, r.hi_open, l.want, False)
    if box.hull().contains(0) and (v == 0 or _zero_when_generalized(v)):        # (Arb first: exact 0 may cost)
        return claim
    _need(box.positive() if l.want > 0 else box.negative(), lambda: f"E({m}) = {v} has not the sign")
    return dataclasses.replace(claim, strict=l.strict and r.strict)


_TRUE_WHEN = {sp.StrictLessThan: (1, True), sp.LessThan: (1, False),
              sp.StrictGreaterThan: (-1, True), sp.GreaterThan: (-1, False)}


def _sign_ok(s, want, strict) -> bool:
    """A sign s (+1, 0, -1) satisfies want*E > 0 (>= 0 if not strict)."""
    return s == want or (not strict and s == 0)


def _holds(cond, truth, sign_ok) -> bool:
    """cond has the truth value `truth` wherever the facts `sign_ok(d, want,
    strict)` ("want*d > 0", ">= 0" if not strict) hold.  A relation l < r
    (<=, >, >=) is true where r - l > 0 (>= 0, < 0, <= 0) and false where
    the opposite weak/strict sign holds; l = r is true where r - l >= 0 and
    <= 0, false where r - l has a strict sign; Ne, Not, And, Or accordingly."""
    if cond in (sp.true, sp.false):
        return bool(cond) == truth
    if isinstance(cond, sp.Not):
        return _holds(cond.args[0], not truth, sign_ok)
    if isinstance(cond, (sp.And, sp.Or)):
        each = (_holds(a, truth, sign_ok) for a in cond.args)
        return all(each) if isinstance(cond, sp.And) == truth else any(each)
    _need(type(cond) in (*_TRUE_WHEN, sp.Eq, sp.Ne), lambda: f"condition {cond} is not a relation")
    d = cond.rhs - cond.lhs
    if isinstance(cond, (sp.Eq, sp.Ne)):
        if truth == isinstance(cond, sp.Eq):
            return sign_ok(d, 1, False) and sign_ok(d, -1, False)
        return sign_ok(d, 1, True) or sign_ok(d, -1, True)
    want, strict = _TRUE_WHEN[type(cond)]
    return sign_ok(d, want, strict) if truth else sign_ok(d, -want, not strict)


def _folded(e):
    """e as one Piecewise (SymPy's `piecewise_fold`: operations applied to a
    Piecewise are applied to each branch, the conditions kept)."""
    pw = sp.piecewise_fold(e)
    _need(isinstance(pw, sp.Piecewise), lambda: f"{e} is not a Piecewise")
    return pw


def _branch(pw, sign_ok, at=0):
    """The branch of the Piecewise pw that applies wherever the facts
    `sign_ok` hold: its condition holds there and every earlier one fails,
    or is an undecided equation p(x) = 0, p a nonconstant polynomial (linear,
    or with rational coefficients), with the value V there and a later
    branch G that applies (the rest of pw), G(c) defined (Arb) and V(c) -
    G(c) exactly 0 (and in Arb) at each real root c of p (SymPy's
    `real_roots`; c >= 0 only, for a nonnegative or positive x, whose
    intervals hold no c < 0): then pw = G where that condition holds too."""
    for i, (value, cond) in enumerate(pw.args[at:], at):
        if _holds(cond, True, sign_ok):
            return value
        if not _holds(cond, False, sign_ok):
            d = cond.rhs - cond.lhs if isinstance(cond, sp.Eq) else sp.Integer(0)
            p = sp.Poly(d, *d.free_symbols) if len(d.free_symbols) == 1 and d.is_polynomial() else sp.Poly(0, sp.Dummy())
            _need(p.degree() == 1 or p.degree() > 1 and p.domain in (sp.ZZ, sp.QQ), lambda: f"condition {cond} not decided")
            G, x = _branch(pw, sign_ok, i + 1), p.gen
            for c in [-p.nth(0) / p.nth(1)] if p.degree() == 1 else p.real_roots():
                if not x.is_nonnegative or _const_sign(c) >= 0:      # (no root c < 0 lies in I then)
                    _need(_enclose(G - value, x, c, c, lambda: f"{G} at {x} = {c}").hull().contains(0), "Arb disagrees")
                    _need(_exact_zero(value.xreplace({x: c}), G.xreplace({x: c}), ()), lambda: f"the value where {cond} is not {G}'s")
            return G
    raise KernelError("no branch applies")


def select_branch(thm, *signs, expr):
    """A claim (sign, sup, limit at the left end, divergence, identity
    G = R) about G on I gives the same claim about P (a Piecewise, or an
    expression of one: `_folded`) when G is the branch of P that applies at
    every point of I (`_branch`): P = G on I.  Each
    condition is decided by sign theorems (`signs`) about its r - l on
    intervals containing I, or by the exact sign of a constant r - l."""
    c = thm.claim
    _need(c.kind in ("sign", "sup_upper", "sup_lower", "limit", "diverges", "identity"), "premise has no interval")
    var = c.x()
    e = _expr(expr, var)
    lo, hi = c.ends()
    _need(_branch(_folded(e), _decided_by(signs, var, lo, hi, c.lo_open, c.hi_open)) == c.e(),
          "the premise is not about the branch that applies on I")
    return dataclasses.replace(c, expr=_s(e))


def _decided_by(signs, var, lo, hi, lo_open, hi_open):
    """`sign_ok` for `_branch` on the interval <lo, hi>: from the sign
    theorems `signs` on intervals containing it, or a constant's exact sign."""
    for p in signs:
        _is_sign(p)

    def sign_ok(d, want, strict):
        if not d.has(var):
            return _sign_ok(_const_sign(d), want, strict)
        e, x = _s(d), _s(var)
        return any(p.claim.expr == e and p.claim.var == x and p.claim.want == want
                   and (p.claim.strict or not strict) and _within(p.claim, lo, hi, lo_open, hi_open)
                   for p in signs)
    return sign_ok


def _pieces(signs, expr, var, cuts):
    """(P, e, the ends 0 < b1 < ... < bn < oo, the branches, the extra
    assumptions) for the rules below: cuts finite, exact and increasing; on
    each open piece between the ends the branch that applies (`_branch`, by
    the sign theorems `signs`) is defined, hence continuous, on that piece
    (`defined_for_positive`) and at its finite ends other than 0 (Arb), so
    on the piece's closure in (0, oo)."""
    e = _expr(expr, var)
    pw = _folded(e)
    _need(isinstance(cuts, list), "cuts must be a list")
    ends = [*(_cuts(var, [0, *cuts]) if cuts else [sp.Integer(0)]), OO]
    _interval(var, 0, OO, True, True)
    branches = [_branch(pw, _decided_by(signs, var, a, b, True, True)) for a, b in zip(ends, ends[1:])]
    extra = {x for g, a, b in zip(branches, ends, ends[1:])
             for x in _defined(g, var, a, b, lo_open=a == 0, hi_open=b == OO)}
    return pw, e, ends, branches, extra


def piecewise_branches(*signs, expr, var, cuts):
    """P (a Piecewise, or an expression of one) agrees on each open piece
    between 0 < b1 < ... < bn < oo with one expression defined, hence
    continuous, on that piece's closure in (0, oo) (`_pieces`); nothing is
    said of P at the cuts (P may jump there).  Claim kind "pieces" on
    (0, oo), other = the cuts."""
    _, e, ends, _, extra = _pieces(signs, expr, var, cuts)
    return Claim("pieces", _s(e), _s(var), _s(0), "oo", True, True, other=_s(sp.Tuple(*ends[1:-1]))), extra


def continuous_piecewise(*signs, expr, var, cuts):
    """P (a Piecewise, or an expression of one: `_folded`) is continuous on
    (0, oo): each open piece as in `piecewise_branches`, and at each cut b
    the branches of both sides and the branch that applies at b have one
    value (their differences at b are exactly 0: SymPy's evaluation, or
    polynomial arithmetic with pi and the like as symbols; Arb agrees).
    Claim kind "continuous" on (0, oo)."""
    pw, e, ends, branches, _ = _pieces(signs, expr, var, cuts)
    for b, left, right in zip(ends[1:-1], branches, branches[1:]):
        at = _branch(pw, lambda d, want, strict: _sign_ok(_const_sign(d.xreplace({var: b})), want, strict))
        for g in (left, right):
            d = g.xreplace({var: b}) - at.xreplace({var: b})
            _need(d == 0 or _zero_when_generalized(d), lambda: f"the branches differ at {b}")
            _need(_enclose(at - g, var, b, b, lambda: f"P undefined at {b}", bits=256).hull().contains(0),
                  "Arb disagrees with exact 0")
    return Claim("continuous", _s(e), _s(var), _s(0), "oo", True, True)


def weaken(thm, *, lo, hi, lo_open, hi_open, strict):
    """A sign on I gives the same sign on any J contained in I, and a
    strict sign gives the weak one."""
    c, var = _is_sign(thm)
    lo, hi = _interval(var, lo, hi, lo_open, hi_open, at_zero=True)
    _need(_within(c, lo, hi, lo_open, hi_open), "J is not inside I")
    _need(c.strict or not strict, "a weak sign does not give a strict one")
    return _sign_claim(c.e(), var, lo, hi, lo_open, hi_open, c.want, strict)


def _within(c: Claim, lo, hi, lo_open, hi_open) -> bool:
    """<lo, hi> is contained in the interval of claim c."""
    a, b = c.ends()
    return ((_lt(a, lo) or (lo == a and (lo_open or not c.lo_open)))
            and (_lt(hi, b) or (hi == b and (hi_open or not c.hi_open))))


def sign_by_rewrite(thm, ident, *, cuts=None):
    """A sign of R on I, an identity L = R (where both are defined) on an
    interval containing I, and L defined on all of I give the sign of L on
    I.  L defined: either I lies in (0, oo) and `defined_for_positive(L)`,
    or I is closed and finite and L evaluates (Arb, range) on every closed
    box of the exact cuts tiling I.  (Covers `prepare`, tail forms, regrouping.)"""
    _is_sign(thm)
    _need(ident.claim.kind == "identity", "second premise must be an identity")
    c, ic = thm.claim, ident.claim
    _need(ic.var == c.var and ic.other == c.expr, "the identity must read L = R for the R of the sign")
    lo, hi = c.ends()
    _need(_within(ic, lo, hi, c.lo_open, c.hi_open), "the identity does not hold on all of I")
    var, lhs, out = c.x(), ic.e(), dataclasses.replace(c, expr=ic.expr)
    if cuts is None:
        _need(_lt(0, lo) or (lo == 0 and c.lo_open), "L not shown defined on I")
        try:
            return out, _defined(lhs, var, lo, hi, c.lo_open, c.hi_open)
        except KernelError:
            raise KernelError("L not shown defined on I") from None
    cuts = _cuts(var, cuts)
    _need(not (c.lo_open or c.hi_open) and cuts[0] == lo and cuts[-1] == hi, "cuts must tile the closed I")
    for u, v in zip(cuts, cuts[1:]):
        _enclose(lhs, var, u, v, lambda: f"L undefined on [{u}, {v}]")
    return out


def defined_for_positive(e, x, lo=0, hi=OO, analytic=True) -> tuple | None:
    """Sufficient check that e is defined (real, finite) at every x in
    (lo, hi), exact ends with 0 <= lo < hi <= oo (by default at every
    x > 0).  Each subterm u gets a lower bound (L, strict), u >= L (u > L
    when strict), L exact or -oo, or none when u is not shown defined:
    x > lo; a finite constant c >= c; a sum's bound is the sum of its
    terms' bounds; a product of factors >= 0 (> 0) is >= 0 (> 0), and
    c G(w) >= c sup G for c < 0 and G <= 1 (tanh, erf, sin, cos, exp(w)
    with w <= 0) or G <= pi/2 (atan); G(w) >= G(L) for G = tanh, atan,
    asinh, sinh, erf, exp, increasing (> G(L) when w > L, and always when
    L = -oo); log w >= log L for w >= L > 0 (log w needs w > 0); cosh >=
    1, sin, cos >= -1, |w| >= 0, w^n >= 0 (n even, > 0 if w > 0) and b^r >
    0 for b > 0 and rational r (a base or a log's argument without a
    bound > 0 (>= 0) is not shown defined).  Where a sign is asked (a
    factor, a base, a function's argument), a rational function of x over
    Q is > 0 (>= 0) on (lo', hi') when `_rational_sign` shows it (lo' <=
    lo and hi' >= hi rational, lo' >= 0).  Returns the extra assumptions
    the check rests on (the polynomial ones when a rational function was
    signed, else ()), or None when definedness is not shown.  x = Tuple(x1,
    x2): e defined at every point of the plane, x1, x2 real of either sign
    (no bound); instead of rational functions, polynomials q(x1^2 + x2^2)
    are signed by Sturm in r >= 0.  `analytic=False` (definedness only):
    also b^y with b > 0 and y any defined exponent, w^r >= 0 for a constant
    r > 0 and w >= 0, and a Piecewise whose last condition is True, each
    condition defined where no earlier one holds and each value where its
    own holds too (`_facts`: bounds of the form c p + k from the
    conditions, and c p > 0 where c p != 0 and c p >= 0)."""
    free = x.free_symbols
    lo, hi = _number(lo), _number(hi)
    _need((lo == 0 or _lt(0, lo)) and _lt(lo, hi), "definedness is checked on some (lo, hi) with 0 <= lo < hi")
    ends = (_rational_beyond(lo, -1), _rational_beyond(hi, 1))
    polys = []

    def shows(b, strict):   # the bound b shows u > 0 (strict) or u >= 0
        return b is not None and (_lt(0, b[0]) or b[0] == 0 and (b[1] or not strict))

    def better(a, b):       # the stronger of two bounds
        return a if b is None else b if a is None or _lt(a[0], b[0]) or a[0] == b[0] and b[1] else a

    def by_sturm(u, weak_too):      # (0, strict) for u over Q > 0 (>= 0) by `_rational_sign`, or None
        q = sp.expand(u.xreplace({x[0]: sp.sqrt(_R - x[1] ** 2)})) if len(free) == 2 and u.is_polynomial(*free) else None
        if len(free) == 1 and _rational_over_q(u, x):
            args = u, x, *ends, True
        elif q is not None and q.free_symbols <= {_R}:     # u = q(x1^2 + x2^2), r >= 0
            args = q, _R, sp.Integer(0), OO, False
        else:
            return None
        for strict in (True, False)[:1 + weak_too]:
            with contextlib.suppress(KernelError):
                _rational_sign(*args, True, 1, strict)
                polys.append(True)
                return sp.Integer(0), strict
        return None

    def checker(facts):     # `_facts`, known where this part of e is evaluated
        def low(u, signed=False):   # u's lower bound: its structure's, a fact's; Sturm's too where a sign is asked
            if signed:              # (a factor, a base, a function's argument: not a sum's term nor e itself)
                b = low(u)
                return better(b, by_sturm(u, not shows(b, False))) if u.has(*free) and not shows(b, True) else b
            c, p, k = _split(u) if facts and u.has(*free) else (0, None, 0)
            b, f = structure(u), facts.get((p, ">="))
            b = better(b, f and (c * f[0] + k, f[1]))       # a fact's bound; u = c p >= 0 with p != 0 is > 0
            return (b[0], True) if b is not None and b[0] == 0 and k == 0 and (p, "!=") in facts else b

        def structure(u):
            if u in free:
                return (lo, True) if len(free) == 1 else (-OO, False)
            if not u.has(*free):
                return (u, False) if u not in (OO, -OO) and _number_ok(u) else None
            if u.is_Add:
                bs = [low(a) for a in u.args]
                return None if None in bs else (sp.Add(*[b for b, _ in bs]), any(s for _, s in bs))
            if u.is_Mul:
                c, g = u.as_coeff_Mul()         # c G with c < 0 and G <= sup G (`_SUP`, `_MAX`; exp(w) <= 1 for w <= 0)
                top = None if not c.is_negative else sp.Integer(1) if isinstance(g, sp.exp) and \
                    shows(low(-g.args[0], True), False) else {**_SUP, **_MAX}.get(type(g))
                if top is not None:
                    return (c * top, False) if low(g) is not None else None
                bs = [low(a, True) for a in u.args]
                return None if None in bs else (sp.Integer(0), all(shows(b, True) for b in bs)) \
                    if all(shows(b, False) for b in bs) else (-OO, False)
            if u.is_Pow:
                b, n = low(u.base, True), u.exp
                if n.is_Integer and n > 0:      # w^n >= 0 for n even or w >= 0, > 0 for w > 0
                    return None if b is None else (sp.Integer(0), shows(b, True)) if n % 2 == 0 or \
                        shows(b, False) else (-OO, False)
                if shows(b, True) and (n.is_Rational or not analytic and low(n) is not None):
                    return sp.Integer(0), True
                return (sp.Integer(0), False) if not analytic and not n.has(*free) and n != OO and _lt(0, n) and \
                    shows(b, False) else None
            if isinstance(u, (*_ODD_INCREASING, sp.exp)):   # G(w) >= G(L), > where w > L; G(-oo) = inf G
                b = low(u.args[0], True)
                return None if b is None else (u.func(b[0]), b[1] or b[0] == -OO)
            if isinstance(u, sp.log):           # log w >= log L where w >= L > 0
                b = low(u.args[0] - 1, True)
                b = better(low(u.args[0], True), b and (b[0] + 1, b[1]))
                return None if not shows(b, True) else (sp.log(b[0]), b[1]) if _lt(0, b[0]) else (-OO, False)
            if type(u) in _FLOOR:               # cosh >= 1, sin, cos >= -1, |w| >= 0
                return None if low(u.args[0]) is None else (sp.Integer(_FLOOR[type(u)]), False)
            if not (isinstance(u, sp.Piecewise) and not analytic and u.args[-1].cond == sp.true):
                return None
            known = dict(facts)         # each value where its condition holds and no earlier one does
            for value, cond in u.args:
                if not (checker(known)[1](cond) and checker(_facts(cond, False, known))[0](value) is not None):
                    return None
                known = _facts(cond, True, known)
            return -OO, False

        def condition(c):
            if c in (sp.true, sp.false):
                return True
            if isinstance(c, (sp.And, sp.Or, sp.Not)):
                return all(condition(a) for a in c.args)
            return isinstance(c, sp.core.relational.Relational) and all(isinstance(a, sp.Expr) and low(a) is not None
                                                                        for a in c.args)
        low = functools.cache(low)
        return low, condition
    if checker({})[0](_sym(e)) is None:
        return None
    return ("sympy-polys", "flint-polys") if any(polys) else ()


_FLOOR = {sp.cosh: 1, sp.sin: -1, sp.cos: -1, sp.Abs: 0}


_R = sp.Symbol("r", nonnegative=True)


def _split(d):
    """(c, p, k) with d = c p + k, c > 0 and k rational, p without constant
    term or content ((0, None, 0) when d has no such form)."""
    k, v = d.as_independent(*d.free_symbols, as_Add=True)
    if not (k.is_Rational and v.free_symbols):
        return 0, None, 0
    c, p = v.as_content_primitive()
    return c, p, k


def _facts(c, negate: bool, known: dict) -> dict:
    """known and what the condition c (its negation) says: for each relation
    A ? B, with A - B = c p + k (`_split`), a lower bound (p, ">=") -> (L,
    strict): p >= L, or p > L; and (p, "!=") when A - B = c p != 0."""
    if isinstance(c, sp.Not):
        return _facts(c.args[0], not negate, known)
    if negate and isinstance(c, sp.And) and all(isinstance(a, sp.Equality) for a in c.args):   # some a != b:
        return _facts(sp.Ne(sp.Add(*[(a.lhs - a.rhs) ** 2 for a in c.args]), 0), False, known)  # sum (a - b)^2 != 0
    if isinstance(c, sp.And if not negate else sp.Or):
        return functools.reduce(lambda k, a: _facts(a, negate, k), c.args, known)
    kind = {sp.StrictGreaterThan: (1, ">"), sp.GreaterThan: (1, ">="), sp.StrictLessThan: (-1, ">"),
            sp.LessThan: (-1, ">="), sp.Unequality: (1, "!="), sp.Equality: (1, "==")}.get(type(c))
    if kind is None:
        return known
    side, op = kind
    if negate:
        side, op = -side, {">": ">=", ">=": ">", "!=": "==", "==": "!="}[op]
    f, p, k = _split(c.lhs - c.rhs if side > 0 or op == "!=" else c.rhs - c.lhs)
    out = dict(known)
    if p is not None and op == "!=" and k == 0:
        out[(p, "!=")] = True
    elif p is not None and op in (">", ">="):       # f p + k > 0: p > -k/f
        new = (-k / f, op == ">")                   # the larger bound; at one bound, the strict one
        out[(p, ">=")] = max(new, out.get((p, ">="), new))
    return out


def _defined(e, var, lo=0, hi=OO, lo_open=True, hi_open=True) -> tuple:
    """The extra assumptions of `defined_for_positive(e, var, lo, hi)`, e
    also defined (Arb) at each closed end; KernelError when e is not shown
    defined at every var in <lo, hi>."""
    how = defined_for_positive(e, var, lo, hi)
    _need(how is not None, lambda: f"{e} not shown defined for all {var} > 0" if (lo, hi) == (0, OO)
          else f"{e} not shown defined on ({lo}, {hi})")
    for end in [v for v, is_open in ((lo, lo_open), (hi, hi_open)) if not is_open]:
        _enclose(e, var, end, end, lambda: f"{e} undefined at {end}", bits=256)
    return how


def _rational_beyond(c, side):
    """c itself when rational or infinite, else a rational q with q < c
    (side -1; q >= 0 when c > 0) or q > c (side +1) within 2^-22 of c,
    certified by Arb."""
    if c in (OO, -OO) or c.is_Rational:
        return c
    man, exp = evaluate(c, bits=256).lo.mid().man_exp()     # c within 2^-250 |c| (a float of c may overflow)
    _need(exp < 1000, lambda: f"no rational bound found for {c}")
    q = sp.Rational(sp.floor(int(man) * sp.Rational(2) ** (int(exp) + 24)) + side * 2, 2 ** 24)
    q = max(q, sp.Integer(0)) if side < 0 and _lt(0, c) else q
    _need(_lt(q, c) if side < 0 else _lt(c, q), lambda: f"no rational bound found for {c}")
    return q


def _number_ok(u):
    with contextlib.suppress(KernelError):
        return _number(u) is not None
    return False


def sign_on_tail(tail, ident, *, expr, var, R):
    """s = 1/t on [R, oo), R > 0.  Premises: (1) a sign theorem about E_t on
    (0, 1/R] in a variable t; (2) an identity theorem E_t(t) = E(1/t) on
    a t-interval containing (0, 1/R], where the right side is literally
    E.xreplace({s: 1/t}); and the kernel's own check that E is defined for every
    s >= R (`_defined`, also for E(1/t) at every t in (0, 1/R)).  For s
    >= R, t = 1/s lies in (0, 1/R], both sides are defined there, so E(s) =
    E_t(t) has the sign: claim on [R, oo)."""
    (tc, t), ic = _is_sign(tail), ident.claim
    _need(ic.kind == "identity", "second premise must be an identity")
    R = _number(R)
    _need(_lt(0, R) and R != OO, "R > 0")
    e = _expr(expr, var)
    _need(t != var and isinstance(t, sp.Symbol), "the tail variable must differ from the variable")
    _need((tc.lo, tc.lo_open, tc.hi, tc.hi_open) == (_s(0), True, _s(1 / R), False),
          "the tail theorem must be about (0, 1/R]")
    et = e.xreplace({var: 1 / t})
    _need(ic.var == tc.var and ic.expr == tc.expr and ic.other == _s(et), "the identity must read E_t(t) = E(1/t)")
    _need(_within(ic, 0, 1 / R, True, False), "the identity must hold on (0, 1/R]")
    extra = _defined(e, var, R, lo_open=False)
    at_t = _defined(et, t, 0, 1 / R)       # E(1/t) defined for t in (0, 1/R)
    _interval(var, R, OO, False, True)
    return _sign_claim(e, var, R, OO, False, True, tc.want, tc.strict), {*extra, *at_t}


def sign_by_substitution(outer, *bounds, inner):
    """G(u(x)) from G(U) on J = <a, b> (premise `outer`, in the variable U)
    and u(x) in J for x in I: premises u - a > 0 (>= 0 if J is closed at a)
    and b - u > 0 (>= 0 if closed at b) on I, one for each finite end of J
    (at least one, which also shows u defined on I).  Then G(u(x)) is
    defined and has G's sign on I; the claim's E is G.subs(U, u)."""
    g, U = _is_sign(outer)
    G = g.e()
    a, b = g.ends()
    needed = [(u_end, op, side) for u_end, op, side in ((a, g.lo_open, 1), (b, g.hi_open, -1))
              if u_end not in (OO, -OO)]
    _need(needed and len(bounds) == len(needed), "one bound premise per finite end of J")
    c = _signs_on_one_interval(bounds)
    var = c.x()
    u = _expr(inner, var)
    for (u_end, op, side), p in zip(needed, bounds):
        _need(p.claim.expr == _s(side * (u - u_end)) and p.claim.want == 1 and (p.claim.strict or not op),
              lambda: f"premise must show {'u - ' + str(u_end) if side > 0 else str(u_end) + ' - u'} "
                      f"{'>' if op else '>='} 0")
    return _sign_on(c, G.subs(U, u), g.want, g.strict)


def sign_by_monotone(deriv, *, expr, var, R):
    """Mean value theorem on [R, oo), R > 0: want*E(R) > 0 (Arb at the exact
    point R) and want*E' >= 0 on [R, oo) (premise about `derivative`(E)), E
    defined for every x > R (`defined_for_positive`) => for x >= R,
    want*E(x) = want*E(R) + want*E'(xi)(x - R) > 0."""
    d, _ = _is_sign(deriv)
    R = _number(R)
    _need(R != OO and _lt(0, R), "R > 0")
    e = _expr(expr, var)
    _need((d.expr, d.var, d.lo, d.lo_open, d.hi) == (_s(derivative(e, var)), _s(var), _s(R), False, "oo"),
          "premise must be a sign of E' on [R, oo)")
    extra = _defined(e, var, R)
    at_r = _enclose(e, var, R, R, lambda: f"E undefined at {R}", bits=256)
    _need(at_r.positive() if d.want > 0 else at_r.negative(), "E(R) has not the sign of E'")
    _interval(var, R, OO, False, True)
    return _sign_claim(e, var, R, OO, False, True, d.want, True), extra


CROSS_CHECK_BITS = 320


def _cross_check(d, var, lo, hi):
    """d(x) = lhs - rhs encloses 0 at fixed rational points of I, with
    radius < 2^-250, at 320 bits; at least 3 points must be evaluable."""
    base, step = (lo, (hi - lo) / 10 if hi != OO else sp.Rational(1, 3)) if lo != -OO else \
        (hi, -sp.Rational(1, 3)) if hi != OO else (sp.Rational(-5, 3), sp.Rational(1, 3))
    pts = [base + step * k for k in range(1, 10)]
    _need(all(p.is_Rational for p in pts), "cross-check needs rational ends")
    _vanishes_at([(f"{var} = {p}", lambda p=p: evaluate(d, var, p, p, bits=CROSS_CHECK_BITS)) for p in pts])


def _vanishes_at(points):
    """lhs - rhs encloses 0 with radius < 2^-250 at every (label, enclosure
    thunk) that evaluates; at least 3 must evaluate."""
    ok = 0
    for where, enclosure in points:
        try:
            v = enclosure().hull()
        except Undefined:
            continue
        _need(v.contains(0), lambda: f"the identity fails at {where}: lhs - rhs = {v}")
        _need(bool(v.rad() < arb(2) ** -250), lambda: f"cross-check at {where} not precise enough")
        ok += 1
    _need(ok >= 3, "fewer than 3 points to cross-check the identity")


def _numerator(d, variables):
    """(ring, N, D) with N, D polynomials over Q in the variables (SymPy's
    sparse PolyRing) and d = N/D, built term by term without cancelling
    (D is a product of d's denominators, nonzero wherever d is defined):
    d is 0 wherever it is defined iff N is the zero polynomial.  None if
    d is not a rational function of the variables over Q or a denominator
    is the zero polynomial."""
    ring = PolyRing(list(variables), sp.QQ)
    gens = dict(zip(variables, ring.gens))

    def nd(u):
        if u.is_Add or u.is_Mul:
            N, D = nd(u.args[0])
            for n, e in map(nd, u.args[1:]):
                N, D = (N * n, D * e) if u.is_Mul else (N + n, D) if e == D else (N * e + n * D, D * e)
            return N, D
        if u.is_Pow and u.exp.is_Integer:
            (n, e), k = nd(u.base), int(u.exp)
            return (n ** k, e ** k) if k >= 0 else (e ** -k, n ** -k)
        return ring.ground_new(sp.QQ(u.p, u.q)) if u.is_Rational else gens[u], ring.one    # KeyError: no polynomial
    try:
        N, D = nd(d)
    except (ValueError, KeyError):
        return None
    return (ring, N, D) if D else None


def _rational_over_q(d, *variables) -> bool:
    """d is a rational function of the variables with integer powers of at
    most 64 (higher ones are left to other routes: polynomial arithmetic in
    such degrees can run for hours), its numbers rationals, no pi or E;
    a constant such as atan(2) may remain in a coefficient (`_numerator`
    refuses it, `_generalized` makes it a symbol)."""
    return d.is_rational_function(*variables) and all(a.is_Rational for a in d.atoms(sp.Number)) \
        and not d.atoms(sp.NumberSymbol) and all(p.exp.is_Integer and abs(p.exp) <= 64 for p in d.atoms(sp.Pow))


def _generalized(d, variables):
    """d with each maximal subterm that is not built from the variables and
    rationals by +, * and integer powers (sqrt(3), pi, tanh(x), x**(1/2), ...)
    replaced by a fresh symbol, one per distinct subterm: a rational function
    over Q of the variables and those symbols.  If it is 0, d = 0 for every
    value of those subterms, in particular for their true values, wherever d
    is defined.  The roots of one base b share one symbol b^(1/L), L the
    lcm of their orders (sqrt(t) and t^(-1/4) as powers of t^(1/4)): a
    second pass when a base has roots of several orders.  With one positive
    variable x, atan(u) with u > 0 for every x > 0 (`defined_for_positive`
    of log u) is read as pi/2 - atan(1/u) when 1/u sorts before u, so that
    atan(1/t) and atan(t) share one symbol (the tail forms hold both)."""
    orders: dict = {}
    for _ in range(2):
        fresh, roots, asked = {}, {}, {}
        out = _generalized_pass(d, variables, fresh, roots, asked, orders)
        if all(len(qs) == 1 for qs in asked.values()) or orders:
            break
        orders = {b: functools.reduce(sp.ilcm, qs) for b, qs in asked.items()}
    return out, fresh, roots


def _generalized_pass(d, variables, fresh, roots, asked, orders):
    """One pass of `_generalized`; `orders` gives the root order L of a base."""
    def power(b, p, q):                         # b^(p/q) = b^i (b^(1/L))^r, p L/q = L i + r, 0 <= r < L
        asked.setdefault(b, set()).add(q)
        L = orders.get(b, q)
        i, r = divmod(p * (L // q), L)
        rt = b ** sp.Rational(1, L)
        if rt.is_Rational:
            return rt ** (p * (L // q))
        if rt not in fresh:
            fresh[rt] = sp.Dummy(real=True)
            roots[fresh[rt]] = (L, walk(b))     # (b^(1/L))^L = b where b^(1/L) is real
        return walk(b) ** i * fresh[rt] ** r

    def walk(e, ev=False):                      # ev: SymPy's canonical form (else +, *, ^ as built)
        if e.is_Rational or e in variables:
            return e
        if e.is_Add or e.is_Mul or e.is_Pow and e.exp.is_Integer and abs(e.exp) <= 64:
            args = [walk(a, ev) for a in e.args]    # (an unchanged subterm is not built again)
            return e if all(a is b for a, b in zip(args, e.args)) else e.func(*args, evaluate=ev)
        if e.is_Pow and e.exp.is_Rational and e.exp.q <= 12 and abs(e.exp.p) <= 48:
            b, p, q = e.base, e.exp.p, e.exp.q  # b^(p/q) = (b^(1/q))^p where b^(p/q) is real; small p, q only
            x = next((v for v in variables if v.is_positive and _rational_over_q(b, v)), None)
            nd = _numerator(b, [x]) if x is not None else None
            if nd is not None:                  # b = N/D = x^k c, x > 0, so b^(p/q) = x^(kp/q) c^(p/q)
                low = [min((m[0] for m in P.monoms()), default=0) for P in nd[1:]]
                k = low[0] - low[1]             # x^low divides N, D
                if abs(k * p) <= 48:            # b / x^k = (N / x^low0) / (D / x^low1), divided exactly
                    N, D = (P.quo_term(((m,), 1)).as_expr() for P, m in zip(nd[1:], low))
                    return power(x, k * p, q) * power(N / D if k else b, p, q)
            return power(b, p, q)
        if isinstance(e, sp.log) and e.args[0].is_Rational and 0 < e.args[0] and max(e.args[0].p, e.args[0].q) < 2**64:
            return sp.Add(*[k * fresh.setdefault(sp.log(b), sp.Dummy(real=True))   # log of a product of primes
                            for b, k in sp.factorrat(e.args[0]).items()])
        if isinstance(e, sp.tanh):      # tanh y = sinh y / cosh y for every real y (cosh y >= 1)
            return walk(sp.sinh(e.args[0])) / walk(sp.cosh(e.args[0]))
        if isinstance(e, sp.atan) and len(variables) == 1 and variables[0].is_positive and \
                sp.default_sort_key(1 / e.args[0]) < sp.default_sort_key(e.args[0]) and \
                defined_for_positive(sp.log(e.args[0]), variables[0]) is not None:      # u > 0 for all x > 0
            return walk(sp.pi / 2 - sp.atan(1 / e.args[0]))     # atan u = pi/2 - atan(1/u) where u > 0
        if isinstance(e, _UNARY) and len(e.args) == 1:  # G(u): one symbol per canonical generalised u
            u = _cancel(walk(e.args[0], True))
            v = _cancel(-u)
            flip = isinstance(e, (sp.cosh, sp.cos, *_ODD_INCREASING, sp.sin)) and \
                sp.default_sort_key(v) < sp.default_sort_key(u)     # G(-u) = -G(u), or = G(u) for cosh, cos
            sign = -1 if flip and not isinstance(e, (sp.cosh, sp.cos)) else 1
            return sign * fresh.setdefault(e.func(v if flip else u, evaluate=False), sp.Dummy(real=True))
        return fresh.setdefault(e, sp.Dummy(real=True))
    return walk(d)


def _cancel(u):
    """sympy.cancel(u), which is u itself when u is a sum of monomials with
    rational coefficients (and then costs milliseconds to say so)."""
    return u if all(f.is_Rational or f.is_Symbol or f.is_Pow and f.base.is_Symbol and f.exp.is_Integer and f.exp > 0
                    for t in sp.Add.make_args(u) for f in sp.Mul.make_args(t)) else sp.cancel(u)


def _zero_when_generalized(d, *variables) -> bool:
    """d with its non-rational subterms generalised is 0 by polynomial
    arithmetic over Q (in the field of the variables and the fresh symbols,
    `_numerator`), so d is identically 0 where defined.  With roots
    r = b^(1/q), b = bn/bd: the numerator N, each r^k (k = a q + j) replaced
    by r^j bn^a bd^(A-a), is N bd^A modulo r^q bd - bn; if repeating this
    leaves the zero polynomial, N = 0 at the roots' true values (bd != 0
    where b is defined)."""
    g, fresh, roots = _generalized(d, variables)       # a rational function over Q by construction
    gens = [*variables, *fresh.values()]
    nds = [_numerator(e, gens) for e in [g, *(b for _, b in roots.values())]]
    if None in nds:
        return False
    (ring, num, _), bs = nds[0], [nd[1:] for nd in nds[1:]]
    relations = [(ring.gens.index(ring(r)), q, b) for (r, (q, _)), b in zip(roots.items(), bs)]
    for _ in range(6):
        for j, q, (bn, bd) in relations:
            A = max((m[j] // q for m in num.monoms()), default=0)
            num = num if not A else sum((ring({m[:j] + (m[j] % q,) + m[j + 1:]: c}) * bn ** (m[j] // q)
                       * bd ** (A - m[j] // q) for m, c in num.terms()), ring.zero)
    return not num


def _exact_zero(l, r, variables) -> bool:
    """l - r is 0 wherever defined by polynomial arithmetic over Q
    (`_zero_when_generalized`): as a rational function of the variables
    (else KernelError), after generalising its other subterms, or branch
    by branch (`_same_branches`)."""
    d = l - r
    if _rational_over_q(d, *variables):
        _need(_zero_when_generalized(d, *variables), "the rational functions differ")
        return True
    return _zero_when_generalized(d, *variables) or _same_branches(l, r, variables)


def identity(*, lhs, rhs, var, lo, hi, lo_open, hi_open):
    """lhs = rhs wherever both are defined on I.  Exact when lhs - rhs is a
    rational function with rational coefficients, or becomes one when its
    non-rational subterms (sqrt(3), tanh(x), ...) are replaced by fresh
    symbols: sympy.cancel gives 0 (polynomial arithmetic over Q).  Otherwise SymPy's simplify must give 0
    AND lhs - rhs must enclose 0 at fixed rational points of I in 320-bit
    Arb; the theorem then rests on "sympy-simplify"."""
    lo, hi = _interval(var, lo, hi, lo_open, hi_open)
    l, r = _expr(lhs, var), _expr(rhs, var)
    d = l - r
    claim = Claim("identity", _s(l), _s(var), _s(lo), _s(hi), bool(lo_open), bool(hi_open), other=_s(r))
    if _exact_zero(l, r, (var,)):
        return claim, ("sympy-polys",)
    _cross_check(d, var, lo, hi)        # first: simplify may run for minutes on what is no identity
    _need(sp.simplify(d) == 0, "SymPy's simplify does not reduce lhs - rhs to 0")
    return claim, ("sympy-simplify", "arb")


def _same_branches(l, r, variables) -> bool:
    """l and r (`piecewise_fold`ed) are Piecewise with the same conditions in
    the same order and, branch by branch, the same expression or an exact
    identity (as in `identity`): then l = r wherever both are defined.  A
    difference with a Piecewise that is not of this form is refused at once
    (KernelError): the evaluator cannot cross-check a Piecewise, so no
    simplification could be accepted either."""
    if not (l - r).has(sp.Piecewise):
        return False
    l, r = sp.piecewise_fold(l), sp.piecewise_fold(r)
    _need(isinstance(l, sp.Piecewise) and isinstance(r, sp.Piecewise) and len(l.args) == len(r.args)
          and all(_condition(cl, variables) == _condition(cr, variables) and (el == er or _zero_when_generalized(el - er, *variables))
                  for (el, cl), (er, cr) in zip(l.args, r.args)),
          "the Piecewise sides differ in a condition or a branch")
    return True


def _condition(c, variables):
    """A condition in a form where equivalent conditions of these kinds
    coincide: a relation of real a, b as a - b against 0 (a >= b as
    b - a <= 0, a = b as a - b = 0 or b - a = 0, whichever sorts first),
    an inequality's a - b divided by its positive rational content
    (`as_content_primitive`: 2 log y <= x as log y - x/2 <= 0 does);
    sqrt(E) = 0 (or != 0) holds exactly where E = 0 (or != 0); and for real
    x, y, (x = 0 and y = 0) exactly where x^2 + y^2 = 0 (its negation
    (x != 0 or y != 0) where x^2 + y^2 != 0)."""
    both = {sp.And: sp.Eq, sp.Or: sp.Ne}.get(type(c))
    if both and len(variables) == 2 and set(c.args) == {both(v, 0) for v in variables}:
        c = both(sp.Add(*[v ** 2 for v in variables]), 0)
    flip = {sp.Gt: sp.Lt, sp.Ge: sp.Le}
    if type(c) in (*flip, sp.Lt, sp.Le):        # (a - b)/k for the positive rational content k of a - b
        d = c.rhs - c.lhs if type(c) in flip else c.lhs - c.rhs
        return flip.get(type(c), c.func)(d.as_content_primitive()[1], 0)
    if isinstance(c, (sp.Eq, sp.Ne)):
        d = next((e.base for e in (c.lhs - c.rhs, c.rhs - c.lhs) if e.is_Pow and e.exp == sp.Rational(1, 2)),
                 c.lhs - c.rhs)
        return c.func(min(d, -d, key=sp.default_sort_key), 0)
    return c


_PLANE_POINTS = [(sp.Rational(p), sp.Rational(q)) for p, q in
                 (("1/3", "2/7"), ("-5/4", "3/2"), ("2", "-1/5"), ("7/3", "11/4"), ("-3", "-2"),
                  ("1/10", "-9/8"), ("5", "1/6"), ("-2/9", "4"), ("3/5", "0"), ("0", "-7/3"))]


def _in_plane(e, x, y) -> sp.Expr:
    """e, exact, in the distinct variables x, y, each declared real only (no sign)."""
    _need(isinstance(x, sp.Symbol) and isinstance(y, sp.Symbol) and x != y, "two distinct variables")
    _need(x.assumptions0 == y.assumptions0 == sp.Symbol("_", real=True).assumptions0,
          lambda: f"{x}, {y} must be declared real only")
    e = _sym(e)
    _need(not e.has(sp.Float) and e.free_symbols <= {x, y}, lambda: f"{e}: a float, or symbols other than {x}, {y}")
    return e


def identity_plane(*, lhs, rhs, x, y):
    """lhs(x, y) = rhs(x, y) at every point of the plane where both are
    defined (x, y real variables).  Exact when both are the same expression,
    or lhs - rhs is a rational function over Q, or becomes one when its
    non-rational subterms are generalised (sympy.cancel gives 0);
    otherwise SymPy's simplify must give 0 AND lhs - rhs must enclose 0,
    with radius < 2^-250, at >= 3 of 10 fixed rational points in 320-bit
    Arb; the theorem then rests on "sympy-simplify".  (With lhs = f and
    rhs = F(sqrt(x^2 + y^2)) this is the radial reduction of P4: then
    x df/dy - y df/dx = F'(r)(x y - y x)/r = 0 wherever F' exists.)"""
    l, r = _in_plane(lhs, x, y), _in_plane(rhs, x, y)
    claim = Claim("identity_plane", _s(l), _s(sp.Tuple(x, y)), other=_s(r))
    if l == r:
        return claim
    d = l - r
    if _exact_zero(l, r, (x, y)):
        return claim, ("sympy-polys",)
    _vanishes_at([(f"({p}, {q})", lambda p=p, q=q: evaluate(d.xreplace({x: p, y: q}), bits=CROSS_CHECK_BITS))
                  for p, q in _PLANE_POINTS])        # first: simplify may run for minutes on what is no identity
    _need(sp.simplify(d) == 0, "SymPy's simplify does not reduce lhs - rhs to 0")
    return claim, ("sympy-simplify", "arb")


def continuous_on_plane(*, expr, x, y):
    """E is defined, hence continuous, at every point (x, y) of the plane:
    `defined_for_positive` with two real variables of either sign (defined,
    neither positive nor nonnegative).  Every construct it accepts but Abs is
    analytic on an open set holding its argument's values (a power's base
    and a log's argument shown > 0), so an E without Abs is analytic (C^oo)
    on the plane.  Claim kind "continuous", var (x, y), on (-oo, oo)."""
    return _on_plane("continuous", expr, x, y)


def defined_on_plane(*, expr, x, y):
    """E has a real value at every point (x, y) of the plane:
    `defined_for_positive` with two real variables of either sign and
    `analytic=False`.  (An identity on the plane holds where both sides are
    defined; with this, everywhere.)  Claim kind "defined", on (-oo, oo)."""
    return _on_plane("defined", expr, x, y)


def _on_plane(kind, expr, x, y):
    e = _in_plane(expr, x, y)
    _need(defined_for_positive(e, sp.Tuple(x, y), analytic=kind == "continuous") is not None,
          lambda: f"{e} not shown defined on the plane")
    return Claim(kind, _s(e), _s(sp.Tuple(x, y)), "-oo", "oo", True, True)


def continuous_at_end(*, expr, var, c, width):
    """E is defined, hence continuous, on the closed [c, c+w] (Arb range
    evaluation: every supported function is continuous where defined) and
    its value at c is exactly v (SymPy's evaluation of E(c) is a number
    without floats, and Arb's enclosure of E(c) - v contains 0).  Then
    lim E(x) as x -> c+ is v.  Claim kind "limit" with other = v."""
    e, c, w, v = _value_at_end(expr, var, c, width)
    return Claim("limit", _s(e), _s(var), _s(c), _s(c + w), other=_s(v))


def _value_at_end(expr, var, c, width):
    """(E, c, w, v) for `continuous_at_end` and `_tail_limit`: E defined on
    the closed [c, c+w] (Arb), v = E(c) exactly (SymPy), Arb agreeing."""
    c, w = _number(c), _number(width)
    _need(c not in (OO, -OO) and w != OO and _lt(0, w), "finite c and w > 0")
    _interval(var, c, c + w, False, False, at_zero=True)
    e = _expr(expr, var)
    _enclose(e, var, c, c + w, lambda: f"{e} not defined on [{c}, {c + w}]")
    v = _number(e.xreplace({var: c}))
    _need(evaluate(e - v, var, c, c, bits=256).hull().contains(0), "Arb disagrees with E(c)")
    return e, c, w, v


def continuous_on_positive(*, expr, var):
    """E is continuous on (0, oo): `defined_for_positive` shows E defined at
    every x > 0, and every construct it accepts (+, *, rational powers, exp,
    log, cosh, sin, cos, tanh, atan, asinh, sinh, erf, Abs) is continuous
    where defined.  Claim kind "continuous" on (0, oo)."""
    e = _expr(expr, var)
    extra = _defined(e, var)
    _interval(var, 0, OO, True, True)
    return Claim("continuous", _s(e), _s(var), _s(0), "oo", True, True), extra


def diverges_by_growth(lower, *, expr, var, R, rate, k):
    """E(x) -> +oo as x -> oo.  Premise: G - k >= 0 on [R, oo), with k > 0
    exact and G = E' (rate "linear"), G = x E' (rate "log") or G = x^(1-p) E'
    (rate a rational p, 0 < p < 1), E' being `derivative`(E); E defined for
    every x >= R (`_defined`), R > 0.  By the mean value theorem
    E(x) >= E(R) + k (x - R); integrating E' >= k/x, resp. E' >= k x^(p-1),
    E(x) >= E(R) + k log(x/R), resp. E(R) + (k/p)(x^p - R^p); all tend to +oo."""
    _is_sign(lower)
    R, k = _number(R), _number(k)
    _need(R != OO and _lt(0, R) and k != OO and _lt(0, k), "R > 0 and k > 0")
    power = rate if isinstance(rate, sp.Rational) else None
    _need(rate in ("linear", "log") or (power is not None and 0 < power < 1),
          "rate is 'linear', 'log' or a rational p with 0 < p < 1")
    e = _expr(expr, var)
    d = derivative(e, var)
    g = d if rate == "linear" else var * d if rate == "log" else var ** (1 - power) * d
    c = lower.claim
    _need((c.expr, c.var, c.lo, c.lo_open, c.hi, c.want) == (_s(g - k), _s(var), _s(R), False, "oo", 1),
          lambda: f"premise must be {g - k} >= 0 on [{R}, oo)")
    return Claim("diverges", _s(e), _s(var), _s(R), "oo", False, True), _defined(e, var, R, lo_open=False)


def diverges_through_increasing(div, *, expr):
    """a + m G(Y) -> +oo as x -> oo when Y -> +oo (premise `div`), for exact
    constants a (0 too) and m > 0 (1 too) and G = log, exp, sinh, asinh or a
    power Y^p with rational p > 0 (increasing and unbounded on the values Y
    takes for large x); E = a + m G(Y) defined for every x >= R (`_defined`).
    Claim on the premise's [R, oo)."""
    c, var = _of_kind(div, "diverges", "premise must be a diverges theorem")
    e = _expr(expr, var)
    a, mg = e.as_independent(var, as_Add=True)
    m, g = mg.as_independent(var)
    _need(_number_ok(a) and _const_sign(m) > 0 and unbounded_increasing(g) and c.expr == _s(g.args[0]),
          lambda: f"{e} is not a + m G(Y), m > 0, with the premise about Y")
    return dataclasses.replace(c, expr=_s(e)), _defined(e, var, c.ends()[0], lo_open=False)


def unbounded_increasing(g) -> bool:
    """g = G(Y) with G increasing and unbounded above on the values Y takes
    for large x: log, exp, sinh, asinh, or Y^p with rational p > 0."""
    return isinstance(g, (sp.log, sp.exp, sp.sinh, sp.asinh)) or (
        g.is_Pow and g.exp.is_Rational and _const_sign(g.exp) > 0)


def diverges_by_comparison(lower, div, *, expr):
    """E(x) -> +oo as x -> oo from E - G >= 0 on <R, oo) (premise `lower`)
    and G -> +oo (premise `div`, a `diverges` theorem); E defined for every
    x >= max(R, R') (`_defined`).  Claim on [max(R, R'), oo)."""
    (c, var), d = _is_sign(lower), div.claim
    _need(d.kind == "diverges", "second premise must be a diverges theorem")
    e = _expr(expr, var)
    _need((c.var, c.hi, c.want) == (d.var, "oo", 1) and c.expr == _s(e - d.e()),
          "first premise must be E - G >= 0 on <R, oo), G the diverging expression")
    (a, _), (b, _) = c.ends(), d.ends()
    R = b if _lt(a, b) else a
    return Claim("diverges", _s(e), _s(var), _s(R), "oo", False, True), _defined(e, var, R, lo_open=False)


def value_sign(*, value):
    """The sign of an exact real constant: +-1 when its Arb enclosure
    excludes 0, 0 when it is exactly 0 (`_const_sign` with `zero`)."""
    v = _number(value)
    _need(v not in (OO, -OO), "a finite constant")
    return Claim("value_sign", _s(v), want=_const_sign(v, zero=True), strict=True)


def sup_upper_by_sign(thm, *, expr, bound):
    """From U - E >= 0 (or > 0) on I: E <= U on I (E defined there because
    U - E is)."""
    c, var = _is_sign(thm)
    e, u = _expr(expr, var), _number(bound)
    _need(c.want == 1 and c.expr == _s(u - e), "premise must be U - E >= 0")
    return Claim("sup_upper", _s(e), c.var, c.lo, c.hi, c.lo_open, c.hi_open, other=_s(u))


def sup_lower_by_point(*, expr, var, point, bound, lo, hi, lo_open, hi_open):
    """sup_I E >= L: the exact point p lies in I and E(p) >= L, either
    exactly (E(p) - L is 0 as in `join_at_point`) or by Arb enclosures."""
    lo, hi = _interval(var, lo, hi, lo_open, hi_open, at_zero=True)
    e, p, L = _expr(expr, var), _number(point), _number(bound)
    _need(_lt(lo, p) or (p == lo and not lo_open), "point before I")
    _need(_lt(p, hi) or (p == hi and not hi_open), "point after I")
    v = _enclose(e, var, p, p, lambda: f"E undefined at {p}", bits=256)       # also: E defined at p
    if not v.lo >= evaluate(L, bits=256).hi:      # else E(p) - L exactly 0 (Arb first: exact 0 may cost)
        _need(_const_sign(e.xreplace({var: p}) - L, zero=True) == 0, lambda: f"E({p}) >= {L} not shown")
    return Claim("sup_lower", _s(e), _s(var), _s(lo), _s(hi), bool(lo_open), bool(hi_open), other=_s(L))


def _tail_limit(ident, expr, var, width):
    """(E, c) with c = lim E(s) as s -> oo: the identity E_t(t) = E(1/t) on
    a t-interval containing (0, w]; E_t defined (hence continuous) on the
    closed [0, w] (Arb range evaluation); c = E_t(0) exactly (SymPy's value,
    Arb agrees); E defined for all s > 1/w (and the extra assumptions of that)."""
    ic, t = _of_kind(ident, "identity", "premise must be an identity")
    _need(t != var, "the tail variable must differ from the variable")
    e = _expr(expr, var)
    _need(ic.other == _s(e.xreplace({var: 1 / t})), "the identity must read E_t(t) = E(1/t)")
    _, _, w, c = _value_at_end(ic.e(), t, 0, width)
    _need(_within(ic, 0, w, True, False), "the identity must hold on (0, w]")
    return e, c, _defined(e, var, 1 / w)


def sup_lower_by_limit(ident, *, expr, var, width, bound, lo, lo_open):
    """sup over <lo, oo) of E >= c where c = lim E(s) as s -> oo (the premises
    of `_tail_limit`), c the given bound exactly, lo >= 0: 1/t lies in
    <lo, oo) for small t, where E(1/t) = E_t(t) -> c."""
    e, c, extra = _tail_limit(ident, expr, var, width)
    _need(c - _number(bound) == 0, lambda: f"E_t(0) is not exactly {bound}")
    lo = _interval(var, lo, OO, lo_open, True)[0]
    _need(lo == 0 or _lt(0, lo), "lo >= 0")
    return Claim("sup_lower", _s(e), _s(var), _s(lo), "oo", lo_open, True, other=_s(c)), extra


def limit_at_infinity(ident, *, expr, var, width):
    """E(s) -> c as s -> oo (the premises of `_tail_limit`).  Claim kind
    "limit_oo" with other = c."""
    e, c, extra = _tail_limit(ident, expr, var, width)
    return Claim("limit_oo", _s(e), _s(var), hi="oo", other=_s(c)), extra


def limit_of_bounded(div, *, expr):
    """G(Y) -> sup G as x -> oo when Y -> +oo (a `diverges` theorem), for
    G = tanh, erf (sup 1) or atan (sup pi/2), which tend to sup G at +oo."""
    c, var = _of_kind(div, "diverges", "premise must be a diverges theorem")
    e = _expr(expr, var)
    _need(type(e) in _SUP and c.expr == _s(e.args[0]), lambda: f"{e} is not G(Y) with the premise about Y")
    return Claim("limit_oo", _s(e), _s(var), hi="oo", other=_s(_SUP[type(e)]))


def limit_of_product(*premises, expr):
    """E = k * E1 * ... * En for an exact constant k (E over the product, its
    non-rational subterms generalised, cancels to k over Q) with Ei -> ci as
    x -> oo, and E defined for all x > 0 (`_defined`: the cancellation may
    drop a 0/0 factor that leaves E defined nowhere): where E and every Ei
    are defined, E = k E1 ... En, so E -> k c1 ... cn."""
    _need(premises and all(p.claim.kind == "limit_oo" for p in premises), "premises must be limits at oo")
    var = premises[0].claim.x()
    _need(all(p.claim.var == _s(var) for p in premises), "premises about one variable")
    e = _expr(expr, var)
    g, fresh, _ = _generalized(e / sp.Mul(*(p.claim.e() for p in premises)), (var,))
    k = sp.cancel(sp.together(g)).xreplace({d: u for u, d in fresh.items()})
    _need(not k.has(var, *fresh.values()) and _number(k) not in (OO, -OO),
          lambda: f"{e} is not a constant times the premises' product")
    c = k * sp.Mul(*(parse(p.claim.other) for p in premises))
    return Claim("limit_oo", _s(e), _s(var), hi="oo", other=_s(c)), _defined(e, var)


def sup_lower_from_limit(lim, *, lo, lo_open):
    """E -> c as x -> oo gives sup over <lo, oo) of E >= c (lo finite): E is
    defined and within any eps of c on some [X, oo), which meets <lo, oo)."""
    (c, var), lo = _of_kind(lim, "limit_oo", "premise must be a limit at oo"), _number(lo)
    _need(lo not in (OO, -OO), "finite lo")
    _interval(var, lo, OO, lo_open, True)
    return Claim("sup_lower", c.expr, c.var, _s(lo), "oo", bool(lo_open), True, other=c.other)


def widen(thm, *, lo, hi, lo_open, hi_open):
    """sup over I of E >= L gives sup over any J containing I of E >= L."""
    c, var = _of_kind(thm, "sup_lower", "premise must be a sup_lower theorem")
    lo, hi = _interval(var, lo, hi, lo_open, hi_open, at_zero=True)
    a, b = c.ends()
    _need(_within(Claim("", "", c.var, _s(lo), _s(hi), lo_open, hi_open), a, b, c.lo_open, c.hi_open),
          "J does not contain I")
    return dataclasses.replace(c, lo=_s(lo), hi=_s(hi), lo_open=bool(lo_open), hi_open=bool(hi_open))


def sup_upper_of_abs(up, down):
    """E <= U and -E <= U on I give |E| <= U on I."""
    a, b = up.claim, down.claim
    _need(a.kind == b.kind == "sup_upper", "premises must be sup_upper theorems")
    _need((a.var, a.lo, a.hi, a.lo_open, a.hi_open, a.other) == (b.var, b.lo, b.hi, b.lo_open, b.hi_open, b.other),
          "premises on different intervals or bounds")
    e = a.e()
    _need(b.expr == _s(-e), "second premise must be about -E")
    return dataclasses.replace(a, expr=_s(sp.Abs(e)))


# ------------------------------------------------------------- the table

# Every rule, grouped by what its theorems rest on besides their premises (see the module docstring),
# made a rule here (`rule`: not as a decorator, for mutation testing).
_RULE_ASSUMPTIONS = {      # beside "sympy-core", which every rule rests on (`_apply`: data read through SymPy)
    (): "join sup_upper_by_sign sup_lower_from_limit sup_upper_of_abs sign_through_increasing sign_by_log_bound "
        "sign_on_tail sign_by_substitution identity identity_plane continuous_on_plane defined_on_plane "
        "continuous_on_positive diverges_through_increasing diverges_by_comparison limit_of_bounded limit_of_product",
    ("arb",): "weaken widen sign_by_cover sign_of_product sign_of_sum sign_below_sup sign_of_increasing_difference "
              "sign_below_product join_at_point sign_by_rewrite continuous_at_end value_sign "
              "sup_lower_by_point sup_lower_by_limit limit_at_infinity",
    ("arb", "sympy-diff"): "sign_by_taylor sign_by_monotone diverges_by_growth",
    ("arb", "sympy-polys"): "select_branch piecewise_branches continuous_piecewise",
    ("arb", "sympy-diff", "sympy-polys"): "limit_by_taylor",
    ("sympy-polys", "flint-polys"): "sign_by_sturm",
}
# Pure functions that the rules call again and again with the same arguments, and their cache sizes.
_CACHED = {"derivative": 8192, "_lt": 8192, "_expr": 4096, "_roots_in": 4096, "_folded": 1024,
           "defined_for_positive": 4096, "_rational_over_q": 4096, "_zero_when_generalized": 1024}
for _assumes, _names in _RULE_ASSUMPTIONS.items():
    for _name in _names.split():
        globals()[_name] = rule(*_assumes)(globals()[_name])
for _name, _size in _CACHED.items():
    globals()[_name] = functools.lru_cache(maxsize=_size)(globals()[_name])
