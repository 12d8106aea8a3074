"""The certified accuracy of generated code (`codegen.accuracy`): the
propagation rules against bounds derived by hand, and the certified bounds
against the errors the compiled code really makes."""
import math
import tempfile
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from flint import arb
from sympy.codegen.cfunctions import log1p

from uwmr_symbolic.codegen import accuracy, build
from uwmr_symbolic.codegen.accuracy import Analysis, Uncertified, _iv, certify
from uwmr_symbolic.codegen.c_backend import DOUBLE, FLOAT
from uwmr_symbolic.codegen.harness import build_library
from uwmr_symbolic.codegen.law import build_model
from uwmr_symbolic.codegen.reference import mp_g
from uwmr_symbolic.kernel.arb import precision
from uwmr_symbolic.properties import Analysis as DesignAnalysis
from uwmr_symbolic.verify import verify_design

X, Y = sp.symbols("x y", positive=True)
U = 2.0 ** -53
ROOT = Path(__file__).resolve().parent.parent


def _bound(expr, box, E=0.0, A=0.0, prec="double", relative=True):
    with precision(128):
        an = Analysis(prec, {X: (_iv(*box), arb(E), arb(A)), Y: (_iv(*box), arb(0), arb(0))})
        if relative:
            return float(an.relative(expr).upper())
        return tuple(float(v.upper()) for v in an.error(expr))


def test_one_rounding_per_operation():
    # x + 1 (same signs): gamma_1 = u; x*y: u; sqrt(x): correctly rounded, u
    assert _bound(X + 1, (1.0, 2.0)) == pytest.approx(U, rel=1e-12)
    assert _bound(X * Y, (1.0, 2.0)) == pytest.approx(U, rel=1e-12)
    assert _bound(sp.sqrt(X), (1.0, 2.0)) == pytest.approx(U, rel=1e-12)
    # x**3 = x*x*x: two roundings; the input's error 1e-10 enters three times
    assert _bound(X ** 3, (1.0, 2.0), E=1e-10) == pytest.approx((1 + 1e-10) ** 3 * (1 + U) ** 2 - 1, rel=1e-9)
    # 1/x: (1 - E)^-1 (1 + u) - 1
    assert _bound(1 / X, (1.0, 2.0), E=1e-10) == pytest.approx((1 - 1e-10) ** -1 * (1 + U) - 1, rel=1e-9)


def test_literals_exact_or_rounded():
    assert _bound(X * sp.Rational(1, 4), (1.0, 2.0)) == pytest.approx(U, rel=1e-12)        # 0.25 exact
    assert _bound(X * sp.Rational(1, 3), (1.0, 2.0)) == pytest.approx(2 * U, rel=1e-6)     # 1/3 rounded


def test_cancellation_is_not_certified():
    # x - 1 vanishes at x = 1: no relative bound
    with pytest.raises(Uncertified):
        _bound(X - 1, (0.5, 2.0))
    # log(1 + x) at x ~ 1e-20: 1 + x loses x; log1p keeps it (the cancellation class)
    assert _bound(sp.log(1 + X), (1e-20, 2e-20)) > 1e3
    assert _bound(log1p(X), (1e-20, 2e-20)) < 40 * U


def test_underflow_is_an_absolute_error():
    # x*x for x ~ 1e-200 underflows: the relative part stays small, the absolute one is a subnormal
    E, A = _bound(X * X, (1e-200, 2e-200), relative=False)
    assert E < 2 * U and A == pytest.approx(2.0 ** -1074, rel=0.01)
    # and no relative bound then (A / x^2 is huge)
    assert _bound(X * X, (1e-200, 2e-200)) > 1e70


def test_function_condition_number():
    # exp(x) with x in [100, 200] and |dx| <= 1e-12 |x|: relative change up to 200 * 1e-12
    E = _bound(sp.exp(X), (100.0, 200.0), E=1e-12)
    assert 200e-12 < E < 1.2 * 200e-12 * math.exp(200 * 1e-12) + 16 * U
    # tanh saturates: far out its argument's error does not matter
    assert _bound(sp.tanh(X), (1e10, 1e12), E=0.1) < 30 * U
    # cosh and sinh over [16, 25] with |dx| <= 1e-15 |x|: the condition number is |x tanh x|
    # resp. |x / tanh x|, at most 25 (sinh(25)/cosh(16) = 8e3 bounds it only from each end apart)
    for f in (sp.cosh, sp.sinh):
        E = _bound(f(X), (16.0, 25.0), E=1e-15)
        assert 25e-15 < E < 25e-15 * 1.01 + 10 * U


