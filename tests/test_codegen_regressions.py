"""Regression tests for the seven classes of wrong generated code of issue 8,
each on a small proved design (tests/designs_codegen/, and v08 of
tests/designs/) at the issue's inputs.  Each design is generated with
`generate` (which validates before writing), compiled with the strict
flags, and its C double, C float and Python results at the issue's inputs
are compared with the exact law (`validate.check`: status 0, finite,
error <= 1e-12 / 1e-5 of the scale, bound (10))."""
from __future__ import annotations

import math
import shutil
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from uwmr_symbolic.codegen import generate, reference
from uwmr_symbolic.codegen.harness import build_library
from uwmr_symbolic.codegen.validate import check, load_module
from uwmr_symbolic.design import load_design

ROOT = Path(__file__).resolve().parent
pytestmark = [pytest.mark.slow, pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc")]


def _generated(path: Path, tmp: Path):
    written = generate(path, tmp / path.stem)
    assert sorted(p.name for p in written) == sorted([*(f"{path.stem}{x}" for x in (".c", ".h", ".py")),
                                                      "example_main.c", "CMakeLists.txt"])
    lib = build_library(tmp / path.stem, path.stem, tmp)
    mod = load_module(tmp / path.stem / f"{path.stem}.py", f"regression_{path.stem}")
    return lib, mod


def _law_rows(e_pairs, lam=1.0, vr=1.0):
    """w = lam vr g(e1, e2) exactly (e3 = 0, wr = k2 = 0), so the check
    measures g's relative error."""
    return np.array([[e1, e2, 0.0, vr, 0.0, 0.0, 0.0, lam] for e1, e2 in e_pairs])


def _check_all(path, tmp, rows_double, rows_float=None, python=True):
    lib, mod = _generated(path, tmp)
    design = load_design(path)
    law = reference.Law.of(design)
    kf = mod.KF
    ref = reference.table(law, rows_double)
    v, w, st = lib.run(rows_double)
    check(path.stem, "C double", rows_double, ref, v, w, st, "double", kf)
    if python:
        v, w, st = mod.control_status(*rows_double.T)
        check(path.stem, "Python", rows_double, ref, v, w, st, "double", kf)
    if rows_float is not None:
        xf = rows_float.astype(np.float32).astype(np.float64)
        ref = reference.table(law, xf)
        v, w, st = lib.run(xf, f32=True)
        check(path.stem, "C float", xf, ref, v, w, st, "float", kf)
    return lib, mod, law


def test_printer_power_of_a_sum(tmp_path):
    """rho/sqrt(1 + rho): H holds (rho + 1)**(3/2); g(0, 1) = 1.0607, not 1.2426."""
    path = ROOT / "designs_codegen/c1_rho_over_sqrt.py"
    rows = _law_rows([(0.0, 1.0), (0.3, -0.7), (2.0, 3.0)])
    _, mod, _ = _check_all(path, tmp_path, rows, rows)
    assert mod.control(0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)[1] == pytest.approx(3 / 2 ** 1.5, rel=1e-15)
    # printed as the error analysis bounds it (the elimination of common subexpressions used to
    # factor it back into (rho + 1.0)*sqrt(rho + 1.0), which the analysis never saw)
    assert "(rho + 2.0)/(rho*sqrt(rho + 1.0) + sqrt(rho + 1.0))" in \
        (tmp_path / "c1_rho_over_sqrt/c1_rho_over_sqrt.c").read_text()


@pytest.mark.parametrize("stem, pairs", [("c2_log_squared", [(0.0, 2e154), (1e200, -1e200), (0.0, 1e300)]),
                                         ("c2_log_log", [(0.0, 1e300), (0.0, -1e300), (3e307, 1e308)])])
def test_tail_without_underflowing_powers_of_t(tmp_path, stem, pairs):
    """The tail formed tt*tt = 0, then log(x1/x0) = inf: status 4 on a finite input."""
    rows = np.concatenate([_law_rows(pairs), _law_rows(pairs, lam=1e300, vr=1e8)])
    _check_all(ROOT / f"designs_codegen/{stem}.py", tmp_path, rows, _law_rows([(0.0, 3e38), (1e30, 1e35)]))


def test_tail_asinh_is_not_silently_zero(tmp_path):
    """log(1 + asinh rho) beyond |e| ~ 1.3e154: asinh(1/(tt*tt)) = inf gave g = 0, status 0."""
    pairs = [(0.0, 2e154), (1e200, 1e200), (0.0, 1.7e308)]
    rows = np.concatenate([_law_rows(pairs), _law_rows(pairs, lam=1e300, vr=1e10)])
    _, mod, _ = _check_all(ROOT / "designs_codegen/c3_log_asinh.py", tmp_path, rows)
    assert mod.control(0.0, 2e154, 0.0, 1.0, 0.0, 0.0, 0.0, 1e300)[1] > 0


def test_cancellation_small_rho(tmp_path):
    """2 sqrt(1 + rho) - 2 - log(1 + rho): g had relative error ~1 for small rho
    (and 1.4 in float at |e| = 3e-4)."""
    pairs = [(0.0, 1e-5), (0.0, 3e-4), (2e-9, 1e-9), (0.0, 1e-20), (1e-60, -1e-60), (0.1, 0.0)]
    rows = _law_rows(pairs, lam=1.0)
    _check_all(ROOT / "designs_codegen/c4_cancel.py", tmp_path, rows,
               _law_rows([(0.0, 3e-4), (1e-3, 2e-3), (0.0, 1e-8)]))


def test_no_math_macros_and_the_strict_build(tmp_path):
    """v08: SymPy printed M_PI_2, M_2_SQRTPI, ... (not C99); float promoted to double."""
    path = ROOT / "designs/v08_atan_integral.py"
    rows = _law_rows([(1.0, 2.0), (0.0, 1e300), (1e-200, 0.5)])
    _check_all(path, tmp_path, rows, _law_rows([(1.0, 2.0), (0.0, 1e30)]))
    for name in ("v08_atan_integral.c", "v08_atan_integral.h"):
        assert "M_" not in (tmp_path / "v08_atan_integral" / name).read_text().replace("UWMR_", "")


def test_erf_design_python_runs_vectorised(tmp_path):
    """F'(s) = erf(s): the module called math.erf without importing math."""
    path = ROOT / "designs_codegen/c6_erf.py"
    rows = _law_rows([(0.3, 0.4), (2.0, -1.0), (1e-8, 1e-8), (0.0, 1e200)])
    _, mod, _ = _check_all(path, tmp_path, rows, rows[:3])
    e = np.linspace(0.1, 3.0, 50)
    v, w = mod.control(e, -e, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)
    assert w.shape == (50,) and np.all(np.isfinite(w)) and np.all(w < 0)


def test_float_overflow_below_the_far_threshold(tmp_path):
    """log(1 + rho^5)/10: rho^5 overflowed float for |e| > 6.9e3, below FAR = 1e4."""
    rows_f = _law_rows([(0.0, 1e4), (0.0, 8e3), (7e3, 7e3), (0.0, 5e3), (0.0, 1e-5)])
    _check_all(ROOT / "designs_codegen/c7_rho5.py", tmp_path, _law_rows([(0.0, 1e4), (1e-40, 1e-39)]), rows_f)


def test_series_at_zero_with_a_relative_next_term_of_order_s(tmp_path):
    """s - log(1 + s): no tiny region was built, 0/0 at rho = 0 (found after the seven)."""
    pairs = [(0.0, 1e-300), (1e-200, -1e-200), (0.0, 5e-324), (1e-20, 0.0)]
    rows = np.concatenate([_law_rows(pairs), _law_rows(pairs, lam=1e300, vr=1e300)])
    _check_all(ROOT / "designs_codegen/c8_s_minus_log.py", tmp_path, rows, _law_rows([(0.0, 1e-40), (1e-13, 1e-13)]))


def test_piecewise_erf_join_tail_does_not_divide_by_zero(tmp_path):
    """Found by make fuzz-codegen: the tail form D(t) = (3 + e exp(-(3t - 2)^2/t^2))/2
    divided by tt*tt, which underflows to 0 for |e| > ~1e162 (float ~1e23); now
    (2 st - 3)^2 (`law.absorb_t_powers`).
    F = s^2 inside the unit circle, 3s/2 + (e sqrt(pi)/8) (erf(2s - 3) + erf(1)) - 1/2 outside
    (an exact C^2 join of the fuzzer's grammar): the sanitizer build at |e| >= 1e162."""
    from codegen_fuzz_grammar import c2_join, design_source     # tests/ is on sys.path (rootdir conftest)
    from uwmr_symbolic.codegen.harness import build_executable, run_executable
    path = tmp_path / "pw_erf.py"
    path.write_text(design_source(c2_join(1, 1, "erf", 1, 2)[0]))
    pairs = [(0.0, 1e162), (0.0, -1e300), (1e200, 1e200), (0.0, 1.7e308)]
    lib, _, _ = _check_all(path, tmp_path, _law_rows(pairs), _law_rows([(0.0, 1e20), (1e30, 3e38)]))
    exe = build_executable(tmp_path / path.stem, path.stem, tmp_path,
                           extra=("-O1", "-g", "-fsanitize=address,undefined,float-divide-by-zero",
                                  "-fno-sanitize-recover=all"))
    for f32, rows in ((False, _law_rows(pairs)), (True, _law_rows([(0.0, 1e20), (1e30, 3e38)]))):
        v, w, st, res = run_executable(exe, rows, tmp_path, f32=f32)
        assert res.returncode == 0 and "runtime error" not in res.stderr, f"sanitizer: {res.stderr}"


def test_exp_of_a_negative_power_of_t_does_not_divide_by_zero(tmp_path):
    """Found by a code-generation campaign: the tail form D(t) = s exp(-1/t^2)
    + 1/sqrt(t^2 + 1) printed exp(-1.0/x0) with x0 = tt*tt, which underflows
    to 0 for |e| > ~1e154 (float ~1e19): a division by zero for the sanitizer,
    although exp(-inf) = 0 gave the right w.  It was then printed exp(-(st*st));
    now the term is left out of the far region, where it is below 2^-80 of
    the rest (`law.split_vanishing`), and 1/t^2 is never formed.  F'(s) =
    s/sqrt(1 + s^2) + s exp(-s^2), so w = lam vr F'(s) e2/s -> 1 on e1 = 0."""
    from uwmr_symbolic.codegen.harness import build_executable, run_executable
    path = ROOT / "designs_codegen" / "c11_exp_of_rho_tail.py"
    generate(path, tmp_path / path.stem, force=True)
    assert "exp(-1.0/" not in (tmp_path / path.stem / f"{path.stem}.c").read_text()
    exe = build_executable(tmp_path / path.stem, path.stem, tmp_path,
                           extra=("-O1", "-g", "-fsanitize=address,undefined,float-divide-by-zero",
                                  "-fno-sanitize-recover=all"))
    law = reference.Law.of(load_design(path))
    for f32, pairs in ((False, [(0.0, 1e200), (1e300, -1e300), (0.0, 1.7e308), (3.0, 4.0)]),
                       (True, [(0.0, 1e30), (1e20, 1e20), (3.0, 4.0)])):
        rows = _law_rows(pairs)
        rows = rows.astype(np.float32).astype(np.float64) if f32 else rows
        v, w, st, res = run_executable(exe, rows, tmp_path, f32=f32)
        assert res.returncode == 0 and "runtime error" not in res.stderr, f"sanitizer: {res.stderr}"
        check(path.stem, "C float" if f32 else "C double", rows, reference.table(law, rows), v, w, st,
              "float" if f32 else "double")
        assert w[0] == pytest.approx(1.0, rel=1e-12 if not f32 else 1e-6)


def test_a_law_without_e1_builds_with_the_strict_flags(tmp_path):
    """Separable f = log(1 + e1^2) + log(1 + e2^2): df/de2 = 2 e2/(1 + e2^2)
    has no e1, and gterm_law's unused parameter stopped the -Werror build
    (found by a simulation campaign; the design refutes P4, so only --force
    code).  Written and compiled without the validation, which such a general
    (non-radial) form still fails at |e2| near the largest double."""
    from uwmr_symbolic.codegen import build, install
    from uwmr_symbolic.verify import verify_design
    path = tmp_path / "sep.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\n"
                    "f = sp.log(1 + e1**2) + sp.log(1 + e2**2)\n")
    _, files = build(path, force=True, report=verify_design(path))
    assert "(void)e1;" in files["sep.c"] and "(void)e2;" not in files["sep.c"]
    install(files, tmp_path / "sep")
    lib = build_library(tmp_path / "sep", "sep", tmp_path)
    v, w, st = lib.run(_law_rows([(5.0, 1.0), (0.0, 3.0)]))
    assert (st == 0).all() and w == pytest.approx([1.0 * 2 / 2, 1.0 * 6 / 10], rel=1e-15)


