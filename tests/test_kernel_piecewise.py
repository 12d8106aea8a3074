"""The kernel's Piecewise rules (issue 9): `select_branch`, `join_at_point`,
`continuous_piecewise`.  Every case below is decided by hand:

* P = x^2 for x < 1, 2x - 1 otherwise: on (0, 1) the first branch applies
  (1 - x > 0), on [1, 2] the second (1 - x <= 0); P(1) = 1 from the second.
* Q = -5 at x = 1 (Eq), x elsewhere: positive on (0, 1) and (1, 2), but
  Q(1) = -5, so no sign on (0, 2) -- the branch taken only at a point.
* C = s^2/2 for s^2 <= 1, s - 1/2 otherwise is continuous (1/2 = 1/2 at 1);
  J = s^2/2 for s^2 <= 1, s otherwise jumps (1/2 vs 1) at s = 1.
"""
import dataclasses

import pytest
import sympy as sp

from uwmr_symbolic.certify import to_certificate
from uwmr_symbolic.kernel import KernelError, check_certificate, rules as K
from uwmr_symbolic.kernel.certificate import CertificateError

x = sp.Symbol("x", real=True)
s = sp.Symbol("s", positive=True)
Q = sp.Rational
ZERO = sp.Integer(0)

P = sp.Piecewise((x ** 2, x < 1), (2 * x - 1, True))


def sturm(e, var, lo, hi, lo_open=False, hi_open=False, want=1, strict=True):
    return K.sign_by_sturm(expr=e, var=var, lo=sp.sympify(lo), hi=sp.sympify(hi),
                           lo_open=lo_open, hi_open=hi_open, want=want, strict=strict)


def why(fn, *args, **kw):
    with pytest.raises(KernelError) as exc:
        fn(*args, **kw)
    return str(exc.value)


# ------------------------------------------------------------ select_branch

def test_select_branch_of_an_identity_and_of_a_max():
    """P = G on I as an identity claim (`design_certificate._one_branch`):
    x^2 = x^2 on (0, 1) becomes P = x^2 there; the other branch is refused.
    M = Piecewise((x^2, x <= x^2), (x, True)) (a Max as the loader writes it):
    on (1, 2) x^2 - x > 0 picks x^2; on (0, 1) it picks x."""
    cond = sturm(1 - x, x, 0, 1, lo_open=True, hi_open=True)
    ident = K.identity(lhs=x ** 2, rhs=x ** 2, var=x, lo=ZERO, hi=sp.Integer(1), lo_open=True, hi_open=True)
    c = K.select_branch(ident, cond, expr=P).claim
    assert (c.kind, c.expr, c.other, c.lo, c.hi, c.lo_open) == (
        "identity", sp.srepr(P), sp.srepr(x ** 2), "Integer(0)", "Integer(1)", True)
    other = K.identity(lhs=2 * x - 1, rhs=2 * x - 1, var=x, lo=ZERO, hi=sp.Integer(1), lo_open=True, hi_open=True)
    assert why(K.select_branch, other, cond, expr=P) == "the premise is not about the branch that applies on I"
    M = sp.Piecewise((x ** 2, x ** 2 >= x), (x, True))
    up = K.identity(lhs=x ** 2, rhs=x ** 2, var=x, lo=sp.Integer(1), hi=sp.Integer(2), lo_open=True, hi_open=True)
    assert K.select_branch(up, sturm(x ** 2 - x, x, 1, 2, True, True), expr=M).claim.expr == sp.srepr(M)
    low = K.identity(lhs=x, rhs=x, var=x, lo=ZERO, hi=sp.Integer(1), lo_open=True, hi_open=True)
    assert K.select_branch(low, sturm(x ** 2 - x, x, 0, 1, True, True, want=-1), expr=M).claim.other == sp.srepr(x)
    assert why(K.select_branch, up, sturm(x ** 2 - x, x, 0, 1, True, True, want=-1), expr=M) == \
        "condition x <= x**2 not decided"


def test_select_branch_moves_a_claim_to_the_piecewise():
    inner = sturm(x ** 2, x, 0, 1, lo_open=True, hi_open=True)
    cond = sturm(1 - x, x, 0, 1, lo_open=True, hi_open=True)            # x < 1 true: 1 - x > 0
    th = K.select_branch(inner, cond, expr=P)
    c = th.claim
    assert (c.kind, c.expr, c.lo, c.hi, c.lo_open, c.hi_open, c.want, c.strict) == (
        "sign", sp.srepr(P), "Integer(0)", "Integer(1)", True, True, 1, True)
    # the second branch on [1, 2]: x < 1 is false where 1 - x <= 0 (weak suffices)
    outer = sturm(2 * x - 1, x, 1, 2)
    false = sturm(1 - x, x, 1, 2, want=-1, strict=False)
    assert K.select_branch(outer, false, expr=P).claim.expr == sp.srepr(P)
    # a premise on a larger interval decides the condition on a smaller one
    wide = sturm(1 - x, x, -1, 1, hi_open=True)
    assert K.select_branch(inner, wide, expr=P).claim.lo == "Integer(0)"


