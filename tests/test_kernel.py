"""The trusted kernel (uwmr_symbolic/kernel): every rule accepts a true claim
and rejects a false or ill-formed one; the evaluator encloses ranges and
refuses what is undefined; tampered certificates are rejected."""
import copy
import dataclasses
import json

import mpmath
import pytest
import sympy as sp

from uwmr_symbolic.certify import to_certificate
from uwmr_symbolic.kernel import (RULES, VERSION, CertificateError, Claim, KernelError, Theorem, Undefined,
                                  check_certificate, evaluate, rules as K)
from uwmr_symbolic.kernel.certificate import SCHEMA
from uwmr_symbolic.kernel.core import _cross_check
from uwmr_symbolic.kernel.parse import ParseError, parse

x = sp.Symbol("x", real=True)
s = sp.Symbol("s", positive=True)
t = sp.Symbol("t", positive=True)
Q = sp.Rational
ZERO = sp.Integer(0)


def rejects(fn, *args, **kw):
    with pytest.raises(KernelError):
        fn(*args, **kw)


def sturm(e, var, lo, hi, lo_open=False, hi_open=False, want=1, strict=True):
    return K.sign_by_sturm(expr=e, var=var, lo=sp.sympify(lo), hi=sp.sympify(hi),
                           lo_open=lo_open, hi_open=hi_open, want=want, strict=strict)


# ------------------------------------------------------------------ evaluator

@pytest.mark.parametrize("e, lo, hi", [
    (x ** 2 - x + 1, -2, 3), (sp.sin(3 * x) * sp.exp(-x), -1, 2), (sp.sqrt(1 + x ** 2) - sp.Abs(x), -3, 1),
    (sp.tanh(x) + sp.atan(x) - sp.asinh(x) + sp.erf(x) * sp.cosh(x), -2, 2),
    (sp.log(2 + sp.cos(x)) / (1 + x ** 4), -1, 5), (x ** Q(5, 3) + x ** Q(-1, 2), Q(1, 10), 4),
    (sp.sinh(x) ** 3 - 1 / (x + 5), -2, 1),
])
def test_evaluator_encloses_the_range(e, lo, hi):
    box = evaluate(e, x, lo, hi)
    f = sp.lambdify(x, e, "mpmath")
    mpmath.mp.dps = 30
    for k in range(201):
        v = f(mpmath.mpf(lo) + (mpmath.mpf(hi) - lo) * k / 200)
        assert float(box.lo.lower()) <= float(v) <= float(box.hi.upper())


@pytest.mark.parametrize("e, lo, hi", [
    (sp.log(x), 0, 1), (sp.sqrt(x), -Q(1, 10 ** 30), 1), (x ** Q(1, 3), -1, 1), (1 / x, -1, 1),
    (x ** Q(-1, 2), 0, 1), (sp.log(x - 1), 1, 2), (sp.gamma(x), 1, 2), (sp.Float(0.5) * x, 0, 1),
    (sp.Piecewise((x, x > 0), (0, True)), -1, 1), (sp.sqrt(x - 2), 0, 1), (sp.I * x, 0, 1),
    (sp.sign(x), -1, 1), (sp.sign(x), 0, 0), (sp.sign(x - Q(1, 3)), Q(1, 3), 1),  # sign jumps at 0: no value there
])
def test_evaluator_refuses_undefined_or_unsupported(e, lo, hi):
    with pytest.raises(Undefined):
        evaluate(e, x, lo, hi)


def test_evaluator_domain_edges_are_not_clipped():
    assert evaluate(sp.sqrt(s), s, 0, Q(1, 8)).lo.is_zero()        # touching 0 from above is fine
    assert evaluate(x ** 2, x, -1, 2).nonnegative()                   # even powers are >= 0
    assert evaluate(sp.Abs(x) - 1, x, -1, 2).lo.lower() >= -1
    assert evaluate(sp.cosh(x), x, -1, 2).lo.lower() >= 1
    assert evaluate(sp.log(x), x, Q(1, 10 ** 30), 1).hi.upper() >= 0
    # powers of an end that is a ball around 0 ((x - 1/3) at x = 1/3; Arb's own b**n is NaN there)
    at_zero = evaluate((x - Q(1, 3)) ** 4, x, Q(1, 3), Q(1, 3))
    assert at_zero.lo.is_zero() and 0 <= at_zero.hi.upper() < Q(1, 10 ** 100)
    # sign u is evaluated where the enclosure of u excludes 0 (constant there, so continuous)
    assert [(float(v.lo.mid()), float(v.hi.mid())) for v in (evaluate(sp.sign(x - 1) * 3, x, Q(3, 2), 5),
            evaluate(2 + sp.sign(x ** 3 - 1), x, -4, Q(1, 2)))] == [(3, 3), (1, 1)]
    odd = evaluate((x - Q(1, 3)) ** 3 + 2, x, 0, Q(1, 3))           # -1/27 + 2 <= e <= 2
    assert abs(float(odd.lo.mid()) - 53 / 27) < 1e-14 and abs(float(odd.hi.mid()) - 2) < 1e-14


# ------------------------------------------------------------------ theorems

def test_theorems_only_from_rules():
    thm = K.value_sign(value=sp.Integer(2))
    with pytest.raises(KernelError):
        Theorem(thm.claim, "made up", (), "{}", frozenset())
    with pytest.raises(KernelError):
        dataclasses.replace(thm, claim=dataclasses.replace(thm.claim, want=-1))
    with pytest.raises(KernelError):
        K.join(thm.claim, thm.claim)      # claims are not theorems


def test_variables_and_expressions_are_checked():
    n = sp.Symbol("n", integer=True)
    z = sp.Symbol("z")
    rejects(K.sign_by_cover, expr=n ** 2 + 1, var=n, cuts=[0, 1], want=1)
    rejects(K.sign_by_cover, expr=z ** 2 + 1, var=z, cuts=[0, 1], want=1)
    rejects(K.sign_by_cover, expr=x + s, var=x, cuts=[0, 1], want=1)
    rejects(K.sign_by_cover, expr=x + sp.Float(1.5), var=x, cuts=[0, 1], want=1)
    rejects(K.sign_by_taylor, expr=sp.sin(s), var=s, c=ZERO, side=-1, width=Q(1, 2), order=1)  # s > 0


def test_parse_reads_srepr_only():
    assert parse(sp.srepr(sp.sqrt(2) * sp.exp(-s) + sp.pi)) == sp.sqrt(2) * sp.exp(-s) + sp.pi
    for bad in ["__import__('os').system('true')", "Symbol('x', integer=True)", "Integer(1).__class__",
                "Float('1.5')", "[1, 2]", "lambda: 1"]:
        with pytest.raises(ParseError):
            parse(bad)


# ------------------------------------------------------------------ rules

def test_sign_by_cover():
    thm = K.sign_by_cover(expr=x ** 2 - x + 1, var=x, cuts=[Q(k, 8) for k in range(-16, 25)], want=1)
    assert (thm.claim.lo, thm.claim.hi, thm.claim.strict) == ("Integer(-2)", "Integer(3)", True)
    rejects(K.sign_by_cover, expr=x ** 2 - 2, var=x, cuts=[0, 1, 2, 3], want=1)     # x**2 - 2 < 0 at 0
    rejects(K.sign_by_cover, expr=x ** 2 - x + 1, var=x, cuts=[-2, 0], want=-1)
    rejects(K.sign_by_cover, expr=x ** 2 + 1, var=x, cuts=[0, 2, 1, 3], want=1)     # not increasing
    rejects(K.sign_by_cover, expr=x ** 2 + 1, var=x, cuts=[0], want=1)
    rejects(K.sign_by_cover, expr=1 / x, var=x, cuts=[-1, 1], want=1)               # undefined at 0
    # weak: x**2 >= 0 across 0; strictly it fails
    K.sign_by_cover(expr=x ** 2, var=x, cuts=[-1, 0, 1], want=1, strict=False)
    rejects(K.sign_by_cover, expr=x ** 2, var=x, cuts=[-1, 0, 1], want=1, strict=True)


def test_sign_by_cover_one_step_below_the_zero():
    c0 = Q(3, 8)
    step = Q(1, 2 ** 60)
    K.sign_by_cover(expr=x - c0, var=x, cuts=[c0 + step, 1], want=1)
    rejects(K.sign_by_cover, expr=x - c0, var=x, cuts=[c0, 1], want=1)
    rejects(K.sign_by_cover, expr=x - c0, var=x, cuts=[c0 - step, 1], want=1, strict=False)


def test_sign_by_cover_mean_value():
    """E = 1 + 10^-6 - x (2 - x) has its minimum 10^-6 at x = 1.  Over a box of
    width 10^-3 the range enclosure loses about 10^-3 to the two copies of x;
    the mean value form E(m) + E'(B)(B - m) loses only about the width squared."""
    e = 1 + Q(1, 10 ** 6) - x * (2 - x)
    cuts = [Q(999, 1000), 1, Q(1001, 1000)]
    rejects(K.sign_by_cover, expr=e, var=x, cuts=cuts, want=1)
    thm = K.sign_by_cover(expr=e, var=x, cuts=cuts, want=1, mean_value=True)
    assert "sympy-diff" in thm.assumptions and thm.claim.strict and thm.claim.lo == "Rational(999, 1000)"
    assert "sympy-diff" not in K.sign_by_cover(expr=x + 1, var=x, cuts=[0, 1], want=1).assumptions
    rejects(K.sign_by_cover, expr=e - Q(2, 10 ** 6), var=x, cuts=cuts, want=1, mean_value=True)   # -10^-6 at 1
    rejects(K.sign_by_cover, expr=e, var=x, cuts=[Q(99, 100), 1, Q(101, 100)], want=1, mean_value=True)
    rejects(K.sign_by_cover, expr=e, var=x, cuts=cuts, want=1, mean_value=1)        # not a boolean
    # |x - 1|^3 is C^1, but its derivative has sign(x - 1): the form is refused
    rejects(K.sign_by_cover, expr=e + sp.Abs(x - 1) ** 3, var=x, cuts=cuts, want=1, mean_value=True)
    # the form needs E defined on the whole box, not only E': log(x) has 1/x on [-2, -1]
    rejects(K.sign_by_cover, expr=sp.log(x) + 5, var=x, cuts=[-2, -1], want=1, mean_value=True)