def test_a_design_name_with_comment_and_docstring_delimiters(tmp_path):
    """A name holding */, /*, triple quotes and a backslash ended the strict
    C build ("/*" within comment) or would end the Python docstring: in
    comments it is written harmlessly, and NAME keeps it exactly."""
    path = tmp_path / "odd_name.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\n"
                    "name = 'A */ b /* c \"\"\" \\\\N{BULLET}'\nf = sp.log(1 + e1**2 + e2**2) / 2\n")
    _, mod = _generated(path, tmp_path)
    assert mod.NAME == 'A */ b /* c """ \\N{BULLET}'
    header = (tmp_path / "odd_name" / "odd_name.h").read_text()
    assert " * Control law (9) for A * / b / * c \'\'\' /N{BULLET}:" in header


def test_piecewise_branch_chosen_from_the_exact_rho(tmp_path):
    """Design 4 (NOT VERIFIED, f jumps at rho = (pi + 1)^2 - 1): in float, e2 =
    4.0190534591674805 has rho 1e-6 above the switch, but rho rounded to float
    equalled the rounded switch, and the inner branch was taken (error 0.2).
    `rho_cmp` decides the branch from e1^2 + e2^2 without rounding."""
    path = ROOT.parent / "designs" / "design4_cosine.py"
    written = generate(path, tmp_path / path.stem, force=True)
    assert written
    lib = build_library(tmp_path / path.stem, path.stem, tmp_path)
    law = reference.Law.of(load_design(path))
    for f32, e2s in ((True, [4.0190534591674805, 4.019053]), (False, [4.0190534591674805, 4.019053459167480])):
        rows = _law_rows([(0.0, e) for e in e2s] + [(e, 0.0) for e in e2s])
        if f32:
            rows = rows.astype(np.float32).astype(np.float64)
        ref = reference.table(law, rows)
        v, w, st = lib.run(rows, f32=f32)
        check(path.stem, "C float" if f32 else "C double", rows, ref, v, w, st, "float" if f32 else "double")


