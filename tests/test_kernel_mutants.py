"""Tests that kill mutants of the trusted kernel (`make mutate`, docs/kernel.md
"Mutation testing").  Each asserts what a rule, the evaluator, the parser or
the certificate checker must accept or reject:

* an accepted claim is compared field by field with the claim worked out by
  hand (interval, open ends, sign, strictness) and with the assumptions the
  theorem must rest on;
* a rejection is checked by its exact message, so the test fails when the
  input is refused by some other check than the one it is aimed at (the
  messages are what `python -m uwmr_symbolic.kernel` prints).
"""
import pytest
import sympy as sp

from uwmr_symbolic.kernel import KernelError, Undefined, evaluate, rules as K
from uwmr_symbolic.kernel.core import Claim

x = sp.Symbol("x", real=True)
s = sp.Symbol("s", positive=True)
t = sp.Symbol("t", positive=True)
n = sp.Symbol("n", nonnegative=True)
Q = sp.Rational
I0, I1, I2, I3 = (sp.Integer(k) for k in range(4))
oo = sp.oo
R = sp.srepr


def why(fn, *args, **kw):
    """The message of the KernelError that fn raises."""
    with pytest.raises(KernelError) as err:
        fn(*args, **kw)
    return str(err.value)


def sign(e, var, lo, hi, lo_open=False, hi_open=False, want=1, strict=True):
    """The claim of a sign theorem, written out by hand."""
    return Claim("sign", R(sp.sympify(e)), R(var), R(sp.sympify(lo)), R(sp.sympify(hi)),
                 lo_open, hi_open, want, strict)


def sturm(e, var, lo, hi, lo_open=False, hi_open=False, want=1, strict=True):
    return K.sign_by_sturm(expr=e, var=var, lo=sp.sympify(lo), hi=sp.sympify(hi),
                           lo_open=lo_open, hi_open=hi_open, want=want, strict=strict)


ARB = {"arb", "sympy-core"}


# ---------------------------------------------------------- shared checks

def test_rule_data_and_premises_are_checked():
    assert why(K.value_sign, value="2") == "expected a SymPy object or an int, got str"
    assert why(K.value_sign, value=True) == "expected a SymPy object or an int, got bool"
    assert why(K.value_sign, value=1.5) == "rule data must be SymPy objects, numbers, strings or lists: 1.5"
    assert why(K.value_sign, value=x) == "not an exact number: x"
    # a Float never reaches a rule: the data is re-read from its srepr, and Float is not allowed there
    assert why(K.value_sign, value=sp.Float(1)) == "value_sign: name not allowed: Float"
    with pytest.raises(KernelError, match="^not an exact number: 0.5"):     # (and not by Arb, later)
        K._number(sp.Float(0.5))
    # (-1)**(1/3) is a number, but the kernel reads x**(1/3) as the real root only for x >= 0
    assert why(K.value_sign, value=sp.Pow(-1, Q(1, 3))) == "not a real constant: (-1)**(1/3): x**(1/3) needs x >= 0"
    assert why(K.value_sign, value=oo) == "a finite constant"
    # (1 + sqrt 2)**2 - 3 - 2 sqrt 2 is exactly 0, though not literally (polynomial arithmetic in
    # sqrt 2); 10^-90 more it is signed at 2,048 bits, 10^-700 more at 32,768; exp(-30000) more, its Arb ball
    # still contains 0 at 32,768 bits, and it is neither 0 nor signed
    c = (1 + sp.sqrt(2)) ** 2 - 3 - 2 * sp.sqrt(2)
    assert K.value_sign(value=c).claim.want == 0 and K.value_sign(value=c + Q(1, 10 ** 90)).claim.want == 1
    assert K.value_sign(value=c - Q(1, 10 ** 700)).claim.want == -1
    assert why(K.value_sign, value=c + sp.exp(-30000)) == f"sign of {c + sp.exp(-30000)} not decided"
    assert why(K.join, 1, 2) == "join: a premise is not a theorem"


def test_value_sign_claims():
    # an int is read as an Integer; sqrt(2) - 1 > 0, 3 - pi < 0, 0 exactly
    for v, w in ((2, 1), (sp.sqrt(2) - 1, 1), (3 - sp.pi, -1), (sp.sqrt(2) ** 2 - 2, 0), (-5, -1)):
        thm = K.value_sign(value=v)
        assert thm.claim == Claim("value_sign", R(sp.sympify(v)), want=w, strict=True)
        assert thm.assumptions == ARB and thm.rule == "value_sign"


def test_interval_checks():
    y = sp.Symbol("y")                    # no assumption at all (integer=True is refused by the parser)
    ident = K.identity
    kw = dict(lhs=I1, rhs=I1)
    assert why(ident, var=x, lo=I0, hi=I1, lo_open=1, hi_open=False, **kw) == "open/closed flags are booleans"
    assert why(ident, var=x, lo=I0, hi=I1, lo_open=False, hi_open=0, **kw) == "open/closed flags are booleans"
    assert why(ident, var=x, lo=I1, hi=I1, lo_open=False, hi_open=False, **kw) == "empty interval (1, 1)"
    assert why(ident, var=x, lo=I2, hi=I1, lo_open=False, hi_open=False, **kw) == "empty interval (2, 1)"
    assert why(ident, var=x, lo=-oo, hi=I1, lo_open=False, hi_open=False, **kw) == "infinite ends are open"
    assert why(ident, var=x, lo=I0, hi=oo, lo_open=False, hi_open=False, **kw) == "infinite ends are open"
    assert why(ident, var=y, lo=I0, hi=I1, lo_open=False, hi_open=False, **kw) == \
        "y: a variable is declared real, positive or nonnegative, nothing else"
    assert why(ident, var=I2, lo=I0, hi=I1, lo_open=False, hi_open=False, **kw) == "not a variable: 2"
    # s > 0: the closed end 0, a negative end, -oo are refused; the open end 0 and 1/2 are fine
    msg = "s > 0 assumed: interval must lie in (0, oo)"
    assert why(ident, var=s, lo=I0, hi=I1, lo_open=False, hi_open=False, **kw) == msg
    assert why(ident, var=s, lo=-I1, hi=I1, lo_open=True, hi_open=False, **kw) == msg
    assert why(ident, var=s, lo=-oo, hi=I1, lo_open=True, hi_open=False, **kw) == msg
    assert ident(var=s, lo=I0, hi=I1, lo_open=True, hi_open=False, **kw).claim.lo == R(I0)
    assert ident(var=s, lo=Q(1, 2), hi=I1, lo_open=False, hi_open=False, **kw).claim.lo == R(Q(1, 2))
    # n >= 0: the closed end 0 is fine, -1 is not
    assert ident(var=n, lo=I0, hi=I1, lo_open=False, hi_open=False, **kw).claim.lo_open is False
    assert why(ident, var=n, lo=-I1, hi=I1, lo_open=False, hi_open=False, **kw) == "n >= 0 assumed"
    assert why(ident, var=n, lo=-oo, hi=I1, lo_open=True, hi_open=False, **kw) == "n >= 0 assumed"
    # rules that only evaluate allow the closed end 0 of s, but still not -1
    assert why(K.sign_by_cover, expr=s + 2, var=s, cuts=[-1, 1], want=1) == "s >= 0 assumed"
    assert K.sign_by_cover(expr=s + 2, var=s, cuts=[0, 1], want=1).claim == sign(s + 2, s, 0, 1)
    # an end that is not a rational: sqrt(2) < 3/2 decided by Arb
    assert K.sign_by_cover(expr=x, var=x, cuts=[1, sp.sqrt(2), Q(3, 2)], want=1).claim.hi == R(Q(3, 2))
    assert why(K.sign_by_cover, expr=x, var=x, cuts=[1, Q(3, 2), sp.sqrt(2)], want=1) == \
        "cut points not increasing: 3/2, sqrt(2)"
    assert why(K.sign_by_cover, expr=x, var=x, cuts=[1, sp.sqrt(2), sp.sqrt(2)], want=1) == \
        "cut points not increasing: sqrt(2), sqrt(2)"
    # a cut that is not a real number
    assert why(K.sign_by_cover, expr=x, var=x, cuts=[1, 2, sp.Pow(-1, Q(1, 3))], want=1) == \
        "not a real constant: (-1)**(1/3): x**(1/3) needs x >= 0"


def test_expressions_are_checked():
    assert why(K.sign_by_cover, expr=x, var=I2, cuts=[0, 1], want=1) == "not a variable: 2"
    assert why(K.sign_by_cover, expr=x + sp.Float(1.5), var=x, cuts=[0, 1], want=1) == \
        "sign_by_cover: name not allowed: Float"
    assert why(K.sign_by_cover, expr=x + s, var=x, cuts=[0, 1], want=1) == "s + x has symbols other than x"


# ---------------------------------------------------------- sign_by_cover

def test_sign_by_cover_claims_and_messages():
    # -x**2 - 1 < 0 everywhere; -x**2 <= 0 (weak) across 0
    thm = K.sign_by_cover(expr=-x ** 2 - 1, var=x, cuts=[-1, 0, 1], want=-1)
    assert thm.claim == sign(-x ** 2 - 1, x, -1, 1, want=-1) and thm.assumptions == ARB
    assert thm.rule == "sign_by_cover"
    weak = K.sign_by_cover(expr=-x ** 2, var=x, cuts=[-1, 0, 1], want=-1, strict=False)
    assert weak.claim == sign(-x ** 2, x, -1, 1, want=-1, strict=False)
    assert why(K.sign_by_cover, expr=-x ** 2, var=x, cuts=[-1, 0, 1], want=-1).startswith(
        "sign not shown on [-1, 0]: Iv(")
    assert why(K.sign_by_cover, expr=x ** 2, var=x, cuts=[-1, 0, 1], want=-1, strict=False).startswith(
        "sign not shown on [-1, 0]: Iv(")
    for bad in (dict(want=0), dict(want=1, strict=1), dict(want=2), dict(want=1, mean_value=0)):
        assert why(K.sign_by_cover, expr=x, var=x, cuts=[1, 2], **bad) == \
            "want is +1 or -1, strict and mean_value booleans"
    mv = K.sign_by_cover(expr=-x ** 2 - 1, var=x, cuts=[-1, 0, 1], want=-1, mean_value=True)
    assert mv.claim == thm.claim and mv.assumptions == ARB | {"sympy-diff"}
    assert why(K.sign_by_cover, expr=sp.Abs(x) - 1, var=x, cuts=[-1, 1], want=1, mean_value=True) == \
        "Abs(x) - 1 not evaluable on [-1, 1]: unsupported function sign"
    assert why(K.sign_by_cover, expr=1 / x, var=x, cuts=[-1, 1], want=1) == \
        "1/x not evaluable on [-1, 1]: division by an interval that may contain 0"
    assert why(K.sign_by_cover, expr=x, var=x, cuts=[1], want=1) == \
        "a cover needs a list of at least two cut points"
    assert why(K.sign_by_cover, expr=x, var=x, cuts=[1, oo], want=1) == "cut points are finite"
    assert why(K.sign_by_cover, expr=x, var=x, cuts=[-oo, 1], want=1) == "cut points are finite"
    assert why(K.sign_by_cover, expr=x, var=x, cuts=[1, 3, 2], want=1) == "cut points not increasing: 3, 2"


# ---------------------------------------------------------- sign_by_taylor

def test_sign_by_taylor_claims_and_messages():
    # x - sin x = x**3/6 - ...: E'''(xi) = cos(xi) > 0 near 0; sign side**3 on each side
    E = x - sp.sin(x)
    right = K.sign_by_taylor(expr=E, var=x, c=I0, side=1, width=Q(1, 2), order=3)
    assert right.claim == sign(E, x, 0, Q(1, 2), lo_open=True, want=1)
    left = K.sign_by_taylor(expr=E, var=x, c=I0, side=-1, width=Q(1, 2), order=3)
    assert left.claim == sign(E, x, -Q(1, 2), 0, hi_open=True, want=-1)
    assert left.assumptions == ARB | {"sympy-diff"} and left.rule == "sign_by_taylor"
    # 1 - cos x = x**2/2 - ...: order 2, positive on both sides (side**2 = 1)
    F = 1 - sp.cos(x)
    assert K.sign_by_taylor(expr=F, var=x, c=I0, side=-1, width=Q(1, 2), order=2).claim == \
        sign(F, x, -Q(1, 2), 0, hi_open=True, want=1)
    # cos x - 1 at 0, order 2: E'' = -cos < 0 on [-1/2, 0], side**2 = 1: negative
    assert K.sign_by_taylor(expr=-F, var=x, c=I0, side=-1, width=Q(1, 2), order=2).claim == \
        sign(-F, x, -Q(1, 2), 0, hi_open=True, want=-1)
    # order 1 about c = 1: E = x - 1, E' = 1 > 0
    assert K.sign_by_taylor(expr=x - 1, var=x, c=I1, side=1, width=I1, order=1).claim == \
        sign(x - 1, x, 1, 2, lo_open=True)
    assert K.sign_by_taylor(expr=x - 1, var=x, c=I1, side=-1, width=I1, order=1).claim == \
        sign(x - 1, x, 0, 1, hi_open=True, want=-1)
    # order 12 is the largest allowed: x**12 at 0
    assert K.sign_by_taylor(expr=x ** 12, var=x, c=I0, side=-1, width=I1, order=12).claim.want == 1
    assert why(K.sign_by_taylor, expr=x ** 13, var=x, c=I0, side=1, width=I1, order=13) == "order m is 1..12"
    assert why(K.sign_by_taylor, expr=x, var=x, c=I0, side=1, width=I1, order=0) == "order m is 1..12"
    assert why(K.sign_by_taylor, expr=x, var=x, c=I0, side=1, width=I1, order=I1) == "order m is 1..12"
    assert why(K.sign_by_taylor, expr=x, var=x, c=I0, side=0, width=I1, order=1) == "side is +1 or -1"
    assert why(K.sign_by_taylor, expr=x, var=x, c=I0, side=2, width=I1, order=1) == "side is +1 or -1"
    assert why(K.sign_by_taylor, expr=x, var=x, c=I0, side=1, width=I0, order=1) == "width > 0"
    assert why(K.sign_by_taylor, expr=x, var=x, c=I0, side=1, width=-I1, order=1) == "width > 0"
    assert why(K.sign_by_taylor, expr=sp.cos(x), var=x, c=I0, side=1, width=I1, order=1) == \
        "derivative 0 at 0 is 1, not exactly 0"
    # E' = 1 + 2x at 0 is 1: order 2 needs it to vanish
    assert why(K.sign_by_taylor, expr=x + x ** 2, var=x, c=I0, side=1, width=I1, order=2) == \
        "derivative 1 at 0 is 1, not exactly 0"
    assert why(K.sign_by_taylor, expr=E, var=x, c=I0, side=1, width=I2 * 2, order=3) == \
        "derivative 3 has no strict sign on [0, 4]"
    assert why(K.sign_by_taylor, expr=x ** 2, var=x, c=I0, side=1, width=I1, order=1) == \
        "derivative 1 has no strict sign on [0, 1]"                  # E' = 2x is 0 at 0
    assert why(K.sign_by_taylor, expr=s * sp.log(s), var=s, c=I0, side=1, width=I1, order=1) == \
        "derivative 0 not defined on [0, 1]: log of an interval that may contain values <= 0"
    assert why(K.sign_by_taylor, expr=x - 1, var=x, c=I1, side=1, width=I1, order=1, cuts=[1, Q(3, 2)]) == \
        "the cuts must run from one end of the box to the other"
    assert why(K.sign_by_taylor, expr=x - 1, var=x, c=I1, side=1, width=I1, order=1, cuts=[Q(3, 2), 2]) == \
        "the cuts must run from one end of the box to the other"
    # the m-th derivative is checked on the sub-boxes: x**2 - x/2 at 0 has E' = 2x - 1/2 < 0 on [0, 1/8]
    # but not on [1/8, 1], so a cut is no help; E' on [0, 1/8] alone is fine
    assert K.sign_by_taylor(expr=x ** 2 - x / 2, var=x, c=I0, side=1, width=Q(1, 8), order=1,
                            cuts=[0, Q(1, 16), Q(1, 8)]).claim.want == -1
    assert why(K.sign_by_taylor, expr=x ** 2 - x / 2, var=x, c=I0, side=1, width=I1, order=1,
               cuts=[0, Q(1, 8), 1]) == "derivative 1 has no strict sign on [0, 1]"


# ---------------------------------------------------------- sign_by_sturm

def test_sign_by_sturm_claims_and_messages():
    thm = sturm(x ** 2 - 2, x, Q(3, 2), oo, hi_open=True)
    assert thm.claim == sign(x ** 2 - 2, x, Q(3, 2), oo, hi_open=True)
    assert thm.assumptions == {"sympy-core", "sympy-polys", "flint-polys"} and thm.rule == "sign_by_sturm"
    assert sturm(x - 2, x, 1, 2, hi_open=True, want=-1).claim == sign(x - 2, x, 1, 2, hi_open=True, want=-1)
    assert why(sturm, x - 2, x, 1, 2, want=-1) == "factor x - 2 has a root in the interval"
    assert why(sturm, x - 1, x, 1, 2) == "factor x - 1 has a root in the interval"
    # weak: a root at an end, open or closed, is allowed for an odd factor
    assert sturm(x * (x - 1), x, 1, 2, lo_open=True, strict=False).claim.strict is False
    assert sturm(x * (x - 2), x, 1, 2, hi_open=True, want=-1, strict=False).claim.want == -1
    assert why(sturm, x * (x - 1), x, 0, 2, strict=False) == "factor x**2 - x has a root in the interval"
    # (x - 1)**2 (x + 1) on [0, 2], weak: the first inner point 1 is a root, the next is 2/3
    assert sturm((x - 1) ** 2 * (x + 1), x, 0, 2, strict=False).claim.want == 1
    assert why(sturm, (x - 1) ** 2 * (x + 1), x, 0, 2, want=-1, strict=False) == "p(2/3) has the wrong sign"
    # the inner point: 1/2 on [0, 1]; 3 on (-oo, 4]... base hi - 1 = 3, then 3 - 1 = 2; 5/2 on [2, oo); -1 on R
    assert why(sturm, x ** 2 + 1, x, 0, 1, want=-1) == "p(1/2) has the wrong sign"
    assert why(sturm, x ** 2 + 1, x, -oo, 4, lo_open=True, want=-1) == "p(2) has the wrong sign"
    assert why(sturm, x ** 2 + 1, x, 2, oo, hi_open=True, want=-1) == "p(5/2) has the wrong sign"
    assert why(sturm, x ** 2 + 1, x, -oo, oo, True, True, want=-1) == "p(-1) has the wrong sign"
    # on (-oo, 4] the candidates are 2, 1, 0, ...: x - 2 and x - 1 vanish there (weak, squared)
    assert why(sturm, (x - 2) ** 2 * (x - 1) ** 2 * (x ** 2 + 1), x, -oo, 4, lo_open=True, want=-1,
               strict=False) == "p(0) has the wrong sign"
    assert why(sturm, x, x, 0, 1, want=0) == "want is +1 or -1, strict a boolean"
    assert why(sturm, x, x, 0, 1, strict=0) == "want is +1 or -1, strict a boolean"
    assert why(sturm, x, x, 0, sp.sqrt(2)) == "factor x has a root in the interval"      # closed at 0
    assert why(sturm, x, x, -sp.sqrt(2), 1) == "factor x has a root in the interval"


def test_sign_by_sturm_with_irrational_ends():
    """Irrational ends: each root's isolating interval is refined until the
    end lies outside it, or the end is exactly that root."""
    S = K.sign_by_sturm
    r2, r3 = sp.sqrt(2), sp.sqrt(3)
    assert S(expr=x ** 2 - 2, var=x, lo=r2, hi=oo, lo_open=True, hi_open=True, want=1).claim == \
        sign(x ** 2 - 2, x, r2, oo, True, True)
    assert S(expr=x ** 2 - 2, var=x, lo=-r2, hi=r2, lo_open=True, hi_open=True, want=-1).claim.want == -1
    assert S(expr=(x ** 2 - 2) ** 2, var=x, lo=I0, hi=r3, lo_open=True, hi_open=True, want=1,
             strict=False).claim.strict is False
    assert S(expr=x - 1, var=x, lo=I1, hi=r2, lo_open=True, hi_open=False, want=1).claim.hi == R(r2)
    assert S(expr=x ** 3 - 3 * x, var=x, lo=r3, hi=sp.pi, lo_open=True, hi_open=False, want=1).claim.lo == R(r3)
    for lo, lo_open, hi, hi_open in ((r2, False, oo, True), (I1, True, r2, False), (-r3, True, -I1, True),
                                     (Q(141, 100), True, r3, True), (I0, True, sp.pi / 2, True)):
        assert why(S, expr=x ** 2 - 2, var=x, lo=lo, hi=hi, lo_open=lo_open, hi_open=hi_open,
                   want=1) in ("factor x**2 - 2 has a root in the interval", f"p({Q(1, 2)}) has the wrong sign",
                               "p(-2) has the wrong sign"), (lo, hi)
    # a root just beyond an irrational end: refined until they separate
    assert S(expr=x - Q(14142135623731, 10 ** 13), var=x, lo=I0, hi=r2, lo_open=True, hi_open=True,
             want=-1).claim.want == -1
    inside = x - Q(14142135623730, 10 ** 13)
    assert why(S, expr=inside, var=x, lo=I0, hi=r2, lo_open=True, hi_open=True, want=-1) == \
        f"factor {sp.Poly(inside, x).sqf_list()[1][0][0].as_expr()} has a root in the interval"
    assert why(sturm, 1 / x, x, -1, 2) == "factor x has a root in the interval"
    assert why(sturm, sp.sqrt(2) / x, x, 1, 2) == "not a rational function over Q: sqrt(2)"
    assert why(sturm, sp.sqrt(2) * x, x, 1, 2) == "not a rational function over Q: sqrt(2)"
    assert why(sturm, I0, x, 1, 2) == "the zero polynomial has no strict sign"
    zero = sturm(I0, x, 1, sp.oo, hi_open=True, want=-1, strict=False)          # 0 <= 0 on [1, oo)
    assert (zero.claim.expr, zero.claim.want, zero.claim.strict, zero.claim.hi) == ("Integer(0)", -1, False, "oo")
    assert why(sturm, x ** 2 - 2, x, 1, 2) == "factor x**2 - 2 has a root in the interval"
    # roots at both ends of a closed interval, strict: both counted
    assert why(sturm, x * (x - 1), x, 0, 1, lo_open=True) == "factor x**2 - x has a root in the interval"
    assert sturm(x * (x - 1), x, 0, 1, lo_open=True, hi_open=True, want=-1).claim.want == -1