def test_select_branch_refuses_what_does_not_follow():
    inner = sturm(x ** 2, x, 0, 1, lo_open=True, hi_open=True)
    cond = sturm(1 - x, x, 0, 1, lo_open=True, hi_open=True)
    # the wrong branch: 2x - 1 > 0 on (1/2, 1) says nothing about P there
    wrong = sturm(2 * x - 1, x, Q(1, 2), 1, lo_open=True, hi_open=True)
    assert why(K.select_branch, wrong, sturm(1 - x, x, Q(1, 2), 1, True, True), expr=P) == \
        "the premise is not about the branch that applies on I"
    # no fact about the condition
    assert why(K.select_branch, inner, expr=P) == "condition x < 1 not decided"
    # the condition decided on a smaller interval only
    part = sturm(1 - x, x, Q(1, 2), 1, hi_open=True)
    assert why(K.select_branch, inner, part, expr=P) == "condition x < 1 not decided"
    # x < 1 true needs 1 - x > 0 strictly; 1 - x >= 0 on (0, 1] does not exclude x = 1
    weak = sturm(1 - x, x, 0, 1, lo_open=True, want=1, strict=False)
    whole = sturm(x ** 2, x, 0, 1, lo_open=True)
    assert why(K.select_branch, whole, weak, expr=P) == "condition x < 1 not decided"
    # on [1, 2] the condition is false (1 - x <= 0): x^2 is not the branch there
    assert why(K.select_branch, sturm(x ** 2, x, 1, 2), sturm(1 - x, x, 1, 2, want=-1, strict=False),
               expr=P) == "the premise is not about the branch that applies on I"
    ident = K.identity(lhs=x, rhs=x, var=x, lo=ZERO, hi=sp.Integer(1), lo_open=False, hi_open=False)
    assert why(K.select_branch, K.value_sign(value=sp.Integer(1)), cond, expr=P) == "premise has no interval"
    assert why(K.select_branch, ident, cond, expr=P) == "condition x < 1 not decided"     # [0, 1], not (0, 1)
    assert why(K.select_branch, inner, cond, expr=x ** 2) == "x**2 is not a Piecewise"
    assert why(K.select_branch, inner, ident, expr=P) == "premise is a identity theorem, not a sign theorem"


def test_select_branch_reads_eq_and_or_not():
    # Eq(x, 0) is false on (0, 1) because 0 - x < 0 there; Ne(x, 0) is true for the same reason
    minus = sturm(-x, x, 0, 1, lo_open=True, want=-1)
    inner = sturm(x, x, 0, 1, lo_open=True)
    assert K.select_branch(inner, minus, expr=sp.Piecewise((0, sp.Eq(x, 0)), (x, True))).claim.kind == "sign"
    assert K.select_branch(inner, minus, expr=sp.Piecewise((x, sp.Ne(x, 0)), (0, True))).claim.kind == "sign"
    # x > 0 and x < 2 on (0, 1): both true; Or(x < 0, x > 3) false: both false
    both = sp.Piecewise((x, (x > 0) & (x < 2)), (-1, True))
    assert K.select_branch(inner, sturm(-x, x, 0, 1, lo_open=True, want=-1), sturm(2 - x, x, 0, 1, lo_open=True),
                           expr=both).claim.expr == sp.srepr(both)
    # And(x > 0, x < 2) needs both: with the fact about x < 2 missing it is undecided
    assert why(K.select_branch, inner, sturm(-x, x, 0, 1, lo_open=True, want=-1), expr=both).startswith("condition")
    neither = sp.Piecewise((-1, (x < 0) | (x > 3)), (x, True))
    facts = [sturm(-x, x, 0, 1, lo_open=True, want=-1, strict=False), sturm(3 - x, x, 0, 1, lo_open=True)]
    assert K.select_branch(inner, *facts, expr=neither).claim.expr == sp.srepr(neither)
    assert why(K.select_branch, inner, facts[0], expr=neither).startswith("condition")
    negated = sp.Piecewise((x, sp.Not(x > 3)), (-1, True))
    assert K.select_branch(inner, facts[1], expr=negated).claim.expr == sp.srepr(negated)


def test_select_branch_moves_sup_and_limit_claims():
    up = K.sup_upper_by_sign(K.sign_by_cover(expr=Q(1, 4) - x ** 2, var=x, cuts=[ZERO, Q(1, 2)], want=1, strict=False),
                             expr=x ** 2, bound=Q(1, 4))
    th = K.select_branch(up, sturm(1 - x, x, 0, Q(1, 2)), expr=P)
    assert (th.claim.kind, th.claim.other) == ("sup_upper", "Rational(1, 4)")
    lim = K.continuous_at_end(expr=x ** 2, var=x, c=ZERO, width=Q(1, 2))
    assert K.select_branch(lim, sturm(1 - x, x, 0, Q(1, 2)), expr=P).claim.other == "Integer(0)"


def test_select_branch_reads_an_expression_of_a_piecewise():
    # 2 - P on (0, 1) is 2 - x^2 (piecewise_fold), > 0 there
    gap = K.select_branch(sturm(2 - x ** 2, x, 0, 1, True, True), sturm(1 - x, x, 0, 1, True, True), expr=2 - P)
    assert gap.claim.expr == sp.srepr(2 - P)
    assert why(K.select_branch, sturm(2 - x ** 2, x, 0, 1, True, True), sturm(1 - x, x, 0, 1, True, True),
               expr=3 - P) == "the premise is not about the branch that applies on I"


