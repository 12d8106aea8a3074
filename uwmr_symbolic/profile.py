"""Radial reduction (P4) and the profile F of a radial f.

If f(e1, e2) = F(|(e1, e2)|) as a symbolic identity, then
  df/de1 = F'(s) e1/s,  df/de2 = F'(s) e2/s,  s = sqrt(e1^2 + e2^2),
so e1 df/de2 = e2 df/de1 wherever F is differentiable (P4), and every other
property becomes a claim about F on [0, oo).  A Piecewise F is split at its
boundaries into pieces, each a plain expression on an open interval; the
boundaries are found by SymPy and then *checked*: every condition is proved
to keep a constant sign between consecutive boundaries, so no boundary can
be missed.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from . import e1 as E1, e2 as E2
from .interval import Interval, IntervalFunction, Undefined
from .kernel import core as K
from .limits import NoLimit, limit_right
from .timeouts import attempt
from .univariate import (X, certified_inside, enclose, exact_sign, exact_value, exact_zeros_in, numerically_equal,
                         prepare, prove_sign, rational_between, substitute)
from .verdict import Verdict, proved, refuted, unknown

S = sp.Symbol("s", nonnegative=True)     # the radius |(e1, e2)|
RHO = sp.sqrt(E1 ** 2 + E2 ** 2)

# exact points on circles of radius 1: (a, b) with a^2 + b^2 = 1
_UNIT_CIRCLE = [(sp.Integer(1), 0), (0, sp.Integer(1)), (-1, 0), (0, -1),
                (sp.Rational(3, 5), sp.Rational(4, 5)), (sp.Rational(-3, 5), sp.Rational(4, 5)),
                (sp.Rational(5, 13), sp.Rational(-12, 13)), (sp.Rational(-8, 17), sp.Rational(-15, 17)),
                (sp.Rational(20, 29), sp.Rational(21, 29))]
_RADII = [sp.Rational(1, 3), sp.Rational(1, 2), 1, sp.Rational(3, 2), 2, 3, 5, 10, 37,
          sp.Rational(1, 100), 100, 10 ** 4, 10 ** 6]


SIMPLIFY_SECONDS = 5.0


def radial_profile(f: sp.Expr) -> sp.Expr:
    """F(s) = f(s, 0) for s >= 0 (the candidate profile)."""
    return sp.piecewise_fold(f.subs({E1: S, E2: 0}))


def verify_radial(f: sp.Expr, F: sp.Expr) -> Verdict:
    """P4 through radial symmetry: prove f == F(|e|), or refute it with two
    points on one circle where f takes different (certified) values."""
    if _same_function(f, F.subs(S, RHO)):
        return proved("f(e1, e2) = F(sqrt(e1^2 + e2^2)) is a symbolic identity, "
                      "so e1 df/de2 - e2 df/de1 = (e1 e2 - e2 e1) F'(s)/s = 0")
    radial = F.subs(S, RHO)
    diff = f - radial
    agree = numerically_equal(f, radial)
    for simplifier in (sp.expand, sp.simplify, lambda e: sp.simplify(sp.expand(e))) if agree else ():
        # (5 s each: simplify ran for minutes on the conditions of Max(log(1 + rho/10^12) 10^12, rho/2))
        if attempt(lambda: simplifier(diff) == 0, SIMPLIFY_SECONDS, False):
            return proved("f(e1, e2) = F(sqrt(e1^2 + e2^2)) is a symbolic identity (SymPy's "
                          "simplification, cross-checked in interval arithmetic), so "
                          "e1 df/de2 - e2 df/de1 = (e1 e2 - e2 e1) F'(s)/s = 0")
    # 200 bits, then 2,000 for differences such as 10^-300 (the kernel's constant signs reach as far)
    radii = _RADII + _condition_radii(f)
    for fn in (IntervalFunction(f, [E1, E2], mode="range", prec=prec) for prec in (200, 2000)):
        for r in radii:
            values = []
            for a, b in _UNIT_CIRCLE:
                p = (r * a, r * b)
                try:
                    values.append((p, fn(Interval.point(p[0]), Interval.point(p[1]))))
                except Undefined:
                    continue
            for p, vp in values:
                for q, vq in values:
                    if vp.upper_fraction() is not None and vq.lower_fraction() is not None \
                            and vp.upper_fraction() < vq.lower_fraction():
                        return refuted(
                            f"f is not radial: f{_pt(p)} < f{_pt(q)} on the circle of radius {r}, so "
                            "e1 df/de2 = e2 df/de1 fails somewhere on the arc between them (or the "
                            "derivatives do not exist there)",
                            {"point_a": _pt_json(p), "point_b": _pt_json(q),
                             "f_a": [vp.lower_float(), vp.upper_float()],
                             "f_b": [vq.lower_float(), vq.upper_float()]})
    # (e1 df/de2 - e2 df/de1 simplifying to 0 is not used: SymPy differentiates
    # a Piecewise branch by branch and says nothing about its boundaries, and
    # only the identity f = F(|e|) licenses the reduction to F)
    try:        # the kernel's own identity: a Piecewise whose conditions read alike (e1 != 0 | e2 != 0 and |e| != 0)
        K.identity_plane(lhs=f, rhs=radial, x=E1, y=E2)
        return proved("f(e1, e2) = F(sqrt(e1^2 + e2^2)) is an identity (the kernel's), "
                      "so e1 df/de2 - e2 df/de1 = (e1 e2 - e2 e1) F'(s)/s = 0")
    except K.KernelError:
        return unknown("could neither prove f radial nor find two points on a circle with different values")


def _condition_radii(f) -> list:
    """Radii for P4's circles from f's Piecewise conditions: each positive
    number c in them, its square root where rational (a condition may read
    rho or |e1|), the midpoints between these and twice the largest (f may
    differ from radial only on an annulus, or only beyond e1 = c)."""
    conds = [c for pw in f.atoms(sp.Piecewise) for _, c in pw.args if c not in (sp.true, sp.false)]
    numbers = {abs(n) for c in conds for n in c.atoms(sp.Rational) if n != 0 and abs(n) < 10 ** 30}
    radii = sorted(numbers | {r for n in numbers for r in [sp.sqrt(n)] if r.is_Rational})[:12]
    return radii + [(a + b) / 2 for a, b in zip(radii, radii[1:])] + [2 * r for r in radii[-1:]]


def elliptic_ratio(f, F):
    """r != 1 with f(e1, e2) = F(sqrt(e1^2 + r e2^2)) proved as a symbolic
    identity, or None.  r is proposed from the leading Taylor terms of f on
    the two axes (a proposal only); the identity decides."""
    t = sp.Symbol("t", positive=True)
    a, b = (attempt(lambda g=g: sp.series(g, t, 0, 7).removeO(), 2.0)      # (SymPy's series can run for minutes)
            for g in (f.subs({E1: t, E2: 0}), f.subs({E1: 0, E2: t})))
    if a is None or b is None:
        return None
    for m in (1, 2, 3):
        ca, cb = a.coeff(t, 2 * m), b.coeff(t, 2 * m)
        if ca != 0 or cb != 0:
            break
    else:
        return None
    if ca == 0 or cb == 0 or (cb / ca).atoms(sp.Function) or not (cb / ca).is_positive:
        return None         # (exp(-10^10 c^2) in a ratio sent radsimp's nsimplify into a MemoryError)
    r = sp.radsimp((cb / ca) ** sp.Rational(1, m))
    if r == 1 or not r.is_positive or r.has(sp.Float):
        return None
    return r if _same_function(f, F.subs(S, sp.sqrt(E1 ** 2 + r * E2 ** 2))) else None


def _equal(a, b) -> bool:
    """a == b as an identity: SymPy's expand or simplify says a - b = 0, and
    the numeric cross-check `numerically_equal` agrees."""
    e = a - b
    if e == 0:
        return True
    if not numerically_equal(a, b):
        return False        # cheap, and spares simplify on what is no identity
    try:
        return sp.expand(e) == 0 or sp.simplify(e) == 0
    except Exception:  # noqa: BLE001 - a SymPy failure is just 'not shown'
        return False


def _same_function(a, b) -> bool:
    """a and b are the same expression up to SymPy identities, compared
    branch by branch and condition by condition for Piecewise."""
    if isinstance(a, sp.Piecewise) and isinstance(b, sp.Piecewise):
        return len(a.args) == len(b.args) and all(
            _same_function(ea, eb) and _same_condition(ca, cb)
            for (ea, ca), (eb, cb) in zip(a.args, b.args))
    return _equal(a, b)


def _canonical_relation(rel):
    """(strict?, g) with the relation meaning g > 0 (strict) or g >= 0."""
    if isinstance(rel, (sp.StrictGreaterThan, sp.GreaterThan)):
        return isinstance(rel, sp.StrictGreaterThan), rel.lhs - rel.rhs
    if isinstance(rel, (sp.StrictLessThan, sp.LessThan)):
        return isinstance(rel, sp.StrictLessThan), rel.rhs - rel.lhs
    return None


def _zero_set(cond):
    """g with cond <=> g = 0 over the reals, for an equation or a conjunction
    of equations (a = 0 and b = 0 <=> a^2 + b^2 = 0; sqrt(h) = 0 <=> h = 0),
    else None."""
    if isinstance(cond, sp.Eq):
        g = cond.lhs - cond.rhs
        while isinstance(g, sp.Pow) and g.exp.is_positive:
            g = g.base          # h**p = 0 <=> h = 0 for p > 0
        return g
    if isinstance(cond, sp.And):
        parts = [_zero_set(c) for c in cond.args]
        if all(p is not None and p.is_real for p in parts):
            return sp.Add(*[p ** 2 for p in parts])
    return None


def _same_condition(a, b) -> bool:
    if a == b:
        return True
    za, zb = _zero_set(a), _zero_set(b)
    if za is not None and zb is not None:
        za, zb = _zero_set(sp.Eq(za, 0)), _zero_set(sp.Eq(zb, 0))
        return _equal(za, zb) or _equal(za, -zb)
    ka, kb = _canonical_relation(a), _canonical_relation(b)
    if ka is not None and kb is not None and ka[0] == kb[0]:
        return _equal(ka[1], kb[1])
    if isinstance(a, (sp.And, sp.Or)) and type(a) is type(b) and len(a.args) == len(b.args):
        return all(_same_condition(x, y) for x, y in zip(a.args, b.args))
    return False


def _pt(p):
    return f"({p[0]}, {p[1]})"


def _pt_json(p):
    return [str(p[0]), str(p[1])]


# --------------------------------------------------------------------------
# pieces of a Piecewise profile

@dataclass
class Piece:
    lo: sp.Expr            # exact, >= 0
    hi: sp.Expr            # exact or oo
    expr: sp.Expr          # F on the open interval (lo, hi)


@dataclass
class Profile:
    """F on [0, oo): pieces between exact boundaries, and F's branch at each
    boundary point (and at 0)."""
    pieces: list
    at_point: dict = field(default_factory=dict)   # boundary -> expression valid there

    @property
    def boundaries(self):
        return [p.lo for p in self.pieces[1:]]

    @property
    def ends(self):
        """0, the boundaries, oo (the cuts of the kernel's Piecewise rules)."""
        return [p.lo for p in self.pieces] + [sp.oo]


def _relationals(cond):
    if isinstance(cond, sp.core.relational.Relational):
        return [cond]
    if isinstance(cond, (sp.And, sp.Or, sp.Not)):
        return [r for a in cond.args for r in _relationals(a)]
    return []


def _choose_branch(pw: sp.Piecewise, truth: dict):
    for branch, cond in pw.args:
        value = cond.xreplace(truth) if truth else cond
        if value in (True, sp.true):
            return branch
        if value not in (False, sp.false):
            return None
    return None


def split_profile(F: sp.Expr) -> tuple[Profile | None, Verdict]:
    """Split F into pieces, proving the boundary list complete."""
    F = sp.piecewise_fold(F)
    if not isinstance(F, sp.Piecewise):
        if F.has(sp.Piecewise):
            return None, unknown("nested Piecewise that could not be folded")
        return Profile([Piece(sp.Integer(0), sp.oo, F)], {sp.Integer(0): F}), proved("no boundaries")
    rels = list(dict.fromkeys(r for _, c in F.args for r in _relationals(c)))
    points, switches = set(), set()         # switches: where a relation other than an Eq changes truth
    for rel in rels:
        g = rel.lhs - rel.rhs
        # SymPy only proposes the switching points: a missed one makes the
        # proof below (each condition keeps its truth value between
        # consecutive points) fail, so any other answer proposes none
        sols = attempt(lambda: sp.solveset(sp.Eq(g, 0), S, sp.Interval.open(0, sp.oo)), 5.0)
        for b in (sols.args if isinstance(sols, sp.FiniteSet) else ()):
            if not certified_inside(b, 0, sp.oo):
                return None, unknown(f"boundary candidate {b} of {rel} is not certified to be a positive real")
            v = exact_value(g, S, b)
            if v is None or exact_sign(v) != 0:
                return None, unknown(f"boundary candidate {b} of {rel} not confirmed")
            if b.has(sp.Float):
                return None, unknown(f"boundary candidate {b} of {rel} is not exact")
            points.add(b)
            switches |= set() if isinstance(rel, sp.Eq) else {b}
    bounds = [sp.Integer(0), *sorted(points, key=lambda b: float(b)), sp.oo]
    pieces, at_point = [], {}
    for i in range(len(bounds) - 1):
        a, b = bounds[i], bounds[i + 1]
        truth = {}
        for rel in rels:
            g = rel.lhs - rel.rhs
            m = rational_between(a, b) if b != sp.oo else a + 1
            s_m = exact_sign(exact_value(g, S, m))
            if not s_m:
                return None, unknown(f"cannot decide {rel} at s = {m}")
            v = prove_sign(g, S, a, b, want=s_m, budget=1500)
            if not v.proved:
                return None, unknown(f"cannot prove {rel} keeps its truth value on ({a}, {b}): {v.reason}")
            truth[rel] = sp.true if rel.func(s_m, 0) else sp.false
        branch = _choose_branch(F, truth)
        if branch is None:
            return None, unknown(f"no branch of F applies on ({a}, {b})")
        pieces.append(Piece(a, b, branch))
    for b in bounds[:-1]:
        truth = {}
        for rel in rels:        # undecided (or without a value at b: log s > 0 at 0): only a later condition's
            sgn = exact_sign(exact_value(rel.lhs - rel.rhs, S, b))
            if sgn is not None:
                truth[rel] = sp.true if rel.func(sgn, 0) else sp.false
        branch = _choose_branch(F, truth)
        if branch is None:
            return None, unknown(f"cannot decide which branch of F applies at s = {b}")
        at_point[b] = branch
    for i in range(len(pieces) - 1, 0, -1):     # a point value (Eq) equal to the formula around it: no boundary
        left, right = pieces[i - 1], pieces[i]
        gap = exact_value(at_point[right.lo] - right.expr, S, right.lo)
        if left.expr == right.expr and right.lo not in switches and gap is not None and exact_sign(gap) == 0:
            pieces[i - 1:i + 1] = [Piece(left.lo, right.hi, left.expr)]
            del at_point[right.lo]
    bounds = [p.lo for p in pieces[1:]]
    found = f"boundaries at s = {', '.join(map(str, bounds))}" if bounds else "no boundaries"
    return Profile(pieces, at_point), proved(found)


# --------------------------------------------------------------------------
# continuity of one expression on an interval, and one-sided values

def guards(expr: sp.Expr) -> list[tuple[sp.Expr, str]] | None:
    """Conditions under which expr is continuous: (g, 'nonzero'|'positive'|
    'nonnegative').  None if expr contains an operation we cannot vouch for."""
    out = []
    for node in sp.preorder_traversal(expr):
        if isinstance(node, (sp.Symbol, sp.Number, sp.NumberSymbol, sp.Add, sp.Mul)):
            continue
        if isinstance(node, sp.Pow):
            b, e = node.args
            if not e.is_number:
                out.append((b, "positive"))
            elif e.is_integer:
                if e < 0:
                    out.append((b, "nonzero"))
            elif e > 0:
                out.append((b, "nonnegative"))
            else:
                out.append((b, "positive"))
        elif isinstance(node, sp.log):
            out.append((node.args[0], "positive"))
        elif isinstance(node, (sp.sign, sp.Heaviside)):
            out.append((node.args[0], "nonzero"))
        elif isinstance(node, sp.tan):
            out.append((sp.cos(node.args[0]), "nonzero"))
        elif isinstance(node, sp.acosh):
            out.append((node.args[0] - 1, "nonnegative"))
        elif isinstance(node, sp.atanh):
            out.append((1 - node.args[0] ** 2, "positive"))
        elif isinstance(node, (sp.asin, sp.acos)):
            out.append((1 - node.args[0] ** 2, "nonnegative"))
        elif isinstance(node, sp.Piecewise):
            for _, c in node.args:
                out.extend((r.lhs - r.rhs, "nonzero") for r in _relationals(c))
        elif isinstance(node, (sp.exp, sp.sin, sp.cos, sp.sinh, sp.cosh, sp.tanh, sp.atan,
                               sp.asinh, sp.erf, sp.Abs, sp.Max, sp.Min)):
            continue
        elif isinstance(node, sp.logic.boolalg.Boolean):
            continue
        else:
            return None
    checked = []
    for g, kind in dict.fromkeys(out):
        if g.has(S):
            checked.append((g, kind))
            continue
        sgn = exact_sign(g)        # a constant guard must hold outright
        if sgn is None or not {"nonzero": sgn != 0, "positive": sgn > 0, "nonnegative": sgn >= 0}[kind]:
            return None
    return checked


def _guard_holds(g, kind, lo, hi, closed) -> bool:
    """g is nonzero / positive / nonnegative on [lo, hi] (closed) or (lo, hi)."""
    ends = dict(lo_open=not closed, hi_open=not closed or hi == sp.oo)
    if kind == "nonnegative":
        if prove_sign(g, S, lo, hi, want=1, strict=False, **ends).proved:
            return True
        # zeros inside the interval (a touching zero of a radicand): g > 0 between them
        zeros = exact_zeros_in(g, S, lo, hi)
        ends_ok = not closed or all(exact_sign(exact_value(g, S, c)) in (0, 1) for c in (lo, hi) if c != sp.oo)
        return bool(zeros) and ends_ok and prove_sign(g, S, lo, hi, want=1, zeros=zeros).proved
    wants = (1, -1) if kind == "nonzero" else (1,)
    return any(prove_sign(g, S, lo, hi, want=w, **ends).proved for w in wants)


def continuous_on(expr, lo, hi, closed=True) -> Verdict:
    """Prove expr continuous on [lo, hi] (closed=True, finite ends included)
    or on the open (lo, hi): every guard holds there.  A guard that fails
    is no refutation by itself (0/0 may be removable); expr is refuted only
    where a guard has an exact zero at which expr has an infinite one-sided
    limit."""
    gs = guards(expr)
    if gs is None:
        return unknown(f"cannot vouch for the continuity of {expr}")
    for g, kind in gs:
        if _guard_holds(g, kind, lo, hi, closed):
            continue
        where = f"[{lo}, {hi}]" if closed else f"({lo}, {hi})"
        for z in exact_zeros_in(g, S, lo, hi):
            for side in (-1, 1):
                if one_sided_value(expr, z, side) in (sp.oo, -sp.oo):
                    return refuted(f"{expr} is unbounded as s -> {z}{'+' if side > 0 else '-'} "
                                   f"({g} vanishes there)", z)
        return unknown(f"cannot show {g} {kind} on {where}")
    return proved("continuous")


NEAR = sp.Rational(1, 1024)     # the one-sided box on which one_sided_value checks continuity


def one_sided_value(expr, c, side: int):
    """lim expr as s -> c from the right (side=+1) or left (side=-1):
    an exact number, +-oo, or None when undecided.  Substitution when expr
    is continuous up to c; the limit calculus otherwise."""
    expr = sp.sympify(expr)
    lo, hi = (c, c + NEAR) if side > 0 else (c - NEAR, c)
    try:       # continuous on the closed one-sided box (proved by interval evaluation): the limit is E(c)
        enclose(expr, S, lo, hi, mode="continuous")
        v = exact_value(expr, S, c)
        if v is not None:
            return v
    except (Undefined, TypeError, ValueError):
        pass
    try:
        lim = limit_right(substitute(prepare(expr), S, c + side * X), X)
        return None if lim.value.has(sp.nan, sp.zoo) else lim.value
    except NoLimit:
        pass
    except (ZeroDivisionError, TypeError, ValueError):
        return None
    if (c, side) == (0, 1):     # 0/0 at the origin: the kernel's Taylor quotient (sinh(s^2)/s^2 - 1 -> 0)
        from .certify import NoProof, taylor_limit
        from .kernel.parse import parse
        try:
            return parse(taylor_limit(expr, S, NEAR).claim.other)
        except (NoProof, ZeroDivisionError, TypeError, ValueError):
            return None
    return None


def same_value(a, b) -> bool | None:
    """Exact comparison of two exact limits: True, False or None."""
    if a is None or b is None:
        return None
    if a in (sp.oo, -sp.oo) or b in (sp.oo, -sp.oo):
        return a == b
    if (a - b).has(sp.Float):
        return None
    sgn = exact_sign(a - b)
    return None if sgn is None else sgn == 0


def float_of(v) -> float:
    return float(sp.N(v, 20)) if v not in (sp.oo, -sp.oo) else (float("inf") if v == sp.oo else float("-inf"))