def test_the_exact_rhos_branch_in_python_and_casadi_too(tmp_path):
    """Design 4 again: at (2.2057465672105434, 3.359683287083449) rho is
    1.0e-16 below the switch (pi + 1)^2 - 1 but its rounding 3.6e-15 above
    it; F' jumps there (sin s/(s + 1) against 1/(s + 1)), so the outer branch
    that the Python module and the CasADi function took from the rounded rho
    gave w 0.24 off.  Both now take the branch from the exact rho, as C."""
    from uwmr_symbolic.codegen import casadi_function
    path = ROOT.parent / "designs" / "design4_cosine.py"
    generate(path, tmp_path / path.stem, force=True)
    mod = load_module(tmp_path / path.stem / f"{path.stem}.py", "regression_design4_python")
    law = reference.Law.of(load_design(path))
    rows = _law_rows([(2.2057465672105434, 3.359683287083449), (3.359683287083449, -2.2057465672105434)])
    ref = reference.table(law, rows)
    v, w, st = mod.control_status(*rows.T)
    check(path.stem, "Python", rows, ref, v, w, st, "double")
    fn = casadi_function(path, force=True)
    out = fn.map(len(rows))(*[rows[:, i][None, :] for i in range(8)])
    check(path.stem, "CasADi", rows, ref, np.asarray(out[0]).ravel(), np.asarray(out[1]).ravel(),
          np.zeros(len(rows), dtype=int), "double")


def test_the_python_branch_test_reads_rho_only_where_its_sign_is_the_exact_sign(tmp_path):
    """The Python `_rho_cmp` takes the sign of rho - bh where |rho - bh| >
    2^-50 bh and runs Dekker and TwoSum only on the others (design 4's
    control: 100 -> 69 ms per 10^6 inputs).  Around its boundary, at relative
    distances 10^-17 ... 10^-12 (either side of the cut 8.9e-16), the sign
    must be that of e1^2 + e2^2 - (bh + bl) in exact rationals; a cut of
    2^-53 bh, or none, gives wrong signs here."""
    from uwmr_symbolic.codegen.law import split_boundary
    path = ROOT.parent / "designs" / "design4_cosine.py"
    generate(path, tmp_path / path.stem, force=True)
    mod = load_module(tmp_path / path.stem / f"{path.stem}.py", "regression_design4_rho_cmp")
    import sympy as sp
    bh, bl = split_boundary((1 + sp.pi) ** 2 - 1)
    near = bh * 2.0 ** -50
    rng = np.random.default_rng(7)
    e1 = rng.uniform(0.0, 3.9, 20_000)
    rel = 10.0 ** rng.uniform(-17, -12, e1.size) * rng.choice([-1.0, 1.0], e1.size)
    e2 = np.sqrt(bh * (1 + rel) - e1 * e1)
    rho = e1 * e1 + e2 * e2
    got = mod._rho_cmp(rho, e1, e2, bh, float(bl), near)
    b = Fraction(bh) + Fraction(str(bl))
    exact = np.array([np.sign(float(Fraction(x) ** 2 + Fraction(y) ** 2 - b)) for x, y in zip(e1, e2)])
    assert (np.abs(rho - bh) <= near).sum() > 1000 and (np.abs(rho - bh) > near).sum() > 1000
    assert (got != np.sign(rho - bh)).sum() > 100        # rounding moves rho across b at many of them
    assert np.array_equal(got, exact)


def test_a_rounded_rho_beyond_a_boundary_with_an_odd_last_bit_stays_in_the_branch(tmp_path):
    """c12: the branch below b = 7881299444482489/2^52 holds (b - rho)^(3/2) in
    its F'.  At points where rho < b but e1*e1 + e2*e2 rounds above b (the
    rows of `validate.rounding_crossings`), the C double code took that
    branch (from the exact rho) with the rounded rho: a NaN, and status 4
    where v and w are finite.  The rounded rho is now brought into the branch's ends."""
    from uwmr_symbolic.codegen.law import build_model
    from uwmr_symbolic.codegen.validate import rounding_crossings
    from uwmr_symbolic.properties import Analysis
    path = ROOT / "designs_codegen" / "c12_join_odd_last_bit.py"
    design = load_design(path)
    pairs = rounding_crossings(build_model(design, Analysis(design), precisions=("double",)), "double")
    b = Fraction(7881299444482489, 2 ** 52)
    assert len(pairs) == 8 and all((Fraction(x) ** 2 + Fraction(y) ** 2 - b) * (Fraction(x * x + y * y) - b) < 0
                                   for x, y in pairs)
    assert any(Fraction(x) ** 2 + Fraction(y) ** 2 < b for x, y in pairs)
    _check_all(path, tmp_path, _law_rows(pairs, lam=0.5, vr=0.5))


def test_bound_10_where_g_reaches_kf(tmp_path):
    """g = df/de2 on e1 = 0 reaches kf = KF = 21 at e2 = 10.5 (c9's docstring);
    near there g's accuracy is not certified (a division by an interval
    holding 0), and the unclamped term came out 14.5 ulps above lam |vr| KF
    (w = 21.000000000000068 at e2 = 10.499999999998082; float 9.9 ulps).  The
    term is now clamped to lam |vr| KF: with lam = vr = 1 and wr = k2 = 0,
    w = g^ must stay <= KF (and >= KF (1 - 1e-12) at the maximum)."""
    path = ROOT / "designs_codegen" / "c9_atan_join_kf_attained.py"
    lib, mod = _generated(path, tmp_path)
    assert mod.KF == 21.0
    e2 = np.array([10.499999999998082, 10.5] + [10.5 + k * 3 * np.spacing(10.5) for k in range(-400, 401)])
    rows = _law_rows([(0.0, x) for x in e2])
    for who, (v, w, st) in (("C double", lib.run(rows)), ("Python", mod.control_status(*rows.T))):
        assert (st == 0).all() and w.max() <= 21.0 and w.max() >= 21.0 * (1 - 1e-12), (who, w.max())
    # Python's fast path (e3 = 0 takes the careful one): sin(1e-10)/1e-10 rounds to 1, the same rows
    fast = rows.copy()
    fast[:, 2] = 1e-10
    w = mod.control(*fast.T)[1]
    assert w.max() <= 21.0 and w.max() >= 21.0 * (1 - 1e-12), w.max()
    xf = np.array([np.float32(10.498237609863281), np.float32(10.5)]
                  + [np.float32(10.5) * np.float32(1 + k * 2.0 ** -16) for k in range(-3000, 3001)], dtype=np.float64)
    v, w, st = lib.run(_law_rows([(0.0, x) for x in xf]), f32=True)
    assert (st == 0).all() and w.max() <= 21.0 and w.max() >= 21.0 * (1 - 1e-5), w.max()


