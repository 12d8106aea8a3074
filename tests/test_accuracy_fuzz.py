"""Soundness fuzz of the error analysis (`codegen.accuracy`): random
expressions in x > 0 (hypothesis), random boxes [a, 16 a] of every
magnitude; whenever the analysis certifies |y^ - y| <= E |y| + A on the box,
the expression as the Python printer emits it (numpy, the same operations
as the C printer) is evaluated at points of the box in float64 and float32
and compared with 700-digit mpmath.  A single violation fails.

The fixed-seed profile runs in `make test`; ACCURACY_FUZZ_EXAMPLES=n runs
n random expressions (fresh seed) instead."""
import os

import mpmath
import numpy as np
import pytest
import scipy.special  # noqa: F401 - the printed code may call it
import sympy as sp
from flint import arb
from hypothesis import HealthCheck, given, settings, strategies as st
from sympy.codegen.cfunctions import expm1, log1p

from uwmr_symbolic.codegen.accuracy import Analysis, Uncertified, _iv
from uwmr_symbolic.codegen.law import plain
from uwmr_symbolic.codegen.printers import PyPrinter
from uwmr_symbolic.kernel.arb import precision

X = sp.Symbol("x", positive=True)
EXAMPLES = int(os.environ.get("ACCURACY_FUZZ_EXAMPLES", "0"))
RANGE = {"double": 300, "float": 37}
#: enough for 1 + x at x = 1e-300 to keep 300 digits of x (the reference has no log1p)
DIGITS = 700

leaves = st.one_of(st.just(X), st.just(X), st.sampled_from([sp.Integer(1), sp.Integer(2), sp.Rational(1, 3),
                                                             sp.Rational(7, 5), sp.pi / 2]))


def _combine(children):
    pairs = st.tuples(children, children)
    return st.one_of(
        pairs.map(lambda p: p[0] + p[1]),
        pairs.map(lambda p: p[0] * p[1]),
        pairs.map(lambda p: p[0] / p[1]),
        pairs.map(lambda p: p[0] - p[1]),
        st.tuples(children, st.sampled_from([2, 3, -1, sp.Rational(1, 2), sp.Rational(3, 2),
                                             sp.Rational(-1, 2), sp.Rational(5, 3)])).map(lambda p: p[0] ** p[1]),
        st.tuples(children, st.sampled_from([log1p, sp.sqrt, sp.exp, sp.tanh, sp.atan, sp.asinh, sp.erf,
                                             sp.log, expm1, sp.cosh])).map(lambda p: p[1](p[0])))


expressions = st.recursive(leaves, _combine, max_leaves=6).filter(lambda e: e.has(X))


def _points(a, b, prec, n=24):
    dtype = np.float32 if prec == "float" else np.float64
    pts = np.exp(np.linspace(np.log(a), np.log(b), n)).astype(dtype)
    return pts[(pts >= a) & (pts <= b)]


def _check(expr, a, b, prec):
    with precision(128):
        try:
            E, A = Analysis(prec, {X: (_iv(a, b), arb(0), arb(0))}).error(expr)
        except Uncertified:
            return 0
    E, A = float(E.upper()) * (1 + 1e-12), float(A.upper()) * (1 + 1e-12)
    code = PyPrinter().doprint(expr)
    pts = _points(a, b, prec)
    with np.errstate(all="ignore"):
        got = eval(code, {"numpy": np, "scipy": scipy, "x": pts})      # noqa: S307 - our own printer's output
    got = np.broadcast_to(np.asarray(got), pts.shape)
    assert got.dtype == pts.dtype, (code, got.dtype)
    exact_fn = sp.lambdify(X, plain(expr), "mpmath")
    checked = 0
    with mpmath.workdps(DIGITS):
        for p, y_hat in zip(pts, got):
            y = exact_fn(mpmath.mpf(float(p)))
            if isinstance(y, mpmath.mpc) or not mpmath.isfinite(y):
                continue
            assert np.isfinite(y_hat), (prec, code, float(p), float(y_hat), y)
            err = abs(mpmath.mpf(float(y_hat)) - y)
            assert err <= E * abs(y) + A, (prec, code, (a, b), float(p), float(y_hat), mpmath.nstr(y, 20), E, A)
            checked += 1
    return checked


def _run(expr, ea, prec):
    a = 10.0 ** ea
    return _check(expr, a, 16 * a, prec)


@settings(max_examples=EXAMPLES or 150, derandomize=not EXAMPLES, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(expressions, st.integers(-RANGE["double"], RANGE["double"] - 2), st.integers(-RANGE["float"], RANGE["float"] - 2))
def test_certified_bounds_hold_in_float64_and_float32(expr, ed, ef):
    _run(expr, ed, "double")
    _run(expr, ef, "float")


def test_known_expressions_are_checked():
    """The harness itself: certified cases do get compared, and a wrong
    (too small) bound would fail."""
    assert _check(log1p(X) * sp.tanh(X) + sp.sqrt(X), 1.0, 16.0, "double") > 10
    assert _check(sp.exp(X) / (1 + X ** 2), 1e-3, 1.6e-2, "float") > 10
    with pytest.raises(AssertionError):
        with precision(128):
            _check_with_bound(sp.log(1 + X), 1e-10, 1.6e-9, "double", 1e-12)


def _check_with_bound(expr, a, b, prec, E):
    """_check with a forced bound E (to show the comparison can fail)."""
    code = PyPrinter().doprint(expr)
    pts = _points(a, b, prec)
    got = eval(code, {"numpy": np, "x": pts})        # noqa: S307
    fn = sp.lambdify(X, expr, "mpmath")
    with mpmath.workdps(60):
        for p, y_hat in zip(pts, got):
            y = fn(mpmath.mpf(float(p)))
            assert abs(mpmath.mpf(float(y_hat)) - y) <= E * abs(y)
