"""The committed generated C and Python against the exact law.

* C compiled with -std=c99 -Wall -Wextra -Werror -pedantic -Wdouble-promotion
  (loaded with ctypes) and again with -fsanitize=address,undefined,float-divide-by-zero;
* agreement with the law evaluated in high precision (Arb, adaptive; the
  reference itself is cross-checked against mpmath at 50 digits) at >= 1e5
  random points over many magnitudes and on the issue's extreme grid, for
  every design in designs/: double <= 1e-12, float <= 1e-5 relative to the
  scale defined in `uwmr_symbolic.codegen.reference`;
* bound (10) for the verified designs, safe stop on NaN/inf/NULL/negative gain.
"""
from __future__ import annotations

import importlib.util
import itertools
import shutil
from pathlib import Path

import mpmath
import numpy as np
import pytest

from uwmr_symbolic.codegen import reference, validate
from uwmr_symbolic.codegen.harness import build_executable, build_library, run_executable
from uwmr_symbolic.design import load_design

ROOT = Path(__file__).resolve().parent.parent
STEMS = sorted(p.stem for p in (ROOT / "designs").glob("*.py"))
VERIFIED = {"design1_jiang", "design2_sqrt", "design3_logcosh"}
OK, ERR_NULL, ERR_NONFINITE, ERR_GAIN, ERR_RANGE = 0, 1, 2, 3, 4
N_FLOAT, N_WIDE = 100_000, 20_000
DOUBLE_TOL, FLOAT_TOL = 1e-12, 1e-5

