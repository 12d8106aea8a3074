"""P5-P8 of an f that is analytic on the whole plane (issue 9: "unknown
where a sound answer is easy"), radial or not: the kernel's
`continuous_on_plane` shows f's formula (and, for P8, that of df/de2) defined
at every point, and the link adds that f holds no Abs, Piecewise, Max, Min
or sign, and, for P8, that df/de2(e1, 0) is exactly 0.

Truths by hand (rho = e1^2 + e2^2):
* e1^2 + log(1 + e2^2): df/de2 = 2 e2/(1 + e2^2), d2f/de2^2 = 2 (1 - e2^2)/(1 + e2^2)^2,
  d2f/de1de2 = 0, all continuous: P7 holds; df/de2 -> 0 as e2 -> 0: P8 holds.
* log(1 + rho + e1^2 e2^2): the argument is >= 1, so f is analytic: P7 holds;
  df/de2 = (2 e2 + 2 e1^2 e2)/(1 + rho + e1^2 e2^2) -> 0 as e2 -> 0: P8 holds.
* log(1 + rho) + e1 e2/10: analytic, P7 holds; df/de2(e1, 0) = e1/10 != 0 for e1 != 0:
  P8 fails (refuted at e1 = 1, limit 1/10).
* log(log(e + rho)): log(e + rho) >= 1 > 0, analytic: P7 holds; df/de2 = 2 e2/((e + rho)
  log(e + rho)) -> 0: P8 holds (the radial route leaves both to the search).
* |e1|^3 + e2^2 is C^2 too, but |.| is not analytic: the link must not take the plane route.
P5, P6 where df/de1 = phi(e1) does not depend on e2 (f = g(e1) + h(e2)):
* e1^2 + log(1 + e2^2): phi = 2 e1, phi tanh(e1) > 0 (P5); phi/e1 = 2: k = 2, h = 1 (P6).
* log(1 + e1^2) + log(1 + e2^2): phi = 2 e1/(1 + e1^2), same sign as e1 (P5); phi/e1 =
  2/(1 + e1^2) in (0, 2]: k = 2 (P6).
* e1 atan(e1) - log(1 + e1^2)/2 + e2^2: phi = atan(e1) (P5); atan(e1)/e1 in (0, 1] (P6).
* e1^4 + e2^2: phi = 4 e1^3 (P5 holds); phi/e1 = 4 e1^2 is unbounded, so P6 fails.
* e1^4 - e1^2 + e2^2: phi = 4 e1^3 - 2 e1 < 0 on (0, 1/sqrt 2): P5 and P6 fail.
P3 where f(e1, e2) = f(e1, 0) + f(0, e2) (separable, f(0, 0) = 0), f defined on the plane:
* log(1 + e1^2) + log(1 + e2^2): log(1 + s^2) > 0 for s != 0 and -> oo: P3 holds.
* e1^2 + sqrt(1 + e2^2) - 1: s^2 and sqrt(1 + s^2) - 1 > 0 for s != 0, both -> oo: P3 holds.
* cosh(e1) - 1 + e2^4: cosh s - 1 > 0 for s != 0 and -> oo: P3 holds.
* log(1 + e1^2) + atan(e2^2): f(0, s) = atan(s^2) < pi/2: not radially unbounded, P3 fails.
* e1^2 + e2^2/(1 + e2^2): f(0, s) -> 1: P3 fails (the limit along the e2 axis is 0 * oo as written:
  1/(x^2 (1 + x^-2)) with e2 = 1/x, which the limit calculus now cancels first).
* e1^2 - e2^2/(1 + e2^2): f(0, 1) = -1/2 < 0: P3 fails.
* e1^2 + e1 + e2^2: f(-1/2, 0) = -1/4 < 0: P3 fails.
P1 where df/de2 = psi(e2) does not depend on e1, f analytic on the plane:
* log(1 + e1^2) + log(1 + e2^2): psi = 2 e2/(1 + e2^2), |psi| <= 1: P1 holds.
* e1^2 + sqrt(1 + e2^2) - 1: psi = e2/sqrt(1 + e2^2), |psi| < 1: P1 holds.
* e1^2 + log(cosh(e2)): psi = tanh(e2), |psi| < 1: P1 holds.
* exp(e1) - 1 - e1 + log(1 + e2^2): psi = 2 e2/(1 + e2^2): P1 holds (df/de1 = exp(e1) - 1 is continuous).
* cosh(e1) - 1 + e2^4: psi = 4 e2^3 is unbounded: P1 fails.
P3 of a Piecewise f whose every branch is radial, G(|e|), with G > 0 on (0, oo) and G -> oo:
* Min(rho/2, log(1 + rho)): rho/2 and log(1 + rho) are both > 0 for rho > 0 and -> oo, and f is
  one of them at each point: P3 holds (the branches cross at a transcendental radius, where F
  has a kink: P1 fails there).
* log(1 + rho) where e1 > 0, 2 log(1 + rho) elsewhere: P3 holds (f jumps across e1 = 0).
* log(1 + rho) where e1 > 0, rho/(1 + rho) elsewhere: f < 1 on the half-plane e1 <= 0: P3 fails.
* log(1 + rho) where e1 > 0, rho - 1 elsewhere: f(-1/2, 0) = -3/4 < 0: P3 fails.
P5, P6 of a Piecewise f whose conditions read e2 only and whose every branch is radial, G(|e|):
along e1 the branch does not change, so df/de1 = G'(|e|) e1/|e| of the branch taken.
* erf(rho) where e2 > 0, 2 erf(rho) elsewhere: G' = 2 s G_u(s^2) (2/sqrt(pi)) exp(-s^4) > 0 (P5);
  G'/s = (4 or 8) exp(-s^4)/sqrt(pi) <= 8/sqrt(pi) (P6).
* rho where e2 > 0, rho^2 elsewhere: G' = 2 s or 4 s^3 > 0 (P5 holds); G'/s = 4 s^2 is unbounded
  on the branch taken at e2 = 0: P6 fails.
* rho where e2 > 0, rho^2 - rho elsewhere: at (1/2, 0), df/de1 = (4 s^3 - 2 s)(1/2)/s = -1/2 < 0
  with e1 > 0: P5 and P6 fail.
kf = sup |psi| over the real line, psi continuous (bound (10)):
* 3 e1^2/(1 + e1^2) + 3 e2^2/(1 + e2^2): psi = 6 e2/(1 + e2^2)^2, psi' = 6 (1 - 3 e2^2)/(1 + e2^2)^3
  vanishes at e2^2 = 1/3: kf = 6 (1/sqrt 3)/(4/3)^2 = 9 sqrt(3)/8 = 1.94855...
* log(1 + e1^2) + e2^2/(1 + e2^2) + e2/4: psi = 2 e2/(1 + e2^2)^2 + 1/4, and 2 s/(1 + s^2)^2
  peaks at s = 1/sqrt 3 with 3 sqrt(3)/8: sup psi = 1/4 + 3 sqrt(3)/8 = 0.89951... (e2 > 0),
  sup -psi = 3 sqrt(3)/8 - 1/4 (e2 < 0): kf = 1/4 + 3 sqrt(3)/8.
* e1^2 + erf(e2^2)/2: psi = 2 e2 exp(-e2^4)/sqrt(pi), peak at e2^4 = 1/4:
  kf = 2^(1/2) exp(-1/4)/sqrt(pi) = 0.62139...; -psi(s) < 0 has sup 0, approached only at 0 and oo.
"""
import pytest
import sympy as sp