def test_widen_a_lower_bound_of_the_sup():
    low = K.sup_lower_by_point(expr=x ** 2, var=x, point=Q(1, 2), bound=Q(1, 4), lo=ZERO, hi=sp.Integer(1),
                               lo_open=True, hi_open=True)
    wide = K.widen(low, lo=ZERO, hi=sp.oo, lo_open=False, hi_open=True)
    assert wide.claim == dataclasses.replace(low.claim, lo="Integer(0)", hi="oo", lo_open=False, hi_open=True)
    assert wide.assumptions == low.assumptions
    # a smaller interval may miss the point where the bound is reached
    assert why(K.widen, low, lo=Q(1, 2), hi=sp.oo, lo_open=False, hi_open=True) == "J does not contain I"
    assert K.widen(low, lo=ZERO, hi=sp.Integer(1), lo_open=True, hi_open=True).claim == low.claim
    assert why(K.widen, low, lo=ZERO, hi=Q(3, 4), lo_open=True, hi_open=True) == "J does not contain I"
    assert why(K.widen, sturm(x, x, 1, 2), lo=ZERO, hi=sp.Integer(3), lo_open=False, hi_open=False) == \
        "premise must be a sup_lower theorem"


# ------------------------------------------------------------ join_at_point

def test_join_at_point_through_the_value_at_the_boundary():
    left = K.select_branch(sturm(x ** 2, x, 0, 1, lo_open=True, hi_open=True),
                           sturm(1 - x, x, 0, 1, lo_open=True, hi_open=True), expr=P)
    right = K.select_branch(sturm(2 * x - 1, x, 1, 2, lo_open=True),
                            sturm(1 - x, x, 1, 2, lo_open=True, want=-1), expr=P)
    j = K.join_at_point(left, right)                     # P(1) = 2*1 - 1 = 1 > 0
    assert (j.claim.lo, j.claim.hi, j.claim.lo_open, j.claim.hi_open, j.claim.strict) == (
        "Integer(0)", "Integer(2)", True, False, True)
    # a value 0 at the point gives the weak sign
    e = (x - 1) ** 2
    assert not K.join_at_point(sturm(e, x, 0, 1, hi_open=True), sturm(e, x, 1, 2, lo_open=True)).claim.strict


def test_join_at_point_sees_a_branch_taken_only_at_the_point():
    Qx = sp.Piecewise((-5, sp.Eq(x, 1)), (x, True))
    sides = []
    for lo, hi, d_want in ((0, 1, 1), (1, 2, -1)):       # Eq(x, 1) false: 1 - x has a strict sign
        sides.append(K.select_branch(sturm(x, x, lo, hi, lo_open=True, hi_open=True),
                                     sturm(1 - x, x, lo, hi, lo_open=True, hi_open=True, want=d_want), expr=Qx))
    assert why(K.join_at_point, *sides) == "E(1) = -5 has not the sign"
    # a point value Arb cannot place at 256 bits (an enclosure about 0) and that is not exactly 0:
    # -(e^d - 1 - d), d = 10^-100, is about -5e-201 < 0: neither a zero nor of the sign
    tiny = sp.Piecewise((-(sp.exp(Q(1, 10 ** 100)) - 1 - Q(1, 10 ** 100)), sp.Eq(x, 1)), (x, True))
    near = [K.select_branch(sturm(x, x, lo, hi, lo_open=True, hi_open=True),
                            sturm(1 - x, x, lo, hi, lo_open=True, hi_open=True, want=d_want), expr=tiny)
            for lo, hi, d_want in ((0, 1, 1), (1, 2, -1))]
    assert why(K.join_at_point, *near).endswith("has not the sign")
    f = x ** 2 - 2 * x + 2                                # f(1) = 1 > 0 but not 0
    assert K.join_at_point(sturm(f, x, 0, 1, hi_open=True), sturm(f, x, 1, 2, lo_open=True)).claim.strict
    assert why(K.join_at_point, sturm(f, x, 0, 1, hi_open=True), sturm(f + 1, x, 1, 2, lo_open=True)) == \
        "different claims"


# ------------------------------------------------------------ continuous_piecewise

C = sp.Piecewise((s ** 2 / 2, s ** 2 <= 1), (s - Q(1, 2), True))


def test_continuous_piecewise_accepts_a_continuous_join():
    facts = [sturm(1 - s ** 2, s, 0, 1, lo_open=True, hi_open=True), sturm(1 - s ** 2, s, 1, sp.oo, True, True, -1)]
    th = K.continuous_piecewise(*facts, expr=C, var=s, cuts=[sp.Integer(1)])
    assert th.claim == K.Claim("continuous", sp.srepr(C), sp.srepr(s), "Integer(0)", "oo", True, True)
    assert th.assumptions == {"arb", "sympy-core", "sympy-polys", "flint-polys"}
    # equal values at the cut only by polynomial arithmetic with pi as a symbol:
    # (1 + pi)^2 / (pi^2 + 2 pi + 1), which SymPy leaves as it is
    E = sp.Piecewise(((s + sp.pi) ** 2 / (sp.pi ** 2 + 2 * sp.pi + 1), s <= 1), (1, True))
    assert E.args[0][0].subs(s, 1) != 1
    cut = [sturm(1 - s, s, 0, 1, True, True), sturm(1 - s, s, 1, sp.oo, True, True, -1)]
    th = K.continuous_piecewise(*cut, expr=E, var=s, cuts=[sp.Integer(1)])
    assert "sympy-polys" in th.assumptions


