"""Tests for uwmr_symbolic.interval: soundness against mpmath, tightness,
extended arithmetic, Undefined cases, modes, and the compiled evaluator."""
import math
from fractions import Fraction
import random
import time
from fractions import Fraction as F

import mpmath
import pytest
import sympy as sp
from flint import arb

from uwmr_symbolic.interval import Interval, IntervalFunction, Undefined, evaluate

s = sp.Symbol("s", real=True)
x, y = sp.symbols("x y", real=True)
t = sp.Symbol("t", positive=True)

DPS = 50


_LAMBDIFIED = {}


def mp_value(expr, syms, point):
    """expr at an exact (dyadic) point, via mpmath at DPS digits (None if undefined/complex)."""
    key = (expr, tuple(syms))
    if key not in _LAMBDIFIED:
        _LAMBDIFIED[key] = sp.lambdify(syms, expr, modules="mpmath")
    f = _LAMBDIFIED[key]
    with mpmath.workdps(DPS):
        args = [mpmath.mpf(p.numerator) / p.denominator for p in point]
        try:
            v = f(*args)
        except (ZeroDivisionError, ValueError):
            return None
        if isinstance(v, mpmath.mpc):
            if abs(v.imag) > mpmath.mpf(10) ** (-DPS + 10):
                return None
            v = v.real
        return mpmath.mpf(v)


def assert_encloses(iv, v, what=""):
    with mpmath.workdps(DPS):
        tol = mpmath.mpf(10) ** (-40) * (1 + abs(v))
        lo, hi = iv.lower_fraction(), iv.upper_fraction()
        if lo is not None:
            assert mpmath.mpf(lo.numerator) / lo.denominator - tol <= v, (what, iv, v)
        if hi is not None:
            assert v <= mpmath.mpf(hi.numerator) / hi.denominator + tol, (what, iv, v)


def dyadic(rng, lo, hi, bits=10):
    return F(rng.randint(int(lo * 2**bits), int(hi * 2**bits)), 2**bits)


def random_box(rng, lo, hi):
    a, b = sorted([dyadic(rng, lo, hi), dyadic(rng, lo, hi)])
    if rng.random() < 0.2:  # sometimes a point box, sometimes a tiny box
        b = a
    return a, b


def samples(rng, a, b, n):
    pts = [a, b]
    for _ in range(n):
        pts.append(a + (b - a) * F(rng.randint(0, 2**20), 2**20))
    return pts


UNIVARIATE = [
    sp.sqrt(1 + s**2),
    sp.log(1 + s**2) / 2,
    sp.tanh(sp.sqrt(4 * s**2 + 1) - 1),
    s / (1 + s**2),
    sp.sin(s) * s,
    sp.cosh(s - 3),
    s**2,
    s**3 - 2 * s,
    s**4 - 3 * s**2 + s,
    sp.Abs(s) - sp.Abs(s - 1),
    sp.Max(s, 1 - s, s**2 / 4),
    sp.Min(s, sp.cos(s)),
    sp.Piecewise((s**2, s < 1), (2 * s - 1, True)),
    sp.Piecewise((sp.sin(s), s <= 0), (s / 2, s < 2), (sp.Rational(1), True)),
    sp.exp(-s**2) * sp.cos(3 * s),
    sp.atan(s) - s / (1 + sp.Abs(s)),
    sp.erf(s) + sp.tanh(s) / 3,
    sp.asinh(s) * sp.sinh(s / 2),
    (1 + s**2) ** sp.Rational(3, 2) - s**2,
    sp.cos(s) ** 2 + sp.sin(2 * s),
    sp.sqrt(sp.Abs(s)),
    1 / (2 + sp.sin(s)),
    sp.log(sp.cosh(s)),
    2**s - s,
    sp.Float(0.75) * s**2 - sp.pi * s + sp.E,
    sp.sign(s) * s**2,
    sp.floor(s) + sp.ceiling(s / 2),
    sp.Heaviside(s) * s,
]


@pytest.mark.parametrize("expr", UNIVARIATE, ids=[str(e) for e in UNIVARIATE])
def test_soundness_univariate(expr):
    rng = random.Random(hash(str(expr)) & 0xFFFF)
    fn = IntervalFunction(expr, [s])
    for _ in range(25):
        a, b = random_box(rng, -6, 6)
        iv = fn(Interval.of(a, b))
        assert iv == evaluate(expr, {s: Interval.of(a, b)})
        for p in samples(rng, a, b, 8):
            v = mp_value(expr, [s], [p])
            assert v is not None
            assert_encloses(iv, v, (expr, a, b, p))