def test_overflow_is_not_certified():
    with pytest.raises(Uncertified):
        _bound(X * X, (1e200, 1e201))
    # the quotient itself leaves the range (x / log1p(1/x) ~ x^2 = 2e308): found by the fuzz test
    with pytest.raises(Uncertified):
        _bound(X / log1p(1 / X), (1e153, 1.6e154))


@pytest.fixture(scope="module")
def models():
    out = {}
    for name in ("design1_jiang", "design2_sqrt", "design3_logcosh", "design5_rational", "design4_cosine"):
        rep = verify_design(ROOT / "designs" / f"{name}.py")
        out[name] = (rep, build_model(rep.design, DesignAnalysis(rep.design), rep))
    return out


def test_paper_designs_certified_within_the_goals(models):
    for name in ("design1_jiang", "design2_sqrt", "design3_logcosh", "design5_rational"):
        _, model = models[name]
        for cfg, goal in ((DOUBLE, 1e-9), (FLOAT, 1e-5)):
            acc = certify(model, cfg.precision, cfg.sinc_cut)
            assert acc.g is not None and acc.g <= goal, (name, cfg.precision, acc.lines())
            assert acc.w <= (1e-12 if cfg.precision == "double" else 1e-5), (name, acc.lines())
            # every region is certified except, at most, the last binades of the range
            for r in acc.uncertified:
                assert r.region == "far" and float(r.where.split("> ")[1]) > 1e37, (name, r)


def test_vanishing_gradient_not_certified(models):
    # design 4: F'(s) = sin(s) ds/dS vanishes at s = pi (m ~ 4.02), where the branches switch
    _, model = models["design4_cosine"]
    acc = certify(model, "double", DOUBLE.sinc_cut)
    bad = [r for r in acc.uncertified if r.region == "mid"]
    assert bad and any("4.02" in r.where for r in bad)
    assert any("NOT CERTIFIED" in line for line in acc.lines())


def test_a_cosh_tail_and_its_branch_switch_are_certified(tmp_path):
    """f = sqrt(1 + rho) - 1 + tanh(rho): FAR = 1 (sech(rho)^2 underflows in
    the mid form), so for 1 < m < 5.66 the far branch prints 2 st/cosh(st st)^2
    + 1/sqrt(t t + 1) and switches at t = 0.177 to the form without the cosh.
    Both used to be NOT CERTIFIED: cosh's condition number was enclosed as
    sinh(hi) hi/cosh(lo) (2.6e-5 on 2.59 <= m <= 5.66), and the branch
    switch was compared without st (4 <= m <= 5.66: "unsupported operation")."""
    path = tmp_path / "tanh_tail.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\n"
                    "f = sp.sqrt(1 + rho) - 1 + sp.tanh(rho)\n")
    rep = verify_design(path)
    model = build_model(rep.design, DesignAnalysis(rep.design), rep)
    assert [br.expr.has(sp.cosh) for br in model.far] == [False, True]
    for cfg, goal in ((DOUBLE, 1e-12), (FLOAT, 4e-6)):
        acc = certify(model, cfg.precision, cfg.sinc_cut)
        assert acc.uncertified == [] and acc.g <= goal, (cfg.precision, acc.lines())


def _measured_g(files, stem, rows, f32):
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in files.items():
            (Path(tmp) / name).write_text(text)
        lib = build_library(tmp, stem, tmp)
        v, w, st = lib.run(rows, f32=f32)
    return w, st