def test_sign_below_product_claims_and_messages():
    """c - A B >= 0 on an open interval keeps its flags; a = 0 is allowed
    (A <= 0 and B >= 0 give -A B >= 0); b enters as a product; each refusal
    names what failed."""
    P = K.sign_below_product
    a_bound, b_sign, b_bound = (sturm(e, s, 0, 1, lo_open=True, hi_open=True, strict=False)
                                for e in (1 - s, s ** 2, 2 - s ** 2))
    thm = P(a_bound, b_sign, b_bound, expr=2 - s ** 3, a=I1, b=I2)             # c = a b: weak
    assert thm.claim == sign(2 - s ** 3, s, 0, 1, True, True, 1, False) and thm.rule == "sign_below_product"
    assert P(a_bound, b_sign, b_bound, expr=3 - s ** 3, a=I1, b=I2).claim.strict
    assert why(P, a_bound, b_sign, b_bound, expr=Q(3, 2) - s ** 3, a=I1, b=I2) == "needs c - a b >= 0"
    zero = P(sturm(s, s, 0, 1, lo_open=True, hi_open=True, strict=False), b_sign, b_bound, expr=s ** 3, a=I0, b=I2)
    assert zero.claim == sign(s ** 3, s, 0, 1, True, True, 1, False)            # A = -s <= 0
    assert why(P, sturm(s, s, 0, 1, lo_open=True, hi_open=True, strict=False), b_sign, b_bound,
               expr=-Q(1, 2) + (1 + s) * s ** 2, a=-I1, b=I1) == "third premise must be about 1 - s**2"
    assert why(P, sturm(s, s, 0, 1, lo_open=True, hi_open=True, strict=False), b_sign, b_bound,
               expr=-Q(1, 2) - (-1 - s) * s ** 2, a=-I1, b=I2) == "needs a >= 0"     # false at 0+
    assert why(P, a_bound, b_sign, b_bound, expr=2 - s ** 4, a=I1, b=I2) == "2 - s**4 is not c - (s) (s**2)"
    assert why(P, a_bound, sturm(-s ** 2, s, 0, 1, lo_open=True, hi_open=True, want=-1, strict=False), b_bound,
               expr=2 - s ** 3, a=I1, b=I2) == "premises must be >= 0 claims"


def test_weak_sturm_checks_every_odd_factor():
    """(x - 2)^2 (x - 1)^3 >= 0 on [0, 3] is false (negative below 1): the
    square-free factors come by multiplicity, x - 2 (even, skipped for a weak
    claim) before x - 1 (odd, with its root inside), which must still be
    checked; the inner point 3/2 alone would pass."""
    p = (x - 2) ** 2 * (x - 1) ** 3
    assert [m for _, m in sp.Poly(p, x).sqf_list()[1]] == [2, 3]
    assert why(sturm, p, x, 0, 3, strict=False) == "factor x - 1 has a root in the interval"
    assert sturm(p, x, 1, 3, strict=False).claim.strict is False                 # true on [1, 3]


def test_roots_whose_isolating_intervals_touch():
    """SymPy isolates the roots -1, -1/2 of this quintic as [-1, -1] and
    [-1, 0]: the end -1 of the second interval is the other root, not the one
    isolated there, so the interval is refined before -1 is placed (a
    rational end once counted -1/2 out of (-1, 0])."""
    q = sp.Poly(x ** 5 + Q(13, 2) * x ** 4 + 10 * x ** 3 + Q(31, 2) * x ** 2 + 16 * x + 5, x, domain=sp.QQ)  # (x+5)(x+1)(x+1/2)(x^2+2)
    assert ((-1, -1), 1) in q.intervals() and ((-1, 0), 1) in q.intervals()
    counts = [K._roots_in(q, lo, hi, lo_open, hi_open) for lo, hi, lo_open, hi_open in
              ((-I1, I0, True, False), (-I1, I0, False, False), (-5 * I1, -I1, True, True),
               (-5 * I1, -I1, False, True), (-Q(1, 2), I0, True, True), (-Q(1, 2), I0, False, True))]
    assert counts == [1, 2, 0, 1, 0, 1]
    assert why(sturm, q.as_expr(), x, -1, 0, lo_open=True) == f"factor {q.as_expr()} has a root in the interval"


def test_descartes_says_rootless_only_where_no_root_can_be():
    """Descartes' rule on a rational (a, b) around <lo, hi>: a closed or
    irrational end is pushed outward, so a root at a closed end, or just past
    an irrational one, is inside (a, b) and the test cannot tell (False); an
    open rational end is a itself.  Every True agrees with the isolation."""
    cases = [(x - 1, I1, I2, True, True, True), (x - 1, I1, I2, False, True, False),
             (x - 2, I1, I2, True, True, True), (x - 2, I1, I2, True, False, False),
             (x - 3, I1, I2, False, False, True), (x - 3, I1, 4 * I1, False, False, False),
             (x + 1, -2 * I1, I0, True, True, False), (x + 1, -sp.oo, I0, True, True, False),
             (x ** 2 - 2, 2 * I1, sp.oo, True, True, True), (x ** 2 - 2, I1, 3 * I1, True, True, False),
             (x ** 2 - 2, I0, I1, False, False, True), (x ** 2 - 2, sp.sqrt(3), 5 * I1, False, False, True),
             (x ** 2 - 2, I0, sp.sqrt(2), True, True, False), (x ** 2 - 2, sp.sqrt(2), 3 * I1, True, True, False),
             (x ** 2 - 2, -I1, I1, False, False, True), (x ** 2 + 1, -sp.oo, sp.oo, True, True, False),
             (x ** 2 - 2, -sp.sqrt(3), -Q(3, 2), False, False, True), (x + 1, -sp.sqrt(2), I0, True, True, False)]
    for e, lo, hi, lo_open, hi_open, rootless in cases:
        q = sp.Poly(e, x, domain=sp.QQ)
        assert K._rootless_by_descartes(q, lo, hi, lo_open, hi_open) is rootless, (e, lo, hi, lo_open, hi_open)
        if rootless:
            assert K._roots_in.__wrapped__(q, lo, hi, lo_open, hi_open) == 0
    # (x - 1/2)(x - 3/2)(x^2 + 1): two roots in (0, 2) whose transform has two sign changes; none past 2
    q = sp.Poly((x - Q(1, 2)) * (x - Q(3, 2)) * (x ** 2 + 1), x, domain=sp.QQ)
    assert not K._rootless_by_descartes(q, I0, I2, True, True) and K._roots_in(q, I0, I2, True, True) == 2
    assert K._rootless_by_descartes(q, I2, sp.oo, False, True) and K._rootless_by_descartes(q, Q(3, 2), I2, True, True)
    assert why(sturm, q.as_expr(), x, 1, 2) == f"factor {q.as_expr()} has a root in the interval"


def test_sign_by_sturm_of_a_rational_function():
    """e = N/D over Q: wherever G != 0, e is defined and equals N/D, where G
    collects every denominator of e's tree (a negative power's base too), so
    a removable singularity still refutes: the claim is about e as written."""
    e = (x ** 2 + 1) / (x - 3)
    assert sturm(e, x, 0, 3, hi_open=True, want=-1).claim == sign(e, x, 0, 3, hi_open=True, want=-1)
    assert sturm(e, x, 0, 3, hi_open=True, want=-1).assumptions == {"sympy-core", "sympy-polys", "flint-polys"}
    assert why(sturm, e, x, 0, 3, want=-1) == "factor x - 3 has a root in the interval"     # closed at the pole
    assert why(sturm, e, x, 0, 2) == "p(1) has the wrong sign"
    assert sturm(-1 / (x + 1), x, 0, oo, hi_open=True, want=-1).claim.want == -1   # the sign of D counts
    assert why(sturm, -1 / (x + 1), x, 0, oo, hi_open=True) == "p(1/2) has the wrong sign"
    # (x^2 - 1)/(x - 1) = x + 1 except at 1, where it is undefined
    assert why(sturm, (x ** 2 - 1) / (x - 1), x, 0, 2) == "factor x - 1 has a root in the interval"
    assert sturm((x ** 2 - 1) / (x - 1), x, 1, 2, lo_open=True).claim.lo_open is True
    # (1 + 1/(x - 1))^-2 = (x - 1)^2/x^2, undefined at 1 (the inner 1/(x - 1)) and at 0
    inv = (1 + 1 / (x - 1)) ** -2
    assert why(sturm, inv, x, Q(1, 2), 2, strict=False) == "factor x**2 - x has a root in the interval"
    assert sturm(inv, x, 1, 2, lo_open=True).claim.strict is True
    # weak: a double root of N inside is allowed, a strict claim is not
    dbl = (x - 1) ** 2 / (x + 1)
    assert sturm(dbl, x, 0, 2, strict=False).claim.strict is False
    assert why(sturm, dbl, x, 0, 2) == "factor x - 1 has a root in the interval"
    assert why(sturm, sp.sqrt(x) / (x + 1), x, 0, 1) == "not a rational function over Q: sqrt(x)"
    assert why(sturm, 1 / (x ** 40 + 1) ** 60, x, 0, 1) == "degree too high"
    assert why(sturm, (x + 1) ** 10 ** 7, x, 0, 1) == "degree too high"         # refused before it is raised
    assert sturm(x ** 100 - 1, x, 0, 1, lo_open=True, hi_open=True, want=-1).claim.want == -1   # a power beyond 64
    # D = (x - 1)^2 >= 0 while the guard G = x - 1 < 0 on (0, 1): the sign is D's, not G's
    assert sturm(x * (x - 1) ** -2, x, 0, 1, lo_open=True, hi_open=True).claim.want == 1
    assert why(sturm, x * (x - 1) ** -2, x, 0, 1, True, True, want=-1) == "p(1/2) has the wrong sign"
    # rational coefficients kept whole: N = x - 1/2 (not x - 1) is positive on (1/2, 1)
    assert sturm((x - Q(1, 2)) / (x + 1), x, Q(1, 2), 1, lo_open=True).claim.lo == R(Q(1, 2))
    assert why(sturm, (x - Q(1, 2)) / (x + 1), x, Q(1, 2), 1, lo_open=True, want=-1) == "p(3/4) has the wrong sign"
    # N = 0 identically (SymPy keeps the fraction): both weak signs, no strict one
    zero = (x ** 2 - 1) / (x + 1) - (x - 1)
    assert sturm(zero, x, 0, 1, strict=False, want=-1).claim.strict is False
    assert why(sturm, zero, x, 0, 1) == "the zero polynomial has no strict sign"


def test_fraction_over_q():
    N, D, G = K._fraction_over_q((1 + 1 / (x - 1)) ** -2 + x / 3, x)
    # (x - 1)^2/x^2 + x/3 = (3 (x - 1)^2 + x^3)/(3 x^2); G = x (x - 1): both denominators met
    to = lambda q: sp.Poly(list(reversed([sp.Rational(int(c.p), int(c.q)) for c in q.coeffs()])), x).as_expr()
    assert sp.expand(to(N) * 3 * x ** 2 - to(D) * (3 * (x - 1) ** 2 + x ** 3)) == 0
    assert sp.factor(to(G)) == x * (x - 1) * sp.LC(to(G), x) and sp.degree(to(D), x) == 2
    N, D, G = K._fraction_over_q(2 * x ** 3 * (x + 1) ** -2 * (x + 1), x)   # SymPy keeps it (x + 1)**(-1) here
    assert sp.cancel(to(N) / to(D) - 2 * x ** 3 / (x + 1)) == 0 and sp.degree(to(G), x) == 1


# ---------------------------------------------------------- products and sums

def test_sign_of_product_claims_and_messages():
    pos = sturm(x + 1, x, 1, 2)                                # x + 1 > 0 on [1, 2]
    neg = sturm(x - 3, x, 1, 2, want=-1)                      # x - 3 < 0
    weak = sturm(x - 1, x, 1, 2, strict=False)                # x - 1 >= 0
    wneg = sturm(x - 2, x, 1, 2, want=-1, strict=False)       # x - 2 <= 0
    P = K.sign_of_product
    cases = [((pos, neg), (x + 1) * (x - 3), -1, True), ((neg,), -2 * (x - 3) ** 3, 1, True),
             ((neg,), (x - 3) ** 2, 1, True), ((neg,), (x - 3) ** 3, -1, True),
             ((neg,), (x - 3) ** -1, -1, True), ((neg,), (x - 3) ** -2, 1, True),
             ((weak,), (x - 1) ** 2, 1, False), ((weak,), (x - 1) ** 3, 1, False),
             ((wneg,), (x - 2) ** 2, 1, False), ((wneg,), (x - 2) ** 3, -1, False),
             ((weak,), sp.sqrt(x - 1), 1, False), ((pos,), (x + 1) ** Q(-1, 2), 1, True),
             ((pos, weak), (x + 1) * (x - 1), 1, False), ((pos, wneg), 3 * (x + 1) ** 2 * (x - 2) ** 3, -1, False),
             ((pos,), (x + 1) ** 2 * 5, 1, True), ((wneg,), -(x - 2) ** 3, 1, False),
             ((pos,), -sp.pi * (x + 1), -1, True), ((neg,), -sp.E * sp.pi * (x - 3), 1, True)]   # two constants
    for prem, e, w, st in cases:
        thm = P(*prem, expr=e)
        assert thm.claim == sign(e, x, 1, 2, want=w, strict=st), e
    assert thm.assumptions == ARB | {"sympy-polys", "flint-polys"} and thm.rule == "sign_of_product"
    assert why(P, pos, expr=(x + 1) * sp.sin(x)) == "no premise for factor sin(x)"
    assert why(P, pos, expr=(x + 1) * (x + 2) ** 2) == "no premise for factor (x + 2)**2 nor its base"
    assert why(P, weak, expr=1 / (x - 1)) == "1/(x - 1): a negative power needs a strict sign of its base"
    assert why(P, neg, expr=sp.sqrt(x - 3)) == "sqrt(x - 3): needs base > 0 (>= 0 if r > 0)"
    assert why(P, weak, expr=(x - 1) ** Q(-1, 2)) == "1/sqrt(x - 1): needs base > 0 (>= 0 if r > 0)"
    assert why(P, pos, neg, expr=x + 1) == "a premise matches no factor"
    assert why(P, pos, expr=(x + 1) * 0) == "a zero factor"
    assert why(P, expr=x) == "no premises"
    assert why(P, pos, sturm(x - 3, x, 1, Q(5, 2), want=-1), expr=(x + 1) * (x - 3)) == "premises on different intervals"
    assert why(P, pos, K.identity(lhs=x, rhs=x, var=x, lo=I1, hi=I2, lo_open=False, hi_open=False),
               expr=x + 1) == "premise is a identity theorem, not a sign theorem"
    # open ends are kept
    op = sturm(x - 1, x, 1, 2, lo_open=True)
    assert P(op, expr=2 * (x - 1) ** 3).claim == sign(2 * (x - 1) ** 3, x, 1, 2, lo_open=True)
    op = sturm(x - 3, x, 1, 2, hi_open=True, want=-1)
    assert P(op, expr=2 * (x - 3) ** 3).claim == sign(2 * (x - 3) ** 3, x, 1, 2, hi_open=True, want=-1)


def test_sign_of_sum_claims_and_messages():
    sq = sturm(x ** 2, x, -1, 1, strict=False)
    S = K.sign_of_sum
    assert S(sq, expr=x ** 2 + 1, want=1).claim == sign(x ** 2 + 1, x, -1, 1)
    nq = sturm(-x ** 2, x, -1, 1, want=-1, strict=False)
    assert S(nq, expr=-x ** 2 - 1, want=-1).claim == sign(-x ** 2 - 1, x, -1, 1, want=-1)
    two = S(sq, sturm(x ** 4, x, -1, 1, strict=False), expr=x ** 2 + 1 + x ** 4, want=1)
    assert two.claim == sign(x ** 4 + x ** 2 + 1, x, -1, 1) and two.assumptions == ARB | {"sympy-polys", "flint-polys"}
    # strict because one term is: x**2 > 0 on [1/2, 1]
    one = S(sturm(x ** 2, x, Q(1, 2), 1), sturm(x ** 4, x, Q(1, 2), 1, strict=False), expr=x ** 2 + x ** 4, want=1)
    assert one.claim == sign(x ** 4 + x ** 2, x, Q(1, 2), 1)
    weak2 = S(sq, sturm(x ** 4, x, -1, 1, strict=False), expr=x ** 2 + x ** 4, want=1)
    assert weak2.claim == sign(x ** 4 + x ** 2, x, -1, 1, strict=False)
    assert why(S, sq, expr=x ** 2 + 1, want=0) == "want = +-1 needed"
    assert why(S, sq, expr=x ** 2 + 1, want=2) == "want = +-1 needed"
    assert why(S, sq, expr=x ** 2 - 1, want=1) == "the constant terms -1 have the wrong sign"
    assert why(S, nq, expr=-x ** 2 + 1, want=-1) == "the constant terms 1 have the wrong sign"
    # the constant terms count by their sum: tanh(1) - 1/2 > 0 (one term of each sign), tanh(1) - 1 < 0
    assert S(sq, expr=x ** 2 + sp.tanh(1) - Q(1, 2), want=1).claim == sign(x ** 2 + sp.tanh(1) - Q(1, 2), x, -1, 1)
    assert why(S, sq, expr=x ** 2 + sp.tanh(1) - 1, want=1) == "the constant terms -1 + tanh(1) have the wrong sign"
    assert why(S, sq, expr=-x ** 2 - 1, want=-1) == "a premise has the other sign"
    assert why(S, sq, expr=x ** 2, want=1) == "not a sum: x**2"
    assert why(S, sq, expr=x ** 2 + x, want=1) == "no premise for the terms [x]"
    assert why(S, sq, sturm(x ** 4, x, -1, 1, strict=False), expr=x ** 2 + 1, want=1) == \
        "a premise matches no term"
    op = sturm(x, x, 0, 1, lo_open=True, hi_open=True)
    assert S(op, expr=x + 2, want=1).claim == sign(x + 2, x, 0, 1, True, True)


def test_sign_through_increasing_claims_and_messages():
    T = K.sign_through_increasing
    y = sturm(x - 1, x, 1, 2, lo_open=True, strict=False)
    ny = sturm(x - 3, x, 1, 2, hi_open=True, want=-1)
    for G in (sp.tanh, sp.atan, sp.asinh, sp.sinh, sp.erf):
        assert T(y, expr=G(x - 1)).claim == sign(G(x - 1), x, 1, 2, lo_open=True, strict=False)
        assert T(ny, expr=G(x - 3)).claim == sign(G(x - 3), x, 1, 2, hi_open=True, want=-1)
    thm = T(ny, expr=sp.exp(x - 3))
    assert thm.claim == sign(sp.exp(x - 3), x, 1, 2, hi_open=True) and thm.assumptions == {"sympy-core", "sympy-polys", "flint-polys"}
    assert T(y, expr=sp.cosh(x - 1)).claim == sign(sp.cosh(x - 1), x, 1, 2, lo_open=True)
    assert why(T, y, expr=sp.cos(x - 1)) == "not G(Y): cos(x - 1)"
    assert why(T, y, expr=sp.tanh(x)) == "premise must be about the argument"
    assert why(T, y, y, expr=sp.tanh(x - 1)) == "premise must be about the argument"
    assert why(T, y, expr=sp.exp(x)) == "premise must be about the argument"
    assert why(T, y, y, expr=sp.cosh(x - 1)) == "premise must be about the argument"
    # log: from x - 1 >= 0 on (1, 2], log x >= 0; from x - 3 < 0 and x > 0, log(x - 2)... use Y = x
    assert T(y, expr=sp.log(x)).claim == sign(sp.log(x), x, 1, 2, lo_open=True, strict=False)
    assert why(T, y, y, expr=sp.log(x)) == "one premise for log Y > 0"
    assert why(T, y, expr=sp.log(x + 1)) == "first premise must be about Y - 1"
    below = sturm(x - 1, x, Q(1, 2), Q(2, 3), hi_open=True, want=-1)
    posx = sturm(x, x, Q(1, 2), Q(2, 3), hi_open=True)
    assert T(below, posx, expr=sp.log(x)).claim == sign(sp.log(x), x, Q(1, 2), Q(2, 3), hi_open=True, want=-1)
    assert why(T, below, expr=sp.log(x)) == "log Y < 0 needs Y > 0 too"
    assert why(T, below, below, expr=sp.log(x)) == "second premise must be Y > 0"
    wpos = sturm(x, x, Q(1, 2), Q(2, 3), hi_open=True, strict=False)
    assert why(T, below, wpos, expr=sp.log(x)) == "second premise must be Y > 0"
    npos = sturm(x - 1, x, Q(1, 2), Q(2, 3), hi_open=True, want=-1)
    assert why(T, below, npos, expr=sp.log(x)) == "second premise must be Y > 0"


# ---------------------------------------------------------- join, join_at_point, weaken