BIVARIATE = [
    (x + y) ** 2 - x * y,
    x / (1 + y**2) - y * sp.exp(x / 4),
    sp.sqrt(x**2 + y**2 + 1) - 1,
    sp.sin(x) * sp.cos(y) + sp.Max(x, y),
    sp.Piecewise((x * y, x + y > 0), (x - y, True)),
    sp.log(1 + x**2 + y**4) * sp.tanh(x - y),
    x**2 * y**3 - x**3 * y**2,
]


@pytest.mark.parametrize("expr", BIVARIATE, ids=[str(e) for e in BIVARIATE])
def test_soundness_bivariate(expr):
    rng = random.Random(hash(str(expr)) & 0xFFFF)
    fn = IntervalFunction(expr, [x, y])
    for _ in range(20):
        ax, bx = random_box(rng, -4, 4)
        ay, by = random_box(rng, -4, 4)
        iv = fn(Interval.of(ax, bx), Interval.of(ay, by))
        for px, py in zip(samples(rng, ax, bx, 6), samples(rng, ay, by, 6)):
            v = mp_value(expr, [x, y], [px, py])
            assert_encloses(iv, v, (expr, ax, bx, ay, by, px, py))


def test_soundness_on_positive_boxes_with_roots_and_logs():
    exprs = [sp.log(s) * s, s ** sp.Rational(1, 3) - sp.sqrt(s), s ** sp.pi, s**s,
             sp.acosh(1 + s), sp.atanh(1 / (1 + s)), sp.asin(1 / (1 + s)) + sp.acos(1 / (2 + s)),
             s ** sp.Float(0.3), 1 / sp.sqrt(s), sp.tan(s / 4)]
    rng = random.Random(7)
    for expr in exprs:
        for _ in range(15):
            a, b = random_box(rng, F(1, 64), 5)
            iv = evaluate(expr, {s: Interval.of(a, b)})
            for p in samples(rng, a, b, 6):
                assert_encloses(iv, mp_value(expr, [s], [p]), (expr, a, b, p))


# ---------------------------------------------------------------- tightness


@pytest.mark.parametrize("expr", [e for e in UNIVARIATE if not e.has(sp.floor, sp.sign, sp.Heaviside)])
def test_tight_at_point(expr):
    iv = evaluate(expr, {s: Interval.point(sp.Rational(1, 3))})
    assert iv.width() < 1e-30
    assert_encloses(iv, mp_value(expr, [s], [F(1, 3)]))


def test_point_constants():
    p = Interval.point(sp.sqrt(3) / 2)
    assert p.width() < 1e-35
    assert p.lower_float() <= math.sqrt(3) / 2 <= p.upper_float()
    q = Interval.point(sp.pi)
    assert q.lower_float() <= math.pi <= q.upper_float() and q.width() < 1e-35
    assert Interval.point(3).lower_fraction() == 3 == Interval.point(3).upper_fraction()
    assert Interval.point(F(3, 8)).is_point()
    third = Interval.point(F(1, 3))
    assert third.lower_fraction() < F(1, 3) < third.upper_fraction()


def test_integer_powers_are_tight():
    def ev(e, a, b):
        r = evaluate(e, {s: Interval.of(a, b)})
        return r.lower_fraction(), r.upper_fraction()

    assert ev(s**2, -1, 2) == (0, 4)
    assert ev(s**2, -3, 2) == (0, 9)
    assert ev(s**2, -3, -2) == (4, 9)
    assert ev(s**3, -2, 1) == (-8, 1)
    assert ev(s**4, F(-1, 2), F(1, 4)) == (0, F(1, 16))
    assert ev(s**-2, -1, 1) == (1, None)  # 1/s^2 >= 1, pole at 0
    assert ev(s**-2, 2, 4) == (F(1, 16), F(1, 4))
    assert ev(s**-3, -2, -1) == (-1, F(-1, 8))
    assert ev(sp.Abs(s), -3, 2) == (0, 3)
    assert ev(sp.Max(s, 0), -3, 2) == (0, 2)
    assert ev(sp.Min(s, 0), -3, 2) == (-3, 0)
    assert ev(sp.Mul(s, s, evaluate=False), -1, 2) == (-2, 4)  # no dependency tracking, still sound