def test_a_tiny_scale_generates_and_validates(tmp_path):
    """log(1 + 1e-30 rho): its code is generated (and validated by `generate`)
    instead of an OverflowError; v, w checked at a few moderate rows.
    kf = sqrt(c) = 1e-15 (F'(s) = 2 c s/(1 + c s^2), largest at s = 1/sqrt(c))."""
    path = ROOT / "designs_codegen" / "c10_log_tiny_scale.py"
    rows = _law_rows([(0.0, 1e15), (3.0, -4.0), (1e20, 1e10), (0.0, 1e-3)])
    _, mod, _ = _check_all(path, tmp_path, rows, rows)
    assert abs(mod.KF - 1e-15) <= 1e-15 * 1e-9


def test_a_result_just_beyond_the_largest_number_rounds_to_it_not_to_inf(tmp_path):
    """The reference rounds as IEEE does: an exact value between the largest
    finite number and it plus half an ulp (2^1024 - 2^970; float 2^128 -
    2^103) rounds to that number, so a code result of it with status 0 is
    right.  The reference used to call every value beyond the largest number
    an overflow, and refused f = (1 + rho^2)^(1/4) - 1, a proved design:
    at e2 = -DBL_MAX, lam = DBL_MAX, vr = 1, wr = -1 the exact w is about
    -(DBL_MAX + 1)."""
    import flint
    big = 1.7976931348623157e308
    old, flint.ctx.prec = flint.ctx.prec, 256          # as `reference.table` evaluates
    try:
        top = flint.arb(2) ** 1024 - flint.arb(2) ** 970
        assert reference._to_float(top) == np.inf and reference._to_float(-top) == -np.inf
        assert reference._to_float(top - 1) == big and reference._to_float(-(flint.arb(big) + 1)) == -big
    finally:
        flint.ctx.prec = old
    ftop = 2.0 ** 128 - 2.0 ** 103
    ref = {"v_hi": np.array([0.0, 0.0, 0.0]), "v_lo": np.zeros(3), "scale_v": np.ones(3), "scale_w": np.ones(3),
           "w_hi": np.array([3.4028234663852886e38 * (1 + 2.0 ** -26), np.nextafter(ftop, 0), ftop]),
           "w_lo": np.zeros(3)}
    assert list(reference.errors(ref, np.zeros(3), np.zeros(3), "float")[2]) == [False, False, True]
    design = tmp_path / "quarter.py"
    design.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\n"
                      "f = (1 + (e1**2 + e2**2)**2)**sp.Rational(1, 4) - 1\n")
    lib, mod = _generated(design, tmp_path)
    row = np.array([[0.5, -big, 0.0, 1.0, -1.0, 0.25, 0.7, big]])
    v, w, st = lib.run(row)
    assert st[0] == 0 and abs(w[0] + big) <= 1e-12 * big      # (within an ulp of -DBL_MAX: the validation)


def test_a_nan_term_is_not_clamped_into_a_value(tmp_path):
    """The C clamp of the term to bound (10), in the checked-in code of
    design 1, called on its own (the .c file included in a test program).
    It once used fmin/fmax, which drop a NaN: a NaN term (as tail forms
    printing inf * 0 gave) came out as -lam |vr| KF with status 0.  It now
    keeps the NaN, so the result is refused (UWMR_ERR_RANGE), as Python's
    numpy.clip already did; finite values are clamped as before."""
    import subprocess
    from uwmr_symbolic.codegen.harness import STRICT
    test = tmp_path / "clamp_test.c"
    test.write_text('#include "design1_jiang.c"\n#include <stdio.h>\nint main(void) {\n'
                    '    const double x[4] = {NAN, 3.0, -3.0, 1.5};\n    int i;\n'
                    '    for (i = 0; i < 4; ++i)\n'
                    '        printf("%g %g\\n", clamp(x[i], 2.0), (double)clamp_f32((float)x[i], 2.0F));\n'
                    '    return 0;\n}\n')
    src = Path(__file__).resolve().parent.parent / "generated" / "design1_jiang"
    exe = tmp_path / "clamp_test"
    subprocess.run(["gcc", *STRICT, "-Wno-unused-function", "-O2", f"-I{src}", str(test), "-o", str(exe), "-lm"],
                   check=True, capture_output=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout.split()
    assert [o.lstrip("-") for o in out[:2]] == ["nan", "nan"]
    assert out[2:] == ["2", "2", "-2", "-2", "1.5", "1.5"]


def test_one_minus_exp_is_printed_with_expm1(tmp_path):
    """f = s + exp(-s) - 1 (s = |e|): F' = 1 - exp(-s), g = F'(s) e2/s.
    Printed as (1 - exp(-s))/s, g lost every digit for small s (1 - exp(-s)
    rounds to 0 below s ~ 1e-16: w = wr, status 0, where the exact w
    overflows), so validation refused the design and nothing was written.
    1 - exp(X) is now -expm1(X), as c exp(X) - c was c expm1(X)."""
    path = tmp_path / "s_exp.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\n"
                    "s = sp.sqrt(e1**2 + e2**2)\nf = s + sp.exp(-s) - 1\n")
    pairs = [(2.0953e-83, 1.7798e-52), (0.0, 1e-20), (1e-9, -3e-9), (0.3, 0.4), (0.0, 50.0)]
    rows = np.concatenate([_law_rows(pairs), _law_rows(pairs, lam=5.77e221, vr=1.99e293)])
    _check_all(path, tmp_path, rows, _law_rows([(1e-30, 2e-30), (0.0, 1e-7), (0.3, 0.4)]))
    assert "expm1(-" in (tmp_path / "s_exp/s_exp.c").read_text()


@pytest.mark.parametrize("stem, f, g", [
    ("sqrt_minus_exp", "sp.sqrt(1 + rho) - sp.exp(-rho)", lambda y: y / np.hypot(1.0, y)),
    ("sqrt_plus_tanh", "sp.sqrt(1 + rho) - 1 + sp.tanh(rho)", lambda y: y / np.hypot(1.0, y)),
    ("log_plus_rho_exp", "sp.log(1 + rho) + rho*sp.exp(-rho)", lambda y: 2 / (y + 1 / y))])