def test_sign_by_taylor():
    thm = K.sign_by_taylor(expr=x - sp.sin(x), var=x, c=ZERO, side=1, width=Q(1, 2), order=3)
    assert (thm.claim.want, thm.claim.lo_open, thm.claim.hi_open) == (1, True, False)
    left = K.sign_by_taylor(expr=x - sp.sin(x), var=x, c=ZERO, side=-1, width=Q(1, 2), order=3)
    assert left.claim.want == -1 and left.claim.hi_open and "sympy-diff" in left.assumptions
    # E'' (0) = 2: the lower derivatives do not vanish
    rejects(K.sign_by_taylor, expr=x - sp.sin(x) + x ** 2, var=x, c=ZERO, side=1, width=Q(1, 2), order=3)
    rejects(K.sign_by_taylor, expr=sp.cos(x), var=x, c=ZERO, side=1, width=Q(1, 2), order=1)
    # E''' = cos x changes sign on [0, 4]
    rejects(K.sign_by_taylor, expr=x - sp.sin(x), var=x, c=ZERO, side=1, width=sp.Integer(4), order=3)
    # sub-boxes for E^(m): its natural enclosure on all of [1, 5/4] is too wide
    D = Q(1, 2) - s / (s ** 2 + 1)
    rejects(K.sign_by_taylor, expr=D, var=s, c=sp.Integer(1), side=1, width=Q(1, 4), order=2)
    cuts = [1 + Q(k, 32) for k in range(9)]
    K.sign_by_taylor(expr=D, var=s, c=sp.Integer(1), side=1, width=Q(1, 4), order=2, cuts=cuts)
    rejects(K.sign_by_taylor, expr=D, var=s, c=sp.Integer(1), side=1, width=Q(1, 4), order=2,
            cuts=cuts[:-1])                                               # cuts must end at c + w
    # E = x*log(x) is not defined at 0
    rejects(K.sign_by_taylor, expr=s * sp.log(s) + s, var=s, c=ZERO, side=1, width=Q(1, 4), order=1)
    # E = 1 - |s - 1| (a condition |e| < 1 on the line e = 1 - s): E' = sign(1 - s) = 1 on [0, 1/4], so E > 0 on
    # (0, 1/4]; on [0, 2] E' jumps at s = 1 and has no value there.  Left of x = 2, E = 2 - x > 0 (E' = -1,
    # side -1); right of it E'(2) = -1 is not 0, so order 2 is refused
    assert K.sign_by_taylor(expr=1 - sp.Abs(s - 1), var=s, c=ZERO, side=1, width=Q(1, 4), order=1).claim.want == 1
    rejects(K.sign_by_taylor, expr=1 - sp.Abs(s - 1), var=s, c=ZERO, side=1, width=sp.Integer(2), order=1)
    assert K.sign_by_taylor(expr=1 - sp.Abs(x - 1), var=x, c=sp.Integer(2), side=-1, width=Q(1, 2),
                            order=1).claim.want == 1
    rejects(K.sign_by_taylor, expr=1 - sp.Abs(x - 1), var=x, c=sp.Integer(2), side=1, width=Q(1, 2), order=2)


def test_limit_by_taylor():
    # by hand: sinh(u) = u + u^3/6 + ..., so sinh(s^2)/s^2 - 1 = (sinh(s^2) - s^2)/s^2 -> 0; D = s^2 has a
    # zero of order 2 at 0 (D'' = 2); (1 - cos s)/s^2 -> 1/2; log(1 + s)^2/s -> 0 with D = s of order 1
    w = Q(1, 2)
    E = sp.sinh(s ** 2) / s ** 2 - 1
    thm = K.limit_by_taylor(expr=E, num=sp.sinh(s ** 2) - s ** 2, den=s ** 2, var=s, order=2, width=w)
    assert (thm.claim.kind, thm.claim.lo, thm.claim.other) == ("limit", "Integer(0)", "Integer(0)")
    assert {"sympy-diff", "sympy-polys"} <= thm.assumptions
    half = K.limit_by_taylor(expr=(1 - sp.cos(s)) / s ** 2, num=1 - sp.cos(s), den=s ** 2, var=s, order=2, width=w)
    assert parse(half.claim.other) == Q(1, 2)
    K.limit_by_taylor(expr=sp.log(1 + s) ** 2 / s, num=sp.log(1 + s) ** 2, den=s, var=s, order=1, width=w)
    # order 1: D' = 2s is 0 at 0, no strict sign on [0, w]; order 0 is continuity (continuous_at_end)
    for order in (0, 1, 13):
        rejects(K.limit_by_taylor, expr=E, num=sp.sinh(s ** 2) - s ** 2, den=s ** 2, var=s, order=order, width=w)
    # N/D is not E (the 1 of E left out); E defined at 0 (cos s = s cos s / s is no 0/0)
    rejects(K.limit_by_taylor, expr=E, num=sp.sinh(s ** 2), den=s ** 2, var=s, order=2, width=w)
    rejects(K.limit_by_taylor, expr=sp.cos(s), num=s * sp.cos(s), den=s, var=s, order=1, width=w)
    # N does not vanish to order 2 (sinh(s)/s^2 -> oo); for D = s^2 - s^3, D'' = 2 - 6s has no strict sign
    # on [0, 1/2] (D vanishes at s = 1 only, but the rule asks D'' signed on all of [0, w]); on [0, 1/4] it has
    rejects(K.limit_by_taylor, expr=sp.sinh(s) / s ** 2, num=sp.sinh(s), den=s ** 2, var=s, order=2, width=w)
    rejects(K.limit_by_taylor, expr=(1 - sp.cos(s)) / (s ** 2 - s ** 3), num=1 - sp.cos(s), den=s ** 2 - s ** 3,
            var=s, order=2, width=w)
    K.limit_by_taylor(expr=(1 - sp.cos(s)) / (s ** 2 - s ** 3), num=1 - sp.cos(s), den=s ** 2 - s ** 3,
                      var=s, order=2, width=Q(1, 4))
    # a tampered limit: the claim moved from 1/2 by 10^-30
    cert = json.loads(json.dumps(to_certificate([half])))
    check_certificate(cert)
    cert["theorems"][0]["claim"]["other"] = sp.srepr(Q(1, 2) + Q(1, 10 ** 30))
    with pytest.raises(CertificateError, match="claims"):
        check_certificate(cert)


def test_sign_by_sturm():
    assert sturm(x ** 2 - 2, x, Q(3, 2), sp.oo, hi_open=True).claim.want == 1
    sturm(x ** 2 - 2, x, -1, 1, want=-1)
    rejects(sturm, x ** 2 - 2, x, 1, 2)                                  # sqrt(2) inside
    sturm(x - 1, x, 1, 2, lo_open=True)
    rejects(sturm, x - 1, x, 1, 2)                                       # closed end is a root
    sturm((x - 1) ** 2, x, 0, 3, strict=False)
    rejects(sturm, (x - 1) ** 2, x, 0, 3)
    sturm(x * (x - 1), x, 1, 2, strict=False)                            # roots at the ends only
    rejects(sturm, x * (x - 1), x, 0, 2, strict=False)                   # a sign change inside
    sturm((x ** 2 - 2 * x + 1) * (x ** 2 + 1), x, -sp.oo, sp.oo, True, True, strict=False)
    rejects(sturm, 1 / x, x, -1, 2)                                      # a pole inside
    rejects(sturm, (x ** 2 - 1) / (x - 1), x, 0, 2)                      # undefined at 1 (= x + 1 elsewhere)
    rejects(sturm, sp.sqrt(2) * x, x, 1, 2)
    rejects(sturm, x ** 2 + 1, x, 0, 1, want=-1)
    # irrational ends: a rational within 2^-22 beside each, found exactly (no float of the end)
    sturm(x ** 2 - 2, x, sp.sqrt(2), 2, lo_open=True)
    rejects(sturm, x ** 2 - 2, x, sp.sqrt(2), 2)                          # the closed end is a root
    sturm(x - 3, x, sp.E, 3, hi_open=True, want=-1)
    rejects(sturm, x - 3, x, sp.E, sp.pi, want=-1)                        # 3 < pi: a root inside
    sturm(x - 2 ** 80, x, sp.exp(60), sp.oo, hi_open=True)                # e^60 = 1.14e26 > 2^80 = 1.21e24
    rejects(sturm, x - 2 ** 90, x, sp.exp(60), sp.oo, hi_open=True)       # 2^90 = 1.24e27 > e^60
    rejects(sturm, x, x, 1, sp.exp(2000))       # red team 16a: an OverflowError (float of e^2000), now refused


def test_sign_of_product():
    num = sturm(s, s, 1, 2)
    den = sturm(s ** 2 + 1, s, 1, 2)
    thm = K.sign_of_product(num, den, expr=s / (s ** 2 + 1))
    assert (thm.claim.want, thm.claim.strict) == (1, True)
    assert K.sign_of_product(num, den, expr=-3 * s / (s ** 2 + 1)).claim.want == -1
    assert K.sign_of_product(den, expr=(s ** 2 + 1) ** Q(-3, 2)).claim.want == 1
    rejects(K.sign_of_product, num, expr=s / (s ** 2 + 1))                       # a factor uncovered
    rejects(K.sign_of_product, num, sturm(s ** 2 + 1, s, 1, 3), expr=s / (s ** 2 + 1))  # other interval
    weak = sturm(x - 1, x, 1, 2, strict=False)
    rejects(K.sign_of_product, weak, expr=1 / (x - 1))                           # 1/0 at x = 1
    rejects(K.sign_of_product, sturm(x - 1, x, 1, 2, want=1, lo_open=True), expr=(x - 1) * sp.Integer(0) + 1)
    neg = sturm(x - 3, x, 1, 2, want=-1)
    assert K.sign_of_product(neg, expr=(x - 3) ** 2).claim.want == 1
    assert K.sign_of_product(neg, expr=(x - 3) ** 3).claim.want == -1
    rejects(K.sign_of_product, neg, expr=sp.sqrt(x - 3))                         # real power of a negative


def test_sign_of_sum():
    sq = sturm(x ** 2, x, -1, 1, strict=False)
    thm = K.sign_of_sum(sq, expr=x ** 2 + 1, want=1)
    assert thm.claim.strict
    assert not K.sign_of_sum(sq, sturm(x ** 4, x, -1, 1, strict=False), expr=x ** 2 + x ** 4, want=1).claim.strict
    rejects(K.sign_of_sum, sq, expr=x ** 2 - 1, want=1)                          # constant -1
    rejects(K.sign_of_sum, sq, expr=x ** 2 + x + 1, want=1)                      # x uncovered
    rejects(K.sign_of_sum, sturm(x - 2, x, -1, 1, want=-1), expr=x ** 2 + x - 2, want=1)


def test_sign_of_sum_over_groups_of_terms():
    """x^2 - x + 2 on [-1, 1] from the groups 2 - x > 0 and x^2 >= 0."""
    two_minus_x, sq = sturm(2 - x, x, -1, 1), sturm(x ** 2, x, -1, 1, strict=False)
    thm = K.sign_of_sum(two_minus_x, sq, expr=x ** 2 - x + 2, want=1)
    assert (thm.claim.expr, thm.claim.want, thm.claim.strict) == (sp.srepr(x ** 2 - x + 2), 1, True)
    assert not K.sign_of_sum(sq, sturm(x ** 4, x, -1, 1, strict=False), expr=x ** 2 + x ** 4, want=1).claim.strict
    rejects(K.sign_of_sum, sturm(3 - x, x, -1, 1), sq, expr=x ** 2 - x + 2, want=1)       # 3 is no term
    rejects(K.sign_of_sum, two_minus_x, sturm(x ** 2 - x + 1, x, -1, 1), expr=x ** 2 - x + 2, want=1)  # -x twice
    rejects(K.sign_of_sum, sq, expr=x ** 2 - x + 2, want=1)                               # -x uncovered


def test_sign_below_sup():
    """G(y) < sup G for every real y: tanh and erf below 1, atan below pi/2."""
    pos = sturm(s, s, 0, 2, lo_open=True)
    for e, g in ((1 - sp.tanh(s), sp.tanh(s)), (2 - 2 * sp.tanh(s), sp.tanh(s)), (Q(3, 2) - sp.erf(s), sp.erf(s)),
                 (sp.pi / 2 - sp.atan(s), sp.atan(s))):
        thm = K.sign_below_sup(pos, expr=e, bounded=g)
        assert thm.claim == Claim("sign", sp.srepr(e), sp.srepr(s), sp.srepr(ZERO), sp.srepr(sp.Integer(2)),
                                  True, False, 1, True)
    for e, g in ((Q(99, 100) - sp.tanh(s), sp.tanh(s)),         # a + m sup G < 0
                 (Q(3, 2) - sp.atan(s), sp.atan(s)),            # 3/2 < pi/2
                 (Q(99, 100) + sp.tanh(s), sp.tanh(s)),         # m > 0: a - |m| sup G < 0 (tanh > -1 only)
                 (1 - sp.tanh(s) ** 2, sp.tanh(s)),             # not a + m G
                 (1 - s * sp.tanh(s), sp.tanh(s)),              # m depends on s
                 (1 - sp.sinh(s), sp.sinh(s)),                  # sinh is unbounded
                 (1 - sp.tanh(2 * s), sp.tanh(2 * s))):         # the premise is about s, not 2 s
        rejects(K.sign_below_sup, pos, expr=e, bounded=g)