def test_trig_interior_extrema():
    r = evaluate(sp.sin(s), {s: Interval.of(1, 2)})
    assert r.upper_fraction() == 1 and r.lower_float() <= math.sin(1) <= 0.85
    r = evaluate(sp.cos(s), {s: Interval.of(3, F(7, 2))})
    assert r.lower_fraction() == -1
    r = evaluate(sp.cos(s), {s: Interval.of(F(1, 2), 1)})
    assert math.cos(1) - 1e-15 < r.lower_float() <= math.cos(1) < math.cos(0.5) <= r.upper_float() < 0.88
    r = evaluate(sp.sin(s), {s: Interval.of(-100, 100)})
    assert (r.lower_fraction(), r.upper_fraction()) == (-1, 1)
    r = evaluate(sp.cosh(s), {s: Interval.of(-1, 2)})
    assert r.lower_fraction() == 1 and r.upper_float() >= math.cosh(2)


# ---------------------------------------------------------------- extended


def test_extended_tanh_at_infinity():
    e = sp.tanh((sp.sqrt(t**2 + 4) - t) / t)
    r = evaluate(e, {t: Interval.of(0, F(1, 100))})
    assert r.lower_float() >= 0.999
    assert r.upper_fraction() == 1


def test_extended_reciprocal_and_zero_limit():
    r = evaluate(1 / t, {t: Interval.of(0, F(1, 10))})
    assert r.upper_fraction() is None and r.hi == arb.pos_inf()
    assert 9.999999 < r.lower_float() <= 10
    r = evaluate(1 / t, {t: Interval.of(0, F(1, 8))})
    assert r.lower_fraction() == 8
    r = evaluate(t / (t**2 + 1), {t: Interval.of(0, F(1, 10))})
    assert r.lower_fraction() == 0 and r.upper_float() <= 0.1000001
    r = evaluate(-1 / t, {t: Interval.of(0, F(1, 8))})
    assert r.lower_fraction() is None and r.upper_fraction() == -8
    r = evaluate(1 / s, {s: Interval.of(-F(1, 4), 0)})
    assert r.lower_fraction() is None and r.upper_fraction() == -4


def test_extended_limits_of_monotone_functions():
    inf = sp.oo
    cases = [
        (sp.exp(-s), (0, inf), (0, 1)),
        (sp.exp(s), (-inf, 0), (0, 1)),
        (sp.tanh(s), (-inf, inf), (-1, 1)),
        (sp.erf(s), (0, inf), (0, 1)),
        (sp.sqrt(s), (4, inf), (2, None)),
        (s ** sp.Rational(-1, 2), (4, inf), (0, F(1, 2))),
        (s ** sp.Rational(-1, 2), (0, F(1, 4)), (2, None)),
        (sp.sin(s), (0, inf), (-1, 1)),
        (s**2, (-inf, 1), (0, None)),
        (s**3, (-inf, 1), (None, 1)),
        (1 / (1 + s**2), (-inf, inf), (0, 1)),
        (sp.cosh(s), (-inf, inf), (1, None)),
    ]
    for e, (a, b), (lo, hi) in cases:
        sym = t if e.has(t) else s
        r = evaluate(e, {sym: Interval.of(a, b)})
        assert r.lower_fraction() == lo, (e, r)
        if hi is None:
            assert r.upper_fraction() is None, (e, r)
        else:
            assert r.upper_fraction() == hi, (e, r)
    r = evaluate(sp.atan(s), {s: Interval.of(-sp.oo, sp.oo)})
    assert r.lower_float() <= -math.pi / 2 and math.pi / 2 <= r.upper_float() and r.width() < math.pi + 1e-12
    r = evaluate(sp.exp(-1 / t), {t: Interval.of(0, F(1, 10))})
    assert r.upper_float() >= math.exp(-10) and r.upper_float() < math.exp(-10) * 1.0001


