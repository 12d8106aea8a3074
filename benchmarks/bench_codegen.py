"""Speed of the generated controllers (part of `make bench`; not a test).

C: ns per evaluation of the generated double variant, of a hand-written C
version of the same law (the obvious formulas, no guards, no input checks)
and of CasADi's generated C (`casadi.Function.generate` of
`uwmr_symbolic.codegen.casadi_function`), each in its own translation unit,
all compiled with the same `gcc -O2 -std=c99`, called on the same 2e4
inputs (moderate errors and references, as on a robot: the fast path), median
of 101 passes, the three interleaved in every pass so that a load on the
machine hits them alike.  Python: generated module vs `sympy.lambdify` of the
law vs plain numpy, 1e6 inputs, median of 9 interleaved rounds.

Generation: wall time of the translation validation (`codegen.validate`)
and of the whole `build` + validation, per design of designs/,
tests/designs/ and tests/designs_codegen/ (verification excluded).

    python benchmarks/bench_codegen.py [--quick] [--validation-only]
"""
from __future__ import annotations

import argparse
import os
import importlib.util
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import sympy as sp

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from uwmr_symbolic import e1 as E1, e2 as E2  # noqa: E402
from uwmr_symbolic.codegen import casadi_function  # noqa: E402
from uwmr_symbolic.codegen.c_backend import c_identifier  # noqa: E402
from uwmr_symbolic.design import load_design  # noqa: E402

FLAGS = ["-O2", "-std=c99"]

# df/de2 written by hand, as one would from the paper (rho = e1^2 + e2^2)
HAND_G = {
    "design1_jiang": "e2 / (1.0 + rho)",
    "design2_sqrt": "e2 / sqrt(1.0 + rho)",
    "design3_logcosh": "4.0 * e2 * tanh(sqrt(4.0 * rho + 1.0) - 1.0) / sqrt(4.0 * rho + 1.0)",
    "design4_cosine": "e2 / sqrt(1.0 + rho) * (sqrt(1.0 + rho) - 1.0 > 3.141592653589793 ? 1.0 : sin(sqrt(1.0 + rho) - 1.0))",
    "design5_rational": "2.0 * e2 / ((1.0 + rho) * (1.0 + rho))",
    "unsaturated_baseline": "e2",
}

HAND_C = r"""
#include <math.h>
int hand_control(double e1, double e2, double e3, double vr, double wr,
                 double k1, double k2, double lam, double *v, double *w)
{{
    const double rho = e1 * e1 + e2 * e2;
    const double g = {g};
    const double sinc = e3 == 0.0 ? 1.0 : sin(e3) / e3;
    *v = vr * cos(e3) + k1 * tanh(e1);
    *w = wr + lam * vr * g * sinc + k2 * tanh(e3);
    return 0;
}}
"""

DRIVER = r"""
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "{stem}.h"
#include "casadi_{ident}.h"

int hand_control(double e1, double e2, double e3, double vr, double wr,
                 double k1, double k2, double lam, double *v, double *w);

static double now(void)
{{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}}

static int cmp(const void *a, const void *b)
{{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}}

int main(int argc, char **argv)
{{
    long n = atol(argv[1]), i;
    int reps = atoi(argv[2]), r, k;
    double *x = malloc(sizeof(double) * 8 * n), t[3][256], sink = 0.0;
    FILE *f = fopen(argv[3], "rb");
    casadi_int sz_arg, sz_res, sz_iw, sz_w;
    const double **arg;
    double **res, *wk;
    casadi_int *iw;
    if (fread(x, sizeof(double), 8 * n, f) != (size_t)(8 * n)) return 2;
    fclose(f);
    control_{ident}_work(&sz_arg, &sz_res, &sz_iw, &sz_w);
    arg = malloc(sizeof(double *) * (sz_arg > 8 ? sz_arg : 8));
    res = malloc(sizeof(double *) * (sz_res > 2 ? sz_res : 2));
    iw = malloc(sizeof(casadi_int) * (sz_iw + 1));
    wk = malloc(sizeof(double) * (sz_w + 1));
    for (r = 0; r < reps; ++r) {{
        for (k = 0; k < 3; ++k) {{
            double t0 = now();
            for (i = 0; i < n; ++i) {{
                const double *a = x + 8 * i;
                double v, w;
                if (k == 0) {{
                    uwmr_{ident}_gains g;
                    g.k1 = a[5]; g.k2 = a[6]; g.lam = a[7];
                    uwmr_{ident}_control(a[0], a[1], a[2], a[3], a[4], &g, &v, &w);
                }} else if (k == 1) {{
                    hand_control(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], &v, &w);
                }} else {{
                    int j;
                    for (j = 0; j < 8; ++j) arg[j] = a + j;
                    res[0] = &v;
                    res[1] = &w;
                    control_{ident}(arg, res, iw, wk, 0);
                }}
                sink += v + w;
            }}
            t[k][r] = (now() - t0) / n * 1e9;
        }}
    }}
    for (k = 0; k < 3; ++k) {{
        qsort(t[k], reps, sizeof(double), cmp);
        printf("%.3f ", t[k][reps / 2]);
    }}
    printf("%g\n", sink == 12345.678 ? 1.0 : 0.0);
    return 0;
}}
"""


