"""Does the verifier's answer contradict the truth?

`check(case, result)` returns the `Contradiction`s between one verifier
result (see `worker.py`) and
  * the truth the grammar knows by construction (`case.truth`, `case.kf`,
    exact zeros in `case.zeros`), and
  * independent numeric evidence: a search in double precision over radii
    1e-8 ... 1e8, many directions, the axes, both sides of every circle
    boundary and the origin; every candidate is re-evaluated with mpmath at
    50 and at 100 digits and counts only if both agree (a robust value).
Numbers only ever refute a claim of the verifier; they prove nothing.
Floats are read as the verifier documents (README): a double as its
shortest round-trip decimal (`grammar.as_read`).  Every contradiction
fails the fixed-seed test (the classes issue 9 reported are fixed).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from uwmr_symbolic import e1, e2

from .grammar import PROPS, Case, as_read, placeholders

SMALL = (sp.Rational(1, 10 ** 12), sp.Rational(1, 10 ** 24))   # distances to a boundary or the origin


@dataclass
class Contradiction:
    prop: str           # P1..P8 or kf
    kind: str           # false proof | wrong refutation | bad witness | wrong kf | certificate | crash | hang | unusable
    evidence: str
    known: str | None = None

    def line(self):
        tag = f" [known: {self.known}]" if self.known else ""
        return f"{self.prop}: {self.kind}{tag}: {self.evidence}"


def exact(f):
    """f with every Float as the verifier reads it (README): a double as its repr decimal, a
    Float beyond the doubles as the decimal the grammar wrote."""
    f = placeholders(f, as_read)
    return f.xreplace({a: as_read(a) for a in f.atoms(sp.Float)})


def _mpf(x, dps):
    if isinstance(x, (float, int)):
        return mpmath.mpf(x)
    return mpmath.mpf(str(sp.N(x, dps + 20)))


class Num:
    """f and its partial derivatives, in doubles (search) and mpmath (evidence)."""

    NAMES = {"f": (), "f1": (e1,), "f2": (e2,), "f22": (e2, e2), "f12": (e1, e2)}

    def __init__(self, f):
        self.fx = exact(f)
        self.exprs = {k: sp.diff(self.fx, *v) if v else self.fx for k, v in self.NAMES.items()}
        self._mp, self._np = {}, {}

    def mp(self, k, x, y, dps=50):
        if k not in self._mp:
            self._mp[k] = sp.lambdify((e1, e2), self.exprs[k], "mpmath")
        with mpmath.workdps(dps):
            try:
                v = self._mp[k](_mpf(x, dps), _mpf(y, dps))
                v = mpmath.mpmathify(v)
            except Exception:
                return None
            return v if mpmath.isfinite(v) and not isinstance(v, mpmath.mpc) else None

    def both(self, k, x, y):
        """The value at 50 and at 100 digits when they agree, else None."""
        a, b = self.mp(k, x, y, 50), self.mp(k, x, y, 100)
        if a is None or b is None:
            return None
        with mpmath.workdps(100):
            if abs(a - b) > mpmath.mpf("1e-35") * max(1, abs(b)):
                return None
        return b

    def np(self, k, X, Y):
        if k not in self._np:
            self._np[k] = sp.lambdify((e1, e2), self.exprs[k], ["scipy", "numpy"])
        with np.errstate(all="ignore"):
            try:
                v = np.broadcast_to(np.asarray(self._np[k](X, Y), dtype=float), X.shape)
            except Exception:
                return np.full(X.shape, np.nan)
        return v


def sample_points(radii):
    r = np.concatenate([np.logspace(-8, 8, 161), np.linspace(0.05, 12, 240)]
                       + [np.sqrt(float(b) ** 2) * (1 + np.array([-1e-3, -1e-6, -1e-9, 0, 1e-9, 1e-6, 1e-3]))
                          for b in radii])
    th = np.array([0, np.pi / 2, np.pi / 4, 3 * np.pi / 4, np.pi, 0.3, 1.1, 2.5, 4.0, 5.5, -1e-7, np.pi / 2 + 1e-7])
    R, T = np.meshgrid(r, th)
    return (R * np.cos(T)).ravel(), (R * np.sin(T)).ravel()


def _worst(values, n=6):
    idx = np.argsort(values)
    return [i for i in idx[:n] if np.isfinite(values[i])]


class Evidence:
    """Numeric searches for counterexamples to each property of f."""

    def __init__(self, case: Case, f=None):
        self.case = case
        self.num = Num(case.f if f is None else f)
        self.X, self.Y = sample_points(case.radii)

    # each returns a description of a robust counterexample, or None
    def p2(self):
        v = sp.N(self.num.fx.subs({e1: 0, e2: 0}), 60)
        if v.is_number and v != 0 and abs(v) > 1e-45:
            return f"f(0, 0) = {sp.N(v, 20)} (exact value of the user's f, 60 digits)"
        return None

    def p3(self):
        for (x, y) in self.case.zeros:
            v = sp.simplify(self.num.fx.subs({e1: x, e2: y}))
            if v == 0:
                return f"f({x}, {y}) = 0 exactly (symbolic substitution)"
        F = self.num.np("f", self.X, self.Y)
        for i in _worst(np.where((self.X == 0) & (self.Y == 0), np.inf, F)):
            if F[i] <= 0:
                v = self.num.both("f", float(self.X[i]), float(self.Y[i]))
                if v is not None and v < 0:
                    return f"f({float(self.X[i])!r}, {float(self.Y[i])!r}) = {mpmath.nstr(v, 15)} (50 and 100 digits)"
        return None

    def p4(self):
        for r in [sp.Rational(1, 3), sp.Integer(1), sp.Rational(7, 4), sp.Integer(5), sp.Rational(1, 1000)] + \
                 [b * sp.Rational(1001, 1000) for b in self.case.radii]:
            pts = [(r, 0), (0, r), (-r, 0), (0, -r), (3 * r / 5, 4 * r / 5), (-4 * r / 5, 3 * r / 5),
                   (3 * r / 5, -4 * r / 5)]
            vals = [(p, self.num.both("f", *p)) for p in pts]
            vals = [(p, v) for p, v in vals if v is not None]
            for (p, v), (q, w) in zip(vals, vals[1:]):
                if abs(v - w) > mpmath.mpf("1e-25") * max(1, abs(v)):
                    return (f"f{p} = {mpmath.nstr(v, 15)} but f{q} = {mpmath.nstr(w, 15)} on the same circle "
                            f"|e| = {r} (50 and 100 digits)")
        return None

    def p5(self):
        X, Y = self.X, self.Y
        G = self.num.np("f1", X, Y) * np.sign(X)
        for i in _worst(np.where(X == 0, np.inf, G)):
            if G[i] <= 0:
                v = self.num.both("f1", float(X[i]), float(Y[i]))
                if v is not None and v * np.sign(X[i]) < 0:
                    return f"df/de1({float(X[i])!r}, {float(Y[i])!r}) = {mpmath.nstr(v, 15)} (50 and 100 digits)"
        for y in [1.0, -0.5, 3.0, 1e-3, 100.0]:
            v = self.num.both("f1", 0, y)
            if v is not None and abs(v) > 1e-20:
                return f"df/de1(0, {y}) = {mpmath.nstr(v, 15)} != 0 (50 and 100 digits)"
        return self.jump("f1") or self.jump("f")

    def p6(self):
        X, Y = self.X, self.Y
        G = self.num.np("f1", X, Y) / X
        for i in _worst(np.where(X == 0, np.inf, G)):
            if G[i] < 0:
                v = self.num.both("f1", float(X[i]), float(Y[i]))
                if v is not None and v / X[i] < 0:
                    return (f"df/de1 / e1 = {mpmath.nstr(v / X[i], 15)} < 0 at ({float(X[i])!r}, {float(Y[i])!r}), "
                            f"so h < 0 (50 and 100 digits)")
        return self.jump("f1") or self.jump("f")

    def p8(self):
        for x in [0, 1, -2.5, 1e-4, 30] + list(self.case.radii):
            vals = [self.num.both("f2", x, d) for d in SMALL]
            # a limit that is not 0: the value stays put when e2 shrinks by 1e12
            if all(v is not None and abs(v) > 1e-4 for v in vals) and abs(vals[1]) > 1e-3 * abs(vals[0]):
                return (f"df/de2({x}, e2) = {mpmath.nstr(vals[0], 10)} at e2 = 1e-12 and "
                        f"{mpmath.nstr(vals[1], 10)} at e2 = 1e-24 (50 and 100 digits): does not tend to 0")
        return None

    def jump(self, k):
        """A robust jump of f or a derivative across a circle boundary or at
        the origin: seen at distance 1e-12 and 1e-24, each value the same at
        50 and 100 digits."""
        dirs = [(1, 0), (0, 1), (sp.Rational(3, 5), sp.Rational(4, 5))]

        def apart(u, v):
            return u is not None and v is not None and abs(u - v) > 1e-6 * max(1, abs(u), abs(v))

        def kept(gaps):     # a jump's gap stays as the distance shrinks 10^12-fold; a slope's shrinks with it
            return abs(gaps[1]) >= abs(gaps[0]) / 2
        for b in self.case.radii:
            for (cx, cy) in dirs:
                seen = [(self.num.both(k, cx * b * (1 - d), cy * b * (1 - d)),
                         self.num.both(k, cx * b * (1 + d), cy * b * (1 + d))) for d in SMALL]
                if all(apart(lo, hi) for lo, hi in seen) and kept([hi - lo for lo, hi in seen]):
                    lo, hi = seen[1]
                    return (f"{k} jumps across |e| = {b} in direction ({cx}, {cy}): {mpmath.nstr(lo, 12)} "
                            f"inside, {mpmath.nstr(hi, 12)} outside at distance 1e-24 (50 and 100 digits)")
            if k == "f":     # the value on the circle against the limit
                on = sp.N(self.num.fx.subs({e1: b, e2: 0}), 60)
                outs = [self.num.both("f", b * (1 + d), 0) for d in SMALL]
                if on.is_number and all(apart(mpmath.mpf(str(on)), o) for o in outs) and \
                        kept([o - mpmath.mpf(str(on)) for o in outs]):
                    return f"f({b}, 0) = {sp.N(on, 15)} but f -> {mpmath.nstr(outs[1], 15)} next to it"
        # the origin: the value against the limit, derivatives from different directions
        rows = [[self.num.both(k, cx * d, cy * d) for cx, cy in dirs + [(-1, 0), (0, -1)]] for d in SMALL]
        if all(v is not None for row in rows for v in row):
            if all(apart(max(row), min(row)) for row in rows) and kept([max(row) - min(row) for row in rows]):
                return (f"{k} near the origin at radius 1e-24 takes the values "
                        f"{[mpmath.nstr(v, 8) for v in rows[1]]} in different directions (50 and 100 digits)")
            if k == "f":
                at0 = sp.N(self.num.fx.subs({e1: 0, e2: 0}), 60)
                if at0.is_number and all(apart(mpmath.mpf(str(at0)), row[0]) for row in rows) and \
                        kept([row[0] - mpmath.mpf(str(at0)) for row in rows]):
                    return f"f(0, 0) = {sp.N(at0, 15)} but f -> {mpmath.nstr(rows[1][0], 15)} at the origin"
        return None

    def p1(self):
        return self.jump("f") or self.jump("f1") or self.jump("f2")

    def p7(self):
        return self.jump("f22") or self.jump("f12") or self.p1()

    def kf_lower(self):
        """max |df/de2| over the samples, refined along its ray, at 50 digits
        and confirmed at 100: a lower bound of the true supremum."""
        A = np.abs(self.num.np("f2", self.X, self.Y))
        best = None
        for i in np.argsort(-np.where(np.isfinite(A), A, -1))[:3]:
            x, y = float(self.X[i]), float(self.Y[i])
            pt = self._refine(x, y)
            v = self.num.both("f2", *pt)
            with mpmath.workdps(100):       # abs() at the default 53 bits would round up by an ulp
                if v is not None and (best is None or abs(v) > best[0]):
                    best = (abs(v), pt)
        return best

    def _refine(self, x, y):
        r, th = math.hypot(x, y), math.atan2(y, x)
        if r == 0:
            return x, y
        with mpmath.workdps(50):
            c, s = mpmath.cos(th), mpmath.sin(th)

            def g(t):
                v = self.num.mp("f2", c * mpmath.exp(t), s * mpmath.exp(t), 50)
                return -abs(v) if v is not None else mpmath.mpf(0)
            a, b = mpmath.log(r) - mpmath.mpf("0.05"), mpmath.log(r) + mpmath.mpf("0.05")
            phi = (mpmath.sqrt(5) - 1) / 2
            for _ in range(60):
                m1, m2 = b - phi * (b - a), a + phi * (b - a)
                if g(m1) < g(m2):
                    b = m2
                else:
                    a = m1
            t = (a + b) / 2
            return (c * mpmath.exp(t), s * mpmath.exp(t)) if g(t) <= g(mpmath.log(r)) else (x, y)


def _bound(s):
    """A kf bound from the worker (Fraction text or srepr) at 100 digits."""
    if s is None:
        return None
    try:
        q = Fraction(s)
        return mpmath.mpf(q.numerator) / q.denominator
    except ValueError:
        return mpmath.mpf(str(sp.N(sp.sympify(s), 110)))


def check(case: Case, result: dict) -> list[Contradiction]:
    if result.get("hang"):
        return [Contradiction("-", "hang", "the verifier outlived its time limit by the hard margin")]
    if result.get("harness"):
        return [Contradiction("-", "harness error", result["harness"])]
    if result.get("crash"):
        return [Contradiction("-", "crash", result["crash"])]
    if "error" in result:
        return [Contradiction("-", "unusable", f"a valid design was rejected: {result['error']}")]
    out = []
    if result.get("certificate_error"):
        out.append(Contradiction("-", "certificate", f"the design certificate does not re-check: "
                                 f"{result['certificate_error'][:300]}"))
    ev = Evidence(case)
    searches = {"P1": ev.p1, "P2": ev.p2, "P3": ev.p3, "P4": ev.p4, "P5": ev.p5, "P6": ev.p6,
                "P7": ev.p7, "P8": ev.p8}
    for p in PROPS:
        status = result["properties"][p]["status"]
        truth = _p2_as_read(ev, case.truth.get(p)) if p == "P2" else case.truth.get(p)
        if status == "proved" and truth is not True:      # a true property needs no search
            found = searches[p]()
            if truth is False:
                out.append(Contradiction(p, "false proof", "false by construction (" + case.family + ": "
                                         + case.note + ")" + (f"; numeric: {found}" if found else "")))
            elif found:
                out.append(Contradiction(p, "false proof", found))
        elif status == "refuted" and truth is True:
            out.append(Contradiction(p, "wrong refutation", f"true by construction ({case.family}: {case.note}); "
                                     f"verifier: {result['properties'][p]['reason'][:300]}"))
        elif status == "refuted":
            bad = check_witness(ev, p, result["properties"][p])
            if bad:     # the verdict may be right (truth False or unknown); its evidence is not
                out.append(Contradiction(p, "bad witness", bad + ("" if truth is None else
                                                                   " (the property is false by construction)")))
    out += check_kf(case, result.get("kf"), ev)
    return out


def _p2_as_read(ev: Evidence, truth):
    """P2 for f as read, where f(0, 0) is an exact rational: the
    construction's truth assumes exact constants, but SymPy folds float
    constants while the grammar builds f (sqrt(1 + e1^2) - 1 + 0.30000000000000004
    (sqrt(1 + e2^2) - 1) has the constant -1.3, 53-bit -1 - 0.30000000000000004),
    so f(0, 0) as read is 1 + 0.30000000000000004 - 1.3 = 4e-17."""
    v = ev.num.fx.subs({e1: 0, e2: 0})
    return v == 0 if v.is_Rational else truth


def check_witness(ev: Evidence, prop: str, verdict: dict) -> str | None:
    """Re-check a refutation's witness point (when it names one) at 50 and
    100 digits: a description of why it is no counterexample, or None."""
    w, reason = verdict.get("witness"), verdict.get("reason", "")
    if prop == "P2":
        v = sp.N(ev.num.fx.subs({e1: 0, e2: 0}), 60)
        return f"f(0, 0) = 0 exactly, refuted with: {reason[:200]}" if v == 0 else None
    if not isinstance(w, dict) or "e1" not in w or "e2" not in w or "exist" in reason or "jump" in reason:
        return None
    try:
        x, y = sp.Rational(sp.sympify(w["e1"])), sp.Rational(sp.sympify(w["e2"]))
    except (TypeError, ValueError, sp.SympifyError):
        return None
    if prop == "P3" and "not positive" in reason:
        v = ev.num.both("f", x, y)
        if v is not None and v > mpmath.mpf("1e-40"):
            return f"witness ({x}, {y}) has f = {mpmath.nstr(v, 15)} > 0 (50 and 100 digits); verifier: {reason[:200]}"
    if prop in ("P5", "P6") and x != 0 and ("fails at" in reason or "< 0 at" in reason):
        v = ev.num.both("f1", x, y)
        if v is not None and v * sp.sign(x) > mpmath.mpf("1e-40"):
            return (f"witness ({x}, {y}) has df/de1 = {mpmath.nstr(v, 15)}, same sign as e1 (50 and 100 digits); "
                    f"verifier: {reason[:200]}")
    return None


def _mp_of(expr, dps=60):
    return mpmath.mpf(str(sp.N(exact(expr), dps)))


def check_kf(case: Case, kf: dict | None, ev: Evidence) -> list[Contradiction]:
    if kf is None:
        return []
    out = []
    with mpmath.workdps(100):
        lo_mp, hi_mp = _bound(kf["lower"]), _bound(kf["upper"])
        tol = mpmath.mpf("1e-40")
        if case.kf is not None and case.kf != sp.oo:
            true = _mp_of(case.kf)
            shown = placeholders(case.kf, sp.Float)
            if hi_mp is not None and true > hi_mp * (1 + tol):
                out.append(Contradiction("kf", "wrong kf", f"true kf = {shown} = {mpmath.nstr(true, 25)} "
                                         f"> certified upper bound {mpmath.nstr(hi_mp, 25)}"))
            if lo_mp is not None and true < lo_mp * (1 - tol):
                out.append(Contradiction("kf", "wrong kf", f"true kf = {shown} = {mpmath.nstr(true, 25)} "
                                         f"< certified lower bound {mpmath.nstr(lo_mp, 25)}"))
            if kf["exact"] is not None:
                claimed = mpmath.mpf(str(sp.N(sp.sympify(kf.get("exact_srepr") or kf["exact"]), 60)))
                if abs(claimed - true) > tol * true:
                    out.append(Contradiction("kf", "wrong kf", f"claimed exact kf = {kf['exact']} = "
                                             f"{mpmath.nstr(claimed, 25)}, true kf = {shown} = {mpmath.nstr(true, 25)}"))
            if kf["unbounded"]:
                out.append(Contradiction("kf", "wrong kf", f"claimed unbounded, true kf = {case.kf}"))
        if case.kf == sp.oo and hi_mp is not None:
            out.append(Contradiction("kf", "wrong kf", f"kf is infinite by construction ({case.note}), "
                                     f"certified upper bound {mpmath.nstr(hi_mp, 20)}"))
        if hi_mp is not None and not out:
            best = ev.kf_lower()
            if best is not None and best[0] > hi_mp * (1 + tol):
                pt = tuple(mpmath.nstr(c, 20) for c in best[1])
                out.append(Contradiction("kf", "wrong kf", f"|df/de2{pt}| = {mpmath.nstr(best[0], 25)} "
                                         f"(50 and 100 digits) > certified upper bound {mpmath.nstr(hi_mp, 25)}"))
    return out