from uwmr_symbolic import design_certificate as DC
from uwmr_symbolic.certify import growth_theorems, sign_theorems, sup_upper_theorem
from uwmr_symbolic.kernel import rules as K
from uwmr_symbolic.kernel.certificate import CertificateError
from uwmr_symbolic.kernel.core import derivative
from uwmr_symbolic.profile import S

from test_soundness_regressions import verify

x, y = sp.symbols("e1 e2", real=True)
rho = x ** 2 + y ** 2


def _plane(*exprs):
    return [K.continuous_on_plane(expr=e, x=x, y=y) for e in exprs]


def test_link_needs_f_analytic_and_df_de2_zero_on_the_axis():
    f = x ** 2 + sp.log(1 + y ** 2)
    g = derivative(f, y)
    assert DC._link("P7", f, _plane(f)) == [] and DC._link("P8", f, _plane(f, g)) == []
    with pytest.raises(CertificateError):               # P8 needs df/de2's formula too
        DC._link("P8", f, _plane(f))
    with pytest.raises(CertificateError):               # a claim about another f
        DC._link("P7", f, _plane(f + 1))
    bad = sp.log(1 + rho) + x * y / 10                 # df/de2(e1, 0) = e1/10
    with pytest.raises(CertificateError):
        DC._link("P8", bad, _plane(bad, derivative(bad, y)))
    kink = sp.Abs(x) ** 3 + y ** 2                     # continuous on the plane, but Abs is not analytic
    with pytest.raises(CertificateError):
        DC._link("P7", kink, _plane(kink))