def inputs(n, seed=0):
    rng = np.random.default_rng(seed)
    x = np.empty((n, 8))
    x[:, 0:2] = 10.0 ** rng.uniform(-3, 1, (n, 2)) * rng.choice([-1, 1], (n, 2))
    x[:, 2] = rng.uniform(-np.pi, np.pi, n)
    x[:, 3] = rng.uniform(0.0, 0.7, n)
    x[:, 4] = rng.uniform(-2.0, 2.0, n)
    x[:, 5:] = (0.25, 0.7, 0.3)
    return x


def bench_c(stem, x, reps, work: Path):
    src = ROOT / "generated" / stem
    ident = c_identifier(stem)
    fn = casadi_function(ROOT / "designs" / f"{stem}.py", force=True)     # the baseline is not verified
    sx_in = fn.sx_in()
    fn = type(fn)(f"control_{ident}", sx_in, fn.call(sx_in), fn.name_in(), fn.name_out())
    fn.generate(f"casadi_{ident}.c", {"with_header": True})
    Path(f"casadi_{ident}.c").replace(work / f"casadi_{ident}.c")
    Path(f"casadi_{ident}.h").replace(work / f"casadi_{ident}.h")
    (work / "hand.c").write_text(HAND_C.format(g=HAND_G[stem]))
    (work / "driver.c").write_text(DRIVER.format(stem=stem, ident=ident))
    x.tofile(work / "x.bin")
    exe = work / f"bench_{stem}"
    cmd = ["gcc", *FLAGS, "-I", str(src), "-I", str(work), str(src / f"{stem}.c"), str(work / "hand.c"),
           str(work / f"casadi_{ident}.c"), str(work / "driver.c"), "-o", str(exe), "-lm"]
    subprocess.run(cmd, check=True, cwd=work)
    out = subprocess.run([str(exe), str(len(x)), str(reps), str(work / "x.bin")], check=True,
                         capture_output=True, text=True).stdout.split()
    return [float(v) for v in out[:3]]


def law_expr(design):
    e3, vr, wr, k1, k2, lam = sp.symbols("e3 vr wr k1 k2 lam", real=True)
    g = sp.diff(design.f, E2)
    sinc = sp.Piecewise((1, sp.Eq(e3, 0)), (sp.sin(e3) / e3, True))
    v = vr * sp.cos(e3) + k1 * sp.tanh(E1)
    w = wr + lam * vr * g * sinc + k2 * sp.tanh(e3)
    return (E1, E2, e3, vr, wr, k1, k2, lam), (v, w)


def plain_numpy(stem):
    g = {"design1_jiang": lambda e1, e2, rho: e2 / (1 + rho),
         "design2_sqrt": lambda e1, e2, rho: e2 / np.sqrt(1 + rho),
         "design3_logcosh": lambda e1, e2, rho: 4 * e2 * np.tanh(np.sqrt(4 * rho + 1) - 1) / np.sqrt(4 * rho + 1),
         "design4_cosine": lambda e1, e2, rho: e2 / np.sqrt(1 + rho) * np.where(np.sqrt(1 + rho) - 1 > np.pi, 1.0,
                                                                                np.sin(np.sqrt(1 + rho) - 1)),
         "design5_rational": lambda e1, e2, rho: 2 * e2 / (1 + rho) ** 2,
         "unsaturated_baseline": lambda e1, e2, rho: e2}[stem]

    def control(e1, e2, e3, vr, wr, k1, k2, lam):
        rho = e1 * e1 + e2 * e2
        with np.errstate(invalid="ignore", divide="ignore"):
            sinc = np.where(e3 == 0, 1.0, np.sin(e3) / e3)
        return vr * np.cos(e3) + k1 * np.tanh(e1), wr + lam * vr * g(e1, e2, rho) * sinc + k2 * np.tanh(e3)
    return control