def test_continuous_piecewise_refuses_jumps_points_and_gaps():
    facts = [sturm(1 - s ** 2, s, 0, 1, lo_open=True, hi_open=True), sturm(1 - s ** 2, s, 1, sp.oo, True, True, -1)]
    J = sp.Piecewise((s ** 2 / 2, s ** 2 <= 1), (s, True))
    assert why(K.continuous_piecewise, *facts, expr=J, var=s, cuts=[sp.Integer(1)]) == "the branches differ at 1"
    # a branch taken only at the cut
    D = sp.Piecewise((5, sp.Eq(s, 1)), (s, True))
    eq = [sturm(1 - s, s, 0, 1, True, True), sturm(1 - s, s, 1, sp.oo, True, True, -1)]
    assert why(K.continuous_piecewise, *eq, expr=D, var=s, cuts=[sp.Integer(1)]) == "the branches differ at 1"
    # the cut left out: on (0, oo) the condition changes truth and is not decided
    assert why(K.continuous_piecewise, *facts, expr=C, var=s, cuts=[]).startswith("condition")
    # a branch defined on its closed piece [1, oo) only: enough (log(2s - 1) + log 2 = log 2 at 1)
    L = sp.Piecewise((sp.log(s + 1), s ** 2 <= 1), (sp.log(2 * s - 1) + sp.log(2), True))
    assert K.continuous_piecewise(*facts, expr=L, var=s, cuts=[sp.Integer(1)]).claim.kind == "continuous"
    # a branch undefined inside its piece (log(s - 3/2) on (1, 3/2]), or at the cut only (log(s - 1))
    L2 = sp.Piecewise((sp.log(s + 1), s ** 2 <= 1), (sp.log(s - Q(3, 2)) + sp.log(4), True))
    assert why(K.continuous_piecewise, *facts, expr=L2, var=s, cuts=[sp.Integer(1)]) == \
        f"{L2.args[1][0]} not shown defined on (1, oo)"
    L3 = sp.Piecewise((sp.log(s + 1), s ** 2 <= 1), (sp.log(s - 1) + sp.log(4), True))
    assert why(K.continuous_piecewise, *facts, expr=L3, var=s, cuts=[sp.Integer(1)]).startswith(
        f"{L3.args[1][0]} undefined at 1")


def test_piecewise_branches_allows_jumps_but_not_undefined_branches():
    """A jump at s = 1 (s^2/2 inside, s beyond): continuous on each piece,
    so "pieces" with the cut listed; the same refusals as
    `continuous_piecewise` on each open piece."""
    facts = [sturm(1 - s ** 2, s, 0, 1, lo_open=True, hi_open=True), sturm(1 - s ** 2, s, 1, sp.oo, True, True, -1)]
    J = sp.Piecewise((s ** 2 / 2, s ** 2 <= 1), (s, True))
    th = K.piecewise_branches(*facts, expr=J, var=s, cuts=[sp.Integer(1)])
    assert th.claim == K.Claim("pieces", sp.srepr(J), sp.srepr(s), "Integer(0)", "oo", True, True,
                               other=sp.srepr(sp.Tuple(1)))
    assert why(K.piecewise_branches, *facts, expr=J, var=s, cuts=[]).startswith("condition")
    L = sp.Piecewise((sp.log(s + 1), s ** 2 <= 1), (sp.log(s - Q(3, 2)) + sp.log(4), True))
    assert "not shown defined on (1, oo)" in why(K.piecewise_branches, *facts, expr=L, var=s, cuts=[sp.Integer(1)])
    # the branch beyond 1 is unbounded near the cut: refused, though P may jump there
    U = sp.Piecewise((s, s ** 2 <= 1), (1 / (s - 1), True))
    assert why(K.piecewise_branches, *facts, expr=U, var=s, cuts=[sp.Integer(1)]).startswith("1/(s - 1) undefined at 1")
    assert why(K.piecewise_branches, *facts, expr=J, var=s, cuts=[sp.Integer(2), sp.Integer(1)]) == \
        "cut points not increasing: 2, 1"
    assert why(K.piecewise_branches, *facts, expr=s + 1, var=s, cuts=[sp.Integer(1)]).endswith("is not a Piecewise")
    cert = to_certificate([th])
    assert [t.claim for t in check_certificate(cert)] == [th.claim]
    cert["theorems"][-1]["claim"]["other"] = sp.srepr(sp.Tuple(2))           # another cut claimed
    with pytest.raises(CertificateError):
        check_certificate(cert)


def test_piecewise_certificate_round_trips_and_tampering_is_rejected():
    facts = [sturm(1 - s ** 2, s, 0, 1, lo_open=True, hi_open=True), sturm(1 - s ** 2, s, 1, sp.oo, True, True, -1)]
    th = K.continuous_piecewise(*facts, expr=C, var=s, cuts=[sp.Integer(1)])
    cert = to_certificate([th])
    assert [t.claim for t in check_certificate(cert)] == [th.claim]
    jump = sp.srepr(sp.Piecewise((s ** 2 / 2, s ** 2 <= 1), (s, True)))
    cert["theorems"][-1]["data"]["expr"] = {"$": jump}
    with pytest.raises(CertificateError, match="the branches differ at 1"):
        check_certificate(cert)


# ------------------------------------------------------------ identities of Piecewise expressions