def test_join_claims_and_messages():
    a = sturm(x + 1, x, 0, 1, lo_open=True, strict=False)
    b = sturm(x + 1, x, 1, 2, lo_open=True, hi_open=True)
    j = K.join(a, b)
    assert j.claim == sign(x + 1, x, 0, 2, True, True, strict=False) and j.rule == "join"
    assert j.assumptions == {"sympy-core", "sympy-polys", "flint-polys"}
    assert K.join(sturm(x + 1, x, 0, 1), b).claim == sign(x + 1, x, 0, 2, hi_open=True)
    assert why(K.join, a, sturm(x + 2, x, 1, 2)) == "different claims"
    assert why(K.join, a, sturm(x + 1, x, 2, 3)) == "not adjacent"
    assert why(K.join, sturm(x + 1, x, 0, 1, hi_open=True), b) == "shared end point Integer(1) is covered by neither"
    ident = K.identity(lhs=x, rhs=x, var=x, lo=I1, hi=I2, lo_open=False, hi_open=False)
    assert why(K.join, ident, b) == "premise is a identity theorem, not a sign theorem"
    assert why(K.join, a, ident) == "premise is a identity theorem, not a sign theorem"


def test_join_at_point_at_a_zero_claims_and_messages():
    e = (x - 1) ** 2 * (x + 1)
    left = sturm(e, x, 0, 1, lo_open=True, hi_open=True)
    right = sturm(e, x, 1, 2, lo_open=True, hi_open=True)
    j = K.join_at_point(left, right)
    assert j.claim == sign(e, x, 0, 2, True, True, strict=False) and j.assumptions == ARB | {"sympy-polys", "flint-polys"}
    assert why(K.join_at_point, left, sturm(e + 1, x, 1, 2, lo_open=True)) == "different claims"
    assert why(K.join_at_point, left, sturm(e, x, Q(3, 2), 2, lo_open=True)) == "not adjacent"
    f = (x ** 2 - 1) / (x - 1)
    assert why(K.join_at_point, sturm(f, x, 0, 1, hi_open=True), sturm(f, x, 1, 2, lo_open=True)) == \
        "E undefined at 1: division by an interval that may contain 0"
    ident = K.identity(lhs=x, rhs=x, var=x, lo=I1, hi=I2, lo_open=False, hi_open=False)
    assert why(K.join_at_point, ident, right) == "premise is a identity theorem, not a sign theorem"
    assert why(K.join_at_point, left, ident) == "premise is a identity theorem, not a sign theorem"


def test_join_at_point_reads_a_piecewise_condition_at_the_point_strictly():
    """At m = 1, x < 2 holds (2 - x = 1 > 0) and x < 1 does not (1 - x = 0
    is not > 0): the branch that applies is read with the relation's own
    strictness; E(m) is read at 256 bits (e^d - 1 - d, d = 10^-30, is about
    5e-61: Arb at 128 bits cannot place it)."""
    def sides(P):
        return [K.select_branch(sturm(branch, x, lo, hi, lo_open=True, hi_open=True),
                                sturm(1 - x, x, lo, hi, lo_open=True, hi_open=True, want=w), expr=P)
                for (lo, hi), w, branch in zip(((0, 1), (1, 2)), (1, -1), [P.args[0].expr, P.args[1].expr])]
    taken = sp.Piecewise((1 - x, x < 1), (x, True))         # E(1) = 1 from the second branch: strict
    assert K.join_at_point(*sides(taken)).claim.strict
    d = Q(1, 10 ** 30)
    tiny = sp.Piecewise((sp.exp(d) - 1 - d, sp.Eq(x, 1)), (x, True))     # the value at 1 alone
    assert K.join_at_point(*[K.select_branch(sturm(x, x, lo, hi, lo_open=True, hi_open=True),
                                             sturm(1 - x, x, lo, hi, lo_open=True, hi_open=True, want=w), expr=tiny)
                             for lo, hi, w in ((0, 1, 1), (1, 2, -1))]).claim.strict
    below = sp.Piecewise((x, x < 2), (-5, True))
    left = K.select_branch(sturm(x, x, 0, 1, lo_open=True, hi_open=True),
                           sturm(2 - x, x, 0, 1, lo_open=True, hi_open=True), expr=below)
    right = K.select_branch(sturm(x, x, 1, 2, lo_open=True, hi_open=True),
                            sturm(2 - x, x, 1, 2, lo_open=True, hi_open=True), expr=below)
    assert K.join_at_point(left, right).claim.strict


def test_expr_messages():
    """(A certificate cannot hold a Float: the parser refuses the name.)"""
    from uwmr_symbolic.kernel.core import _expr
    assert why(_expr, x + sp.Float(0.5), x) == "floats are not exact: x + 0.5"
    assert why(_expr, x, sp.Integer(2)) == "not a variable: 2"
    assert why(_expr, x + sp.Symbol("y"), x) == "x + y has symbols other than x"
    assert _expr(3, x) == 3


def test_pow_at_exponent_zero():
    """x**0 is 1 (SymPy makes it 1 before the evaluator sees it; the
    evaluator's own case is kept)."""
    from flint import arb
    from uwmr_symbolic.kernel.arb import Iv, _pow
    one = _pow(Iv(arb(2), arb(3)), sp.Integer(0))
    assert (one.lo, one.hi) == (1, 1) and one.lo.rad() == 0 and one.hi.rad() == 0


def test_weaken_claims_and_messages():
    j = sturm(x + 1, x, 0, 2, lo_open=True)
    W = K.weaken
    w = W(j, lo=Q(1, 2), hi=I2, lo_open=False, hi_open=True, strict=False)
    assert w.claim == sign(x + 1, x, Q(1, 2), 2, hi_open=True, strict=False) and w.rule == "weaken"
    assert w.assumptions == {"sympy-core", "arb", "sympy-polys", "flint-polys"}
    # the same interval, and its ends: (0, 2] inside (0, 2], (0, 1) inside; [0, 2] not
    assert W(j, lo=I0, hi=I2, lo_open=True, hi_open=False, strict=True).claim == j.claim
    assert W(j, lo=I0, hi=I1, lo_open=True, hi_open=True, strict=True).claim == sign(x + 1, x, 0, 1, True, True)
    assert why(W, j, lo=I0, hi=I2, lo_open=False, hi_open=False, strict=True) == "J is not inside I"
    assert why(W, j, lo=Q(1, 2), hi=I3, lo_open=False, hi_open=False, strict=True) == "J is not inside I"
    h = sturm(x + 1, x, 0, 2, hi_open=True)
    assert why(W, h, lo=I1, hi=I2, lo_open=False, hi_open=False, strict=True) == "J is not inside I"
    assert W(h, lo=I1, hi=I2, lo_open=False, hi_open=True, strict=True).claim.hi_open is True
    assert why(W, w, lo=Q(1, 2), hi=I1, lo_open=False, hi_open=False, strict=True) == \
        "a weak sign does not give a strict one"
    ident = K.identity(lhs=x, rhs=x, var=x, lo=I1, hi=I2, lo_open=False, hi_open=False)
    assert why(W, ident, lo=I1, hi=I2, lo_open=False, hi_open=False, strict=False) == \
        "premise is a identity theorem, not a sign theorem"


# ---------------------------------------------------------- rewrite, tail, substitution, monotone

def exact_identity(lhs, rhs, var, lo, hi, lo_open=False, hi_open=False):
    return K.identity(lhs=lhs, rhs=rhs, var=var, lo=sp.sympify(lo), hi=sp.sympify(hi),
                      lo_open=lo_open, hi_open=hi_open)


def test_sign_by_rewrite_claims_and_messages():
    L = (s ** 2 + 2 * s + 1) / (s + 1)                     # = s + 1 for s > 0, defined there
    Rw = sturm(s + 1, s, 0, oo, True, True)
    ident = exact_identity(L, s + 1, s, 0, oo, True, True)
    thm = K.sign_by_rewrite(Rw, ident)
    assert thm.claim == sign(L, s, 0, oo, True, True) and thm.rule == "sign_by_rewrite"
    assert thm.assumptions == ARB | {"sympy-polys", "flint-polys"}
    # I = [1, 2] inside (0, oo): lo > 0, defined for s > 0
    assert K.sign_by_rewrite(sturm(s + 1, s, 1, 2), ident).claim == sign(L, s, 1, 2)
    # the identity on (0, oo) does not cover [0, 2] (x real, closed at 0)
    Lx = (x ** 2 + 2 * x + 1) / (x + 1)
    identx = exact_identity(Lx, x + 1, x, 0, 2)
    Rx = sturm(x + 1, x, 0, 2)
    assert K.sign_by_rewrite(Rx, identx, cuts=[0, 1, 2]).claim == sign(Lx, x, 0, 2)
    assert why(K.sign_by_rewrite, Rx, identx) == "L not shown defined on I"             # 0 is not > 0
    # on (0, 2] Lx is defined (syntactically, for x > 0): accepted without cuts
    assert K.sign_by_rewrite(sturm(x + 1, x, 0, 2, lo_open=True), identx).claim == sign(Lx, x, 0, 2, lo_open=True)
    assert why(K.sign_by_rewrite, Rx, identx, cuts=[0, 1]) == "cuts must tile the closed I"
    assert why(K.sign_by_rewrite, Rx, identx, cuts=[1, 2]) == "cuts must tile the closed I"
    assert why(K.sign_by_rewrite, sturm(x + 1, x, 0, 2, lo_open=True), exact_identity(Lx, x + 1, x, 0, 2),
               cuts=[0, 2]) == "cuts must tile the closed I"
    assert why(K.sign_by_rewrite, sturm(x + 1, x, 0, 2, hi_open=True), identx, cuts=[0, 2]) == \
        "cuts must tile the closed I"
    # (x**2 - 1)/(x - 1) is undefined at 1: each closed box is evaluated, [1/2, 2] included
    L1 = (x ** 2 - 1) / (x - 1)
    ident1 = exact_identity(L1, x + 1, x, 0, 2)
    assert why(K.sign_by_rewrite, Rx, ident1, cuts=[0, Q(1, 2), 2]) == \
        "L undefined on [1/2, 2]: division by an interval that may contain 0"
    assert why(K.sign_by_rewrite, sturm(x + 1, x, 0, 2, lo_open=True), ident1) == "L not shown defined on I"
    assert why(K.sign_by_rewrite, Rx, Rx) == "second premise must be an identity"
    assert why(K.sign_by_rewrite, ident, ident) == "premise is a identity theorem, not a sign theorem"
    assert why(K.sign_by_rewrite, sturm(x + 2, x, 0, 2), identx) == \
        "the identity must read L = R for the R of the sign"
    # same expression (a constant), another variable
    assert why(K.sign_by_rewrite, sturm(I2, x, 0, 2), exact_identity(I2, I2, n, 0, 2)) == \
        "the identity must read L = R for the R of the sign"
    assert why(K.sign_by_rewrite, sturm(x + 1, x, 0, 3), identx, cuts=[0, 3]) == \
        "the identity does not hold on all of I"
    # a closed end is an end where L must be defined too: (x^2 - 1)/(x - 1) at 1, (x^2 - 4)/(x - 2) at 2
    assert K.sign_by_rewrite(sturm(x + 1, x, 1, 2, lo_open=True, hi_open=True), ident1).claim.lo == R(I1)
    assert why(K.sign_by_rewrite, sturm(x + 1, x, 1, 2, hi_open=True), ident1) == "L not shown defined on I"
    ident2 = exact_identity((x ** 2 - 4) / (x - 2), x + 2, x, 0, 2)
    assert why(K.sign_by_rewrite, sturm(x + 2, x, 1, 2, lo_open=True), ident2) == "L not shown defined on I"


def test_defined_for_positive():
    d = K.defined_for_positive
    # defined for every s > 0
    for e in (s, 2 * s, s + 1, 1 / s, sp.log(s), sp.log(1 + s ** 2), sp.sqrt(s), s ** Q(-3, 2),
              1 / (s ** 2 + 1), sp.log(sp.exp(s)), 1 / sp.cosh(s), sp.sqrt(sp.Abs(s - 1) + s), 1 / (s + (s - 1) ** 2),
              sp.tanh(s - 1) + sp.atan(s) + sp.sin(s) + sp.cos(s) + sp.Abs(s - 2) + sp.erf(s),
              sp.log(sp.exp(s - 3)), 1 / (s * (s + 2)), sp.Integer(3), (s - 1) ** 2, sp.sqrt(2) / s,
              1 / (sp.sqrt(2) + (s - 1) ** 2), 1 / ((s - 1) ** 2 + sp.Abs(s - 3) + s),
              1 / (s + (s - 1) ** 2 * (s - 2) ** 2), 1 / (s + (s - 1) ** 4), sp.log(s + sp.Abs(s - 1) * (s - 2) ** 2),
              # log w > 0 where w - 1 > 0, >= 0 where w - 1 >= 0
              1 / sp.log(1 + s), sp.log(1 + sp.log(1 + s ** 2)), 1 / (1 + sp.log(1 + s ** 2)),
              sp.log(sp.log(2 + s)), sp.log(1 + sp.log(1 + sp.log(1 + s))), sp.sqrt(sp.log(2 + s)),
              1 / (2 + sp.log(1 + (s - 1) ** 2)), sp.log(sp.log(1 + s)),
              # G(w) > 0 where w > 0, >= 0 where w >= 0, for G odd increasing
              sp.log(1 + sp.asinh(s ** 2)), 1 / sp.tanh(s), 1 / (1 + sp.atan((s - 1) ** 2)), sp.sqrt(sp.erf(s)),
              1 / (1 + s * (s - 1) ** 2),                                  # s >= 0 because s > 0
              1 / (s + sp.sinh((s - 2) ** 2)),
              # lower bounds: sin >= -1, erf(s) > erf(0) = 0, exp(s) > exp(0) = 1, tanh(w) > -1 for every w
              sp.log(sp.sin(s) + 2), 1 / (1 + sp.sin(s) + sp.erf(s)), 1 / (sp.exp(s) - 1), sp.log(1 + sp.tanh(sp.log(s)))):
        assert d(e, s) == (), e
    # a rational function over Q whose numerator and denominator keep one sign on (0, oo) (Sturm)
    for e in (1 / (1 + (s ** 2 - 1) ** 3), sp.log(1 + (s ** 2 - 1) ** 3), 1 / ((s - 1) ** 2 + (s - 2) ** 2),
              sp.sqrt(1 + (1 / s ** 2 - 1) ** 3), 1 / (2 - 3 * s + 2 * s ** 2), 1 / ((s - 1) ** 3 + 3 * s + 1),
              sp.log((s ** 2 - s + 1) / (s ** 2 + 1)) ** 2,
              sp.log((s - 1) ** 3 + 1), 1 / (s + 1 - 1 / (s + 1)),
              1 / sp.log(s ** 2 - s + 2)):                     # log w > 0 from w - 1 = s^2 - s + 1 > 0
        assert d(e, s) == ("sympy-polys", "flint-polys"), e
    # not (or not syntactically) defined for every s > 0
    for e in (1 / (s - 1), sp.log(s - 1), sp.sqrt(s - 1), 1 / sp.sin(s), sp.log(sp.sin(s) + 1), s ** s,
              sp.gamma(s), 1 / (1 - s), (s - 1) ** Q(1, 2), 1 / ((s - 1) ** 2), sp.log(-s), sp.log(s * (s - 1)),
              1 / (s - 1) ** 3, sp.log(sp.Abs(s - 1)), sp.log(1 - sp.exp(s)),
              1 / (sp.exp(s) - 2), sp.sqrt(sp.log(s)), 1 / sp.Integer(-1) * sp.log(s - 2), sp.log(sp.log(s)),
              sp.exp(1 / (s - 1)), sp.cosh(sp.log(s - 1)), sp.log(sp.Pow(-1, Q(1, 3)) + s), 1 / (s + sp.Pow(-1, Q(1, 3))),
              s + sp.Pow(-1, Q(1, 3)), 1 / (s + (s - 1) ** 3), sp.log(s ** s), sp.log(s + (s - 1) ** 3 * (s - 2) ** 2),
              1 / (((1 + sp.sqrt(2)) ** 2 - 3 - 2 * sp.sqrt(2)) * s), sp.log(s + s * (s - 1) ** 2 - 2 * s),
              1 / sp.log(1 + (s - 1) ** 2), 1 / sp.log(1 + s ** 2 - s), sp.log(sp.log(1 + (s - 1) ** 2)),
              sp.log(1 + sp.log(s)),
              # G(w) for G odd increasing has w's sign: not positive where w may be <= 0
              1 / sp.tanh(s - 1), sp.log(sp.asinh(s - 1)), 1 / sp.atan((s - 1) ** 2), 1 / (sp.sin(s) + sp.erf(s)),
              sp.log(Q(1, 2) + sp.tanh(sp.log(s))), 1 / sp.cosh(s) ** 0 / sp.sinh(s - 2),
              # rational, but n or d vanishes or changes sign on (0, oo), or not over Q
              1 / (s ** 2 - 3 * s + 2 - s ** 3), 1 / (2 - 3 * s + s ** 2),
              1 / (s ** 3 - 3 * s ** 2 + 4 * s - 1), sp.sqrt((s ** 2 - 25) / (s - 5)), 1 / ((s - 2) ** 2 * (s + 1)),
              sp.log(-1 - s ** 2), 1 / (s ** 2 - sp.pi * s + 3), sp.log((s ** 2 + 1) / (s - 3) + 4 - s / 10),
              1 / ((1 - 2 * s) / (s - 3) ** 2 - 1 / (s - 3) ** 2 + 7), sp.log(-(s ** 2 + 1) / (s + 2)),
              -sp.oo * sp.sin(s), -sp.oo * sp.erf(s - 2)):          # -oo sin(1) has no finite value
        assert d(e, s) is None, e
    assert d(s ** sp.oo, s, analytic=False) is None and d(s ** sp.pi, s, analytic=False) == ()


def test_defined_on_an_interval():
    """`defined_for_positive(e, s, lo, hi)`: defined on (lo, hi); the Sturm
    count runs on rational bounds around irrational ends (outward, so a
    root at an irrational end is not excluded); closed ends by Arb."""
    d = K.defined_for_positive
    assert d(1 / (s - 1), s) is None and d(1 / (s - 1), s, I2) == d(1 / (s - 1), s, I1) == ()    # s - 1 > lo - 1 >= 0
    assert d(1 / (s ** 2 - 1), s, I2) == d(1 / (s ** 2 - 1), s, I1) == ("sympy-polys", "flint-polys")
    assert d(1 / (s - 1), s, Q(1, 2)) is None and d(1 / (s ** 2 - 1), s, Q(1, 2)) is None and d(1 / (1 - s), s, I0, I1) == ("sympy-polys", "flint-polys")
    assert d(1 / (1 - s), s, I0, Q(3, 2)) is None and d(sp.log(s), s, I2, 4 * I1) == ()
    assert d(1 / (s - 1), s, I0, I1) is None        # a base must be positive: s - 1 < 0 there is not enough
    assert d(1 / (s ** 2 - 2), s, sp.sqrt(3)) == ("sympy-polys", "flint-polys") and d(1 / (s ** 2 - 2), s, sp.sqrt(2)) is None
    assert d(1 / (2 - s ** 2), s, I0, sp.sqrt(2) - Q(1, 10 ** 6)) == ("sympy-polys", "flint-polys")
    assert d(1 / (2 - s ** 2), s, I0, sp.sqrt(2)) is None and d(1 / (3 - s), s, I0, sp.pi) is None
    assert d(1 / (3 - s), s, I0, 3 * I1) == ("sympy-polys", "flint-polys") and d(1 / (3 - s), s, I0, 4 * I1) is None
    assert d(sp.log(s ** 2 - 3), s, Q(7, 4)) == ("sympy-polys", "flint-polys") and d(sp.log(s ** 2 - 3), s, Q(17, 10)) is None
    for lo, hi in ((I2, I1), (-I1, I1), (I1, I1)):
        with pytest.raises(KernelError, match="definedness is checked on some"):
            d(s, s, lo, hi)
    assert K._defined(sp.log(s - 2), s, I2) == () and K._defined(sp.log(s ** 2 - 4), s, I2) == ("sympy-polys", "flint-polys")
    with pytest.raises(KernelError, match="log.s - 2. undefined at 2"):
        K._defined(sp.log(s - 2), s, I2, lo_open=False)
    with pytest.raises(KernelError, match="undefined at 3"):
        K._defined(sp.log(3 - s), s, I1, 3 * I1, hi_open=False)
    assert K._defined(sp.log(4 - s), s, I1, 3 * I1, lo_open=False, hi_open=False) == ("sympy-polys", "flint-polys")
    with pytest.raises(KernelError, match=r"not shown defined on \(1, 5\)"):
        K._defined(sp.log(4 - s), s, I1, 5 * I1)


def test_numerator():
    """A rational function over Q read as N/D term by term: an identity's N
    is the zero polynomial; what the ring cannot read (a radical, pi) and a
    denominator that is the zero polynomial give None."""
    def zero(d, *v):
        nd = K._numerator(d, v)
        return nd is not None and not nd[1]
    assert zero((x ** 2 - 1) / (x - 1) - x - 1, x) and zero(x / 3 - x / 3 + 0 * x, x)
    assert not zero((x ** 2 - 1) / (x - 1) - x, x) and not zero(sp.sqrt(2) * x - x, x)
    assert not zero(sp.sqrt(x) - sp.sqrt(x) + 1, x) and not zero(sp.pi * x, x)
    y = sp.Symbol("y", real=True)
    assert zero(x * y / (x + y) - y + y ** 2 / (x + y), x, y) and not zero(x * y / (x + y) - y, x, y)
    ring, N, D = K._numerator(1 / x + 1 / (x + 1), [x])
    assert (N, D) == (ring(2 * x + 1), ring(x ** 2 + x))        # over the product, not reduced
    assert K._numerator(x / (x + 1) - 1 / (x + 1), [x])[1:] == (ring(x - 1), ring(x + 1))   # one denominator
    assert K._numerator(1 / (x * (x + 1) - x ** 2 - x), [x]) is None and K._numerator(sp.sqrt(x), [x]) is None
    assert K._numerator((x + 1) ** -2, [x])[1:] == (ring(1), ring((x + 1) ** 2))