@pytest.mark.slow
@pytest.mark.parametrize("body, p7, p8", [
    ("f = e1**2 + log(1 + e2**2)\n", "proved", "proved"),
    ("f = log(1 + rho + e1**2*e2**2)\n", "proved", "proved"),
    ("f = log(1 + rho) + e1*e2/10\n", "proved", "refuted"),
    ("f = log(log(sp.E + rho))\n", "proved", "proved"),
    # df/de1(s, 0)/s = (e^s - 1)/s: P6's proposal sampled e^(2^30)/2^30 and read it as a Fraction,
    # which ran past --timeout and left P7 and P8 unknown
    ("f = sp.exp(e1) - 1 - e1 + log(1 + e2**2)\n", "proved", "proved"),
])
def test_p7_p8_verdicts_by_the_kernel(tmp_path, body, p7, p8):
    report, v = verify(tmp_path, body)
    assert (v["P7"], v["P8"]) == (p7, p8), report.properties
    if p8 == "proved":
        checks = {c.name: c for c in DC.check(DC.build(report))}
        assert checks["P8"].kernel_checked and checks["P8"].theorems == 2
        assert checks["P7"].kernel_checked


@pytest.mark.slow
@pytest.mark.parametrize("body, p5, p6", [
    ("f = e1**2 + log(1 + e2**2)\n", "proved", "proved"),
    ("f = log(1 + e1**2) + log(1 + e2**2)\n", "proved", "proved"),
    ("f = e1*atan(e1) - log(1 + e1**2)/2 + e2**2\n", "proved", "proved"),
    ("f = e1**4 + e2**2\n", "proved", "refuted"),
    ("f = e1**4 - e1**2 + e2**2\n", "refuted", "refuted"),
])
def test_p5_p6_where_df_de1_depends_on_e1_only(tmp_path, body, p5, p6):
    report, v = verify(tmp_path, body)
    assert (v["P5"], v["P6"]) == (p5, p6), report.properties
    checks = {c.name: c for c in DC.check(DC.build(report))}
    for name, status in (("P5", p5), ("P6", p6)):
        assert checks[name].kernel_checked if status == "proved" else checks[name].refutation_checked, name


def _sides(f):
    phi = derivative(f, x)
    return phi.xreplace({x: S}), -phi.xreplace({x: -S})


def test_p5_p6_links_need_both_sides_of_this_f_and_one_k():
    f = sp.log(1 + x ** 2) + sp.log(1 + y ** 2)
    a, b = _sides(f)
    signs = [K.sign_by_sturm(expr=e, var=S, lo=0, hi=sp.oo, lo_open=True, hi_open=True, want=1) for e in (a, b)]
    assert DC._link("P5", f, _plane(f) + signs) == []
    with pytest.raises(CertificateError):               # one side only
        DC._link("P5", f, _plane(f) + signs[:1])
    with pytest.raises(CertificateError):               # the sides of another f
        g = sp.log(1 + 2 * x ** 2) + sp.log(1 + y ** 2)
        DC._link("P5", g, _plane(g) + signs)
    def upper(e, k):
        gap = K.sign_by_sturm(expr=k - e / S, var=S, lo=0, hi=sp.oo, lo_open=True, hi_open=True, want=1,
                              strict=False)
        return K.sup_upper_by_sign(gap, expr=e / S, bound=k)
    assert DC._link("P6", f, _plane(f) + signs + [upper(a, 2), upper(b, 2)]) == []
    with pytest.raises(CertificateError):               # two different k
        DC._link("P6", f, _plane(f) + signs + [upper(a, 2), upper(b, 3)])
    cross = f + x * y / 10                              # df/de1 depends on e2: no claim about phi(e1) fits
    with pytest.raises(CertificateError):
        DC._link("P5", cross, _plane(cross) + signs)