def test_extended_products_with_infinity():
    # t * exp(1/t) on [0, 1/10]: 0 * inf endpoint product uses the set rule 0*inf = 0
    r = evaluate(t * sp.exp(1 / t), {t: Interval.of(0, F(1, 10))})
    assert r.lower_fraction() == 0 and r.upper_fraction() is None
    r = evaluate(s * sp.exp(s), {s: Interval.of(-sp.oo, 0)})  # true range [-1/e, 0]
    assert r.lower_fraction() is None and r.upper_fraction() == 0
    r = evaluate(s - s, {s: Interval.of(0, sp.oo)})  # SymPy folds to 0
    assert r.lower_fraction() == 0 == r.upper_fraction()
    r = evaluate(sp.exp(s) - s**2, {s: Interval.of(0, sp.oo)})
    assert r.lower_fraction() is None and r.upper_fraction() is None
    r = evaluate(sp.exp(s) / (1 + sp.exp(s)), {s: Interval.of(0, sp.oo)})  # inf/inf
    assert r.lower_fraction() == 0 and r.upper_fraction() is None


# ---------------------------------------------------------------- Undefined


@pytest.mark.parametrize(
    "expr,box,mode",
    [
        (sp.sqrt(s - 1), (0, 2), "range"),
        (sp.log(s), (0, 1), "range"),
        (sp.log(s), (-1, 1), "range"),
        (1 / (s - 1), (0, 2), "range"),
        (s / t, (0, 1), "range"),
        (1 / s, (0, 0), "range"),
        (s**-1, (-1, 1), "range"),
        (sp.sign(s), (-1, 1), "continuous"),
        (sp.Piecewise((s, s < 1), (2 * s, True)), (0, 2), "continuous"),
        (sp.nan * s, (0, 1), "range"),
        (sp.I * s, (0, 1), "range"),
        (s + sp.zoo, (0, 1), "range"),
        (s ** sp.Rational(1, 3), (-1, 1), "range"),
        (sp.acosh(s), (0, 2), "range"),
        (sp.atanh(s), (0, 1), "range"),
        (sp.asin(s), (0, 2), "range"),
        (sp.tan(s), (1, 2), "range"),
        (sp.tan(s), (0, sp.oo), "range"),
        (sp.Derivative(sp.Function("g")(s), s), (0, 1), "range"),
        (sp.Integral(sp.exp(s**2), (s, 0, 1)) * s, (0, 1), "range"),
        (sp.DiracDelta(s), (0, 1), "range"),
        (sp.gamma(s), (1, 2), "range"),
        (1 / t, (0, 1), "continuous"),
        (sp.sqrt(s), (0, sp.oo), "continuous"),
        (sp.floor(s), (F(1, 2), F(3, 2)), "continuous"),
        (sp.ceiling(s), (1, F(3, 2)), "continuous"),
        (sp.Heaviside(s), (-1, 1), "continuous"),
        (sp.Piecewise((s, s > 1)), (0, 2), "range"),
        ((-2) ** s, (0, 1), "range"),
        (s**x, (0, 1), "range"),
    ],
)
def test_undefined(expr, box, mode):
    syms = sorted(expr.free_symbols, key=str)
    env = {v: Interval.of(*box) for v in syms}
    with pytest.raises(Undefined):
        evaluate(expr, env, mode=mode)
    with pytest.raises(Undefined):  # the compiled path agrees
        IntervalFunction(expr, syms, mode=mode)(*env.values())


def test_undefined_message_names_subexpression():
    with pytest.raises(Undefined, match="log"):
        evaluate(1 + sp.log(s), {s: Interval.of(0, 1)})
    with pytest.raises(Undefined, match="DiracDelta"):
        evaluate(sp.DiracDelta(s) + 1, {s: Interval.of(0, 1)})


# ---------------------------------------------------------------- modes / Piecewise


def test_piecewise_range_hull():
    pw = sp.Piecewise((s, s < 1), (2 * s, True))
    r = evaluate(pw, {s: Interval.of(0, 2)})
    assert (r.lower_fraction(), r.upper_fraction()) == (0, 4)
    r = evaluate(pw, {s: Interval.of(0, F(1, 2))}, mode="continuous")  # decided: first branch
    assert (r.lower_fraction(), r.upper_fraction()) == (0, F(1, 2))
    r = evaluate(pw, {s: Interval.of(1, 2)}, mode="continuous")  # decided: second branch
    assert (r.lower_fraction(), r.upper_fraction()) == (2, 4)