def test_a_tail_term_that_vanishes_like_exp_is_left_out_not_printed_as_inf_times_0(tmp_path, stem, f, g):
    """F'(1/t) holds a term such as 2 exp(-1/t^2)/t or 2/(t cosh(1/t^2)^2):
    printed, it is 2 st exp(-st st) or 2 st/cosh(st st)^2, inf * 0 or
    inf / inf = NaN as s nears the largest double, so the validation refused
    the three designs (status 4 at e2 = -1.8e308) and nothing was written.  The term is now left out of the far region, where Arb shows
    it below 2^-80 of the rest (the accuracy bound includes it).  Far out,
    g(0, y) is y/sqrt(1 + y^2) and 2 y/(1 + y^2) up to that term."""
    path = tmp_path / f"{stem}.py"
    path.write_text(f"import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\nf = {f}\n")
    big = np.finfo(float).max
    pairs = [(0.0, -big), (0.0, big), (big, big), (3e307, -1e308), (0.0, 1e300), (1e154, 1e154), (0.0, 1e4),
             (0.0, 1.0001e4), (7e3, 8e3), (0.0, 9e3), (0.3, 0.4), (1e-30, 2e-30)]
    lib, mod, law = _check_all(path, tmp_path, _law_rows(pairs), _law_rows([(0.0, 3e38), (2e4, 1e5), (0.3, 0.4)]))
    y = np.array([1e5, 1e300, big])
    v, w, st = lib.run(_law_rows([(0.0, x) for x in y]))
    assert (st == 0).all() and (np.abs(w - g(y)) <= 1e-12 * g(y)).all()


def test_a_series_that_needs_a_lower_tiny_gets_it(tmp_path):
    """f = log(cosh(1e8 s))/1e8: F' = tanh(1e8 s) = 1e8 s (1 - 1e16 s^2/3 + ...).
    At the float TINY 1e-12 the next term is 7e-9 of the first, above the
    2^-30 the tiny region allows, so there was no series for either
    precision and H = tanh(1e8 sqrt(rho))/sqrt(rho) was 0/0 once rho
    underflowed: status 4 at e2 = -1e-300 and nothing written.  The float
    TINY is now lowered to 1e-13, where the next term is 7e-11."""
    path = tmp_path / "sharp_logcosh.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\ns = sp.sqrt(e1**2 + e2**2)\n"
                    "f = sp.log(sp.cosh(10**8*s))/10**8\n")
    pairs = [(0.0, -1e-300), (1e-310, 0.0), (3e-120, 4e-120), (0.0, 1e-101), (0.0, 1e-9), (0.3, 0.4), (0.0, 1e10)]
    lib, mod, law = _check_all(path, tmp_path, _law_rows(pairs),
                               _law_rows([(0.0, -1e-40), (1e-14, 2e-14), (0.0, 1e-13), (0.0, 3e-12), (0.3, 0.4)]))
    from uwmr_symbolic.codegen import build
    model, _ = build(path)
    assert model.tiny == (10 ** 8, 1) and model.thresholds["float"][0] == 1e-13
    assert model.thresholds["double"][0] == 1e-100          # enough there: the next term is 7e-185
    # at m = 1e-300 g(0, y) = tanh(1e8 |y|) sign(y) = 1e8 y to the last digit
    v, w, st = lib.run(_law_rows([(0.0, -1e-300)]))
    assert st[0] == 0 and w[0] == pytest.approx(-1e-292, rel=1e-14)


def test_a_constant_beyond_the_float_range_leaves_out_the_float_variant_alone(tmp_path):
    """f = 3e38 log(1 + rho): F'(s) = 6e38 s/(1 + s^2), a constant no float
    holds.  The float printer refused it, and with it the whole design: no
    file was written although double and Python hold every constant.  Now
    the double variant and the Python module are written and validated,
    the banner says why there is no float variant, the header declares no
    _f32 function, and a build with UWMR_NO_DOUBLE stops with that reason."""
    import subprocess
    path = tmp_path / "huge_log.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\n"
                    "f = 3*10**38*sp.log(1 + rho)\n")
    pairs = [(0.0, 1e-300), (0.3, 0.4), (0.0, 1.0), (1e3, -2e3), (0.0, 1e300)]
    lib, mod, law = _check_all(path, tmp_path, _law_rows(pairs, lam=1e-38))
    header = (tmp_path / "huge_log" / "huge_log.h").read_text()
    text = " ".join(header.replace("\n * ", " ").split())
    assert "_f32(" not in header and "no float (_f32) variant: the constant 6e+38 is beyond the float range" in text
    # g(0, 1) = 6e38/2 = 3e38 exactly in the law; lam = 1e-38, vr = 1: w = 3
    v, w, st = lib.run(_law_rows([(0.0, 1.0)], lam=1e-38))
    assert st[0] == 0 and w[0] == pytest.approx(3.0, rel=1e-14)
    res = subprocess.run(["gcc", "-std=c99", "-DUWMR_NO_DOUBLE", "-c", str(tmp_path / "huge_log" / "huge_log.c"),
                          "-o", str(tmp_path / "x.o")], capture_output=True, text=True)
    assert res.returncode != 0 and "this controller has no float variant" in res.stderr


def test_a_law_that_cancels_at_zero_gets_its_taylor_polynomial_there(tmp_path):
    """f = s atan(s) - log(1 + rho) (proved): H = F'(s)/s = (atan(s) -
    s/(1 + s^2))/s is a difference of two terms near 1 that cancel to
    2 rho/3 as rho -> 0, so the printed form lost every digit (status 0 and
    w wrong by 1e4 relative near e = 1e-6), and the design was refused.
    Now, below a cut, H is its Taylor polynomial (remainder bounded in
    Arb): the double variant and the Python module are written and match
    the exact law on both sides of the cut and down to the tiny region.
    Float would need the polynomial beyond rho = 1 (atan's radius of
    convergence), so it is left out, and the banner says why."""
    import mpmath
    path = tmp_path / "atan_cancel.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\n"
                    "s = sp.sqrt(rho)\nf = s*sp.atan(s) - sp.log(1 + rho)\n")
    pairs = [(0.0, 1e-6), (1e-3, -2e-3), (0.1, 0.2), (0.25, 0.0), (0.0, 0.2500001), (0.0, 0.26), (0.5, 0.5),
             (3.0, 4.0), (1e-60, 1e-60), (0.0, 1e-120)]
    lib, mod, law = _check_all(path, tmp_path, _law_rows(pairs))
    header = (tmp_path / "atan_cancel" / "atan_cancel.h").read_text()
    text = " ".join(header.replace("\n * ", " ").split())
    assert "Taylor polynomial at 0" in text and "no float (_f32) variant: f' cancels near e = 0" in text
    assert "NOT CERTIFIED" not in header and "_f32(" not in header
    # g(0, e2) = F'(e2) = atan(e2) - e2/(1 + e2^2) = 2/3 e2^3 - 4/5 e2^5 + ...
    for e2 in (1e-6, 1e-3, 0.2, 0.26):
        with mpmath.workdps(50):
            x = mpmath.mpf(e2)
            exact = float(mpmath.atan(x) - x / (1 + x * x))
        v, w, st = lib.run(_law_rows([(0.0, e2)]))
        assert st[0] == 0 and w[0] == pytest.approx(exact, rel=1e-13), e2
        assert mod.control(0.0, e2, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)[1] == pytest.approx(exact, rel=1e-13)


@pytest.mark.parametrize("formula, dF", [
    # F' = atan(10 s)/10 - s/(1 + 100 s^2) = 200/3 s^3 - ...: 1/10 is not binary, so Arb's s^1
    # coefficient was a ball around 0, not an exact 0, and no polynomial was built (refused)
    ("s*sp.atan(10*s)/10 - sp.log(1 + 100*rho)/100", "atan(10*x)/10 - x/(1 + 100*x**2)"),
    # H = 2/(1 + rho/16) - 2 exp(-rho/16) ~ rho^2/128: the printer's common-subexpression pass factored
    # 1e-104 out of the polynomial, and 1e-104 rho^2 underflowed at rho = 1e-122 (error 1, refused)
    ("16*sp.log(1 + rho/16) + 16*sp.exp(-rho/16) - 16", "2*x/(1 + x**2/16) - 2*x*exp(-x**2/16)")])
