"""Grammar of the codegen fuzzer (tests/test_codegen_fuzz.py): radial profiles
G(rho), rho = e1^2 + e2^2, as SymPy expressions in the positive symbol RHO.

* `radial_profiles`: sums and multiples of compositions of log(1 + u), asinh,
  sqrt(1 + u) - 1, atan, tanh, erf, log cosh(sqrt(1 + u) - 1) over c rho and
  c rho^2;
* `piecewise_profiles`: a C^2 join on the circle s = R (s = |e| = sqrt(rho)):
  F(s) = a s^2 inside (rho <= R^2), and outside the linear Taylor part of
  a s^2 at R plus a bounded increasing function,

      F(s) = a R^2 + c1 (s - R) + B (W(k (s - R) - x0) - W(-x0)),

  W a bounded increasing sigmoid (atan, tanh, erf, x/sqrt(1 + x^2)) shifted
  by x0 > 0 so that W''(-x0) > 0, k = m/R.  B and c1 are solved exactly
  from F'(R) = 2 a R and F''(R) = 2 a (`c2_join`), and value, first and
  second derivative at the join are checked to be equal exactly with SymPy.
  c1 > 0 keeps F unbounded, F' = c1 + B k W' > 0 and bounded (kf finite)."""
from __future__ import annotations

import sympy as sp
from hypothesis import strategies as st

RHO = sp.Symbol("rho", positive=True)
S = sp.Symbol("s", positive=True)

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


# bounded increasing sigmoids W, odd, convex for x < 0 (W''(-x0) > 0 for x0 > 0)
SIGMOIDS = {
    "atan": sp.atan,
    "tanh": sp.tanh,
    "erf": sp.erf,
    "algebraic": lambda x: x / sp.sqrt(1 + x ** 2),
}


class JoinError(AssertionError):
    """A C^2 join that does not hold exactly (a bug of the grammar)."""


def check_c2(inner, outer, R, what="join"):
    """Raise JoinError unless inner(s) and outer(s) have exactly equal value,
    first and second derivative at s = R (SymPy: each gap simplifies to 0)."""
    for order in range(3):
        gap = sp.simplify((sp.diff(inner, S, order) - sp.diff(outer, S, order)).subs(S, R))
        if gap != 0:
            raise JoinError(f"{what} at R = {R}: derivative {order} differs by {gap}")


def design_source(G) -> str:
    """A design file for f = G(rho), written in rho = e1**2 + e2**2 and read
    back exactly (sympify: 1/3 is a Rational, not a Python float)."""
    return ("from sympy import *\n"
            "e1, e2 = symbols('e1 e2', real=True)\n"
            "rho = e1**2 + e2**2\n"
            f"name = {sp.sstr(G)!r}\n"
            f"f = sympify({sp.sstr(G)!r}, locals=dict(rho=rho))\n"
            "gains = {'circle': dict(k1=0.25, k2=0.7, lam=0.1, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}\n")


def c2_join(a, R, sigmoid: str, x0, m, strict=False, outer_first=False):
    """G(rho) of the Piecewise C^2 join (module doc) for exact a, R, x0 > 0
    and m > 0 (k = m/R); returns (G, F_inner(s), F_outer(s)).  Raises
    JoinError unless F is exactly C^2 at s = R with c1 > 0 and B > 0.
    `strict`: the condition rho < R^2 instead of rho <= R^2; `outer_first`:
    Piecewise((outer, rho > R^2), (inner, True)) (rho >= R^2 when strict)."""
    a, R, x0, m = map(sp.nsimplify, (a, R, x0, m))
    W = SIGMOIDS[sigmoid]
    x = sp.Symbol("x", real=True)
    k = m / R
    w1 = sp.diff(W(x), x).subs(x, -x0)
    w2 = sp.diff(W(x), x, 2).subs(x, -x0)
    # F''(R) = B k^2 W''(-x0) = 2a and F'(R) = c1 + B k W'(-x0) = 2aR
    B = sp.simplify(2 * a / (k ** 2 * w2))
    c1 = sp.simplify(2 * a * R - B * k * w1)
    inner = a * S ** 2
    outer = a * R ** 2 + c1 * (S - R) + B * (W(k * (S - R) - x0) - W(-x0))
    check_c2(inner, outer, R, f"{sigmoid} join")
    for name, val in (("B", B), ("c1", c1)):
        if not (sp.N(val, 50) > 0 and val.is_positive is not False):
            raise JoinError(f"{sigmoid} join at R = {R}: {name} = {val} is not positive")
    g_in, g_out = inner.subs(S, sp.sqrt(RHO)), outer.subs(S, sp.sqrt(RHO))
    if outer_first:
        cond = RHO >= R ** 2 if strict else RHO > R ** 2
        G = sp.Piecewise((g_out, cond), (g_in, True))
    else:
        cond = RHO < R ** 2 if strict else RHO <= R ** 2
        G = sp.Piecewise((g_in, cond), (g_out, True))
    return G, inner, outer


@st.composite
def piecewise_profiles(draw):
    """G(rho) with a C^2 join on a circle (`c2_join`)."""
    a = draw(st.sampled_from(COEFFS))
    R = draw(st.sampled_from([sp.Integer(1), sp.Integer(2), sp.Rational(1, 2), sp.Rational(3, 2)]))
    sigmoid = draw(st.sampled_from(sorted(SIGMOIDS)))
    x0 = draw(st.sampled_from([sp.Integer(1), sp.Rational(1, 2), sp.Integer(2)]))
    m = draw(st.sampled_from([sp.Integer(2), sp.Integer(3)]))     # R k = m > W'(-x0)/W''(-x0): c1 > 0
    G, _, _ = c2_join(a, R, sigmoid, x0, m, strict=draw(st.booleans()), outer_first=draw(st.booleans()))
    return G