def test_p1_link_needs_one_bound_on_both_signs_of_df_de2_on_both_half_axes():
    f = x ** 2 + sp.sqrt(1 + y ** 2) - 1
    bounds = [sup_upper_theorem(e, 1, S) for e in DC.e2_sides(f)]
    assert DC._link("P1", f, _plane(f) + bounds) == []
    with pytest.raises(CertificateError):               # three of the four sides
        DC._link("P1", f, _plane(f) + bounds[:3])
    with pytest.raises(CertificateError):               # two different bounds
        DC._link("P1", f, _plane(f) + bounds[:3] + [sup_upper_theorem(DC.e2_sides(f)[3], 2, S)])
    cross = f + x * y / 10                              # df/de2 depends on e1 (and is unbounded)
    with pytest.raises(CertificateError):
        DC._link("P1", cross, _plane(cross) + bounds)
    kink = sp.Abs(x) ** 3 + sp.sqrt(1 + y ** 2) - 1     # bounded df/de2, but Abs: not the analytic route
    with pytest.raises(CertificateError):
        DC._link("P1", kink, _plane(kink) + bounds)


def _separable_claims(f, split=None):
    """The theorems the P3 link of a separable f expects, in order."""
    halves = DC.half_axes(f)
    return (_plane(f) + [K.identity_plane(lhs=f, rhs=DC.axis_split(f) if split is None else split, x=x, y=y)]
            + [sign_theorems(u, S, 0, sp.oo)[0][0] for u in halves] + [growth_theorems(u, S)[0] for u in halves])


def test_p3_link_needs_the_split_and_all_four_half_axes_of_this_f():
    f = x ** 2 + x ** 3 + x ** 4 + sp.log(1 + y ** 2)     # s^2 (1 + s + s^2) > 0 and s^2 (1 - s + s^2) > 0
    good = _separable_claims(f)
    assert DC._link("P3", f, good) == []
    with pytest.raises(CertificateError):               # one divergence missing
        DC._link("P3", f, good[:-1])
    with pytest.raises(CertificateError):               # the positivity of a half-axis twice, another left out
        DC._link("P3", f, good[:2] + [good[2], good[2], good[4], good[5]] + good[6:])
    other = x ** 2 * (1 + x + x ** 2) + sp.log(1 + y ** 2)
    with pytest.raises(CertificateError):               # f = other: true, but not the split
        DC._link("P3", f, good[:1] + _separable_claims(f, split=other)[1:2] + good[2:])
    g = f + x ** 2 * y ** 2                             # P3 holds, but g is not the sum of its axes
    with pytest.raises(CertificateError):
        DC._link("P3", g, _plane(g) + good[1:])
    with pytest.raises(K.KernelError):                  # and the kernel refuses the split of g
        K.identity_plane(lhs=g, rhs=DC.axis_split(g), x=x, y=y)


@pytest.mark.slow
@pytest.mark.parametrize("body, name, verdict", [
    ("f = log(1 + e1**2) + log(1 + e2**2)\n", "P1", "proved"),
    ("f = e1**2 + sqrt(1 + e2**2) - 1\n", "P1", "proved"),
    ("f = e1**2 + log(sp.cosh(e2))\n", "P1", "proved"),
    ("f = sp.exp(e1) - 1 - e1 + log(1 + e2**2)\n", "P1", "proved"),
    ("f = sp.cosh(e1) - 1 + e2**4\n", "P1", "refuted"),
    ("f = log(1 + e1**2) + log(1 + e2**2)\n", "P3", "proved"),
    ("f = e1**2 + sqrt(1 + e2**2) - 1\n", "P3", "proved"),
    ("f = sp.cosh(e1) - 1 + e2**4\n", "P3", "proved"),
    ("f = log(1 + e1**2) + atan(e2**2)\n", "P3", "refuted"),
    ("f = e1**2 + e2**2/(1 + e2**2)\n", "P3", "refuted"),
    ("f = e1**2 - e2**2/(1 + e2**2)\n", "P3", "refuted"),
    ("f = e1**2 + e1 + e2**2\n", "P3", "refuted"),
])
def test_p1_p3_of_a_separable_f(tmp_path, body, name, verdict):
    report, v = verify(tmp_path, body)
    assert v[name] == verdict, report.properties[name]
    check = {c.name: c for c in DC.check(DC.build(report))}[name]
    assert check.kernel_checked if verdict == "proved" else check.refutation_checked
    assert name != "P3" or verdict != "proved" or check.theorems == 10


