"""The search proposes, the kernel decides: sign lemmas as kernel theorems.

A sign lemma "want*E(x) > 0 (or >= 0) on an interval" is what P3, P5, P6,
P7 and kf rest on (see `properties`, `kf`).  `sign_theorems` rebuilds such a
lemma from the kernel's rules only (`uwmr_symbolic.kernel.core`): it
searches — bisection cut points, widths of one-sided neighbourhoods, the
order of a Taylor expansion, the tail form of s = 1/t — and hands every
conclusion to a kernel rule, which re-checks it.  Nothing here can make a
theorem that the kernel did not check; a step the kernel refuses makes the
whole lemma `None` (the search's verdict then rests on the prover alone,
and the certificate says so).

Strategy, per piece between the caller's exact zeros:
* a polynomial over Q: its roots isolated (`sign_by_sturm`);
* an open end c: a one-sided lemma on (c, c+w] or [c-w, c) — a closed
  cover then `weaken` when E is defined at c, else by the structure of E
  (products, sums, odd increasing functions, log), else Taylor at c;
* the closed middle: bisection with the kernel's own evaluator, the
  accepted boxes become one `sign_by_cover`;
* [R, oo): the tail form E_t of s = 1/t (`univariate.tail_form`), an
  `identity` E_t(t) = E(1/t), the sign of E_t on (0, 1/R], `sign_on_tail`;
  or `sign_by_monotone` from E(R) and the sign of E' on [R, oo).
"""
from __future__ import annotations

import functools
import json
import math
import time
from contextlib import contextmanager
from fractions import Fraction

import sympy as sp

from . import timeouts
from .kernel import arb, certificate as CERT, core as K
from .kernel.arb import Undefined, centered, evaluate
from .kernel.core import derivative
from .univariate import log_groups, log_of, replaced, zero_of_denominator
from .profile import _relationals

OO = sp.oo
WIDTHS = [sp.Rational(1, 2 ** k) for k in range(1, 16, 2)]
TAYLOR_ORDER = 6
BOX_BUDGET = 3000
QUICK_BOXES = 256       # a large rational function's cover before its common denominator
REDUCTION = "f(e1, e2) = F(sqrt(e1^2 + r e2^2)) (the reduction to one variable; P4 when r = 1)"
# The proposer's budgets are counted in work units, not seconds, so that what
# it certifies is the same on every machine: one unit per expression node Arb
# evaluates (`arb.nodes`), CLAIM_UNITS per sign claim tried (its SymPy work),
# and RATIONAL_UNITS * size^2.5 before an identity of `count_ops` size that
# the kernel will try to simplify (0.4 s at size 39, 2.3 s at 79); also
# STURM_UNITS * degree^2 per root isolation and TAIL_UNITS * size^2 per
# s = 1/t form or common denominator (linear beyond size 100: `_tail_units`,
# 0.6 s at size 400); FACTOR_UNITS * size^2 before factoring a rational function
# over Q (about 0.01-0.2 s up to size 260); an identity the kernel checks
# by polynomial arithmetic alone CANCEL_UNITS * size^2 with radicals, else
# IDENTITY_UNITS * size (in a field of rational functions over Q: 0.2 ms
# per op, 0.67 s at size 3,400).  About 8 microseconds per unit here (4 to
# 24 measured); CPU_CAP is a backstop only.
CLAIM_UNITS = 200
RATIONAL_UNITS = 6
STURM_UNITS = 2
TAIL_UNITS = 2
CANCEL_UNITS = 4
FACTOR_UNITS = 2
IDENTITY_UNITS = 30
CHEAP_RATIONAL = 30     # larger rational functions try the sign rules of their parts first
WORK = 60_000           # for one lemma (about 0.5 s here); the verdict does not depend on it
DESIGN_WORK = 300_000   # for all the lemmas of one design (see `design_budget`)
EXPLORE_WORK = 120_000  # for each pool of lemmas one design may do without (see `exploring`)
LEMMA_SIZE = 50         # a lemma about an expression of n > LEMMA_SIZE ops gets n/LEMMA_SIZE times the work
CPU_CAP = 8.0           # a budget also ends after CPU_CAP times its nominal CPU seconds (backstop)
WALL_CAP = 4.0          # and a sign lemma after WALL_CAP times its nominal seconds on the clock, inside SymPy too
UNIT_SECONDS = 8e-6
REFERENCE_SECONDS = 1.7e-3  # `machine_factor`'s workload where the caps above were tuned
_charged = 0


@functools.cache
def machine_factor() -> float:
    """How many times slower than the machine CPU_CAP and WALL_CAP were tuned
    on this one runs a fixed Arb workload (best of 3; at least 1, at most 8).
    The caps are scaled by it: they are backstops against SymPy calls that
    run away, and a slower machine should not stop a lemma that a faster one
    proves.  The workload's Arb nodes are not charged to any budget."""
    x, nodes = sp.Symbol("x", positive=True), arb.nodes
    e = sp.log(1 + x ** 2) * sp.tanh(x) / (2 + sp.cos(x)) + sp.sqrt(1 + x ** 3)

    def run():
        start = time.process_time()
        for k in range(30):
            evaluate(e, x, sp.Rational(k, 8), sp.Rational(k + 1, 8))
        return time.process_time() - start
    best = min(run() for _ in range(3))
    arb.nodes = nodes
    return min(max(best / REFERENCE_SECONDS, 1.0), 8.0)


def _work() -> int:
    return arb.nodes + _charged - _explored[0]


def _cpu() -> float:
    return time.process_time() - _explored[1]


class Budget:
    """A share of work (units above) ending no later than an enclosing one."""

    def __init__(self, work, outer=None):
        self.limit = _work() + work
        self.cpu = _cpu() + CPU_CAP * UNIT_SECONDS * work * machine_factor()
        if outer is not None:
            self.limit, self.cpu = min(self.limit, outer.limit), min(self.cpu, outer.cpu)

    def spent(self, extra=0) -> bool:
        """True if the budget is spent, or would be by `extra` more units."""
        return _work() + extra > self.limit or _cpu() > self.cpu


