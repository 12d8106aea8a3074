"""Random design functions f(e1, e2), each paired with its truth.

Every strategy here yields a `Case`: the SymPy expression a user would write
(float constants stay SymPy Floats, i.e. binary doubles) and, for each of
P1-P8 of SPEC.md, True / False when the construction decides it and None when
it does not.  Nothing here calls the verifier: truth comes from the way f is
built.  The numeric oracle (`oracle.py`) only searches for contradictions.

Conventions (the ones `tests/designs/` and SPEC.md use):
  * P1, P5, P6, P7 require the partial derivatives they name to exist at
    every point of R^2; for a discontinuous f, kf is read as the sup of
    |df/de2| where it exists, so its truth is left None there.
  * P4 is "e1 df/de2 = e2 df/de1"; its truth is given for f that is C^1
    (then P4 <=> f radial) and for clearly non-radial f; None for a radial f
    that is not C^1 (the reading "wherever the partials exist" differs).
  * P8 is: for every e1, df/de2(e1, e2) -> 0 as e2 -> 0 (e2 != 0).

Radial building blocks G(u) are increasing on [0, oo), vanish at 0 and are
analytic at u = 0, so f = sum c_i G_i(rho) (c_i > 0) is C^oo, f(0) = 0,
df/de1 = 2 e1 G'(rho) has the sign of e1.  Growth at infinity is tracked as
rho^a log(rho)^b (None: bounded) and decides, for these Hardy-field
functions, kf < oo  <=>  a < 1/2 or (a = 1/2, b <= 0)   (F'(s) = 2 s G'(s^2))
and sup G' < oo <=>  a < 1   or (a = 1,   b <= 0)       (P6: h = 2 G'/k).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction

import sympy as sp
from hypothesis import strategies as st

from uwmr_symbolic import e1, e2

RHO = e1 ** 2 + e2 ** 2
R = sp.Rational
PROPS = ("P1", "P2", "P3", "P4", "P5", "P6", "P7", "P8")


@dataclass
class Case:
    family: str
    f: sp.Expr
    truth: dict                     # P1..P8 -> True / False / None
    kf: sp.Expr | None = None       # sup |df/de2| (sp.oo: infinite; None: not known); float
                                    # constants in it are kfc placeholders
    radii: list = field(default_factory=list)   # exact radii of circle boundaries
    zeros: list = field(default_factory=list)   # exact points (e1, e2) where f = 0, e != 0
    note: str = ""

    def __post_init__(self):
        # comparisons of SymPy numbers give SymPy booleans: make every truth a Python bool
        for p, v in self.truth.items():
            self.truth[p] = None if v is None else bool(v)

    def known(self, prop):
        return self.truth.get(prop)


_WRITTEN: dict = {}     # SymPy Floats that no double holds -> the decimal each was written as


def as_read(x) -> sp.Rational:
    """The value uwmr-symbolic reads for a float (README): a double's shortest
    round-trip decimal, Python's repr; a SymPy Float beyond the doubles that
    `fl_text` made, the decimal it was written as."""
    if isinstance(x, sp.Float) and x in _WRITTEN:
        return _WRITTEN[x]
    return sp.Rational(repr(float(x)))


def fl_text(text: str) -> sp.Float:
    """A 53-bit SymPy Float written as a one-digit decimal no double holds
    (Float('1e-400'), a user's sp.N(...) of a tiny number): read as that
    decimal, the shortest one that rounds back to it (docs/verifier.md)."""
    x = sp.Float(text, precision=53)
    assert not 1e-300 < abs(float(x)) < 1e300
    _WRITTEN[x], _WRITTEN[-x] = sp.Rational(text), -sp.Rational(text)     # (-x is a Float of its own)
    return x


def fl(x: float) -> sp.Float:
    """A float constant the way a user's `0.1 + 0.2` reaches SymPy."""
    return sp.Float(x)


def kfc(x: float) -> sp.Symbol:
    """A float constant inside an exact kf: a placeholder symbol (SymPy would
    round Float * sqrt(3) or sqrt(Float) to 53 bits), replaced by the
    oracle with the double's exact value or with its 15-digit decimal."""
    return sp.Symbol("flt_" + x.hex(), positive=True)


def placeholders(expr, read):
    """expr with every kfc placeholder replaced by read(float)."""
    return expr.xreplace({s: read(float.fromhex(s.name[4:])) for s in expr.free_symbols
                          if s.name.startswith("flt_")})


# ---------------------------------------------------------------- radial blocks
# A growth (a, b, c, ...) is rho^a log(rho)^b log(log(rho))^c ... as rho -> oo, compared
# lexicographically (missing exponents are 0); None: bounded.
# name -> (G(u), growth map, sup over s of d/ds G(s^2) when known exactly)
def _log_growth(g):
    """log of a growth whose first nonzero exponent is positive: the next iterated log
    (log rho^a = a log rho; log (log rho)^b = b log log rho, which is unbounded: before,
    it was read as a constant, and sqrt(rho) log(log(rho)) as having a finite kf)."""
    if g is None:
        return None
    i = next(i for i, x in enumerate(g) if x != 0)
    return tuple(Fraction(int(k == i + 1)) for k in range(i + 2))


def _padded(*gs):
    n = max(len(g) for g in gs)
    return [tuple(g) + (Fraction(0),) * (n - len(g)) for g in gs]


BLOCKS = {
    "log1p":   (lambda u: sp.log(1 + u), _log_growth, sp.Integer(1)),
    "asinh":   (sp.asinh, _log_growth, sp.sqrt(2)),
    "sqrt1p":  (lambda u: sp.sqrt(1 + u) - 1, lambda g: None if g is None else tuple(x / 2 for x in g), sp.Integer(1)),
    "logcosh": (lambda u: sp.log(sp.cosh(u)), lambda g: g, None),
    "atan":    (sp.atan, lambda g: None, R(3, 2) * 3 ** R(-1, 4)),
    "tanh":    (sp.tanh, lambda g: None, None),
    "erf":     (sp.erf, lambda g: None, 2 * sp.sqrt(2) * sp.exp(R(-1, 4)) / sp.sqrt(sp.pi)),
    "ratio":   (lambda u: u / (1 + u), lambda g: None, 3 * sp.sqrt(3) / 8),
    "expm":    (lambda u: 1 - sp.exp(-u), lambda g: None, sp.sqrt(2) * sp.exp(R(-1, 2))),
    "pow2":    (lambda u: u ** 2, lambda g: None if g is None else tuple(2 * x for x in g), sp.oo),
    "id":      (lambda u: u, lambda g: g, sp.oo),
}
SAFE_BLOCKS = [b for b in BLOCKS if b not in ("pow2", "id")]


@dataclass
class Atom:
    """G(u) increasing, G(0) = 0, analytic at 0, with its growth and, for a
    single block of beta*rho, sup d/ds G(s^2) exactly."""
    expr: sp.Expr
    growth: tuple | None
    ksup: sp.Expr | None = None


def kf_finite(g):
    """F(s) = G(s^2) has a bounded F' iff G grows at most like rho^(1/2)."""
    if g is None:
        return True
    a, b = _padded(g, (Fraction(1, 2),))
    return a <= b


def dG_bounded(g):
    """G' is bounded iff G grows at most like rho."""
    if g is None:
        return True
    a, b = _padded(g, (Fraction(1),))
    return a <= b


def g_max(a, b):
    if a is None:
        return b
    if b is None:
        return a
    return max(_padded(a, b))


def g_mul(a, b):
    if a is None:
        return b
    if b is None:
        return a
    return tuple(x + y for x, y in zip(*_padded(a, b)))


RHO_GROWTH = (Fraction(1), Fraction(0))


@st.composite
def coefficients(draw, allow_float=True):
    """A positive coefficient: exact rational or a float a user would type."""
    if allow_float and draw(st.booleans()):
        x = draw(st.sampled_from([0.1 + 0.2, 1 / 3.0, math.e, math.pi / 4, 0.7071067811865476,
                                  2 ** -0.5, 0.1, 2.5, 1e-3, 1 / 7]))
        return fl(x), kfc(x)       # the second is for kf (see kfc)
    q = draw(st.sampled_from([R(1), R(1, 2), R(3), R(2, 7), R(1, 1000), R(5, 3), sp.EulerGamma, sp.Catalan / 2]))
    return q, q


@st.composite
def atoms(draw, depth=2, u=RHO, ug=RHO_GROWTH):
    """block(beta * u) or block(inner atom) or block(u)^2-style products."""
    name = draw(st.sampled_from(list(BLOCKS)))
    G, grow, ksup = BLOCKS[name]
    kind = draw(st.sampled_from(["plain", "scaled", "nested"] if depth > 1 else ["plain", "scaled"]))
    if kind == "plain":
        return Atom(G(u), grow(ug), ksup if u is RHO else None)
    if kind == "scaled":
        beta = draw(st.sampled_from([R(1, 4), R(4), R(9, 7), R(1, 100)]))
        k = None if ksup is None or u is not RHO else (ksup * sp.sqrt(beta) if ksup != sp.oo else sp.oo)
        return Atom(G(beta * u), grow(ug), k)
    inner = draw(atoms(depth=depth - 1, u=u, ug=ug))
    return Atom(G(inner.expr), grow(inner.growth))


def radial_truth(growth, offset_sign=0, unb=None):
    """Truth for f = G(rho) + offset, G smooth, increasing, G(0) = 0."""
    unbounded = growth is not None if unb is None else unb
    return {"P1": kf_finite(growth), "P2": offset_sign == 0,
            "P3": offset_sign >= 0 and unbounded, "P4": True, "P5": True,
            "P6": dG_bounded(growth), "P7": True, "P8": True}


@st.composite
def smooth_radial(draw, max_terms=3, allow_float=True):
    """(expr, growth, exact kf or None, scale) for sum c_i * atom_i."""
    n = draw(st.integers(1, max_terms))
    expr, growth, kf = sp.Integer(0), None, None
    for _ in range(n):
        c, c_exact = draw(coefficients(allow_float))
        a = draw(atoms())
        if draw(st.integers(0, 4)) == 0:          # a product of two atoms
            b = draw(atoms(depth=1))
            a = Atom(a.expr * b.expr, g_mul(a.growth, b.growth))
        expr += c * a.expr
        growth = g_max(growth, a.growth)
        kf = None if n > 1 or a.ksup is None else (sp.oo if a.ksup == sp.oo else c_exact * a.ksup)
    if not kf_finite(growth):
        kf = sp.oo
    return expr, growth, kf


# ---------------------------------------------------------------- families
@st.composite
def radial_designs(draw):
    expr, growth, kf = draw(smooth_radial())
    return Case("radial", expr, radial_truth(growth), kf)


# float offsets a user might write: (value as SymPy sees it, exact intended value)
OFFSETS = [
    ("(0.1+0.2)/0.3 - 1", lambda: fl((0.1 + 0.2) / 0.3) - 1),
    ("1 - (0.1+0.2)/0.3", lambda: 1 - fl((0.1 + 0.2) / 0.3)),
    ("0.1 + 0.2 - 0.3", lambda: fl(0.1 + 0.2 - 0.3)),
    ("Float(pi) - pi", lambda: fl(math.pi) - sp.pi),
    ("3.0/3 - 1", lambda: fl(3.0 / 3) - 1),
]


def _origin_as_read(f: sp.Expr) -> sp.Expr:
    """f(0, 0) with each float read first (as_read): substituting into f
    itself lets SymPy add a float to the exact constants it meets in 53-bit
    arithmetic (-5/3 exp(0) + 4.80825932025646 becomes one double)."""
    return f.xreplace({a: as_read(a) for a in f.atoms(sp.Float)}).subs({e1: 0, e2: 0})


def _exact_sign(x: sp.Expr) -> int:
    x = x.xreplace({a: as_read(a) for a in x.atoms(sp.Float)})
    v = sp.N(x, 60)
    if v == 0 and sp.N(x, 120) == 0:
        return 0
    assert abs(v) > sp.Float(10) ** -40, x
    return 1 if v > 0 else -1


@st.composite
def float_offset_designs(draw):
    """G(rho) + a float expression that is 0 in decimal but not in binary."""
    expr, growth, kf = draw(smooth_radial(max_terms=2))
    label, make = draw(st.sampled_from(OFFSETS))
    f = expr + make()
    # f(0, 0) as read: G(0) = 0, but SymPy may fold the offset's float into the
    # constant of a block (5/3 (1 - exp(-u)) + Float(pi) - pi: 5/3 + Float(pi)
    # rounded to one double), which can flip its sign
    sign = _exact_sign(_origin_as_read(f))
    return Case("float-offset", f, radial_truth(growth, sign), kf, note=f"offset {label}")


@st.composite
def power_designs(draw):
    """G(rho) + c |e|^q, q non-even: not smooth at the origin or kf infinite."""
    expr, growth, kf = draw(smooth_radial(max_terms=1, allow_float=False))
    q = draw(st.sampled_from([R(1, 2), R(1), R(3, 2), R(5, 2), R(3)]))
    c, _ = draw(coefficients(allow_float=False))
    f = expr + c * RHO ** (q / 2)
    t = {"P1": False, "P2": True, "P3": True, "P4": True if q > 1 else None, "P5": q > 1,
         "P6": False, "P7": q > 2, "P8": q > 1}
    return Case("power", f, t, sp.oo if q > 1 else None, note=f"|e|^{q}")


@st.composite
def elliptic_designs(draw):
    """c G(a e1^2 + 2 h e1 e2 + b e2^2), (a, h, b) != (a, 0, a), ab > h^2."""
    name = draw(st.sampled_from(SAFE_BLOCKS + ["logcosh"]))
    G, grow, ksup = BLOCKS[name]
    a, a_ex = draw(st.sampled_from([(R(1), R(1)), (R(2), R(2)), (R(1, 3), R(1, 3)),
                                    (fl(0.7071067811865476), as_read(0.7071067811865476))]))
    b, b_ex, b_kf = draw(st.sampled_from([(R(1), R(1), R(1)), (R(4), R(4), R(4)), (R(1, 2), R(1, 2), R(1, 2)),
                                          (fl(0.1 + 0.2), as_read(0.1 + 0.2), kfc(0.1 + 0.2))]))
    h = draw(st.sampled_from([R(0), R(0), R(1, 4), R(-1, 3)]))
    if h == 0 and a_ex == b_ex:
        h = R(1, 5)
    while a_ex * b_ex <= 2 * h ** 2:      # keep the quadratic form positive definite
        h /= 4
    c, c_ex = draw(coefficients())
    q = a * e1 ** 2 + 2 * h * e1 * e2 + b * e2 ** 2
    f = c * G(q)
    g = grow(RHO_GROWTH)
    kf = sp.oo if not kf_finite(g) else (None if ksup is None else c_ex * ksup * sp.sqrt(b_kf))
    t = {"P1": kf_finite(g), "P2": True, "P3": g is not None, "P4": False, "P5": h == 0,
         "P6": h == 0 and dG_bounded(g), "P7": True, "P8": h == 0}
    return Case("elliptic", f, t, kf, note=f"{name}, a={a}, b={b}, h={h}")


@st.composite
def separable_designs(draw):
    """c1 G1(e1^2) + c2 G2(e2^2): smooth, not radial; or the l1 norm."""
    if draw(st.integers(0, 3)) == 0:
        c, _ = draw(coefficients(allow_float=False))
        inner = abs(e1) + abs(e2)
        wrap = draw(st.sampled_from(["id", "log1p"]))
        f = c * (inner if wrap == "id" else sp.log(1 + inner))
        t = {"P1": False, "P2": True, "P3": True, "P4": False, "P5": False, "P6": False,
             "P7": False, "P8": False}
        return Case("l1", f, t, None, note=wrap)
    n1, n2 = draw(st.sampled_from(SAFE_BLOCKS)), draw(st.sampled_from(SAFE_BLOCKS))
    (c1, _), (c2, c2_ex) = draw(coefficients()), draw(coefficients())
    G1, gr1, _ = BLOCKS[n1]
    G2, gr2, k2 = BLOCKS[n2]
    f = c1 * G1(e1 ** 2) + c2 * G2(e2 ** 2)
    g1, g2 = gr1(RHO_GROWTH), gr2(RHO_GROWTH)
    t = {"P1": kf_finite(g2), "P2": True, "P3": g1 is not None and g2 is not None, "P4": False,
         "P5": True, "P6": dG_bounded(g1), "P7": True, "P8": True}
    kf = None if k2 is None else c2_ex * k2
    return Case("separable", f, t, kf, note=f"{n1}(e1^2), {n2}(e2^2)")


@st.composite
def cross_term_designs(draw):
    """G(rho) + c e1 e2 with G sublinear: f -> -oo along e1 = -sign(c) e2."""
    name = draw(st.sampled_from([b for b in SAFE_BLOCKS if b != "logcosh"]))   # sublinear G
    G, grow, _ = BLOCKS[name]
    c = draw(st.sampled_from([R(1, 10), R(-1, 2), R(1, 1000)]))
    f = G(RHO) + c * e1 * e2
    t = {"P1": False, "P2": True, "P3": False, "P4": False, "P5": False, "P6": False,
         "P7": True, "P8": False}
    return Case("cross", f, t, sp.oo, note=name)


@st.composite
def half_plane_designs(draw):
    """c1 G(rho) for e1 > 0 (or e2 > 0), c2 G(rho) otherwise: f jumps on a line."""
    name = draw(st.sampled_from(SAFE_BLOCKS))
    G, grow, _ = BLOCKS[name]
    c1, c2 = draw(st.sampled_from([(R(1), R(2)), (R(2), R(1)), (R(1), R(1, 3))]))
    var = draw(st.sampled_from([e1, e2]))
    f = sp.Piecewise((c1 * G(RHO), var > 0), (c2 * G(RHO), True))
    g = grow(RHO_GROWTH)
    # across e2 = 0 the jump is in the e2 direction only: df/de1 exists everywhere then
    t = {"P1": False, "P2": True, "P3": g is not None, "P4": None, "P5": var == e2,
         "P6": var == e2 and dG_bounded(g), "P7": False, "P8": None}
    return Case("half-plane", f, t, None, note=f"{name} switch on {var} > 0")


JOINS = {   # J(u), u = rho - c >= 0, added outside the circle: order of contact
    "Cinf": sp.Integer(0),
    "C2": None, "C1": None, "C0": None, "jump": None,
}


def _join(kind, u):
    return {"C2": u ** 3 / (1 + u ** 3), "C1": u ** 2 / (1 + u ** 2), "C0": u / (1 + u),
            "jump": sp.Integer(1)}[kind]


@st.composite
def circle_piecewise_designs(draw):
    """G(rho) inside the circle rho = c, G(rho) + D J(rho - c) outside."""
    expr, growth, kf = draw(smooth_radial(max_terms=1))
    c, c_ex = draw(st.sampled_from([(R(1), R(1)), (R(4), R(4)), (R(1, 2), R(1, 2)),
                                    (fl(0.1 + 0.2), as_read(0.1 + 0.2)), (R(2), R(2))]))
    kind = draw(st.sampled_from(["Cinf", "C2", "C1", "C0", "jump", "jump"]))
    form = draw(st.sampled_from(["<", "<=", ">", ">="]))
    D = draw(st.sampled_from([R(1), R(1, 3), R(5)]))
    u = RHO - c
    pos = True
    if kind == "Cinf":
        outer = expr
    elif kind == "jump" and draw(st.booleans()):
        Gc = sp.N(expr.subs({e1: sp.sqrt(c_ex), e2: 0}), 50)
        ratio = draw(st.sampled_from([R(1, 2), R(2)]))
        D = -R(Fraction(str(sp.N(Gc * ratio, 30))).limit_denominator(10 ** 9))
        pos = ratio < 1
        outer = expr + D
    else:
        outer = expr + D * _join(kind, u)
    if form in ("<", "<="):
        cond = RHO < c if form == "<" else RHO <= c
        f = sp.Piecewise((expr, cond), (outer, True))
    else:
        cond = RHO > c if form == ">" else RHO >= c
        f = sp.Piecewise((outer, cond), (expr, True))
    smooth1 = kind in ("Cinf", "C2", "C1")
    t = {"P1": smooth1 and kf_finite(growth), "P2": True, "P3": pos and growth is not None,
         "P4": True if smooth1 else None, "P5": smooth1, "P6": smooth1 and dG_bounded(growth),
         "P7": kind in ("Cinf", "C2"), "P8": True}
    kfv = kf if kind == "Cinf" else (sp.oo if not kf_finite(growth) and smooth1 else None)
    return Case("circle-piecewise", f, t, kfv, radii=[sp.sqrt(c_ex)], note=f"{kind} join at rho {form} {c}")


@st.composite
def point_value_designs(draw):
    """An isolated value on a circle: Piecewise((v, Eq(rho, c)), (G(rho), True))."""
    which = draw(st.sampled_from(["ratio", "pow", "log1p"]))
    c = draw(st.sampled_from([R(1), R(3), R(1, 2)]))
    G = {"ratio": RHO / (1 + RHO), "pow": RHO ** 2 / 3, "log1p": sp.log(1 + RHO)}[which]
    Gc = G.subs({e1: sp.sqrt(c), e2: 0})
    v = draw(st.sampled_from(["same", "other", "zero"]))
    val = {"same": Gc, "other": sp.Integer(2), "zero": sp.Integer(0)}[v]
    if v == "other" and Gc == 2:
        val = sp.Integer(3)
    f = sp.Piecewise((val, sp.Eq(RHO, c)), (G, True))
    growth = {"ratio": None, "pow": (Fraction(2), Fraction(0)), "log1p": (Fraction(0), Fraction(1))}[which]
    if v == "same":
        t = radial_truth(growth)
        kf = {"ratio": 3 * sp.sqrt(3) / 8, "pow": sp.oo, "log1p": sp.Integer(1)}[which]
    else:
        t = {"P1": False, "P2": True, "P3": v == "other" and growth is not None, "P4": None,
             "P5": False, "P6": False, "P7": False, "P8": True}
        kf = None
    return Case("point-value", f, t, kf, radii=[sp.sqrt(c)],
                zeros=[(sp.sqrt(c), 0)] if v == "zero" else [], note=f"value {val} on rho = {c}")


# removable singularities at the origin: H(rho)/rho-type forms, analytic at 0
REMOVABLE = {   # name -> (expr valid for rho > 0, limit at 0, growth, increasing)
    "1-atan/rho": (1 - sp.atan(RHO) / RHO, 0, None, True),
    "2-2log1p/rho": (2 - 2 * sp.log(1 + RHO) / RHO, 0, None, True),
    "log1p^2/rho": (sp.log(1 + RHO) ** 2 / RHO, 0, None, False),
    "sinh/rho-1": (sp.sinh(RHO) / RHO - 1, 0, (Fraction(10 ** 6), Fraction(0)), True),
}


@st.composite
def origin_designs(draw):
    """The value at the origin given separately (Eq(rho, 0) or rho > 0)."""
    if draw(st.booleans()):
        name = draw(st.sampled_from(list(REMOVABLE)))
        H, lim, growth, inc = REMOVABLE[name]
        note = name
    else:
        H, growth, _ = draw(smooth_radial(max_terms=1, allow_float=False))
        lim, inc, note = 0, True, "smooth"
    shift = draw(st.sampled_from([0, 0, 1]))          # 1: f -> 1 at the origin
    v0 = draw(st.sampled_from([0, 0, R(1, 2)]))
    body = H + shift
    if draw(st.booleans()):
        f = sp.Piecewise((v0, sp.Eq(RHO, 0)), (body, True))
    else:
        f = sp.Piecewise((body, RHO > 0), (v0, True))
    consistent = v0 == lim + shift
    if consistent:
        t = radial_truth(growth) if inc else {"P1": True, "P2": True, "P3": False, "P4": True,
                                               "P5": False, "P6": False, "P7": True, "P8": True}
        if growth is not None and growth[0] >= 1000:
            t["P1"] = t["P6"] = False
    else:
        t = {"P1": False, "P2": v0 == 0, "P3": (growth is not None) if inc else None, "P4": None,
             "P5": False, "P6": False, "P7": False, "P8": True}
    return Case("origin", f, t, None, note=f"{note}, f(0) = {v0}, limit {lim + shift}")


@st.composite
def dip_designs(draw):
    """Near misses: touching zeros, dips negative on a tiny interval, and
    a monotonicity margin of exactly 0."""
    kind = draw(st.sampled_from(["touch", "eps", "eta", "cube"]))
    a = draw(st.sampled_from([R(2), R(6), R(1, 2), R(3)]))
    s = sp.sqrt(RHO)
    if kind == "touch":          # log(1 + rho (sqrt(rho) - a)^2): zero at |e| = a
        f = sp.log(1 + RHO * (s - a) ** 2)
        t = {"P1": True, "P2": True, "P3": False, "P4": True, "P5": False, "P6": False,
             "P7": True, "P8": True}
        return Case("dip", f, t, None, zeros=[(a, 0)], note="touching zero")
    if kind == "eps":            # H' = 2s[(s-a)(2s-a) + eps], min of (s-a)(2s-a) is -a^2/8
        k = draw(st.sampled_from([None, 3, 6, 12]))
        sgn = draw(st.sampled_from([1, -1]))
        eps = a ** 2 / 8 + (0 if k is None else sgn * R(1, 10 ** k))
        f = sp.log(1 + RHO * (s - a) ** 2 + eps * RHO)
        t = {"P1": True, "P2": True, "P3": True, "P4": True, "P5": eps > a ** 2 / 8,
             "P6": eps >= a ** 2 / 8, "P7": True, "P8": True}
        return Case("dip", f, t, None, note=f"eps - a^2/8 = {eps - a ** 2 / 8}")
    if kind == "eta":            # log(1 + G(rho) ((rho - c)^2 + eta)), |eta| tiny
        name = draw(st.sampled_from(["log1p", "atan", "id", "sqrt1p"]))
        G = BLOCKS[name][0](RHO)
        c = draw(st.sampled_from([R(1), R(2), R(5)]))
        eta = draw(st.sampled_from([0, 1, -1])) * R(1, 10 ** draw(st.integers(2, 10)))
        f = sp.log(1 + G * ((RHO - c) ** 2 + eta))
        t = {"P1": True, "P2": True, "P3": eta > 0, "P4": True, "P5": False, "P6": False,
             "P7": True, "P8": True}
        return Case("dip", f, t, None, radii=[sp.sqrt(c)],
                    zeros=[(sp.sqrt(c), 0)] if eta == 0 else [], note=f"eta = {eta}, {name}")
    # |rho - c|^3 written as a power 3/2 of an expanded square: f C^2, every property true
    c = draw(st.sampled_from([R(1), R(3, 2)]))
    w = draw(st.sampled_from([R(1), R(1, 2)]))
    f = sp.log(1 + RHO * (1 + w * (RHO ** 2 - 2 * c * RHO + c ** 2) ** R(3, 2)))
    t = {p: True for p in PROPS}
    return Case("dip", f, t, None, radii=[sp.sqrt(c)], note=f"|rho - {c}|^3 as a 3/2 power (w c^3 < 4)")


@st.composite
def mixed_sign_designs(draw):
    """A(rho) - c B(rho): positivity and monotonicity are not known by
    construction; only the oracle's numeric search can contradict a proof."""
    a, b = draw(atoms()), draw(atoms(depth=1))
    c = draw(st.sampled_from([R(1, 2), R(9, 10), R(1), R(11, 10), R(2), R(1, 100)]))
    f = a.expr - c * b.expr
    both_finite = kf_finite(a.growth) and kf_finite(b.growth)
    t = {"P1": True if both_finite else None, "P2": True, "P3": None, "P4": True, "P5": None,
         "P6": None, "P7": True, "P8": True}
    return Case("mixed", f, t, None, note=f"c = {c}")


@st.composite
def far_dip_designs(draw):
    """G(rho) - delta exp(-(rho - R)^2) with a bump far out (|e| = 10, 100, 1e4):
    f(0, 0) = -delta exp(-R^2) is not 0 (but below 1e-4000), f < 0 near the
    origin, and f' < 0 just beyond rho = R (delta sqrt(2/e) > G'(R), G concave)."""
    name = draw(st.sampled_from(["log1p", "sqrt1p"]))
    G = BLOCKS[name][0](RHO)
    Rr = draw(st.sampled_from([R(100), R(10 ** 4), R(10 ** 8)]))
    GR = sp.N(G.subs({e1: sp.sqrt(Rr), e2: 0}), 30)
    delta = R(Fraction(str(GR)).limit_denominator(1000)) * draw(st.sampled_from([R(1, 2), R(2), R(1)]))
    f = G - delta * sp.exp(-(RHO - Rr) ** 2)
    t = {"P1": True, "P2": False, "P3": False, "P4": True, "P5": False, "P6": False, "P7": True, "P8": True}
    return Case("far-dip", f, t, None, radii=[sp.sqrt(Rr)], note=f"{name}, bump at rho = {Rr}, delta = {delta}")


@st.composite
def almost_radial_designs(draw):
    """G(rho) + eps e1^2 e2^2/(1 + rho^2), eps tiny: not radial (P4 false)."""
    expr, growth, _ = draw(smooth_radial(max_terms=1, allow_float=False))
    eps = R(1, 10 ** draw(st.sampled_from([3, 10, 20])))
    f = expr + eps * e1 ** 2 * e2 ** 2 / (1 + RHO ** 2)
    t = {"P1": kf_finite(growth), "P2": True, "P3": growth is not None, "P4": False, "P5": None,
         "P6": None, "P7": True, "P8": True}
    return Case("almost-radial", f, t, sp.oo if not kf_finite(growth) else None, note=f"eps = {eps}")


ORDER = {"Cinf": 99, "C2": 2, "C1": 1, "C0": 0, "jump": -1}


@st.composite
def chain_designs(draw):
    """G(rho) with n = 2..4 circle boundaries, each join of a random order
    (D > 0 terms, so f stays increasing): the smoothness is the worst join."""
    expr, growth, _ = draw(smooth_radial(max_terms=1, allow_float=False))
    n = draw(st.integers(2, 4))
    cs = sorted(draw(st.lists(st.sampled_from([R(1, 4), R(1, 2), R(1), R(3, 2), R(2), R(3), R(5), R(9)]),
                              min_size=n, max_size=n, unique=True)))
    kinds = [draw(st.sampled_from(["C2", "C1", "C0", "jump", "Cinf"])) for _ in cs]
    pieces, body = [], expr
    for c, kind in zip(cs, kinds):
        pieces.append((body, RHO < c))
        if kind != "Cinf":
            body = body + draw(st.sampled_from([R(1), R(1, 3)])) * _join(kind, RHO - c)
    f = sp.Piecewise(*pieces, (body, True))
    worst = min(ORDER[k] for k in kinds)
    t = {"P1": worst >= 1 and kf_finite(growth), "P2": True, "P3": growth is not None,
         "P4": True if worst >= 1 else None, "P5": worst >= 1, "P6": worst >= 1 and dG_bounded(growth),
         "P7": worst >= 2, "P8": True}
    kf = sp.oo if worst >= 1 and not kf_finite(growth) else None
    return Case("chain", f, t, kf, radii=[sp.sqrt(c) for c in cs], note=", ".join(f"{k}@{c}" for c, k in zip(cs, kinds)))


@st.composite
def maxmin_designs(draw):
    """Max/Min of two radial functions: one dominates everywhere (f is the
    smooth one: every truth as for it), they cross with different slopes, or
    they touch to third order where they cross (f is C^2 there)."""
    which = draw(st.sampled_from(["max-dominated", "min-dominated", "max-cross", "min-cross", "max-tangent"]))
    L = sp.log(1 + RHO)
    if which == "max-dominated":      # log(1+x) >= x/(1+x), equal only at 0
        f, t, kf = sp.Max(L, RHO / (1 + RHO)), radial_truth((Fraction(0), Fraction(1))), sp.Integer(1)
    elif which == "min-dominated":    # log(1+x) <= x
        f, t, kf = sp.Min(L, RHO), radial_truth((Fraction(0), Fraction(1))), sp.Integer(1)
    elif which == "max-tangent":      # L + max(0, g^3/(1+x)^4), g = x - 2L < 0 before x = 2.513, > 0 after:
        # C^2 at the crossing; F' = 2s/(1+s^2) + 2s (3 g^2 g' (1+x) - 4 g^3)/(1+x)^5 > 0, and sup F' = 1 at s = 1
        # (below the crossing; 50-digit mpmath on a grid of [0.001, 200]: at most 0.90 beyond it)
        f, t, kf = sp.Max(L, L + (RHO - 2 * L) ** 3 / (1 + RHO) ** 4), {p: True for p in PROPS}, sp.Integer(1)
    else:                             # log(1+x) = x/2 at x = 2.513: slopes 0.285 and 1/2
        f = sp.Max(L, RHO / 2) if which == "max-cross" else sp.Min(L, RHO / 2)
        t = {"P1": False, "P2": True, "P3": True, "P4": None, "P5": False, "P6": False, "P7": False, "P8": True}
        kf = None
    return Case("maxmin", f, t, kf, radii=[sp.sqrt(R(2513, 1000))] if "cross" in which or "tangent" in which else [],
                note=which)


@st.composite
def float_power_designs(draw):
    """c rho^p, p a float a user would compute: f = c |e|^(2p)."""
    label, p = draw(st.sampled_from([("(0.1+0.2)/0.3", (0.1 + 0.2) / 0.3), ("0.3/(0.1*3)", 0.3 / (0.1 * 3)),
                                     ("0.75", 0.75), ("1.5", 1.5)]))
    c, _ = draw(coefficients(allow_float=False))
    f = c * RHO ** fl(p)

    def truth(q):                     # F(s) = c s^(2q); F'(s)/s = 2qc s^(2q-2); F''(s) ~ s^(2q-2)
        return {"P1": False, "P2": True, "P3": True, "P4": True, "P5": True,
                "P6": q == 1, "P7": q >= 1, "P8": True}
    return Case("float-power", f, truth(as_read(p)), sp.oo, note=f"rho**({label}) = rho**{p!r}")


@st.composite
def classic_designs(draw):
    """Fixed designs from the issue tracker, with their truth."""
    which = draw(st.sampled_from(["cube4", "zero-pow", "zero-pow-jump", "log-e", "design3"]))
    if which == "design3":     # c log cosh(sqrt(beta rho + 1) - 1): kf = c sqrt(beta) (sup at oo)
        # (c, not 1/alpha: SymPy would round 1/Float(alpha) to a new Float the truth must not ignore)
        (c, c_kf), (b, b_kf) = draw(coefficients()), draw(coefficients())
        f = c * sp.log(sp.cosh(sp.sqrt(b * RHO + 1) - 1))
        return Case("classic", f, radial_truth((Fraction(1, 2), Fraction(0))), c_kf * sp.sqrt(b_kf),
                    note=f"design 3, 1/alpha = {c}, beta = {b}")
    if which == "log-e":       # log(math.e + rho) - 1: math.e < e, so f(0) < 0
        t = radial_truth((Fraction(0), Fraction(1)), offset_sign=-1)
        return Case("classic", sp.log(fl(math.e) + RHO) - 1, t, 1 / sp.sqrt(kfc(math.e)), note=which)
    if which == "cube4":       # |rho - 4|^3: C^2, f(0) = 64
        f = (RHO ** 2 - 8 * RHO + 16) ** R(3, 2)
        t = {"P1": False, "P2": False, "P3": False, "P4": True, "P5": False, "P6": False,
             "P7": True, "P8": True}
        return Case("classic", f, t, sp.oo, radii=[R(2)], note=which)
    if which == "zero-pow":    # (1 - 0**rho) is 1 off the origin: f = log(1 + rho) with f(0) = 0
        f = sp.log(1 + RHO) * (1 - sp.Pow(0, RHO, evaluate=False))
        return Case("classic", f, radial_truth((Fraction(0), Fraction(1))), sp.Integer(1), note=which)
    # log(1 + rho) - 1 off the origin, 0 at it
    f = sp.log(1 + RHO) + sp.Pow(0, RHO, evaluate=False) - 1
    t = {"P1": False, "P2": True, "P3": False, "P4": None, "P5": False, "P6": False,
         "P7": False, "P8": True}
    return Case("classic", f, t, None, note=which)


@st.composite
def extreme_designs(draw):
    """Constants beyond the doubles' range and steep exponentials (the audit
    of 2026-11-25 found crashes there), every property true by construction
    (each term is increasing, 0 at the origin, analytic; growth log):
    c log(1 + rho): F' = 2 c s/(1 + s^2), kf = c at s = 1;
    log(1 + c rho): F' = 2 c s/(1 + c s^2), kf = sqrt(c) at s = 1/sqrt(c);
    log(1 + rho) + c (1 - exp(-K rho)): F'/s <= 2 + 2 c K, kf not known here.
    And SymPy Floats no double holds (red team 14a: read as 0 through a
    double): d log(1 + rho), all true, kf = d; log(1 + rho) + d, f(0, 0) = d
    (P2 false; P3 as the sign of d); 0 on the disc rho <= d, log(1 + rho)
    beyond: F jumps by about d at s = sqrt(d) (P1, P5, P6, P7 false; P3
    false: f = 0 on the disc; P8 true: df/de2 = 0 inside, 2 e2/(1 + rho)
    on the circle's outside and on it)."""
    kind = draw(st.sampled_from(["outer", "inner", "steep", "float-outer", "float-offset", "float-disc"]))
    if kind.startswith("float"):
        d = draw(st.sampled_from(["1e-400", "9e-330", "4e-600"] + (["3e-324", "5e400"] if kind == "float-outer"
                                                                     else [])))
        c, sign = fl_text(d), draw(st.sampled_from([1, -1])) if kind == "float-offset" else 1
        log_growth = (Fraction(0), Fraction(1))
        if kind == "float-outer":
            return Case("extreme", c * sp.log(1 + RHO), radial_truth(log_growth), sp.Rational(d),
                        note=f"Float('{d}') log(1 + rho)")
        if kind == "float-offset":
            return Case("extreme", sp.log(1 + RHO) + sign * c, radial_truth(log_growth, sign), sp.Integer(1),
                        note=f"log(1 + rho) + {sign} Float('{d}')")
        t = {"P1": False, "P2": True, "P3": False, "P4": None, "P5": False, "P6": False, "P7": False, "P8": True}
        return Case("extreme", sp.Piecewise((0, RHO <= c), (sp.log(1 + RHO), True)), t, None,
                    radii=[sp.sqrt(sp.Rational(d))], note=f"0 on rho <= Float('{d}'), log(1 + rho) beyond")
    c = sp.Integer(10) ** (draw(st.sampled_from([12, 40, 310, 400])) * draw(st.sampled_from([1, -1])))
    truth = radial_truth((Fraction(0), Fraction(1)))
    if kind == "outer":
        return Case("extreme", c * sp.log(1 + RHO), truth, c, note=f"c log(1 + rho), c = {c}")
    if kind == "inner":
        return Case("extreme", sp.log(1 + c * RHO), truth, sp.sqrt(c), note=f"log(1 + c rho), c = {c}")
    K = sp.Integer(10) ** draw(st.sampled_from([3, 6, 30]))
    return Case("extreme", sp.log(1 + RHO) + c * (1 - sp.exp(-K * RHO)), truth, None,
                note=f"log(1 + rho) + c (1 - exp(-K rho)), c = {c}, K = {K}")


@st.composite
def rotated_designs(draw):
    """c G((e1 cos t + e2 sin t)^2 + (e1 sin t - e2 cos t)^2) = c G(rho)
    (cos^2 t + sin^2 t = 1): radial, though SymPy's automatic evaluation
    neither expands the squares nor sees the identity; its proofs build
    expressions SymPy reads back in another form (a fresh checker once
    rejected such certificates)."""
    name = draw(st.sampled_from(SAFE_BLOCKS))
    G, grow, ksup = BLOCKS[name]
    t = draw(st.sampled_from([sp.Integer(1), R(1, 2), sp.pi / 7, R(3)]))
    c, c_ex = draw(coefficients())
    f = c * G((e1 * sp.cos(t) + e2 * sp.sin(t)) ** 2 + (e1 * sp.sin(t) - e2 * sp.cos(t)) ** 2)
    g = grow(RHO_GROWTH)
    kf = sp.oo if not kf_finite(g) else (None if ksup is None else c_ex * ksup)
    return Case("rotated", f, radial_truth(g), kf, note=f"{name}, t = {t}")


FAMILIES = {
    "radial": radial_designs, "float-offset": float_offset_designs, "power": power_designs,
    "elliptic": elliptic_designs, "separable": separable_designs, "cross": cross_term_designs,
    "half-plane": half_plane_designs, "circle-piecewise": circle_piecewise_designs,
    "point-value": point_value_designs, "origin": origin_designs, "dip": dip_designs,
    "classic": classic_designs, "mixed": mixed_sign_designs, "far-dip": far_dip_designs,
    "almost-radial": almost_radial_designs, "chain": chain_designs, "maxmin": maxmin_designs,
    "float-power": float_power_designs, "extreme": extreme_designs, "rotated": rotated_designs,
}


def settle_origin(case: Case) -> Case:
    """SymPy adds the constant terms of float-coefficient sums in 53-bit
    arithmetic (c2 (sqrt(1 + u) - 1) + c1 (1 - exp(-u)) keeps c1 - c2 rounded),
    so f(0, 0) may be a few ulps off 0: the truth follows the expression."""
    if not case.f.atoms(sp.Float) or case.truth.get("P2") is not True:
        return case
    sign = _exact_sign(_origin_as_read(case.f))
    if sign:
        case.truth = dict(case.truth, P2=False)       # (a plain bool: no __post_init__ here)
        if sign < 0:
            case.truth["P3"] = False
        case.note += f" (constants rounded by SymPy: f(0, 0) {'<' if sign < 0 else '>'} 0)"
    return case


def designs(family: str | None = None):
    """Any design of the grammar, or of one family."""
    return st.one_of(*(s().map(settle_origin) for name, s in FAMILIES.items() if family in (None, name)))


def design_source(case: Case) -> str:
    """A design file that rebuilds exactly `case.f` (srepr keeps every Float's bits)."""
    doc = f"{case.family}: {case.note}\nf = {case.f}".replace('"""', "'''").replace("\\", "\\\\")
    return (f'"""{doc}"""\nfrom sympy import *\n'
            "from sympy.functions.elementary.piecewise import ExprCondPair\n"
            "from sympy.core.relational import Equality, StrictLessThan, LessThan, StrictGreaterThan, GreaterThan\n\n"
            f"f = {sp.srepr(case.f)}\n")