def test_a_generalized_denominator_that_vanishes_is_refused():
    """tanh y = sinh y / cosh y makes 1/(tanh x - sinh x / cosh x) a zero
    polynomial's reciprocal: nowhere defined, so an identity refuses it
    (`_numerator` gives None) rather than taking it as 0, also under a root."""
    assert not K._zero_when_generalized(1 / (sp.tanh(x) - sp.sinh(x) / sp.cosh(x)), x)
    assert not K._zero_when_generalized(sp.sqrt(1 / (sp.tanh(x) - sp.sinh(x) / sp.cosh(x))) + 1, x)
    assert K._zero_when_generalized(sp.tanh(x) * sp.cosh(x) - sp.sinh(x), x)     # and reads what it can


def test_identity_with_transcendental_constants_is_exact():
    """lhs - rhs rational in t over Q(atan(255/64)): the constant becomes a
    fresh symbol, so the identity is exact (no simplify), and a difference
    of c/t^2 is refused as such."""
    c = sp.atan(Q(255, 64))
    lhs, rhs = c - 1 / t, (t ** 2 * c - t + c) / t ** 2 - c / t ** 2
    thm = K.identity(lhs=lhs, rhs=rhs, var=t, lo=I0, hi=I1, lo_open=True, hi_open=False)
    assert thm.assumptions == {"sympy-core", "sympy-polys"}
    assert why(K.identity, lhs=lhs, rhs=rhs + c / t ** 2, var=t, lo=I0, hi=I1, lo_open=True,
               hi_open=False) == "the rational functions differ"


def test_power_of_a_positive_variable_is_split_off_a_radicand_exactly():
    """b = s^3/(s - 1) - 2 s^2/(s - 1) = s^2 (s - 2)/(s - 1), a sum SymPy
    keeps whole: sqrt(b) = s sqrt((s - 2)/(s - 1)) for s >= 2, exactly
    (N/D once s^2 is divided out); a split into sqrt(N D) would make
    s sqrt((s - 2)(s - 1)), which is no identity, exact instead."""
    b = s ** 3 / (s - 1) - 2 * s ** 2 / (s - 1)
    ends = dict(var=s, lo=I3, hi=sp.Integer(4), lo_open=False, hi_open=False)
    assert K.identity(lhs=sp.sqrt(b), rhs=s * sp.sqrt((s - 2) / (s - 1)), **ends).assumptions == \
        {"sympy-core", "sympy-polys"}
    assert why(K.identity, lhs=sp.sqrt(b), rhs=s * sp.sqrt((s - 2) * (s - 1)), **ends).startswith(
        "the identity fails at s = 31/10: lhs - rhs = [-2.467976807794")


def tail(E, Et, Rv, ident_lo=0, ident_hi=oo, ident_hi_open=True):
    tt = K.sign_by_taylor(expr=Et, var=t, c=I0, side=1, width=1 / Rv, order=1)
    ident = K.identity(lhs=Et, rhs=E.subs(s, 1 / t), var=t, lo=sp.sympify(ident_lo), hi=sp.sympify(ident_hi),
                       lo_open=True, hi_open=ident_hi_open)
    return tt, ident


def test_sign_on_tail_claims_and_messages():
    E, Et = s / (s ** 2 + 1), t / (t ** 2 + 1)
    tt, ident = tail(E, Et, I2)
    thm = K.sign_on_tail(tt, ident, expr=E, var=s, R=I2)
    assert thm.claim == sign(E, s, 2, oo, hi_open=True) and thm.rule == "sign_on_tail"
    assert thm.assumptions == {"arb", "sympy-core", "sympy-diff", "sympy-polys"}
    # an identity on exactly (0, 1/2] is enough; (0, 1/2) is not; (0, 1/3] is not
    _, id_half = tail(E, Et, I2, ident_hi=Q(1, 2), ident_hi_open=False)
    assert K.sign_on_tail(tt, id_half, expr=E, var=s, R=I2).claim == thm.claim
    _, id_open = tail(E, Et, I2, ident_hi=Q(1, 2), ident_hi_open=True)
    msg = "the identity must hold on (0, 1/R]"
    assert why(K.sign_on_tail, tt, id_open, expr=E, var=s, R=I2) == msg
    _, id_third = tail(E, Et, I2, ident_hi=Q(1, 3), ident_hi_open=False)
    assert why(K.sign_on_tail, tt, id_third, expr=E, var=s, R=I2) == msg
    _, id_from = tail(E, Et, I2, ident_lo=Q(1, 10))
    assert why(K.sign_on_tail, tt, id_from, expr=E, var=s, R=I2) == msg
    assert why(K.sign_on_tail, tt, ident, expr=E, var=s, R=I0) == "R > 0"
    assert why(K.sign_on_tail, tt, ident, expr=E, var=s, R=-I1) == "R > 0"
    assert why(K.sign_on_tail, tt, ident, expr=E, var=s, R=oo) == "R > 0"
    assert why(K.sign_on_tail, tt, tt, expr=E, var=s, R=I2) == "second premise must be an identity"
    assert why(K.sign_on_tail, ident, ident, expr=E, var=s, R=I2) == \
        "premise is a identity theorem, not a sign theorem"
    assert why(K.sign_on_tail, tt, ident, expr=Et, var=t, R=I2) == "the tail variable must differ from the variable"
    assert why(K.sign_on_tail, tt, ident, expr=E, var=s, R=I3) == "the tail theorem must be about (0, 1/R]"
    closed = K.weaken(K.sign_by_cover(expr=Et, var=t, cuts=[Q(1, 4), Q(1, 2)], want=1), lo=Q(1, 4),
                      hi=Q(1, 2), lo_open=True, hi_open=False, strict=True)
    assert why(K.sign_on_tail, closed, ident, expr=E, var=s, R=I2) == "the tail theorem must be about (0, 1/R]"
    assert why(K.sign_on_tail, tt, ident, expr=2 * E, var=s, R=I2) == "the identity must read E_t(t) = E(1/t)"
    other = K.identity(lhs=2 * Et, rhs=2 * E.subs(s, 1 / t), var=t, lo=I0, hi=oo, lo_open=True, hi_open=True)
    assert why(K.sign_on_tail, tt, other, expr=2 * E, var=s, R=I2) == "the identity must read E_t(t) = E(1/t)"
    # E = (s**2 - 25)/(s - 5) is undefined at s = 5, though E(1/t) = (1 + 5t)/t where both are defined
    E5, Et5 = (s ** 2 - 25) / (s - 5), (1 + 5 * t) / t
    id5 = K.identity(lhs=Et5, rhs=E5.subs(s, 1 / t), var=t, lo=I0, hi=oo, lo_open=True, hi_open=True)
    pos5 = K.sign_of_product(sturm(1 + 5 * t, t, 0, Q(1, 4), lo_open=True), sturm(t, t, 0, Q(1, 4), lo_open=True),
                             expr=Et5)
    assert why(K.sign_on_tail, pos5, id5, expr=E5, var=s, R=4 * I1) == \
        "(s**2 - 25)/(s - 5) not shown defined on (4, oo)"


def test_sign_by_substitution_claims_and_messages():
    u = sp.Symbol("u", real=True)
    S = K.sign_by_substitution
    outer = sturm(u - 1, u, 2, 3, hi_open=True)                   # u - 1 > 0 on J = [2, 3)
    # x in [3/2, 8/5]: x**2 in [9/4, 64/25], inside J
    lo_b = sturm(x ** 2 - 2, x, Q(3, 2), Q(8, 5))
    hi_b = sturm(3 - x ** 2, x, Q(3, 2), Q(8, 5))
    thm = S(outer, lo_b, hi_b, inner=x ** 2)
    assert thm.claim == sign(x ** 2 - 1, x, Q(3, 2), Q(8, 5)) and thm.rule == "sign_by_substitution"
    assert thm.assumptions == {"sympy-core", "sympy-polys", "flint-polys"}
    # a weak bound suffices at the closed end 2 of J, not at the open end 3
    lo_w = sturm(x ** 2 - 2, x, Q(3, 2), Q(8, 5), strict=False)
    hi_w = sturm(3 - x ** 2, x, Q(3, 2), Q(8, 5), strict=False)
    assert S(outer, lo_w, hi_b, inner=x ** 2).claim == thm.claim
    assert why(S, outer, lo_b, hi_w, inner=x ** 2) == "premise must show 3 - u > 0"
    assert why(S, outer, hi_b, lo_b, inner=x ** 2) == "premise must show u - 2 >= 0"
    assert why(S, lo_b, lo_b, lo_b, inner=x ** 2) == "premise must show u - 3/2 >= 0"
    assert why(S, outer, lo_b, sturm(x ** 2 - 3, x, Q(3, 2), Q(8, 5), want=-1), inner=x ** 2) == \
        "premise must show 3 - u > 0"
    assert why(S, outer, lo_b, inner=x ** 2) == "one bound premise per finite end of J"
    assert why(S, outer, lo_b, hi_b, hi_b, inner=x ** 2) == "one bound premise per finite end of J"
    assert why(S, sturm(u ** 2 + 1, u, -oo, oo, True, True), lo_b, inner=x ** 2) == \
        "one bound premise per finite end of J"
    # the sign, strictness and open ends: 4 - u... u - 4 < 0 on [2, 3); weak outer gives a weak claim
    assert S(sturm(u - 4, u, 2, 3, hi_open=True, want=-1), lo_b, hi_b, inner=x ** 2).claim == \
        sign(x ** 2 - 4, x, Q(3, 2), Q(8, 5), want=-1)
    assert S(sturm(u - 2, u, 2, 3, hi_open=True, strict=False), lo_b, hi_b, inner=x ** 2).claim == \
        sign(x ** 2 - 2, x, Q(3, 2), Q(8, 5), strict=False)
    lo_o = sturm(x ** 2 - 2, x, Q(3, 2), Q(8, 5), lo_open=True, hi_open=True)
    hi_o = sturm(3 - x ** 2, x, Q(3, 2), Q(8, 5), lo_open=True, hi_open=True)
    assert S(outer, lo_o, hi_o, inner=x ** 2).claim == sign(x ** 2 - 1, x, Q(3, 2), Q(8, 5), True, True)
    # one finite end: 1 - u > 0 on (-oo, 0]; u = -x**2 <= 0 from x**2 >= 0
    half = sturm(1 - u, u, -oo, 0, lo_open=True)
    assert S(half, sturm(x ** 2, x, 1, 2, strict=False), inner=-x ** 2).claim == sign(x ** 2 + 1, x, 1, 2)
    assert why(S, half, sturm(x ** 2 - 1, x, 1, 2, strict=False), inner=-x ** 2) == "premise must show 0 - u >= 0"
    ident = exact_identity(x, x, x, 1, 2)
    assert why(S, ident, lo_b, inner=x ** 2) == "premise is a identity theorem, not a sign theorem"
    assert why(S, outer, lo_b, ident, inner=x ** 2) == "premise is a identity theorem, not a sign theorem"


def test_sign_by_monotone_claims_and_messages():
    M = K.sign_by_monotone
    E = 1 - 1 / s                                            # E(2) = 1/2 > 0, E' = s**-2 > 0
    dE = K.sign_of_product(sturm(s, s, 2, oo, hi_open=True), expr=sp.diff(E, s))
    thm = M(dE, expr=E, var=s, R=I2)
    assert thm.claim == sign(E, s, 2, oo, hi_open=True) and thm.rule == "sign_by_monotone"
    assert thm.assumptions == ARB | {"sympy-diff", "sympy-polys", "flint-polys"}
    # decreasing and negative: 1/s - 1, E(2) = -1/2, E' = -s**-2 < 0
    F = 1 / s - 1
    dF = K.sign_of_product(sturm(s, s, 2, oo, hi_open=True), expr=sp.diff(F, s))
    assert M(dF, expr=F, var=s, R=I2).claim == sign(F, s, 2, oo, hi_open=True, want=-1)
    # a weak E' >= 0 still gives E > 0: (s - 2)**3 + 1, E(2) = 1, E' = 3 (s - 2)**2 >= 0
    G = (s - 2) ** 3 + 1
    dG = K.sign_of_product(sturm(s - 2, s, 2, oo, hi_open=True, strict=False), expr=sp.diff(G, s))
    assert not dG.claim.strict and M(dG, expr=G, var=s, R=I2).claim == sign(G, s, 2, oo, hi_open=True)
    assert why(M, dE, expr=E, var=s, R=I0) == "R > 0"
    assert why(M, dE, expr=E, var=s, R=-I1) == "R > 0"
    assert why(M, dE, expr=E, var=s, R=oo) == "R > 0"
    msg = "premise must be a sign of E' on [R, oo)"
    assert why(M, dE, expr=E, var=s, R=I3) == msg
    assert why(M, dE, expr=2 * E, var=s, R=I2) == msg
    assert why(M, dE, expr=E.subs(s, x), var=x, R=I2) == msg
    op = K.sign_of_product(sturm(s, s, 2, oo, lo_open=True, hi_open=True), expr=sp.diff(E, s))
    assert why(M, op, expr=E, var=s, R=I2) == msg
    fin = K.sign_of_product(sturm(s, s, 2, 5), expr=sp.diff(E, s))
    assert why(M, fin, expr=E, var=s, R=I2) == msg
    # 1/s - 1/4: E(2) = 1/4 > 0 but E' < 0
    H = 1 / s - Q(1, 4)
    dH = K.sign_of_product(sturm(s, s, 2, oo, hi_open=True), expr=sp.diff(H, s))
    assert why(M, dH, expr=H, var=s, R=I2) == "E(R) has not the sign of E'"
    assert why(M, dE, expr=E - 1, var=s, R=I2) == "E(R) has not the sign of E'"      # -1/s < 0 at 2
    L = sp.log(s - 1) + 1                   # defined on (1, oo) only: enough on [2, oo)
    dL = K.sign_of_product(sturm(s - 1, s, 2, oo, hi_open=True), expr=sp.diff(L, s))
    assert M(dL, expr=L, var=s, R=I2).claim == sign(L, s, 2, oo, hi_open=True)
    ident = exact_identity(s, s, s, 2, oo, hi_open=True)
    assert why(M, ident, expr=E, var=s, R=I2) == "premise is a identity theorem, not a sign theorem"


# ---------------------------------------------------------- identities and the cross-check

def test_cross_check_points_and_precision():
    cc = K._cross_check
    few = "fewer than 3 points to cross-check the identity"
    # the points: k/10 on [0, 1], lo + k/3 or hi - k/3 on a half-line, k/3 (|k| <= 4) on the line
    cc(sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1, x, I0, I1)
    with pytest.raises(KernelError, match="^the identity fails at x = 1/10: lhs - rhs = "):
        cc(x - Q(9, 10), x, I0, I1)
    with pytest.raises(KernelError, match="^cross-check at x = 1/10 not precise enough$"):
        cc(2 ** 100 * (sp.sin(x) ** 2 + sp.cos(x) ** 2) - 2 ** 100, x, I0, I1)
    with pytest.raises(KernelError, match="^cross-check needs rational ends$"):
        cc(x - x, x, sp.sqrt(2), I2)

    def only_from(a):
        """sin(x)**2 + cos(x)**2 - 1, times sqrt(x - a): zero, defined only for x > a (at x = a,
        a not dyadic, the ball of x - a straddles 0, so sqrt is undefined there too)."""
        return sp.sqrt(x - a) * (sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1)
    cc(only_from(Q(3, 5)), x, I0, I1)                           # 7/10, 8/10, 9/10
    with pytest.raises(KernelError, match=f"^{few}$"):
        cc(only_from(Q(7, 10)), x, I0, I1)                      # 8/10, 9/10
    # [0, oo): 1/3, 2/3, ..., 3: x > 2 leaves 7/3, 8/3, 3 (x = 2 exactly is fine too: 2 - 2 = 0)
    cc(only_from(Q(13, 6)), x, I0, oo)
    with pytest.raises(KernelError, match=f"^{few}$"):
        cc(only_from(Q(7, 3) + Q(1, 100)), x, I0, oo)
    # (-oo, 0]: -1/3, ..., -3
    cc(only_from(Q(13, 6)).subs(x, -x), x, -oo, I0)
    with pytest.raises(KernelError, match=f"^{few}$"):
        cc(only_from(Q(7, 3) + Q(1, 100)).subs(x, -x), x, -oo, I0)
    # (-oo, oo): -4/3, ..., 4/3
    cc(only_from(Q(1, 2)), x, -oo, oo)                          # 2/3, 1, 4/3
    with pytest.raises(KernelError, match=f"^{few}$"):
        cc(only_from(Q(3, 4)), x, -oo, oo)                      # 1, 4/3
    # [2, 3]: 2 + k/10
    cc(only_from(Q(13, 5)), x, I2, I3)                          # 2.7, 2.8, 2.9
    with pytest.raises(KernelError, match=f"^{few}$"):
        cc(only_from(Q(27, 10)), x, I2, I3)                     # 2.8, 2.9 (2.7 - 27/10 straddles 0)
    # (1, oo): 1 + k/3
    cc(only_from(Q(19, 6)), x, I1, oo)                          # 10/3, 11/3, 4
    with pytest.raises(KernelError, match=f"^{few}$"):
        cc(only_from(Q(10, 3) + Q(1, 100)), x, I1, oo)
    # (-oo, -1]: -1 - k/3
    cc(only_from(Q(19, 6)).subs(x, -x), x, -oo, -I1)
    with pytest.raises(KernelError, match=f"^{few}$"):
        cc(only_from(Q(10, 3) + Q(1, 100)).subs(x, -x), x, -oo, -I1)


def test_identity_claims_and_messages():
    ex = exact_identity(s / (s ** 2 + 1), 1 / (s + 1 / s), s, 0, oo, True, True)
    assert ex.claim == Claim("identity", R(s / (s ** 2 + 1)), R(s), R(I0), "oo", True, True,
                             other=R(1 / (s + 1 / s)))
    assert ex.assumptions == {"sympy-core", "sympy-polys"} and ex.rule == "identity"
    trig = exact_identity(sp.sin(x) ** 2 + sp.cos(x) ** 2, I1, x, -1, 2, hi_open=True)
    assert trig.claim == Claim("identity", R(sp.sin(x) ** 2 + sp.cos(x) ** 2), R(x), R(-I1), R(I2), False, True,
                               other=R(I1))
    assert trig.assumptions == {"sympy-core", "sympy-simplify", "arb"}
    # a radical, pi, a function of x: rational over Q once each such subterm is a fresh symbol -- exact
    for l, r in ((sp.sqrt(2) * (x + 1), sp.sqrt(2) * x + sp.sqrt(2)), (sp.pi * (x + 1), sp.pi * x + sp.pi),
                 (sp.sqrt(x + 2) * (x + 1), sp.sqrt(x + 2) * x + sp.sqrt(x + 2)),
                 (sp.exp(x) * (x + 1), x * sp.exp(x) + sp.exp(x)),
                 (1 / (sp.tanh(x) + 1) ** 2, 1 / (sp.tanh(x) ** 2 + 2 * sp.tanh(x) + 1))):
        assert exact_identity(l, r, x, 0, 1).assumptions == {"sympy-core", "sympy-polys"}, l
    # powers of a positive variable leave a radical: sqrt(1 + 4/s^2) = sqrt(s^2 + 4)/s, (1 + 1/s)^(3/2) too
    for l, r in ((sp.sqrt(1 + 4 / s ** 2), sp.sqrt(s ** 2 + 4) / s),
                 ((1 + 1 / s) ** Q(3, 2), (s + 1) * sp.sqrt(s + 1) / (s * sp.sqrt(s)))):
        assert exact_identity(l, r, s, 0, 1, True).assumptions == {"sympy-core", "sympy-polys"}, l
    # what is no identity fails the numeric cross-check first (simplify could run for minutes on it)
    assert why(exact_identity, sp.sqrt(1 + 4 / s ** 2), sp.sqrt(s ** 2 + 4) / s ** 2, s, 0, 1, True).startswith(
        "the identity fails at s = 1/10: lhs - rhs = [-180.22485955050")
    # lhs - rhs = exp(x) (x - 1/10) ... (x - 9/10) vanishes at every cross-check point: simplify decides
    dip = sp.Mul(*[x - sp.Rational(k, 10) for k in range(1, 10)])
    assert why(exact_identity, sp.exp(x) * (1 + dip), sp.exp(x), x, 0, 1) == \
        "SymPy's simplify does not reduce lhs - rhs to 0"
    # a function of the same generalised argument up to sign: odd G(-u) = -G(u), even cosh(-u) = cosh(u)
    u, w = 1 - sp.sqrt(s ** 2 + 4) / s, sp.sqrt(1 + 4 / s ** 2) - 1          # w = -u for s > 0
    for l, r in ((sp.sinh(u), -sp.sinh(w)), (sp.cosh(u), sp.cosh(w)), (sp.atan(u) + sp.atan(w), sp.Integer(0)),
                 (sp.tanh(u), -sp.sinh(w) / sp.cosh(w))):
        assert exact_identity(l, r, s, 0, 1, True).assumptions == {"sympy-core", "sympy-polys"}, l
    for l, r in ((sp.sinh(u), sp.sinh(w)), (sp.cosh(u), -sp.cosh(w)), (sp.exp(u), sp.exp(w))):
        assert why(exact_identity, l, r, s, 0, 1, True).startswith("the identity fails at s = 1/10: "), l
    # the radical's relation r^2 = s^2 + 4 is needed: (2 r - 4)/r = 2 - 4/(s sqrt(1 + 4/s^2)) = 2 - 4 r/(s^2 + 4)
    assert exact_identity((2 * sp.sqrt(s ** 2 + 4) - 4) / sp.sqrt(s ** 2 + 4), 2 - 4 / (s * sp.sqrt(1 + 4 / s ** 2)),
                          s, 0, 1, True).assumptions == {"sympy-core", "sympy-polys"}
    # powers of a real (not positive) variable stay inside: sqrt(x^2 + x^4) = |x| sqrt(1 + x^2), not x sqrt(1 + x^2)
    assert why(exact_identity, sp.sqrt(x ** 2 + x ** 4), x * sp.sqrt(1 + x ** 2), x, -1, 1).startswith(
        "the identity fails at x = -4/5: ")                 # (x < 0: the sides differ in sign)
    # distinct subterms that are no radical or listed function are distinct symbols too
    for l, r in ((sp.pi * x, sp.E * x), (sp.Abs(x), sp.Abs(x - 1)), (sp.pi + sp.Abs(x), sp.Abs(x) + sp.E)):
        assert why(exact_identity, l, r, x, -1, 1) .startswith("the identity fails at"), l
    # not for a real x: sqrt(x^2) is |x|, and the generalisation keeps sqrt(x^2) as one symbol
    assert why(exact_identity, sp.sqrt(x ** 2), x, x, -1, 1) .startswith("the identity fails at")
    # the generalised subterms need a relation between them (sqrt(s + 1) sqrt(s + 2) = sqrt(s^2 + 3 s + 2)):
    # simplify; but sqrt(s) sqrt(s + 1) = sqrt(s^2 + s) is exact (s^2 + s = s (s + 1), s > 0)
    assert "sympy-simplify" in exact_identity(sp.sqrt(s + 1) * sp.sqrt(s + 2), sp.sqrt(s ** 2 + 3 * s + 2),
                                              s, 0, 1, True).assumptions
    assert exact_identity(sp.sqrt(s) * sp.sqrt(s + 1), sp.sqrt(s ** 2 + s), s, 0, 1, True).assumptions == \
        {"sympy-core", "sympy-polys"}
    # distinct subterms are distinct symbols: tanh(x) - tanh(2x) is not generalised to a - a = 0
    for l, r in ((sp.tanh(x), sp.tanh(2 * x)), (sp.sqrt(2) * x, sp.sqrt(3) * x), (sp.exp(x) * (x + 1), sp.exp(x) * x)):
        assert why(exact_identity, l, r, x, 0, 1) .startswith("the identity fails at")
    assert why(exact_identity, x ** 2, x, x, 0, 1) == "the rational functions differ"
    assert why(exact_identity, sp.sin(x), sp.cos(x), x, 0, 1) .startswith("the identity fails at")
    assert why(exact_identity, sp.sin(x) ** 2 + sp.cos(x) ** 2, I1, x, sp.sqrt(2), 2) == \
        "cross-check needs rational ends"
    assert why(exact_identity, 2 ** 100 * (sp.sin(x) ** 2 + sp.cos(x) ** 2), 2 ** 100, x, 0, 1) == \
        "cross-check at x = 1/10 not precise enough"
    assert why(exact_identity, sp.sqrt(x - Q(7, 10)) * (sp.sin(x) ** 2 + sp.cos(x) ** 2), sp.sqrt(x - Q(7, 10)),
               x, 0, 1) == "fewer than 3 points to cross-check the identity"
    assert why(exact_identity, x, x, s, 1, 2) == "x has symbols other than s"