def _scaled(work, e) -> int:
    """The budget of a lemma about e: `work`, times count_ops(e)/LEMMA_SIZE
    when e is larger (its steps -- factoring, identities, root isolation,
    s = 1/t forms -- grow with its size)."""
    return max(work, work * sp.count_ops(e) // LEMMA_SIZE)


def _degree_bound(p, var) -> int:
    """An upper bound of the degree of the polynomial p in var, read off its
    tree (`sympy.degree` would expand p)."""
    if not p.has(var):
        return 0
    if p.is_Add:
        return max(_degree_bound(a, var) for a in p.args)
    if p.is_Mul:
        return sum(_degree_bound(a, var) for a in p.args)
    if p.is_Pow:
        return int(p.exp) * _degree_bound(p.base, var)
    return 1


def _fraction_degree(e, var) -> int:
    """An upper bound of the degrees of N and D in e = N/D, a rational
    function of var, read off its tree (about 3 times the true one on sums
    of fractions)."""
    if not e.has(var):
        return 0
    if e.is_Add or e.is_Mul:
        return sum(_fraction_degree(a, var) for a in e.args)
    if e.is_Pow:
        return abs(int(e.exp)) * _fraction_degree(e.base, var)
    return 1


def _tail_units(size) -> int:
    """The cost of an s = 1/t form or a common denominator at `count_ops`
    size: quadratic up to size 100, linear beyond (as measured)."""
    return TAIL_UNITS * min(size ** 2, 100 * size)


def _rational_units(size) -> int:
    """The estimated cost, at `count_ops` size, of factoring a rational
    function not over Q, or of an identity the kernel will try to simplify."""
    return int(RATIONAL_UNITS * size ** 2.5)


_design = None      # the enclosing design's Budget, if any


@contextmanager
def design_budget(f=None):
    """The proposer's budget for one design's lemmas (`verify.verify_loaded`):
    the kernel certification of a design costs at most about DESIGN_WORK units
    per branch of the Piecewise in f (`branches`; at least one) or, if more,
    per LEMMA_SIZE operations of df/de1 (whose lemmas' budgets grow so, see
    `_scaled`), beyond its search, whatever it fails to prove.  The failures
    remembered are forgotten: a design's verdicts do not depend on the
    designs before it."""
    global _design
    size = sp.count_ops(sp.diff(f, sorted(f.free_symbols, key=str)[0])) if isinstance(f, sp.Basic) and \
        f.free_symbols else 0
    old, _design = _design, Budget(DESIGN_WORK * max(branches(f), size // LEMMA_SIZE))
    old_pools = dict(_pools)
    _pools.update(dict.fromkeys(_pools, EXPLORE_WORK))
    _FAILED.clear()
    try:
        yield
    finally:
        _design = old
        _pools.update(old_pools)


_pools = {"tails": EXPLORE_WORK, "exact": EXPLORE_WORK}     # what is left of the design's pools (`exploring`)
_explored = [0, 0.0]        # the work and CPU seconds spent in `exploring`, which no budget outside it sees


@contextmanager
def exploring(pool="tails"):
    """Lemmas a design can do without spend a pool of their own, EXPLORE_WORK
    per design, and not the design's budget: their failures do not starve
    the properties' own lemmas, nor those of a proof under way that asked
    for them.  "tails": those the search asks for only to find where a proof
    may start (the sign rules on a tail it cannot enclose: `univariate.
    enclose_sup`, `univariate.term_bound_on_tail`); "exact": P6's bound by
    the exact sup, which a looser k can replace.  Outside a design, the
    pool alone bounds them."""
    global _design
    outer, start, cpu = _design, _work(), _cpu()
    _design = Budget(_pools[pool])
    try:
        yield
    finally:
        spent = _work() - start
        _pools[pool] = max(0, _pools[pool] - spent)
        _explored[0] += spent
        _explored[1] += _cpu() - cpu
        _design = outer


def renew_pool(pool="tails"):
    """Each supremum the search encloses (`kf.certify_sup`: kf's F' and -F',
    P6's F'/s), and the kernel's proof of kf (`kf._with_kernel`), starts
    with a full pool: the terms of -F' are not those of F', and what F'
    spent would leave -F' without its tail bound."""
    _pools[pool] = EXPLORE_WORK


def branches(f) -> int:
    """How many branches the Piecewise in f have together (1 without any):
    each lemma about a Piecewise is one lemma per piece."""
    return max(1, sum(len(p.args) for p in f.atoms(sp.Piecewise))) if isinstance(f, sp.Basic) else 1


class NoProof(Exception):
    """The kernel did not accept a step (or the search found none).
    `NoProof(template, *parts)` fills the template's {} with the parts only
    when the message is read, each printed briefly (`_brief`): most of these
    are caught and dropped, and printing a large derivative costs seconds."""

    def __str__(self):
        template, *parts = self.args
        return template.format(*map(_brief, parts)) if parts else str(template)


def _brief(x, limit=160) -> str:
    """x, and a SymPy x in its unsorted order cut at `limit` characters."""
    if not isinstance(x, sp.Basic):
        return str(x)
    text = sp.sstr(x, order="none")
    return text if len(text) <= limit else text[:limit] + " ..."


_CYCLE = NoProof("a claim that needs itself")
SPENT = "the proposer's budget is spent"
STOPPED = (None, "the lemma's time backstop (WALL_CAP times its nominal seconds) ran out")
_U, _U_REAL = sp.Symbol("u", nonnegative=True), sp.Symbol("u", real=True)     # `Prover._substituted`


def _ok(v, want, strict) -> bool:
    if strict:
        return v.positive() if want > 0 else v.negative()
    return v.nonnegative() if want > 0 else v.nonpositive()


def _rule(fn, *args, **kw):
    try:
        return fn(*args, **kw)
    except (K.KernelError, Undefined, TypeError, ValueError, ZeroDivisionError) as exc:
        raise NoProof("{}: {}", getattr(fn, '__name__', fn), exc) from None


def _mid(a, b):
    """A short rational strictly between the exact a < b (exact comparisons
    with Fractions when a and b are rational, the kernel's `_lt` otherwise)."""
    fa, fb = float(a), float(b)
    for digits in range(1, 40):
        q = Fraction(round((fa + fb) / 2 * 10 ** digits), 10 ** digits)
        if a.is_Rational and b.is_Rational:
            if Fraction(a.p, a.q) < q < Fraction(b.p, b.q):
                return sp.Rational(q.numerator, q.denominator)
        elif fa < float(q) < fb and K._lt(a, sp.Rational(q.numerator, q.denominator)) \
                and K._lt(sp.Rational(q.numerator, q.denominator), b):
            return sp.Rational(q.numerator, q.denominator)
    return (a + b) / 2


def _cover(e, var, a, b, want, strict, boxes=BOX_BUDGET):
    """sign_by_cover on the closed [a, b] from a bisection (the search); its
    mean value form where the range enclosure of a box has no sign."""
    cuts, used = _cover_cuts(e, var, a, b, want, strict, boxes, mean_value=True)
    return _rule(K.sign_by_cover, expr=e, var=var, cuts=cuts, want=want, strict=strict,
                 **({"mean_value": True} if used else {}))


def _cover_cuts(e, var, a, b, want, strict, boxes=BOX_BUDGET, mean_value=False):
    """(cut points a = c0 < ... < cn = b with e signed want on every
    [ci, ci+1] (Arb), whether a box needed the mean value form
    `arb.centered`, tried only with `mean_value`), from at most `boxes`
    evaluations."""
    leaves, stack, n, slope, used = [], [(a, b)], 0, None, False
    while stack:
        u, v = stack.pop()
        n += 1
        if n > boxes:
            raise NoProof("cover of [{}, {}]: budget exhausted", a, b)
        try:
            if _ok(evaluate(e, var, u, v), want, strict):
                leaves.append(u)
                continue
            if mean_value and n > 1:
                slope = derivative(e, var) if slope is None else slope
                if _ok(centered(e, slope, var, u, v), want, strict):
                    leaves.append(u)
                    used = True
                    continue
        except Undefined:
            pass
        if n == 1:                              # undefined or unsigned at an end: no cover can work
            for end in (a, b):
                try:
                    ok = _ok(evaluate(e, var, end, end, bits=192), want, strict)
                except Undefined:
                    ok = False
                if not ok:
                    raise NoProof("no sign at the end {} = {} of [{}, {}]", var, end, a, b)
        if float(v) - float(u) < 1e-12:
            raise NoProof("cover of [{}, {}]: stuck near {}", a, b, f"{float(u):.6g}")
        m = _mid(u, v)
        stack += [(m, v), (u, m)]
    return sorted(leaves, key=float) + [b], used


class Prover:
    """Proposes kernel steps for sign claims about one expression tree.

    `prove(e, var, I, want, strict)` returns a kernel theorem "want*e > 0
    (>= 0) on I" (I = (lo, hi, lo_open, hi_open), hi may be oo) or raises
    NoProof.  Results and failures are memoised per claim."""

    def __init__(self, work=WORK):
        self.memo, self.factored, self.identities, self.together = {}, {}, {}, {}
        self.budget = Budget(work, _design)
        self.spent = NoProof(SPENT)

    def prove(self, e, var, I, want, strict=True, depth=0, near=False):
        """`near`: I is a one-sided neighbourhood of its open end; no further
        splitting there, Taylor at that end instead."""
        key = (e, var, I, want, strict, depth, near)
        if key not in self.memo:
            self.charge(CLAIM_UNITS)        # a claim met before costs a look-up only
            self.memo[key] = _CYCLE
            try:
                self.memo[key] = self._prove(e, var, I, want, strict, depth, near)
            except NoProof as exc:
                self.memo[key] = exc
            except (K.KernelError, Undefined) as exc:     # a sign the kernel cannot decide (a constant's): no proof
                self.memo[key] = NoProof("{}", exc)
            except (TypeError, ValueError, ZeroDivisionError, OverflowError) as exc:   # a step could not be
                self.memo[key] = NoProof("SymPy: {}", exc)     # evaluated (nan compared, 10^400 in a float): no proof
        out = self.memo[key]
        if isinstance(out, NoProof):
            raise out
        return out

    def charge(self, units):
        """Count `units` of work about to be done; stop instead if they would
        overspend the budget (work not done is not counted)."""
        global _charged
        if self.budget.spent(units):
            raise self.spent
        _charged += units

    def _prove(self, e, var, I, want, strict, depth, near):
        lo, hi, lo_open, hi_open = I
        last = None
        polynomial = e.is_polynomial(var)
        if polynomial or K._rational_over_q(e, var):      # exact: Sturm on p, or on N and D of e = N/D
            try:
                self.charge(STURM_UNITS * (_degree_bound(e, var) ** 2 if polynomial else
                                           _fraction_degree(e, var) ** 2 // 8))
                return _rule(K.sign_by_sturm, expr=e, var=var, lo=lo, hi=hi, lo_open=lo_open, hi_open=hi_open,
                             want=want, strict=strict)
            except NoProof as exc:
                if exc is self.spent:
                    raise
                last = exc
        if e.is_rational_function(var) and not e.is_polynomial(var) and not e.has(sp.Float, sp.NumberSymbol):
            size = sp.count_ops(e)
            if size > CHEAP_RATIONAL:           # factoring a large sum costs seconds: a short cover, its terms
                try:
                    return _first_of(([lambda: self._weaken(_cover(e, var, lo, hi, want, strict, QUICK_BOXES), I,
                                                            strict)] if hi != OO else []) +
                                     [lambda: self._structure(e, var, I, want, strict, depth, near)], self)
                except NoProof as exc:
                    if exc is self.spent:
                        raise
                    last = exc
            try:                                # over one denominator: Sturm on the numerator as it is
                return self._rewritten(e, self._together(e), var, I, want, strict, depth, near)
            except NoProof as exc:
                if exc is self.spent:
                    raise
                last = exc
            try:                                # factored over Q: Sturm on each factor
                if not _factorable(e):
                    raise NoProof("{} has constants that factor cannot take", e)
                if e not in self.factored:
                    self.charge(FACTOR_UNITS * size ** 2 if K._rational_over_q(e, var) else _rational_units(size))
                    self.factored[e] = sp.factor(sp.together(e))
                return self._rewritten(e, self.factored[e], var, I, want, strict, depth, near)
            except NoProof as exc:
                last = exc
        if hi == OO and not near and e.has(sp.log, sp.asinh):
            try:                                # rational in a log: Sturm in U = log(...), before costlier forms
                return self._substituted(e, var, I, want, strict, logs_only=True)
            except NoProof as exc:
                if exc is self.spent:
                    raise
        if hi != OO:
            try:                                # defined on the closure: one cover
                return self._weaken(_cover(e, var, lo, hi, want, strict), I, strict)
            except NoProof as exc:
                last = exc
        elif e.is_Add and (shared := _shared_exp(e, var)) is not None:
            try:                                # exp(-s^4/10^4) (s^4 L - ...), cosh(4 s^2)^-2 (16 s^2 tanh(4 s^2) - 1):
                return self._rewritten(e, shared, var, I, want, strict, depth, near)       # no cover at t = 0
            except NoProof as exc:
                if exc is self.spent:
                    raise
        elif want > 0 and e.is_Add:
            try:                                # before the sum's other forms spend the budget
                return self._constant_shared(e, var, I, strict, depth)
            except NoProof as exc:
                if exc is self.spent:
                    raise
        if lo == 0 and (spread := _spread(e, var)) is not None:
            try:                                # (A + B)/s^k, 0/0 at 0 (F'(s)/s of P6), as A/s^k + B/s^k
                return self._rewritten(e, spread, var, I, want, strict, depth, near)
            except NoProof as exc:
                if exc is self.spent:
                    raise
        try:
            return self._structure(e, var, I, want, strict, depth, near)
        except NoProof as exc:
            last = exc
        if not near:
            try:
                return self._substituted(e, var, I, want, strict)
            except NoProof as exc:
                if exc is self.spent:
                    raise
        if near and e.is_Add and any(t.is_Mul and any(a.is_Pow and a.exp.is_negative for a in t.args)
                                     for t in e.args):
            try:                                # 0/0 at the end: 1 - tanh(s)/s = (s - tanh(s))/s
                return self._rewritten(e, self._together(e), var, I, want, strict, depth, near)
            except NoProof as exc:
                if exc is self.spent:
                    raise
        if near:
            return self._taylor(e, var, I, want)
        if hi == OO:
            return self._unbounded(e, var, I, want, strict, depth)
        if lo_open or hi_open:
            return self._split(e, var, I, want, strict, depth)
        raise last

    def _together(self, e):
        """e over one denominator (`sympy.together`), charged `_tail_units`
        the first time it is asked for."""
        if e not in self.together:
            self.charge(_tail_units(sp.count_ops(e)))
            self.together[e] = sp.together(e)
        return self.together[e]

    def _rewritten(self, e, form, var, I, want, strict, depth, near):
        """The sign of e from that of an identical form (`sign_by_rewrite`)."""
        if form == e:
            raise NoProof("no other form")
        return self._rewritten_by(e, form, self.prove(form, var, I, want, strict, depth, near), var, I)

    def _identity(self, **claim):
        """The kernel's `identity`, charged like factoring (its cancel costs so).
        For a nonnegative variable it is first tried on all of (0, oo), where
        it serves every later interval (`sign_by_rewrite` takes an identity
        on a superset)."""
        key = (claim["lhs"], claim["rhs"], claim["var"])
        if key in self.identities:
            return self.identities[key]
        size = max(sp.count_ops(claim["lhs"]), sp.count_ops(claim["rhs"]))
        d = claim["lhs"] - claim["rhs"]
        over_q = K._rational_over_q(d, claim["var"])
        radicals = any(p.exp.is_Rational and not p.exp.is_Integer for p in d.atoms(sp.Pow))
        self.charge(CANCEL_UNITS * size ** 2 if radicals else IDENTITY_UNITS * size)     # (no radicals: the field)
        if not (over_q or K._zero_when_generalized(d, claim["var"])):
            self.charge(_rational_units(size))          # the kernel will try simplify
        if claim["var"].is_nonnegative:
            try:
                th = _rule(K.identity, **{**claim, "lo": 0, "hi": OO, "lo_open": True, "hi_open": True})
                self.identities[key] = th
                return th
            except NoProof:
                pass
        return _rule(K.identity, **claim)

    def _weaken(self, th, I, strict):
        lo, hi, lo_open, hi_open = I
        c = th.claim
        if (K.parse(c.lo), K.parse(c.hi), c.lo_open, c.hi_open, c.strict) == (lo, hi, lo_open, hi_open, strict):
            return th
        return _rule(K.weaken, th, lo=lo, hi=hi, lo_open=lo_open, hi_open=hi_open, strict=strict)

    def _structure(self, e, var, I, want, strict, depth, near=False):
        """Products, sums, odd increasing functions, exp, cosh and log."""
        sub = lambda x, w, st=strict: self.prove(x, var, I, w, st, depth, near)   # noqa: E731
        if e.is_Mul or (e.is_Pow and e.exp.is_Rational):
            premises, sign = [], 1
            for f in sp.Mul.make_args(e):
                if not f.has(var):
                    sign *= K._const_sign(f)
                    continue
                base, n = (f.base, f.exp) if f.is_Pow and f.exp.is_Rational else (f, sp.Integer(1))
                if base == e:
                    raise NoProof("no rule for {}", e)
                if not n.is_Integer:
                    premises.append(sub(base, 1, strict or bool(n < 0)))
                    continue
                st = strict or bool(n < 0)
                first = -1 if _against(base, var, I, 1) else 1      # (the hopeless sign can spend the budget)
                try:
                    p = sub(base, first, st)
                except NoProof:
                    p = sub(base, -first, st)
                premises.append(p)
                sign *= p.claim.want ** int(n % 2)
            if sign != want:
                raise NoProof("the product has the other sign")
            return _rule(K.sign_of_product, *_unique(premises), expr=e)
        if isinstance(e, K._ODD_INCREASING):
            return _rule(K.sign_through_increasing, sub(e.args[0], want), expr=e)
        if isinstance(e, (sp.exp, sp.cosh)) and want > 0:
            y = e.args[0]
            for w in (1, -1):
                try:
                    return _rule(K.sign_through_increasing, sub(y, w, False), expr=e)
                except NoProof:
                    continue
            raise NoProof("{} has no sign on {}", y, I)
        if isinstance(e, sp.log):
            y = e.args[0]
            prem = [sub(y - 1, want)] + ([] if want > 0 else [sub(y, 1, True)])
            return _rule(K.sign_through_increasing, *prem, expr=e)
        if e.is_Add:
            diff = _increasing_difference(e, var)
            if diff is not None:
                g, c, y, sign = diff
                return _rule(K.sign_of_increasing_difference, sub(y - c, want * sign), expr=e, inner=g, c=c)
            try:
                groups = _sum_groups(e, var, I, want)
                premises = []
                for t in groups:
                    try:
                        premises.append(sub(t, want))
                    except NoProof:
                        premises.append(sub(t, want, False))
                return _rule(K.sign_of_sum, *premises, expr=e, want=want)
            except NoProof as exc:
                if exc is self.spent or want < 0 and not e.has(*K._SUP, *K._MAX):
                    raise
                if want < 0:                # a + m G(Y) < 0: tanh(s) - 1
                    return self._below_sup(e, var, I, strict, depth, near, want)
                if _product_split(e, var) is not None:
                    try:
                        return self._below_product(e, var, I, depth, near)
                    except NoProof as again:
                        if again is self.spent:
                            raise
                if not e.has(*_INCREASING, sp.sin, sp.cos):
                    raise
                try:
                    return self._below_sup(e, var, I, strict, depth, near)
                except NoProof as exc:
                    if exc is self.spent:
                        raise
                size = sp.count_ops(e)
                for attempt in (_factored, _tanh_form, _common_factors, None) if size <= CHEAP_RATIONAL else (None,):
                    try:
                        if attempt is None:
                            return self._above_floor(e, var, I, strict, depth, near)
                        form = attempt(e)           # (e itself, at once, when there is nothing to rewrite)
                        if form != e:
                            self.charge(CANCEL_UNITS * size ** 2)
                        return self._rewritten(e, form, var, I, want, strict, depth, near)
                    except NoProof as exc:
                        if exc is self.spent or attempt is None:
                            raise
        raise NoProof("no structural rule for {}", e)

    def _constant_shared(self, e, var, I, strict, depth):
        """e on I = <lo, oo) where its tail form in t = 1/s has no interval
        cover at t = 0, or one only the search's intervals give (exp(-1/t^4):
        `_essential_at_zero`), and e = c - (a_1 + ... + a_k), c > 0: the
        head <lo, R] as any finite interval, and on [R, oo) each c_i - a_i
        >= 0, c_i just above sup a_i there as the search sees it
        (`univariate.term_bound_on_tail`), the c_i adding up to at most c
        (`sign_of_sum`), R the first of R0, 4 R0, 16 R0, 64 R0 where they do
        (R0 = `tail_start`): kf - F' for F = tanh(s^2) + log(1 + s^2), whose F' =
        2 s sech(s^2)^2 + 2 s/(s^2 + 1) has no such cover, and whose F'' the
        sign rules do not sign within a budget."""
        from .univariate import log_factors, split_terms, tail_box, tail_start, term_bound_on_tail
        lo, _, lo_open, _ = I
        c, rest = e.as_independent(var, as_Add=True)
        terms = split_terms(rest)              # (k - F'/s: the 1/s multiplied in)
        if not (c.is_Rational and c > 0 and len(terms) > 1):
            raise NoProof("{} is not c - (a_1 + ... + a_k), c > 0", e)
        R = tail_start(lo)                      # (OverflowError where lo is beyond the doubles: no proof)
        whole = sp.factor_terms(rest)           # A(s) G(L), G rational in a log L: one term (its sum bounded)
        if whole.is_Mul and log_factors(-whole, var, R) is not None:
            terms = (whole,)
        if tail_box(e, var, R) is not None and not _essential_at_zero(_tail_form(e, var)):
            raise NoProof("{} is not c - (a_1 + ... + a_k), c > 0, with a blind tail", e)
        for R in (R, 4 * R, 16 * R, 64 * R):   # (s exp(-s^4/10^4) log(1 + s^2/4) falls beyond 16 only)
            found = [term_bound_on_tail(-t, var, R) for t in terms]    # each a_i >= 0 somewhere on the tail
            if all(b is not None and b[0] >= 0 for b in found) and sum(b[0] for b in found) < c:
                break
        else:
            raise NoProof("the terms of {} are not seen bounded below its constant beyond {}", e, R)
        bounds, hows = zip(*found)
        room = (Fraction(c.p, c.q) - sum(bounds)) / (2 * len(terms))
        step = Fraction(1, 2 ** max(0, math.ceil(-math.log2(room))))      # a short dyadic in (b, b + room]
        shares = [sp.Rational(math.floor(b / step) + 1, 1) * sp.Rational(step.numerator, step.denominator)
                  for b in bounds]
        J, form = (R, OO, False, True), c + sp.Add(*terms)
        tail = _rule(K.sign_of_sum, *[self._share_above(share, -t, how, var, J, depth)
                                      for share, t, how in zip(shares, terms, hows)], expr=form, want=1)
        tail = tail if form == e else self._rewritten_by(e, form, tail, var, J)
        head = self.prove(e, var, (lo, R, lo_open, False), 1, strict, depth)
        return _rule(K.join, head, self._weaken(tail, J, strict))

    def _share_above(self, c, a, how, var, J, depth):
        """c - a >= 0 on the tail J = [R, oo) (`_constant_shared`), first as
        the search bounded a (`how`, see `univariate.term_bound_on_tail`):
        for "product", a = A B with 0 <= B <= b (`bounded_factors`), by
        c/b - A >= 0 (as the search bounded A), B >= 0 and b - B >= 0
        (`sign_below_product`); for "falls", from c - a(R) > 0 and a' <= 0
        on J (`sign_by_monotone`); then as any claim."""
        from .univariate import bounded_factors, term_bound_on_tail
        sub = lambda x, d=depth: self.prove(x, var, J, 1, False, d)    # noqa: E731
        try:
            if how == "product":
                A, B, b = bounded_factors(a, var, J[0])
                below = self._share_above(c / b, A, term_bound_on_tail(A, var, J[0])[1], var, J, depth)
                return _rule(K.sign_below_product, below, sub(B), sub(b - B), expr=c - a, a=c / b, b=b)
            if how == "falls":          # the search's own lemma (`term_bound_on_tail`), remembered, else anew
                falls = sign_theorems(derivative(c - a, var), var, J[0], OO, lo_open=False, strict=False,
                                      work=max(0, self.budget.limit - _work()))[0] or \
                    [sub(derivative(c - a, var), depth + 1)]
                return self._weaken(_rule(K.sign_by_monotone, falls[0], expr=c - a, var=var, R=J[0]), J, False)
        except NoProof as exc:
            if exc is self.spent:
                raise
        return sub(c - a)

    def _below_product(self, e, var, I, depth, near):
        """c - A B >= 0 (`sign_below_product`, see `_product_split`) from
        c/b - A >= 0, B >= 0 and b - B >= 0 (b the least of 1, 2, 4, ...
        that B is not seen above), the last by the same rule again
        or over one denominator (for B = k/Y^n, (Y^n - k)/Y^n): F' =
        2 s/(s^2 + 1) times factors 1/(1 + log(...)) <= 1 stays below c on
        [R, oo) where 2 s/(s^2 + 1) does (a nest of logs, whose forms in
        t = 1/s are not defined at t = 0)."""
        c, A, B = _product_split(e, var)
        b = next((sp.Integer(2) ** k for k in range(21) if not _against(2 ** k - B, var, I, 1)), None)
        if b is None or _against(c / b - A, var, I, 1):
            raise NoProof("A <= {}/b or B <= b fails inside {}", c, I)
        sub = lambda x: self.prove(x, var, I, 1, False, depth, near)    # noqa: E731
        below = sub(c / b - A)
        last = None
        if not (len(sp.Mul.make_args(B)) == 1 and B.is_Pow and B.exp.is_negative):    # 1/Y^n: at once below
            try:
                last = sub(b - B)
            except NoProof as exc:
                if exc is self.spent:
                    raise
        if last is None:
            last = self._rewritten(b - B, sp.together(b - B), var, I, 1, False, depth, near)
        return _rule(K.sign_below_product, below, sub(B), last, expr=e, a=c / b, b=b)

    def _above_floor(self, e, var, I, strict, depth, near):
        """e > 0 where a term t = M G(Y) of e, G increasing, M >= 0, and a
        short rational c <= Y on I give e = (e - t + M G(c)) + M (G(Y) - G(c)),
        each part signed (the second by `sign_of_increasing_difference`)."""
        form = _with_tanh(e)
        for g in sorted((g for g in form.atoms(*_INCREASING) if g.has(var)), key=sp.count_ops):
            try:                                # Y's value at the left end (Y increasing there, or no proof)
                low = evaluate(g.args[0], var, I[0], I[0], bits=64).lo.lower()
            except Undefined:
                continue
            c = sp.Rational(math.floor(float(low) * 64) - 1, 64)
            try:
                return self._split_term(e, form, g, lambda t, G=g.func(c): [form - t + (t / g) * G, (t / g) * (g - G)],
                                        var, I, (strict, False), depth, near)
            except NoProof as exc:
                if exc is self.spent:
                    raise
        raise NoProof("no lower bound of an increasing function makes {} positive", e)

    def _split_term(self, e, form, g, parts_of, var, I, stricts, depth, near):
        """e > 0 from `parts_of(t)` for a term t of form = e that is linear in g."""
        for t in form.args:
            if t.has(g) and not (t / g).has(g):
                try:
                    return self._sum_of_parts(e, parts_of(t), var, I, stricts, depth, near)
                except NoProof as exc:
                    if exc is self.spent:
                        raise
        raise NoProof("no term of {} is linear in {}", e, g)

    def _below_sup(self, e, var, I, strict, depth, near, want=1):
        """want e > 0 where e is a + m G(Y), |G| bounded by sup G (tanh, erf,
        atan, sin, cos; sinh(Y)/cosh(Y) read as tanh(Y)): `sign_below_sup`; or (want = 1) where a
        term t = -M G(Y) of e, M >= 0, gives e = (e - t + t|G=sup G) +
        M (sup G - G(Y)), each part signed (sup G - G(Y) > 0 for tanh, erf,
        atan; >= 0 only for sin and cos, whose maximum is attained); or t =
        M G(Y) the same with G(Y) + sup G >= 0."""
        form = _with_tanh(e)
        for g in sorted((g for g in form.atoms(*K._SUP, *K._MAX) if g.has(var)), key=sp.count_ops):
            a = form.xreplace({g: 0})
            m = form.xreplace({g: 1}) - a
            if not (a.has(var) or m.has(var)) and a + m * g == form:
                y = g.args[0]
                for w in (1, -1):                # any sign of Y on I shows Y defined there
                    try:
                        th = _rule(K.sign_below_sup, self.prove(y, var, I, w, False, depth, near), expr=form, bounded=g,
                                   **({"want": want} if want < 0 else {}))
                        if strict and not th.claim.strict:
                            raise NoProof("{} reaches 0", form)
                        break
                    except NoProof:
                        continue
                else:
                    continue
                return th if form == e else self._rewritten_by(e, form, th, var, I)
            if want < 0:
                continue
            top = {**K._SUP, **K._MAX}[type(g)]
            stricts = (False, strict) if type(g) in K._SUP else (strict, False)
            for end, part in ((top, lambda t: (-t / g) * (top - g)), (-top, lambda t: (t / g) * (g + top))):
                try:        # t = -M G(Y): M (sup G - G(Y)) >= 0; t = M G(Y): M (G(Y) + sup G) >= 0
                    return self._split_term(e, form, g, lambda t: [form - t + t.xreplace({g: end}), part(t)],
                                            var, I, stricts, depth, near)
                except NoProof as exc:
                    if exc is self.spent:
                        raise
        raise NoProof("no bound of a tanh, erf, atan, sin or cos makes {} positive", e)

    def _sum_of_parts(self, e, parts, var, I, stricts, depth, near):
        """e > 0 from parts, positive (strict as asked) unless constant, that
        add up to e exactly: `sign_of_sum` over the parts, `sign_by_rewrite`."""
        if any(_against(p, var, I, 1) for p in parts if p.has(var)):
            raise NoProof("a part is negative somewhere")
        premises = [self.prove(p, var, I, 1, st, depth, near) for p, st in zip(parts, stricts) if p.has(var)]
        form = sum(parts)
        th = premises[0] if not form.is_Add else _rule(K.sign_of_sum, *premises, expr=form, want=1)   # (0 + part)
        return self._rewritten_by(e, form, th, var, I)

    def _rewritten_by(self, e, form, th, var, I):
        lo, hi, lo_open, hi_open = I
        ident = self._identity(lhs=e, rhs=form, var=var, lo=lo, hi=hi, lo_open=lo_open, hi_open=hi_open)
        return _rule(K.sign_by_rewrite, th, ident)

    def _taylor(self, e, var, I, want):
        """Taylor at the open end c of a one-sided neighbourhood I."""
        lo, hi, lo_open, _ = I
        c, side = (lo, 1) if lo_open else (hi, -1)
        m, _ = _derivative_order(e, var, c)
        if m == 0:
            raise NoProof("{} neither vanishes nor is defined at {}", e, c)
        try:
            th = _rule(K.sign_by_taylor, expr=e, var=var, c=c, side=side, width=hi - lo, order=m)
        except NoProof as exc:                  # the m-th derivative's sign on a finer cover of the box
            d = e
            for _ in range(m):                  # as the kernel differentiates: once at a time
                d = derivative(d, var)
            try:
                sigma = evaluate(d, var, c, c, bits=128)
            except Undefined:
                raise exc from None
            if not (sigma.positive() or sigma.negative()):
                raise
            cuts, _ = _cover_cuts(d, var, lo, hi, 1 if sigma.positive() else -1, True)
            th = _rule(K.sign_by_taylor, expr=e, var=var, c=c, side=side, width=hi - lo, order=m, cuts=cuts)
        if th.claim.want != want:
            raise NoProof("{} has the other sign beside {}", e, c)
        return th

    def _near(self, e, var, c, side, want, w, depth):
        """A strict sign on (c, c+w] (side +1) or [c-w, c) (side -1)."""
        I = (c, c + w, True, False) if side > 0 else (c - w, c, False, True)
        return self.prove(e, var, I, want, True, depth, near=True)

    def _one_sided(self, e, var, c, side, want, room, depth):
        """A one-sided lemma at c, trying shrinking widths; where e is not
        defined at c (no Taylor, no cover touching c) only the widest, or
        the widest four for a 0/0 whose numerator and denominator are
        (Taylor after one denominator: `_prove`)."""
        last = None
        try:
            evaluate(e, var, c, c)
            widths = WIDTHS
        except Undefined:
            widths = [w for w in WIDTHS if K._lt(2 * w, room)][:4 if self._quotient_at(e, var, c) else 1]
        for w in widths:
            if K._lt(2 * w, room):
                try:
                    return self._near(e, var, c, side, want, w, depth)
                except NoProof as exc:
                    if exc is self.spent:
                        raise
                    last = exc
        raise NoProof("no one-sided lemma at {}: {}", c, last)

    def _quotient_at(self, e, var, c) -> bool:
        """e is a sum with a negative power whose numerator and denominator
        over one denominator are defined at c."""
        if not (e.is_Add and any(a.exp.is_negative for a in e.atoms(sp.Pow))):
            return False
        try:
            for part in sp.fraction(self._together(e)):
                evaluate(sp.sympify(part), var, c, c)
        except Undefined:
            return False
        return True

    def _split(self, e, var, I, want, strict, depth):
        """One-sided lemmas at the open ends, a cover in between, joined."""
        a, b, a_open, b_open = I
        parts, u, v, right = [], a, b, None
        if a_open:
            parts.append(self._one_sided(e, var, a, 1, want, b - a, depth))
            u = K.parse(parts[0].claim.hi)
        if b_open:
            right = self._one_sided(e, var, b, -1, want, b - a, depth)
            v = K.parse(right.claim.lo)
        parts.append(_cover(e, var, u, v, want, strict))
        if right is not None:
            parts.append(right)
        out = parts[0]
        for p in parts[1:]:
            out = _rule(K.join, self._weaken(out, _ends(out), strict), self._weaken(p, _ends(p), strict))
        return out

    def _substituted(self, e, var, I, want, strict, logs_only=False):
        """e = G(u) for u the argument of a function in e that occurs in e
        more than once (u - sin(u)): G signed in its own variable on J =
        <u(lo), u(hi)> and u(x) in J on I (`sign_by_substitution`).  Interval
        arithmetic on G(U) has no dependency between the two copies of u.
        On a tail, u may also be a log(...) (or asinh) itself when G is
        rational in U (1 - L/(1 + L), L = log(1 + s^2)): Sturm signs G on
        [a, oo), a a rational at or below u(lo), where a cover of the form
        in t = 1/s meets oo/oo at t = 0 (`logs_only`: only these)."""
        lo, hi, lo_open, hi_open = I
        inner = set() if logs_only else {a for g in e.atoms(sp.Function) for a in g.args if a.has(var) and a != var}
        log = log_of(e, var) if hi == OO else None
        for u, is_log in [(u, False) for u in sorted(inner, key=sp.count_ops, reverse=True)] + \
                ([(log, True)] if log is not None else []):
            G = e.xreplace({u: _U}) if is_log else replaced(e, u, _U)      # (a log is a subterm, never a sum)
            if G.has(var) or G.count(_U) < 2 or is_log and not K._rational_over_q(G, _U) or G.subs(_U, u) != e:
                continue
            a, b = (u.subs(var, x) if x != OO else OO for x in (lo, hi))
            if is_log:                  # J's lower end a rational at or below u(lo)
                try:
                    a = K._rational_beyond(a, -1)
                except K.KernelError:
                    continue
            if any(v.free_symbols or v.has(sp.nan, sp.zoo) or v == -OO for v in (a, b)) or not K._lt(a, b):
                continue
            J = (a, b, lo_open, hi_open)
            U = _U if a == 0 or K._lt(0, a) else _U_REAL
            try:
                outer = self.prove(G.subs(_U, U), U, J, want, strict)
                bounds = [self.prove(u - a, var, I, 1, lo_open)] + (       # strict where J is open
                    [self.prove(b - u, var, I, 1, hi_open)] if b != OO else [])
                return _rule(K.sign_by_substitution, outer, *bounds, inner=u)
            except NoProof as exc:
                if exc is self.spent:
                    raise
        raise NoProof("no substitution signs {}", e)

    def _log_bound(self, e, var, I, want, strict, depth):
        """e on the tail I = [R, oo) by `sign_by_log_bound`: one term M log(Y)
        (or M asinh(X), a log of X + sqrt(X^2 + 1)) of the sum e replaced by
        M (Y^p - 1)/p, p > 0 where M has the sign -want, p = -1 (1 - 1/Y)
        where it has the sign want; or one term M exp(Y), Y <= 0 on I and M
        with the sign -want, by M/T(-Y), T(z) = 1 + z + ... + z^p/p!, p = 4
        or 8 (an algebraic tail where log's or exp's is not)."""
        for term in e.args:
            split = K._log_term(term)
            if split is None:
                continue
            m, y, g = split
            rest = [a for a in e.args if a != term]
            for p in (4, 8) if g is sp.exp else (sp.Integer(1), sp.Rational(1, 4), sp.Rational(1, 16), -sp.Integer(1)):
                z, bound = K._log_bound_of(y, g, p)
                b, m_sign = sp.Add(*rest, m * bound), -want * (1 if p > 0 else -1)
                if not (_plausible(b, var, I[0], want) and _plausible(m, var, I[0], m_sign)):
                    continue                    # false somewhere: do not spend the budget on it
                try:
                    positive = self.prove(z, var, I, 1, g is not sp.exp, depth)
                    coeff = self.prove(m, var, I, m_sign, False, depth)
                    bound = _tail_first(self, b, var, I[0], want, strict, depth)
                    return _rule(K.sign_by_log_bound, bound, coeff, positive, expr=e, term=term, p=p)
                except NoProof as exc:
                    if exc is self.spent:
                        raise
        raise NoProof("no term M log(Y) or M exp(Y) of {} to bound", e)

    def _unbounded(self, e, var, I, want, strict, depth):
        """[lo, R] as a finite interval, [R, oo) by c - A B in s (R, 4R or
        16R), s = 1/t or monotonicity."""
        from .univariate import T, tail_start
        lo, _, lo_open, _ = I
        R = tail_start(lo)
        tail, last = None, NoProof("no tail rule for {}", e)
        for start in (R, 4 * R, 16 * R) if want > 0 and not strict and _product_split(e, var) else ():
            try:                                # c - A B in s: no identity with a form in t to check
                tail, R = self._below_product(e, var, (start, OO, False, True), depth, False), start
                break
            except NoProof as exc:
                if exc is self.spent:
                    raise
        try:
            if tail is None:
                self.charge(_tail_units(sp.count_ops(e)))
                et = _tail_form(e, var)
                th = self.prove(et, T, (sp.Integer(0), 1 / R, True, False), want, strict, depth)
                ident = self._identity(lhs=et, rhs=e.xreplace({var: 1 / T}), var=T, lo=0, hi=1 / R,
                                       lo_open=True, hi_open=False)       # only now: simplify may be slow
                tail = _rule(K.sign_on_tail, th, ident, expr=e, var=var, R=R)
        except NoProof as exc:
            last = exc
        if tail is None and e.has(sp.tanh, sp.sinh, sp.erf, sp.atan, sp.sin, sp.cos):
            try:                                # bounded functions beyond R, by the sign rules in s
                tail = self._structure(e, var, (R, OO, False, True), want, strict, depth)
            except NoProof as exc:
                if exc is self.spent:
                    raise
        if tail is None and depth < 1:
            try:
                d = derivative(e, var)
                if not _plausible(d, var, R, want):     # (e -> 0 from the side want, as an exp tail does)
                    raise NoProof("{} is seen to have the sign {} beyond {}", d, -want, R)
                dth = self.prove(d, var, (R, OO, False, True), want, False, depth + 1)
                tail = self._weaken(_rule(K.sign_by_monotone, dth, expr=e, var=var, R=R), (R, OO, False, True), strict)
            except NoProof as exc:
                if exc is self.spent:
                    raise
        if tail is None and e.is_Add and e.has(sp.log, sp.asinh, sp.exp):
            logs = e.has(sp.log, sp.asinh)
            for start in (16 * R, 256 * R):         # the bound (Y^p - 1)/p of log Y is loose: start late
                J = (start, OO, False, True)        # a log in a denominator: over one denominator first;
                try:                                # the terms of one exp(Y) as one M exp(Y)
                    tail, R = _first_of([
                        lambda: self._log_bound(e, var, J, want, strict, depth),
                        (lambda: self._rewritten(e, _over_one_denominator(e), var, J, want, strict, depth, False))
                        if logs else (lambda: self._rewritten_by(e, _exp_collected(e), self._log_bound(
                            _exp_collected(e), var, J, want, strict, depth), var, J))], self), start
                    break
                except NoProof as exc:
                    if exc is self.spent:
                        raise
        if tail is None:
            raise last
        head = self.prove(e, var, (lo, R, lo_open, False), want, strict, depth)
        return _rule(K.join, head, tail)


_INCREASING = (sp.tanh, sp.atan, sp.asinh, sp.sinh, sp.erf, sp.exp)


def _tanh_pairs(m):
    """The product m with sinh(a)^k cosh(a)^-j written tanh(a)^n sinh(a)^(k-n)
    cosh(a)^(n-j), n = min(k, j): structurally, not by `subs` (see `replaced`)."""
    exps = dict(a.as_base_exp() for a in m.args)
    if len(exps) != len(m.args):        # two factors on one base (2 sqrt(2)): left alone
        return m
    for b in [b for b in exps if isinstance(b, sp.sinh)]:
        c, t = sp.cosh(b.args[0]), sp.tanh(b.args[0])
        k, j = exps[b], -sp.sympify(exps.get(c, 0))
        if k.is_Integer and j.is_Integer and k > 0 and j > 0:
            n = min(k, j)
            exps[b], exps[c], exps[t] = k - n, n - j, exps.get(t, 0) + n
    return sp.Mul(*[b ** x for b, x in exps.items()])


def _tanh_form(e):
    """e with sinh(a)/cosh(a) written tanh(a) (SymPy's derivative of
    log(cosh(a))) and its terms grouped by powers of its variable, so that
    the bounded-function rules see it; else e."""
    out = e.replace(lambda m: m.is_Mul and m.has(sp.sinh), _tanh_pairs)
    if out == e:
        return e
    var = next(iter(e.free_symbols), None)          # its terms grouped by powers of var: h^2 (1 - tanh^2)
    return sp.collect(sp.expand(out), var) if var is not None else out


def _factorable(e) -> bool:
    """e has no constant power of E: `factor` reads exp(-85525571/64) as
    a power of E^(1/64) (x^2 - exp(-85525571/64) did not factor within a
    minute), where it takes sqrt(3), pi or erf(31/32) as one more generator."""
    return all(a.free_symbols for a in e.atoms(sp.exp))


def _factored(e):
    """e factored when it holds a square or higher power of a bounded
    function (1 - tanh(y)^2 = (1 - tanh y)(1 + tanh y)), each factor of the
    form c - B with the sign that makes it nonnegative for B below sup, else e."""
    if not any(p.exp.is_Integer and p.exp > 1 and type(p.base) in (*K._SUP, *K._MAX) for p in e.atoms(sp.Pow)) \
            or not _factorable(e):
        return e
    f = sp.factor(e)
    coeff, factors = f.as_coeff_mul()
    if coeff < 0:           # B - c as c - B
        i = next((i for i, x in enumerate(factors) if x.is_Add and x.as_coeff_Add()[0] < 0), None)
        if i is None:
            return e
        factors = factors[:i] + (-factors[i],) + factors[i + 1:]
        coeff = -coeff
    return sp.Mul(*([coeff] if coeff != 1 else []), *factors, evaluate=False) if f.is_Mul else e


def _shared_exp(e, var):
    """e with the factors common to its terms taken out (`factor_terms`) when
    they hold an exp, cosh or sinh of var (or a power of one), else None
    (at once when e has none: `factor_terms` of a large sum takes long)."""
    if not any(g.has(var) for g in e.atoms(sp.exp, sp.cosh, sp.sinh)):
        return None
    f = sp.factor_terms(e)
    return f if f.is_Mul and any(isinstance(a.base if a.is_Pow else a, (sp.exp, sp.cosh, sp.sinh)) and a.has(var)
                                 for a in f.args) else None


def _common_factors(e):
    """e with the factors common to its terms taken out (`factor_terms`, no
    polynomial factoring): 16 s^4 exp(-s^4) - 4 exp(-s^4) = 4 (4 s^4 - 1)
    exp(-s^4), whose sign is that of its factors on any interval, where a
    cover of the sum needs boxes narrower than 1/s^3.  Else, expanded, the
    terms that share their exponentials grouped and factored, and those with
    none over one denominator: 2 s (-2 s exp(-s^2) - 2 s/(s^2 + 1)^2) +
    2 exp(-s^2) + 2/(s^2 + 1) (F'' of log(1 + s^2) + 1 - exp(-s^2)) as
    2 (1 - s^2)/(s^2 + 1)^2 + 2 (1 - 2 s^2) exp(-s^2), both parts negative
    beyond s = 1, while in t = 1/s the sum's t^-2 exp(-t^-2) has no
    enclosure at t = 0.  e itself when nothing is gained."""
    f = sp.factor_terms(e)
    c, rest = f.as_coeff_Mul()
    if not rest.is_Add:
        return f if f.is_Mul else e
    groups = {}
    for t in sp.Add.make_args(sp.expand(rest)):
        key = frozenset(a for a in sp.Mul.make_args(t) if isinstance(a, sp.exp) and a.free_symbols)
        groups.setdefault(key, []).append(t)
    if len(groups) < 2:
        return e
    parts = [sp.together(sp.Add(*ts)) if not key else sp.factor_terms(sp.Add(*ts)) for key, ts in groups.items()]
    return sp.Add(*[c * p for p in parts])


def _increasing_difference(e, var):
    """(k G(Y), c, Y, sign of k) if e = k G(Y) - k G(c), G increasing, c and
    k != 0 constants (G(c) as SymPy evaluates it: exp(0) = 1); else None."""
    if len(e.args) == 2:
        for a, b in (e.args, e.args[::-1]):
            k, g = a.as_independent(var, as_Add=False)
            if type(g) not in _INCREASING or b.has(var) or k == 0:
                continue
            v = -b / k                  # = G(c)
            c = v.args[0] if type(v) is type(g) else sp.Integer(0) if g.func(0) == v else None
            if c is None:
                continue
            try:
                return a, c, g.args[0], K._const_sign(k)
            except K.KernelError:
                return None
    return None


def _sum_groups(e, var, I, want) -> list:
    """The parts of the sum e for `sign_of_sum`, each to have the sign want:
    its terms, or, where a term or the constant has the other sign
    somewhere, the rational terms together (9 s^2 - 20 s + 9, signed by
    Sturm) and the others one by one (the logs' terms of a numerator put over
    one denominator), or the terms that are rational in one log(...) L
    together (L^2/(2 + L) - L/2, signed by Sturm in L), or, when only the
    constant has the other sign, the constant with one term (s^(3/2) +
    (sqrt(s^2 + 1) - 1)); NoProof when a term with the other sign is left
    alone."""
    terms = [t for t in e.args if t.has(var)]
    constant = sp.Add(*[t for t in e.args if not t.has(var)])
    clear = not any(_against(t, var, I, want) for t in terms)
    if clear and K._const_sign(constant) != -want:
        return terms
    shared = _by_denominator(terms, var)
    if 1 < len(shared) < len(terms) and K._const_sign(constant) != -want and \
            not any(_against(t, var, I, want) for t in shared):
        return shared
    rational = [t for t in e.args if t.is_rational_function(var)]
    others = [t for t in terms if not t.is_rational_function(var)]
    if others and not any(_against(t, var, I, want) for t in others) and not _against(sp.Add(*rational), var, I, want):
        return [sp.Add(*rational), *others]
    for group in log_groups(terms, var).values():      # the terms rational in one L = log(...): Sturm in L
        rest = [t for t in terms if t not in group]
        if len(group) > 1 and K._const_sign(constant) != -want and \
                not any(_against(t, var, I, want) for t in [sp.Add(*group), *rest]):
            return [sp.Add(*group), *rest]
    for i, t in enumerate(terms if clear and len(terms) > 1 else ()):  # s^(3/2) + (sqrt(s^2 + 1) - 1)
        if set(_signs(t + constant, var, I, want)) == {1}:      # seen to have the sign, not just not against
            return [t + constant, *terms[:i], *terms[i + 1:]]
    raise NoProof("a term of {} has the other sign", e)


def _by_denominator(terms, var) -> list:
    """The terms summed in groups of one denominator (the set of bases of
    their negative powers): a derivative's terms 6 s x^2/(10 x^3 + 10) - 60 s
    x^5/(10 x^3 + 10)^2 of opposite signs, whose sum has one sign."""
    groups = {}
    for t in terms:
        key = frozenset(b for b, n in (f.as_base_exp() for f in sp.Mul.make_args(t)) if n.is_negative and b.has(var))
        groups.setdefault(key, []).append(t)
    return [sp.Add(*g) for g in groups.values()]


def _product_split(e, var):
    """(c, A, B) for e = c - A B, c > 0 a constant, A the rational factors
    of the product (its constant included) and B the others, or A the first
    of these and B the rest when there are no rational factors; None when e
    is not of this form or A or B would be constant."""
    c, rest = e.as_independent(var, as_Add=True)
    if not (c.is_number and c.is_positive) or rest.is_Add or not rest.could_extract_minus_sign():
        return None
    factors = sp.Mul.make_args(-rest)
    rational = [f for f in factors if f.is_rational_function(var)]
    others = [f for f in factors if not f.is_rational_function(var)]
    if not others:
        return None
    A, B = (sp.Mul(*rational), sp.Mul(*others)) if any(f.has(var) for f in rational) else \
        (sp.Mul(*rational, others[0]), sp.Mul(*others[1:]))
    return (c, A, B) if A.has(var) and B.has(var) else None


def _signs(t, var, I, want) -> list[int]:
    """At three inner points of I (Arb, 64 bits), +1 where t has the sign
    want, -1 where it has the other, 0 where the enclosure cannot tell."""
    lo, hi = I[0], I[1]
    points = [lo + sp.Rational(1, 16), lo + 1, lo + 16] if hi == OO else \
        [lo + (hi - lo) * sp.Rational(k, 8) for k in (1, 4, 7)]
    out = []
    for p in points:
        try:
            v = evaluate(t, var, p, p, bits=64)
        except Undefined:
            continue
        out.append(1 if (v.positive() if want > 0 else v.negative()) else
                   -1 if (v.negative() if want > 0 else v.positive()) else 0)
    return out


def _against(t, var, I, want) -> bool:
    """t has the sign -want at one of three inner points of I (Arb): no sum
    rule can use t."""
    return -1 in _signs(t, var, I, want)


def _with_tanh(e):
    """e with each sinh(Y)/cosh(Y) in a product written tanh(Y)."""
    def fix(m):
        args = list(m.args)
        for a in m.args:
            if isinstance(a, sp.sinh) and 1 / sp.cosh(a.args[0]) in args:
                args.remove(a)
                args.remove(1 / sp.cosh(a.args[0]))
                args.append(sp.tanh(a.args[0]))
        return sp.Mul(*args)
    return e.replace(lambda x: x.is_Mul, fix)


def _ends(th):
    c = th.claim
    return K.parse(c.lo), K.parse(c.hi), c.lo_open, c.hi_open


def _tail_form(e, var):
    from .univariate import tail_form
    return tail_form(e, var)


def _essential_at_zero(et) -> bool:
    """The tail form et has exp, erf, cosh, sinh or tanh of an argument with
    a negative power of t: no Taylor expansion at t = 0, and the kernel's
    Arb has no value there (the search's intervals take limits)."""
    from .univariate import T
    return any(a.has(T) and any(p.base.has(T) and p.exp.is_negative for p in a.atoms(sp.Pow))
               for g in et.atoms(sp.exp, sp.erf, sp.cosh, sp.sinh, sp.tanh) for a in g.args)


def _derivative_order(e, var, c):
    """m and E^(m) with E(c) = ... = E^(m-1)(c) = 0 exactly, E^(m)(c) != 0."""
    d = e
    for m in range(TAYLOR_ORDER + 1):
        if not _exactly_zero(d.xreplace({var: c})):     # (a TypeError out of SymPy: no proof, Prover.prove)
            return m, d
        d = derivative(d, var)
    raise NoProof("Taylor order too high")


def _exactly_zero(v) -> bool:
    """v is 0 as the kernel's Taylor rule sees it (`_const_sign`)."""
    try:
        return v == 0 or K._const_sign(v, zero=True) == 0
    except (K.KernelError, Undefined):
        return False


def _unique(premises):
    seen, out = set(), []
    for p in premises:
        if p.claim.expr not in seen:
            seen.add(p.claim.expr)
            out.append(p)
    return out


_FOUND: dict = {}          # lemmas already proved in this process
_FAILED: dict = {}         # sign lemmas not proved: the work they had, and why


def sign_theorems(e, var, lo, hi, want=1, lo_open=True, hi_open=True, zeros=(), strict=True, work=WORK):
    """Kernel theorems whose union is the sign lemma: one theorem on each
    part of <lo, hi> between the exact `zeros` (strict claims exclude them),
    or None with the reason when the kernel did not accept a step."""
    key = (e, var, lo, hi, want, lo_open, hi_open, tuple(zeros), strict)
    if key not in _FOUND:
        if _FAILED.get(key, (-1, ""))[0] >= work:      # failed before with as much work: fails again
            return None, _FAILED[key][1]
        # the budget counts work between SymPy's calls; one call can run for minutes (an assumption
        # query of diff that isolates the real roots of a huge polynomial): a wall-clock backstop too
        theorems, why = timeouts.attempt(lambda: _sign_theorems(e, var, lo, hi, want, lo_open, hi_open, zeros, strict,
                                                                work), WALL_CAP * UNIT_SECONDS * work * machine_factor(), STOPPED)
        if theorems is None:
            _remember(key, (work, why), _FAILED)
            return None, why
        _remember(key, theorems)
    return _FOUND[key], ""


def _remember(key, found, store=_FOUND):
    """Keep a lemma proved (in `_FOUND`: asked again, it costs no budget),
    or a failure (in `_FAILED`); at most 512 of each."""
    if len(store) > 512:
        store.clear()
    store[key] = found


def _sign_theorems(e, var, lo, hi, want, lo_open, hi_open, zeros, strict, work):
    lo, hi = sp.sympify(lo), sp.sympify(hi)
    pts = sorted(set(map(sp.sympify, zeros)), key=float)
    ends = [lo, *pts, hi]
    prover = Prover(_scaled(work, e))
    try:
        return [prover.prove(sp.sympify(e), var, (ends[i], ends[i + 1], lo_open if i == 0 else True,
                                                  hi_open if i == len(ends) - 2 else True), want, strict)
                for i in range(len(ends) - 1)], ""
    except (NoProof, K.KernelError, Undefined) as exc:
        return None, str(exc)


def piecewise_sign_theorem(P, ends, var, want=1, strict=True, work=2 * WORK, zeros=()):
    """want*P > 0 (>= 0 if not strict) on (0, oo) for P a Piecewise or an
    expression of one, as one kernel theorem, or (None, why).  `ends`: the
    search's boundaries 0 < b1 < ... < oo; `zeros`: exact points inside the
    pieces where P touches 0 (weak claims only), cut there too.  On each
    open piece the branch that applies is signed (`on_branch`);
    `join_at_point` joins the pieces through P's value at each cut.  Each
    piece is a lemma of its own, with its own budget `work` (its relations'
    signs included), scaled to the largest branch (`_scaled`)."""
    folded = sp.piecewise_fold(P)
    if not isinstance(folded, sp.Piecewise):
        return None, f"{P} is not a Piecewise"
    key = ("piecewise", P, tuple(ends), var, want, strict, tuple(zeros))
    if key in _FOUND:
        return _FOUND[key], ""
    work = _scaled(work, max((g for g, _ in folded.args), key=sp.count_ops))
    cuts = sorted({*ends[:-1], *zeros}, key=float) + [ends[-1]]
    try:
        whole = None
        for lo, hi in zip(cuts, cuts[1:]):
            I, prover = (lo, hi, True, True), Prover(work)
            th = on_branch(P, var, I, prover, lambda g: prover.prove(g, var, I, want, strict))
            whole = th if whole is None else _rule(K.join_at_point, whole, th)
    except (NoProof, K.KernelError, Undefined) as exc:
        return None, str(exc)
    _remember(key, whole)
    return whole, ""


def on_branch(P, var, I, prover, about):
    """A kernel claim about P (a Piecewise or an expression of one) on I from
    `about(G)`, a theorem about the branch G that applies on I: the
    relations r - l of P's conditions are signed on I (strict, the sign at
    an inner point), the kernel picks the branch from them (`select_branch`)."""
    signs = _relation_signs(P, var, I)
    have = {(t.claim.expr, t.claim.want) for t in signs}
    branch = K._branch(K._folded(P), lambda d, w, st: K._sign_ok(K._const_sign(d), w, st) if not d.has(var)
                       else (K._s(d), w) in have)
    return _rule(K.select_branch, about(branch), *signs, expr=P)


def _relation_signs(P, var, I):
    """Strict sign theorems on I of every relation r - l of P's conditions
    (the sign at an inner point); an equation's is left out where it has
    none (it may hold at one point of I: the kernel's `_branch` then asks
    that its branch agree there with the branch that applies around it)."""
    signs = []
    for d, eq in dict.fromkeys((r.rhs - r.lhs, isinstance(r, sp.Eq)) for _, c in K._folded(P).args
                               for r in _relationals(c)):
        try:
            signs += [_relation_sign(d, var, I)] if d.has(var) else []
        except NoProof:
            if not eq:
                raise
    return signs


@functools.lru_cache(maxsize=4096)
def _relation_sign(d, var, I):
    """d > 0 or d < 0 on I, the sign at an inner point, with a budget of its
    own; memoised (each theorem about a Piecewise asks for them again)."""
    lo, hi = I[:2]
    inner = _mid(lo, hi) if hi != OO else lo + 1
    box = evaluate(d, var, inner, inner, bits=128)
    want = 1 if box.positive() else -1
    try:
        return Prover(WORK).prove(d, var, I, want, True)
    except NoProof:
        if I[2] and I[3]:
            raise
        return Prover(WORK).prove(d, var, I, want, False)    # d may vanish at a closed end (the point of a join)


def piecewise_sup_theorems(F, c, point, var, ends, lower=None, work=2 * WORK):
    """kf = sup F' = c on (0, oo) for a Piecewise F (`ends` its boundaries):
    the conclusions of `sup_theorems` -- F' > 0, c - F' >= 0, sup F' >= c
    (the value at `point` or the limit at oo of the branch there, `widen`ed
    to (0, oo)) -- then F and F' continuous on (0, oo); or (None, why).
    `lower` < c: kf is only enclosed in [lower, c], and the last conclusion
    is sup F' >= lower, by F'(point) >= lower.  `work`: the budget of each
    piece's sign lemmas (`piecewise_sign_theorem`)."""
    dF = derivative(F, var)
    try:
        try:
            whole, jumps = continuity_pair(F, var, ends), False     # first: cheap, and often what fails
        except NoProof:
            whole, jumps = branches_pair(F, var, ends), True
        if not isinstance(sp.piecewise_fold(dF), sp.Piecewise):      # one formula for F' (F jumps by constants)
            if lower is not None:
                raise NoProof("kf of a Piecewise F whose F' is one formula is enclosed only")
            positive, why = sign_theorems(dF, var, 0, OO)
            theorems, why = sup_theorems(dF, c, point, var, positive[0]) if positive else (None, why)
            if theorems is None:
                raise NoProof(why)
            return [*theorems, *whole], ""
        positive, why = piecewise_sign_theorem(dF, ends, var, strict=not jumps)     # (whatever c: its own budget)
        inside = [point] if point is not None and lower is None and point not in ends else []
        upper, why = (piecewise_sign_theorem(sp.sympify(c) - dF, ends, var, strict=False, work=work, zeros=inside)
                      if positive else (None, why))
        if upper is None:
            raise NoProof(why)
        upper = _rule(K.sup_upper_by_sign, upper, expr=dF, bound=c)
        below = _piecewise_lower(dF, c if lower is None else lower, point, var, ends)
        if not jumps:       # (where F jumps, the sup must stay on a piece: see design_certificate._link_kf)
            below = _rule(K.widen, below, lo=0, hi=OO, lo_open=True, hi_open=True)
        return [positive, upper, below, *whole], ""
    except (NoProof, K.KernelError, Undefined) as exc:
        return None, str(exc)


def _piecewise_lower(dF, c, point, var, ends):
    """sup F' >= c on a piece: F'(point) = c when the point lies inside a
    piece, else (a boundary point, or c approached) c = lim F' at oo."""
    prover = Prover(WORK)
    pieces = [*zip(ends, ends[1:])] if point is not None else []
    inside = [(a, b, True, True) for a, b in pieces if K._lt(a, point) and K._lt(point, b)] or \
        [(a, b, a != point, b != point) for a, b in pieces if point in (a, b) and point not in (0, OO)]
    for I in inside:        # (at a join: the piece on either side, closed at the point, whose branch applies there)
        try:
            return on_branch(dF, var, I, prover, lambda g: _rule(
                K.sup_lower_by_point, expr=g, var=var, point=point, bound=c, lo=I[0], hi=I[1], lo_open=I[2],
                hi_open=I[3]))
        except (NoProof, K.KernelError, Undefined):
            pass
    R = _beyond(ends[-2])
    lower = on_branch(dF, var, (R, OO, False, True), prover, lambda g: _rule(
        K.sup_lower_from_limit, limit_at_infinity(g, var), lo=R, lo_open=False))
    if K.parse(lower.claim.other) != sp.sympify(c):
        raise NoProof("F' tends to {}, not {}", lower.claim.other, c)
    return lower


def _beyond(b):
    """A power of 4 greater than b >= 0 (the start of a tail past every boundary)."""
    return sp.Integer(4 ** math.ceil(math.log(max(float(b), 1) + 1, 4)))


def continuity_theorem(P, ends, var, rule=K.continuous_piecewise):
    """P (a Piecewise) continuous on (0, oo) as a kernel theorem
    (`continuous_piecewise`, the relations signed on each open piece
    between the search's `ends` 0 < b1 < ... < oo), or None.  With
    rule=`piecewise_branches`: P continuous on each open piece only."""
    if not isinstance(P, sp.Piecewise):
        return None
    key = ("continuous", P, tuple(ends), var, rule.__name__)
    if key not in _FOUND:
        try:                                        # every relation signed on every piece
            signs = [t for lo, hi in zip(ends, ends[1:])
                     for t in _relation_signs(P, var, (lo, hi, True, True))]
            _remember(key, _rule(rule, *signs, expr=P, var=var, cuts=list(ends[1:-1])))
        except (NoProof, K.KernelError, Undefined):
            return None
    return _FOUND[key]


def one_branch_theorems(F, var):
    """(G, [F = G on (0, oo), F(0) - G(0) = 0]) when the Piecewise profile F
    follows one branch G at every s > 0 (its conditions signed there,
    `on_branch`) and takes G's value at 0, or (G, [F = G on (0, oo), G(0+) =
    L, F(0) - L = 0]) when G is 0/0 at 0 (Piecewise((0, Eq(s, 0)),
    (sinh(s^2)/s^2 - 1, True))): then the kernel's lemmas may be about G
    (`design_certificate._one_branch`); (G, [F = G on (0, oo)]) when F(0) is
    another value (enough for P3 and P8); else (F, [])."""
    if not F.has(sp.Piecewise):
        return F, []
    prover = Prover(WORK)
    try:
        th = on_branch(F, var, (sp.Integer(0), OO, True, True), prover,
                       lambda g: _rule(K.identity, lhs=g, rhs=g, var=var, lo=0, hi=OO, lo_open=True, hi_open=True))
        G = K.parse(th.claim.other)
        if G.subs(var, 0).has(sp.nan, sp.zoo):       # 0/0 at 0: F(0) against the limit G(0+) (`taylor_limit`)
            lim = taylor_limit(G, var, sp.Rational(1, 16))
            at_zero = [lim, _rule(K.value_sign, value=F.subs(var, 0) - K.parse(lim.claim.other))]
        else:
            at_zero = [_rule(K.value_sign, value=F.subs(var, 0) - G.subs(var, 0))]
        return (F, []) if G.has(sp.Piecewise) else (G, [th, *at_zero] if at_zero[-1].claim.want == 0 else [th])
    except (NoProof, K.KernelError, Undefined, IndexError):
        return F, []


def radial_theorems(f, F, x, y, var, ratio=1) -> list:
    """The reduction f(x, y) = F(sqrt(x^2 + r y^2)) at every point of the
    plane as kernel theorems, or []: the kernel's `identity_plane` (where
    both sides are defined), for r != 1 also r > 0 (`value_sign`), and f
    defined on the plane (`defined_on_plane`).  P4 when r = 1, the elliptic
    reduction otherwise."""
    try:
        ident = K.identity_plane(lhs=f, rhs=F.subs(var, sp.sqrt(x ** 2 + ratio * y ** 2)), x=x, y=y)
        return [ident, *([] if ratio == 1 else [K.value_sign(value=ratio)]), K.defined_on_plane(expr=f, x=x, y=y)]
    except (K.KernelError, Undefined):
        return []


def plane_theorems(f, x, y, exprs) -> list:
    """f and each expression of `exprs` (formulas of its derivatives) defined,
    hence continuous, at every point of the plane, as kernel theorems
    (`continuous_on_plane`), or [] when the kernel does not show one."""
    try:
        return [K.continuous_on_plane(expr=e, x=x, y=y) for e in (f, *exprs)]
    except (K.KernelError, Undefined):
        return []


def separable_theorems(f, x, y, split) -> list:
    """f defined, hence continuous, on the plane and f = split there (the
    sum f(x, 0) + f(0, y)), as kernel theorems, or []."""
    try:
        return [K.continuous_on_plane(expr=f, x=x, y=y), K.identity_plane(lhs=f, rhs=split, x=x, y=y)]
    except (K.KernelError, Undefined):
        return []


def growth_theorems(F, var, last=None) -> list:
    """P3's "F(s) -> oo": `diverges_by_growth` from F' >= k or s F' >= k > 0
    on [R, oo) (the proposer picks R, the rate and k), or [].  For a
    Piecewise F, `last` is the start of its last piece: R lies beyond it and
    the divergence of the branch there becomes F's (`on_branch`)."""
    if isinstance(F, sp.Piecewise):
        R = _beyond(last)
        prover = Prover(WORK)
        try:
            return [on_branch(F, var, (R, OO, False, True), prover,
                              lambda g: (_diverges(g, var, (R,)) or _diverges_above(g, var, (R,)))[0])]
        except (NoProof, IndexError, K.KernelError, Undefined):
            return []
    G = _outer(F, var)
    if G is not None and G.args[0].atoms(sp.Function):     # a nest: the rates grow slow and dear
        return _diverges_inside(F, var) or _diverges(F, var, (sp.Integer(4), sp.Integer(16))) or \
            _diverges_above(F, var)
    return _diverges(F, var, (sp.Integer(4), sp.Integer(16))) or _diverges_above(F, var) or _diverges_inside(F, var)


def _outer(F, var):
    """G for F = a + m G(Y), a and m constants (m > 0: the kernel checks), G
    increasing and unbounded (`unbounded_increasing`), else None."""
    G = F.as_independent(var, as_Add=True)[1].as_independent(var)[1]
    return G if K.unbounded_increasing(G) else None


def _diverges_inside(F, var) -> list:
    """F = a + m G(Y) -> oo because Y -> oo, a and m > 0 constants, G
    increasing and unbounded (log, exp, sinh, asinh, Y^p): `diverges_through_increasing`
    (log(1 + log(1 + s^2)), slower than any rate `diverges_by_growth` knows;
    nested deeper through a = 1)."""
    G = _outer(F, var)
    if G is None:
        return []
    inner = growth_theorems(G.args[0], var)
    try:
        return [_rule(K.diverges_through_increasing, inner[0], expr=F)] if inner else []
    except NoProof:
        return []


def _diverges_above(F, var, starts=(sp.Integer(4), sp.Integer(16))) -> list:
    """F -> oo because F >= G -> oo (`diverges_by_comparison`) on [R, oo), R
    from `starts`, G being F with each term c B(Y), B = sin, cos (|B| <= 1)
    or tanh, erf, atan, replaced by its floor -|c| sup|B|: F - G is then
    a + m B(Y) >= 0; or, when F has algebraic terms, G their sum, or the sum
    of the others: F - G is the sum of the rest, which must be >= 0 (a
    vanishing transcendental term beside a power, sqrt(h)/2 + 10 (1 -
    tanh(h^-2)^2)/(3 h); bounded rational terms beside a log); or, for a
    product A B of functions of h, A B(R0), R0 the first start (F - G =
    A (B - B(R0)) >= 0 where B increases); a product c(h) (A + B) is read
    as c A + c B."""
    spread = sp.expand_mul(F, deep=False)
    terms = sp.Add.make_args(spread)
    bounded = {t: abs(c) * {**K._SUP, **K._MAX}[type(b)] for t in terms
               for c, b in [t.as_independent(var)] if type(b) in (*K._SUP, *K._MAX) and not c.has(var)}
    algebraic = [t for t in terms if not t.atoms(sp.Function)]
    transcendental = [t for t in terms if t.atoms(sp.Function)]
    floors = [sp.Add(*[-bounded[t] if t in bounded else t for t in terms])] if bounded else []
    factors = [b for b in sp.Mul.make_args(F) if b.has(var)]
    gaps = {F / b * b.subs(var, starts[0]): F / b * (b - b.subs(var, starts[0])) for b in factors} \
        if len(factors) > 1 else {}             # G = A B(R0): F - G = A (B - B(R0))
    leading = _leading_terms(terms, var)
    prover = Prover(_scaled(WORK, F))
    subsets = [sp.Add(*ts) for ts in (algebraic, leading, transcendental) if ts and len(ts) < len(terms)]
    for G0 in floors + subsets + [*gaps] + _log_powers(F, var):
        G = _as_tanh(G0)
        nest = _outer(G, var) is not None
        for R in starts if nest or _plausible(G - 2 * G.subs(var, starts[0]) - 1, var, 10 ** 6, 1) else ():
            gap = F - G0 if spread == F and G0 not in gaps else gaps.get(G0, spread - G0)
            if not _plausible(gap, var, R, 1):     # (F >= G seen false: its proof would spend the budget)
                continue
            try:                        # (a nest of logs grows too slowly for the plausibility filter)
                I = (R, OO, False, True)
                lower = prover.prove(gap, var, I, 1, False) if gap == F - G else \
                    prover._rewritten(F - G, gap, var, I, 1, False, 0, False)
                div = _diverges(G, var, (R,)) or _diverges_inside(G, var)
                if div:
                    return [_rule(K.diverges_by_comparison, lower, div[0], expr=F)]
                break                   # G does not grow: the next G
            except NoProof as exc:
                if exc is prover.spent:
                    return []
    return []


def _log_powers(F, var) -> list:
    """For F = G(L) + H, G rational in U = L (a log(...) or asinh), G(U) ~
    c U^d as U -> oo, c > 0 and d >= 1, H the terms of F not rational in L
    alone (0 too): [c/2 L^d], which diverges with L and stays below F far
    out where H >= 0 (L^2/(1 + L): L/2), for `_diverges_above`."""
    out = []
    for g, group in log_groups(sp.Add.make_args(F), var).items():
        G = sp.Add(*group).xreplace({g: _U_REAL})
        if not K._rational_over_q(G, _U_REAL):
            continue
        num, den = (sp.Poly(p, _U_REAL) for p in sp.fraction(sp.cancel(G)))
        d = num.degree() - den.degree()
        c = num.LC() / den.LC()
        if d >= 1 and c > 0:
            out.append(c / 2 * g ** d)
    return out


def _spread(e, var):
    """e with each quotient (A + B + ...)/s^k among its terms spread into
    A/s^k + B/s^k + ... (SymPy cancels the powers of s term by term: F'(s)/s
    of 1/3 (1 - exp(-s^2))^2 + s^2/(1 + s^2) is defined at 0 so), or None
    unless that makes an e undefined at 0 (as SymPy evaluates it) defined there."""
    if not any(t.is_Mul and any(f.is_Add for f in t.args) and any(f.is_Pow and f.base == var and f.exp.is_negative
                                                                    for f in t.args) for t in sp.Add.make_args(e)):
        return None
    out = sp.Add(*[sp.expand_mul(t, deep=False) for t in sp.Add.make_args(e)])
    undefined = [u.xreplace({var: sp.Integer(0)}).has(sp.nan, sp.zoo) for u in (e, out)]
    return out if undefined == [True, False] else None


def _as_tanh(e):
    """e with each product's factors sinh(u) and 1/cosh(u) read as tanh(u)
    (the derivative of log cosh u: the divergence rules bound tanh's tail,
    not the quotient of two functions that overflow there)."""
    def fix(m):
        fs = sp.Mul.make_args(m)
        us = {f.args[0] for f in fs if isinstance(f, sp.sinh)} & \
            {f.base.args[0] for f in fs if f.is_Pow and f.exp == -1 and isinstance(f.base, sp.cosh)}
        pair = lambda f: isinstance(f, sp.sinh) and f.args[0] in us or \
            f.is_Pow and f.exp == -1 and isinstance(f.base, sp.cosh) and f.base.args[0] in us     # noqa: E731
        return sp.Mul(*[f for f in fs if not pair(f)], *map(sp.tanh, us)) if us else m
    return e.replace(lambda n: n.is_Mul, fix) if e.has(sp.sinh) else e


def _leading_terms(terms, var):
    """The terms of a sum that are not below 1/1000 of the largest at
    s = 10^6 (128-bit Arb; [] when a term is undefined there): the others,
    if >= 0, are dropped for `diverges_by_comparison`."""
    try:
        size = [abs(float(evaluate(t, var, 10 ** 6, 10 ** 6, bits=128).hull().mid())) for t in terms]
    except (Undefined, TypeError, ValueError, OverflowError):
        return []
    return [t for t, m in zip(terms, size) if m >= max(size) / 1000]


def _plausible(e, var, R, want) -> bool:
    """e is not seen to have the sign opposite to `want` at R, 4R, 64R, 10^6 R
    (128-bit Arb at single points; a cheap filter before a proof on [R, oo))."""
    for x in (R, 4 * R, 64 * R, 10 ** 6 * R):
        try:
            box = evaluate(e, var, x, x, bits=128)
        except Undefined:
            return False
        if (box.negative() if want > 0 else box.positive()):
            return False
    return True


def _over_one_denominator(e):
    """e as N/D with N expanded and collected in its logs: one term M log(Y)
    per log for `Prover._log_bound`; refused (NoProof) for a large e, whose
    expansion can take a minute (a profile of 16 nested logs)."""
    if sp.count_ops(e) > 4 * CHEAP_RATIONAL:
        raise NoProof("too large to put over one denominator")
    n, d = sp.fraction(sp.together(e))
    return sp.collect(sp.expand(n), sorted(n.atoms(sp.log, sp.asinh), key=sp.default_sort_key)) / d


def _exp_collected(e):
    """e with its terms M_i exp(Y) (one exp factor each) gathered into one
    (M_1 + M_2 + ...) exp(Y) per exp, for `Prover._log_bound`; by the factors
    as they stand (`sympy.collect` rebuilds powers of exp, and SymPy may then
    evaluate e to thousands of digits).  NoProof when no two terms share one."""
    groups: dict = {}
    for term in e.args:
        exps = [a for a in sp.Mul.make_args(term) if isinstance(a, sp.exp)]
        groups.setdefault(exps[0] if len(exps) == 1 else term, []).append(term)
    if all(len(ts) == 1 for ts in groups.values()):
        raise NoProof("no two terms of {} share an exp", e)
    return sp.Add(*[ts[0] if len(ts) == 1 else sp.Mul(sp.Add(*[t / g for t in ts]), g) for g, ts in groups.items()])


def _first_of(attempts, prover):
    """The first of the thunks `attempts` that proves (NoProof from the last;
    a spent budget stops at once)."""
    for i, attempt in enumerate(attempts):
        try:
            return attempt()
        except NoProof as exc:
            if exc is prover.spent or i == len(attempts) - 1:
                raise


def _tail_first(prover, e, var, R, want=1, strict=False, depth=0):
    """The sign of e on [R, oo), by s = 1/t first: a sum of terms of both
    signs (the rates of `_diverges`, the bounds of `_log_bound`) would spend
    the budget in the sign rules.  (A rational function over Q: Sturm first,
    through `prove`.)"""
    if not K._rational_over_q(e, var):
        try:
            return prover._unbounded(e, var, (R, OO, False, True), want, strict, depth)
        except NoProof as exc:
            if exc is prover.spent:
                raise
    return prover.prove(e, var, (R, OO, False, True), want, strict, depth)


_POWER_RATES = (sp.Rational(1, 2), sp.Rational(1, 4))     # F ~ s^p: F' s^(1-p) >= k (`diverges_by_growth`)


def _growth_exponent(F, var, R):
    """log(F(64 R)/F(R))/log 64 by Arb at 64 bits, a guess of p in F ~ s^p
    (it only orders the rates `_diverges` tries); None when not positive."""
    try:
        a, b = (float(evaluate(F, var, x, x, bits=64).lo.mid()) for x in (R, 64 * R))
    except (Undefined, ValueError, OverflowError):
        return None
    return math.log(b / a) / math.log(64) if a > 0 and b > a else None


def _diverges(F, var, starts) -> list:
    d = derivative(F, var)
    prover = Prover(_scaled(WORK, d))        # one budget for every attempt
    rates = [("linear", d), ("log", var * d), *((p, var ** (1 - p) * d) for p in _POWER_RATES)]
    grow = _growth_exponent(F, var, starts[-1])
    if grow is not None:     # the likeliest rate first (s^(2/3) + ...: 1/2, not log, whose proof spent the budget),
        power = lambda r: r[0] not in ("linear", "log")     # noqa: E731   and F ~ s^p's own p before it: then
        rates.sort(key=lambda r: 0 if (r[0] == "linear" and grow > 0.95) or (power(r) and abs(r[0] - grow) < 0.05)
                   else 1 if power(r) and r[0] < grow - 0.05 else 2 if r[0] == "log" else 3)  # s^(1-p) F' -> c > 0
    for R in starts:
        for rate, g in rates:
            try:
                lo = float(evaluate(g, var, R, R, bits=128).lo.lower())
            except Undefined:
                continue
            if not lo > 0:
                continue
            lo = min(lo, 1e300)     # (a rate beyond the doubles: any smaller k serves)
            for k in (Fraction(lo / 2).limit_denominator(1000), Fraction(lo / 16).limit_denominator(1000)):
                if k <= 0:
                    continue
                k = sp.Rational(k.numerator, k.denominator)
                if not _plausible(g - k, var, R, 1):      # (F' -> 0: not linear growth)
                    continue
                try:
                    th = prover.prove(g - k, var, (R, OO, False, True), 1, False) if g.atoms(sp.Function) \
                        else _tail_first(prover, g - k, var, R)     # algebraic: its t-form is, too
                    return [_rule(K.diverges_by_growth, th, expr=F, var=var, R=R, rate=rate, k=k)]
                except NoProof as exc:
                    if exc is prover.spent:
                        return []
                    continue
    return []


def origin_theorems(F, var, ends=None) -> list:
    """P5 at the origin: F and F' continuous on [0, w] with F'(0) = 0
    (`continuous_at_end`), so F'(0+) = 0 and F has the one-sided derivative
    0 at s = 0 (mean value theorem), or [].  For a Piecewise F (boundaries
    `ends`) also F and F' continuous on (0, oo), so that F' is F's derivative
    across the boundaries too."""
    key = ("origin", F, tuple(ends or ()), var)
    if key in _FOUND:
        return _FOUND[key]
    d = derivative(F, var)
    for w in (sp.Rational(1, 2), sp.Rational(1, 16)):
        try:
            out = [_limit_at_zero(F, var, w), _limit_at_zero(d, var, w)]
            if isinstance(F, sp.Piecewise):
                out += continuity_pair(F, var, ends)
        except NoProof:
            continue
        if out[1].claim.other == K._s(0):
            _remember(key, out)
            return out
    return []


def smoothness_theorems(F, var, order, ends=None) -> list:
    """P8 (order 1): F' continuous on (0, oo) and at 0+ with F'(0) = 0.
    P7 (order 2): also F'' continuous on (0, oo) and at 0+ (value L), so that
    F'(s)/s = F''(xi) -> L too (mean value theorem), and F continuous at 0+.
    For a Piecewise F (boundaries `ends`) also F continuous on (0, oo), so
    that F' and F'' are derivatives across the boundaries.  [] if not shown."""
    d1 = derivative(F, var)
    d2 = derivative(d1, var)
    try:
        out = [_continuous(d, var, ends) for d in (d1, d2)[:order]]
        whole = [_continuous(F, var, ends)] if isinstance(F, sp.Piecewise) else []
    except NoProof:
        if order == 2 or not isinstance(F, sp.Piecewise):
            return []
        try:        # P8 of an F that may jump: F and F' continuous on each piece
            whole, out = ([t] for t in branches_pair(F, var, ends))
        except NoProof:
            return []
    for w in (sp.Rational(1, 2), sp.Rational(1, 16)):
        try:
            limits = [_limit_at_zero(d, var, w) for d in (d1, d2, F)[:1 if order == 1 else 3]]
        except NoProof:
            continue
        if limits[0].claim.other == K._s(0):
            return out + limits + whole
    return []


def continuity_pair(F, var, ends) -> list:
    """F and F' continuous on (0, oo) (for a Piecewise F: the links' proof
    that F' is F's derivative across the boundaries too); NoProof if not shown."""
    return [_continuous(F, var, ends), _continuous(derivative(F, var), var, ends)]


def _continuous(e, var, ends, rule=K.continuous_piecewise):
    """E continuous on (0, oo): `continuous_on_positive`, or for a Piecewise
    `continuity_theorem` (with rule=`piecewise_branches`: continuous on each
    open piece between the `ends`)."""
    if not isinstance(e, sp.Piecewise):
        return _rule(K.continuous_on_positive, expr=e, var=var)
    th = continuity_theorem(e, ends, var, rule)
    if th is None:
        raise NoProof("{} not shown continuous", e)
    return th


def branches_pair(F, var, ends) -> list:
    """F and F' continuous on (0, oo) or on each open piece between the
    `ends` (`piecewise_branches`): for a Piecewise F that may jump, what the
    links of P8 and kf need in place of `continuity_pair`."""
    return [_continuous(e, var, ends, K.piecewise_branches) for e in (F, derivative(F, var))]


def _limit_at_zero(e, var, w):
    """E(0+): E(0) (`continuous_at_end` on [0, w]), or for 0/0 by Taylor
    (`taylor_limit`); for a Piecewise, that of the branch that applies there."""
    if not isinstance(e, sp.Piecewise):
        try:
            return _rule(K.continuous_at_end, expr=e, var=var, c=0, width=w)
        except NoProof:
            return taylor_limit(e, var, w)
    try:
        return on_branch(e, var, (sp.Integer(0), w, False, False), Prover(WORK),
                         lambda g: _limit_at_zero(g, var, w))
    except (K.KernelError, Undefined) as exc:
        raise NoProof(str(exc)) from None


def taylor_limit(e, var, w, orders=8):
    """E(0+) for E = N/D over one denominator (`sympy.together`) with D(0) =
    0 (`limit_by_taylor`), m the order of D's zero at 0, up to `orders`
    (`univariate.zero_of_denominator`); NoProof if none."""
    found = zero_of_denominator(e, var, orders)
    if found is None:
        raise NoProof("{} is no quotient whose denominator has a zero of known order at 0", e)
    n, d, _, m = found
    return _rule(K.limit_by_taylor, expr=e, num=n, den=d, var=var, order=m, width=w)


def origin_value_theorems(value) -> list:
    """P2: the kernel's `value_sign` of the exact f(0, 0), or [] if refused."""
    try:
        return [K.value_sign(value=value)]
    except (K.KernelError, Undefined):
        return []


def sup_theorems(dF, c, point, var, positive):
    """kf = sup F' = c on (0, oo) (bound (10)) as kernel theorems, or (None,
    reason).  `point`: where c is attained (None: approached as s -> oo);
    `positive`: a kernel theorem F' > 0 on (0, oo), so that sup |F'| = sup F'
    (`_sup_pair` gives F' <= c and sup F' >= c)."""
    try:
        return [positive, *_sup_pair(dF, c, point, var)], ""
    except (NoProof, K.KernelError, Undefined) as exc:
        return None, str(exc)


def sup_abs_theorems(dF, c, point, var, side):
    """kf = sup |F'| = c on (0, oo) when F' changes sign, or (None, reason):
    E = side F' (side +-1, the side whose sup is c) has E <= c and sup E >= c
    (`_sup_pair`), -E <= c too, so |F'| <= c (`sup_upper_of_abs`)."""
    try:
        upper, lower = _sup_pair(side * dF, c, point, var)
        other = sup_upper_theorem(-side * dF, c, var)
        if other is None:
            raise NoProof("{} <= {} not shown", -side * dF, c)
        pair = (upper, other) if side == 1 else (other, upper)      # (about F', about -F')
        return [_rule(K.sup_upper_of_abs, *pair), lower], ""
    except (NoProof, K.KernelError, Undefined) as exc:
        return None, str(exc)


def _sup_pair(E, c, point, var):
    """E <= c and sup E >= c on (0, oo).  The upper bound is weak, so that
    E = c on a whole interval is allowed: c - E >= 0, by sign lemmas on both
    sides of the touching point joined there (`join_at_point`, E = 0 there), then
    `sup_upper_by_sign`.  Lower: the value at the point
    (`sup_lower_by_point`) or the limit of the tail form at t = 0
    (`sup_lower_by_limit`, else `limit_at_infinity`)."""
    from .univariate import T
    gap = sp.sympify(c) - E
    zeros = (point,) if point is not None and point != 0 else ()
    parts, why = sign_theorems(gap, var, 0, OO, zeros=zeros, strict=False, work=WORK)
    if parts is None:
        raise NoProof("{} - ({}) >= 0: {}", c, E, why)
    upper = parts[0] if not zeros else _rule(K.join_at_point, *parts)
    upper = _rule(K.sup_upper_by_sign, upper, expr=E, bound=c)
    if zeros:                   # (attained at s = 0 only: a sup over (0, oo), so a limit below)
        lower = _rule(K.sup_lower_by_point, expr=E, var=var, point=point, bound=c, lo=0, hi=OO,
                      lo_open=True, hi_open=True)
    else:
        w = sp.Rational(1, 4)
        try:
            ident = _rule(K.identity, lhs=_tail_form(E, var), rhs=E.xreplace({var: 1 / T}), var=T, lo=0, hi=w,
                          lo_open=True, hi_open=False)
            lower = _rule(K.sup_lower_by_limit, ident, expr=E, var=var, width=w, bound=c, lo=0, lo_open=True)
        except NoProof:
            lower = _rule(K.sup_lower_from_limit, limit_at_infinity(E, var), lo=0, lo_open=True)
            if K.parse(lower.claim.other) != sp.sympify(c):
                raise NoProof("{} tends to {}, not {}", E, lower.claim.other, c) from None
    return upper, lower


def limit_at_infinity(e, var, w=sp.Rational(1, 4)):
    """E -> c as s -> oo as a kernel theorem: from the tail form's value at
    t = 0 (`limit_at_infinity`), or for a product with tanh, erf or atan
    factors of diverging arguments (sinh/cosh read as tanh) from their
    limits and that of the rest (`limit_of_bounded`, `limit_of_product`)."""
    from .univariate import T
    form = _with_tanh(e)
    power = lambda a: a.exp if a.is_Pow and type(a.base) in K._SUP and a.exp.is_Integer and a.exp > 0 else 0  # noqa
    bounded = [a for a in sp.Mul.make_args(form) if type(a) in K._SUP] + \
        [a.base for a in sp.Mul.make_args(form) for _ in range(power(a))]      # G(Y)^n: n times G(Y)
    if not bounded:
        ident = _rule(K.identity, lhs=_tail_form(e, var), rhs=e.xreplace({var: 1 / T}), var=T, lo=0, hi=w,
                      lo_open=True, hi_open=False)
        lim = _rule(K.limit_at_infinity, ident, expr=e, var=var, width=w)
    else:
        premises = []
        for g in bounded:
            div = growth_theorems(g.args[0], var)
            if not div:
                raise NoProof("{} not shown to diverge", g.args[0])
            premises.append(_rule(K.limit_of_bounded, div[0], expr=g))
        rest = sp.Mul(*[a for a in sp.Mul.make_args(form) if type(a) not in K._SUP and not power(a)])
        if rest.has(var):
            premises.append(limit_at_infinity(rest, var, w))
        lim = _rule(K.limit_of_product, *premises, expr=e)
    return lim


def sup_upper_theorem(e, bound, var, gap=None, work=WORK):
    """E <= bound on (0, oo) (`sup_upper_by_sign` over bound - E >= 0, a
    theorem `gap` or one proved here with `work`; for a Piecewise E piece by
    piece between the roots of its conditions), or None."""
    if gap is None and e.has(sp.Piecewise):
        gap = piecewise_sign_theorem(sp.sympify(bound) - e, _condition_roots(e, var), var, strict=False)[0]
        if gap is None:
            return None
    parts = [gap] if gap is not None else sign_theorems(sp.sympify(bound) - e, var, 0, OO, strict=False,
                                                        work=work)[0]
    if parts is None:
        return None
    try:
        return _rule(K.sup_upper_by_sign, parts[0], expr=e, bound=bound)
    except NoProof:
        return None


def abs_upper_theorem(e, bound, var, work=WORK):
    """|E| <= bound on (0, oo) (`sup_upper_of_abs` over E <= bound and -E <=
    bound), or None."""
    up = sup_upper_theorem(e, bound, var, work=work)
    down = up and sup_upper_theorem(-e, bound, var, work=work)
    return _rule(K.sup_upper_of_abs, up, down) if down else None


def sup_lower_theorem(e, bound, point, var):
    """sup E >= bound on (0, oo) by E's value at `point` (`sup_lower_by_point`), or None."""
    try:
        return _rule(K.sup_lower_by_point, expr=e, var=var, point=point, bound=bound, lo=0, hi=OO,
                     lo_open=True, hi_open=True)
    except NoProof:
        return None


# ---------------------------------------------------------------- refutations

def _condition_roots(P, var):
    """[0, the positive roots in radicals of the polynomial relations of P's
    conditions, oo].  A relation of another kind (atan(s^2) >= s^2/(1 + s^2),
    from a Max) adds no boundary: the kernel signs each relation on each
    piece, so where one changes sign there, the proof fails."""
    roots = set()
    for _, c in K._folded(P).args:
        for r in _relationals(c):
            d = r.rhs - r.lhs
            if d.has(var) and d.is_polynomial(var):
                roots |= {x for x in sp.Poly(d, var).real_roots() if not x.has(sp.CRootOf) and x.is_positive}
    return [sp.Integer(0), *sorted(roots, key=float), OO]


_STEPS = [sp.Rational(1, 4 ** k) for k in (1, 2, 4, 7)]
_JUMP_WIDTHS = [sp.Rational(1, 2), sp.Rational(1, 16), sp.Rational(1, 256)]


def _exact_point(x, y):
    """The exact point of a witness (its text, as the verdict gives it) in
    the form the checker reads back, or None (a limit, oo, a float...)."""
    try:
        p = [sp.sympify(v) for v in (x, y)]
        p = [K.parse(K._s(v)) for v in p]
        if not all(K._number(v) not in (OO, -OO) for v in p):
            return None
    except (sp.SympifyError, K.KernelError, Undefined, TypeError, ValueError, SyntaxError):
        return None
    return tuple(p)


def _witness_candidates(name, witness):
    """Witness records to try for property `name`, from the search's witness."""
    w = witness if isinstance(witness, dict) else {}
    if name == "P2":
        yield {"kind": "value", "points": [(sp.Integer(0), sp.Integer(0))]}
    if name == "P4" and "point_a" in w and "point_b" in w:
        a, b = _exact_point(*w["point_a"]), _exact_point(*w["point_b"])
        if a is not None and b is not None:
            yield {"kind": "circle", "points": [a, b]}
    p = _exact_point(w.get("e1"), w.get("e2")) if "e1" in w and "e2" in w else None
    if name == "P3" and p is not None:
        yield {"kind": "value", "points": [p]}
    at_origin = p is not None and p == (0, 0)
    if name in ("P5", "P6") and p is not None and not at_origin:
        yield {"kind": "slope", "points": [p]}
        for d in _STEPS:
            yield {"kind": "step", "points": [p, (p[0] + d, p[1])]}
            yield {"kind": "step", "points": [(p[0] - d, p[1]), p]}
    if name == "P3" and "limit" in w and "direction" in w:     # f -> a finite limit along rays
        d = (sp.Integer(1), sp.Integer(0)) if w["direction"] == "every" else _exact_point(*w["direction"])
        try:
            lim = sp.sympify(w["limit"])
        except (sp.SympifyError, TypeError, SyntaxError):
            lim = None
        if d is not None and lim is not None and lim.is_real and lim.is_finite and not lim.has(sp.Float):
            for m in (lim + 1, lim):
                yield {"kind": "bounded", "direction": d, "bound": m}
    if name == "P3" and w.get("direction") == "every" and "bound" in w:     # a bound the kernel has shown
        yield {"kind": "bounded", "direction": (sp.Integer(1), sp.Integer(0)), "bound": sp.Integer(w["bound"])}
    if name in ("P1", "P6", "P7") and str(w.get("limit")) == "oo":   # kf, F'(s)/s or F'' unbounded
        near_zero = "0+" in str(w.get("e1")) + str(w.get("e2"))
        for at in (("0", "oo") if near_zero else ("oo", "0")):
            if name != "P7" or at == "0":
                yield {"kind": "unbounded", "var": "e1" if name == "P6" else "e2", "order": 2 if name == "P7" else 1,
                       "at": at}
    if str(w.get("F'(0+)")) == "oo" or (name == "P8" and str(w.get("limit")) == "oo"):   # |grad f| -> oo at 0
        if name in ("P1", "P6", "P7", "P8"):
            yield {"kind": "unbounded", "var": "e1" if name == "P6" else "e2", "order": 1, "at": "0"}
        if name == "P5":
            yield {"kind": "unbounded", "var": "e1", "order": 1, "at": "0", "divided": False}
    # f(t, 0) or df/de1 jumps at t = e1?  (or on the line through p when the search says so)
    if name in ("P1", "P5", "P6") and p is not None and (p[1] == 0 or w.get("jump") == "e1"):
        yield {"kind": "jump", "points": [p]}
        yield {"kind": "jump", "points": [p], "var": "e1", "order": 1}
    if name == "P7" and p is not None and p[1] == 0:                  # f(0, t) or a derivative jumps at t = e1?
        for order in (0, 1, 2):
            yield {"kind": "jump", "points": [(sp.Integer(0), p[0])], "var": "e2", "order": order}
    if name in ("P1", "P7") and p is not None and w.get("jump") == "e1":      # df/de2 or its slope in e1 jumps?
        for order in (1, 2) if name == "P7" else (1,):
            yield {"kind": "jump", "points": [p], "var": "e1", "order": order, "mixed": True}
    if name in ("P1", "P7") and p is not None and w.get("jump") == "e2":      # f(e1, t) jumps at t = e2?
        for order in (0, 1) if name == "P1" else (0, 1, 2):
            yield {"kind": "jump", "points": [p], "var": "e2", "order": order}
    if name in ("P1", "P5", "P6", "P7") and "crossing" in w:       # a Max or Min switches between two rationals
        q1, q2 = (sp.Rational(q) for q in w["crossing"])
        v, zero = "e2" if name == "P7" else "e1", sp.Integer(0)
        for order in (1, 0):
            yield {"kind": "crossing", "var": v, "order": order,
                   "points": [(zero, q1), (zero, q2)] if v == "e2" else [(q1, zero), (q2, zero)]}
    if name == "P8" and p is not None and w.get("approach") == "e2":       # df/de2(x, h) -> L != 0 as h -> 0+
        yield {"kind": "e2_limit", "points": [p]}
    if str(w.get("e1")) == "0":          # at the origin (P8: e2 -> 0+ along e1 = 0)
        for v in {"P1": ("e2", "e1"), "P7": ("e2",), "P8": ("e2",), "P5": ("e1",), "P6": ("e1",)}.get(name, ()):
            yield {"kind": "origin_jump", "var": v}


def _witness_theorems(f, record):
    """Kernel theorems for one witness record (NoProof if the kernel refuses)."""
    from .design_certificate import H, along_ray, axis_derivative, growing, witness_values
    if record["kind"] == "bounded":
        # twice a lemma's work: a tail such as that of log(1 + h^2)^2/h^2 <= 1 costs more than one
        th = sup_upper_theorem(along_ray(f, record["direction"]), record["bound"], H, work=2 * WORK)
        if th is None:          # or its limit along the ray (atan(h)^2 -> pi^2/4)
            th = limit_at_infinity(along_ray(f, record["direction"]), H)
        return [th]
    if record["kind"] == "unbounded":
        v = sp.Symbol(record["var"], real=True)
        if isinstance(f, sp.Piecewise):
            if record["at"] != "oo" or record["order"] != 1:
                raise NoProof("a Piecewise f: only its last branch at infinity")
            return _tail_branch_theorems(f, v, record)
        out = growth_theorems(growing(f, v, record["order"], record["at"], record.get("divided", True)), H)
        if not out:
            raise NoProof("no growth bound found")
        return out
    if record["kind"] == "jump":
        return _jump_theorems(f, record)
    if record["kind"] == "crossing":
        return _crossing_theorems(f, record)
    if record["kind"] == "e2_limit":
        from .design_certificate import e2_limit_expr
        e = e2_limit_expr(f, record["points"][0][0])
        for w in _JUMP_WIDTHS:
            try:
                lim = _rule(K.continuous_at_end, expr=e, var=H, c=0, width=w)
            except NoProof:
                continue
            return [lim, _rule(K.value_sign, value=K.parse(lim.claim.other))]
        raise NoProof("df/de2(x, h) is not continuous up to h = 0")
    if record["kind"] != "origin_jump":
        return [_rule(K.value_sign, value=v) for v in witness_values(record["kind"], f, record["points"])]
    v = sp.Symbol(record["var"], real=True)
    ends = [axis_derivative(f, v, side) for side in (1, -1)]
    for w in _JUMP_WIDTHS:
        try:
            lims = [_rule(K.continuous_at_end, expr=e, var=H, c=0, width=w) for e in ends]
        except NoProof:
            continue
        jump = K.parse(lims[0].claim.other) - K.parse(lims[1].claim.other)
        return [*lims, _rule(K.value_sign, value=jump)]
    raise NoProof("df/dv is not continuous up to the origin on either side")


def _tail_branch_theorems(f, v, record):
    """The `unbounded` witness of a Piecewise f at infinity: R at or beyond
    every root of its conditions along the v axis, the branch i taken at
    R + h for all h > 0 (sign theorems on (0, oo)), that branch's growth.
    Fills in the record's branch and from."""
    from .design_certificate import E1, E2, CertificateError, H, branch_conditions, growing
    axis = f.subs({v: H, (E2 if v == E1 else E1): 0}, simultaneous=True)
    ends = _condition_roots(axis, H)
    R = sp.ceiling(ends[-2]) if len(ends) > 2 else sp.Integer(0)
    for i in range(len(f.args)):
        try:
            conds = [_claim_one(options, OO) for options in branch_conditions(f, R, 1, i, OO, v)]
        except (CertificateError, NoProof):
            continue
        growth = growth_theorems(growing(f.args[i][0], v, 1, "oo"), H)
        if not growth:
            raise NoProof("branch {} beyond {}: no growth bound found", i, R)
        record.update(branch=i, **{"from": R})
        return [*conds, *growth]
    raise NoProof("no branch shown to apply beyond {}", R)


def _jump_theorems(f, record):
    """The jump witness (see `design_certificate`): the branch of the
    Piecewise f on each side of b on the record's axis (var, default e1),
    its conditions' signs on (0, w], the one-sided limits of the branches'
    order-th derivatives, a nonzero gap.  Fills in record's branches, width
    and compare."""
    from .design_certificate import CertificateError, H, at_point, branch_conditions, chosen_by_e1, jump_parts
    if not isinstance(f, sp.Piecewise):
        raise NoProof("f is not a Piecewise")
    v = sp.Symbol(record.get("var", "e1"), real=True)
    order = record.get("order", 0)
    b, other = record["points"][0] if v.name == "e1" else record["points"][0][::-1]
    for w in (sp.Rational(1, 4), sp.Rational(1, 64), sp.Rational(1, 1024)):
        found = []
        for side in (-1, 1):
            for i in range(len(f.args)):
                try:
                    conds = [_claim_one(options, w) for options in branch_conditions(f, b, side, i, w, v, other)]
                except (NoProof, CertificateError):
                    continue
                found.append((i, conds))
                break
        if len(found) < 2:
            continue
        branches = [found[0][0], found[1][0]]
        if record.get("mixed") and not chosen_by_e1(f, branches):
            raise NoProof("a branch there is chosen by e2 too")
        try:
            lims = [_rule(K.continuous_at_end, expr=e, var=H, c=0, width=w)
                    for e in jump_parts(f, b, branches, w, v, order, other, record.get("mixed", False))]
        except NoProof:
            continue
        left, right = (K.parse(t.claim.other) for t in lims)
        value = at_point(f, record["points"][0])         # f at the witness point, as the link computes it
        gaps = (("sides", right - left), ("left", value - left), ("right", value - right))
        for compare, gap in gaps[:1 if order else 3]:
            try:
                th = _rule(K.value_sign, value=gap)
            except NoProof:
                continue
            if th.claim.want != 0:
                record.update(branches=branches, width=w, compare=compare)
                return [*found[0][1], lims[0], *found[1][1], lims[1], th]
    raise NoProof("no branch or no gap found on both sides")


def _crossing_theorems(f, record):
    """The crossing witness (see `design_certificate`): covers of d' and of
    the gap on [q1, q2] with one strict sign each, d's signs at q1 and q2,
    and M - E >= 0 for each part E, M an integer above E's Arb enclosure."""
    from .design_certificate import CertificateError, H, crossing_parts
    v = sp.Symbol(record["var"], real=True)
    (q1, _), (q2, _) = record["points"] if record["var"] == "e1" else [p[::-1] for p in record["points"]]
    try:
        d, dd, gap, defined = crossing_parts(f, record["order"], v)
        ranges = [evaluate(e, H, q1, q2) for e in (dd, gap)]
    except (CertificateError, Undefined) as exc:
        raise NoProof("{}", exc) from None
    signed = [_cover(e, H, q1, q2, want=1 if r.lo + r.hi > 0 else -1, strict=True) for e, r in zip((dd, gap), ranges)]
    ends = [_rule(K.value_sign, value=d.xreplace({H: q})) for q in (q1, q2)]
    bounds = []
    for e in defined:
        try:
            hi = float(evaluate(e, H, q1, q2).hi)
            top = sp.Integer(math.ceil(hi + abs(hi) * 1e-6) + 1)
        except (Undefined, OverflowError, ValueError) as exc:
            raise NoProof("{} on [{}, {}]: {}", e, q1, q2, exc) from None
        bounds.append(_cover(top - e, H, q1, q2, want=1, strict=False))
    return [signed[0], *ends, signed[1], *bounds]


def _claim_one(options, w):
    """A kernel sign theorem on (0, w] (on (0, oo) for w = oo) for one of the acceptable claims."""
    from .design_certificate import H
    last = None
    for e, want, strict in options:
        theorems, why = sign_theorems(e, H, 0, w, want=want, lo_open=True, hi_open=w == OO, strict=strict,
                                      work=WORK // 4)
        if theorems is not None:
            return theorems[0]
        last = why
    raise NoProof("condition not shown: {}", last)


_WITNESSED: dict = {}        # (f, witness record) -> its kernel theorems


def refutation_theorems(name, verdict, f):
    """A refuted property's witness, checked by the kernel: (theorems, the
    witness record of the design certificate, "") for the first candidate
    whose kernel theorems link to the property (`design_certificate.
    link_refutation`), or (None, None, why) -- the refutation then rests on
    the search's witness alone."""
    from .design_certificate import CertificateError, link_refutation
    why = "no witness of a kind the kernel checks"
    budget = Budget(WORK)
    for record in _witness_candidates(name, verdict.witness):
        if budget.spent():
            why = SPENT
            break
        try:
            key = (f, repr(sorted(record.items())))
            if key not in _WITNESSED:       # P1, P7, P8 can share one witness (or its failure)
                if len(_WITNESSED) > 64:
                    _WITNESSED.clear()
                try:
                    _WITNESSED[key] = _witness_theorems(f, record), dict(record)   # (it completes the record)
                except (NoProof, K.KernelError, Undefined) as exc:
                    _WITNESSED[key] = exc, None
            theorems, done = _WITNESSED[key]
            if isinstance(theorems, Exception):
                raise theorems
            record = done
            link_refutation(name, f, theorems, _encode_record(record))
        except (NoProof, CertificateError, K.KernelError, Undefined, TypeError, ValueError) as exc:
            why = f"{record['kind']}: {exc}"
            continue
        return theorems, _encode_record(record), ""
    return None, None, why


def _encode_record(record):
    out = {k: v for k, v in record.items() if k not in ("points", "direction", "bound", "width", "from")}
    for key in ("width", "from"):
        if key in record:
            out[key] = K._s(record[key])
    if "points" in record:
        out["points"] = [[K._s(c) for c in p] for p in record["points"]]
    if "direction" in record:
        out["direction"] = [K._s(c) for c in record["direction"]]
    return out


def to_certificate(theorems) -> dict:
    """The kernel certificate of the given theorems (conclusions), premises
    first, in the format `kernel.certificate.check_certificate` reads (it
    re-checks every step, so this writer need not be trusted)."""
    order, ids = [], {}

    def visit(t: K.Theorem):
        if id(t) in ids:
            return
        for p in t.premises:
            visit(p)
        ids[id(t)] = len(order)
        order.append(t)
    for t in theorems:
        visit(t)
    return {"format": CERT.FORMAT, "version": CERT.VERSION,
            "theorems": [{"id": ids[id(t)], "rule": t.rule, "premises": [ids[id(p)] for p in t.premises],
                          "data": json.loads(t.data), "claim": t.claim.to_json()} for t in order],
            "conclusions": [ids[id(t)] for t in theorems],
            "assumptions": sorted(set().union(*[t.assumptions for t in theorems]))}