def test_cancelling_laws_with_scaled_constants_get_their_polynomial(tmp_path, formula, dF):
    """Two more laws whose df/de2 cancels at 0 (see the test above), each
    written and equal to F'(s) e2/s (mpmath, 80 digits) along e1 = 0."""
    import mpmath
    import sympy as sp
    path = tmp_path / "scaled_cancel.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\n"
                    f"s = sp.sqrt(rho)\nf = {formula}\n")
    pairs = [(0.0, 1e-6), (1e-3, -2e-3), (0.1, 0.2), (0.0, 1.5), (3.0, 4.0), (-9.1e-90, 1.6e-61)]
    lib, mod, _ = _check_all(path, tmp_path, _law_rows(pairs))
    assert "Taylor polynomial at 0" in (tmp_path / "scaled_cancel" / "scaled_cancel.h").read_text()
    x = sp.Symbol("x")
    exact = sp.lambdify(x, sp.sympify(dF, locals={"x": x}), "mpmath")
    for e2 in (1e-6, 1e-2, 0.3, 2.0):
        with mpmath.workdps(80):
            want = float(exact(mpmath.mpf(e2)))
        v, w, st = lib.run(_law_rows([(0.0, e2)]))
        assert st[0] == 0 and w[0] == pytest.approx(want, rel=1e-13), e2


def test_a_huge_kf_gets_its_code_with_status_4_where_w_overflows(tmp_path):
    """10^307 log(1 + rho): kf = 10^307 (F' = 2 10^307 s/(1 + s^2)).  At the
    row below g = -8.86e306 and w = lam vr g... = 2.6e310 is beyond the
    doubles: the C and control_status give status 4.  The validation had
    asked status 0 there of control() (which has no status) and of the
    CasADi function (neither has one), and refused the proved design."""
    path = tmp_path / "huge_kf.py"
    path.write_text('import sympy as sp\ne1, e2 = sp.symbols("e1 e2", real=True)\n'
                    'f = 10**307*sp.log(1 + e1**2 + e2**2)\n')
    beyond = np.array([[0.3, -0.7, 0.2, -1e4, 1.0, 0.25, 0.7, 0.3]])
    rows = np.vstack([beyond, _law_rows([(3.0, -4.0), (0.0, 1e-3)], lam=1e-300)])
    lib, mod, _ = _check_all(path, tmp_path, rows)
    assert lib.run(beyond)[2][0] == 4 and mod.control_status(*beyond.T)[2][0] == 4
    assert 1e307 <= mod.KF <= 1e307 * (1 + 2 ** -52)       # 10^307 rounded up (the clamp's side)


def test_a_constant_beyond_the_doubles_is_refused_by_name(tmp_path):
    """log(1 + rho)/10^310 (proved; kf = 10^-310): H = F'(s)/s is printed
    over 5 10^309 (SymPy's form), which no double holds.  The printer wrote
    the literal inf.0 and the design was refused with the C compiler's
    "'inf' undeclared"; now the refusal names the constant."""
    from uwmr_symbolic.codegen import CodegenInvalid
    path = tmp_path / "beyond.py"
    path.write_text('import sympy as sp\ne1, e2 = sp.symbols("e1 e2", real=True)\n'
                    'f = sp.log(1 + e1**2 + e2**2)/10**310\n')
    with pytest.raises(CodegenInvalid, match=r"the constant 5\.0+E\+309 is beyond the double range") as info:
        generate(path, tmp_path / "out")
    assert not (tmp_path / "out").exists()
    # the CLI says so, not that the code failed a validation it never reached
    assert info.value.unprintable and "cannot be written" in info.value.what


def test_parameter_names_cannot_redefine_the_generated_constants(tmp_path):
    """Parameters named h, kf and ok, and one whose name holds "*/": they
    became the macros UWMR_<STEM>_H (the include guard), UWMR_<STEM>_KF
    (redefined with the parameter's 100) and, in Python, KF = 100 after the
    certified KF and OK = 1.  Each now is a PARAM_ constant."""
    path = tmp_path / "pkf.py"
    path.write_text('import sympy as sp\ne1, e2 = sp.symbols("e1 e2", real=True)\n'
                    'kf, h, ok, a = sp.symbols("kf h ok a", positive=True)\nb = sp.Symbol("b*/x", positive=True)\n'
                    'f = kf*h*ok*a*b*sp.log(1 + e1**2 + e2**2)\n'
                    'params = {"kf": 100, "h": 1, "ok": 1, "a": sp.Rational(1, 50), "b*/x": 1}\n')
    lib, mod, _ = _check_all(path, tmp_path, _law_rows([(0.0, 1.0), (3.0, -4.0)]))
    assert mod.KF == 2.0 and mod.OK == 0 and mod.PARAMS == {"a": 0.02, "b*/x": 1.0, "h": 1.0, "kf": 100.0, "ok": 1.0}
    assert (mod.PARAM_KF, mod.PARAM_H, mod.PARAM_OK, mod.PARAM_B__X) == (100.0, 1.0, 1.0, 1.0)
    header = (tmp_path / "pkf" / "pkf.h").read_text()
    assert "#define UWMR_PKF_KF 2.0\n" in header and "#define UWMR_PKF_PARAM_KF 100.0  /* kf = 100 */" in header
    assert "/* b* /x = 1 */" in header
    assert mod.control(0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)[1] == pytest.approx(2.0, rel=1e-15)


def test_parameter_names_that_would_give_one_constant_are_numbered():
    from uwmr_symbolic.codegen import _param_macros
    assert _param_macros(["a-1", "a_1", "α"]) == ["PARAM1_A_1", "PARAM2_A_1", "PARAM3__"]
    assert _param_macros(["alpha", "beta"]) == ["PARAM_ALPHA", "PARAM_BETA"]


@pytest.mark.skipif(shutil.which("cmake") is None, reason="cmake missing: `make test` installs it")
def test_a_design_file_name_with_a_space_builds_with_cmake(tmp_path):
    """"a b.py": CMakeLists.txt had add_library(... STATIC a b.c), two
    sources "a" and "b.c"; the source is quoted now."""
    import subprocess
    path = tmp_path / "a b.py"
    path.write_text('import sympy as sp\ne1, e2 = sp.symbols("e1 e2", real=True)\nf = sp.log(1 + e1**2 + e2**2)\n')
    generate(path, tmp_path / "a b")
    for cmd in (["cmake", "-S", str(tmp_path / "a b"), "-B", str(tmp_path / "build")],
                ["cmake", "--build", str(tmp_path / "build")]):
        run = subprocess.run(cmd, capture_output=True, text=True)
        assert run.returncode == 0, run.stdout + run.stderr
    assert list((tmp_path / "build").glob("libuwmr_a_b_*.a"))