def test_identity_reads_atan_of_a_reciprocal_only_where_its_argument_is_positive():
    """atan(u) + atan(1/u) = pi/2 where u > 0 (and -pi/2 where u < 0): with
    one positive variable, atan(u) for u > 0 at every t > 0 is read as
    pi/2 - atan(1/u), so a tail form's pi/2 - atan(t) meets atan(1/t) -- exact."""
    tail = sp.atan(t) - t / (t ** 2 + 1)                   # (atan(s) + s/(1 + s^2) at s = 1/t) read off pi/2
    at_s = sp.pi / 2 - sp.atan(1 / t) - (1 / t) / (1 + 1 / t ** 2)
    for l, r in ((tail, at_s), (sp.atan(t ** 2) + sp.atan(t ** -2), sp.pi / 2), (sp.atan(2 / (t + 1)),
                                                                                  sp.pi / 2 - sp.atan((t + 1) / 2))):
        assert exact_identity(l, r, t, 0, Q(1, 4), True).assumptions == {"sympy-core", "sympy-polys"}, l
    # not for a real x (on (-2, -1), atan(x) = -pi/2 - atan(1/x)): cross-checked, and false
    assert why(exact_identity, sp.atan(x), sp.pi / 2 - sp.atan(1 / x), x, -2, -1).startswith(
        "the identity fails at x = -19/10")
    # nor where u is not shown positive at every t > 0: atan(t - 1) on (1/4, 1/2), where t - 1 < 0
    assert why(exact_identity, sp.atan(t - 1), sp.pi / 2 - sp.atan(1 / (t - 1)), t, Q(1, 4), Q(1, 2)).startswith(
        "the identity fails at t = 11/40")


def test_identity_plane_claims_and_messages():
    y = sp.Symbol("y", real=True)
    P = K.identity_plane
    same = P(lhs=x * y, rhs=x * y, x=x, y=y)
    assert same.claim == Claim("identity_plane", R(x * y), R(sp.Tuple(x, y)), other=R(x * y))
    assert same.assumptions == {"sympy-core"} and same.rule == "identity_plane"
    rat = P(lhs=(x ** 2 - y ** 2) / (x - y), rhs=x + y, x=x, y=y)
    assert rat.assumptions == {"sympy-core", "sympy-polys"}
    # radicals, pi, functions of x or y: exact once generalised to fresh symbols
    for l, r in ((sp.sqrt(2) * (x + y), sp.sqrt(2) * x + sp.sqrt(2) * y), (sp.pi * (x + 1), sp.pi * x + sp.pi),
                 (sp.exp(y) * (x + 1), x * sp.exp(y) + sp.exp(y)), (sp.exp(x) * (y + 1), y * sp.exp(x) + sp.exp(x)),
                 (sp.sqrt(y ** 2 + 1) * (x + 1), x * sp.sqrt(y ** 2 + 1) + sp.sqrt(y ** 2 + 1))):
        assert P(lhs=l, rhs=r, x=x, y=y).assumptions == {"sympy-core", "sympy-polys"}, l
    # a relation between subterms is needed: simplify + cross-check
    assert P(lhs=sp.exp(x) * sp.exp(y), rhs=sp.exp(x + y), x=x, y=y).assumptions == \
        {"sympy-core", "sympy-simplify", "arb"}
    # what is no identity fails the cross-check at the first point, before simplify is asked
    assert why(P, lhs=sp.exp(x) * (y + 1), rhs=sp.exp(y) * (x + 1), x=x, y=y).startswith(
        "the identity fails at (1/3, 2/7): lhs - rhs = [0.02007590232374")
    assert why(P, lhs=x ** 2 + y, rhs=x ** 2 + y ** 2, x=x, y=y) == "the rational functions differ"
    assert why(P, lhs=sp.sin(x), rhs=sp.cos(y), x=x, y=y).startswith("the identity fails at (1/3, 2/7): ")
    # lhs - rhs = exp(x) times a polynomial that vanishes at the ten cross-check points: simplify decides
    dip = sp.Mul(*[(x - p) ** 2 + (y - q) ** 2 for p, q in K._PLANE_POINTS])
    assert why(P, lhs=sp.exp(x) * (1 + dip), rhs=sp.exp(x), x=x, y=y) == \
        "SymPy's simplify does not reduce lhs - rhs to 0"
    assert why(P, lhs=x, rhs=x, x=x, y=x) == "two distinct variables"
    assert why(P, lhs=x, rhs=x, x=x, y=I2) == "two distinct variables"
    assert why(P, lhs=x, rhs=x, x=I2, y=y) == "two distinct variables"
    assert why(P, lhs=x, rhs=x, x=x, y=s) == "x, s must be declared real only"
    assert why(P, lhs=x, rhs=x, x=n, y=y) == "n, y must be declared real only"
    assert why(P, lhs=x + s, rhs=x + s, x=x, y=y) == "s + x: a float, or symbols other than x, y"
    assert why(P, lhs=x, rhs=x + s - s + t, x=x, y=y) == "t + x: a float, or symbols other than x, y"
    # the cross-check at the 10 fixed points: sqrt(x - 2) is defined at (2, -1/5), (7/3, 11/4), (5, 1/6)
    one = sp.sin(y) ** 2 + sp.cos(y) ** 2
    ok = P(lhs=sp.sqrt(x - 2) * one, rhs=sp.sqrt(x - 2), x=x, y=y)
    assert "sympy-simplify" in ok.assumptions
    assert why(P, lhs=sp.sqrt(x - 3) * one, rhs=sp.sqrt(x - 3), x=x, y=y) == \
        "fewer than 3 points to cross-check the identity"
    # and at (1/3, 2/7) first: 2**100 (sin**2 + cos**2) is 2**100 only to about 2**-218 in 320 bits
    assert why(P, lhs=2 ** 100 * one, rhs=2 ** 100, x=x, y=y) == "cross-check at (1/3, 2/7) not precise enough"
    # sqrt(-x - 2 + ...) first evaluable at (-3, -2): the points are tried in their order
    assert why(P, lhs=2 ** 100 * sp.sqrt(-x - 2) * one, rhs=2 ** 100 * sp.sqrt(-x - 2), x=x, y=y) == \
        "cross-check at (-3, -2) not precise enough"


def test_continuous_at_end_and_diverges_by_growth_claims_and_messages():
    C = K.continuous_at_end
    thm = C(expr=sp.cos(x), var=x, c=I0, width=Q(1, 2))
    assert thm.claim == Claim("limit", R(sp.cos(x)), R(x), R(I0), R(Q(1, 2)), other=R(I1))
    assert thm.assumptions == ARB and thm.rule == "continuous_at_end"
    assert C(expr=sp.exp(x), var=x, c=I1, width=I1).claim.other == R(sp.E)
    assert C(expr=sp.sqrt(n), var=n, c=I0, width=I1).claim.other == R(I0)
    for c, w in ((oo, I1), (I0, oo), (I0, I0), (I0, -I1), (-oo, I1)):
        assert why(C, expr=x, var=x, c=c, width=w) == "finite c and w > 0"
    assert why(C, expr=n, var=n, c=-I1, width=I1) == "n >= 0 assumed"
    assert why(C, expr=1 / n, var=n, c=I0, width=Q(1, 2)) == \
        "1/n not defined on [0, 1/2]: division by an interval that may contain 0"
    D = K.diverges_by_growth
    lin = sturm(2 * s - 2, s, 1, oo, hi_open=True, strict=False)          # (s**2)' - 2 = 2s - 2 >= 0 on [1, oo)
    d = D(lin, expr=s ** 2, var=s, R=I1, rate="linear", k=I2)
    assert d.claim == Claim("diverges", R(s ** 2), R(s), R(I1), "oo", False, True) and d.rule == "diverges_by_growth"
    assert d.assumptions == ARB | {"sympy-diff", "sympy-polys", "flint-polys"}
    # log rate: s * (s**2)' - 2 = 2 s**2 - 2 >= 0 on [1, oo)
    lg = sturm(2 * s ** 2 - 2, s, 1, oo, hi_open=True, strict=False)
    assert D(lg, expr=s ** 2, var=s, R=I1, rate="log", k=I2).claim == d.claim
    assert why(D, lg, expr=s ** 2, var=s, R=I1, rate="linear", k=I2) == "premise must be 2*s - 2 >= 0 on [1, oo)"
    assert why(D, lin, expr=s ** 2, var=s, R=I1, rate="log", k=I2) == "premise must be 2*s**2 - 2 >= 0 on [1, oo)"
    for rate in ("square", I1, I0, Q(3, 2), -Q(1, 2)):
        assert why(D, lin, expr=s ** 2, var=s, R=I1, rate=rate, k=I2) == \
            "rate is 'linear', 'log' or a rational p with 0 < p < 1"
    # rate p = 1/2: s^(1/2) (sqrt(s))' - 1/2 = 0 >= 0 on [1, oo); with p = 1/4 the premise is another
    half = sturm(sp.Integer(0), s, 1, oo, hi_open=True, strict=False)
    assert D(half, expr=sp.sqrt(s), var=s, R=I1, rate=Q(1, 2), k=Q(1, 2)).claim == \
        Claim("diverges", R(sp.sqrt(s)), R(s), R(I1), "oo", False, True)
    assert why(D, half, expr=sp.sqrt(s), var=s, R=I1, rate=Q(1, 4), k=Q(1, 2)) == \
        "premise must be s**(1/4)/2 - 1/2 >= 0 on [1, oo)"
    for Rv, k in ((I0, I2), (I1, I0), (oo, I2), (I1, oo), (-I1, I2), (I1, -I2)):
        assert why(D, lin, expr=s ** 2, var=s, R=Rv, rate="linear", k=k) == "R > 0 and k > 0"
    assert why(D, lin, expr=s ** 2, var=s, R=I2, rate="linear", k=I2) == "premise must be 2*s - 2 >= 0 on [2, oo)"
    op = sturm(2 * s - 2, s, 1, oo, lo_open=True, hi_open=True)
    assert why(D, op, expr=s ** 2, var=s, R=I1, rate="linear", k=I2) == "premise must be 2*s - 2 >= 0 on [1, oo)"
    fin = sturm(2 * s - 2, s, 1, 5, strict=False)
    assert why(D, fin, expr=s ** 2, var=s, R=I1, rate="linear", k=I2) == "premise must be 2*s - 2 >= 0 on [1, oo)"
    # -s**2 with k = 1: (-s**2)' - 1 = -2s - 1 < 0, the wrong sign
    neg = sturm(-2 * s - 1, s, 1, oo, hi_open=True, want=-1)
    assert why(D, neg, expr=-s ** 2, var=s, R=I1, rate="linear", k=I1) == "premise must be -2*s - 1 >= 0 on [1, oo)"
    xs = sturm(2 * x - 2, x, 1, oo, hi_open=True, strict=False)
    assert why(D, xs, expr=s ** 2, var=s, R=I1, rate="linear", k=I2) == "premise must be 2*s - 2 >= 0 on [1, oo)"
    # log(s - 1) + s**2 grows, but is not defined for every s > 0
    L = sp.log(s - 1) + s ** 2
    # log(s - 1) + s**2 + 2s: E' - 2 = 2s + 1/(s - 1) > 0 on [2, oo); E is defined there (not on (0, 1])
    L = sp.log(s - 1) + s ** 2 + 2 * s
    pl = K.sign_of_sum(K.sign_of_product(sturm(s, s, 2, oo, hi_open=True), expr=2 * s),
                       K.sign_of_product(sturm(s - 1, s, 2, oo, hi_open=True), expr=1 / (s - 1)),
                       expr=2 * s + 1 / (s - 1), want=1)
    assert D(pl, expr=L, var=s, R=I2, rate="linear", k=I2).claim == Claim("diverges", R(L), R(s), R(I2), "oo",
                                                                          False, True)
    ident = exact_identity(s, s, s, 1, oo, hi_open=True)
    assert why(D, ident, expr=s ** 2, var=s, R=I1, rate="linear", k=I2) == \
        "premise is a identity theorem, not a sign theorem"


# ---------------------------------------------------------- sup rules

def test_sup_upper_rules_claims_and_messages():
    S = K.sup_upper_by_sign
    g = 2 * x - x ** 2
    sq = sturm(1 - g, x, -1, 3, lo_open=True, strict=False)         # 1 - (2x - x**2) = (x - 1)**2 >= 0
    thm = S(sq, expr=g, bound=I1)
    assert thm.claim == Claim("sup_upper", R(g), R(x), R(-I1), R(I3), True, False, other=R(I1))
    assert thm.assumptions == {"sympy-core", "sympy-polys", "flint-polys"} and thm.rule == "sup_upper_by_sign"
    assert why(S, sq, expr=g, bound=I2) == "premise must be U - E >= 0"
    neg = sturm(-x ** 2 - 1, x, 0, 1, want=-1)                       # 0 - (x**2 + 1) < 0
    assert why(S, neg, expr=x ** 2 + 1, bound=I0) == "premise must be U - E >= 0"
    assert why(S, exact_identity(x, x, x, 0, 1), expr=x, bound=I0) == \
        "premise is a identity theorem, not a sign theorem"
    A = K.sup_upper_of_abs

    def U(expr, var, cuts, bound):                                  # E <= U from U - E >= 0 on a cover
        return S(K.sign_by_cover(expr=bound - expr, var=var, cuts=cuts, want=1, strict=False), expr=expr, bound=bound)
    a = U(expr=x, var=x, cuts=[-1, 1], bound=I1)
    b = U(expr=-x, var=x, cuts=[-1, 1], bound=I1)
    ab = A(a, b)
    assert ab.claim == Claim("sup_upper", R(sp.Abs(x)), R(x), R(-I1), R(I1), other=R(I1)) and ab.rule == "sup_upper_of_abs"
    assert ab.assumptions == ARB
    assert why(A, a, a) == "second premise must be about -E"
    assert why(A, a, U(expr=-x, var=x, cuts=[-1, 1], bound=I2)) == "premises on different intervals or bounds"
    assert why(A, a, U(expr=-x, var=x, cuts=[-1, 2], bound=I1)) == "premises on different intervals or bounds"
    assert why(A, sq, b) == "premises must be sup_upper theorems"
    assert why(A, a, sq) == "premises must be sup_upper theorems"


def test_sup_lower_by_point_claims_and_messages():
    L = K.sup_lower_by_point
    E = s / (s ** 2 + 1)
    kw = dict(lo=I0, hi=I2, lo_open=True, hi_open=False)
    low = L(expr=E, var=s, point=I1, bound=Q(1, 2), **kw)              # E(1) = 1/2 exactly
    assert low.claim == Claim("sup_lower", R(E), R(s), R(I0), R(I2), True, False, other=R(Q(1, 2)))
    assert low.assumptions == ARB and low.rule == "sup_lower_by_point"
    # the closed end 2 may be the point (E(2) = 2/5), an open end may not
    assert L(expr=E, var=s, point=I2, bound=Q(2, 5), **kw).claim.other == R(Q(2, 5))
    assert why(L, expr=E, var=s, point=I2, bound=Q(2, 5), lo=I0, hi=I2, lo_open=True, hi_open=True) == \
        "point after I"
    assert why(L, expr=E, var=s, point=I3, bound=I0, **kw) == "point after I"
    assert L(expr=x, var=x, point=I0, bound=I0, lo=I0, hi=I1, lo_open=False, hi_open=False).claim.lo == R(I0)
    assert why(L, expr=x, var=x, point=I0, bound=I0, lo=I0, hi=I1, lo_open=True, hi_open=False) == "point before I"
    assert why(L, expr=x, var=x, point=-I1, bound=-I2, lo=I0, hi=I1, lo_open=False, hi_open=False) == \
        "point before I"
    # exact: (sqrt 2)**2 = 2 literally, though Arb's ball of it is not >= 2; by Arb: E(1) = 1/2 >= 2/5
    assert L(expr=x ** 2, var=x, point=sp.sqrt(2), bound=I2, lo=I0, hi=I2, lo_open=False, hi_open=False).claim.other \
        == R(I2)
    assert L(expr=E, var=s, point=I1, bound=Q(2, 5), **kw).claim.other == R(Q(2, 5))
    B = Q(1, 2) + Q(1, 10 ** 30)
    assert why(L, expr=E, var=s, point=I1, bound=B, **kw) == f"E(1) >= {B} not shown"
    assert why(L, expr=1 / (s - 1), var=s, point=I1, bound=I0, **kw) == \
        "E undefined at 1: division by an interval that may contain 0"