def test_sign_below_product():
    """c - A B >= 0 from A <= a, 0 <= B <= b, c >= a b: 1 - s^3 = 1 - (s)(s^2)
    on [0, 1] (weak: c = a b), 2 - s^3 strictly."""
    I1 = sp.Integer(1)
    a_bound, b_sign, b_bound = (sturm(e, s, 0, 1, strict=False) for e in (1 - s, s ** 2, 1 - s ** 2))
    thm = K.sign_below_product(a_bound, b_sign, b_bound, expr=1 - s ** 3, a=I1, b=I1)
    assert thm.claim == Claim("sign", sp.srepr(1 - s ** 3), sp.srepr(s), sp.srepr(ZERO), sp.srepr(I1),
                              False, False, 1, False)
    assert K.sign_below_product(a_bound, b_sign, b_bound, expr=2 - s ** 3, a=I1, b=I1).claim.strict
    rejects(K.sign_below_product, a_bound, b_sign, b_bound, expr=Q(1, 2) - s ** 3, a=I1, b=I1)   # c < a b
    rejects(K.sign_below_product, a_bound, b_sign, b_bound, expr=1 - s ** 3, a=I1, b=2 * I1)      # 2 - s^2: no premise
    rejects(K.sign_below_product, a_bound, b_sign, b_bound, expr=1 - s ** 4, a=I1, b=I1)          # not c - A B
    rejects(K.sign_below_product, a_bound, b_sign, a_bound, expr=1 - s ** 3, a=I1, b=I1)          # b - B is 1 - s^2
    rejects(K.sign_below_product, a_bound, sturm(s ** 2, s, 0, 2, strict=False), b_bound,
            expr=1 - s ** 3, a=I1, b=I1)                                                          # two intervals
    rejects(K.sign_below_product, a_bound, sturm(-s ** 2 - 1, s, 0, 1, want=-1), b_bound,
            expr=1 - s ** 3, a=I1, b=I1)                                                          # a <= 0 claim
    # a = -1 < 0: A = -1 - s <= a, yet -1/2 - A s^2 = -1/2 + (1 + s) s^2 is -1/2 at 0 (c - a b = 1/2 >= 0)
    A = -1 - s
    rejects(K.sign_below_product, sturm(s, s, 0, 1, strict=False), b_sign, b_bound, expr=-Q(1, 2) - A * s ** 2,
            a=-I1, b=I1)


def test_sign_of_increasing_difference():
    """G(Y) - G(c) has the sign of Y - c for G increasing: tanh(s) - tanh(1) on (1, 3]."""
    above = sturm(s - 1, s, 1, 3, lo_open=True)
    for G in (sp.tanh, sp.atan, sp.asinh, sp.sinh, sp.erf, sp.exp):
        thm = K.sign_of_increasing_difference(above, expr=G(s) - G(1), inner=G(s), c=sp.Integer(1))
        assert thm.claim == Claim("sign", sp.srepr(G(s) - G(1)), sp.srepr(s), sp.srepr(sp.Integer(1)),
                                  sp.srepr(sp.Integer(3)), True, False, 1, True)
    below = sturm(s - 3, s, 1, 3, hi_open=True, want=-1, strict=False)
    weak = K.sign_of_increasing_difference(below, expr=sp.tanh(s) - sp.tanh(3), inner=sp.tanh(s), c=sp.Integer(3))
    assert (weak.claim.want, weak.claim.strict) == (-1, False)
    rejects(K.sign_of_increasing_difference, above, expr=sp.tanh(s) - sp.tanh(2), inner=sp.tanh(s), c=sp.Integer(2))
    rejects(K.sign_of_increasing_difference, above, expr=sp.cos(s) - sp.cos(1), inner=sp.cos(s), c=sp.Integer(1))
    rejects(K.sign_of_increasing_difference, above, expr=sp.tanh(s) - sp.atan(1), inner=sp.tanh(s), c=sp.Integer(1))
    rejects(K.sign_of_increasing_difference, above, expr=sp.tanh(s) - sp.tanh(1), inner=sp.tanh(s), c=sp.oo)
    # k (G(Y) - G(c)) for an exact k != 0 has the sign of k (Y - c) (SymPy writes 5 tanh(s) - 5 tanh(1));
    # not two different k's, not k = 0
    for k in (5, -5, sp.pi, -sp.E / 2):
        th = K.sign_of_increasing_difference(above, expr=k * sp.tanh(s) - k * sp.tanh(1), inner=k * sp.tanh(s),
                                             c=sp.Integer(1))
        assert (th.claim.want, th.claim.strict) == (1 if k > 0 else -1, True)
    rejects(K.sign_of_increasing_difference, above, expr=5 * sp.tanh(s) - 4 * sp.tanh(1), inner=5 * sp.tanh(s),
            c=sp.Integer(1))
    rejects(K.sign_of_increasing_difference, above, expr=sp.Integer(0), inner=0 * sp.tanh(s), c=sp.Integer(1))
    rejects(K.sign_of_increasing_difference, above, expr=s * sp.tanh(s) - s * sp.tanh(1), inner=s * sp.tanh(s),
            c=sp.Integer(1))
    # G(c) as SymPy evaluates it: e/2 - e exp(-(2s - 3)^2)/2 >= 0 (k = -e/2, c = 0; the erf join's kf - F')
    y = -(2 * s - 3) ** 2
    nonpositive = sturm(y, s, 1, 3, want=-1, strict=False)
    th = K.sign_of_increasing_difference(nonpositive, expr=sp.E / 2 - sp.E * sp.exp(y) / 2,
                                         inner=-sp.E * sp.exp(y) / 2, c=sp.Integer(0))
    assert (th.claim.expr, th.claim.want, th.claim.strict) == (sp.srepr(sp.E / 2 - sp.E * sp.exp(y) / 2), 1, False)


def diverges_s():
    """s -> oo: s' - 1/2 = 1/2 >= 0 on [1, oo)."""
    half = K.sign_by_sturm(expr=Q(1, 2), var=s, lo=sp.Integer(1), hi=sp.oo, lo_open=False, hi_open=True,
                           want=1, strict=False)
    return K.diverges_by_growth(half, expr=s, var=s, R=sp.Integer(1), rate="linear", k=Q(1, 2))


def test_limit_rules():
    """tanh(s) -> 1, s/sqrt(s^2 + 1) -> 1 (its tail form 1/sqrt(t^2 + 1) at t = 0), so
    3 tanh(s) s/sqrt(s^2 + 1) -> 3 and its sup over (0, oo) is >= 3."""
    E = s / sp.sqrt(s ** 2 + 1)
    ident = K.identity(lhs=1 / sp.sqrt(t ** 2 + 1), rhs=E.subs(s, 1 / t), var=t, lo=ZERO, hi=sp.oo,
                       lo_open=True, hi_open=True)
    lim_E = K.limit_at_infinity(ident, expr=E, var=s, width=Q(1, 2))
    assert (lim_E.claim.kind, lim_E.claim.expr, lim_E.claim.other) == ("limit_oo", sp.srepr(E), sp.srepr(sp.Integer(1)))
    lim_tanh = K.limit_of_bounded(diverges_s(), expr=sp.tanh(s))
    assert (lim_tanh.claim.expr, lim_tanh.claim.other) == (sp.srepr(sp.tanh(s)), sp.srepr(sp.Integer(1)))
    assert parse(K.limit_of_bounded(diverges_s(), expr=sp.atan(s)).claim.other) == sp.pi / 2
    rejects(K.limit_of_bounded, diverges_s(), expr=sp.sinh(s))               # no finite limit
    rejects(K.limit_of_bounded, diverges_s(), expr=sp.tanh(-s))              # -s -> -oo
    rejects(K.limit_of_bounded, lim_E, expr=sp.tanh(s))                      # premise must diverge
    prod = K.limit_of_product(lim_tanh, lim_E, expr=3 * sp.tanh(s) * E)
    assert parse(prod.claim.other) == 3
    rejects(K.limit_of_product, lim_tanh, lim_E, expr=s * sp.tanh(s) * E)    # the factor s is no constant
    rejects(K.limit_of_product, lim_tanh, expr=sp.tanh(s) * E)               # E has no premise
    # the product is exact once tanh = sinh/cosh and the radical are generalised; sqrt(3) stays a constant
    moved = K.limit_of_product(lim_tanh, lim_E, expr=sp.sqrt(3) * sp.sinh(s) * s / (sp.cosh(s) * sp.sqrt(s ** 2 + 1)))
    assert parse(moved.claim.other) == sp.sqrt(3)
    rejects(K.limit_of_product, lim_tanh, lim_E, expr=sp.sinh(s) * s / sp.sqrt(s ** 2 + 1))   # no cosh
    # red team 16a: u = cosh^2 - sinh^2 is 1, so tanh(s) (u^2 - 1)/((u - 1)(u + 1)) is 0/0 at every s; over Q
    # with cosh, sinh generalised it cancels to tanh(s), and "E -> 1" (then sup E >= 1) had been accepted
    u = sp.cosh(s) ** 2 - sp.sinh(s) ** 2
    rejects(K.limit_of_product, lim_tanh, expr=sp.tanh(s) * (u ** 2 - 1) / ((u - 1) * (u + 1)))
    low = K.sup_lower_from_limit(prod, lo=ZERO, lo_open=True)
    assert (low.claim.kind, low.claim.lo, low.claim.hi, parse(low.claim.other)) == ("sup_lower", sp.srepr(ZERO), "oo", 3)
    rejects(K.sup_lower_from_limit, ident, lo=ZERO, lo_open=True)
    cert = json.loads(json.dumps(to_certificate([low])))
    assert [c.claim for c in check_certificate(cert)] == [low.claim]
    cert["theorems"][-1]["claim"]["other"] = sp.srepr(sp.Integer(4))         # a larger sup claimed
    with pytest.raises(CertificateError):
        check_certificate(cert)


def test_sign_through_increasing():
    y = sturm(x - 1, x, 1, 2, lo_open=True)
    for G in (sp.tanh, sp.atan, sp.asinh, sp.sinh, sp.erf):
        assert K.sign_through_increasing(y, expr=G(x - 1)).claim.want == 1
    assert K.sign_through_increasing(y, expr=sp.exp(x - 1)).claim.want == 1
    rejects(K.sign_through_increasing, y, expr=sp.tanh(x - 2))
    rejects(K.sign_through_increasing, y, expr=sp.cos(x - 1))
    big = sturm(x - 1, x, 2, 3)
    assert K.sign_through_increasing(big, expr=sp.log(x)).claim.want == 1
    below = sturm(x - 1, x, Q(1, 2), Q(2, 3), want=-1)
    rejects(K.sign_through_increasing, below, expr=sp.log(x))                    # needs x > 0
    pos = sturm(x, x, Q(1, 2), Q(2, 3))
    assert K.sign_through_increasing(below, pos, expr=sp.log(x)).claim.want == -1
    rejects(K.sign_through_increasing, below, below, expr=sp.log(x))


