"""kf = sup over R^2 of |df/de2| (property P1, bound (10)), certified.

For a radial f, |df/de2| = |F'(s)| |e2|/s, whose supremum over the circle of
radius s is |F'(s)| (at e1 = 0), so kf = sup_{s >= 0} |F'(s)|.  The result is
a rigorous enclosure [lower, upper] from interval branch and bound, and an
exact closed form when one is found *and proved*: a candidate c (a critical
value or a limit) is accepted only after c - |F'| >= 0 is proved on all of
[0, oo) with the prover of `univariate`."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction

import mpmath
import sympy as sp

from . import e1 as E1, e2 as E2
from .design_certificate import SMOOTH_ONLY, e2_sides
from .interval import Interval, Undefined
from .kernel import core as K
from .kernel.core import derivative
from .limits import NoLimit, rational_parts
from .profile import S, float_of, one_sided_value
from .timeouts import attempt
from .certify import (WORK, abs_upper_theorem, growth_theorems, piecewise_sup_theorems, plane_theorems, renew_pool,
                      sign_theorems, sup_abs_theorems, sup_lower_theorem, sup_theorems, sup_upper_theorem)
from .univariate import (certified_inside, decimal_beyond, enclose_sup, exact_sign, exact_value, far_out_trend,
                         limit_at_infinity, prepare, prove_sign, quotient_near_zero, small_rates, solveset_hopeless,
                         tail_start, value_at)

REL_WIDTH = 1e-7          # target relative width of enclosures (issue: <= 1e-6)


@dataclass
class SupCertificate:
    """sup of a function of s over [0, oo) in [lower, upper] (Fractions,
    rounded outward); `exact` (a SymPy number) when proved; `attained`
    True/False when proved, else None."""
    lower: Fraction | None
    upper: Fraction | None        # None: no finite bound
    exact: sp.Expr | None
    attained: bool | None
    reason: str
    unbounded_witness: dict | None = None
    point: sp.Rational | None = None                # an s where the function is >= lower (enclosures)
    kernel_bounds: tuple | None = None              # (L, U), Fractions: the enclosure the kernel checked
    kernel: list = field(default_factory=list)      # kernel theorems (see `certify.sup_theorems`)
    unchecked: list = field(default_factory=lambda: ["the whole argument (no kernel rules for it yet)"])

    def show(self) -> str:
        if self.exact is not None:
            x = self.exact      # (a rational by `show`: a float prints 10^-400 as 0)
            approx = show(Fraction(x.p, x.q)) if x.is_Rational else f"{float_of(x):.10g}"
            text = exact_text(x)
            return text if approx == text else f"{text} = {approx}"
        if self.upper is None:
            return "unbounded" if self.unbounded_witness else "undecided"
        return show_interval(self.lower, self.upper)


KfCertificate = SupCertificate


def exact_certificate(value, attained, reason) -> SupCertificate:
    """The certificate of a proved exact supremum `value`."""
    box = Interval.point(value)
    return SupCertificate(box.lower_fraction(), box.upper_fraction(), value, attained, reason)


def scale(cert: SupCertificate, c) -> SupCertificate:
    """The certificate of c * sup (c > 0 exact), enclosure rounded outward."""
    if c == 1 or cert.upper is None:
        return cert
    reason = f"sqrt(r) = {c} times: {cert.reason}"
    if cert.exact is not None:
        return exact_certificate(cert.exact * c, cert.attained, reason)
    lo = None if cert.lower is None else Interval.point(sp.Rational(cert.lower) * c).lower_fraction()
    hi = Interval.point(sp.Rational(cert.upper) * c).upper_fraction()
    out = SupCertificate(lo, hi, None, cert.attained, reason, cert.unbounded_witness)
    if cert.kernel_bounds is not None:
        L, U = (sp.Rational(b.numerator, b.denominator) * c for b in cert.kernel_bounds)
        out.kernel_bounds = (Interval.point(L).lower_fraction(), Interval.point(U).upper_fraction())
    return out


def _candidates(expr, lo, hi, interior=True):
    """(value, point) candidates for the sup of expr on (lo, hi): critical
    points found by SymPy (only when `interior`: the best box of the branch
    and bound was not the one at infinity), one-sided values at the ends
    (point None at oo, asked only when not `interior`: its limit calculus is slow)."""
    out = []
    d = derivative(expr, S)
    # SymPy solves E' = 0 in closed form only for algebraic or singly transcendental E'
    # (exp(-s^2)(1 - 2 s^2)); with functions of functions it searches until the time limit
    solvable = interior and _nesting(d) <= 1
    crit = None
    if solvable:
        crit = _rational_critical(d, lo, hi)
        if crit is False:
            crit = attempt(lambda: sp.solveset(d, S, sp.Interval.open(lo, hi)), 3.0) \
                if small_rates(d) and not solveset_hopeless(d, S) else None
    if isinstance(crit, sp.FiniteSet) and any(c.has(sp.CRootOf, sp.RootOf) for c in crit):
        crit = None     # algebraic numbers without radicals: no closed form to offer
    if isinstance(crit, sp.FiniteSet):
        for c in crit:
            if not certified_inside(c, lo, hi):
                continue     # SymPy's answer is a proposal: E(c) <= sup only for c in (lo, hi)
            v = exact_value(expr, S, c)
            if v is not None and not v.has(sp.Float):
                out.append((attempt(lambda: _tidy(v), 2.0, v), c))
    if lo != sp.oo:
        v = one_sided_value(expr, lo, +1)
        if v is not None and v not in (sp.oo, -sp.oo):
            out.append((v, lo))
    if hi == sp.oo and not interior:
        try:
            v = limit_at_infinity(expr, S)
            if v not in (sp.oo, -sp.oo):
                out.append((v, None))
        except NoLimit:
            pass
    elif hi != sp.oo:
        v = one_sided_value(expr, hi, -1)
        if v is not None and v not in (sp.oo, -sp.oo):
            out.append((v, hi))
    return out


SHORT_RADICAL = 24     # operations in a root worth offering as an exact critical point


def _tidy(v):
    """An exact value in a shorter exact form: radsimp, then expand when that
    is shorter (a polynomial in radicals collapses: F'(1 + sqrt(2)) = 1/2)."""
    v = sp.radsimp(v)
    w = sp.expand(v)
    return w if sp.count_ops(w) < sp.count_ops(v) else v


def _rational_critical(d, lo, hi):
    """Zeros in (lo, hi) of a rational d, from the factors of its numerator
    over Q of degree <= 4 (SymPy's solveset would search a higher one until
    the time limit), keeping only short radicals (s^4 = 3 gives 3^(1/4);
    Cardano's and Ferrari's formulas are no closed form worth offering and
    make radsimp crawl): a FiniteSet, None (a factor could not be solved), or
    False (d is not rational)."""
    parts = rational_parts(d, S)
    if parts is None:
        return False
    poly = parts[0]
    roots = set()
    for fac, _ in poly.factor_list()[1]:
        if fac.degree() > 4:
            continue
        sol = attempt(lambda: sp.solveset(fac.as_expr(), S, sp.Interval.open(lo, hi)), 3.0)
        if sol is sp.S.EmptySet:
            continue
        if not isinstance(sol, sp.FiniteSet):
            return None
        roots |= {r for r in sol if sp.count_ops(r) <= SHORT_RADICAL}
    return sp.FiniteSet(*roots)


def _nesting(expr) -> int:
    """How deeply functions are nested in expr (sqrt and powers do not count)."""
    if not expr.args:
        return 0
    inner = max(_nesting(a) for a in expr.args)
    return inner + 1 if isinstance(expr, sp.Function) else inner


def _prove_bound(c, exprs, pieces, zeros_of, strictly=True) -> tuple[bool, bool | None]:
    """Prove c - E_i >= 0 on every piece; returns (proved, strictly): strictly
    is True when c - E_i > 0 was proved everywhere, None when undecided (or
    not asked for: `strictly` False)."""
    for E, piece in zip(exprs, pieces):
        zeros = [z for z in zeros_of.get(id(piece), []) if z is not None and z not in (piece.lo, piece.hi)]
        search = lambda: prove_sign(c - E, S, piece.lo, piece.hi, want=1, strict=False, zeros=zeros).proved  # noqa
        kernel = lambda: sign_theorems(c - E, S, piece.lo, piece.hi, zeros=tuple(zeros), strict=False)[0]  # noqa
        # the kernel first where it is exact (a rational function over Q: Sturm), else where boxes fail
        if not any(way() for way in ((kernel, search) if K._rational_over_q(c - E, S) else (search, kernel))):
            return False, None
    if not strictly:
        return True, None
    for E, piece in zip(exprs, pieces):
        zeros = [z for z in zeros_of.get(id(piece), []) if z is not None]
        if zeros or not prove_sign(c - E, S, piece.lo, piece.hi, want=1).proved:
            return True, None if not zeros else False
    return True, True


NEAR_ZERO = Fraction(1, 8)
QUICK_POINTS = 15           # per piece, for `_quick_lower`


def _continued_at(exprs, pieces, point, value) -> bool:
    """Both one-sided limits at a boundary equal value."""
    for E, piece in zip(exprs, pieces):
        for end, side in ((piece.lo, +1), (piece.hi, -1)):
            if end == point:
                v = one_sided_value(E, point, side)
                if v is None or v in (sp.oo, -sp.oo) or exact_sign(v - value) != 0:
                    return False
    return True


def _value_continued_at(profile, point) -> bool:
    """F itself continuous at a boundary: its one-sided limits there and its
    value there (the branch taken at the point) agree.  Where F jumps, f has
    no partial derivatives on that circle, so a sup of |F'| reached only
    there as a one-sided limit is not attained (f = log(1 + rho) except 0 on
    rho = 1: kf = 1 at s = 1, not attained)."""
    pieces = profile.pieces
    value = exact_value(profile.at_point[point], S, point) if point in profile.at_point else \
        next((one_sided_value(p.expr, point, -1) for p in pieces if p.hi == point), None)
    return value is not None and _continued_at([p.expr for p in pieces], pieces, point, value)


def _quick_lower(exprs, pieces):
    """The largest lower bound of the sup that the values at a few inner
    points of each piece give (None if none): a floor for the pieces that
    cannot hold it.  An unbounded piece is sampled on [lo, R] (`tail_start`)."""
    best = None
    for E, p in zip(exprs, pieces):
        hi = p.hi if p.hi != sp.oo else tail_start(p.lo)
        for k in range(1, QUICK_POINTS + 1):
            try:
                low = value_at(E, S, p.lo + (hi - p.lo) * sp.Rational(k, QUICK_POINTS + 1), prec=128).lower_fraction()
            except Undefined:
                continue
            if low is not None and (best is None or low > best):
                best = low
    return best


def _unbounded_at_infinity(E, name: str, limit=True, growth=False) -> SupCertificate | None:
    """The certificate that E, the formula of the last piece, tends to +oo as
    s -> oo (`limit`: by the limit calculus; `growth`: else by the kernel's
    divergence rules, as of s (sqrt(atan(s^2) + 1) - 1) tanh(s^2) + ..., the
    F' of a log cosh whose limit the calculus cannot take), or None."""
    try:
        if limit and limit_at_infinity(E, S) == sp.oo:
            return SupCertificate(None, None, None, None, f"{name} -> oo as s -> oo", {"s": "oo", "limit": "oo"})
    except NoLimit:
        pass
    if growth and far_out_trend(E, S) > 0 and growth_theorems(E, S):
        return SupCertificate(None, None, None, None, f"{name} -> oo as s -> oo (the kernel's divergence rules)",
                              {"s": "oo", "limit": "oo"})
    return None


def certify_sup(analysis, exprs, name: str, near_zero=None, bound_by=None) -> SupCertificate:
    """Certify sup over s > 0 of a function given piecewise by ``exprs``
    (one expression per piece of the profile).  ``bound_by(c)``: True when
    the kernel shows E <= c on (0, oo); tried before the search's own proof
    that an exact candidate attained at a point bounds E.

    ``near_zero``: for E = F'/s, whose formula is 0/0 at s = 0, the caller
    passes F''; by the mean value theorem (F'(0) = 0) E(s) = F''(xi) with
    0 < xi < s, so sup F'' over [0, 1/8] bounds E there from above.  An E
    that is 0/0 at 0 otherwise is bounded there by `quotient_near_zero`."""
    renew_pool()
    pieces = analysis.profile.pieces
    exprs = [prepare(e) for e in exprs]
    if any(e.has(sp.nan, sp.zoo, sp.oo, -sp.oo) for e in exprs):
        return SupCertificate(None, None, None, None, f"{name} has no finite formula on some piece")
    if all(not e.has(S) for e in exprs) and len(set(exprs)) == 1:
        c = exprs[0]
        return exact_certificate(c, True, f"{name} = {c} is constant")
    # unboundedness: a one-sided limit of +oo is a proof
    for E, piece in zip(exprs, pieces):
        ends = [(piece.lo, +1)] + ([(piece.hi, -1)] if piece.hi != sp.oo else [])
        for c, side in ends:
            v = one_sided_value(E, c, side)
            if v == sp.oo:
                return SupCertificate(None, None, None, None, f"{name} -> oo as s -> {c}",
                                      {"s": str(c), "limit": "oo"})
    early = far_out_trend(exprs[-1], S) >= 0     # else the limit at oo only if no bound is found (it is slow)
    if early and (unbounded := _unbounded_at_infinity(exprs[-1], name)):
        return unbounded
    lower, upper, top, near, far = None, Fraction(0), None, None, Fraction(0)   # far: the pieces' bounds beyond
    floor = _quick_lower(exprs, pieces) if len(pieces) > 2 else None   # pieces below it need no tight sup
    for i, (E, piece) in enumerate(zip(exprs, pieces)):
        lo = piece.lo
        if i == 0 and exact_value(E, S, 0) is None and (piece.hi == sp.oo or piece.hi > NEAR_ZERO):
            near = _near_zero_upper(E, near_zero, Fraction(NEAR_ZERO))
            if near is None:
                upper = None
            elif upper is not None:
                upper = max(upper, near)      # an upper bound only (see above)
            lo = sp.Rational(NEAR_ZERO)
        known = [x for x in (floor, lower) if x is not None]
        enc = enclose_sup(E, S, lo, piece.hi, rel_tol=REL_WIDTH, floor=max(known) if known else None)
        if enc.lower is not None and (lower is None or enc.lower > lower):
            lower, top = enc.lower, (E, piece, enc)
        if enc.upper is None:
            upper = None
        elif upper is not None:
            upper, far = max(upper, enc.upper), max(far, enc.upper)
    narrow = near is not None and upper is not None and lower is not None and lower < upper == near
    if narrow and near_zero is None:        # the Taylor quotient's bound: narrowed before the exact candidates
        lower, upper = _narrower_near_zero(exprs[0], near_zero, lower, upper, far)
    if upper is None or lower is None:
        return _unbounded_at_infinity(exprs[-1], name, limit=not early, growth=True) or \
            SupCertificate(lower, None, None, None, f"branch and bound found no finite bound for {name}")
    # exact candidates from the piece holding the supremum
    E, piece, enc = top
    for value, point in _candidates(E, piece.lo, piece.hi, interior=not enc.at_infinity):
        fv = float_of(value)
        if not (float(lower) - 1e-9 * abs(fv) - 1e-300 <= fv <= float(upper) + 1e-9 * abs(fv)):
            continue
        zeros = {id(piece): [point] if point is not None else []}
        ok, strict = (True, None) if point is not None and bound_by is not None and bound_by(value) else \
            _prove_bound(value, exprs, pieces, zeros, strictly=point is None)     # (see `attained`)
        if not ok:
            continue
        if point is not None and point != sp.oo:
            # a one-sided limit at a piece end is a value only where the
            # neighbouring piece (or the origin) continues it; at s = 0 only a
            # sup of 0 (a limit F'(0+) != 0 is no gradient: f has a cone there)
            attained = True if (piece.lo < point < piece.hi or (value == 0 if point == 0 else
                                _continued_at(exprs, pieces, point, value)
                                and _value_continued_at(analysis.profile, point))) else None
        else:
            attained = False if strict else None
        where = f"at s = {point}" if point is not None else "approached as s -> oo"
        return exact_certificate(value, attained,
                              f"sup {name} = {value} {where}, proved by {value} - {name} >= 0 on [0, oo)")
    if narrow and near_zero is not None:    # the bound by sup F'' near 0: narrowed only for an enclosure (slow)
        lower, upper = _narrower_near_zero(exprs[0], near_zero, lower, upper, far)
    return SupCertificate(lower, upper, None, None,
                          f"interval branch and bound: sup {name} in {show_interval(lower, upper)}",
                          point=enc.point)


def _near_zero_upper(E, near_zero, w: Fraction):
    """An upper bound of E on (0, w] (see `certify_sup`): sup F'' there when
    the caller passes F'' (mean value theorem), else, or where that sup has
    no bound (F'' itself 0/0 at 0: F' of sinh(s^2)/s^2 - 1), the Taylor
    quotient bound `quotient_near_zero`; None if neither gives one."""
    if near_zero is not None:
        up = enclose_sup(prepare(near_zero), S, 0, sp.Rational(w), rel_tol=REL_WIDTH).upper
        if up is not None:
            return up
    box = quotient_near_zero(prepare(near_zero if near_zero is not None else E), S, sp.Rational(w))
    return None if box is None else box.upper_fraction()


def _narrower_near_zero(E, near_zero, lower, upper, far):
    """The sup bounds (lower, upper) of E over (0, oo) when the bound on
    (0, NEAR_ZERO] (`_near_zero_upper`) set `upper` above the sup `lower`
    seen: that bound on (0, w] for w = NEAR_ZERO/8, /64, /512 with the branch
    and bound between w and NEAR_ZERO (a short one: the cancellation near 0
    makes it slow; its lower bound raises `lower`) and `far`, the bound of E
    beyond NEAR_ZERO (red team 17: without it the enclosure of a sup at
    s > NEAR_ZERO shrank to [lower, lower], below the true sup), the first
    at or below `lower`; else the smallest found."""
    top, w = Fraction(NEAR_ZERO), Fraction(NEAR_ZERO)
    for _ in range(3):
        w /= 8
        near = _near_zero_upper(E, near_zero, w)
        if near is None or near >= upper:
            break
        mid = enclose_sup(E, S, sp.Rational(w), sp.Rational(top), rel_tol=REL_WIDTH, floor=lower, budget=1500)
        if mid.upper is None:
            break
        lower = lower if mid.lower is None else max(lower, mid.lower)
        upper = min(upper, max(near, mid.upper, far, lower))
        if upper <= lower:
            break
    return lower, upper


def _with_kernel(cert: SupCertificate, analysis, side=None) -> SupCertificate:
    """cert with the kernel's theorems of an exact kf = sup F' (F' > 0,
    F' <= kf, sup F' >= kf; for a Piecewise F also F and F' continuous), or,
    when F' changes sign (`side` = +-1: kf = sup side*F'), of |F'| <= kf and
    sup side*F' >= kf; or the reason it has none."""
    renew_pool()
    pieces = analysis.profile.pieces
    if cert.exact is None and cert.point is not None:
        return _enclosure_with_kernel(cert, analysis, side)
    if cert.exact is None or cert.attained is None:
        cert.unchecked = ["kf: " + ("no exact value" if cert.exact is None else "attainment undecided")]
        return cert
    point = None
    if cert.attained:
        point = next((p for piece in pieces for v, p in _candidates(derivative((side or 1) * piece.expr, S),
                                                                    piece.lo, piece.hi)
                      if p is not None and exact_sign(v - cert.exact) == 0), None)
    if side is not None:
        theorems, why = sup_abs_theorems(derivative(pieces[0].expr, S), cert.exact, point, S, side) \
            if len(pieces) == 1 else (None, "F' of a Piecewise F changes sign")
    elif len(pieces) == 1:
        dF = derivative(pieces[0].expr, S)
        positive, why = sign_theorems(dF, S, 0, sp.oo)
        theorems, why = sup_theorems(dF, cert.exact, point, S, positive[0]) if positive else (None, why)
    else:
        theorems, why = piecewise_sup_theorems(analysis.F, cert.exact, point, S, analysis.profile.ends)
    cert.kernel, cert.unchecked = (theorems, []) if theorems else ([], [f"kf = {cert.exact} (kernel: {why})"])
    if not theorems and point is not None and point != 0:
        return _exact_as_enclosure(cert, analysis, side, point, why)
    return cert


def _exact_as_enclosure(cert: SupCertificate, analysis, side, point, why) -> SupCertificate:
    """An exact kf attained at `point` (an algebraic s, say) that the kernel
    did not take, as the enclosure the kernel checks instead
    (`_enclosure_with_kernel`: F' <= U and F'(p) >= L at a rational p within
    10^-40 of `point`); cert unchanged when it does not take that either."""
    near = sp.Rational(str(sp.N(point, 45)))
    enc = SupCertificate(cert.lower, cert.upper, None, None,
                         f"{cert.reason} (the search's; the kernel did not take the exact value: {why})", point=near)
    enc = _enclosure_with_kernel(enc, analysis, side)
    return enc if enc.kernel else cert


def _enclosure_with_kernel(cert: SupCertificate, analysis, side=None) -> SupCertificate:
    """cert, when kf = sup F' (F' >= 0) is only enclosed, with the kernel's
    theorems F' >= 0, F' <= U and sup F' >= L (its value at cert.point),
    where L <= lower and U >= upper are short decimals (U about 1/8 above
    when the tight one is not shown within its budget): `kernel_bounds`; for a
    Piecewise F, `_piecewise_enclosure`.  When F' changes sign (`side` = +-1:
    kf = sup side*F'), |F'| <= U and sup side*F' >= L instead."""
    L, tiers = decimal_beyond(cert.lower, -1), _tiers(cert.upper)
    if len(analysis.profile.pieces) > 1:
        U, theorems, why = (None, None, "F' of a Piecewise F changes sign") if side else \
            _piecewise_enclosure(cert, analysis, L, tiers)
    else:
        U, theorems, why = _formula_enclosure(cert, analysis, L, tiers, side)
    if theorems is None:
        cert.unchecked = [f"kf in {show_interval(cert.lower, cert.upper)} (kernel: {why})"]
        return cert
    cert.kernel_bounds = (Fraction(L.p, L.q), Fraction(U.p, U.q))
    cert.kernel, cert.unchecked = theorems, []
    return cert


def _tiers(upper):
    """The upper bounds U the kernel is asked for, with their budgets: a
    short decimal just above `upper` (twice a lemma's work), then one about
    1/8 above it."""
    return (decimal_beyond(upper, 1), 2 * WORK), (decimal_beyond(upper * Fraction(9, 8), 1, 2), WORK)


def _formula_enclosure(cert: SupCertificate, analysis, L, tiers, side=None):
    """(U, [F' >= 0, F' <= U, sup F' >= L], "") for an F of one formula, the
    first U of `tiers` (with its budget) that the kernel takes; with `side`,
    (U, [|F'| <= U, sup side*F' >= L], ""); or (None, None, why)."""
    dF = derivative(analysis.kernel_F, S)
    positive = analysis.slope_sign
    upper = None
    for U, work in tiers:
        if L <= 0 or side is None and positive is None:
            break
        renew_pool()        # (what a tighter U spent exploring tails is no loss to a looser one)
        upper = sup_upper_theorem(dF, U, S, work=work) if side is None else abs_upper_theorem(dF, U, S, work=work)
        if upper is not None:
            break
    if upper is None:
        return None, None, f"F' >= 0 and F' <= {U} not shown" if side is None else f"|F'| <= {U} not shown"
    lower = sup_lower_theorem((side or 1) * dF, L, cert.point, S)
    if lower is None:
        return None, None, f"F'({cert.point}) >= {L} not shown"
    return U, [upper, lower] if side else [positive, upper, lower], ""


def _piecewise_enclosure(cert: SupCertificate, analysis, L, tiers):
    """(U, theorems of `piecewise_sup_theorems` with the enclosure [L, U],
    "") for a Piecewise F, each U of `tiers` with its budget scaled to the
    branch (the covers near the maximum use the mean value form, so the
    tight U costs about what the loose one does); or (None, None, why)."""
    if L <= 0:
        return None, None, "the lower end is not positive"
    for U, work in tiers:
        theorems, why = piecewise_sup_theorems(analysis.F, U, cert.point, S, analysis.profile.ends, lower=L,
                                               work=work)
        if theorems:
            return U, theorems, ""
    return None, None, why


class _CompactPrinter(sp.printing.str.StrPrinter):
    """SymPy's str, with an integer of more than 21 digits that is m 10^k
    (k >= 6) or 2^k written so, in parentheses: (10**300), not 301 digits."""

    def _print_Integer(self, expr):
        n = int(expr)
        if abs(n) < 10 ** 21:
            return str(n)
        m, k = abs(n), 0
        while m % 10 == 0:
            m, k = m // 10, k + 1
        sign = "-" if n < 0 else ""
        if k >= 6:
            return f"{sign}({'' if m == 1 else f'{m}*'}10**{k})"
        if abs(n) & (abs(n) - 1) == 0:
            return f"{sign}(2**{abs(n).bit_length() - 1})"
        return str(n)

    def _print_Rational(self, expr):
        if expr.q == 1:
            return self._print_Integer(expr)
        return f"{self._print_Integer(sp.Integer(expr.p))}/{self._print_Integer(sp.Integer(expr.q))}"


def exact_text(e) -> str:
    """An exact SymPy value or expression for messages and reports, which
    SymPy reads back (`sympify`): huge integers as powers (`_CompactPrinter`)."""
    text = _CompactPrinter().doprint(sp.sympify(e))
    sign, body = ("-", text[1:]) if text.startswith("-") else ("", text)
    inner = body[1:-1]
    return sign + inner if body.startswith("(") and body.endswith(")") and "(" not in inner else text


def show(x, digits: int = 10) -> str:
    """x (a Fraction or rational of any size) with `digits` significant digits,
    for messages: as a float where that is exact enough, else by mpmath (a
    float would print 10^-400 as 0 and fail on 10^400)."""
    x = Fraction(x)
    try:
        v = float(x)
    except OverflowError:
        v = math.inf
    if x == 0 or 1e-300 < abs(v) < math.inf:
        return f"{v:.{digits}g}"
    return mpmath.nstr(mpmath.mpf(x.numerator) / x.denominator, digits)


def show_interval(lower, upper, digits: int = 10) -> str:
    """[lower, upper] (Fractions or floats) with `digits` significant digits,
    rounded outward: the printed interval holds the one given."""
    return f"[{show(decimal_beyond(lower, -1, digits), digits)}, {show(decimal_beyond(upper, 1, digits), digits)}]"


def certify_kf(analysis) -> SupCertificate:
    """kf = sup |F'| over [0, oo) (bound (10), property P1); an enclosure's
    lower end at least 0 (a sup of |F'|: a branch and bound that cancels
    badly, log(1 + rho) (cosh^2 e1 - sinh^2 e1), had printed [-5949.9, 5965.9])."""
    cert = _sup_abs_slope(analysis)
    if cert.lower is not None and cert.lower < 0:
        cert.lower = Fraction(0)
    return cert


def _sup_abs_slope(analysis) -> SupCertificate:
    pieces = analysis.profile.pieces
    dF = [prepare(derivative(p.expr, S)) for p in pieces]
    pos = certify_sup(analysis, dF, "F'")
    if pos.upper is None:
        return pos
    if analysis.slope_theorem is not None or all(prove_sign(e, S, p.lo, p.hi, want=1, strict=False, budget=1500).proved
                                                 for e, p in zip(dF, pieces)):
        return _with_kernel(pos, analysis)    # F' >= 0 everywhere: sup |F'| = sup F'
    neg = certify_sup(analysis, [-e for e in dF], "-F'")
    if neg.upper is None:
        return neg
    if neg.upper <= (pos.lower if pos.lower is not None else 0):
        return _with_kernel(pos, analysis, side=1)
    if pos.upper <= (neg.lower if neg.lower is not None else 0):
        return _with_kernel(neg, analysis, side=-1)
    return SupCertificate(max(pos.lower, neg.lower), max(pos.upper, neg.upper), None, None,
                          "sup |F'| from both signs of F'")


def psi_sides(f) -> list | None:
    """psi(s), -psi(s), psi(-s), -psi(-s) for an f without Abs, Piecewise,
    Max, Min or sign whose df/de2 = psi(e2) is free of e1 and not constant;
    else None."""
    sides = e2_sides(f)
    if f.has(*SMOOTH_ONLY, sp.Abs) or any(e.has(E1) for e in sides) or not sides[0].has(S):
        return None
    return sides


def certify_kf_along_e2(f) -> SupCertificate | None:
    """kf = sup over R of |psi(e2)| (bound (10)) for an f analytic on the plane
    whose df/de2 = psi(e2) is free of e1 (a separable g(e1) + h(e2), radial
    or not): the largest sup over s > 0 of psi(s), -psi(s), psi(-s),
    -psi(-s) (psi is continuous at 0), each enclosed by branch and bound.
    The kernel's theorems (`design_certificate._link_plane`): f analytic on
    the plane, the four <= U and sup >= L of the side that reaches it, for
    short decimals L <= lower, U >= upper (`kernel_bounds`).  None when f is
    not of this kind or a side has no finite bound found."""
    sides = psi_sides(f)
    if sides is None:
        return None
    encs = [enclose_sup(e, S, 0, sp.oo, rel_tol=REL_WIDTH) for e in sides]
    found = [(e, enc) for e, enc in zip(sides, encs) if enc.upper is not None and enc.lower is not None]
    if not found:
        return None
    side, best = max(found, key=lambda p: p[1].lower)
    cert = SupCertificate(best.lower, max(enc.upper for _, enc in found), None, None, "", point=best.point)
    blind = len(found) < len(sides)     # (-psi when psi > 0 decays: sup 0, approached at 0 and oo)
    cert.reason = (f"df/de2 = psi(e2) does not depend on e1 (f analytic on the plane): kf = sup |psi| in "
                   f"{show_interval(cert.lower, cert.upper)} (interval branch and bound on both half-axes)")
    L = decimal_beyond(cert.lower, -1)
    plane = plane_theorems(f, E1, E2, []) if L > 0 and best.point is not None else []
    lower = sup_lower_theorem(side, L, best.point, S) if plane else None
    for U, work in _tiers(cert.upper) if lower else ():
        renew_pool()
        uppers = [sup_upper_theorem(e, U, S, work=work) for e in sides]
        if None not in uppers:
            cert.kernel, cert.unchecked = plane + uppers + [lower], []
            cert.kernel_bounds = (Fraction(L.p, L.q), Fraction(U.p, U.q))
            if blind:
                cert.upper = max(cert.upper, cert.kernel_bounds[1])
            return cert
    if blind:          # a side the search did not bound: only the kernel's bound U makes [lower, upper] an enclosure
        return None
    cert.unchecked = [f"kf in {show_interval(cert.lower, cert.upper)} (kernel: "
                      + ("f not shown analytic on the plane, or sup psi >= L not shown)" if not lower else
                         "|psi| <= U not shown)")]
    return cert