def bench_python(stem, n, reps):
    design = load_design(ROOT / "designs" / f"{stem}.py")
    spec = importlib.util.spec_from_file_location(stem, ROOT / "generated" / stem / f"{stem}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    x = inputs(n, seed=1)
    args = [x[:, i].copy() for i in range(5)] + [0.25, 0.7, 0.3]
    syms, (v, w) = law_expr(design)
    lam = sp.lambdify(syms, [v, w], "numpy")
    plain = plain_numpy(stem)
    fns = (mod.control, lam, plain)
    times = [[], [], []]
    with np.errstate(all="ignore"):
        for f in fns:
            f(*args)
        for _ in range(reps):
            for f, t in zip(fns, times):
                t0 = time.perf_counter()
                f(*args)
                t.append(time.perf_counter() - t0)
    return tuple(statistics.median(t) for t in times)


def bench_validation():
    """Seconds per design for build (render) and for the validation."""
    from uwmr_symbolic.codegen import CodegenInvalid, CodegenRefused, build, validate_build
    from uwmr_symbolic.verify import verify_design
    paths = sorted((ROOT / "designs").glob("*.py")) + sorted((ROOT / "tests/designs").glob("v*.py")) \
        + sorted((ROOT / "tests/designs_codegen").glob("*.py"))
    print("Generation with validation, seconds per design (verification excluded):")
    print(f"{'design':22s} {'render':>7s} {'validate':>9s}  result")
    worst = 0.0
    for path in paths:
        rep = verify_design(path)
        t0 = time.perf_counter()
        try:
            model, files = build(path, force=True, report=rep)
        except CodegenRefused as exc:
            print(f"{path.stem:22s} refused: {exc}")
            continue
        t1 = time.perf_counter()
        try:
            res = validate_build(path, model, files, rep)
            result = "ok, " + ", ".join(f"{t.name} {t.rows}" for t in res.targets if t.rows)
        except CodegenInvalid as exc:
            result = "REFUSED: " + exc.reasons[0][:80]
        t2 = time.perf_counter()
        worst = max(worst, t2 - t1)
        print(f"{path.stem:22s} {t1 - t0:7.2f} {t2 - t1:9.2f}  {result}")
    print(f"slowest validation: {worst:.2f} s (goal <= 5 s)\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="fewer inputs and repetitions")
    ap.add_argument("--validation-only", action="store_true", help="only the generation/validation times")
    a = ap.parse_args()
    bench_validation()
    if a.validation_only:
        return
    n_c, reps_c, n_py, reps_py = (20_000, 11, 100_000, 3) if a.quick else (20_000, 101, 1_000_000, 9)
    x = inputs(n_c)
    print(f"C, ns per evaluation (median of {reps_c}, {n_c} inputs, gcc {' '.join(FLAGS)}):")
    print(f"{'design':22s} {'generated':>10s} {'hand':>8s} {'casadi':>8s} {'gen/hand':>9s} {'gen/casadi':>10s}")
    with tempfile.TemporaryDirectory() as tmp:
        for stem in HAND_G:
            work = Path(tmp) / stem
            work.mkdir()
            cwd = os.getcwd()
            os.chdir(work)
            try:
                gen, hand, cas = bench_c(stem, x, reps_c, work)
            finally:
                os.chdir(cwd)
            print(f"{stem:22s} {gen:10.1f} {hand:8.1f} {cas:8.1f} {gen / hand:8.2f}x {gen / cas:9.2f}x")
    print(f"\nPython, ms per call on {n_py} inputs (median of {reps_py}):")
    print(f"{'design':22s} {'generated':>10s} {'lambdify':>9s} {'numpy':>8s} {'gen/numpy':>10s}")
    for stem in HAND_G:
        gen, lam, plain = bench_python(stem, n_py, reps_py)
        print(f"{stem:22s} {gen * 1e3:10.1f} {lam * 1e3:9.1f} {plain * 1e3:8.1f} {gen / plain:9.2f}x")


if __name__ == "__main__":
    main()