def test_a_design_file_name_the_generated_code_cannot_quote_is_refused_by_name(tmp_path):
    from uwmr_symbolic.codegen import CodegenInvalid
    path = tmp_path / 'a"b.py'
    path.write_text('import sympy as sp\ne1, e2 = sp.symbols("e1 e2", real=True)\nf = sp.log(1 + e1**2 + e2**2)\n')
    with pytest.raises(CodegenInvalid, match=r"""a"b: the design file's name holds '"', .* rename the file"""):
        generate(path, tmp_path / "out")
    assert not (tmp_path / "out").exists()


def test_a_float_variant_certified_for_no_input_is_not_written(tmp_path):
    """f = 2.5e-40 (sqrt(1 + rho) - 1): g = 2.5e-40 e2/sqrt(1 + rho), below
    the normal floats.  The float analysis certified nothing (the ranges
    marked NOT CERTIFIED covered every m, and the header still read "g within
    0" for them), yet the float variant was written, 2.1e-5 off in g, on
    testing alone.  Now it is left out, with the reason; the double is
    certified and written."""
    path = tmp_path / "tiny.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\n"
                    "f = sp.Rational(25, 10**41)*(sp.sqrt(1 + e1**2 + e2**2) - 1)\n")
    lib, mod, law = _check_all(path, tmp_path, _law_rows([(0.0, 1.0), (3.0, -4.0), (1e-3, 2e-3)], lam=1e38))
    header = (tmp_path / "tiny" / "tiny.h").read_text()
    text = " ".join(header.replace("\n * ", " ").split())
    assert "_f32(" not in header and "within 0." not in text
    assert "no float (_f32) variant: no accuracy of the float code is certified for any input (0 < m <" in text
    assert "double: |g^ - g| <= 3.6e-15 |g|" in text and "NOT CERTIFIED" not in text
    # g(0, 1) = 2.5e-40/sqrt(2); lam = 1e38, vr = 1: w = 2.5e-2/sqrt(2)
    v, w, st = lib.run(_law_rows([(0.0, 1.0)], lam=1e38))
    assert st[0] == 0 and w[0] == pytest.approx(0.025 / 2 ** 0.5, rel=1e-14)


def test_exceptions_that_cover_a_region_leave_it_uncertified():
    from uwmr_symbolic.codegen.accuracy import _covers
    assert _covers([(0.0, 0.101, "a")], 0.0, 0.1) and _covers([(0.0, 1.0, "a"), (1.0, 2.0, "b")], 0.0, 2.0)
    assert not _covers([(0.0, 1.0, "a"), (1.5, 2.0, "b")], 0.0, 2.0) and not _covers([(0.1, 2.0, "a")], 0.0, 2.0)
    assert not _covers([], 0.0, 1.0) and not _covers([(0.0, 0.5, "a")], 0.0, 1.0)


@pytest.mark.parametrize("formula", ["s - sp.atan(s)", "s - sp.tanh(s)"])
def test_the_casadi_function_near_zero_where_f_prime_starts_with_an_even_power(tmp_path, formula):
    """F'(s) ~ s^2 at 0 (H = F'(s)/s ~ s, no power of rho): where rho
    underflows the CasADi function computed H(0) = 0/0 and w = NaN at
    e2 = -1e-300, and the proved design was refused although its C and
    Python were right.  g = e2 s/(1 + s^2) and e2 tanh(s)^2/s."""
    import mpmath
    from uwmr_symbolic.codegen import casadi_function
    path = tmp_path / "even.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\ns = sp.sqrt(e1**2 + e2**2)\n"
                    f"f = {formula}\n")
    fn = casadi_function(path)
    for e1, e2 in ((0.0, -1e-300), (3e-200, 4e-200), (0.0, 1e-160), (1e-100, 2e-100), (0.3, -0.4), (3.0, 4.0)):
        w = float(fn(e1, e2, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)[1])
        with mpmath.workdps(60):
            s = mpmath.hypot(e1, e2)
            g = e2 * s / (1 + s**2) if "atan" in formula else e2 * mpmath.tanh(s) ** 2 / s
        assert w == pytest.approx(float(g), rel=1e-13, abs=1e-320), (e1, e2)


def test_a_law_with_a_named_constant_is_validated_and_written(tmp_path):
    """EulerGamma log(1 + rho) (proved, kf = EulerGamma): the exact law of the
    validation had no Arb value for EulerGamma, so the design was refused
    ("the exact law cannot be evaluated")."""
    path = tmp_path / "euler.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\n"
                    "f = sp.EulerGamma*sp.log(1 + e1**2 + e2**2)\n")
    lib, mod, _ = _check_all(path, tmp_path, _law_rows([(0.0, 1.0), (3.0, -4.0), (1e-200, 1e-3)]))
    gamma = 0.57721566490153286061
    assert gamma <= mod.KF <= gamma * (1 + 2 ** -52)
    v, w, st = lib.run(_law_rows([(0.0, 1.0)]))      # g(0, 1) = 2 EulerGamma/(1 + 1)
    assert st[0] == 0 and w[0] == pytest.approx(gamma, rel=1e-15)


@pytest.mark.parametrize("R", [100, 10**4])
def test_a_c2_join_far_out_is_generated(tmp_path, R):
    """F = s^2/2 up to R, then R s - R^2/2 + (R^2/2) log(1 + ((s - R)/R)^2)
    (C^2 at R: value R^2/2, slope R, F'' = 1; proved, kf = 3R/2).  Asking
    SymPy's simplify whether the formula at the join is the piece's ran for
    minutes (the log's argument raised to the power R^2/2) and --codegen
    never finished; it gets 2 s now.  At e = (0, e2), g = F'(|e2|): e2 inside,
    and beyond F'(s) = R + (s - R)/(1 + ((s - R)/R)^2), so F'(2R) = 3R/2."""
    path = tmp_path / "join.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\n"
                    f"s = sp.sqrt(rho)\nR = sp.Integer({R})\n"
                    "f = sp.Piecewise((rho/2, rho <= R**2), (R*s - R**2/2 + R**2/2*sp.log(1 + ((s - R)/R)**2), True))\n")
    lib, mod, _ = _check_all(path, tmp_path, _law_rows([(0.0, 0.5 * R), (0.0, 2.0 * R), (3.0 * R, 4.0 * R)]))
    v, w, st = lib.run(_law_rows([(0.0, 0.5 * R), (0.0, 2.0 * R)]))
    assert list(st) == [0, 0] and w[0] == pytest.approx(0.5 * R, rel=1e-14) and w[1] == pytest.approx(1.5 * R, rel=1e-14)


def test_a_tolerance_scale_beyond_every_number_is_inf():
    """|e . grad g| beyond the doubles (log(1 + rho) + (1 - cos rho)/(2 (1 + rho))
    at e2 = -DBL_MAX): the reference raised in man_exp, and the proved design
    was refused as "the exact law could not be evaluated"; the refusal now
    names what fails (the C double's status 4 where the law is finite)."""
    import flint
    from uwmr_symbolic.codegen.reference import _to_float
    assert _to_float(flint.arb("inf")) == math.inf and _to_float(-flint.arb("inf")) == -math.inf
    assert _to_float(flint.arb(2) ** 1100) == math.inf and _to_float(flint.arb(3) / 4) == 0.75