def test_piecewise_identities_branch_by_branch():
    """f(x, y) = F(sqrt(x^2 + y^2)) for a Piecewise f written with 4x^2 + 4y^2
    where F gives 4(x^2 + y^2): the same conditions, each pair of branches
    equal as rational functions.  A different condition (< 1/4 against <= 1/4)
    or branch is refused at once, without SymPy's simplify (a Piecewise cannot
    be cross-checked by the evaluator)."""
    X, Y = sp.symbols("x y", real=True)
    rho = X ** 2 + Y ** 2
    f = sp.Piecewise(((4 * X ** 2 + 4 * Y ** 2) / (2 * (4 * rho + 1)), rho < Q(1, 4)), (sp.log(1 + rho), True))
    F = sp.Piecewise((4 * s ** 2 / (2 * (4 * s ** 2 + 1)), s ** 2 < Q(1, 4)), (sp.log(1 + s ** 2), True))
    rhs = F.subs(s, sp.sqrt(rho))
    assert f != rhs
    th = K.identity_plane(lhs=f, rhs=rhs, x=X, y=Y)
    assert th.assumptions == {"sympy-core", "sympy-polys"}
    other = rhs.subs(sp.Rational(1, 4), sp.Rational(1, 3))
    assert why(K.identity_plane, lhs=f, rhs=other, x=X, y=Y) == "the Piecewise sides differ in a condition or a branch"
    G = sp.Piecewise((x ** 2 - 1, x < 1), (x + 1, True))
    H = sp.Piecewise(((x - 1) * (x + 1), x < 1), (1 + x, True))
    assert K.identity(lhs=G, rhs=H, var=x, lo=ZERO, hi=sp.Integer(2), lo_open=False, hi_open=False).claim.kind == \
        "identity"
    assert why(K.identity, lhs=G, rhs=H + 1, var=x, lo=ZERO, hi=sp.Integer(2), lo_open=False, hi_open=False) == \
        "the Piecewise sides differ in a condition or a branch"


def test_a_condition_scaled_by_a_positive_rational_is_the_same_condition():
    """Min(r/2, log(1 + r)) as the design's Piecewise reads log(1 + r) <= r/2,
    while its profile F(s) = f(s, 0), through SymPy's subs, reads s^2 >=
    2 log(1 + s^2): the same condition times 2.  Scaled by -2 (the inequality
    turned round) or made strict, it is another condition."""
    X, Y = sp.symbols("x y", real=True)
    rho = X ** 2 + Y ** 2
    L = sp.log(1 + rho)
    f = sp.Piecewise((L, L <= rho / 2), (rho / 2, True))
    assert K.identity_plane(lhs=f, rhs=sp.Piecewise((L, rho >= 2 * L), (rho / 2, True)), x=X, y=Y).claim.kind \
        == "identity_plane"
    assert K.identity_plane(lhs=f, rhs=sp.Piecewise((L, 3 * L - 3 * rho / 2 <= 0), (rho / 2, True)),
                            x=X, y=Y).claim.kind == "identity_plane"
    for cond in (rho <= 2 * L, rho > 2 * L, -2 * L + rho <= 1):
        assert why(K.identity_plane, lhs=f, rhs=sp.Piecewise((L, cond), (rho / 2, True)), x=X, y=Y) == \
            "the Piecewise sides differ in a condition or a branch"


def test_continuous_piecewise_cuts_are_finite_positive_and_increasing():
    facts = [sturm(1 - s ** 2, s, 0, 1, lo_open=True, hi_open=True), sturm(1 - s ** 2, s, 1, sp.oo, True, True, -1)]
    for cuts, msg in (([sp.oo], "cut points are finite"), ([ZERO], "cut points not increasing: 0, 0"),
                      ([sp.Integer(2), sp.Integer(1)], "cut points not increasing: 2, 1")):
        assert why(K.continuous_piecewise, *facts, expr=C, var=s, cuts=cuts) == msg


# ------------------------------------------------------------ the truth of a condition, relation by relation

def _facts(*known):
    """sign_ok from facts (d, want, strict); a strict fact gives the weak one too."""
    have = set(known)
    return lambda d, w, st: (d, w, True) in have or (not st and (d, w, False) in have)


D = 1 - x           # r - l for every relation x REL 1 below


@pytest.mark.parametrize("cond, truth, known, holds", [
    (x < 1, True, [(D, 1, True)], True), (x < 1, True, [(D, 1, False)], False),
    (x < 1, False, [(D, -1, False)], True), (x < 1, False, [(D, 1, True)], False),
    (x <= 1, True, [(D, 1, False)], True), (x <= 1, True, [(D, -1, True)], False),
    (x <= 1, False, [(D, -1, True)], True), (x <= 1, False, [(D, -1, False)], False),
    (x > 1, True, [(D, -1, True)], True), (x > 1, True, [(D, -1, False)], False),
    (x > 1, False, [(D, 1, False)], True), (x > 1, False, [(D, -1, True)], False),
    (x >= 1, True, [(D, -1, False)], True), (x >= 1, True, [(D, 1, True)], False),
    (x >= 1, False, [(D, 1, True)], True), (x >= 1, False, [(D, 1, False)], False),
    (sp.Eq(x, 1), True, [(D, 1, False), (D, -1, False)], True), (sp.Eq(x, 1), True, [(D, 1, False)], False),
    (sp.Eq(x, 1), False, [(D, -1, True)], True), (sp.Eq(x, 1), False, [(D, 1, True)], True),
    (sp.Eq(x, 1), False, [(D, 1, False)], False),
    (sp.Ne(x, 1), True, [(D, 1, True)], True), (sp.Ne(x, 1), True, [(D, 1, False)], False),
    (sp.Ne(x, 1), False, [(D, 1, False), (D, -1, False)], True), (sp.Ne(x, 1), False, [(D, -1, True)], False),
    (sp.true, True, [], True), (sp.true, False, [], False), (sp.false, False, [], True), (sp.false, True, [], False),
    (sp.Or(x < 1, x > 3), True, [(D, 1, True)], True), (sp.Or(x < 1, x > 3), False, [(D, -1, False)], False),
    (sp.And(x < 1, x > 3), False, [(3 - x, 1, False)], True), (sp.And(x < 1, x > 3), True, [(D, 1, True)], False),
    (sp.Not(x < 1), True, [(D, -1, False)], True), (sp.Not(x < 1), False, [(D, 1, True)], True),
    (sp.Not(x < 1), True, [(D, 1, True)], False),
])
def test_the_truth_of_a_condition(cond, truth, known, holds):
    from uwmr_symbolic.kernel.core import _holds
    assert _holds(cond, truth, _facts(*known)) is holds