@pytest.mark.slow
@pytest.mark.parametrize("name", ["design1_jiang", "design2_sqrt", "design3_logcosh", "design5_rational"])
def test_certified_bound_holds_for_compiled_code(models, name):
    """lam = vr = 1, e3 = wr = k2 = 0: w = g exactly, so the C output's
    error against g in 50-digit mpmath must be within the certified bound
    of its region, at random inputs of every magnitude."""
    rep, model = models[name]
    _, files = build(ROOT / "designs" / f"{name}.py", force=True, report=rep)
    rng = np.random.default_rng(7)
    for cfg, top in ((DOUBLE, 300), (FLOAT, 37)):
        acc = certify(model, cfg.precision, cfg.sinc_cut)
        mags = 10.0 ** rng.uniform(-top, top, 300)
        angles = rng.uniform(0, 2 * np.pi, 300)
        rows = np.zeros((300, 8))
        rows[:, 0], rows[:, 1] = mags * np.cos(angles), mags * np.sin(angles)
        rows[:, 3], rows[:, 7] = 1.0, 1.0
        if cfg is FLOAT:
            rows = rows.astype(np.float32).astype(np.float64)
        w, st = _measured_g(files, model.stem, rows, cfg is FLOAT)
        tiny_normal = accuracy.MIN_NORMAL[cfg.precision]
        checked = 0
        for (e1, e2), got, status in zip(rows[:, :2], w, st):
            exact = float(mp_g(rep.design, e1, e2))
            if status != 0 or abs(exact) < tiny_normal * 4 or max(abs(e1), abs(e2)) > 1e37:
                continue
            assert abs(got - exact) <= acc.g * abs(exact), (name, cfg.precision, e1, e2, got, exact, acc.g)
            checked += 1
        assert checked > 50


def test_partial_product_underflow_counts():
    # (x * y) * 1e300 with x, y ~ 1e-200: x*y underflows to 0 though the result 1e-100 is normal
    assert _bound(X * Y * sp.Integer(10) ** 300, (1e-200, 2e-200)) > 1e50
    # x*y*1e-10 at x, y ~ 1: nothing underflows, one relative rounding per product (+ the literal)
    assert _bound(X * Y * sp.Rational(1, 10 ** 10), (1.0, 2.0)) < 4 * U


def test_first_violation_finds_a_broken_certificate(models):
    """The validation's check of the certificate can fail: the true bounds
    pass on the validation sample, bounds a million times too small do not."""
    import dataclasses
    from uwmr_symbolic.codegen import _kf_upper_double, reference
    from uwmr_symbolic.codegen.validate import sample_inputs
    rep, model = models["design1_jiang"]
    _, files = build(ROOT / "designs" / "design1_jiang.py", report=rep)
    acc = certify(model, "double", DOUBLE.sinc_cut)
    x = sample_inputs(model, "double", (0.25, 0.7, 0.3), 200, 5)
    ref = reference.table(reference.Law.of(rep.design), x)
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in files.items():
            (Path(tmp) / name).write_text(text)
        v, w, st = build_library(tmp, model.stem, tmp).run(x)
    kf = _kf_upper_double(model.kf_upper)
    assert accuracy.first_violation(acc, x, ref, v, w, st, kf) is None
    tight = dataclasses.replace(acc, v=acc.v * 1e-6, w=acc.w * 1e-6, absolute=0.0)
    assert accuracy.first_violation(tight, x, ref, v, w, st, kf) is not None


