"""Designs nobody wrote by hand: hypothesis builds random radial designs
f = G(rho), rho = e1^2 + e2^2, from a small grammar (sums and multiples of
compositions of log(1 + u), asinh, sqrt(1 + u) - 1, atan, tanh, erf,
log cosh(sqrt(1 + u) - 1) over c rho and c rho^2), keeps those whose P1-P8
the verifier proves, and generates their code: `generate` must write it,
i.e. C double, C float (strict build), Python and CasADi pass the
translation validation against the exact law (`codegen.validate`), and the
C built with -fsanitize=address,undefined,float-divide-by-zero runs the
validation sample without a report.

A fixed-seed profile of UWMR_FUZZ_EXAMPLES examples (default 4) runs in the
test suite; `make fuzz-codegen` runs 40 (UWMR_FUZZ_EXAMPLES) and prints how many designs were
tried, proved and generated."""
from __future__ import annotations

import collections
import os
import shutil
import sys

import numpy as np
import pytest
import sympy as sp

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import HealthCheck, given, settings, strategies as st  # noqa: E402

from uwmr_symbolic.codegen import CodegenInvalid, build, generate  # noqa: E402
from uwmr_symbolic.codegen.harness import build_executable, run_executable  # noqa: E402
from uwmr_symbolic.codegen.validate import sample_inputs  # noqa: E402
from uwmr_symbolic.verify import verify_design  # noqa: E402

EXAMPLES = int(os.environ.get("UWMR_FUZZ_EXAMPLES", "3"))
TIMEOUT = float(os.environ.get("UWMR_FUZZ_TIMEOUT", "10"))
RHO = sp.Symbol("rho", positive=True)
COUNTS = collections.Counter()
pytestmark = [pytest.mark.slow, pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc")]

WRAPS = [
    lambda u: sp.log(1 + u),
    sp.asinh,
    lambda u: sp.sqrt(1 + u) - 1,
    sp.atan,
    sp.tanh,
    sp.erf,
    lambda u: sp.log(sp.cosh(sp.sqrt(1 + u) - 1)),
]
COEFFS = [sp.Rational(1, 2), sp.Integer(1), sp.Integer(2)]


@st.composite
def radial_profiles(draw):
    """G(rho): one or two terms, each c * W1(W2(c' rho^k)) with 1-2 wrappers."""
    terms = []
    for _ in range(draw(st.integers(1, 2))):
        u = draw(st.sampled_from(COEFFS)) * RHO ** draw(st.sampled_from([1, 2]))
        for _ in range(draw(st.integers(1, 2))):
            u = draw(st.sampled_from(WRAPS))(u)
        terms.append(draw(st.sampled_from(COEFFS)) * u)
    return sp.Add(*terms)


def _design_file(path, G):
    f = G.subs(RHO, sp.Symbol("e1", real=True) ** 2 + sp.Symbol("e2", real=True) ** 2)
    path.write_text(
        "from sympy import *\n"
        "e1, e2 = symbols('e1 e2', real=True)\n"
        f"name = {sp.sstr(G)!r}\n"
        f"f = {sp.sstr(f)}\n"
        "gains = {'circle': dict(k1=0.25, k2=0.7, lam=0.1, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}\n")


@pytest.fixture(scope="module", autouse=True)
def summary():
    yield
    print(f"\ncodegen fuzz: {COUNTS['tried']} designs tried, {COUNTS['proved']} proved P1-P8, "
          f"{COUNTS['generated']} generated and validated, {COUNTS['refused']} refused by validation",
          file=sys.stderr)


@settings(max_examples=EXAMPLES, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(G=radial_profiles())
def test_proved_random_designs_generate_validated_code(G, tmp_path_factory):
    tmp = tmp_path_factory.mktemp("fuzz")
    path = tmp / "fuzz_design.py"
    _design_file(path, G)
    COUNTS["tried"] += 1
    if os.environ.get("UWMR_FUZZ_VERBOSE"):
        print(f"fuzz: G(rho) = {G}", file=sys.stderr)
    report = verify_design(path, timeout=TIMEOUT)
    if report.error is not None or not all(v.proved for v in report.properties.values()):
        return
    COUNTS["proved"] += 1
    try:
        written = generate(path, tmp / "out", report=report)
    except CodegenInvalid as exc:
        COUNTS["refused"] += 1
        pytest.fail(f"G(rho) = {G}: a proved design whose code fails validation: {exc.reasons[0]}")
    COUNTS["generated"] += 1
    assert len(written) == 5
    # the sanitizer build on the validation sample: no report, the status codes of the strict build
    model, _ = build(path, report=report)
    exe = build_executable(tmp / "out", "fuzz_design", tmp,
                           extra=("-O1", "-g", "-fsanitize=address,undefined,float-divide-by-zero",
                                  "-fno-sanitize-recover=all"))
    for f32 in (False, True):
        x = sample_inputs(model, "float" if f32 else "double", (0.25, 0.7, 0.1), n_random=200)
        v, w, st, res = run_executable(exe, x, tmp, f32=f32, env={"ASAN_OPTIONS": "detect_leaks=1"})
        assert res.returncode == 0 and "runtime error" not in res.stderr, f"G(rho) = {G}: {res.stderr[-2000:]}"
        assert np.isin(st, [0, 4]).all()