@pytest.mark.slow
@pytest.mark.parametrize("body, kf", [
    ("f = 3*e1**2/(1 + e1**2) + 3*e2**2/(1 + e2**2)\n", 9 * sp.sqrt(3) / 8),
    ("f = log(1 + e1**2) + e2**2/(1 + e2**2) + e2/4\n", sp.Rational(1, 4) + 3 * sp.sqrt(3) / 8),
    ("f = e1**2 + sp.erf(e2**2)/2\n", sp.sqrt(2) * sp.exp(-sp.Rational(1, 4)) / sp.sqrt(sp.pi)),
])
def test_kf_where_df_de2_depends_on_e2_only(tmp_path, body, kf):
    """The kernel's enclosure of kf holds the value worked out by hand, within 1e-6."""
    report, _ = verify(tmp_path, body)
    assert report.kf is not None and report.kf.kernel_bounds is not None, report.kf
    lower, upper = report.kf.lower, report.kf.upper
    assert lower < kf < upper and upper - lower < 1e-6 * kf
    assert {c.name: c for c in DC.check(DC.build(report))}["kf"].kernel_checked


def test_kf_link_needs_the_four_bounds_a_side_and_its_enclosure():
    f = x ** 2 + sp.sqrt(1 + y ** 2) - 1                # psi = e2/sqrt(1 + e2^2): kf = 1, approached only
    uppers = [sup_upper_theorem(e, 1, S) for e in DC.e2_sides(f)]
    half = sp.Rational(1, 2)
    lower = K.sup_lower_by_point(expr=DC.e2_sides(f)[0], var=S, point=sp.Integer(1), bound=half, lo=0, hi=sp.oo,
                                 lo_open=True, hi_open=True)     # psi(1) = 1/sqrt 2 >= 1/2
    good = _plane(f) + uppers + [lower]
    assert DC._link("kf", f, good, (half, sp.Integer(1))) == []
    assert DC._link("kf", f, good, (sp.Rational(1, 3), sp.Integer(2))) == []
    for bounds in ((sp.Rational(2, 3), sp.Integer(1)), (half, sp.Rational(99, 100))):     # [L, U] not inside
        with pytest.raises(CertificateError):
            DC._link("kf", f, good, bounds)
    with pytest.raises(CertificateError):               # a bound of three sides only
        DC._link("kf", f, good[:4] + good[5:], (half, sp.Integer(1)))
    other = K.sup_lower_by_point(expr=2 * DC.e2_sides(f)[0], var=S, point=sp.Integer(1), bound=half, lo=0, hi=sp.oo,
                                 lo_open=True, hi_open=True)     # about 2 psi, which is no side
    with pytest.raises(CertificateError):
        DC._link("kf", f, good[:5] + [other], (half, sp.Integer(1)))


@pytest.mark.slow
@pytest.mark.parametrize("body, verdict", [
    ("f = sp.Min(rho/2, log(1 + rho))\n", "proved"),
    ("f = sp.Piecewise((log(1 + rho), e1 > 0), (2*log(1 + rho), True))\n", "proved"),
    ("f = sp.Piecewise((log(1 + rho), e1 > 0), (rho/(1 + rho), True))\n", "not proved"),
    ("f = sp.Piecewise((log(1 + rho), e1 > 0), (rho - 1, True))\n", "not proved"),
])
def test_p3_of_a_piecewise_f_whose_every_branch_is_radial(tmp_path, body, verdict):
    report, v = verify(tmp_path, body)
    if verdict == "proved":
        assert v["P3"] == "proved", report.properties["P3"]
        assert {c.name: c for c in DC.check(DC.build(report))}["P3"].kernel_checked
    else:
        assert v["P3"] != "proved", report.properties["P3"]