def test_generation_refuses_code_outside_its_certificate(models, tmp_path, monkeypatch):
    """The validation checks the header's certified bounds: with bounds a
    million times too small, generation is refused and nothing written."""
    import dataclasses
    from uwmr_symbolic.codegen import CodegenInvalid, generate
    real = accuracy.certify

    def too_tight(model, precision, cut):
        acc = real(model, precision, cut)
        return dataclasses.replace(acc, v=acc.v * 1e-6, w=acc.w * 1e-6, absolute=0.0)
    monkeypatch.setattr(accuracy, "certify", too_tight)
    rep, _ = models["design1_jiang"]
    with pytest.raises(CodegenInvalid, match="outside the certified accuracy"):
        generate(ROOT / "designs" / "design1_jiang.py", out_dir=tmp_path / "out", report=rep)
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("name", ["design1_jiang", "design3_logcosh"])
def test_term_bound_holds_where_sinc_is_below_the_normal_range(models, name):
    """e = (0, 1), vr = 1, wr = k1 = k2 = 0: w is the term lam g(0, 1) sin(e3)/e3.
    For |e3| near the largest number sin(e3)/e3 is subnormal (it lost up to 8
    digits, an error of 1.2e-10 in double and 7.9e-3 in float was measured,
    against certified bounds of about 1e-14 and 1e-6), while with a large lam
    the term is a normal number, where the header certifies it (the term
    bound of the region of m = 1).  Checked in C (double and float) and in
    both Python entry points against mpmath."""
    import mpmath
    from uwmr_symbolic.codegen.validate import load_module
    rep, model = models[name]
    _, files = build(ROOT / "designs" / f"{name}.py", report=rep)
    g = mp_g(rep.design, 0.0, 1.0)
    for cfg, e3s, lam in ((DOUBLE, [1.000066427752305e308, 1.7976931348623157e308, -9e307], 1e10),
                          (FLOAT, [1.0156026172643704e38, 3.4028234663852886e38, -2e38], 1e6)):
        rows = np.zeros((len(e3s), 8))
        rows[:, 1], rows[:, 2], rows[:, 3], rows[:, 7] = 1.0, e3s, 1.0, lam
        if cfg is FLOAT:
            rows = rows.astype(np.float32).astype(np.float64)
        with mpmath.workdps(60):
            exact = [float(lam * g * mpmath.sin(mpmath.mpf(e3)) / mpmath.mpf(e3)) for e3 in rows[:, 2]]
        assert all(abs(x) > accuracy.MIN_NORMAL[cfg.precision] for x in exact)    # the term is normal
        bound = next(r.term for r in certify(model, cfg.precision, cfg.sinc_cut).certified
                     if r.m_range[0] <= 1.0 <= r.m_range[1])
        w, st = _measured_g(files, model.stem, rows, cfg is FLOAT)
        results = [("C " + cfg.precision, w, st)]
        if cfg is DOUBLE:
            with tempfile.TemporaryDirectory() as tmp:
                (Path(tmp) / f"{model.stem}.py").write_text(files[f"{model.stem}.py"])
                mod = load_module(Path(tmp) / f"{model.stem}.py", model.stem)
            cols = [rows[:, i] for i in range(8)]
            results += [("Python control_status", *mod.control_status(*cols)[1:]),
                        ("Python control", mod.control(*cols)[1], np.zeros(len(rows)))]
        for what, got, status in results:
            for x, y, s in zip(exact, got, status):
                assert s == 0 and abs(y - x) <= bound * abs(x), (what, x, y, bound)


def test_python_fast_path_never_clamps_an_overflow_into_a_finite_w(tmp_path):
    """f = log(1 + rho): H = F'(s)/s = 2/(1 + rho) is 2 > KF = 1 near the
    origin, so lam vr H overflows where lam |vr| KF does not.  The fast path
    of `control` clamped that inf to lam |vr| KF (1e308 at the first row,
    exact 1.92e305) and returned it; it must take the careful path, which
    agrees with `control_status` and with the exact law (mpmath)."""
    import mpmath
    from uwmr_symbolic.codegen import generate
    from uwmr_symbolic.codegen.validate import load_module
    design = tmp_path / "logrho.py"
    design.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nf = sp.log(1 + e1**2 + e2**2)\n")
    generate(design, out_dir=tmp_path / "out")
    mod = load_module(tmp_path / "out" / "logrho.py", "logrho")
    rows = [(1e-3, 1e-3, 0.5, 1e154, 0.0, 0.0, 0.0, 1e154),
            (0.7, 0.7, math.pi, 1.0, 0.0, 0.0, 0.0, 1.7976931348623157e308),
            (1e-50, 1e-50, 0.5, 1.0, 0.0, 0.0, 0.0, 1.7976931348623157e308)]
    for e1, e2, e3, vr, wr, k1, k2, lam in rows:
        with mpmath.workdps(60):
            E1, E2, E3, LV = (mpmath.mpf(x) for x in (e1, e2, e3, lam))
            exact = float(LV * vr * 2 * E2 / (1 + E1 ** 2 + E2 ** 2) * mpmath.sin(E3) / E3)
        assert math.isfinite(exact)
        for entry in (mod.control, lambda *a: mod.control_status(*a)[:2]):
            w = entry(e1, e2, e3, vr, wr, k1, k2, lam)[1]
            assert abs(w - exact) <= 1e-14 * abs(exact), (e1, e3, lam, w, exact)
        # the same rows as arrays (the fast path is tried on whole arrays)
        w = mod.control(*[np.full(3, x) for x in (e1, e2, e3, vr, wr, k1, k2, lam)])[1]
        assert np.all(np.abs(w - exact) <= 1e-14 * abs(exact))


