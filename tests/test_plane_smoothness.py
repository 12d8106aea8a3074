"""P7 and P8 of an f that is analytic on the whole plane (issue 9: "unknown
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
"""
import pytest
import sympy as sp

from uwmr_symbolic import design_certificate as DC
from uwmr_symbolic.kernel import KernelError, check_certificate, rules as K, to_certificate
from uwmr_symbolic.kernel.certificate import CertificateError
from uwmr_symbolic.kernel.core import derivative

from test_soundness_regressions import verify

x, y = sp.symbols("e1 e2", real=True)
rho = x ** 2 + y ** 2


@pytest.mark.parametrize("expr", [x ** 2 + sp.log(1 + y ** 2), sp.log(1 + rho + x ** 2 * y ** 2),
                                  sp.atan(x * y) + sp.exp(-x ** 2), x / (1 + x ** 2), sp.log(sp.E - 1 + rho),
                                  sp.sqrt(2 + x ** 2) * sp.cosh(y)])
def test_defined_on_the_plane(expr):
    t = K.continuous_on_plane(expr=expr, x=x, y=y)
    assert (t.claim.kind, t.claim.var, t.claim.lo, t.claim.hi) == ("continuous", sp.srepr(sp.Tuple(x, y)), "-oo", "oo")
    assert t.claim.expr == sp.srepr(expr) and t.assumptions == {"sympy-core"}


@pytest.mark.parametrize("expr", [sp.log(rho), 1 / x, sp.sqrt(1 + x), sp.log(x ** 2 - sp.Rational(1, 2)),
                                  sp.sqrt(rho), rho ** sp.Rational(3, 2), sp.log(1 + sp.sin(x))])
def test_not_defined_everywhere_is_refused(expr):
    # log rho, 1/e1 at the origin; sqrt(1 + e1) for e1 < -1; log(e1^2 - 1/2) near 0;
    # sqrt(rho) and rho^(3/2) are defined but their base is not > 0 (not shown analytic);
    # log(1 + sin e1) at e1 = -pi/2
    with pytest.raises(KernelError):
        K.continuous_on_plane(expr=expr, x=x, y=y)


def test_variables_must_be_real_of_either_sign():
    p = sp.Symbol("p", positive=True)
    with pytest.raises(KernelError, match="must be declared real only"):
        K.continuous_on_plane(expr=p ** 2 + y ** 2, x=p, y=y)
    with pytest.raises(KernelError, match="symbols other than"):
        K.continuous_on_plane(expr=p + y ** 2, x=x, y=y)


def test_tampered_plane_claim_is_rejected():
    cert = to_certificate([K.continuous_on_plane(expr=sp.log(1 + rho), x=x, y=y)])
    assert check_certificate(cert)[0].claim.var == sp.srepr(sp.Tuple(x, y))
    cert["theorems"][0]["data"]["expr"] = {"$": sp.srepr(sp.log(rho))}
    cert["theorems"][0]["claim"]["expr"] = sp.srepr(sp.log(rho))
    with pytest.raises(CertificateError, match="not shown defined on the plane"):
        check_certificate(cert)


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
])
def test_p7_p8_verdicts_by_the_kernel(tmp_path, body, p7, p8):
    report, v = verify(tmp_path, body)
    assert (v["P7"], v["P8"]) == (p7, p8), report.properties
    if p8 == "proved":
        checks = {c.name: c for c in DC.check(DC.build(report))}
        assert checks["P8"].kernel_checked and checks["P8"].theorems == 2
        assert checks["P7"].kernel_checked
