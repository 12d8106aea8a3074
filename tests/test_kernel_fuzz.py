"""Small soundness fuzz of the kernel's evaluating rules (fixed seeds):
random expressions, random intervals; whenever a rule accepts a sign claim,
the claim is checked independently at many points in 40-digit mpmath (and,
for Sturm, against SymPy's exact real roots).  A single false acceptance
fails.  KERNEL_FUZZ_SCALE=n runs n times as many cases."""
import itertools
import os
import random

import mpmath
import sympy as sp

from uwmr_symbolic.kernel import KernelError, Undefined, evaluate, rules as K

x = sp.Symbol("x", real=True)
Q = sp.Rational
SCALE = int(os.environ.get("KERNEL_FUZZ_SCALE", "1"))     # longer runs: KERNEL_FUZZ_SCALE=20


def random_expr(rng, depth):
    if depth == 0 or rng.random() < 0.25:
        return x if rng.random() < 0.6 else Q(rng.randint(-5, 5), rng.randint(1, 4))
    op = rng.choice(["add", "add", "mul", "mul", "div", "exp", "log", "sqrt", "sin", "cos",
                     "tanh", "atan", "abs", "pow", "cosh", "erf"])
    a = random_expr(rng, depth - 1)
    if op in ("add", "mul", "div"):
        b = random_expr(rng, depth - 1)
        return a + b if op == "add" else a * b if op == "mul" else a / b
    if op == "pow":
        return a ** rng.choice([2, 3, -1, Q(1, 2), Q(3, 2), Q(-1, 3)])
    return {"exp": sp.exp, "log": sp.log, "sqrt": sp.sqrt, "sin": sp.sin, "cos": sp.cos,
            "tanh": sp.tanh, "atan": sp.atan, "abs": sp.Abs, "cosh": sp.cosh, "erf": sp.erf}[op](a)


def holds(e, lo, hi, want, strict, n=60):
    """The sign claim at n + 1 points of [lo, hi], 40 digits."""
    mpmath.mp.dps = 40
    f = sp.lambdify(x, e, "mpmath")
    for k in range(n + 1):
        p = mpmath.mpf(lo.p) / lo.q + (mpmath.mpf(hi.p) / hi.q - mpmath.mpf(lo.p) / lo.q) * k / n
        try:
            v = f(p)
        except (ZeroDivisionError, ValueError):
            return False
        if isinstance(v, mpmath.mpc):
            if v.imag != 0:
                return False
            v = v.real
        if not mpmath.isfinite(v) or not (want * v > 0 if strict else want * v >= -mpmath.mpf(10) ** -30):
            return False
    return True


def random_interval(rng):
    a = Q(rng.randint(-12, 8), rng.randint(1, 4))
    return a, a + Q(rng.randint(1, 12), rng.randint(1, 4))


def test_evaluator_encloses_random_expressions():
    rng = random.Random(20261123)
    mpmath.mp.dps = 40
    checked = 0
    for _ in range(150 * SCALE):
        e = random_expr(rng, 3)
        if not e.has(x):
            continue
        lo, hi = random_interval(rng)
        try:
            box = evaluate(e, x, lo, hi)
        except Undefined:
            continue
        f = sp.lambdify(x, e, "mpmath")
        for k in range(41):
            v = f(mpmath.mpf(lo.p) / lo.q + (mpmath.mpf(hi.p) / hi.q - mpmath.mpf(lo.p) / lo.q) * k / 40)
            assert not isinstance(v, mpmath.mpc) or v.imag == 0, (e, lo, hi)
            v = v.real if isinstance(v, mpmath.mpc) else v
            assert float(box.lo.lower()) - 1e-12 * abs(v) <= float(v) <= float(box.hi.upper()) + 1e-12 * abs(v), (e, lo, hi)
        checked += 1
    assert checked > 50


def test_cover_never_accepts_a_false_sign():
    rng = random.Random(7)
    accepted = 0
    for _ in range(160 * SCALE):
        e = random_expr(rng, 3)
        if not e.has(x):
            continue
        lo, hi = random_interval(rng)
        n = rng.choice([1, 4, 16])
        cuts = [lo + (hi - lo) * Q(k, n) for k in range(n + 1)]
        for want, strict, mean_value in itertools.product((1, -1), (True, False), (False, True)):
            try:
                K.sign_by_cover(expr=e, var=x, cuts=cuts, want=want, strict=strict, mean_value=mean_value)
            except KernelError:
                continue
            accepted += 1
            assert holds(e, lo, hi, want, strict), (e, lo, hi, want, strict, mean_value)
    assert accepted > 20