def test_printed_bounds_are_never_below_the_certified_ones(models):
    """The header rounds each certified bound up to two digits (it rounded to
    nearest: design 3's term bound 4.3xe-14 printed as 4.3e-14), and the ends
    of a range NOT CERTIFIED outwards (8.507e37 printed as 8.51e37 left
    8.507e37..8.51e37 promised)."""
    import re
    from uwmr_symbolic.codegen.accuracy import _above, _range
    assert [_above(x) for x in (3.34e-15, 4.301e-14, 9.97e-7, 2.5e-15)] == ["3.4e-15", "4.4e-14", "1e-06", "2.5e-15"]
    assert _range(8.507059e37, 1e39, widen=True) == "m > 8.5e+37"
    assert _range(1.234e-5, 5.678e3, widen=True) == "1.23e-05 <= m <= 5.68e+03"
    _, model = models["design3_logcosh"]
    for cfg in (DOUBLE, FLOAT):
        acc = certify(model, cfg.precision, cfg.sinc_cut)
        text = " ".join(acc.lines())
        printed = lambda what: float(re.search(what + r" <= ([0-9.e+-]+)", text).group(1))   # noqa: E731
        assert printed(r"\|g\^ - g\|") >= acc.g
        assert printed(r"\|term\^ - term\|") >= max(r.term for r in acc.certified)
        assert printed(r"\|v\^ - v\|") >= acc.v and printed(r"\|w\^ - w\|") >= acc.w
        for r in acc.certified:
            assert float(re.search(re.escape(r.where) + r": g within ([0-9.e+-]+?)\.( |$)", text).group(1)) >= r.g


def test_the_near_polynomial_and_its_remainder_bound_hold():
    """law._taylor_polynomial for F'(s) = atan(s) - s/(1 + s^2), whose H =
    F'(s)/s is (atan(s) - s/(1 + s^2))/s, all digits lost near 0: below
    rho = 1/16 the polynomial P (odd series of F', 2/3 s^3 - 4/5 s^5 + ...,
    divided by s) and its bound must satisfy |H - P| <= bound at 60 digits,
    the bound must be tiny against H, and its first coefficient is 2/3."""
    import mpmath
    from uwmr_symbolic.codegen.law import RHO, S, _taylor_polynomial
    dF = sp.atan(S) - S / (1 + S ** 2)
    cut = sp.Rational(1, 16)
    poly, bound, degree = _taylor_polynomial(dF, cut, 2.0 ** -52)
    assert degree % 2 == 1 and degree >= 21
    assert sp.expand(poly).coeff(RHO, 1) == pytest.approx(2 / 3, rel=1e-28) and sp.expand(poly).coeff(RHO, 0) == 0
    P, B = sp.lambdify(RHO, poly, "mpmath"), sp.lambdify(RHO, bound, "mpmath")
    for r in ["0.0625", "0.05", "1e-3", "1e-9", "1e-40"]:
        with mpmath.workdps(60 + 2 * len(r)):     # the exact H cancels too: digits for it
            r = mpmath.mpf(r)
            s = mpmath.sqrt(r)
            H = (mpmath.atan(s) - s / (1 + r)) / s
            assert abs(H - P(r)) <= B(r) <= 2.0 ** -52 * abs(H), r
    # a bound that is not bounding: the same polynomial with one coefficient moved is caught
    with mpmath.workdps(60):
        r = mpmath.mpf("0.05")
        H = (mpmath.atan(mpmath.sqrt(r)) - mpmath.sqrt(r) / (1 + r)) / mpmath.sqrt(r)
        assert abs(H - (P(r) + r * mpmath.mpf("1e-17"))) > B(r)