def test_a_condition_that_is_no_relation_is_refused():
    from uwmr_symbolic.kernel.core import _holds
    p = sp.Symbol("p")
    with pytest.raises(KernelError, match="condition p is not a relation"):
        _holds(p, True, _facts())


def test_select_branch_needs_the_variable_and_the_sign_of_the_premise():
    inner = sturm(x ** 2, x, 0, 1, True, True)
    t_fact = sturm(1 - s, s, 0, 1, True, True)                      # about s, not x
    assert why(K.select_branch, inner, t_fact, expr=P) == "condition x < 1 not decided"
    wrong_sign = sturm(x - 1, x, 0, 1, True, True, want=-1)         # x - 1 < 0 is not a fact about 1 - x
    assert why(K.select_branch, inner, wrong_sign, expr=P) == "condition x < 1 not decided"


def test_select_branch_moves_a_divergence_and_a_lower_sup():
    above = sturm(Q(1, 2) + 0 * s, s, 4, sp.oo, False, True)        # F' - 1/2 = 1/2 >= 0 on [4, oo) for F = s
    div = K.diverges_by_growth(K.weaken(above, lo=sp.Integer(4), hi=sp.oo, lo_open=False, hi_open=True,
                                        strict=False), expr=s, var=s, R=sp.Integer(4), rate="linear", k=Q(1, 2))
    Ps = sp.Piecewise((s, s > 1), (0, True))
    th = K.select_branch(div, sturm(1 - s, s, 4, sp.oo, False, True, want=-1), expr=Ps)
    assert (th.claim.kind, th.claim.expr, th.claim.lo, th.claim.hi) == ("diverges", sp.srepr(Ps), "Integer(4)", "oo")
    low = K.sup_lower_by_point(expr=s, var=s, point=sp.Integer(5), bound=sp.Integer(5), lo=sp.Integer(4), hi=sp.oo,
                               lo_open=False, hi_open=True)
    up = K.select_branch(low, sturm(1 - s, s, 4, sp.oo, False, True, want=-1), expr=Ps)
    assert (up.claim.kind, up.claim.other) == ("sup_lower", "Integer(5)")
    wide = K.widen(up, lo=ZERO, hi=sp.oo, lo_open=False, hi_open=True)
    assert wide.claim == dataclasses.replace(up.claim, lo="Integer(0)", lo_open=False)


def test_join_at_point_is_weak_when_a_side_is():
    e = x ** 2 + 1
    j = K.join_at_point(sturm(e, x, 0, 1, hi_open=True), sturm(e, x, 1, 2, lo_open=True, strict=False))
    assert (j.claim.strict, j.claim.lo, j.claim.hi, j.claim.lo_open, j.claim.hi_open) == (
        False, "Integer(0)", "Integer(2)", False, False)
    neg = -e
    jn = K.join_at_point(sturm(neg, x, 0, 1, hi_open=True, want=-1), sturm(neg, x, 1, 2, lo_open=True, want=-1))
    assert (jn.claim.want, jn.claim.strict) == (-1, True)
    assert why(K.join_at_point, sturm(e, x, 0, 1, hi_open=True), sturm(e, x, 2, 3, lo_open=True)) == "not adjacent"
    assert why(K.join_at_point, sturm(x, x, -1, 0, hi_open=True, want=-1), sturm(x, x, 0, 1, lo_open=True)) == \
        "different claims"


def test_piecewise_identity_needs_as_many_branches():
    G = sp.Piecewise((x ** 2 - 1, x < 1), (x + 1, True))
    three = sp.Piecewise(((x - 1) * (x + 1), x < 1), (1 + x, x < 5), (0, True))
    assert why(K.identity, lhs=G, rhs=three, var=x, lo=ZERO, hi=sp.Integer(2), lo_open=False, hi_open=False) == \
        "the Piecewise sides differ in a condition or a branch"
    # a branch equal only once tanh is read as sinh/cosh (the generalised route)
    T1 = sp.Piecewise((sp.tanh(x), x < 1), (x, True))
    T2 = sp.Piecewise((sp.sinh(x) / sp.cosh(x), x < 1), (x, True))
    assert K.identity(lhs=T1, rhs=T2, var=x, lo=ZERO, hi=sp.Integer(2), lo_open=False,
                      hi_open=False).assumptions == {"sympy-core", "sympy-polys"}


def test_not_of_a_conjunction_no_branch_and_an_open_end_of_widen():
    from uwmr_symbolic.kernel.core import _holds
    # SymPy keeps Not(And(...)) (a Not of one relation becomes the opposite relation)
    assert _holds(sp.Not(sp.And(x < 1, x > 3)), True, _facts((3 - x, 1, False)))
    assert not _holds(sp.Not(sp.And(x < 1, x > 3)), True, _facts((D, 1, True)))
    none = sp.Piecewise((x, x > 5), (0, x > 6))                    # on [0, 1] both conditions are false
    inner = sturm(x + 1, x, 0, 1)
    assert why(K.select_branch, inner, sturm(5 - x, x, 0, 1), sturm(6 - x, x, 0, 1), expr=none) == "no branch applies"
    # sup over [0, 1] >= 1/4 does not give the sup over (0, 2]: 0 is not in it
    low = K.sup_lower_by_point(expr=x + 1, var=x, point=ZERO, bound=sp.Integer(1), lo=ZERO, hi=sp.Integer(1),
                               lo_open=False, hi_open=False)
    assert why(K.widen, low, lo=ZERO, hi=sp.Integer(2), lo_open=True, hi_open=False) == "J does not contain I"
    assert K.widen(low, lo=ZERO, hi=sp.Integer(2), lo_open=False, hi_open=False).claim.hi == "Integer(2)"