def test_piecewise_conditions():
    pw = sp.Piecewise((1, sp.And(s > 0, s < 1)), (2, sp.Or(s <= 0, s >= 3)), (3, True))
    def ev(a, b, mode="range"):
        r = evaluate(pw, {s: Interval.of(a, b)}, mode=mode)
        return r.lower_fraction(), r.upper_fraction()
    assert ev(F(1, 4), F(1, 2), "continuous") == (1, 1)
    assert ev(-2, -1, "continuous") == (2, 2)
    assert ev(4, 5, "continuous") == (2, 2)
    assert ev(F(3, 2), 2, "continuous") == (3, 3)
    assert ev(F(1, 2), 2) == (1, 3)
    pw2 = sp.Piecewise((5, sp.Eq(s, 1)), (6, sp.Ne(s, 2)), (7, sp.Not(s > 10)), (8, True))
    assert evaluate(pw2, {s: Interval.of(1, 1)}, "continuous").upper_fraction() == 5
    assert evaluate(pw2, {s: Interval.of(3, 4)}, "continuous").upper_fraction() == 6
    r = evaluate(pw2, {s: Interval.of(2, 2)}, "continuous")
    assert (r.lower_fraction(), r.upper_fraction()) == (7, 7)
    r = evaluate(pw2, {s: Interval.of(0, 3)})
    assert (r.lower_fraction(), r.upper_fraction()) == (5, 7)


def test_continuous_mode_accepts_continuous_things():
    box = {s: Interval.of(-2, 3)}
    for e in [sp.Abs(s), sp.Max(s, 0) ** 2, sp.sqrt(1 + s**2), s / (1 + s**2), sp.cosh(s - 3) * sp.sin(s)]:
        r = evaluate(e, box, mode="continuous")
        assert r.is_finite() and r == evaluate(e, box)
    r = evaluate(sp.sqrt(s), {s: Interval.of(0, 4)}, mode="continuous")
    assert (r.lower_fraction(), r.upper_fraction()) == (0, 2)
    r = evaluate(sp.floor(s), {s: Interval.of(F(1, 4), F(3, 4))}, mode="continuous")
    assert (r.lower_fraction(), r.upper_fraction()) == (0, 0)
    r = evaluate(sp.sign(s - 5), box, mode="continuous")
    assert (r.lower_fraction(), r.upper_fraction()) == (-1, -1)


def test_range_mode_sign_floor_heaviside():
    def ev(e, a, b):
        r = evaluate(e, {s: Interval.of(a, b)})
        return r.lower_fraction(), r.upper_fraction()
    assert ev(sp.sign(s), -1, 1) == (-1, 1)
    assert ev(sp.sign(s), 0, 1) == (0, 1)
    assert ev(sp.floor(s), F(-1, 2), F(5, 2)) == (-1, 2)
    assert ev(sp.ceiling(s), F(-1, 2), F(5, 2)) == (0, 3)
    assert ev(sp.Heaviside(s), -1, 1) == (0, 1)
    assert ev(sp.Heaviside(s), 0, 0) == (F(1, 2), F(1, 2))


# ---------------------------------------------------------------- Interval API


def test_interval_api():
    iv = Interval.of(F(-3, 4), 2)
    assert iv.lower_fraction() == F(-3, 4) and iv.upper_fraction() == 2
    assert iv.lower_float() == -0.75 and iv.upper_float() == 2.0
    assert iv.contains_zero() and not iv.is_positive() and not iv.is_negative()
    assert iv.mid() == F(5, 8) and iv.width() >= 2.75
    assert Interval.of(1, 2).is_positive() and Interval.of(0, 2).is_nonnegative()
    assert not Interval.of(0, 2).is_positive()
    assert Interval.of(-2, -1).is_negative() and Interval.of(-2, 0).is_nonpositive()
    up = Interval.of(3, sp.oo)
    assert not up.is_finite() and up.upper_fraction() is None and up.upper_float() == math.inf
    assert up.mid() == 6 and Interval.of(0, float("inf")).mid() == 1
    assert Interval.of(-sp.oo, -3).mid() == -6 and Interval.of(-sp.oo, sp.oo).mid() == 0
    third = Interval.of(F(1, 3), F(2, 3))
    assert third.lower_float() <= 1 / 3 and third.upper_float() >= 2 / 3
    assert F(third.lower_float()) <= F(1, 3) and F(third.upper_float()) >= F(2, 3)
    assert third.lower_fraction() <= F(1, 3) and third.upper_fraction() >= F(2, 3)
    assert Interval.of(sp.Float(0.1), 1).lower_fraction() == F(0.1)
    assert Interval.of(-sp.sqrt(2), sp.sqrt(2)).contains(F(141421, 100000))
    with pytest.raises(ValueError):
        Interval.of(2, 1)
    with pytest.raises(ValueError):
        Interval.of(sp.oo, sp.oo)
    big = Interval.of(F(10) ** 400, F(10) ** 400 + 1)
    assert big.lower_float() == 1.7976931348623157e308 and big.upper_float() == math.inf


