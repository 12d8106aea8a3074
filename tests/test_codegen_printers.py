"""The printers cannot change an expression's meaning: every operator pair,
powers of sums with exponents +-1/2, +-3/2, +-2, ..., negative bases, unary
minus, nested powers and every supported function, printed as C double, C
float (compiled with the strict flags) and Python, evaluated and compared
with SymPy/mpmath at 30 digits.  Constants never become M_* macros."""
from __future__ import annotations

import ctypes
import itertools
import math
import shutil
import subprocess

import mpmath
import numpy as np
import pytest
import scipy.special  # noqa: F401  (used by the printed Python)
import sympy as sp
from sympy.codegen.cfunctions import expm1, hypot, log1p

from uwmr_symbolic.codegen.harness import STRICT
from uwmr_symbolic.codegen.printers import CPrinter, PyPrinter, Unsupported

pytestmark = pytest.mark.slow        # compiles ~350 expressions: not in make test-fast

x, y, z = sp.symbols("x y z", real=True)
EXPS = [sp.Rational(1, 2), -sp.Rational(1, 2), sp.Rational(3, 2), -sp.Rational(3, 2), 2, -2, 3, -1,
        sp.Rational(5, 2), 9, sp.Rational(1, 3)]


def _pairs():
    """op1(op2(a, b), c) and op1(a, op2(b, c)) for every pair of binary
    operators, with unary minus on either side; bases kept positive where the
    exponent is fractional (the sums below are > 0 on the sample points)."""
    binops = {
        "add": lambda a, b: a + b, "sub": lambda a, b: a - b, "mul": lambda a, b: a * b,
        "div": lambda a, b: a / b,
    }
    out = []
    ops = list(binops)
    for o1, o2 in itertools.product(ops, repeat=2):
        f1, f2 = binops[o1], binops[o2]
        out += [f1(f2(x, y), z), f1(x, f2(y, z)), -f1(f2(x, y), z), f1(-f2(x, y), z), f1(x, -f2(y, z))]
    # powers of sums, products, quotients and negated sums, in every position
    for n in EXPS:
        for base in (x + y, x * y + z, 3 - x - y + 2 * z):
            p = base ** n
            out += [p, x * p, x / p, z - p, -p, (x - y) / p, sp.sqrt(p) * y, 1 / (1 + p)]
    # negative bases with integer exponents
    for n in (2, -2, 3, -3, 5):
        out += [(x - 3) ** n, (-x) ** n * y, (y - x - 4) ** n - z, -(x - 5) ** n, z / (x - 4) ** n]
    return out


def _functions():
    return [sp.erf(x - y), sp.erfc(x * y), sp.gamma(x + y), sp.loggamma(x + z), sp.asinh(x - 3 * y),
            sp.acosh(x + y + 1), sp.atanh((x - y) / 4), sp.Min(x, y, z), sp.Max(x - y, z - 2),
            sp.Abs(x - y - 1), sp.sign(x - y) * z, sp.exp(-x * y), sp.log(x + y), log1p(x * y * 1e-9),
            expm1(x * 1e-10) / x, sp.atan(x / y), sp.tanh(x - 2 * y), sp.cosh(x) - sp.sinh(y),
            sp.pi / 2 * x, 2 / sp.sqrt(sp.pi) * sp.exp(-x ** 2), sp.log(2) * y + sp.log(10) * z,
            sp.sqrt(2) * x + 1 / sp.sqrt(2), sp.E * x, x / sp.pi + 2 / sp.pi, hypot(x, y - 4),
            sp.Piecewise((x ** 2, x < y), (sp.sqrt(y), True)), sp.Rational(1, 3) * x ** sp.Rational(1, 3)]


EXPRS = _pairs() + _functions()
rng = np.random.default_rng(7)
POINTS = np.concatenate([rng.uniform(0.5, 2.0, (40, 3)), np.array([[1.25, 0.75, 1.5], [2.0, 0.5, 0.625]])])


def _exact(expr):
    fn = sp.lambdify((x, y, z), expr, "mpmath")
    out = []
    with mpmath.workdps(30):
        for p in POINTS:
            try:
                val = fn(*[mpmath.mpf(float(c)) for c in p])
                out.append(float(val) if mpmath.im(val) == 0 else math.nan)
            except (ValueError, ZeroDivisionError):
                out.append(math.nan)
    return np.array(out)


def _check(got, exact, tol, what):
    ok = np.isfinite(exact)
    assert ok.sum() >= 10, what
    err = np.abs(got[ok] - exact[ok]) / np.maximum(np.abs(exact[ok]), 1e-3)
    assert err.max() <= tol, f"{what}: relative error {err.max():.3g}"


@pytest.fixture(scope="module")
def compiled(tmp_path_factory):
    if shutil.which("gcc") is None:
        pytest.skip("needs gcc")
    tmp = tmp_path_factory.mktemp("printers")
    lines = ["#include <math.h>"]
    for i, e in enumerate(EXPRS):
        for prec, t, sfx in (("double", "double", ""), ("float", "float", "_f")):
            code = CPrinter(prec).doprint(e)
            assert "M_" not in code, code
            lines.append(f"{t} f{i}{sfx}({t} x, {t} y, {t} z) {{ (void)x; (void)y; (void)z; return {code}; }}")
    src = tmp / "exprs.c"
    src.write_text("\n".join(lines) + "\n")
    lib = tmp / "libexprs.so"
    res = subprocess.run(["gcc", *STRICT, "-O1", "-fPIC", "-shared", str(src), "-o", str(lib), "-lm"],
                         capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    return ctypes.CDLL(str(lib))


def test_printed_c_and_python_mean_what_sympy_means(compiled):
    assert len(EXPRS) > 250
    for i, expr in enumerate(EXPRS):
        _one(compiled, i, expr)


def _one(compiled, i, expr):
    exact = _exact(expr)
    fd, ff = getattr(compiled, f"f{i}"), getattr(compiled, f"f{i}_f")
    fd.restype, fd.argtypes = ctypes.c_double, [ctypes.c_double] * 3
    ff.restype, ff.argtypes = ctypes.c_float, [ctypes.c_float] * 3
    cd = np.array([fd(*map(float, p)) for p in POINTS])
    cf = np.array([ff(*map(float, p)) for p in POINTS])
    _check(cd, exact, 1e-12, f"C double {expr}")
    _check(cf, exact, 1e-4, f"C float {expr}")
    code = PyPrinter().doprint(expr)
    with np.errstate(all="ignore"):
        py = eval(code, {"numpy": np, "scipy": scipy}, {"x": POINTS[:, 0], "y": POINTS[:, 1], "z": POINTS[:, 2]})
    _check(np.broadcast_to(np.asarray(py, dtype=float), exact.shape), exact, 1e-12, f"Python {code}")


def test_issue_example_power_of_a_sum():
    rho = sp.Symbol("rho", positive=True)
    assert CPrinter().doprint((rho + 1) ** sp.Rational(3, 2)) == "((rho + 1.0)*sqrt(rho + 1.0))"
    assert CPrinter("float").doprint(sp.pi / 2) == "1.5707964F"


def test_unsupported_function_is_refused_not_printed():
    with pytest.raises(Unsupported, match="erfi"):
        CPrinter().doprint(sp.erfi(x))
    with pytest.raises(Unsupported, match="zeta"):
        PyPrinter().doprint(sp.zeta(x))
