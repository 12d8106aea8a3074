"""Designs nobody wrote by hand: hypothesis builds random radial designs
f = G(rho), rho = e1^2 + e2^2, from a small grammar (`codegen_fuzz_grammar`:
sums and multiples of compositions of log(1 + u), asinh, sqrt(1 + u) - 1,
atan, tanh, erf, log cosh(sqrt(1 + u) - 1) over c rho and c rho^2; and
Piecewise profiles with an exact C^2 join on a circle, a s^2 inside and a
linear part plus a bounded sigmoid outside), keeps those whose P1-P8 the
verifier proves, and generates their code: `generate` must write it,
i.e. C double, C float (strict build), Python and CasADi pass the
translation validation against the exact law (`codegen.validate`), and the
C built with -fsanitize=address,undefined,float-divide-by-zero runs the
validation sample without a report.

A fixed-seed profile of UWMR_FUZZ_EXAMPLES examples (default 3, plus one
explicit Piecewise design that must be proved) runs in the test suite;
`make fuzz-codegen` runs 40 (UWMR_FUZZ_EXAMPLES) and prints how many designs
were tried, proved and generated (and how many of them Piecewise)."""
from __future__ import annotations

import collections
import os
import shutil
import sys

import numpy as np
import pytest
import sympy as sp

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import HealthCheck, example, given, settings, strategies as st  # noqa: E402

from codegen_fuzz_grammar import (RHO, S, JoinError, c2_join, check_c2, design_source,  # noqa: E402
                                  piecewise_profiles, radial_profiles)
from uwmr_symbolic.codegen import CodegenInvalid, build, generate  # noqa: E402
from uwmr_symbolic.codegen.harness import build_executable, run_executable  # noqa: E402
from uwmr_symbolic.codegen.validate import sample_inputs  # noqa: E402
from uwmr_symbolic.verify import verify_design  # noqa: E402