def test_join_and_weaken():
    a = sturm(x + 1, x, 0, 1, lo_open=True)
    b = sturm(x + 1, x, 1, 2)
    j = K.join(a, b)
    assert (j.claim.lo, j.claim.hi, j.claim.lo_open, j.claim.hi_open) == ("Integer(0)", "Integer(2)", True, False)
    rejects(K.join, a, sturm(x + 1, x, 2, 3))                                   # a gap (1, 2)
    rejects(K.join, sturm(x + 1, x, 0, 1, hi_open=True), sturm(x + 1, x, 1, 2, lo_open=True))  # 1 uncovered
    rejects(K.join, a, sturm(x + 2, x, 1, 2))
    rejects(K.join, a, sturm(x - 3, x, 1, 2, want=-1))
    w = K.weaken(j, lo=Q(1, 2), hi=sp.Integer(2), lo_open=False, hi_open=True, strict=False)
    assert not w.claim.strict and w.claim.lo == "Rational(1, 2)"
    rejects(K.weaken, j, lo=ZERO, hi=sp.Integer(2), lo_open=False, hi_open=False, strict=True)  # 0 not in I
    rejects(K.weaken, j, lo=Q(1, 2), hi=sp.Integer(3), lo_open=False, hi_open=False, strict=True)
    rejects(K.weaken, w, lo=Q(1, 2), hi=sp.Integer(1), lo_open=False, hi_open=False, strict=True)


def test_join_at_a_zero():
    e = (x - 1) ** 2 * (x + 1)
    left = sturm(e, x, 0, 1, hi_open=True)
    right = sturm(e, x, 1, 2, lo_open=True)
    j = K.join_at_point(left, right)
    assert not j.claim.strict and not j.claim.lo_open and not j.claim.hi_open
    f = (x ** 2 - 1) / (x - 1)                                                   # x + 1, but undefined at 1
    rejects(K.join_at_point, sturm(f, x, 0, 1, hi_open=True), sturm(f, x, 1, 2, lo_open=True))
    # (x - 1) * sqrt(x - 2): SymPy evaluates it to 0 at x = 1, but it is not real there
    g = (x - 1) * sp.sqrt(x - 2)
    assert g.subs(x, 1) == 0
    with pytest.raises(Undefined):
        evaluate(g, x, 1, 1)