def test_piecewise_identity_reads_equivalent_conditions():
    """Conditions equal as sets of the plane: (x = 0 and y = 0) is
    x^2 + y^2 = 0 is sqrt(x^2 + y^2) = 0 (and their negations); a >= b is
    b <= a.  Near misses are refused: (x = 0 and y = 1), a <= b for a >= b,
    sqrt(x^2 + y^2) = 1, (x = 0 or y = 0)."""
    X, Y = sp.symbols("x y", real=True)
    rho = X ** 2 + Y ** 2
    g = sp.log(1 + rho)

    def ok(c1, c2):
        return K.identity_plane(lhs=sp.Piecewise((0, c1), (g, True)), rhs=sp.Piecewise((0, c2), (g, True)),
                                x=X, y=Y).assumptions <= {"sympy-core", "sympy-polys"}

    def refused(c1, c2):
        return why(K.identity_plane, lhs=sp.Piecewise((0, c1), (g, True)), rhs=sp.Piecewise((0, c2), (g, True)),
                   x=X, y=Y) == "the Piecewise sides differ in a condition or a branch"

    origin = sp.And(sp.Eq(X, 0), sp.Eq(Y, 0))
    assert ok(origin, sp.Eq(sp.sqrt(rho), 0)) and ok(origin, sp.Eq(rho, 0)) and ok(sp.Eq(0, rho), origin)
    assert ok(sp.Or(sp.Ne(Y, 0), sp.Ne(X, 0)), sp.Ne(sp.sqrt(rho), 0))
    assert ok(rho / 2 >= sp.sqrt(rho) - Q(1, 2), sp.sqrt(rho) <= rho / 2 + Q(1, 2))
    assert ok(rho > 1, 1 < rho) and ok(sp.Eq(rho, 1), sp.Eq(1, rho))
    assert refused(origin, sp.And(sp.Eq(X, 0), sp.Eq(Y, 1)))
    assert refused(sp.Or(sp.Eq(X, 0), sp.Eq(Y, 0)), sp.Eq(rho, 0))
    assert refused(origin, sp.Eq(sp.sqrt(rho), 1))
    assert refused(rho / 2 >= sp.sqrt(rho), rho / 2 <= sp.sqrt(rho))
    assert refused(rho > 1, rho >= 1)
    assert refused(sp.Ne(rho, 0), sp.Eq(rho, 0))
    # (a Piecewise puts some conditions in SymPy's canonical form first; the reading itself:)
    from uwmr_symbolic.kernel.core import _condition
    same = lambda a, b: _condition(a, (X, Y)) == _condition(b, (X, Y))      # noqa: E731
    assert same(sp.Eq(0, -sp.sqrt(rho)), sp.Eq(rho, 0)) and same(sp.Eq(-sp.sqrt(rho), 0), sp.Eq(rho, 0))
    assert same(sp.Eq(rho + 1, 2), sp.Eq(rho, 1)) and same(sp.Eq(X, Y), sp.Eq(Y, X))
    assert not same(sp.Eq(X, Y), sp.Eq(X, -Y)) and not same(sp.Eq(sp.sqrt(rho), 1), sp.Eq(rho, 1))


# ------------------------------------------------------------ a branch taken at points only