def test_taylor_never_accepts_a_false_sign():
    rng = random.Random(11)
    accepted = 0
    for _ in range(50 * SCALE):
        c = Q(rng.randint(-4, 4), rng.randint(1, 3))
        m = rng.randint(1, 3)
        e = (x - c) ** m * random_expr(rng, 2) + (x - c) ** (m + 1) * Q(rng.randint(-3, 3))
        for order in (1, 2, 3, 4):
            for side in (1, -1):
                w = Q(1, rng.choice([2, 4, 8]))
                try:
                    thm = K.sign_by_taylor(expr=e, var=x, c=c, side=side, width=w, order=order)
                except KernelError:
                    continue
                accepted += 1
                a, b = (c + w / 1000, c + w) if side > 0 else (c - w, c - w / 1000)
                assert holds(e, a, b, thm.claim.want, True), (e, c, side, order)
                assert not holds(e, a, b, -thm.claim.want, False, n=8), (e, c, side, order)
    assert accepted > 10


def test_sturm_agrees_with_exact_roots():
    rng = random.Random(3)
    accepted = 0
    for _ in range(60 * SCALE):
        roots = [Q(rng.randint(-6, 6), rng.randint(1, 2)) for _ in range(rng.randint(1, 4))]
        p = sp.expand(sp.Mul(*[(x - r) for r in roots]) * rng.choice([1, -1]) * (x ** 2 + rng.randint(0, 2)))
        lo, hi = random_interval(rng)
        lo_open, hi_open = rng.random() < 0.5, rng.random() < 0.5
        for want in (1, -1):
            for strict in (True, False):
                try:
                    K.sign_by_sturm(expr=p, var=x, lo=lo, hi=hi, lo_open=lo_open, hi_open=hi_open,
                                    want=want, strict=strict)
                except KernelError:
                    continue
                accepted += 1
                inside = [r for r in sp.real_roots(sp.Poly(p, x))
                          if (lo < r or (r == lo and not lo_open)) and (r < hi or (r == hi and not hi_open))]
                if strict:
                    assert not inside, (p, lo, hi, lo_open, hi_open)
                a = lo + (hi - lo) / 1000 if lo_open else lo
                b = hi - (hi - lo) / 1000 if hi_open else hi
                assert holds(p, a, b, want, strict), (p, lo, hi, want, strict)
    assert accepted > 15


def structural_proof(e, lo, hi, lo_open, hi_open, rng, depth=0):
    """A tiny prover that proposes kernel steps the way `_sign_near` does
    (Sturm, product, sum, monotone functions, log, cover) and lets the
    kernel decide; returns a theorem or None."""
    iv = dict(lo=lo, hi=hi, lo_open=lo_open, hi_open=hi_open)
    attempts = []
    if e.is_polynomial(x):
        attempts += [lambda w=w, st=st: K.sign_by_sturm(expr=e, var=x, want=w, strict=st, **iv)
                     for w in (1, -1) for st in (True, False)]
    if depth < 3:
        def sub(u):
            return structural_proof(u, lo, hi, lo_open, hi_open, rng, depth + 1)
        if e.is_Mul:
            attempts.append(lambda: K.sign_of_product(*[p for p in map(sub, [f.base if f.is_Pow else f for f in e.args
                                                                          if f.has(x)])], expr=e))
        if e.is_Pow:
            attempts.append(lambda: K.sign_of_product(sub(e.base), expr=e))
        if e.is_Add:
            attempts += [lambda w=w: K.sign_of_sum(*[sub(a) for a in e.args if a.has(x)], expr=e, want=w)
                         for w in (1, -1)]
        if isinstance(e, (sp.tanh, sp.atan, sp.asinh, sp.sinh, sp.erf, sp.exp, sp.cosh)):
            attempts.append(lambda: K.sign_through_increasing(sub(e.args[0]), expr=e))
        if isinstance(e, sp.log):
            attempts.append(lambda: K.sign_through_increasing(sub(e.args[0] - 1), expr=e))
            attempts.append(lambda: K.sign_through_increasing(sub(e.args[0] - 1), sub(e.args[0]), expr=e))
    for attempt in attempts:
        try:
            thm = attempt()
        except (KernelError, TypeError):    # TypeError: a None premise
            continue
        return thm
    if not (lo_open or hi_open):
        for w in (1, -1):
            try:
                return K.sign_by_cover(expr=e, var=x, cuts=[lo + (hi - lo) * Q(k, 8) for k in range(9)], want=w)
            except KernelError:
                pass
    return None


def test_composed_rules_never_accept_a_false_sign():
    rng = random.Random(5)
    proved = 0
    for _ in range(120 * SCALE):
        e = random_expr(rng, 3)
        if not e.has(x):
            continue
        lo, hi = random_interval(rng)
        lo_open, hi_open = rng.random() < 0.3, rng.random() < 0.3
        thm = structural_proof(e, lo, hi, lo_open, hi_open, rng)
        if thm is None:
            continue
        proved += 1
        c = thm.claim
        a = lo + (hi - lo) / 1000 if lo_open else lo
        b = hi - (hi - lo) / 1000 if hi_open else hi
        assert holds(e, a, b, c.want, c.strict), (e, lo, hi, c)
        # the halves joined, and a weakened piece, say the same
        m = (lo + hi) / 2
        left = structural_proof(e, lo, m, lo_open, False, rng)
        right = structural_proof(e, m, hi, True, hi_open, rng)
        if left is not None and right is not None:
            try:
                j = K.join(left, right)
            except KernelError:
                continue
            assert holds(e, a, b, j.claim.want, j.claim.strict), (e, lo, hi, j.claim)
    assert proved > 30