@pytest.mark.parametrize("condition", ["sp.Eq(e1, 0) & sp.Eq(e2, 0)", "sp.Not(sp.Ne(e1, 0) | sp.Ne(e2, 0))"])
def test_a_point_branch_given_by_and_or_not_is_generated(tmp_path, condition):
    """Red team 18b: f = 0 at the origin, log(1 + rho) elsewhere, is log(1 +
    rho) (proved P1-P8), but its validation stopped ("'And' object has no
    attribute 'lhs'"): the Arb reference read relations only.  It now reads
    Eq, Ne, And, Or, Not; the law is w = lam vr 2 e2/(1 + rho) exactly."""
    path = tmp_path / "point_branch.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\n"
                    f"f = sp.Piecewise((0, {condition}), (sp.log(1 + e1**2 + e2**2), True))\n")
    pairs = [(0.0, 0.0), (-0.0, 1.0), (0.0, -1.0), (1e-300, 0.0), (3.0, 4.0), (0.0, 1e-170), (-2.5, 1e150)]
    _, mod, _ = _check_all(path, tmp_path, _law_rows(pairs), _law_rows(pairs[:5]))
    v, w, st = mod.control_status(*_law_rows([(0.0, 1.0), (3.0, 4.0)]).T)
    assert list(st) == [0, 0] and w[0] == 1.0 and abs(w[1] - 8 / 26) < 1e-15


def test_a_max_whose_arguments_tie_is_generated(tmp_path):
    """Red team 21: f = Max(g, g + (rho - 1)^3/(8 (1 + rho)^3)), g = log(1 + rho),
    the two arguments crossing tangentially (C^2) on the unit circle, has P1-P8
    proved, but its validation stopped ("a Piecewise condition is undecidable")
    at (1, 0) and (0, 1): log 2 - log 2 is a ball around 0 at every precision.
    At a tie the reference now takes the union of the two branches, where they
    agree (P1: df/de2 is continuous across the circle): df/de2 = 2 e2/(1 + rho)
    on the circle: 0 at (1, 0), 1 at (0, 1)."""
    path = tmp_path / "max_tie.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\n"
                    "g = sp.log(1 + rho)\nf = sp.Max(g, g + (rho - 1)**3/(1 + rho)**3/8)\n")
    law = reference.Law.of(load_design(path))
    assert law.g(1.0, 0.0) == 0 and law.g(0.0, 1.0) == 1 and law.g(0.0, -1.0) == -1
    pairs = [(1.0, 0.0), (0.0, 1.0), (0.6, 0.8), (-0.8, 0.6), (0.5, 0.5), (2.0, 3.0), (1e-200, 1e-200), (0.0, 1e100)]
    _, mod, _ = _check_all(path, tmp_path, _law_rows(pairs), _law_rows(pairs[:6]))
    v, w, st = mod.control_status(*_law_rows([(0.0, 1.0), (2.0, 3.0)]).T)
    g23 = 6 / 14 + 3 * 3 * 144 / (4 * 14 ** 3) - 3 * 3 * 12 ** 3 / (4 * 14 ** 4)      # outside: the second branch
    assert list(st) == [0, 0] and w[0] == 1.0 and abs(w[1] - g23) < 1e-15


def test_the_reference_reads_every_kind_of_condition():
    """`reference._arb_cond` at exact points: Eq, Ne, the four orders, And,
    Or, Not, and an And whose undecidable part does not matter."""
    import flint
    import sympy as sp
    e1, e2 = sp.symbols("e1 e2", real=True)
    at = lambda cond, a, b: reference._arb_cond(cond)(flint.arb(a), flint.arb(b))
    assert at(sp.Eq(e1, 0), 0, 5) and not at(sp.Eq(e1, 0), 1, 5) and at(sp.Ne(e2, 1), 0, 2) and not at(sp.Ne(e2, 1), 0, 1)
    assert at(e1 >= 1, 1, 0) and not at(e1 > 1, 1, 0) and at(e1 <= 1, 1, 0) and not at(e1 < 1, 1, 0)
    assert at(sp.And(e1 > 0, e2 > 0), 1, 1) and not at(sp.And(e1 > 0, e2 > 0), 1, -1)
    assert at(sp.Or(e1 > 0, e2 > 0), -1, 1) and not at(sp.Or(e1 > 0, e2 > 0), -1, -1)
    assert at(sp.Not(e1 > 0), -1, 0) and not at(sp.Not(e1 > 0), 1, 0)
    third = flint.arb(1) / 3      # a ball around 1/3, never exactly 1/3: e1 = 1/3 is undecidable there
    cond = sp.And(e2 > 0, sp.Eq(3 * e1, 1))
    assert reference._arb_cond(cond)(third, flint.arb(-1)) is False
    with pytest.raises(reference.NeedPrecision):
        reference._arb_cond(cond)(third, flint.arb(1))


def test_casadi_reads_every_kind_of_condition():
    """`casadi_backend.to_casadi` of a Piecewise with Eq, Ne, And, Or, Not
    conditions, at points on either side of each."""
    import casadi as ca
    import sympy as sp
    from uwmr_symbolic.codegen.casadi_backend import to_casadi
    e1, e2 = sp.symbols("e1 e2", real=True)
    x, y = ca.SX.sym("x"), ca.SX.sym("y")
    pw = sp.Piecewise((1, sp.And(e1 > 0, sp.Ne(e2, 1))), (2, sp.Or(sp.Eq(e1, 0), sp.Not(e2 < 3))), (3, True))
    fn = ca.Function("pw", [x, y], [to_casadi(pw, {e1: x, e2: y})])
    got = [float(fn(a, b)) for a, b in ((1, 0), (1, 1), (0, 1), (-1, 3), (-1, 2))]
    assert got == [1, 3, 2, 2, 3]


def test_a_value_given_on_a_circle_is_no_derivative_there(tmp_path):
    """Red team 19: f = log(2)/2 on the unit circle (Eq(rho, 1)), log(1 + rho)/2
    elsewhere, is log(1 + rho)/2 everywhere (proved P1-P8); its g = df/de2 at
    (0, -1) is e2/(1 + rho) = -1/2, but the validation's reference took the
    derivative of the circle's branch, 0, and refused the (right) code.
    Branches taken on a set without inner points are left out before
    differentiating (`law.partial_e2`)."""
    path = tmp_path / "circle_value.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\n"
                    "f = sp.Piecewise((sp.log(2)/2, sp.Eq(e1**2 + e2**2, 1)), (sp.log(1 + e1**2 + e2**2)/2, True))\n")
    pairs = [(0.0, -1.0), (1.0, 0.0), (0.6, 0.8), (0.0, 1.0), (2.0, 3.0)]
    _, mod, law = _check_all(path, tmp_path, _law_rows(pairs), _law_rows(pairs))
    v, w, st = mod.control_status(*_law_rows([(0.0, -1.0), (0.6, 0.8)]).T)
    assert list(st) == [0, 0] and w[0] == -0.5 and abs(w[1] - 0.4) < 1e-15