pytestmark = [pytest.mark.slow, pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc")]


def random_inputs(seed):
    """N_FLOAT rows representable in float (magnitudes 1e-45..1e38, half of
    them in 1e-4..1e4) and N_WIDE rows of doubles over 1e-323..1e308 (with
    subnormals); 5% zeros; gains >= 0."""
    rng = np.random.default_rng(seed)

    def rows(n, lo, hi):
        x = 10.0 ** rng.uniform(lo, hi, (n, 8)) * rng.choice([-1.0, 1.0], (n, 8))
        x[rng.random((n, 8)) < 0.05] = 0.0
        x[:, 5:] = np.abs(x[:, 5:])
        return x
    f = np.concatenate([rows(N_FLOAT // 2, -45.5, 38.4), rows(N_FLOAT - N_FLOAT // 2, -4, 4)])
    f = f.astype(np.float32).astype(np.float64)
    return f, rows(N_WIDE, -323.5, 308.2)


def grid(values, gains_values, nominal):
    """e1, e2, e3, vr, wr over `values` with nominal gains, then the gains over
    `gains_values` with (e1, e2, e3) over a sub-grid and vr = 1, wr = -1."""
    a = np.array([(*p, *nominal) for p in itertools.product(values, repeat=5)])
    sub = values[::2]
    b = np.array([(*p, 1.0, -1.0, *g) for p in itertools.product(sub, repeat=3)
                  for g in itertools.product(gains_values, repeat=3)])
    return np.concatenate([a, b])


GRID_D = [0.0, 1e-300, -1e-300, 1.0, -1.0, 1e150, -1e150, 1e300, -1e300]
GRID_F = [0.0, 1e-40, -1e-40, 1.0, -1.0, 1e19, -1e19, 3e38, -3e38]   # float analogues (1e-40 subnormal)


class Case:
    """Everything one design's tests share (built once per module)."""

    def __init__(self, stem, tmp):
        self.stem = stem
        self.src = ROOT / "generated" / stem
        self.design = load_design(ROOT / "designs" / f"{stem}.py")
        sc = next(iter(self.design.gains.values()))
        self.nominal = tuple(float(sc[k]) for k in ("k1", "k2", "lam"))
        self.lib = build_library(self.src, stem, tmp)                 # strict flags, -O2
        spec = importlib.util.spec_from_file_location(f"gen_{stem}", self.src / f"{stem}.py")
        self.py = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(self.py)
        xf, xw = random_inputs(STEMS.index(stem) + 11)
        gf = grid(GRID_F, [0.0, 1e-40, 1.0, 1e19, 3e38], self.nominal).astype(np.float32).astype(np.float64)
        self.x_float = np.concatenate([xf, gf])
        self.x_double = np.concatenate([xf, xw, grid(GRID_D, [0.0, 1e-300, 1.0, 1e150, 1e300], self.nominal)])
        self.n_random_float, self.n_random_double = len(xf), len(xf) + len(xw)
        # one reference for every row (the float rows are a prefix of the double rows)
        self.ref_double = reference.table_parallel(ROOT / "designs" / f"{stem}.py", self.x_double)
        xg = self.x_float[len(xf):]
        gref = reference.table_parallel(ROOT / "designs" / f"{stem}.py", xg)
        self.ref_float = {k: np.concatenate([v[:len(xf)], gref[k]]) for k, v in self.ref_double.items()}


@pytest.fixture(scope="module", params=STEMS)
def case(request, tmp_path_factory):
    return Case(request.param, tmp_path_factory.mktemp(request.param))


def _check(case, x, ref, v, w, st, precision, tol, what):
    """The generator's own validation check (`validate.check`): statuses,
    safe stop, error <= tol of the scale, bound (10) for verified designs."""
    assert tol == validate.TOL[precision]
    kf = case.py.KF if case.stem in VERIFIED else None
    return validate.check(case.stem, what, x, ref, v, w, st, precision, kf)


def test_c_double_agrees_with_exact_law(case):
    v, w, st = case.lib.run(case.x_double)
    assert case.n_random_double >= 100_000
    _check(case, case.x_double, case.ref_double, v, w, st, "double", DOUBLE_TOL, "C double")


def test_c_float_agrees_with_exact_law(case):
    v, w, st = case.lib.run(case.x_float, f32=True)
    assert case.n_random_float >= 100_000
    _check(case, case.x_float, case.ref_float, v.astype(float), w.astype(float), st, "float", FLOAT_TOL, "C float")


def test_python_agrees_with_exact_law(case):
    x = case.x_double
    v, w = case.py.control(*x.T)
    v2, w2, st = case.py.control_status(*x.T)
    assert np.array_equal(v, v2) and np.array_equal(w, w2)
    _check(case, x, case.ref_double, v, w, st, "double", DOUBLE_TOL, "Python")
    # the fast path on the moderate rows gives the same as the careful path
    xm = case.x_float[N_FLOAT // 2:N_FLOAT]
    fv, fw = case.py.control(*xm.T)
    cv, cw, _ = case.py.control_status(*xm.T)
    ref = {k: v[N_FLOAT // 2:N_FLOAT] for k, v in case.ref_double.items()}
    assert max(m.max() for m in reference.errors(ref, fv, fw)[:2]) <= DOUBLE_TOL
    assert max(m.max() for m in reference.errors(ref, cv, cw)[:2]) <= DOUBLE_TOL


@pytest.mark.parametrize("f32", [False, True])
def test_safe_stop_on_nonfinite_and_negative_gains(case, f32):
    base = np.array([0.3, -0.7, 0.2, 0.5, 1.0, 0.25, 0.7, 0.3])
    rows = []
    for i in range(8):
        for bad in (np.inf, -np.inf, np.nan):
            for e in ([0.0, 1.0, 1e30] if not f32 else [0.0, 1.0]):
                r = base.copy()
                r[(i + 1) % 8] = e if (i + 1) % 8 < 5 else abs(e)
                r[i] = bad
                rows.append(r)
    neg = []
    for i in (5, 6, 7):
        r = base.copy()
        r[i] = -1e-30 if f32 else -1e-300
        neg.append(r)
    x = np.array(rows + neg)
    v, w, st = case.lib.run(x, f32=f32)
    assert np.all(st[:len(rows)] == ERR_NONFINITE) and np.all(st[len(rows):] == ERR_GAIN)
    assert np.all(v == 0) and np.all(w == 0)
    if not f32:
        pv, pw, pst = case.py.control_status(*x.T)
        assert np.array_equal(pst, st) and np.all(pv == 0) and np.all(pw == 0)


def test_sanitizers_and_null_pointers(case, tmp_path):
    """-fsanitize=address,undefined,float-divide-by-zero: no report on the grids and a random
    sample, the same results as the optimised build, NULL handled."""
    exe = build_executable(case.src, case.stem, tmp_path,
                           extra=("-O1", "-g", "-fsanitize=address,undefined,float-divide-by-zero",
                                  "-fno-sanitize-recover=all"))
    env = {"ASAN_OPTIONS": "detect_leaks=1:abort_on_error=0", "UBSAN_OPTIONS": "print_stacktrace=1"}
    for f32, x in ((False, case.x_double[::7]), (True, case.x_float[::7])):
        v, w, st, res = run_executable(exe, x, tmp_path, f32=f32, env=env)
        assert res.returncode == 0 and "runtime error" not in res.stderr and "Sanitizer" not in res.stderr, res.stderr
        lv, lw, lst = case.lib.run(x, f32=f32)
        assert np.array_equal(st, lst)
        assert np.array_equal(v, lv, equal_nan=True) and np.array_equal(w, lw, equal_nan=True)


def test_reference_agrees_with_mpmath_50_digits(case):
    """The Arb reference against mpmath at 50 digits (more where rho's
    cancellation against 1 needs it): g = df/de2 at random and extreme points."""
    rng = np.random.default_rng(3)
    pts = list(itertools.product(GRID_D[:5] + [1e150, 1e300], repeat=2))
    pts += [tuple(p) for p in 10.0 ** rng.uniform(-200, 200, (150, 2)) * rng.choice([-1, 1], (150, 2))]
    pts += [tuple(p) for p in rng.uniform(-8, 8, (150, 2))]
    law = reference.Law.of(case.design)
    for e1, e2 in pts:
        a = law.g(e1, e2)
        b = reference.mp_g(case.design, e1, e2)
        with mpmath.workdps(80):
            mid = mpmath.mpf(a.mid().str(60, radius=False))
            assert abs(mid - b) <= abs(b) * mpmath.mpf(10) ** -25, (e1, e2, a, b)   # Arb: 2**-90


def fast_path_boundary_rows(cfg, nominal):
    """Rows on both sides of every test of the C fast path (`c_backend.fast_lines`)
    for one precision: |e1| + |e2| at 2 TINY and FAR, |e3| at CUT and e3_max,
    lam vr at the smallest normal number, |vr| + |wr| + k1 + k2 at `big`, and a
    grid of lam over every binade (q = lam vr H crosses q_lo and q_hi)."""
    from uwmr_symbolic.codegen.c_backend import FLOAT
    f = cfg.fast
    tiny_normal = 2.0 ** -126 if cfg is FLOAT else 2.0 ** -1022
    top = 127 if cfg is FLOAT else 1023
    bottom = -149 if cfg is FLOAT else -1074
    base = np.array([0.3, -0.7, 0.2, 0.5, 1.0, *nominal])
    rows = []

    def row(**kw):
        r = base.copy()
        for k, val in kw.items():
            r["e1 e2 e3 vr wr k1 k2 lam".split().index(k)] = val
        rows.append(r)
    for fac in (1 - 2.0 ** -10, 1.0, 1 + 2.0 ** -10):
        for sg in (1.0, -1.0):
            for s in (2 * cfg.tiny * fac, cfg.far * fac):
                row(e1=s / 2, e2=sg * s / 2)
                row(e1=0.0, e2=sg * s)
                row(e1=sg * s, e2=0.0)
            for e in (cfg.sinc_cut * fac, f.e3_max * fac):
                row(e3=sg * e)
            row(vr=sg * tiny_normal * fac / nominal[2])
            row(wr=sg * f.big * fac)
            row(vr=sg * f.big * fac, lam=tiny_normal * 4)
            row(k1=f.big * fac)
            row(k2=f.big * fac)
    for k in range(bottom, top, 3):
        row(lam=2.0 ** k)
        row(lam=2.0 ** k, vr=-0.5, e1=1e-3, e2=2e-3)
    x = np.array(rows)
    return x.astype(np.float32).astype(np.float64) if cfg is FLOAT else x


def test_fast_path_boundaries_agree_with_exact_law(case):
    """Both sides of each range test of the fast path: the same accuracy as
    everywhere else (the fast path is the careful path without guards)."""
    from uwmr_symbolic.codegen.c_backend import DOUBLE, FLOAT
    design = ROOT / "designs" / f"{case.stem}.py"
    xd = fast_path_boundary_rows(DOUBLE, case.nominal)
    xf = fast_path_boundary_rows(FLOAT, case.nominal)
    rd, rf = reference.table_parallel(design, xd), reference.table_parallel(design, xf)
    v, w, st = case.lib.run(xd)
    _check(case, xd, rd, v, w, st, "double", DOUBLE_TOL, "C double, fast-path boundaries")
    v, w, st = case.lib.run(xf, f32=True)
    _check(case, xf, rf, v.astype(float), w.astype(float), st, "float", FLOAT_TOL, "C float, fast-path boundaries")
    v, w, st = case.py.control_status(*xd.T)
    _check(case, xd, rd, v, w, st, "double", DOUBLE_TOL, "Python careful, fast-path boundaries")
    # row by row, so that each row takes the Python fast path or not on its own
    pv, pw = np.array([case.py.control(*r) for r in xd]).T
    _check(case, xd, rd, pv, pw, st, "double", DOUBLE_TOL, "Python, fast-path boundaries")


def test_python_fast_path_is_taken_and_exact(case):
    """Moderate rows (no zeros, rho within the mid region) take the Python
    fast path (checked), which agrees with the exact law and with the careful
    path."""
    if not hasattr(case.py, "_H"):
        pytest.skip("no fast path for a non-radial f")
    sl = slice(N_FLOAT // 2, N_FLOAT)
    rows = case.x_float[sl]
    keep = np.all(rows != 0, axis=1) & (rows[:, 0] ** 2 + rows[:, 1] ** 2 <= 0.99 * case.py._FAR2)
    args = [np.ascontiguousarray(c) for c in rows[keep].T]
    assert keep.sum() > 10_000 and case.py._fast(*args) is not None
    v, w = case.py.control(*args)
    cv, cw, _ = case.py.control_status(*args)
    ref = {k: val[sl][keep] for k, val in case.ref_double.items()}
    assert max(m.max() for m in reference.errors(ref, v, w)[:2]) <= DOUBLE_TOL
    assert max(m.max() for m in reference.errors(ref, cv, cw)[:2]) <= DOUBLE_TOL


def test_two_designs_whose_names_differ_only_in_punctuation_link_into_one_program(tmp_path):
    """`my-design` and `my design` once both became uwmr_my_design_*: two
    definitions of every function when linked together.  A stem that is not
    a lower-case C identifier now gets 8 hex digits of its hash."""
    import subprocess
    from uwmr_symbolic.codegen import generate
    from uwmr_symbolic.codegen.c_backend import c_identifier
    assert c_identifier("design1_jiang") == "design1_jiang"
    names = ["my-design", "my design", "My_design", "my_design"]
    assert len({c_identifier(n).upper() for n in names}) == 4       # the macros (upper case) differ too
    objects = []
    for n in names[:2]:
        shutil.copy(ROOT / "designs" / "design1_jiang.py", tmp_path / f"{n}.py")
        generate(tmp_path / f"{n}.py", tmp_path / n.replace(" ", "_"))
        obj = tmp_path / f"{n.replace(' ', '_')}.o"
        subprocess.run(["gcc", "-std=c99", "-O1", "-Wall", "-Wextra", "-Werror", "-c",
                        str(tmp_path / n.replace(" ", "_") / f"{n}.c"), "-o", str(obj)], check=True)
        objects.append(str(obj))
    link = subprocess.run(["gcc", "-shared", *objects, "-o", str(tmp_path / "both.so"), "-lm"],
                          capture_output=True, text=True)
    assert link.returncode == 0, link.stderr