def test_interval_function_matches_evaluate_and_precision():
    e = sp.sqrt(1 + x**2 + y**2) - 1 + sp.Piecewise((x, x > y), (y, True)) * sp.atan(x * y)
    fn = IntervalFunction(e, [x, y])
    rng = random.Random(3)
    for _ in range(30):
        bx = Interval.of(*random_box(rng, -3, 3))
        by = Interval.of(*random_box(rng, -3, 3))
        assert fn(bx, by) == evaluate(e, {x: bx, y: by})
    p = Interval.point(F(1, 3))
    assert evaluate(sp.exp(s), {s: p}, prec=64).width() > evaluate(sp.exp(s), {s: p}, prec=256).width()
    with pytest.raises(ValueError):
        IntervalFunction(x + y, [x])
    with pytest.raises(ValueError):
        IntervalFunction(x, [x], mode="bogus")


def test_speed_of_compiled_function():
    e1, e2 = x, y
    f = sp.sqrt(1 + e1**2 + e2**2) - 1
    expr = (sp.diff(f, e1) * sp.tanh(e1 / 2) + sp.diff(f, e2) * e2 / (1 + e2**2)
            - sp.Rational(1, 4) * sp.log(1 + e1**2) + sp.cos(e1 - e2) * sp.exp(-e2**2))
    fn = IntervalFunction(expr, [x, y])
    bx, by = Interval.of(F(1, 4), F(1, 2)), Interval.of(F(-1, 8), F(3, 8))
    fn(bx, by)
    n = 300
    t0 = time.perf_counter()
    for _ in range(n):
        fn(bx, by)
    per_call = (time.perf_counter() - t0) / n
    assert per_call < 2e-3, per_call  # lenient bound; typically tens of microseconds


@pytest.mark.parametrize(
    "cond,box,expected",
    [
        (s > 0, (0, 1), (1, 2)),
        (s >= 0, (0, 1), (1, 1)),
        (s > 0, (-1, 0), (2, 2)),
        (s >= 0, (-1, 0), (1, 2)),
        (s < 0, (-1, 0), (1, 2)),
        (s <= 0, (-1, 0), (1, 1)),
        (s < 0, (0, 1), (2, 2)),
        (s <= 0, (0, 1), (1, 2)),
        (sp.Eq(s, 0), (0, 0), (1, 1)),
        (sp.Eq(s, 0), (0, 1), (1, 2)),
        (sp.Eq(s, 0), (F(1, 2), 1), (2, 2)),
        (sp.Ne(s, 0), (0, 0), (2, 2)),
        (2 * s > 1, (F(1, 2), 1), (1, 2)),
        (2 * s >= 1, (F(1, 2), 1), (1, 1)),
        (s**2 < 1, (-1, 1), (1, 2)),
    ],
)
def test_condition_boundaries(cond, box, expected):
    pw = sp.Piecewise((1, cond), (2, True))
    r = evaluate(pw, {s: Interval.of(*box)})
    assert (r.lower_fraction(), r.upper_fraction()) == expected
    if expected[0] == expected[1]:
        assert evaluate(pw, {s: Interval.of(*box)}, mode="continuous") == r
    else:
        with pytest.raises(Undefined):
            evaluate(pw, {s: Interval.of(*box)}, mode="continuous")


def test_piecewise_branch_narrowing_is_sound_and_useful():
    # the sqrt branch is only active for s >= 0: evaluating it there is fine
    pw = sp.Piecewise((sp.sqrt(s), s >= 0), (0, True))
    r = evaluate(pw, {s: Interval.of(-1, 4)})
    assert (r.lower_fraction(), r.upper_fraction()) == (0, 2)
    pw = sp.Piecewise((s - sp.pi + 1, s > sp.pi), (1 - sp.cos(s), True))
    r = evaluate(pw, {s: Interval.of(0, 4)})
    assert r.lower_fraction() == 0 and r.upper_float() <= 2.0000001
    # the second branch is inactive on [2, 3] (negation of s < 4 is empty there)
    pw = sp.Piecewise((s, s < 4), (100 * s, True))
    r = evaluate(pw, {s: Interval.of(2, 3)})
    assert (r.lower_fraction(), r.upper_fraction()) == (2, 3)
    pw = sp.Piecewise((s, sp.Or(s < 1, s > 3)), (-s, True))
    r = evaluate(pw, {s: Interval.of(0, 4)})
    assert (r.lower_fraction(), r.upper_fraction()) == (-3, 4)
    rng = random.Random(11)
    for _ in range(40):
        a, b = random_box(rng, -5, 5)
        r = evaluate(pw, {s: Interval.of(a, b)})
        for p in samples(rng, a, b, 6):
            assert_encloses(r, mp_value(pw, [s], [p]), (a, b, p))