def test_exact_identities_are_true():
    """The exact `identity` route (cancel after generalising radicals, powers
    of the positive variable inside radicals, tanh = sinh/cosh): random pairs
    lhs, rhs where rhs is an algebraic rewrite of lhs (true) or of a perturbed
    lhs (usually false).  Every accepted pair must agree in 40-digit mpmath
    at points of (0, 3] where both are defined; some true pairs must be
    accepted exactly (so the route is exercised)."""
    s = sp.Symbol("s", positive=True)
    rng = random.Random(99)
    accepted = exact = 0
    for _ in range(60 * SCALE):
        e = random_expr(rng, 3).subs(x, s)
        rewrite = rng.choice([sp.together, sp.expand, sp.cancel, lambda u: u.rewrite(sp.exp),
                              lambda u: sp.powsimp(u, force=True), lambda u: sp.radsimp(u)])
        other = e + Q(rng.randint(1, 3), 1000) * rng.choice([s, 1, s ** Q(1, 2)]) if rng.random() < 0.4 else e
        try:
            r = rewrite(other)
            thm = K.identity(lhs=e, rhs=r, var=s, lo=sp.Integer(0), hi=sp.Integer(3), lo_open=True, hi_open=False)
        except (KernelError, Undefined, TypeError, ValueError, ZeroDivisionError, RecursionError):
            continue
        accepted += 1
        exact += "sympy-polys" in thm.assumptions
        mpmath.mp.dps = 40
        fl, fr = sp.lambdify(s, e, "mpmath"), sp.lambdify(s, r, "mpmath")
        for k in range(1, 31):
            p = mpmath.mpf(k) / 10
            try:
                a, b = fl(p), fr(p)
            except (ZeroDivisionError, ValueError, OverflowError):
                continue
            if all(isinstance(v, (mpmath.mpf, int)) or getattr(v, "imag", 1) == 0 for v in (a, b)) \
                    and mpmath.isfinite(a) and mpmath.isfinite(b):
                assert abs(a - b) <= mpmath.mpf(10) ** -25 * (1 + abs(a)), (e, r, p)
    assert accepted >= 10 and exact >= 5, (accepted, exact)


def test_derivative_is_sympys_without_its_queries():
    """`derivative` (the kernel's chain rule over SymPy's per-function
    formulas) on random expressions of x, and of x and a second symbol y
    held constant: the same expression as `sympy.diff` (so the prover's and
    the checker's claims about a derivative match), and, as an independent
    check, the same value as a 40-digit central difference of e itself at
    points where e is real and smooth."""
    y = sp.Symbol("y", real=True)
    rng = random.Random(4217)
    mpmath.mp.dps = 40
    compared = 0
    for _ in range(150 * SCALE):
        e = random_expr(rng, 3)
        if rng.random() < 0.3:
            e = e.subs(x, x * y + rng.choice([y, 1, y ** 2]))
        if rng.random() < 0.15:
            e = e ** x                                  # an exponent with x in it
        if e.has(sp.zoo, sp.nan):
            continue
        d = K.derivative(e, x)
        assert d == sp.diff(e, x), e
        f, g = sp.lambdify((x, y), e, "mpmath"), sp.lambdify((x, y), d, "mpmath")
        for p in (mpmath.mpf("0.37"), mpmath.mpf("1.9"), mpmath.mpf("-2.3")):
            h = mpmath.mpf(10) ** -12
            try:
                vals = [f(p + k * h, mpmath.mpf("0.8")) for k in (-1, 1)] + [g(p, mpmath.mpf("0.8"))]
            except (ZeroDivisionError, ValueError, OverflowError, TypeError):
                continue
            if any(isinstance(v, mpmath.mpc) or not mpmath.isfinite(v) or abs(v) > 10 ** 8 for v in vals):
                continue
            assert abs((vals[1] - vals[0]) / (2 * h) - vals[2]) <= mpmath.mpf(10) ** -8 * (1 + abs(vals[2])), (e, p)
            compared += 1
    assert compared > 100, compared
    for e in (sp.Abs(x - 1), sp.Piecewise((x, x < 1), (x ** 2, True)), sp.Max(x, 1 - x)):
        assert K.derivative(e, x) == sp.diff(e, x)    # |u|, Piecewise, Max keep SymPy's rule