EXAMPLES = int(os.environ.get("UWMR_FUZZ_EXAMPLES", "3"))
TIMEOUT = float(os.environ.get("UWMR_FUZZ_TIMEOUT", "10"))
COUNTS = collections.Counter()
FAILURES: list[str] = []      # one line per failing design; test_no_design_failed reports them all
pytestmark = [pytest.mark.slow, pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc")]

# always in the profile, must be proved: F = s^2 inside the unit circle, atan join outside
PIECEWISE_EXAMPLE = c2_join(1, 1, "atan", 1, 2)[0]


def _design_file(path, G):
    path.write_text(design_source(G))


@pytest.fixture(scope="module", autouse=True)
def summary():
    yield
    print(f"\ncodegen fuzz: {COUNTS['tried']} designs tried ({COUNTS['pw tried']} Piecewise), "
          f"{COUNTS['proved']} proved P1-P8 ({COUNTS['pw proved']} Piecewise), "
          f"{COUNTS['generated']} generated and validated ({COUNTS['pw generated']} Piecewise), "
          f"{COUNTS['refused']} refused by validation, {COUNTS['sanitizer']} failed the sanitizer build",
          file=sys.stderr)
    for line in FAILURES:
        print(f"codegen fuzz FAILURE: {line}", file=sys.stderr)


@settings(max_examples=EXAMPLES, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(G=st.one_of(radial_profiles(), piecewise_profiles()))
@example(G=PIECEWISE_EXAMPLE)
def test_proved_random_designs_generate_validated_code(G, tmp_path_factory):
    tmp = tmp_path_factory.mktemp("fuzz")
    path = tmp / "fuzz_design.py"
    _design_file(path, G)
    pw = G.has(sp.Piecewise)
    count = (lambda key: COUNTS.update([key, "pw " + key])) if pw else (lambda key: COUNTS.update([key]))
    count("tried")
    if os.environ.get("UWMR_FUZZ_VERBOSE"):
        print(f"fuzz: G(rho) = {G}", file=sys.stderr)
    # the explicit Piecewise example must be proved: a generous timeout on a loaded machine
    report = verify_design(path, timeout=max(TIMEOUT, 120) if G == PIECEWISE_EXAMPLE else TIMEOUT)
    proved = report.error is None and all(v.proved for v in report.properties.values())
    if G == PIECEWISE_EXAMPLE:
        assert proved, [f"{p} {v.status}: {v.reason}" for p, v in report.properties.items() if not v.proved]
    if not proved:
        return
    count("proved")
    # a failing design is recorded and the run goes on (every design of `make fuzz-codegen`
    # is tried); test_no_design_failed, run after this test, fails with all of them
    try:
        written = generate(path, tmp / "out", report=report)
    except CodegenInvalid as exc:
        COUNTS["refused"] += 1
        FAILURES.append(f"G(rho) = {G}: a proved design whose code fails validation: {exc.reasons[0]}")
        return
    count("generated")
    assert len(written) == 5
    # the sanitizer build on the validation sample: no report, the status codes of the strict build
    model, _ = build(path, report=report)
    exe = build_executable(tmp / "out", "fuzz_design", tmp,
                           extra=("-O1", "-g", "-fsanitize=address,undefined,float-divide-by-zero",
                                  "-fno-sanitize-recover=all"))
    for f32 in (False, True):
        x = sample_inputs(model, "float" if f32 else "double", (0.25, 0.7, 0.1), n_random=200)
        v, w, st, res = run_executable(exe, x, tmp, f32=f32, env={"ASAN_OPTIONS": "detect_leaks=1"})
        report_line = next((ln.strip() for ln in res.stderr.splitlines() if "runtime error" in ln or "ERROR" in ln),
                           f"exit status {res.returncode}")
        if res.returncode != 0 or "runtime error" in res.stderr:
            COUNTS["sanitizer"] += 1
            FAILURES.append(f"G(rho) = {G}: sanitizer build ({'float' if f32 else 'double'}): {report_line}")
            return
        if not np.isin(st, [0, 4]).all():
            COUNTS["sanitizer"] += 1
            FAILURES.append(f"G(rho) = {G}: sanitizer build ({'float' if f32 else 'double'}): status "
                            f"{int(st[~np.isin(st, [0, 4])][0])} on a finite input")
            return


def test_no_design_failed():
    """Runs after the fuzz test (file order): every proved design it tried
    generated validated code that ran cleanly under the sanitizers."""
    assert not FAILURES, f"{len(FAILURES)} fuzzed design(s) failed:\n" + "\n".join(FAILURES)


# the Piecewise grammar itself: every join it draws is exactly C^2


def test_c2_join_matches_value_slope_and_curvature_exactly():
    for sigmoid in ("atan", "tanh", "erf", "algebraic"):
        G, inner, outer = c2_join(sp.Rational(1, 2), sp.Rational(3, 2), sigmoid, sp.Rational(1, 2), 2)
        assert G.has(sp.Piecewise) and G.args[0][1] == (RHO <= sp.Rational(9, 4))
        check_c2(inner, outer, sp.Rational(3, 2))
        # beyond the join: F' > 0, F unbounded (c1 > 0)
        d = sp.diff(outer, S)
        assert all(sp.N(d.subs(S, v)) > 0 for v in (sp.Rational(3, 2), 2, 10, 10 ** 6))
        assert sp.N(outer.subs(S, 10 ** 6)) > 10 ** 5


def test_a_join_that_is_only_c1_is_caught():
    inner, R = S ** 2, sp.Integer(1)
    with pytest.raises(JoinError, match="derivative 2 differs"):
        check_c2(inner, 1 + 2 * (S - 1) + sp.tanh(S - 1) - (S - 1), R)
    check_c2(inner, 1 + 2 * (S - 1) + (S - 1) ** 2 + (S - 1) ** 3, R)


def test_design_files_are_read_back_exactly(tmp_path):
    from uwmr_symbolic.design import load_design
    G = c2_join(1, 1, "algebraic", 1, 2)[0]          # holds 1/3: a Python float if printed as code
    _design_file(tmp_path / "d.py", G)
    f = load_design(tmp_path / "d.py").f
    assert not f.atoms(sp.Float)
    e1, e2 = sp.symbols("e1 e2", real=True)
    assert sp.simplify(f - G.subs(RHO, e1 ** 2 + e2 ** 2)) == 0