def test_contains_is_exact_for_rationals():
    r = evaluate(1 / sp.Min(-3, sp.log(sp.Max(sp.Rational(5, 4), s))), {s: Interval.of(-sp.oo, -2)})
    assert r.contains(sp.Rational(-1, 3)) and r.contains(F(-1, 3))
    assert not r.contains(F(-1, 3) + F(1, 10**30))
    assert Interval.point(sp.pi).contains(Interval.point(sp.pi, prec=256))
    assert Interval.of(3, 4).contains(sp.pi) and not Interval.of(3, F(314, 100)).contains(sp.pi)


@pytest.mark.parametrize("op", ["add", "add3", "sub", "mul", "div"])
def test_every_operation_rounds_outward(op):
    """Exact dyadic inputs whose exact result needs more than the working
    precision: the enclosure must contain the exact rational result (an
    endpoint rounded inward, e.g. the lower bound of a sum rounded up, fails)."""
    x, y = sp.symbols("x y", real=True)
    expr = {"add": x + y, "add3": x + y + 1, "sub": x - y, "mul": x * y, "div": x / y}[op]
    exact = {"add": lambda a, b: a + b, "add3": lambda a, b: a + b + 1, "sub": lambda a, b: a - b,
             "mul": lambda a, b: a * b, "div": lambda a, b: a / b}[op]
    fn = IntervalFunction(expr, [x, y], mode="range", prec=64)
    tiny = Fraction(1, 2 ** 200)
    values = [Fraction(1), Fraction(-1), Fraction(3), 1 + Fraction(1, 2 ** 100), -(1 + Fraction(3, 2 ** 90))]
    for a in values:
        for b in [tiny, -tiny, 3 * tiny, 1 + Fraction(1, 2 ** 100), Fraction(3)]:
            box = fn(Interval.point(a), Interval.point(b))
            want = exact(a, b)
            assert box.lower_fraction() <= want <= box.upper_fraction(), (op, a, b)
            # and the enclosure is not trivially wide (inputs rounded to 64 bits)
            scale = max(abs(a), abs(b), abs(want), abs(a) / abs(b), 1)
            assert box.upper_fraction() - box.lower_fraction() <= scale * Fraction(1, 2 ** 50)


def test_sup_bounds_are_rounded_outward_to_53_bits_at_any_scale():
    """`univariate._rounded`: the branch and bound's bounds, 53 bits from
    2^-4000 to 2^4000 (a double had flushed 10^-400 to 0); a bound of
    2^(-10^12) (exp(-e2^2) far out) once asked for a 2^(10^12) integer."""
    from fractions import Fraction
    from flint import arb, ctx
    from uwmr_symbolic.univariate import _rounded
    for text in ("1e-320", "-1e-320", "1e-400", "-2.5e-1000", "3", "-3", "1e400", "0.1"):
        prec, ctx.prec = ctx.prec, 200
        try:
            x = (arb(text) / 7).mid()               # a mantissa wider than 53 bits
        finally:
            ctx.prec = prec
        m, e = (int(v) for v in x.man_exp())
        exact = Fraction(m) * Fraction(2) ** e
        lo, hi = _rounded(x, True), _rounded(x, False)
        assert lo <= exact <= hi and 0 < (hi - lo) <= abs(exact) / 2 ** 51, text
        assert max(abs(lo.numerator), lo.denominator).bit_length() <= 4053
    tiny = arb(2) ** -(10 ** 12)
    assert _rounded(tiny, True) == 0 and _rounded(tiny, False) == Fraction(1, 2 ** 4000)
    assert _rounded(-tiny, True) == -Fraction(1, 2 ** 4000) and _rounded(-tiny, False) == 0
    assert _rounded(arb(2) ** 5000, False) is None and _rounded(arb(3), True) == 3