def test_select_branch_passes_over_a_point_value_equal_to_the_branch_around_it():
    """Piecewise((V, Eq(x, c)), (G, True)) is G on all of I when V = G(c):
    log(10) at s = 3 beside log(1 + s^2) (log 10 there too) is log(1 + s^2) on
    (0, oo), with no sign fact about 3 - s.  Decided by hand: V - G(c) is
    2 - log 10 != 0, or 10^-30 off, or G(3) = sin(0)/0 undefined -> refused;
    Eq(s^2, 9) has the roots 3 and -3, only 3 > 0 counts for a positive s,
    while for a real x the value at -3 must agree too."""
    G = sp.log(1 + s ** 2)
    ident = K.identity(lhs=G, rhs=G, var=s, lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    for cond in (sp.Eq(s, 3), sp.Eq(s ** 2, 9), sp.Eq(2 * s - 6, 0)):
        F = sp.Piecewise((sp.log(10), cond), (G, True))
        th = K.select_branch(ident, expr=F)
        assert (th.claim.expr, th.claim.other) == (sp.srepr(F), sp.srepr(G))
        assert th.assumptions == {"arb", "sympy-core", "sympy-polys"}
    root2 = sp.Piecewise((sp.log(3), sp.Eq(s, sp.sqrt(2))), (G, True))          # a linear p with c = sqrt(2)
    assert K.select_branch(ident, expr=root2).claim.other == sp.srepr(G)
    cube = sp.Piecewise((sp.log(1 + 2 ** Q(2, 3)), sp.Eq(s ** 3, 2)), (G, True))  # the real root 2^(1/3)
    assert K.select_branch(ident, expr=cube).claim.other == sp.srepr(G)
    for V, msg in ((sp.Integer(2), "Arb disagrees"), (sp.pi, "Arb disagrees"),      # V - G(3) far from 0
                   (sp.log(10) + Q(1, 10 ** 30), "Arb disagrees"),                  # 10^-30: Arb sees it
                   (sp.log(10) + Q(1, 10 ** 60), "the rational functions differ"),  # Arb does not, exactly not 0
                   (sp.log(10) + sp.pi / 10 ** 60, f"the value where Eq(s, 3) is not {G}'s")):   # with pi
        assert why(K.select_branch, ident, expr=sp.Piecewise((V, sp.Eq(s, 3)), (G, True))) == msg
    H = sp.sin(s - 3) / (s - 3)
    hole = K.identity(lhs=H, rhs=H, var=s, lo=ZERO, hi=Q(1), lo_open=True, hi_open=True)
    assert why(K.select_branch, hole, expr=sp.Piecewise((1, sp.Eq(s, 3)), (H, True))).startswith(f"{H} at s = 3")
    for cond in (sp.Eq(sp.sin(s), 0), sp.Eq(sp.sqrt(s), 2), sp.Eq(s ** 2, sp.pi)):   # no polynomial over Q
        assert why(K.select_branch, ident, expr=sp.Piecewise((G.subs(s, 2), cond), (G, True))) == \
            f"condition {cond} not decided"
    # a real variable: both roots of x^2 = 9 count; log(1 + x^2) + x is log 10 + 3 at 3, log 10 - 3 at -3
    Gx = sp.log(1 + x ** 2) + x
    idx = K.identity(lhs=Gx, rhs=Gx, var=x, lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    assert why(K.select_branch, idx, expr=sp.Piecewise((sp.log(10) + 3, sp.Eq(x ** 2, 9)), (Gx, True))) == \
        "Arb disagrees"                                               # 6 at x = -3
    # a nonnegative n meets 0: the root 0 of n^2 + n = 0 counts (-1 does not), and -5 there is not
    # n's value 0 (else "P >= 0 on [0, 1]" with P(0) = -5)
    n = sp.Symbol("n", nonnegative=True)
    weak = K.sign_by_cover(expr=n, var=n, cuts=[0, 1], want=1, strict=False)
    assert why(K.select_branch, weak, expr=sp.Piecewise((-5, sp.Eq(n ** 2 + n, 0)), (n, True))) == "Arb disagrees"
    assert K.select_branch(weak, expr=sp.Piecewise((0, sp.Eq(n ** 2 + n, 0)), (n, True))).claim.want == 1
    # a positive s at the closed end 0 of a limit claim (s -> 0 as s -> 0+, "s continuous on [0, 1]"):
    # s^2 - s = 0 holds at 0 and 1, where P = 1; the root 0 must count (P(0) = 1, not 0)
    lim = K.continuous_at_end(expr=s, var=s, c=0, width=1)
    assert why(K.select_branch, lim, expr=sp.Piecewise((1, sp.Eq(s ** 2 - s, 0)), (s, True))) == "Arb disagrees"
    Gs = sp.log(1 + s ** 2) + s
    ids = K.identity(lhs=Gs, rhs=Gs, var=s, lo=ZERO, hi=sp.oo, lo_open=True, hi_open=True)
    assert K.select_branch(ids, expr=sp.Piecewise((sp.log(10) + 3, sp.Eq(s ** 2, 9)), (Gs, True))).claim.kind == \
        "identity"


def test_a_point_value_is_checked_in_a_certificate_and_on_each_piece():
    """The same rule inside `continuous_piecewise` (no cut at the point) and
    through a certificate; D = 5 at s = 1 beside s is refused there."""
    G = sp.log(1 + s ** 2)
    F = sp.Piecewise((sp.log(10), sp.Eq(s, 3)), (G, True))
    th = K.continuous_piecewise(expr=F, var=s, cuts=[])
    assert th.claim == K.Claim("continuous", sp.srepr(F), sp.srepr(s), "Integer(0)", "oo", True, True)
    assert check_certificate(to_certificate([th]))[0].claim == th.claim
    D = sp.Piecewise((5, sp.Eq(s, 1)), (s, True))
    assert why(K.continuous_piecewise, expr=D, var=s, cuts=[]) == "Arb disagrees"     # 5 - 1


def test_a_point_value_before_a_branch_decided_by_the_facts():
    """Piecewise((V, Eq(s, 3)), (G1, s < 5), (G2, True)) on (0, 5): the branch
    after the point value is G1 (s < 5 holds there by the premise 5 - s > 0),
    not the last one; V = log 10 = G1(3), while G2(3) = 9.  Two point values
    in a row (log 10 at 3, log 17 at 4) are passed over one after the other."""
    G1, G2 = sp.log(1 + s ** 2), s ** 2
    on = dict(var=s, lo=ZERO, hi=Q(5), lo_open=True, hi_open=True)
    ident, below = K.identity(lhs=G1, rhs=G1, **on), sturm(5 - s, s, 0, 5, lo_open=True, hi_open=True)
    F = sp.Piecewise((sp.log(10), sp.Eq(s, 3)), (G1, s < 5), (G2, True))
    assert K.select_branch(ident, below, expr=F).claim.other == sp.srepr(G1)
    wrong = sp.Piecewise((G2.subs(s, 3), sp.Eq(s, 3)), (G1, s < 5), (G2, True))     # V = G2(3), not G1(3)
    assert why(K.select_branch, ident, below, expr=wrong) == "Arb disagrees"
    two = sp.Piecewise((sp.log(10), sp.Eq(s, 3)), (sp.log(17), sp.Eq(s, 4)), (G1, True))
    assert K.select_branch(ident, expr=two).claim.other == sp.srepr(G1)
    assert why(K.select_branch, ident, expr=sp.Piecewise((sp.log(10), sp.Eq(s, 3)), (sp.log(16), sp.Eq(s, 4)),
                                                          (G1, True))) == "Arb disagrees"