def test_sup_lower_by_limit_claims_and_messages():
    E = s / sp.sqrt(s ** 2 + 1)                                   # -> 1 as s -> oo
    Et = 1 / sp.sqrt(t ** 2 + 1)
    half = Q(1, 2)

    def ident(lo=I0, hi=oo, hi_open=True, lhs=Et, rhs=E.subs(s, 1 / t), var=t):
        return K.identity(lhs=lhs, rhs=rhs, var=var, lo=lo, hi=hi, lo_open=True, hi_open=hi_open)
    L = K.sup_lower_by_limit
    idt = ident()
    low = L(idt, expr=E, var=s, width=half, bound=I1, lo=I0, lo_open=True)
    assert low.claim == Claim("sup_lower", R(E), R(s), R(I0), "oo", True, True, other=R(I1))
    assert low.assumptions == {"arb", "sympy-core", "sympy-polys"} and low.rule == "sup_lower_by_limit"
    assert L(idt, expr=E, var=s, width=half, bound=I1, lo=I3, lo_open=False).claim == \
        Claim("sup_lower", R(E), R(s), R(I3), "oo", False, True, other=R(I1))
    # the identity on exactly (0, 1/2] is enough; (0, 1/2) and (0, 1/4] are not
    assert L(ident(hi=half, hi_open=False), expr=E, var=s, width=half, bound=I1, lo=I0, lo_open=True).claim == low.claim
    msg = "the identity must hold on (0, w]"
    assert why(L, ident(hi=half), expr=E, var=s, width=half, bound=I1, lo=I0, lo_open=True) == msg
    assert why(L, ident(hi=Q(1, 4), hi_open=False), expr=E, var=s, width=half, bound=I1, lo=I0, lo_open=True) == msg
    assert why(L, ident(lo=Q(1, 10)), expr=E, var=s, width=half, bound=I1, lo=I0, lo_open=True) == msg
    assert why(L, idt, expr=E, var=s, width=half, bound=Q(101, 100), lo=I0, lo_open=True) == \
        "E_t(0) is not exactly 101/100"
    assert why(L, idt, expr=2 * E, var=s, width=half, bound=I2, lo=I0, lo_open=True) == \
        "the identity must read E_t(t) = E(1/t)"
    assert why(L, sturm(t, t, 0, 1, lo_open=True), expr=E, var=s, width=half, bound=I1, lo=I0, lo_open=True) == \
        "premise must be an identity"
    assert why(L, idt, expr=Et, var=t, width=half, bound=I1, lo=I0, lo_open=True) == \
        "the tail variable must differ from the variable"
    for w in (I0, oo, -I1):
        assert why(L, idt, expr=E, var=s, width=w, bound=I1, lo=I0, lo_open=True) == "finite c and w > 0"
    for b in (oo, -oo):
        assert why(L, idt, expr=E, var=s, width=half, bound=b, lo=I0, lo_open=True) == f"E_t(0) is not exactly {b}"
    # E = s: E(1/t) = 1/t is not defined at t = 0
    i2 = ident(lhs=1 / t, rhs=1 / t)
    assert why(L, i2, expr=s, var=s, width=half, bound=I1, lo=I0, lo_open=True) == \
        "1/t not defined on [0, 1/2]: division by an interval that may contain 0"
    # E = 1 + 1/(s - 1): E(1/t) = 1/(1 - t) -> 1; E is undefined at s = 1, but defined for s > 1/w = 2
    E1 = 1 + 1 / (s - 1)
    i3 = ident(lhs=1 / (1 - t), rhs=E1.subs(s, 1 / t))
    assert L(i3, expr=E1, var=s, width=half, bound=I1, lo=I0, lo_open=True).claim.other == R(I1)
    # E = 1 + (s^2 - 25)/((s - 5) s^2): E(1/t) = 1 + t + 5t^2 where both are defined, but E is undefined at s = 5 > 2
    E5 = 1 + (s ** 2 - 25) / ((s - 5) * s ** 2)
    i5 = ident(lhs=1 + t + 5 * t ** 2, rhs=E5.subs(s, 1 / t))
    assert why(L, i5, expr=E5, var=s, width=half, bound=I1, lo=I0, lo_open=True) == \
        f"{E5} not shown defined on (2, oo)"
    # lo must be >= 0: for s > 0 the interval check says so, for a real x the rule does
    assert why(L, idt, expr=E, var=s, width=half, bound=I1, lo=-I1, lo_open=True) == \
        "s > 0 assumed: interval must lie in (0, oo)"
    Ex = x / sp.sqrt(x ** 2 + 1)
    ix = ident(rhs=Ex.subs(x, 1 / t))
    assert L(ix, expr=Ex, var=x, width=half, bound=I1, lo=I0, lo_open=False).claim.lo == R(I0)
    assert why(L, ix, expr=Ex, var=x, width=half, bound=I1, lo=-I1, lo_open=False) == "lo >= 0"


# ---------------------------------------------------------- the parser

def test_parse_accepts_srepr_and_refuses_the_rest():
    from uwmr_symbolic.kernel.parse import ParseError, parse
    assert parse("Add(Integer(1), Integer(2))") == 3
    assert parse("Integer(-3)") == -3 and parse(" Integer( -3 ) ") == -3     # spaces are skipped
    assert parse("-oo") == -oo and parse("-Integer(3)") == -3                 # a unary minus (srepr(-oo))
    assert parse("Symbol('x', real=True)") == x
    assert parse("Rational(1, 3)") == Q(1, 3)
    assert parse("Max(Integer(1), Integer(2))", design=True) == 2
    assert parse("Piecewise(ExprCondPair(Integer(1), true))", design=True) == 1
    cases = {
        "Max(Integer(1), Integer(2))": "name not allowed: Max",            # design names only with design=True
        "getattr(Integer(1), 'p')": "name not allowed: getattr",
        "Integer(x)": "name not allowed: x",
        "Integer(1.5)": "character not allowed: '.'",
        "Integer(True)": "name not allowed: True",
        "Integer(None)": "name not allowed: None",
        "Integer('x')": "Integer: invalid literal for int() with base 10: 'x'",
        "Symbol()": "Symbol: Symbol.__new__() missing 1 required positional argument: 'name'",
        "Symbol('x', integer=True)": "keyword not allowed: integer",
        "Symbol('x', real=False)": "keyword not allowed: real",
        "Symbol('x', real=1)": "keyword not allowed: real",
        "Symbol('x', real='True')": "keyword not allowed: real",
        "Symbol('x', **{'real': True})": "character not allowed: '*'",
        "Symbol('x', real=Integer(1))": "keyword not allowed: real",
        "Symbol(real=True, 'x')": "a positional argument after a keyword",
        "Symbol('x\\n')": "character not allowed: \"'\"",
        "--oo": "expected 'name', found '-'",
        "-Integer": "a minus sign before what is not an expression",
        "-true": "a minus sign before what is not an expression",
        "+Integer(1)": "character not allowed: '+'",
        "~Integer(1)": "character not allowed: '~'",
        "Integer(1).p": "character not allowed: '.'",
        "Integer(1)(2)": "expected 'end', found '('",
        "[Integer(1)]": "character not allowed: '['",
        "Integer(1) + Integer(2)": "character not allowed: '+'",
        "Integer(1) Integer(2)": "expected 'end', found 'Integer'",
        "Integer(1": "expected ',', found the end",
        "Integer(1,": "expected 'name', found the end",
        "Integer(\u0661)": "character not allowed: '\u0661'",       # an Arabic-Indic digit: ASCII only
        "Add(" * 2000 + ")" * 2000: "nested too deeply",
    }
    for text, msg in cases.items():
        with pytest.raises(ParseError) as err:
            parse(text)
        assert str(err.value) == msg, text
    assert parse("Integer") is sp.Integer         # a bare name is the constructor itself: no rule takes it
    # a quoted "(", ")" or "=" is a name, never punctuation
    assert parse("Symbol(')')") == sp.Symbol(")") and parse("Symbol('(')") == sp.Symbol("(")
    for text, msg in (("pi'('", "expected 'end', found '('"), ("Tuple(Integer(1)')')", "expected ',', found ')'"),
                      ("Symbol(x'=')", "name not allowed: x")):
        with pytest.raises(ParseError) as err:
            parse(text)
        assert str(err.value) == msg, text
    with pytest.raises(ParseError, match="^integer not allowed: Exceeds the limit"):
        parse("Integer(" + "9" * 5000 + ")")                # more digits than Python converts
    for bad in (12, None, "Integer(1)" + " " * 200_000):
        with pytest.raises(ParseError) as err:
            parse(bad)
        assert str(err.value) == "expected an srepr string"
    assert parse("Integer(1)" + " " * (200_000 - 10)) == 1                 # exactly 200,000 characters
    with pytest.raises(ParseError, match="^expected an srepr string$"):
        parse("Integer(1)" + " " * (200_001 - 10))                            # one more
    # names outside the scope are not builtins either
    with pytest.raises(ParseError, match="^name not allowed: __import__$"):
        parse("__import__('os')")


# ---------------------------------------------------------- the evaluator

def lo_hi(box):
    return float(box.lo.lower()), float(box.hi.upper())


def test_evaluator_enclosures_are_tight():
    # hand-computed ranges; the enclosure must contain them and be within 1e-9 of them
    cases = [
        (x + 1, -1, 2, (0, 3)), (-x, -1, 2, (-2, 1)), (2 * x - 3 * x ** 2, 0, 1, (-3, 2)),
        # a product is enclosed by its corner products: x in [-1, 2], x + 1 in [0, 3] -> [-3, 6]
        (x * (x + 1), -1, 2, (-3, 6)), (x * (x - 3), 1, 2, (-4, -1)), ((x - 3) * (x - 4), 1, 2, (2, 6)),
        # one factor >= 0, or both (the shortcut [lo1 lo2, hi1 hi2] only for the latter)
        ((x - 1) * (2 - x), 0, 2, (-2, 2)), ((x + 1) * (x - 1), 0, 2, (-3, 3)), ((x + 1) * (x + 2), 0, 1, (2, 6)),
        ((x - 3) * (x + 1), 1, 2, (-6, -2)),
        (x ** 2, -1, 2, (0, 4)), (x ** 2, -3, -1, (1, 9)), (x ** 2, 1, 3, (1, 9)), (x ** 3, -1, 2, (-1, 8)),
        (x ** -1, 1, 2, (0.5, 1)), (x ** -1, -2, -1, (-1, -0.5)), (x ** -2, 1, 2, (0.25, 1)),
        (x ** -2, -2, -1, (0.25, 1)), (x ** -3, -2, -1, (-1, -0.125)),
        (sp.sqrt(x), 0, 4, (0, 2)), (sp.sqrt(x), 1, 4, (1, 2)), (x ** Q(3, 2), 0, 4, (0, 8)),
        (x ** Q(-1, 2), 1, 4, (0.5, 1)), (x ** Q(-3, 2), 1, 4, (0.125, 1)),
        (sp.Abs(x), -3, 2, (0, 3)), (sp.Abs(x), -3, -2, (2, 3)), (sp.Abs(x), 1, 2, (1, 2)),
        (sp.cosh(x), -1, 2, (1, float(sp.cosh(2)))), (sp.cosh(x), -2, -1, (float(sp.cosh(1)), float(sp.cosh(2)))),
        (sp.exp(x), 0, 1, (1, float(sp.E))), (sp.log(x), 1, sp.E, (0, 1)), (sp.E ** x, 0, 1, (1, float(sp.E))),
        (sp.tanh(x), -1, 1, (-float(sp.tanh(1)), float(sp.tanh(1)))),
        (sp.atan(x), 0, 1, (0, float(sp.pi / 4))), (sp.asinh(x), 0, 1, (0, float(sp.asinh(1)))),
        (sp.sinh(x), 0, 1, (0, float(sp.sinh(1)))), (sp.erf(x), 0, 1, (0, float(sp.erf(1)))),
        (sp.sin(x), 0, 0, (0, 0)), (sp.cos(x), 0, 0, (1, 1)), (sp.pi * x, 1, 1, (float(sp.pi), float(sp.pi))),
        (x / 3, 1, 1, (1 / 3, 1 / 3)), (sp.Integer(7), 0, 1, (7, 7)),
    ]
    for e, a, b, (ra, rb) in cases:
        lo, hi = lo_hi(evaluate(e, x, sp.sympify(a), sp.sympify(b)))
        assert lo <= ra + 1e-12 and rb - 1e-12 <= hi, (e, lo, hi)
        assert ra - 1e-9 <= lo and hi <= rb + 1e-9, (e, lo, hi)
    # sin and cos take the hull: sin on [0, 1] is within [sin 0, sin 1] = [0, 0.8415] (+ rounding)
    lo, hi = lo_hi(evaluate(sp.sin(x), x, I0, I1))
    assert -1e-6 <= lo <= 0 and 0.84 <= hi <= 1
    lo, hi = lo_hi(evaluate(sp.cos(x), x, I0, I1))
    assert 0 <= lo <= 0.55 and 1 <= hi <= 1 + 1e-9
    assert lo_hi(evaluate(sp.pi)) == pytest.approx((3.141592653589793, 3.141592653589793))
    assert lo_hi(evaluate(sp.E)) == pytest.approx((2.718281828459045, 2.718281828459045))
    assert lo_hi(evaluate(Q(-7, 2))) == (-3.5, -3.5)


def test_evaluator_comparisons_and_precision():
    box = evaluate(x - 1, x, I1, I2)
    assert box.nonnegative() and not box.positive() and not box.negative() and not box.nonpositive()
    box = evaluate(x - 2, x, I1, I2)
    assert box.nonpositive() and not box.negative() and not box.nonnegative()
    assert evaluate(x, x, I1, I2).positive() and evaluate(-x, x, I1, I2).negative()
    assert repr(evaluate(sp.Integer(2))) == "Iv(2.00000000000000, 2.00000000000000)"
    # bits: 1/3 at 256 bits is far tighter than at 53
    fine, coarse = evaluate(Q(1, 3), bits=256), evaluate(Q(1, 3), bits=53)
    assert float(fine.lo.rad()) < 2.0 ** -250 and float(coarse.lo.rad()) > 2.0 ** -120
    import flint
    before = flint.ctx.prec
    evaluate(Q(1, 3), bits=300)
    assert flint.ctx.prec == before                     # precision restored
    with pytest.raises(Undefined):
        evaluate(sp.log(x), x, I0, I1, bits=300)
    assert flint.ctx.prec == before                     # also after an error


def test_evaluator_refusals_have_reasons():
    cases = [
        (sp.sqrt(x), -1, 1, "x**(1/2) needs x >= 0"), (x ** Q(-1, 2), 0, 1, "x**(-1/2) needs x > 0"),
        (1 / x, -1, 1, "division by an interval that may contain 0"), (1 / x, 0, 1, "division by an interval that may contain 0"),
        (x ** -2, -1, 0, "division by an interval that may contain 0"),
        (sp.log(x), 0, 1, "log of an interval that may contain values <= 0"),
        (x ** x, 1, 2, "only rational exponents: x**x"), (2 ** x, 1, 2, "only rational exponents: 2**x"),
        (sp.gamma(x), 1, 2, "unsupported function gamma"), (sp.Max(x, 1), 0, 2, "unsupported: Max"),
        (sp.I * x, 0, 1, "unsupported: ImaginaryUnit"),
        (x + sp.Float(0.5), 0, 1, "not an exact real constant: 0.500000000000000"),
        (x + sp.oo, 0, 1, "not an exact real constant: oo"),
        (x + sp.Symbol("y"), 0, 1, "free symbol y"),
    ]
    for e, a, b, msg in cases:
        with pytest.raises(Undefined) as err:
            evaluate(e, x, sp.sympify(a), sp.sympify(b))
        assert str(err.value) == msg, e
    with pytest.raises(Undefined, match="^unsupported constant TribonacciConstant$"):
        evaluate(sp.TribonacciConstant)


# ---------------------------------------------------------- certificates and the command line

def small_proof():
    """x - 1 > 0 on (1, 2] (Sturm), tanh(x - 1) > 0 there, and sqrt(2) - 1 > 0: two conclusions
    sharing nothing, the first with one premise."""
    base = sturm(x - 1, x, 1, 2, lo_open=True)
    return [K.sign_through_increasing(base, expr=sp.tanh(x - 1)), K.value_sign(value=sp.sqrt(2) - 1)], base


def test_to_certificate_lists_premises_once_and_first():
    from uwmr_symbolic.certify import to_certificate
    from uwmr_symbolic.kernel import check_certificate
    (th, vs), base = small_proof()
    both = K.sign_of_product(base, sturm(x + 1, x, 1, 2, lo_open=True), expr=(x - 1) * (x + 1))
    cert = to_certificate([th, both, vs])
    assert [n["rule"] for n in cert["theorems"]] == ["sign_by_sturm", "sign_through_increasing", "sign_by_sturm",
                                                    "sign_of_product", "value_sign"]
    assert [n["id"] for n in cert["theorems"]] == [0, 1, 2, 3, 4]
    assert [n["premises"] for n in cert["theorems"]] == [[], [0], [], [0, 2], []]   # base listed once
    assert cert["conclusions"] == [1, 3, 4]
    assert cert["assumptions"] == ["arb", "flint-polys", "sympy-core", "sympy-polys"]
    assert (cert["format"], cert["version"]) == ("uwmr-kernel-certificate", 3)
    assert cert["theorems"][1]["claim"] == th.claim.to_json()
    assert [t.claim for t in check_certificate(cert)] == [th.claim, both.claim, vs.claim]


def test_certificate_checker_messages():
    import copy

    from uwmr_symbolic.certify import to_certificate
    from uwmr_symbolic.kernel import CertificateError, check_certificate
    (th, vs), _ = small_proof()
    good = to_certificate([th, vs])

    def refused(edit):
        cert = copy.deepcopy(good)
        out = edit(cert)
        with pytest.raises(CertificateError) as err:
            check_certificate(cert if out is None else out)
        return str(err.value)
    assert refused(lambda c: [c]) == "a certificate is a JSON object"
    assert refused(lambda c: "[" * 100_000 + "]" * 100_000) == "not JSON: nested too deeply"
    assert refused(lambda c: "{").startswith("not JSON: Expecting property name enclosed in double quotes")
    assert refused(lambda c: c.update(format="other")) == "not a uwmr-kernel-certificate (format = 'other')"
    assert refused(lambda c: c.__delitem__("format")) == "not a uwmr-kernel-certificate (format = None)"
    assert refused(lambda c: c.update(version=2)) == (
        "certificate format version 2 is not supported: this kernel reads version 3 only; re-create the certificate")
    assert refused(lambda c: c.update(version="3")).startswith("certificate format version '3' is not supported")
    for key in ("theorems", "conclusions", "assumptions"):
        assert refused(lambda c: c.update({key: {}})) == f"'{key}' must be a list"
    shape = "theorem 0: needs id = 0, rule, premises, data, claim"
    for edit in (lambda c: c["theorems"][0].update(id=1), lambda c: c["theorems"][0].update(rule=3),
                 lambda c: c["theorems"][0].update(premises={}), lambda c: c["theorems"][0].update(data=[]),
                 lambda c: c["theorems"][0].update(claim=[]), lambda c: c["theorems"].__setitem__(0, [])):
        assert refused(edit) == shape
    assert refused(lambda c: c["theorems"][1].update(id=0)) == "theorem 1: needs id = 1, rule, premises, data, claim"
    assert refused(lambda c: c["theorems"][0].update(rule="trust_me")) == "theorem 0: unknown rule 'trust_me'"
    early = "theorem 1: premises must be earlier theorems"
    for prem in ([1], [-1], [True], ["0"], [0.0]):
        assert refused(lambda c: c["theorems"][1].update(premises=prem)) == early, prem
    assert refused(lambda c: c["theorems"][0]["data"].update(want=-1)) == (
        "theorem 0 (sign_by_sturm) does not check: p(3/2) has the wrong sign")
    assert refused(lambda c: c["theorems"][0]["data"].update(frob=1)).startswith(
        "theorem 0 (sign_by_sturm) does not check: ")
    assert refused(lambda c: c["theorems"][0]["claim"].update(frob=1)).startswith("theorem 0: malformed claim: ")
    claimed = refused(lambda c: c["theorems"][0]["claim"].update(strict=False))
    assert claimed.startswith("theorem 0 (sign_by_sturm): the rule proves Claim(") and \
        "the certificate claims Claim(" in claimed
    concl = "conclusions must name theorems of the certificate"
    for bad in ([], [3], [-1], ["0"]):
        assert refused(lambda c: c.update(conclusions=bad)) == concl, bad
    assert refused(lambda c: c.update(assumptions=["arb", "sympy-core"])) == (
        "the certificate rests on ['arb', 'flint-polys', 'sympy-core', 'sympy-polys'], it lists ['arb', 'sympy-core']")
    assert refused(lambda c: "{") .startswith("not JSON: ")
    assert refused(lambda c: c.update(assumptions=[1, "arb"])) == (      # red team 16a: sorted() raised TypeError
        "the certificate rests on ['arb', 'flint-polys', 'sympy-core', 'sympy-polys'], it lists [1, 'arb']")
    # the listed assumptions may come in any order; only the last conclusion may be named
    ok = copy.deepcopy(good)
    ok["assumptions"] = list(reversed(ok["assumptions"]))
    assert [t.claim for t in check_certificate(ok)] == [th.claim, vs.claim]
    ok["conclusions"], ok["assumptions"] = [2], ["arb", "sympy-core"]
    assert [t.claim for t in check_certificate(ok)] == [vs.claim]
    import json
    assert [t.claim for t in check_certificate(json.dumps(good).encode())] == [th.claim, vs.claim]


def test_command_line(tmp_path, capsys):
    import json

    from uwmr_symbolic.certify import to_certificate
    from uwmr_symbolic.kernel.__main__ import main
    (th, vs), _ = small_proof()
    up = K.sup_upper_by_sign(sturm(1 - x, x, 0, 1, strict=False), expr=x, bound=I1)
    ho = sturm(x + 1, x, 0, 1, hi_open=True)
    # a limit at oo and a plane identity have no interval (red team 16a: the command stopped on their "")
    half = K.sign_by_sturm(expr=sp.Rational(1, 2), var=x, lo=sp.Integer(1), hi=sp.oo, lo_open=False, hi_open=True,
                           want=1, strict=False)
    lim = K.limit_of_bounded(K.diverges_by_growth(half, expr=x, var=x, R=sp.Integer(1), rate="linear",
                                                  k=sp.Rational(1, 2)), expr=sp.tanh(x))
    e1, e2 = sp.symbols("e1 e2", real=True)
    plane = K.identity_plane(lhs=(e1 + e2) ** 2, rhs=e1 ** 2 + 2 * e1 * e2 + e2 ** 2, x=e1, y=e2)
    good = tmp_path / "good.json"
    good.write_text(json.dumps(to_certificate([th, vs, up, ho, lim, plane])))
    assert main([str(good)]) == 0
    assert capsys.readouterr().out.splitlines() == [
        f"{good}: checked sign tanh(x - 1) want=1 strict=True for x in (1, 2]",
        f"{good}: checked value_sign -1 + sqrt(2) want=1 strict=True",
        f"{good}: checked sup_upper x want=0 strict=False other=1 for x in [0, 1]",
        f"{good}: checked sign x + 1 want=1 strict=True for x in [0, 1)",
        f"{good}: checked limit_oo tanh(x) want=0 strict=False other=1 as x -> oo",
        f"{good}: checked identity_plane (e1 + e2)**2 want=0 strict=False other=e1**2 + 2*e1*e2 + e2**2 "
        f"for all (e1, e2)",
        f"{good}: rests on arb, flint-polys, sympy-core, sympy-diff, sympy-polys"]      # (diverges_by_growth)
    bad = tmp_path / "bad.json"
    bad.write_text("{")
    missing = tmp_path / "missing.json"
    assert main([str(bad), str(good), str(missing)]) == 1
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith(f"{bad}: REJECTED: Expecting property name") and len(out) == 9
    assert out[8].startswith(f"{missing}: REJECTED: [Errno 2]")
    wrong = tmp_path / "wrong.json"
    cert = to_certificate([vs])
    cert["version"] = 7
    wrong.write_text(json.dumps(cert))
    assert main([str(wrong)]) == 1
    assert capsys.readouterr().out == (f"{wrong}: REJECTED: certificate format version 7 is not supported: "
                                       "this kernel reads version 3 only; re-create the certificate\n")
    assert main([]) == 2
    assert capsys.readouterr().out.startswith("python -m uwmr_symbolic.kernel CERT.json ...: re-check certificates.")
    import sys
    old = sys.argv
    sys.argv = ["kernel", str(good)]
    try:
        assert main() == 0
    finally:
        sys.argv = old
    assert capsys.readouterr().out.count("checked") == 6