def tail_parts(E, Et, R, w=None):
    """sign_on_tail premises for E > 0 with E_t > 0 proved by Taylor at t = 0."""
    tail_t = K.sign_by_taylor(expr=Et, var=t, c=ZERO, side=1, width=1 / R, order=1)
    ident = K.identity(lhs=Et, rhs=E.subs(s, 1 / t), var=t, lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    return tail_t, ident


def test_sign_on_tail():
    E = s / (s ** 2 + 1)
    Et = t / (t ** 2 + 1)
    tail_t, ident = tail_parts(E, Et, sp.Integer(4))
    thm = K.sign_on_tail(tail_t, ident, expr=E, var=s, R=sp.Integer(4))
    assert (thm.claim.lo, thm.claim.hi, thm.claim.lo_open) == ("Integer(4)", "oo", False)
    rejects(K.sign_on_tail, tail_t, ident, expr=E, var=s, R=sp.Integer(2))          # t-range (0, 1/4] only
    rejects(K.sign_on_tail, ident, tail_t, expr=E, var=s, R=sp.Integer(4))
    rejects(K.sign_on_tail, tail_t, ident, expr=2 * E, var=s, R=sp.Integer(4))      # identity is about E
    # E = (s**2 - 25)/(s - 5) has E(1/t) = (1 + 5t)/t where both are defined, E_t > 0 on (0, 1/4],
    # but E is undefined at s = 5: the tail rule must not claim E > 0 on [4, oo)
    E5 = (s ** 2 - 25) / (s - 5)
    Et5 = (1 + 5 * t) / t
    ident5 = K.identity(lhs=Et5, rhs=E5.subs(s, 1 / t), var=t, lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    pos5 = K.sign_of_product(sturm(1 + 5 * t, t, 0, Q(1, 4), lo_open=True), sturm(t, t, 0, Q(1, 4), lo_open=True),
                             expr=Et5)
    rejects(K.sign_on_tail, pos5, ident5, expr=E5, var=s, R=sp.Integer(4))


def test_sign_by_substitution():
    u = sp.Symbol("u", positive=True)
    half = Q(1, 2)
    outer = K.sign_by_taylor(expr=u - sp.sin(u), var=u, c=ZERO, side=1, width=half, order=3)   # (0, 1/2]
    low = sturm(x ** 2, x, 0, half, lo_open=True)                       # u - 0 > 0
    high = sturm(half - x ** 2, x, 0, half, lo_open=True, strict=False)  # 1/2 - u >= 0
    thm = K.sign_by_substitution(outer, low, high, inner=x ** 2)
    assert parse(thm.claim.expr) == x ** 2 - sp.sin(x ** 2) and thm.claim.want == 1 and thm.claim.strict
    rejects(K.sign_by_substitution, outer, low, inner=x ** 2)                          # upper end unbounded
    rejects(K.sign_by_substitution, outer, high, low, inner=x ** 2)                    # order: a, then b
    rejects(K.sign_by_substitution, outer, sturm(x ** 2, x, 0, half, strict=False),     # u = 0 at x = 0
            sturm(half - x ** 2, x, 0, half, strict=False), inner=x ** 2)
    rejects(K.sign_by_substitution, outer, low, high, inner=2 * x ** 2)
    wide = sturm(1 - x ** 2, x, 0, 1, lo_open=True, strict=False)                     # u up to 1 > 1/2
    rejects(K.sign_by_substitution, outer, sturm(x ** 2, x, 0, 1, lo_open=True), wide, inner=x ** 2)


def test_sign_by_monotone():
    E = 1 - 1 / s
    dE = K.sign_of_product(sturm(s, s, 2, sp.oo, hi_open=True), expr=sp.diff(E, s))   # s**-2 > 0
    thm = K.sign_by_monotone(dE, expr=E, var=s, R=sp.Integer(2))
    assert (thm.claim.lo, thm.claim.hi, thm.claim.want, thm.claim.strict) == ("Integer(2)", "oo", 1, True)
    rejects(K.sign_by_monotone, dE, expr=E, var=s, R=sp.Integer(3))                  # premise on [2, oo)
    assert K.sign_by_monotone(dE, expr=E + 1, var=s, R=sp.Integer(2)).claim.want == 1  # same derivative
    rejects(K.sign_by_monotone, dE, expr=E - 1, var=s, R=sp.Integer(2))              # -1/s < 0
    rejects(K.sign_by_monotone, dE, expr=E * 2, var=s, R=sp.Integer(2))              # another derivative
    F = 1 / s - Q(1, 4)                     # F(2) > 0 but F decreases: F(8) < 0
    dF = K.sign_of_product(sturm(s, s, 2, sp.oo, hi_open=True), expr=sp.diff(F, s))
    rejects(K.sign_by_monotone, dF, expr=F, var=s, R=sp.Integer(2))
    G = sp.log(s - 1) + 1                   # log(s - 1) is defined on (1, oo) only: enough on [2, oo)
    dG = K.sign_of_product(sturm(s - 1, s, 2, sp.oo, hi_open=True), expr=sp.diff(G, s))
    assert K.sign_by_monotone(dG, expr=G, var=s, R=sp.Integer(2)).claim.ends() == (2, sp.oo)


def test_sign_by_rewrite():
    L = (s ** 2 + 2 * s + 1) / (s + 1)
    R = sturm(s + 1, s, 0, sp.oo, True, True)
    ident = K.identity(lhs=L, rhs=s + 1, var=s, lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    assert parse(K.sign_by_rewrite(R, ident).claim.expr) == L
    # (s**2 - 1)/(s - 1) = s + 1 where both are defined, but it is undefined at s = 1
    L1 = (s ** 2 - 1) / (s - 1)
    ident1 = K.identity(lhs=L1, rhs=s + 1, var=s, lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    rejects(K.sign_by_rewrite, R, ident1)
    Lx = (x ** 2 - 1) / (x - 1)
    Rx = sturm(x + 1, x, 0, 2)
    identx = K.identity(lhs=Lx, rhs=x + 1, var=x, lo=ZERO, hi=sp.Integer(2), lo_open=False, hi_open=False)
    rejects(K.sign_by_rewrite, Rx, identx, cuts=[0, 1, 2])
    rejects(K.sign_by_rewrite, Rx, identx)
    Lok = (x ** 2 + 2 * x + 1) / (x + 1)
    identok = K.identity(lhs=Lok, rhs=x + 1, var=x, lo=ZERO, hi=sp.Integer(2), lo_open=False, hi_open=False)
    assert K.sign_by_rewrite(Rx, identok, cuts=[0, 1, 2]).claim.want == 1
    rejects(K.sign_by_rewrite, sturm(x + 1, x, 0, 3), identok, cuts=[0, 3])   # identity only on [0, 2]


def test_identity():
    exact = K.identity(lhs=s / (s ** 2 + 1), rhs=1 / (s + 1 / s), var=s, lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    assert "sympy-simplify" not in exact.assumptions and "sympy-polys" in exact.assumptions
    rejects(K.identity, lhs=s / (s ** 2 + 1), rhs=1 / (s + 2 / s), var=s, lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    rejects(K.identity, lhs=s / (s ** 2 + 1), rhs=1 / (s + 1 / s) + Q(1, 10 ** 60), var=s, lo=ZERO, hi=sp.oo,
            lo_open=True, hi_open=True)
    trig = K.identity(lhs=sp.sin(x) ** 2 + sp.cos(x) ** 2, rhs=sp.Integer(1), var=x, lo=-sp.oo, hi=sp.oo,
                      lo_open=True, hi_open=True)
    assert "sympy-simplify" in trig.assumptions
    rejects(K.identity, lhs=sp.sin(x) ** 2 + sp.cos(x) ** 2 + Q(1, 10 ** 60), rhs=sp.Integer(1), var=x,
            lo=-sp.oo, hi=sp.oo, lo_open=True, hi_open=True)


def test_identity_with_roots_of_one_base_of_several_orders():
    """(1 + 1/s^2)^(1/4) = (s^2 + 1)^(1/4) s^(-1/2) for s > 0 (a tail form):
    s^(-1/2) from the first side and s^(-1/2) written as sqrt(s)/s on the
    other are powers of one symbol s^(1/4), so the identity is exact; a
    side off by s^(1/4) is refused."""
    lhs = (1 + 1 / s ** 2) ** Q(1, 4) + sp.sqrt(s)
    rhs = (s ** 2 + 1) ** Q(1, 4) * sp.sqrt(s) / s + s / sp.sqrt(s)
    th = K.identity(lhs=lhs, rhs=rhs, var=s, lo=ZERO, hi=sp.Integer(1), lo_open=True, hi_open=False)
    assert th.assumptions == {"sympy-core", "sympy-polys"}
    rejects(K.identity, lhs=lhs, rhs=rhs + s ** Q(1, 4) / 10 ** 40, var=s, lo=ZERO, hi=sp.Integer(1),
            lo_open=True, hi_open=False)


def test_cross_check_sees_1e_minus_60():
    _cross_check(sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1, x, sp.Integer(0), sp.Integer(1))
    with pytest.raises(KernelError):
        _cross_check(sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1 + sp.exp(x) / 10 ** 60, x, sp.Integer(0), sp.Integer(1))
    with pytest.raises(KernelError):                                      # nowhere evaluable
        _cross_check(sp.log(x) - sp.log(x) + sp.sqrt(x), x, sp.Integer(-2), sp.Integer(-1))


def test_value_sign():
    assert K.value_sign(value=sp.sqrt(2) - 1).claim.want == 1
    assert K.value_sign(value=sp.pi - Q(355, 113)).claim.want == -1
    assert K.value_sign(value=sp.sqrt(2) ** 2 - 2).claim.want == 0
    rejects(K.value_sign, value=x)
    rejects(K.value_sign, value=sp.Float(0.1))
    rejects(K.value_sign, value=sp.log(-1))
    # named constants, each against a rational 10^-30 away (mpmath: EulerGamma = 0.57721566490153286060651209008240...,
    # Catalan = 0.91596559417721901505460351493238..., GoldenRatio = 1.61803398874989484820458683436563...)
    for c, near in ((sp.EulerGamma, "0.577215664901532860606512090083"), (sp.Catalan, "0.915965594177219015054603514933"),
                    (sp.GoldenRatio, "1.618033988749894848204586834366")):
        assert K.value_sign(value=c - sp.Rational(near)).claim.want == -1, c
        assert K.value_sign(value=c - sp.Rational(near) + sp.Rational(1, 10**30)).claim.want == 1, c
        assert parse(sp.srepr(2 * c)) == 2 * c
    # a difference of about 10^-300 (log(1 + t) = t - t^2/2 + ...), beyond 256 bits, within 2,048 (red team 18b's
    # elliptic designs); 10^-700 is beyond both, within 32,768 (a design's f(0, 0) = -10^-400 or -exp(-10^4),
    # whose P3 witness is near the origin); exp(-30000)/2 = 2^-43281.5 is beyond all three, its sign undecided
    tiny = sp.log(2 + Q(1, 10 ** 300)) - sp.log(2)
    assert K.value_sign(value=tiny).claim.want == 1 and K.value_sign(value=-tiny).claim.want == -1
    assert K.value_sign(value=sp.log(2) - sp.log(2 + Q(1, 10 ** 700))).claim.want == -1
    rejects(K.value_sign, value=sp.log(2 + sp.exp(-30000)) - sp.log(2))


def test_a_sum_of_logarithms_of_rationals_is_exactly_zero():
    """log(4)/2 - log(2) is not SymPy's literal 0; read through the primes
    (log 4 = 2 log 2, log(9/4) = 2 log 3 - 2 log 2) it is 0 exactly.  Moved
    by 10^-90 it is signed (at 2,048 bits: 256 do not separate it); by
    exp(-30000), beyond 32,768 bits too, it is neither 0 nor signed.  The Taylor
    rule takes such a value as the zero it needs at c."""
    assert K.value_sign(value=sp.log(4) / 2 - sp.log(2)).claim.want == 0
    assert K.value_sign(value=sp.log(Q(9, 4)) - 2 * sp.log(3) + 2 * sp.log(2)).claim.want == 0
    assert K.value_sign(value=sp.log(6) - sp.log(2) - sp.log(3) + Q(1, 10 ** 9)).claim.want == 1
    assert K.value_sign(value=sp.log(4) / 2 - sp.log(2) - Q(1, 10 ** 90)).claim.want == -1
    rejects(K.value_sign, value=sp.log(4) / 2 - sp.log(2) + sp.exp(-30000))
    rejects(K.value_sign, value=sp.log(4) / 3 - sp.log(2) + sp.log(2) / 3 + sp.exp(-30000))
    F = sp.log(4 + x ** 2) / 2 - sp.log(2)             # F(0) = F'(0) = 0, F''(0) = 1/4
    assert K.sign_by_taylor(expr=F, var=x, c=ZERO, side=1, width=Q(1, 2), order=2).claim.want == 1
    rejects(K.sign_by_taylor, expr=F + Q(1, 10 ** 90), var=x, c=ZERO, side=1, width=Q(1, 2), order=2)


def test_zero_at_a_radical_point_is_exact():
    """1/2 - F' for F' = 2x(x^2 - 1)/(x^2 + 1)^2 is E = (x^2 - 2x - 1)^2/(2(x^2 + 1)^2):
    0 at m = 1 + sqrt(2), where SymPy's evaluation does not give the literal 0;
    polynomial arithmetic in sqrt(2) (sqrt(2)^2 = 2) does (Arb alone cannot
    show E(m) > 0 there).  A point off by 10^-30 is joined by E's sign there."""
    E = (s ** 2 - 2 * s - 1) ** 2 / (2 * (s ** 2 + 1) ** 2)
    dF = 2 * s * (s ** 2 - 1) / (s ** 2 + 1) ** 2
    m = 1 + sp.sqrt(2)

    def halves(m):
        return [K.weaken(K.sign_by_cover(expr=E, var=s, cuts=cuts, want=1, strict=False), lo=cuts[0], hi=cuts[1],
                         lo_open=cuts[0] == m, hi_open=cuts[1] == m, strict=False)
                for cuts in ([ZERO, m], [m, sp.Integer(4)])]
    assert E.subs(s, m) != 0 and dF.subs(s, m) != Q(1, 2)
    j = K.join_at_point(*halves(m))
    assert (j.claim.lo, j.claim.hi, j.claim.strict) == ("Integer(0)", "Integer(4)", False)
    off = K.join_at_point(*halves(m + Q(1, 10 ** 30)))      # E there is about 10^-60 > 0: joined by its sign
    assert not off.claim.strict and E.subs(s, m + Q(1, 10 ** 30)) > 0
    low = K.sup_lower_by_point(expr=dF, var=s, point=m, bound=Q(1, 2), lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    assert low.claim.other == "Rational(1, 2)"
    rejects(K.sup_lower_by_point, expr=dF, var=s, point=m, bound=Q(1, 2) + Q(1, 10 ** 30),
            lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)


def test_sup_rules():
    E = s / (s ** 2 + 1)
    cuts = [ZERO] + [Q(k, 16) for k in range(1, 65)]
    up = K.sup_upper_by_sign(K.sign_by_cover(expr=Q(3, 5) - E, var=s, cuts=cuts, want=1), expr=E, bound=Q(3, 5))
    assert up.claim.kind == "sup_upper" and up.claim.other == "Rational(3, 5)"
    rejects(K.sign_by_cover, expr=Q(49, 100) - E, var=s, cuts=cuts, want=1)   # E(1) = 1/2
    low = K.sup_lower_by_point(expr=E, var=s, point=sp.Integer(1), bound=Q(1, 2), lo=ZERO, hi=sp.oo,
                               lo_open=True, hi_open=True)
    assert low.claim.kind == "sup_lower"
    rejects(K.sup_lower_by_point, expr=E, var=s, point=sp.Integer(1), bound=Q(1, 2) + Q(1, 10 ** 30),
            lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    rejects(K.sup_lower_by_point, expr=E, var=s, point=sp.Integer(5), bound=ZERO,
            lo=ZERO, hi=sp.Integer(4), lo_open=True, hi_open=False)
    # sup (2x - x**2) <= 1 from 1 - (2x - x**2) = (x - 1)**2 >= 0
    g = 2 * x - x ** 2
    sq = sturm(1 - g, x, -sp.oo, sp.oo, True, True, strict=False)
    assert K.sup_upper_by_sign(sq, expr=g, bound=sp.Integer(1)).claim.other == "Integer(1)"
    rejects(K.sup_upper_by_sign, sq, expr=g, bound=sp.Integer(2))


# ------------------------------------------------------------------ the wiring demo

def prove_dF_positive():
    """F(s) = log(1 + s**2)/2: F'(s) > 0 on (0, oo) entirely through kernel
    rules, as `univariate.prove_sign` would: Taylor at 0, a cover, s = 1/t."""
    E = sp.diff(sp.log(1 + s ** 2) / 2, s)
    near = K.sign_by_taylor(expr=E, var=s, c=ZERO, side=1, width=Q(1, 4), order=1)
    mid = K.sign_by_cover(expr=E, var=s, cuts=[Q(1, 4), 1, 2, 4], want=1)
    tail_t, ident = tail_parts(E, t / (t ** 2 + 1), sp.Integer(4))
    tail = K.sign_on_tail(tail_t, ident, expr=E, var=s, R=sp.Integer(4))
    return K.join(K.join(near, mid), tail)


def prove_kf_half():
    """kf = sup F' = 1/2 exactly (as `kf.certify_sup` would): 1/2 - F' >= 0
    on (0, oo) with a touching zero at s = 1, and F'(1) = 1/2."""
    E = sp.diff(sp.log(1 + s ** 2) / 2, s)
    D = Q(1, 2) - E
    one = sp.Integer(1)
    head = K.weaken(K.sign_by_cover(expr=D, var=s, cuts=[ZERO] + [Q(k, 32) for k in range(1, 25)], want=1),
                    lo=ZERO, hi=Q(3, 4), lo_open=True, hi_open=False, strict=True)
    left = K.sign_by_taylor(expr=D, var=s, c=one, side=-1, width=Q(1, 4), order=2,
                            cuts=[Q(3, 4) + Q(k, 32) for k in range(9)])
    right = K.sign_by_taylor(expr=D, var=s, c=one, side=1, width=Q(1, 4), order=2,
                             cuts=[one + Q(k, 32) for k in range(9)])
    mid = K.sign_by_cover(expr=D, var=s, cuts=[Q(5, 4) + Q(k, 64) for k in range(0, 177)], want=1)
    Dt = Q(1, 2) - t / (t ** 2 + 1)
    tail_t = K.weaken(K.sign_by_cover(expr=Dt, var=t, cuts=[ZERO, Q(1, 8), Q(1, 4)], want=1),
                      lo=ZERO, hi=Q(1, 4), lo_open=True, hi_open=False, strict=True)
    ident = K.identity(lhs=Dt, rhs=D.subs(s, 1 / t), var=t, lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    tail = K.sign_on_tail(tail_t, ident, expr=D, var=s, R=sp.Integer(4))
    whole = K.join(K.join(K.join(head, K.join_at_point(left, right)), mid), tail)
    upper = K.sup_upper_by_sign(whole, expr=E, bound=Q(1, 2))
    lower = K.sup_lower_by_point(expr=E, var=s, point=one, bound=Q(1, 2), lo=ZERO, hi=sp.oo,
                                 lo_open=True, hi_open=True)
    return upper, lower


def test_demo_dF_positive_on_0_oo():
    thm = prove_dF_positive()
    c = thm.claim
    assert (c.kind, c.lo, c.hi, c.lo_open, c.hi_open, c.want, c.strict) == ("sign", "Integer(0)", "oo", True, True, 1, True)
    assert parse(c.expr) == s / (s ** 2 + 1)
    assert thm.assumptions == {"arb", "sympy-core", "sympy-diff", "sympy-polys"}


def test_demo_kf_is_one_half():
    upper, lower = prove_kf_half()
    assert upper.claim.other == lower.claim.other == "Rational(1, 2)"
    assert (upper.claim.lo, upper.claim.hi) == ("Integer(0)", "oo")
    back = check_certificate(json.dumps(to_certificate([upper, lower])))
    assert [b.claim for b in back] == [upper.claim, lower.claim]


def prove_kf_design2():
    """Design 2, F(s) = sqrt(1 + s**2) - 1: kf = sup |F'| = 1, approached as
    s -> oo, not attained: |F'| <= 1 on (0, oo) and sup F' >= lim F' = 1."""
    E = sp.diff(sp.sqrt(1 + s ** 2) - 1, s)                 # s/sqrt(s**2 + 1)
    one, two, half = sp.Integer(1), sp.Integer(2), Q(1, 2)
    D = 1 - E
    head = K.weaken(K.sign_by_cover(expr=D, var=s, cuts=[Q(k, 16) for k in range(33)], want=1),
                    lo=ZERO, hi=two, lo_open=True, hi_open=False, strict=True)
    Dt = 1 - 1 / sp.sqrt(t ** 2 + 1)
    tail_t = K.sign_by_taylor(expr=Dt, var=t, c=ZERO, side=1, width=half, order=2,
                              cuts=[Q(k, 16) for k in range(9)])
    ident = K.identity(lhs=Dt, rhs=D.subs(s, 1 / t), var=t, lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    below_one = K.join(head, K.sign_on_tail(tail_t, ident, expr=D, var=s, R=two))
    up = K.sup_upper_by_sign(below_one, expr=E, bound=one)
    pos = K.sign_of_product(sturm(s, s, 0, sp.oo, True, True), sturm(s ** 2 + 1, s, 0, sp.oo, True, True), expr=E)
    down = K.sup_upper_by_sign(K.sign_of_sum(pos, expr=1 + E, want=1), expr=-E, bound=one)
    kf_upper = K.sup_upper_of_abs(up, down)
    Et = 1 / sp.sqrt(t ** 2 + 1)
    ident_e = K.identity(lhs=Et, rhs=E.subs(s, 1 / t), var=t, lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    kf_lower = K.sup_lower_by_limit(ident_e, expr=E, var=s, width=half, bound=one, lo=ZERO, lo_open=True)
    return kf_upper, kf_lower


def test_demo_kf_design2_approached_at_infinity():
    upper, lower = prove_kf_design2()
    assert parse(upper.claim.expr) == sp.Abs(s / sp.sqrt(s ** 2 + 1)) and upper.claim.other == "Integer(1)"
    assert lower.claim.kind == "sup_lower" and lower.claim.other == "Integer(1)"
    # the tail identity sqrt(1 + 1/t^2) = sqrt(t^2 + 1)/t (t > 0) is exact: t^-2 leaves the radical
    assert "sympy-simplify" not in upper.assumptions and "sympy-polys" in upper.assumptions
    back = check_certificate(json.dumps(to_certificate([upper, lower])))
    assert [b.claim for b in back] == [upper.claim, lower.claim]


def test_sup_lower_by_limit():
    E = s / sp.sqrt(s ** 2 + 1)
    Et = 1 / sp.sqrt(t ** 2 + 1)
    ident = K.identity(lhs=Et, rhs=E.subs(s, 1 / t), var=t, lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    half = Q(1, 2)
    rejects(K.sup_lower_by_limit, ident, expr=E, var=s, width=half, bound=Q(101, 100), lo=ZERO, lo_open=True)
    rejects(K.sup_lower_by_limit, ident, expr=2 * E, var=s, width=half, bound=sp.Integer(2), lo=ZERO, lo_open=True)
    # E_t = 1/t is not defined at t = 0 (1/t -> oo has no finite limit)
    ident2 = K.identity(lhs=1 / t, rhs=s.subs(s, 1 / t), var=t, lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    rejects(K.sup_lower_by_limit, ident2, expr=s, var=s, width=half, bound=sp.Integer(5), lo=ZERO, lo_open=True)
    low = K.sup_lower_by_limit(ident, expr=E, var=s, width=half, bound=sp.Integer(1), lo=ZERO, lo_open=True)
    assert parse(low.claim.other) == 1 and parse(low.claim.expr) == E
    up = K.sup_upper_by_sign(K.sign_by_cover(expr=2 - E, var=s, cuts=[0, 1, 2], want=1), expr=E, bound=sp.Integer(2))
    rejects(K.sup_upper_of_abs, up, up)                                   # second premise must be about -E


# ------------------------------------------------------------------ certificates

def demo_certificate():
    return json.loads(json.dumps(to_certificate([prove_dF_positive()])))


def node(cert, rule, k=0):
    return [n for n in cert["theorems"] if n["rule"] == rule][k]


def test_certificate_round_trip():
    thm = prove_dF_positive()
    text = json.dumps(to_certificate([thm]), indent=1)
    back = check_certificate(text)
    assert [b.claim for b in back] == [thm.claim]
    cert = json.loads(text)
    assert cert["version"] == 3 and cert["assumptions"] == sorted(thm.assumptions)
    assert {n["rule"] for n in cert["theorems"]} == {"sign_by_taylor", "sign_by_cover", "identity",
                                                     "sign_on_tail", "join"}


def test_schema_matches_the_kernel():
    schema = json.loads(SCHEMA.read_text())
    assert set(schema["$defs"]["theorem"]["properties"]["rule"]["enum"]) == set(RULES)
    assert set(schema["$defs"]["claim"]["required"]) == set(K.Claim.__dataclass_fields__)
    assert schema["properties"]["version"]["const"] == VERSION


def test_certificate_validates_against_the_schema():
    import jsonschema
    jsonschema.validate(demo_certificate(), json.loads(SCHEMA.read_text()))


def tampered(edit):
    cert = demo_certificate()
    edit(cert)
    with pytest.raises(CertificateError) as err:
        check_certificate(cert)
    return str(err.value)


def test_tampered_cut_point_onto_a_zero():
    # the cover [1/4, 1, 2, 4] of s/(s**2 + 1) > 0 with its first cut moved
    # onto the zero at s = 0: the box [0, 1] no longer has a strict sign
    def edit(cert):
        n = node(cert, "sign_by_cover")
        n["data"]["cuts"][0] = {"$": "Integer(0)"}
        n["claim"]["lo"] = "Integer(0)"
    msg = tampered(edit)
    assert "does not check" in msg


def test_tampered_dyadic_cut_point():
    c0 = Q(3, 8)
    thm = K.sign_by_cover(expr=x - c0, var=x, cuts=[c0 + Q(1, 2 ** 60), 1], want=1)
    cert = json.loads(json.dumps(to_certificate([thm])))
    check_certificate(cert)
    cert["theorems"][0]["data"]["cuts"][0] = {"$": "Rational(3, 8)"}
    cert["theorems"][0]["claim"]["lo"] = "Rational(3, 8)"
    with pytest.raises(CertificateError, match="sign not shown"):
        check_certificate(cert)


def test_tampered_cover_with_a_gap():
    def edit(cert):
        n = node(cert, "sign_by_cover")
        n["data"]["cuts"][0] = {"$": "Rational(3, 8)"}
        n["claim"]["lo"] = "Rational(3, 8)"
    assert "not adjacent" in tampered(edit)


def test_tampered_wrong_sign_claimed():
    def edit(cert):
        cert["theorems"][-1]["claim"]["want"] = -1
    assert "claims" in tampered(edit)

    def edit_cover(cert):
        n = node(cert, "sign_by_cover")
        n["data"]["want"] = -1
        n["claim"]["want"] = -1
    assert "sign not shown" in tampered(edit_cover)


def test_tampered_identity_off_by_1e_60():
    def edit(cert):
        n = node(cert, "identity")
        rhs = parse(n["data"]["rhs"]["$"]) + Q(1, 10 ** 60)
        n["data"]["rhs"] = {"$": sp.srepr(rhs)}
        n["claim"]["other"] = sp.srepr(rhs)
    assert "differ" in tampered(edit)


def test_tampered_taylor_order():
    def edit(cert):
        node(cert, "sign_by_taylor")["data"]["order"] = 2
    assert "not exactly 0" in tampered(edit)


def test_tampered_version_and_shape():
    def edit(cert):
        cert["version"] = 0
    assert "version 0 is not supported" in tampered(edit)
    assert "version 1 is not supported" in tampered(lambda c: c.update(version=1))
    assert "format" in tampered(lambda c: c.update(format="something else"))
    assert "unknown rule" in tampered(lambda c: c["theorems"][0].update(rule="trust_me"))
    assert "earlier" in tampered(lambda c: c["theorems"][0].update(premises=[3]))
    assert "rests on" in tampered(lambda c: c["assumptions"].remove("sympy-diff"))
    with pytest.raises(CertificateError):
        check_certificate("{not json")


def test_tampered_claim_only():
    def edit(cert):
        node(cert, "sign_by_cover")["claim"]["hi"] = "Integer(5)"
    assert "claims" in tampered(edit)


def test_certificate_does_not_execute_code():
    cert = demo_certificate()
    node(cert, "sign_by_cover")["data"]["expr"] = {"$": "__import__('os').system('false')"}
    with pytest.raises(CertificateError, match="not allowed"):
        check_certificate(cert)


def test_strings_are_never_sympified():
    rejects(K.sign_by_cover, expr="x**2 + 1", var=x, cuts=[0, 1], want=1)
    rejects(K.sign_by_cover, expr=x ** 2 + 1, var=x, cuts=[0, "__import__('os').getpid()"], want=1)
    rejects(K.sign_by_cover, expr=x ** 2 + 1, var=x, cuts=[0, 1], want=1, strict="yes")
    cert = demo_certificate()
    node(cert, "sign_by_cover")["data"]["cuts"][0] = "__import__('os').getpid()"
    with pytest.raises(CertificateError, match="expected a SymPy object"):
        check_certificate(cert)


def test_certificate_is_not_mutated_by_the_rules():
    cert = demo_certificate()
    before = copy.deepcopy(cert)
    check_certificate(cert)
    assert cert == before


def test_malformed_steps_are_rejected_not_crashes():
    for edit in (lambda n: n["data"].update(expr={"$": "Add(" * 400 + "Integer(1)" + ")" * 400}),
                 lambda n: n["data"].update(expr={"$": "Symbol(1)"}),
                 lambda n: n["data"].update(expr={"no dollar": 1}),
                 lambda n: n["data"].update(cuts=None),
                 lambda n: n["data"].pop("var")):
        cert = demo_certificate()
        edit(node(cert, "sign_by_cover"))
        with pytest.raises(CertificateError):
            check_certificate(cert)


def test_identity_plane():
    """f = log(1 + x^2 + y^2) equals F(sqrt(x^2 + y^2)) with F(s) = log(1 + s^2)
    (literally, after SymPy's automatic sqrt(u)^2 = u); a rational identity is
    checked by cancel; a false one, or one off by 1e-60, is rejected."""
    x, y = sp.symbols("x y", real=True)
    r = sp.sqrt(x ** 2 + y ** 2)
    t = K.identity_plane(lhs=sp.log(1 + x ** 2 + y ** 2), rhs=sp.log(1 + r ** 2), x=x, y=y)
    assert t.claim.kind == "identity_plane" and t.assumptions == {"sympy-core"}
    t = K.identity_plane(lhs=(x ** 2 - y ** 2) / (x - y), rhs=x + y, x=x, y=y)
    assert "sympy-polys" in t.assumptions
    t = K.identity_plane(lhs=sp.sqrt(4 * x ** 2 + 4 * y ** 2), rhs=2 * r, x=x, y=y)
    assert "sympy-simplify" in t.assumptions
    rejects(K.identity_plane, lhs=x ** 2 + y, rhs=x ** 2 + y ** 2, x=x, y=y)
    rejects(K.identity_plane, lhs=sp.exp(x + y), rhs=sp.exp(x) * sp.exp(y) + sp.Rational(1, 10 ** 60), x=x, y=y)
    rejects(K.identity_plane, lhs=x, rhs=x, x=x, y=sp.Symbol("y", positive=True))


def log_rate(g, s):
    """g = (s^2 - 1)/(s^2 + 1) >= 0 on [1, oo) (Sturm on both factors, then
    the identity): s F' - 1 for F = log(1 + s^2) + c."""
    return K.sign_by_rewrite(
        K.sign_of_product(
            K.sign_by_sturm(expr=s ** 2 - 1, var=s, lo=sp.Integer(1), hi=sp.oo, lo_open=False, hi_open=True,
                            want=1, strict=False),
            K.sign_by_sturm(expr=s ** 2 + 1, var=s, lo=sp.Integer(1), hi=sp.oo, lo_open=False, hi_open=True,
                            want=1, strict=True),
            expr=(s ** 2 - 1) / (s ** 2 + 1)),
        K.identity(lhs=g, rhs=(s ** 2 - 1) / (s ** 2 + 1), var=s, lo=sp.Integer(1), hi=sp.oo,
                   lo_open=False, hi_open=True))


def test_continuous_at_end_and_diverges_by_growth():
    """s/(1 + s^2) is continuous on [0, 1/2] with value 0 at 0; 1/s is not
    defined at 0.  log(1 + s^2):
    s F' = 2 s^2/(1 + s^2) >= 1 on [1, oo) (Sturm: s^2 - 1 >= 0 there), so it
    diverges at log rate; F' >= 1 is false there, so the linear rate is refused."""
    s = sp.Symbol("s", nonnegative=True)
    t = K.continuous_at_end(expr=s / (1 + s ** 2), var=s, c=ZERO, width=Q(1, 2))
    assert (t.claim.kind, t.claim.other) == ("limit", sp.srepr(ZERO))
    rejects(K.continuous_at_end, expr=1 / s, var=s, c=ZERO, width=Q(1, 2))
    F = sp.log(1 + s ** 2)
    g = s * sp.diff(F, s) - 1
    lower = log_rate(g, s)
    d = K.diverges_by_growth(lower, expr=F, var=s, R=sp.Integer(1), rate="log", k=sp.Integer(1))
    assert (d.claim.kind, d.claim.lo, d.claim.hi) == ("diverges", sp.srepr(sp.Integer(1)), "oo")
    rejects(K.diverges_by_growth, lower, expr=F, var=s, R=sp.Integer(1), rate="linear", k=sp.Integer(1))
    rejects(K.diverges_by_growth, lower, expr=F, var=s, R=sp.Integer(1), rate="log", k=sp.Integer(2))


def test_diverges_by_comparison():
    """s - sin(s) >= s - 1 -> oo: the gap 1 - sin(s) >= 0 (`sign_below_sup`,
    weak: sin attains 1); s - 1 diverges at the linear rate from s = 1.  The
    claim starts at the later of the two starts (here 2)."""
    E, G = s - sp.sin(s), s - 1
    gap = K.sign_below_sup(sturm(s, s, 2, sp.oo, hi_open=True), expr=E - G, bounded=sp.sin(s))
    assert gap.claim.expr == sp.srepr(1 - sp.sin(s)) and not gap.claim.strict
    div = K.diverges_by_growth(
        K.sign_by_sturm(expr=Q(1, 2), var=s, lo=sp.Integer(1), hi=sp.oo, lo_open=False, hi_open=True, want=1,
                        strict=False), expr=G, var=s, R=sp.Integer(1), rate="linear", k=Q(1, 2))
    d = K.diverges_by_comparison(gap, div, expr=E)
    assert d.claim == Claim("diverges", sp.srepr(E), sp.srepr(s), sp.srepr(sp.Integer(2)), "oo", False, True)
    rejects(K.diverges_by_comparison, gap, div, expr=s - 2 * sp.sin(s))       # the gap is about another E
    rejects(K.diverges_by_comparison, gap, gap, expr=E)                       # no divergence premise
    rejects(K.diverges_by_comparison, K.sign_below_sup(sturm(s, s, 2, 3), expr=E - G, bounded=sp.sin(s)), div,
            expr=E)                                                           # E >= G only up to 3
    # the gap from 0 on, the divergence from 1: the claim starts at 1
    early = K.sign_below_sup(sturm(s, s, 0, sp.oo, lo_open=True, hi_open=True), expr=E - G, bounded=sp.sin(s))
    assert K.diverges_by_comparison(early, div, expr=E).claim.lo == sp.srepr(sp.Integer(1))


def test_diverges_through_increasing():
    """log(1 + log(1 + s^2)) -> oo: Y = 1 + log(1 + s^2) diverges at the log
    rate (s Y' = 2 s^2/(1 + s^2) >= 1 on [1, oo), Sturm on s^2 - 1 after the
    rewrite), and log is increasing and unbounded.  Not for a bounded G
    (tanh, atan), a power with p <= 0, or a premise about another Y."""
    Y = 1 + sp.log(1 + s ** 2)
    g = s * sp.diff(Y, s) - 1
    lower = log_rate(g, s)
    div = K.diverges_by_growth(lower, expr=Y, var=s, R=sp.Integer(1), rate="log", k=sp.Integer(1))
    for E in (sp.log(Y), sp.sqrt(Y), Y ** Q(3, 2), sp.asinh(Y), sp.sinh(Y), 1 + sp.log(Y), sp.sinh(Y) - sp.pi,
              2 * sp.log(Y), Q(1, 10 ** 400) * sp.sinh(Y) - 5, (sp.pi - 3) * sp.sqrt(Y)):
        d = K.diverges_through_increasing(div, expr=E)
        assert d.claim == Claim("diverges", sp.srepr(E), sp.srepr(s), sp.srepr(sp.Integer(1)), "oo", False, True)
    # a + m G(Y) only for exact constants a and m > 0 and G itself increasing
    for E in (sp.tanh(Y), sp.atan(Y), 1 / Y, Y ** Q(-1, 2), sp.log(Y + 1), sp.log(s + 1), 1 - sp.log(Y),
              sp.Float(1.5) + sp.log(Y), sp.tanh(s) + sp.log(Y), -2 * sp.log(Y), (3 - sp.pi) * sp.sqrt(Y),
              sp.Float(2) * sp.log(Y), s * sp.log(Y), sp.tanh(s) * sp.log(Y)):
        rejects(K.diverges_through_increasing, div, expr=E)
    rejects(K.diverges_through_increasing, lower, expr=sp.log(Y))            # not a divergence


def test_continuous_on_positive():
    """log(1 + s^2), s/sqrt(1 + s^2) and sqrt(s) are defined (so continuous) for
    every s > 0; 1/(s - 1) is not (s = 1), log(s - 1) is not (s <= 1)."""
    s = sp.Symbol("s", nonnegative=True)
    for e in (sp.log(1 + s ** 2), s / sp.sqrt(1 + s ** 2), sp.sqrt(s)):
        t = K.continuous_on_positive(expr=e, var=s)
        assert (t.claim.kind, t.claim.lo, t.claim.hi, t.claim.lo_open) == ("continuous", sp.srepr(ZERO), "oo", True)
    for e in (1 / (s - 1), sp.log(s - 1)):
        rejects(K.continuous_on_positive, expr=e, var=s)


def test_a_claim_prints_what_a_checker_reads_back_not_the_form_it_was_built_in():
    """2 (s - 7/3) built without distributing reads back (srepr, then parse) as
    2 s - 14/3; the claim must name that, however the prover's objects looked,
    or a checker in a fresh process prints another text and rejects the step
    (found on f = (e1 cos 1 + e2 sin 1)^2 + (e1 sin 1 - e2 cos 1)^2)."""
    built = sp.Mul(2, s - sp.Rational(7, 3), evaluate=False)
    t = K.sign_by_cover(expr=built, var=s, cuts=[3, 4], want=1)
    assert t.claim.expr == sp.srepr(2 * s - sp.Rational(14, 3)) != sp.srepr(built)
    again = check_certificate(json.loads(json.dumps(to_certificate([t]))))
    assert again[0].claim == t.claim


# continuous_on_plane: E defined at every point of the plane (P5-P8 of f analytic there;
# the links are in tests/test_plane_smoothness.py)
px, py = sp.symbols("e1 e2", real=True)
prho = px ** 2 + py ** 2


@pytest.mark.parametrize("expr", [px ** 2 + sp.log(1 + py ** 2), sp.log(1 + prho + px ** 2 * py ** 2),
                                  sp.atan(px * py) + sp.exp(-px ** 2), px / (1 + px ** 2), sp.log(sp.E - 1 + prho),
                                  sp.sqrt(2 + px ** 2) * sp.cosh(py)])
def test_defined_on_the_plane(expr):
    t = K.continuous_on_plane(expr=expr, x=px, y=py)
    assert (t.claim.kind, t.claim.var, t.claim.lo, t.claim.hi, t.claim.lo_open, t.claim.hi_open) == (
        "continuous", sp.srepr(sp.Tuple(px, py)), "-oo", "oo", True, True)
    assert t.claim.expr == sp.srepr(expr) and t.assumptions == {"sympy-core"}


@pytest.mark.parametrize("expr", [sp.log(prho), 1 / px, sp.sqrt(1 + px), sp.log(px ** 2 - sp.Rational(1, 2)),
                                  sp.sqrt(prho), prho ** sp.Rational(3, 2), sp.log(1 + sp.sin(px)),
                                  sp.log(sp.E - 3 + prho), 1 / (sp.E - 3 + prho ** 2)])
def test_not_defined_everywhere_is_refused(expr):
    # log rho, 1/e1 at the origin; sqrt(1 + e1) for e1 < -1; log(e1^2 - 1/2) near 0;
    # sqrt(rho) and rho^(3/2) are defined but their base is not > 0 (not shown analytic);
    # log(1 + sin e1) at e1 = -pi/2; e - 3 + rho (its constant terms taken together) is < 0 near 0
    with pytest.raises(KernelError):
        K.continuous_on_plane(expr=expr, x=px, y=py)


_PW = sp.Piecewise


@pytest.mark.parametrize("expr", [
    sp.sqrt(prho), prho ** sp.Rational(3, 4), prho ** sp.pi, 2 ** prho - 1, sp.log(1 + sp.sqrt(prho)),
    _PW((0, sp.Eq(prho, 0)), (sp.log(prho), True)),                       # the origin given its own value
    _PW((0, sp.Eq(px, 0) & sp.Eq(py, 0)), (prho * sp.log(prho), True)),   # the same, as two equations
    _PW((prho, prho < 4), (sp.log(sp.sqrt(prho) / 2) + 4, True)),         # log read where rho >= 4
    _PW((1, sp.Not(prho >= 1)), (1 / sp.sqrt(prho), True)),
    _PW((1, px <= 2), (sp.log(px - 2), True)),                           # e1 > 2 there
    _PW((prho, prho < 1), (sp.sqrt(prho - 1), True)),                     # rho - 1 >= 0 there
    _PW((prho, prho < 3), ((prho - 3) / (prho - 2), True)),              # rho - 2 >= 1 > 0 there
    _PW((prho, (prho < 1) | (prho < 2)), (1 / (2 * prho - 3), True)),    # 2 rho - 3 >= 1 there
    sp.log(1 + sp.log(sp.cosh(prho))), sp.expand((prho - 4) ** 2) ** sp.Rational(3, 2),   # log cosh >= 0; (rho - 4)^2
    sp.log(2 - sp.exp(-prho)), 1 / (3 - 2 * sp.tanh(prho)), 1 / (2 - sp.atan(prho)),   # terms bounded below
    sp.log(2 + sp.sin(px)), 1 / (sp.cosh(px) - sp.Rational(1, 2)), sp.log(1 + sp.tanh(px)),   # sin >= -1, cosh >= 1,
    1 / (1 + sp.erf(px * py)), sp.log(sp.log(prho + 2)), sp.log(1 + sp.atan(prho)),         # tanh, erf > -1; log 2
    sp.log(1 + prho ** 3 * sp.exp(px)), sp.log(1 + (sp.Abs(px) + py ** 2) ** 3),   # an odd power of a base >= 0
    # facts: a negated Not(And), a negated And of equations off the origin, > and >=, the larger of two bounds
    _PW((1, sp.Not(sp.And(prho < 4, px < 100))), (sp.log(4 - prho), True)),
    _PW((0, sp.Eq(px, 1) & sp.Eq(py, 2)), (1 / ((px - 1) ** 2 + (py - 2) ** 2), True)),
    _PW((sp.log(prho - 1), prho > 1), (0, True)), _PW((sp.sqrt(prho - 1), prho >= 1), (0, True)),
    _PW((1, prho < 4), (2, prho < 1), (sp.log(prho - 3), True)), _PW((sp.log(prho), prho > 0), (0, True)),
])
def test_defined_on_the_plane_where_each_branch_is_taken(expr):
    t = K.defined_on_plane(expr=expr, x=px, y=py)
    assert (t.claim.kind, t.claim.var, t.claim.lo, t.claim.hi, t.claim.lo_open, t.claim.hi_open, t.claim.expr) == (
        "defined", sp.srepr(sp.Tuple(px, py)), "-oo", "oo", True, True, sp.srepr(expr))


@pytest.mark.parametrize("expr", [
    py / (py - 2) - 2 / (py - 2), (sp.sqrt(4 - py) + 1) ** 2 - 2 * sp.sqrt(4 - py) + py,    # the red team's
    (px ** 2 + (py - 2) ** 2) / (px ** 2 + py ** 2 - 4 * py + 4), sp.log(prho), prho ** -sp.pi,
    _PW((1, prho < 4), (sp.log(prho - 4), True)),        # rho = 4 takes the second branch: log 0
    _PW((1, prho < 3), (1 / (2 * prho - 6), True)),      # ... and 1/0 at rho = 3
    sp.expand((prho - 4) * (prho - 5)) ** sp.Rational(1, 2),            # < 0 for 4 < rho < 5
    sp.log(1 - sp.exp(-prho)), sp.log(2 - 2 * sp.cos(prho)),            # log 0 at the origin
    1 / (1 - sp.tanh(prho)),     # defined (tanh < 1), but the bound -1 of -tanh gives only >= 0: not shown
    _PW((1, sp.Ne(py, 2)), (1 / (py - 2), True)),        # e2 = 2 takes the second branch
    _PW((sp.log(prho), prho > -1), (0, True)),           # the first branch holds at the origin
    _PW((0, sp.Eq(px, 0) | sp.Eq(py, 0)), (sp.log(prho), True)),
    _PW((1, prho < 1)), _PW((1, prho < 1), (2, prho > 1)),   # no condition holds on rho = 1 (or anywhere else)
    _PW((1, sp.log(px) > 0), (2, True)),                 # a condition not defined everywhere
    _PW((sp.oo, prho < 1), (prho, True)), _PW((-sp.oo, sp.Eq(prho, 2)), (prho, True)),   # no real value
    1 / (1 + sp.sin(px)), 1 / (sp.cosh(px) - 1), sp.log(sp.log(prho + 1)), 1 / (1 + sp.erf(px) + sp.tanh(py)),
    # bounds that must not be made up (each has no value somewhere: the mutants that survived a run)
    1 / (sp.Rational(5, 4) - sp.atan(prho)), sp.log(2 - sp.tanh(sp.log(px))), 1 / (px ** 2 * py ** 2 - sp.Rational(1, 2)),
    1 / (px ** 2 * sp.exp(py)), sp.log(px ** 2 * sp.exp(py)), 1 / (1 + sp.log(px) ** 2), sp.log(prho ** 2),
    1 / (prho ** 2 * sp.exp(px)),
    1 / (sp.sqrt(prho) - sp.Rational(1, 2)), sp.log(sp.sqrt(prho)), sp.log(sp.tanh(px) / 2),
    sp.log(_PW((px - 2, px > 1), (1, True))), _PW((1, sp.Eq(sp.sin(px), 0)), (sp.log(sp.sin(px) + 1), True)),
    # facts that must not be made up: Not(And) where it holds, < read as >, a negative end, >= read as !=,
    # != read as a bound, a coefficient of 2 (2 rho >= 1 is rho >= 1/2)
    _PW((sp.log(4 - prho), sp.Not(sp.And(prho < 4, px < 100))), (1, True)),
    _PW((sp.log(prho - 3), prho < 4), (0, True)), _PW((sp.log(px - 5), px < -10), (0, True)),
    _PW((1 / px, px >= 0), (1, True)), _PW((sp.log(px - 2), sp.Ne(px, 3)), (0, True)),
    _PW((1, 2 * prho < 1), (sp.log(prho - 1), True)),
    # red team round 11: -oo times a bounded function, a constant exponent oo, a relation between conditions
    -sp.oo * sp.tanh(px), px ** 2 - sp.oo * sp.cos(py), (1 + px ** 2) ** sp.oo, sp.Abs(px) ** sp.oo,
    _PW((0, px > 1), (1, sp.Eq(px > 0, py > 0)), (2, True)),
])
def test_not_defined_somewhere_is_not_defined_on_the_plane(expr):
    with pytest.raises(KernelError, match="not shown defined on the plane"):
        K.defined_on_plane(expr=expr, x=px, y=py)


def test_facts_read_from_a_condition_or_its_negation():
    """`_facts`: p >= L (p > L) for A - B = c p + k with c > 0, p != 0 for
    A != B with k = 0, nothing from A != B with k != 0 (no bound)."""
    F, half = K._facts, sp.Rational(1, 2)
    assert F(px >= 0, False, {}) == {(px, ">="): (0, False)} and F(px > 1, False, {}) == {(px, ">="): (1, True)}
    assert F(px < 1, True, {}) == {(px, ">="): (1, False)} and F(px <= 1, True, {}) == {(px, ">="): (1, True)}
    assert F(2 * prho < 1, True, {}) == {(prho, ">="): (half, False)}      # 2 rho >= 1: rho >= 1/2
    assert F(sp.Ne(px, 0), False, {}) == F(sp.Eq(px, 0), True, {}) == {(px, "!="): True}
    assert F(sp.Ne(px, 3), False, {}) == F(sp.Eq(px, 3), False, {}) == F(sp.Eq(px, 0), False, {}) == {}
    assert F(sp.And(px > 1, px >= 2), False, {}) == {(px, ">="): (2, False)}       # the larger bound
    assert F(sp.And(px >= 2, px > 2), False, {}) == {(px, ">="): (2, True)}        # at one bound, the strict one
    assert F(sp.Or(px > 1, py > 1), False, {}) == {} and F(sp.Or(px > 1, py > 1), True, {}) == {
        (-px, ">="): (-1, False), (-py, ">="): (-1, False)}
    assert F(sp.Eq(px, 1) & sp.Eq(py, 2), True, {}) == {((px - 1) ** 2 + (py - 2) ** 2, "!="): True}


def test_variables_must_be_real_of_either_sign():
    p = sp.Symbol("p", positive=True)
    with pytest.raises(KernelError, match="must be declared real only"):
        K.continuous_on_plane(expr=p ** 2 + py ** 2, x=p, y=py)
    with pytest.raises(KernelError, match="must be declared real only"):
        K.continuous_on_plane(expr=p ** 2 + px ** 2, x=px, y=p)
    with pytest.raises(KernelError, match="two distinct variables"):
        K.continuous_on_plane(expr=px ** 2, x=px, y=px)
    with pytest.raises(KernelError, match="not allowed: Float"):      # the parser reads no Float
        K.continuous_on_plane(expr=px ** 2 + sp.Float(0.5), x=px, y=py)
    with pytest.raises(KernelError, match="symbols other than"):
        K.continuous_on_plane(expr=p + py ** 2, x=px, y=py)


def test_tampered_plane_claim_is_rejected():
    cert = to_certificate([K.continuous_on_plane(expr=sp.log(1 + prho), x=px, y=py)])
    assert check_certificate(cert)[0].claim.var == sp.srepr(sp.Tuple(px, py))
    cert["theorems"][0]["data"]["expr"] = {"$": sp.srepr(sp.log(prho))}
    cert["theorems"][0]["claim"]["expr"] = sp.srepr(sp.log(prho))
    with pytest.raises(CertificateError, match="not shown defined on the plane"):
        check_certificate(cert)


def test_what_is_no_identity_is_refused_by_the_cross_check_before_simplify_runs():
    """f = prod_k (1 + sin(e1 + k e2)^2) - 1 + e1^2 against f(e1, 0) + f(0, e2): no identity, and
    SymPy's simplify ran for minutes on the difference (a tampered P3 certificate hung the checker,
    found by an adversarial campaign); Arb shows the difference nonzero at the first point at once."""
    f = sp.Mul(*[1 + sp.sin(px + k * py) ** 2 for k in range(1, 7)]) - 1 + px ** 2
    split = f.xreplace({py: 0}) + f.xreplace({px: 0})
    with pytest.raises(KernelError, match=r"^the identity fails at \(1/3, 2/7\): lhs - rhs = "):
        K.identity_plane(lhs=f, rhs=split, x=px, y=py)
    t = sp.Symbol("t", positive=True)
    g = sp.Mul(*[1 + sp.sin(t + k) ** 2 for k in range(1, 7)])
    with pytest.raises(KernelError, match=r"^the identity fails at t = 1/10: lhs - rhs = "):
        K.identity(lhs=g, rhs=g.xreplace({t: 2 * t}), var=t, lo=0, hi=1, lo_open=True, hi_open=False)


def test_sympy_takes_a_number_s_sign_from_arb():
    """c = log(1 + 10^-40) - T4(10^-40) = 2.0 10^-201 (1 + ...) > 0 (T4 the Taylor polynomial of degree 4;
    mpmath at 400 digits).  SymPy's own sign of a number comes from a 2-digit evalf, which calls c negative,
    and with it Abs, sign, sqrt(c^2), Max and the relations of c went wrong (red teams 23, 24).  Importing the
    kernel makes SymPy ask Arb (256, 2,048, 32,768 bits) first; undecided stays undecided; numbers Arb does
    not take (complex, gamma) keep SymPy's answer."""
    from uwmr_symbolic.kernel import arb
    k = Q(1, 10 ** 40)
    t4 = k - k ** 2 / 2 + k ** 3 / 3 - k ** 4 / 4
    c = sp.log(1 + k) - t4
    assert arb._SYMPY_SIGN(c, False) is True and arb._SYMPY_N2(sp.log(1 + k), t4) < 0      # SymPy's own
    assert (c.is_positive, c.is_negative, sp.sign(c), sp.Abs(-c), sp.sqrt(c ** 2)) == (True, False, 1, c, c)
    assert sp.Lt(sp.log(1 + k), t4) == sp.false and sp.Max(sp.log(1 + k), t4) == sp.log(1 + k)
    assert (-c).is_negative and sp.Min(c, -c) == -c and sp.Eq(c, 0) == sp.false
    zero = sp.atan(Q(1, 2)) + sp.atan(Q(1, 3)) - sp.pi / 4      # exactly 0: no ball excludes it
    assert zero.is_positive is None and zero.is_negative is None and isinstance(sp.Abs(zero), sp.Abs)
    assert sp.sign(sp.I) == sp.I and (sp.gamma(Q(1, 3)) - 2).is_positive and sp.Lt(1, sp.oo) == sp.true
    # beyond 32,768 bits nothing is decided: log(2 + exp(-30000)) - log(2) > 0 stays unsigned, and the same
    # difference as c for 10^-2500 (about 2 10^-12501), which SymPy's own evalf calls negative, too
    assert (sp.log(2 + sp.exp(-30000)) - sp.log(2)).is_positive is None
    assert isinstance(sp.Eq(sp.log(2 + sp.exp(-30000)), sp.log(2)), sp.Eq)
    k = Q(1, 10 ** 2500)
    t4 = k - k ** 2 / 2 + k ** 3 / 3 - k ** 4 / 4
    tiny = sp.log(1 + k) - t4
    assert arb._SYMPY_SIGN(tiny, False) is True and tiny.is_positive is None and tiny.is_negative is None
    assert isinstance(sp.Ge(sp.log(1 + k), t4), sp.GreaterThan)
    # the kernel: lim |h^2 - c| as h -> 0+ is |c| = c > 0 (it had been -c by SymPy's Abs, and signed negative)
    h = sp.Symbol("h", positive=True)
    th = K.continuous_at_end(expr=sp.Abs(h ** 2 - c), var=h, c=ZERO, width=Q(1))
    assert parse(th.claim.other) == c and K.value_sign(value=parse(th.claim.other)).claim.want == 1