def _branch_claims(f):
    """The theorems the P3 link of a Piecewise f with radial branches expects, in order."""
    out = []
    for g, _ in sp.piecewise_fold(f).args:
        G = DC.branch_profile(g)
        out += _plane(g) + [K.identity_plane(lhs=g, rhs=G.xreplace({S: sp.sqrt(rho)}), x=x, y=y),
                            sign_theorems(G, S, 0, sp.oo)[0][0], growth_theorems(G, S)[0]]
    return out


def test_p3_link_of_radial_branches_needs_every_branch_and_defined_conditions():
    L = sp.log(1 + rho)
    f = sp.Piecewise((L, x > 0), (2 * L, True))
    good = _branch_claims(f)
    assert len(good) == 8 and DC._link("P3", f, good) == []
    with pytest.raises(CertificateError):               # the second branch's divergence left out
        DC._link("P3", f, good[:-1])
    with pytest.raises(CertificateError):               # the first branch's claims twice, the second's left out
        DC._link("P3", f, good[:4] + good[:4])
    for other in (sp.Piecewise((L, sp.sqrt(x) > 1), (2 * L, True)),     # sqrt(e1) is not real for e1 < 0
                  sp.Piecewise((L, x > 0), (2 * L, y > 0))):             # no branch where x <= 0, y <= 0
        with pytest.raises(CertificateError):
            DC._link("P3", other, _plane(L) + good[1:4] + _plane(2 * L) + good[5:])


@pytest.mark.slow
@pytest.mark.parametrize("body, p5, p6", [
    ("f = sp.Piecewise((sp.erf(rho), e2 > 0), (2*sp.erf(rho), True))\n", "proved", "proved"),
    ("f = sp.Piecewise((rho, e2 > 0), (rho**2, True))\n", "proved", "not proved"),
    ("f = sp.Piecewise((rho, e2 > 0), (rho**2 - rho, True))\n", "not proved", "not proved"),
])
def test_p5_p6_of_a_piecewise_f_chosen_by_e2(tmp_path, body, p5, p6):
    report, v = verify(tmp_path, body)
    checks = {c.name: c for c in DC.check(DC.build(report))}
    for name, verdict in (("P5", p5), ("P6", p6)):
        if verdict == "proved":
            assert v[name] == "proved" and checks[name].kernel_checked, report.properties[name]
        else:
            assert v[name] != "proved", report.properties[name]
    if p6 == "proved":
        k = sp.Rational(report.properties["P6"].details["k"])
        assert k >= 8 / sp.sqrt(sp.pi)                  # sup G'/s over both branches


def test_p5_p6_links_of_branches_need_conditions_free_of_e1_and_one_k():
    f = sp.Piecewise((sp.log(1 + rho), y > 0), (2 * sp.log(1 + rho), True))
    claims = {"P5": [], "P6": []}
    for (g, _), k in zip(f.args, (2, 3)):
        G = DC.branch_profile(g)
        dG = derivative(G, S)
        head = _plane(g) + [K.identity_plane(lhs=g, rhs=G.xreplace({S: sp.sqrt(rho)}), x=x, y=y),
                            sign_theorems(dG, S, 0, sp.oo)[0][0]]
        claims["P5"] += head
        claims["P6"] += head + [sup_upper_theorem(dG / S, 4, S)]
    assert DC._link("P5", f, claims["P5"]) == [] and DC._link("P6", f, claims["P6"]) == []
    with pytest.raises(CertificateError):               # two different k
        G = DC.branch_profile(f.args[1][0])
        DC._link("P6", f, claims["P6"][:-1] + [sup_upper_theorem(derivative(G, S) / S, 5, S)])
    jump = sp.Piecewise((sp.log(1 + rho), x > 0), (2 * sp.log(1 + rho), True))   # P5 fails across e1 = 0
    for name in ("P5", "P6"):
        with pytest.raises(CertificateError):
            DC._link(name, jump, claims[name])