# ---------------------------------------------------------- theorems, rule application, comparisons

# sqrt(2) cut after 60 decimals: 0 < sqrt(2) - P < 1e-60 (the next digits are 7379...), which
# 256-bit balls (radius ~1e-77) resolve and 128-bit ones (~1e-38) do not
P = sp.Rational(1414213562373095048801688724209698078569671875376948073176679, 10 ** 60)


def test_theorem_records_its_rule_premises_data_and_assumptions():
    import dataclasses
    import json

    from uwmr_symbolic.kernel import Theorem
    a = sturm(x + 1, x, 0, 1)
    b = K.sign_by_cover(expr=x + 2, var=x, cuts=[0, Q(1, 2), 1], want=1)
    thm = K.sign_of_product(a, b, expr=(x + 1) * (x + 2))
    assert thm.rule == "sign_of_product" and thm.premises == (a, b)
    assert thm.assumptions == {"arb", "sympy-core", "sympy-polys", "flint-polys"}        # the rule's, a's and b's
    assert json.loads(thm.data) == {"expr": {"$": R((x + 1) * (x + 2))}}
    # the data as JSON with sorted keys, SymPy objects as srepr, ints as ints; strict was not given
    assert b.data == json.dumps({"cuts": [0, {"$": "Rational(1, 2)"}, 1],
                                 "expr": {"$": R(x + 2)}, "var": {"$": R(x)}, "want": 1}, sort_keys=True)
    assert thm._token is None
    with pytest.raises(KernelError, match="^theorems are made only by kernel rules$"):
        Theorem(thm.claim, "made up", (), "{}", frozenset())
    with pytest.raises(KernelError, match="^theorems are made only by kernel rules$"):
        dataclasses.replace(thm, assumptions=frozenset())
    assert why(K.sign_of_product, a, thm.claim, expr=(x + 1) * (x + 2)) == "sign_of_product: a premise is not a theorem"
    # None, booleans, strings and nested lists are rule data too
    assert why(K.sign_by_cover, expr=x, var=x, cuts=[[0], [1]], want=1) == "expected a SymPy object or an int, got list"
    assert why(K.sign_by_cover, expr=x, var=x, cuts=None, want=1) == "a cover needs a list of at least two cut points"
    assert why(K.sign_by_cover, expr=x, var=x, cuts=I2, want=1) == "a cover needs a list of at least two cut points"
    assert why(K.sign_by_cover, expr=x, var=x, cuts=[0, 1], want={"$": "Integer(1)"}) == \
        "rule data must be SymPy objects, numbers, strings or lists: {'$': 'Integer(1)'}"


def test_comparisons_of_ends():
    ident = K.identity
    kw = dict(lhs=I1, rhs=I1, var=x, lo_open=True, hi_open=True)
    assert why(ident, lo=oo, hi=I2 * 5 // 2, **kw) == "empty interval (oo, 5)"
    assert why(ident, lo=I1, hi=-oo, **kw) == "empty interval (1, -oo)"
    assert why(ident, lo=oo, hi=oo, **kw) == "empty interval (oo, oo)"
    assert why(ident, lo=-oo, hi=-oo, **kw) == "empty interval (-oo, -oo)"
    assert ident(lo=-oo, hi=oo, **kw).claim.hi == "oo"
    # sqrt(2) against a rational 1e-60 below it: decided only with enough bits
    p = P
    assert K.sign_by_cover(expr=x, var=x, cuts=[1, p, sp.sqrt(2)], want=1).claim.hi == R(sp.sqrt(2))
    assert why(K.sign_by_cover, expr=x, var=x, cuts=[1, sp.sqrt(2), p], want=1) == f"cut points not increasing: sqrt(2), {p}"
    # a constant that is exactly 1 but not literally: neither above nor below 1
    one = (1 + sp.sqrt(2)) ** 2 - 2 * sp.sqrt(2) - 2
    assert why(K.sign_by_cover, expr=x, var=x, cuts=[1, one], want=1) == f"cut points not increasing: 1, {one}"
    assert why(K.sign_by_cover, expr=x, var=x, cuts=[one, 1], want=1) == f"cut points not increasing: {one}, 1"


def test_weaken_keeps_the_closed_end_0_of_a_positive_variable():
    cover = K.sign_by_cover(expr=s + 1, var=s, cuts=[0, 1], want=1)
    assert K.weaken(cover, lo=I0, hi=Q(1, 2), lo_open=False, hi_open=False, strict=False).claim == \
        sign(s + 1, s, 0, Q(1, 2), strict=False)




def test_rules_that_need_256_bits():
    assert sp.Rational(7, 10 ** 61) < sp.sqrt(2) - P < sp.Rational(1, 10 ** 60)
    assert K.value_sign(value=sp.sqrt(2) - P).claim.want == 1
    assert K.value_sign(value=P - sp.sqrt(2)).claim.want == -1
    # sup over [0, 2] of x is >= P, shown at the point sqrt(2)
    assert K.sup_lower_by_point(expr=x, var=x, point=sp.sqrt(2), bound=P, lo=I0, hi=I2, lo_open=False,
                                hi_open=False).claim.other == R(P)
    # E = s + sqrt(2) - P - 1 has E(1) = sqrt(2) - P > 0 and E' = 1
    E = s + sp.sqrt(2) - P - 1
    d = sturm(I1, s, 1, oo, hi_open=True)
    assert K.sign_by_monotone(d, expr=E, var=s, R=I1).claim == sign(E, s, 1, oo, hi_open=True)


def test_parse_design_scope_reaches_every_argument():
    from uwmr_symbolic.kernel.parse import ParseError, parse
    assert parse("Mul(Integer(-1), Max(Integer(1), Integer(2)))", design=True) == -2
    assert parse("-Max(Integer(1), Integer(2))", design=True) == -2
    assert parse("Add(Max(Integer(1), Integer(2)), Integer(1))", design=True) == 3
    assert parse("Max(Integer(1), Min(Integer(2), Integer(3)))", design=True) == 2
    with pytest.raises(ParseError, match="^name not allowed: Max$"):
        parse("Add(Integer(1), Max(Integer(1), Integer(2)))")          # the scope holds in every argument
    # blanks around tokens are skipped, also at the end of a long text (no backtracking: linear time)
    assert parse("Integer(1)" + " " * 199_990) == 1 and parse(" Add( Integer(1) ,Integer(2) ) ") == 3


def test_evaluator_refuses_nan():
    with pytest.raises(Undefined, match="^not an exact real constant: nan$"):
        evaluate(sp.nan)


def test_boundaries_seen_by_the_mutants():
    # sign_by_monotone with R = 1/2 < 1: E = 1 - 1/(4s), E(1/2) = 1/2 > 0, E' = s**-2/4 > 0
    E = 1 - 1 / (4 * s)
    dE = K.sign_of_product(sturm(s, s, Q(1, 2), oo, hi_open=True), expr=sp.diff(E, s))
    assert K.sign_by_monotone(dE, expr=E, var=s, R=Q(1, 2)).claim == sign(E, s, Q(1, 2), oo, hi_open=True)
    # the closed end 0 of a positive variable: continuity and a sup at the point 0 only evaluate
    assert K.continuous_at_end(expr=s + 1, var=s, c=I0, width=I1).claim == \
        Claim("limit", R(s + 1), R(s), R(I0), R(I1), other=R(I1))
    assert K.sup_lower_by_point(expr=s, var=s, point=I0, bound=I0, lo=I0, hi=I1, lo_open=False,
                                hi_open=False).claim == Claim("sup_lower", R(s), R(s), R(I0), R(I1), other=R(I0))
    # an open right end is kept: sup over (0, oo) of s/(s**2 + 1) >= 1/2, at s = 1
    E2 = s / (s ** 2 + 1)
    assert K.sup_lower_by_point(expr=E2, var=s, point=I1, bound=Q(1, 2), lo=I0, hi=oo, lo_open=True,
                                hi_open=True).claim == Claim("sup_lower", R(E2), R(s), R(I0), "oo", True, True,
                                                             other=R(Q(1, 2)))
    # -oo is no finite constant
    assert why(K.value_sign, value=-oo) == "a finite constant"
    # lim E_t(0) = 1 exactly; 1 + 1e-90 is inside Arb's 256-bit ball of E_t(0) - c but is not the limit
    Et = 1 / sp.sqrt(t ** 2 + 1)
    idt = K.identity(lhs=Et, rhs=(s / sp.sqrt(s ** 2 + 1)).subs(s, 1 / t), var=t, lo=I0, hi=oo, lo_open=True,
                     hi_open=True)
    c = 1 + Q(1, 10 ** 90)
    assert why(K.sup_lower_by_limit, idt, expr=s / sp.sqrt(s ** 2 + 1), var=s, width=Q(1, 2), bound=c, lo=I0,
               lo_open=True) == f"E_t(0) is not exactly {c}"


# ---------------------------------------------------------- bounded functions and limits at oo

def test_sign_below_sup_claims_and_messages():
    B = K.sign_below_sup
    pos = sturm(s, s, 0, 2, lo_open=True)                  # (0, 2]
    th = B(pos, expr=2 - 2 * sp.tanh(s), bounded=sp.tanh(s))
    assert th.claim == sign(2 - 2 * sp.tanh(s), s, 0, 2, True, False) and th.assumptions == ARB | {"sympy-polys", "flint-polys"}
    closed = B(sturm(s, s, 1, 2), expr=sp.pi / 2 - sp.atan(s), bounded=sp.atan(s))
    assert closed.claim == sign(sp.pi / 2 - sp.atan(s), s, 1, 2)
    msg = "bounded must be G(Y) and the premise about Y"
    assert why(B, pos, expr=1 - sp.sinh(s), bounded=sp.sinh(s)) == msg
    assert why(B, pos, expr=1 - sp.tanh(2 * s), bounded=sp.tanh(2 * s)) == msg
    assert why(B, pos, expr=1 - s * sp.tanh(s), bounded=sp.tanh(s)) == f"{1 - s * sp.tanh(s)} is not a + m tanh(s)"
    assert why(B, pos, expr=s - sp.tanh(s), bounded=sp.tanh(s)) == f"{s - sp.tanh(s)} is not a + m tanh(s)"
    assert why(B, pos, expr=1 - sp.tanh(s) ** 2, bounded=sp.tanh(s)) == f"{1 - sp.tanh(s) ** 2} is not a + m tanh(s)"
    needs = "needs m != 0 and w a - |m| sup G >= 0"
    for e in (sp.Integer(0), sp.Integer(1)):                       # m = 0: "0 > 0" must not follow
        assert why(B, pos, expr=e, bounded=sp.tanh(s)) == needs
    for e in (Q(99, 100) + sp.tanh(s), Q(99, 100) - sp.tanh(s), Q(3, 2) - sp.atan(s), Q(3, 2) + sp.atan(s),
              -1 - sp.tanh(s)):
        assert why(B, pos, expr=e, bounded=e.atoms(sp.tanh, sp.atan).pop()) == needs, e
    # an open right end stays open
    assert B(sturm(s, s, 0, 2, lo_open=True, hi_open=True), expr=1 - sp.tanh(s), bounded=sp.tanh(s)).claim == \
        sign(1 - sp.tanh(s), s, 0, 2, True, True)
    # m > 0: tanh > -1 and atan > -pi/2 everywhere (odd, sup never attained)
    assert B(pos, expr=1 + sp.tanh(s), bounded=sp.tanh(s)).claim == sign(1 + sp.tanh(s), s, 0, 2, True, False)
    assert B(pos, expr=sp.pi + 2 * sp.atan(s), bounded=sp.atan(s)).claim.strict
    # want = -1: a + m G(Y) < 0 where a + |m| sup G <= 0 (tanh(s) - 1 < 0; sin(s) - 1 <= 0 only)
    assert B(pos, expr=sp.tanh(s) - 1, bounded=sp.tanh(s), want=-1).claim == \
        sign(sp.tanh(s) - 1, s, 0, 2, True, False, want=-1)
    assert B(pos, expr=-4 - 2 * sp.atan(s), bounded=sp.atan(s), want=-1).claim.strict      # 4 > pi
    assert not B(pos, expr=sp.sin(s) - 1, bounded=sp.sin(s), want=-1).claim.strict
    for e in (sp.tanh(s) - Q(99, 100), 1 - sp.tanh(s), -Q(5, 2) - 2 * sp.atan(s)):    # 0.99 < 1; > 0; 5/2 < pi
        assert why(B, pos, expr=e, bounded=e.atoms(sp.tanh, sp.atan).pop(), want=-1) == needs, e
    assert why(B, pos, expr=sp.tanh(s) - 1, bounded=sp.tanh(s), want=2) == "want is +1 or -1"
    assert why(B, pos, expr=sp.tanh(s) - 1, bounded=sp.tanh(s), want=0) == "want is +1 or -1"


def test_sign_of_increasing_difference_claims_and_messages():
    D = K.sign_of_increasing_difference
    above = sturm(s - 1, s, 1, 3, lo_open=True, strict=False)          # s - 1 >= 0 on (1, 3]
    th = D(above, expr=sp.exp(s) - sp.E, inner=sp.exp(s), c=I1)
    assert th.claim == sign(sp.exp(s) - sp.E, s, 1, 3, True, False, strict=False)
    assert th.assumptions == {"arb", "sympy-core", "sympy-polys", "flint-polys"}       # the sign of k
    below = sturm(s - 3, s, 1, 3, hi_open=True, want=-1)
    assert D(below, expr=sp.atan(s) - sp.atan(3), inner=sp.atan(s), c=I3).claim == \
        sign(sp.atan(s) - sp.atan(3), s, 1, 3, False, True, want=-1)
    assert why(D, above, expr=sp.cos(s) - sp.cos(1), inner=sp.cos(s), c=I1) == "inner must be k G(Y), c finite"
    assert why(D, above, expr=sp.tanh(s) - 1, inner=sp.tanh(s), c=oo) == "inner must be k G(Y), c finite"
    assert why(D, above, expr=sp.Integer(0), inner=0 * sp.tanh(s), c=I1) == "inner must be k G(Y), c finite"
    zero = (1 + sp.sqrt(2)) ** 2 - 3 - 2 * sp.sqrt(2)                     # k = 0 in disguise: no sign
    assert why(D, above, expr=zero * sp.tanh(s) - zero * sp.tanh(1), inner=zero * sp.tanh(s), c=I1).startswith(
        "sign of ")
    k = sp.sqrt(2) - sp.sqrt(2) * (1 + sp.Integer(10) ** -80)          # k < 0, tiny: decided by 256-bit Arb
    neg = D(above, expr=k * sp.tanh(s) - k * sp.tanh(1), inner=k * sp.tanh(s), c=I1)
    assert (neg.claim.want, neg.claim.strict) == (-1, False)
    msg = lambda e: f"{e} is not k (G(Y) - G(c)) with the premise Y - c"      # noqa: E731
    assert why(D, above, expr=sp.tanh(s) - sp.tanh(2), inner=sp.tanh(s), c=I2) == msg(sp.tanh(s) - sp.tanh(2))
    assert why(D, above, expr=sp.tanh(s) - sp.tanh(2), inner=sp.tanh(s), c=I1) == msg(sp.tanh(s) - sp.tanh(2))
    assert why(D, above, expr=sp.tanh(2 * s) - sp.tanh(1), inner=sp.tanh(2 * s), c=I1) == \
        msg(sp.tanh(2 * s) - sp.tanh(1))


def _diverging_s():
    half = K.sign_by_sturm(expr=Q(1, 2), var=s, lo=I1, hi=oo, lo_open=False, hi_open=True, want=1, strict=False)
    return K.diverges_by_growth(half, expr=s, var=s, R=I1, rate="linear", k=Q(1, 2))


def test_diverges_through_increasing_messages():
    """s -> oo, so 1 + log(s) -> oo; not from a premise that is no divergence,
    not for -2 log(s) (m < 0) or 3 + sqrt(s - 1) (G of another Y), and not for
    log(s - 2), which s - 2 -> oo makes diverge but which is not defined for
    every s > 0."""
    D, div = K.diverges_through_increasing, _diverging_s()
    assert D(div, expr=1 + sp.log(s)).claim == Claim("diverges", R(1 + sp.log(s)), R(s), R(I1), "oo", False, True)
    sign_only = sturm(s, s, 1, 4)
    assert why(D, sign_only, expr=sp.log(s)) == "premise must be a diverges theorem"
    assert why(D, div, expr=-2 * sp.log(s)) == "-2*log(s) is not a + m G(Y), m > 0, with the premise about Y"
    assert why(D, div, expr=3 + sp.sqrt(s - 1)) == "sqrt(s - 1) + 3 is not a + m G(Y), m > 0, with the premise about Y"
    assert D(div, expr=2 * sp.log(s)).claim.expr == R(2 * sp.log(s))
    half = K.sign_by_sturm(expr=Q(1, 2), var=s, lo=sp.Integer(3), hi=oo, lo_open=False, hi_open=True, want=1,
                           strict=False)
    shifted = K.diverges_by_growth(half, expr=s - 2, var=s, R=sp.Integer(3), rate="linear", k=Q(1, 2))
    assert D(shifted, expr=sp.log(s - 2)).claim == Claim("diverges", R(sp.log(s - 2)), R(s), R(sp.Integer(3)), "oo", False, True)
    below = K.diverges_by_growth(half, expr=s - 4, var=s, R=sp.Integer(3), rate="linear", k=Q(1, 2))
    assert why(D, below, expr=sp.log(s - 4)) == "log(s - 4) not shown defined on (3, oo)"


def test_limit_rules_claims_and_messages():
    E = s / sp.sqrt(s ** 2 + 1)
    ident = K.identity(lhs=1 / sp.sqrt(t ** 2 + 1), rhs=E.subs(s, 1 / t), var=t, lo=I0, hi=oo,
                       lo_open=True, hi_open=True)
    lim = K.limit_at_infinity(ident, expr=E, var=s, width=Q(1, 2))
    assert lim.claim == Claim("limit_oo", R(E), R(s), "", "oo", other=R(I1))
    assert lim.assumptions == {"arb", "sympy-core", "sympy-polys"}
    div = _diverging_s()
    tanh = K.limit_of_bounded(div, expr=sp.tanh(s))
    assert tanh.claim == Claim("limit_oo", R(sp.tanh(s)), R(s), "", "oo", other=R(I1))
    assert K.limit_of_bounded(div, expr=sp.erf(s)).claim.other == R(I1)
    assert why(K.limit_of_bounded, lim, expr=sp.tanh(s)) == "premise must be a diverges theorem"
    assert why(K.limit_of_bounded, div, expr=sp.tanh(2 * s)) == "tanh(2*s) is not G(Y) with the premise about Y"
    assert why(K.limit_of_bounded, div, expr=sp.exp(s)) == "exp(s) is not G(Y) with the premise about Y"
    P = K.limit_of_product
    prod = P(tanh, lim, expr=3 * sp.tanh(s) * E)
    assert prod.claim == Claim("limit_oo", R(3 * sp.tanh(s) * E), R(s), "", "oo", other=R(sp.Integer(3)))
    assert P(tanh, lim, expr=sp.tanh(s) * E / 2).claim.other == R(Q(1, 2))
    E2 = 2 * s / sp.sqrt(s ** 2 + 1)                                       # -> 2
    lim2 = K.limit_at_infinity(K.identity(lhs=2 / sp.sqrt(t ** 2 + 1), rhs=E2.subs(s, 1 / t), var=t, lo=I0, hi=oo,
                                          lo_open=True, hi_open=True), expr=E2, var=s, width=Q(1, 2))
    assert P(tanh, lim2, expr=3 * sp.tanh(s) * E2).claim.other == R(sp.Integer(6))
    assert why(P, expr=E) == "premises must be limits at oo"
    assert why(P, tanh, ident, expr=E) == "premises must be limits at oo"
    other = K.limit_of_bounded(K.diverges_by_growth(
        K.sign_by_sturm(expr=Q(1, 2), var=t, lo=I1, hi=oo, lo_open=False, hi_open=True, want=1, strict=False),
        expr=t, var=t, R=I1, rate="linear", k=Q(1, 2)), expr=sp.tanh(t))
    assert why(P, tanh, other, expr=sp.tanh(s) * sp.tanh(t)) == "premises about one variable"
    assert why(P, tanh, expr=s * sp.tanh(s)) == f"{s * sp.tanh(s)} is not a constant times the premises' product"
    assert why(P, tanh, lim, expr=sp.sqrt(s) * sp.tanh(s) * E) == \
        f"{sp.sqrt(s) * sp.tanh(s) * E} is not a constant times the premises' product"
    F = K.sup_lower_from_limit
    low = F(prod, lo=I2, lo_open=False)
    assert low.claim == Claim("sup_lower", R(3 * sp.tanh(s) * E), R(s), R(I2), "oo", False, True,
                              other=R(sp.Integer(3)))
    assert F(prod, lo=I0, lo_open=True).claim.lo_open is True
    assert why(F, ident, lo=I0, lo_open=True) == "premise must be a limit at oo"
    assert why(F, prod, lo=oo, lo_open=True) == "finite lo"
    assert why(F, prod, lo=-I1, lo_open=True) == "s > 0 assumed: interval must lie in (0, oo)"


def test_continuous_on_positive_claim_and_message():
    e = s / sp.sqrt(1 + s ** 2)
    th = K.continuous_on_positive(expr=e, var=s)
    assert th.claim == Claim("continuous", R(e), R(s), R(I0), "oo", True, True) and th.assumptions == {"sympy-core"}
    assert why(K.continuous_on_positive, expr=1 / (s - 1), var=s) == f"{1 / (s - 1)} not shown defined for all s > 0"


def test_sign_of_sum_groups_messages():
    sq = sturm(x ** 2, x, -1, 1, strict=False)
    assert why(K.sign_of_sum, sturm(2 - x, x, -1, 1), sturm(x ** 2 - x + 1, x, -1, 1), expr=x ** 2 - x + 2,
               want=1) == "premises share a term"
    grouped = K.sign_of_sum(sturm(2 - x, x, -1, 1), sq, expr=x ** 2 - x + 2, want=1)
    assert grouped.claim == sign(x ** 2 - x + 2, x, -1, 1) and grouped.assumptions == ARB | {"sympy-polys", "flint-polys"}


def test_sign_below_sup_of_sin_and_cos_is_weak_at_the_maximum():
    """sin and cos reach their maximum 1 and minimum -1: 1 - sin(Y) >= 0 only
    weakly, 2 - cos(Y) > 0 strictly, 1/2 - sin(Y) and 1/2 + sin(Y) have no sign."""
    B = K.sign_below_sup
    pos = sturm(s, s, 0, 2, lo_open=True)
    weak = B(pos, expr=1 - sp.sin(s), bounded=sp.sin(s))
    assert weak.claim == sign(1 - sp.sin(s), s, 0, 2, True, False, strict=False)
    assert B(pos, expr=2 - 3 * sp.cos(s) / 2, bounded=sp.cos(s)).claim == sign(2 - 3 * sp.cos(s) / 2, s, 0, 2, True, False)
    needs = "needs m != 0 and w a - |m| sup G >= 0"
    assert why(B, pos, expr=Q(1, 2) - sp.sin(s), bounded=sp.sin(s)) == needs
    assert why(B, pos, expr=Q(1, 2) + sp.sin(s), bounded=sp.sin(s)) == needs
    # sin and cos reach -1 too: 1 + sin(Y) >= 0 only weakly, 2 + cos(Y) > 0
    assert B(pos, expr=1 + sp.sin(s), bounded=sp.sin(s)).claim == sign(1 + sp.sin(s), s, 0, 2, True, False, strict=False)
    assert B(pos, expr=2 + sp.cos(s), bounded=sp.cos(s)).claim.strict


def test_sign_of_sum_counts_the_premises_constants():
    """E = x^2 + 3 on [-1, 1] from x^2 + 1 > 0: E = (x^2 + 1) + 2, strict.
    From x^2 + 5 > 0 the rest would be 3 - 5 = -2: refused.  And
    sqrt(x^2 + 1) - 1 - sin(x) from sqrt(x^2 + 1) - 2 > 0 and 1 - sin(x) >= 0
    (their constants -2 and 1 make up E's -1 exactly: r = 0)."""
    three = K.sign_of_sum(sturm(x ** 2 + 1, x, -1, 1), expr=x ** 2 + 3, want=1)
    assert three.claim == sign(x ** 2 + 3, x, -1, 1)
    assert why(K.sign_of_sum, sturm(x ** 2 + 5, x, -1, 1), expr=x ** 2 + 3, want=1) == \
        "the constant terms -2 have the wrong sign"
    r = sp.sqrt(s ** 2 + 1)
    far = K.sign_by_cover(expr=r - 2, var=s, cuts=[I3, sp.Integer(4)], want=1)
    bound = K.sign_below_sup(sturm(s, s, 3, 4), expr=1 - sp.sin(s), bounded=sp.sin(s))
    th = K.sign_of_sum(far, bound, expr=r - 1 - sp.sin(s), want=1)
    assert th.claim == sign(r - 1 - sp.sin(s), s, 3, 4)


def test_sign_by_log_bound_claims_and_messages():
    """Upper bound (p > 0): 3 - log(s) on [1, 4], M = -1 <= 0, log s <= s - 1
    (p = 1): B = 4 - s >= 0 there (0 at s = 4), so 3 - log s >= 0, weak as B.
    Lower bound (p < 0): 1 + log(s), M = 1 >= 0, log s >= 1 - 1/s (p = -1):
    B = 2 - 1/s > 0, so 1 + log s > 0."""
    L = K.sign_by_log_bound
    E, T = 3 - sp.log(s), -sp.log(s)
    pos, neg = sturm(s, s, 1, 4), sturm(-I1, s, 1, 4, want=-1)
    B = sturm(4 - s, s, 1, 4, strict=False)
    th = L(B, neg, pos, expr=E, term=T, p=I1)
    assert th.claim == Claim("sign", R(E), R(s), R(I1), R(sp.Integer(4)), False, False, 1, False)
    assert th.rule == "sign_by_log_bound" and th.assumptions == {"sympy-core", "sympy-polys", "flint-polys"}
    low = K.sign_by_cover(expr=2 - 1 / s, var=s, cuts=[I1, sp.Integer(4)], want=1, strict=True)
    up = L(low, sturm(I1, s, 1, 4), pos, expr=1 + sp.log(s), term=sp.log(s), p=-I1)
    assert (up.claim.expr, up.claim.want, up.claim.strict) == (R(1 + sp.log(s)), 1, True)
    # open ends are kept: (1, 4), the tail's [R, oo) has an open right end
    opened = [sturm(4 - s, s, 1, 4, True, True), sturm(-I1, s, 1, 4, True, True, want=-1), sturm(s, s, 1, 4, True, True)]
    assert L(*opened, expr=E, term=T, p=I1).claim == Claim("sign", R(E), R(s), R(I1), R(sp.Integer(4)), True, True, 1, True)
    # the bound of the other side: log s <= s - 1 says nothing about 1 + log s from below
    assert why(L, low, sturm(I1, s, 1, 4), pos, expr=1 + sp.log(s), term=sp.log(s), p=I1) == \
        "premise must be the sign -1 of 1"
    for p in (I0, I2, -I2, sp.sqrt(2) / 2):
        assert why(L, B, neg, pos, expr=E, term=T, p=p) == "p is rational, 0 < |p| <= 1 (log), an integer 1 <= p <= 16 (exp)"
    assert why(L, B, neg, pos, expr=E, term=T, p=Q(1, 2)) == "premise must be about 5 - 2*sqrt(s)"
    assert why(L, B, pos, pos, expr=E, term=T, p=I1) == "premise must be the sign -1 of -1"
    assert why(L, B, neg, sturm(s + 1, s, 1, 4), expr=E, term=T, p=I1) == "premise must be s > 0"
    assert why(L, B, neg, sturm(s, s, 1, 4, strict=False), expr=E, term=T, p=I1) == "premise must be s > 0"
    assert why(L, B, neg, pos, expr=E, term=sp.log(s), p=I1) == f"log(s) is not a term M log(Y) or M exp(Y) of {E}"
    assert why(L, B, neg, pos, expr=-sp.log(s), term=T, p=I1) == "-log(s) is not a term M log(Y) or M exp(Y) of -log(s)"
    two = 3 - sp.log(s) * sp.log(s + 1)
    assert why(L, B, neg, pos, expr=two, term=two - 3, p=I1).endswith("is not a term M log(Y) or M exp(Y) of " + str(two))
    assert why(L, B, neg, sturm(s, s, 1, 2), expr=E, term=T, p=I1) == "premises on different intervals"


def test_sign_by_log_bound_reads_asinh_as_a_log():
    """asinh s = log W, W = s + sqrt(s^2 + 1): log W >= 1 - 1/W (p = -1)
    gives 1 + asinh s > 0 on [1, 4] from B = 2 - 1/W > 0 and W > 0; the
    premise "Y > 0" is about W, not s.  asinh s <= W - 1 (p = 1) is too
    loose for 2 - asinh s near s = 4 (B = 3 - s - sqrt(s^2 + 1) < 0 there),
    so no premise about B shows it."""
    L, a, W = K.sign_by_log_bound, sp.asinh(s), s + sp.sqrt(s ** 2 + 1)
    cover = lambda e: K.sign_by_cover(expr=e, var=s, cuts=[I1, sp.Integer(2), sp.Integer(4)], want=1, strict=True)
    th = L(cover(2 - 1 / W), sturm(I1, s, 1, 4), cover(W), expr=1 + a, term=a, p=-I1)
    assert th.claim == Claim("sign", R(1 + a), R(s), R(I1), R(sp.Integer(4)), False, False, 1, True)
    assert why(L, cover(2 - 1 / W), sturm(I1, s, 1, 4), sturm(s, s, 1, 4), expr=1 + a, term=a, p=-I1) == \
        "premise must be s + sqrt(s**2 + 1) > 0"
    assert why(K.sign_by_cover, expr=3 - s - sp.sqrt(s ** 2 + 1), var=s, cuts=[I1, sp.Integer(4)], want=1,
               strict=False).startswith("sign not shown")
    assert why(L, cover(2 - 1 / W), sturm(I1, s, 1, 4), cover(W), expr=1 + sp.sinh(s), term=sp.sinh(s),
               p=-I1) == "sinh(s) is not a term M log(Y) or M exp(Y) of sinh(s) + 1"


def test_sign_by_log_bound_bounds_exp_by_its_taylor_polynomial():
    """exp(Y) <= 1/T(-Y) for -Y >= 0, T(z) = 1 + z + ... + z^p/p! (e^z >= T(z)
    >= 1 for z >= 0).  1 - s exp(-s) on [1, 4]: M = -s <= 0, p = 1 gives
    B = 1 - s/(1 + s) = 1/(1 + s) > 0, so E > 0.  1 - s^2 exp(-s) on [1, 8]
    (max 4/e^2 at s = 2): p = 4 gives B = (T - s^2)/T > 0 with
    T - s^2 = 1 + s - s^2/2 + s^3/6 + s^4/24 (> 2 there), while p = 2 gives
    B = (1 + s - s^2/2)/T, negative beyond s = 1 + sqrt(3): no theorem."""
    L, X = K.sign_by_log_bound, sp.exp(-s)
    cover = lambda e, hi: K.sign_by_cover(expr=e, var=s, cuts=[1 + Q(k, 8) for k in range(8 * hi - 7)], want=1,
                                          strict=True)
    E, B = 1 - s * X, 1 - s / (1 + s)
    pos, neg = sturm(s, s, 1, 4), sturm(-s, s, 1, 4, want=-1)
    th = L(cover(B, 4), neg, pos, expr=E, term=-s * X, p=I1)
    assert th.claim == Claim("sign", R(E), R(s), R(I1), R(sp.Integer(4)), False, False, 1, True)
    assert L(cover(B, 4), neg, sturm(s, s, 1, 4, strict=False), expr=E, term=-s * X, p=I1).claim == th.claim  # -Y >= 0
    T4 = sum(s ** k / sp.factorial(k) for k in range(5))
    far = L(cover(1 - s ** 2 / T4, 8), sturm(-s ** 2, s, 1, 8, want=-1, strict=False), sturm(s, s, 1, 8),
            expr=1 - s ** 2 * X, term=-s ** 2 * X, p=sp.Integer(4))
    assert (far.claim.expr, far.claim.hi, far.claim.want) == (R(1 - s ** 2 * X), R(sp.Integer(8)), 1)
    assert why(cover, 1 - s ** 2 / (1 + s + s ** 2 / 2), 8).startswith("sign not shown")
    T16 = sum(s ** k / sp.factorial(k) for k in range(17))
    assert L(cover(1 - s / T16, 4), neg, pos, expr=E, term=-s * X, p=sp.Integer(16)).claim == th.claim   # p <= 16
    for p in (I0, sp.Integer(17), Q(1, 2), -I1):
        assert why(L, cover(B, 4), neg, pos, expr=E, term=-s * X, p=p).startswith("p is rational")
    assert why(L, cover(B, 4), neg, sturm(-s, s, 1, 4, want=-1), expr=E, term=-s * X, p=I1) == \
        "premise must be s > 0 (or >= 0)"                       # about -Y, not Y
    assert why(L, cover(B, 4), pos, pos, expr=E, term=-s * X, p=I1) == "premise must be the sign -1 of -s"
    assert why(L, cover(B, 4), neg, pos, expr=E, term=-s * X, p=I2).startswith("premise must be about")
    # exp(s) with -Y = -s < 0: no premise -Y >= 0 exists (T(-s) = 1 - s would bound nothing)
    G = 3 - s * sp.exp(s)
    assert why(L, cover(B, 4), neg, pos, expr=G, term=-s * sp.exp(s), p=I1) == \
        "premise must be -s > 0 (or >= 0)"


def test_rule_data_read_from_a_certificate_has_the_encoded_shape():
    # a certificate's step is applied as written (`apply.from_json`): the same theorem as the rule
    # applied to the objects, and data of any other shape is refused before the rule runs
    two = {"$": sp.srepr(sp.Integer(2))}
    assert K.value_sign.from_json(data={"value": two}) == K.value_sign(value=sp.Integer(2))
    msg = "value_sign: rule data must be SymPy objects, numbers, strings or lists"
    for bad in ({"$": 5}, {"$": "Integer(2)", "x": 1}, [1.5], [two, {"y": 1}], [[two, {"$": None}]], 1.5):
        with pytest.raises(KernelError) as err:
            K.value_sign.from_json(data={"value": bad})
        assert str(err.value) == msg, bad
    with pytest.raises(KernelError, match="^value_sign: rule data must be"):
        K.value_sign.from_json(data=[("value", two)])       # not a dict at all


def test_identity_with_roots_by_reducing_their_powers():
    """`_zero_when_generalized` with roots r = b^(1/q): r^q is replaced by b
    (times the denominator of b) until no power reaches q; the rest must be
    the zero polynomial.  True identities of radicals are exact; a false one,
    or one true only up to a missed reduction, is not."""
    from uwmr_symbolic.kernel.core import _zero_when_generalized as zero
    r2, r3 = sp.sqrt(2), sp.sqrt(3)
    rr, rq = sp.sqrt(1 + sp.sqrt(t)), sp.sqrt(1 + 1 / (t + 2))      # a root inside a root's base; b with a denominator
    for d in (sp.sqrt(t ** 2 + 4) / t - sp.sqrt(1 + 4 / t ** 2),         # t^(-1) split off
              (1 + sp.sqrt(t)) ** 3 - (1 + 3 * t + (3 + t) * sp.sqrt(t)),  # r^3 = t r
              (t ** 3 + t) ** Q(3, 4) - t ** Q(3, 4) * (t ** 2 + 1) ** Q(3, 4),  # t^(3/4) split off
              (1 + rr) ** 4 - (8 + 8 * rr + 8 * sp.sqrt(t) + 4 * rr * sp.sqrt(t) + t),  # two passes
              (1 + rq) ** 2 - 2 - 2 * rq - 1 / (t + 2),                     # r^2 = (t + 3)/(t + 2)
              1 / (r2 + r3) - (r3 - r2)):
        assert d != 0 and zero.__wrapped__(d, t), d
    for d in (sp.sqrt(t) ** 3 - t, sp.sqrt(t ** 2 + 4) / t - sp.sqrt(1 + 5 / t ** 2),
              (1 + sp.sqrt(t)) ** 2 - 1 - t, r2 * r3 - sp.sqrt(5), (1 + rq) ** 2 - 2 * rq - 1 - (t + 3)):
        assert not zero.__wrapped__(d, t), d


def test_derivative_keeps_the_log_term_of_a_variable_exponent_and_sympys_rules_elsewhere():
    """`derivative` of b^p with the variable in p: d(b^p) = b^p (p' log b + b' p/b).
    Written out by hand: d(2^s) = 2^s log 2, d(s^s) = s^s (log s + 1),
    d((1 + s)^(s/2)) = (1 + s)^(s/2) (log(1 + s)/2 + s/(2 (1 + s))), each also
    checked as a value against a 30-digit central difference; |u|, Piecewise
    and Max keep SymPy's own rules (sign(x - 1), the branch derivatives)."""
    import mpmath
    by_hand = {2 ** s: 2 ** s * sp.log(2), s ** s: s ** s * (sp.log(s) + 1),
               (1 + s) ** (s / 2): (1 + s) ** (s / 2) * (sp.log(1 + s) / 2 + s / (2 * (1 + s))),
               sp.exp(s) * s ** 3: sp.exp(s) * s ** 3 + 3 * s ** 2 * sp.exp(s)}
    mpmath.mp.dps = 30
    for e, d in by_hand.items():
        got = K.derivative(e, s)
        assert sp.expand(got - d) == 0, (e, got)
        h, p = mpmath.mpf(10) ** -10, mpmath.mpf("1.7")
        value = lambda u, at: sp.N(u.subs(s, at), 30)      # noqa: E731
        quotient = (value(e, sp.Float(p + h, 30)) - value(e, sp.Float(p - h, 30))) / (2 * sp.Float(h, 30))
        assert abs(quotient - value(got, sp.Float(p, 30))) < 1e-12
    assert K.derivative(sp.Abs(x - 1), x) == sp.sign(x - 1)
    assert K.derivative(sp.Piecewise((x, x < 1), (x ** 2, True)), x) == sp.Piecewise((1, x < 1), (2 * x, True))
    assert K.derivative(sp.Max(x, 1 - x) + x, x) == sp.diff(sp.Max(x, 1 - x), x) + 1


def test_logarithms_of_rationals_are_read_through_their_primes():
    """log(p/q), 0 < p/q and p, q < 2^64, is a sum of logarithms of primes,
    one fresh symbol per prime: log(3/4) - log 3 + 2 log 2 and log 256 - 8 log 2
    are 0 exactly (Arb alone cannot say so); log 2^64 is not factored (the cost
    bound), so log(2^64) - 64 log 2 stays undecided.  Distinct primes keep
    distinct symbols: (log 3 - log 2)(log(2 + exp(-30000)) - log 2) is not 0
    although Arb's 32,768 bits cannot sign it (sqrt 3 - r for r below sqrt 3
    by less than 10^-90 they do: positive)."""
    V = K.value_sign
    assert V(value=sp.log(Q(3, 4)) - sp.log(3) + 2 * sp.log(2)).claim.want == 0
    assert V(value=sp.log(256) - 8 * sp.log(2)).claim.want == 0
    big = sp.log(sp.Integer(2) ** 64) - 64 * sp.log(2)
    assert why(V, value=big) == f"sign of {big} not decided"
    r = sp.Rational(sp.floor(sp.sqrt(3) * 10 ** 90), 10 ** 90)
    assert V(value=(sp.log(3) - sp.log(2)) * (sp.sqrt(3) - r)).claim.want == 1
    c = (sp.log(3) - sp.log(2)) * (sp.log(2 + sp.exp(-30000)) - sp.log(2))
    assert why(V, value=c) == f"sign of {c} not decided"


def test_limit_by_taylor_claim_and_refusals():
    # (1 - cos s)/s^2 -> 1/2 (cos s = 1 - s^2/2 + ...): the claim on [0, w] closed, other = 1/2 exactly
    e, w = (1 - sp.cos(s)) / s ** 2, Q(1, 2)
    base = dict(expr=e, num=1 - sp.cos(s), den=s ** 2, var=s, order=2, width=w)
    th = K.limit_by_taylor(**base)
    assert th.claim == Claim("limit", R(e), R(s), R(I0), R(w), False, False, 0, False, R(Q(1, 2)))
    assert th.assumptions == {"arb", "sympy-core", "sympy-diff", "sympy-polys"}
    # the ends of the order range: 1 (log(1 + s)^2/s -> 0) and 12 (the same quotient over s^12)
    assert K.limit_by_taylor(expr=sp.log(1 + s) ** 2 / s, num=sp.log(1 + s) ** 2, den=s, var=s, order=1,
                             width=w).claim.other == R(I0)
    assert K.limit_by_taylor(**{**base, "num": (1 - sp.cos(s)) * s ** 10, "den": s ** 12,
                                "order": 12}).claim.other == R(Q(1, 2))
    for bad in ({"order": 0}, {"order": 13}, {"width": I0}, {"width": oo}):
        assert why(K.limit_by_taylor, **{**base, **bad}) == "order 1..12 and a finite w > 0"
    # cos s = s cos s/s is defined at 0: continuity, not this rule
    assert why(K.limit_by_taylor, **{**base, "expr": sp.cos(s), "num": s * sp.cos(s), "den": s, "order": 1}) \
        == "E(0) defined, or E D - N not 0"
    assert why(K.limit_by_taylor, **{**base, "num": 1 - sp.cos(s) + s ** 3}) == "the rational functions differ"
    # D = s^2 - s^3: D'' = 2 - 6s is not signed on [0, 1/2]; sinh(s) does not vanish at 0 to order 2
    assert why(K.limit_by_taylor, **{**base, "expr": (1 - sp.cos(s)) / (s ** 2 - s ** 3), "den": s ** 2 - s ** 3}) \
        == "derivative 2 of D has no strict sign on [0, 1/2]"
    assert why(K.limit_by_taylor, **{**base, "expr": sp.sinh(s) / s ** 2, "num": sp.sinh(s)}) \
        == "derivative 1 at 0 is 1, not exactly 0"
    assert why(K.limit_by_taylor, **{**base, "order": 1}) == "derivative 1 of D has no strict sign on [0, 1/2]"
