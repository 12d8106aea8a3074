"""Properties P1-P8 of f (Section 3 of the paper), each as a `Verdict`.

For a radial f = F(|e|) (P4 proved first) every property reduces to F on
[0, oo), split into pieces at Piecewise boundaries (see `profile`):

  P1  F, F' continuous on every piece and across every boundary, F'(0+) = 0
      (gradient continuous at the origin), and kf = sup |F'| finite
  P2  f(0, 0) = 0, by exact evaluation
  P3  F > 0 on (0, oo) and F -> oo as s -> oo
  P5  F' > 0 on (0, oo) (df/de1 = F'(s) e1/s), derivative existing everywhere
  P6  0 <= F'(s)/s <= k: k = sup F'/s, h = F'(s)/(k s)
  P7  F'' continuous on every piece and across every boundary, F''(0+) finite
  P8  F'(0+) = 0 and F' bounded near every point of (0, oo)

When f is not radial the verifier still refutes what it can with certified
witnesses (P2 exactly; P3, P5, P6 at points of half-lines through the axes
and diagonals, P6 on e1 = 0 and where df/de1 / e1 is unbounded, P8 by a
limit of df/de2; limits along rays via the limit calculus) and says
"unknown" for the rest."""
from __future__ import annotations

import functools
import math
from dataclasses import replace
from fractions import Fraction
from functools import cached_property

import mpmath
import sympy as sp

from . import e1 as E1, e2 as E2
from .design import Design
from .design_certificate import (_JUMPS, SMOOTH_ONLY, H, CertificateError, along_ray, at_point, axis_split,
                                 branch_profile, crossing_parts, e1_sides,
                                 half_axes, relations_defined)
from .interval import Interval, IntervalFunction, Undefined
from .certify import (REDUCTION, SPENT, WORK, NoProof, continuity_pair, exploring, growth_theorems,
                      one_branch_theorems, origin_theorems, origin_value_theorems, piecewise_sign_theorem,
                      plane_theorems, radial_theorems, refutation_theorems, separable_theorems, sign_theorems,
                      smoothness_theorems, sup_upper_theorem)
from .kernel import core as K
from .kernel import arb as kernel_arb
from .kernel.core import derivative
from .kf import (KfCertificate, certify_kf, certify_sup, decimal_beyond, exact_text, psi_sides, scale, show,
                 show_interval)
from .limits import NoLimit, limit_right
from .profile import (RHO, S, continuous_on, elliptic_ratio, float_of, one_sided_value,
                      radial_profile,
                      same_value, split_profile, verify_radial)
from .univariate import (MAX_BOXES, T, X, enclose, exact_sign, exact_value, far_out_trend, limit_at_infinity, prepare,
                         prove_sign, tail_form, tail_start, value_at)
from .verdict import PROPERTIES, Verdict, proved, refuted, unknown  # noqa: F401 (PROPERTIES re-exported)


def _at(s_value):
    """The witness point (s, 0) of the plane for a radius s."""
    return {"e1": str(s_value), "e2": "0", "e1_float": float_of(s_value)}


def _on_e2_axis(v: Verdict, ratio) -> Verdict:
    """P7's refutation with its witness (s, 0) moved to the point (0, e2) of
    the same circle: on the e2 axis d2f/de2^2 is F''(s), while at (s, 0) it
    is F'(s)/s, continuous where F' is, so a jump or singularity of F'' at
    s shows there only (red team 29).  "jump": "e2" tells the proposer that
    f or a derivative in e2 jumps there (`certify._witness_candidates`)."""
    w = v.witness if isinstance(v.witness, dict) else {}
    if w.get("e2") != "0" or w.get("e1") in (None, "0") or "e1_float" not in w:
        return v
    y = sp.sympify(w["e1"]) / sp.sqrt(ratio)
    moved = {k: x for k, x in w.items() if k not in ("e1", "e2", "e1_float")}
    return replace(v, witness={"e1": "0", "e2": str(y), "e2_float": float_of(y), "jump": "e2", **moved})


class Analysis:
    """Everything the properties share for one design, computed once."""

    def __init__(self, design: Design):
        self.design = design
        self.f = design.f
        self._derivatives: dict = {}

    # ---- radial reduction -------------------------------------------------
    @cached_property
    def F(self):
        return radial_profile(self.f)

    @cached_property
    def p4(self) -> Verdict:
        return verify_radial(self.f, self.F)

    @cached_property
    def ratio(self):
        """r with f(e1, e2) = F(sqrt(e1^2 + r e2^2)) proved: 1 for a radial f,
        another r > 0 for an elliptic one (P4 then fails, but the other
        properties still reduce to F), None when neither is shown."""
        if self.p4.proved:
            return sp.Integer(1)
        return elliptic_ratio(self.f, self.F)

    @property
    def reduced(self) -> bool:
        return self.ratio is not None

    @property
    def radius(self):
        """The s of the reduction, in e1 and e2."""
        return sp.sqrt(E1 ** 2 + self.ratio * E2 ** 2)

    @cached_property
    def split(self):
        if not self.reduced:
            return None, unknown("f is not known to be radial")
        return split_profile(self.F)

    @property
    def profile(self):
        return self.split[0]

    def derivative(self, expr, k):
        """d^k expr/ds^k, prepared; memoised (each piece's F' and F'' are asked
        for by several properties: 128 times for a chain of 16 joins).  One
        order at a time: SymPy's diff(expr, s, 2) of the chain's last piece
        takes 0.4 s, the derivative of its prepared F' 2 ms."""
        if not k:
            return expr
        if (expr, k) not in self._derivatives:
            self._derivatives[expr, k] = prepare(derivative(self.derivative(expr, k - 1), S))
        return self._derivatives[expr, k]

    # ---- continuity facts (order k = 0, 1, 2) -----------------------------
    def _piece_continuity(self, k) -> Verdict:
        for piece in self.profile.pieces:
            v = continuous_on(self.derivative(piece.expr, k), piece.lo, piece.hi, closed=False)
            if v.refuted:
                return refuted(f"F{'′' * k} is singular at s = {v.witness}: {v.reason}",
                               _at(v.witness))
            if not v.proved:
                return unknown(f"continuity of F{'′' * k} on ({piece.lo}, {piece.hi}): {v.reason}")
        return proved(f"F{'′' * k} continuous on every piece")

    def _boundary_match(self, k) -> Verdict:
        """F^(k) has equal one-sided limits at every boundary (and, for k = 0,
        equal to F's value there)."""
        pieces = self.profile.pieces
        for left, right in zip(pieces, pieces[1:]):
            b = right.lo
            lv = one_sided_value(self.derivative(left.expr, k), b, -1)
            rv = one_sided_value(self.derivative(right.expr, k), b, +1)
            name = "F" + "′" * k
            if lv in (sp.oo, -sp.oo) or rv in (sp.oo, -sp.oo):
                return refuted(f"{name} is unbounded near s = {b} (|e| = {float_of(b):.6g}): left limit "
                               f"{_show(lv)}, right limit {_show(rv)}",
                               {**_at(b), "left": _show(lv), "right": _show(rv)})
            values = [lv, rv]
            if k == 0:
                values.append(exact_value(self.profile.at_point[b], S, b))
            verdicts = [same_value(values[0], v) for v in values[1:]]
            if all(verdicts):
                continue
            if False in verdicts:
                return refuted(
                    f"{name} jumps at s = {b} (|e| = {float_of(b):.6g}): left limit {_show(lv)}, right limit "
                    f"{_show(rv)}" + ("" if k else f", value {_show(values[2])}"),
                    {**_at(b), "left": _show(lv), "right": _show(rv)})
            return unknown(f"cannot compare the one-sided limits of {name} at s = {b}")
        return proved("no jumps at the boundaries")

    @cached_property
    def dF0(self):
        """F'(0+): the limit of |grad f| at the origin; the literal 0 when it
        is 0 in disguise (log 6 - log 2 - log 3), None when neither 0 nor
        signed (`exact_sign`): a refutation needs a value shown nonzero."""
        d = one_sided_value(self.derivative(self.profile.pieces[0].expr, 1), 0, +1)
        if d is None or d == 0 or not d.is_number or d in (sp.oo, -sp.oo):    # (is_finite may be None: undecided)
            return d
        sign = exact_sign(d)
        return sp.Integer(0) if sign == 0 else None if sign is None else d

    @cached_property
    def d2F0(self):
        return one_sided_value(self.derivative(self.profile.pieces[0].expr, 2), 0, +1)

    def _origin_value(self) -> Verdict:
        """f(0, 0) = F(0) equals the limit F(0+): f is continuous at the origin."""
        value = exact_value(self.profile.at_point[sp.Integer(0)], S, 0)
        lim = one_sided_value(self.profile.pieces[0].expr, 0, +1)
        same = same_value(value, lim)
        if same:
            return proved(f"f(0, 0) = F(0+) = {lim}")
        if same is False:
            return refuted(f"f is not continuous at the origin: f(0, 0) = {_show(value)} but "
                           f"f(e) -> {_show(lim)} as e -> 0", {"e1": "0", "e2": "0", "f": _show(value),
                                                                "limit": _show(lim)})
        return unknown(f"cannot compare f(0, 0) = {_show(value)} with the limit F(0+) = {_show(lim)}")

    @cached_property
    def c0(self):
        return self._piece_continuity(0), self._boundary_match(0), self._origin_value()

    @cached_property
    def gradient_exists(self) -> Verdict:
        """grad f exists everywhere: F continuous, F' without jumps, F'(0+) = 0."""
        return _all([*self.c0, self._boundary_match(1), self._origin_gradient()],
                    "F continuous, F' without jumps, F'(0+) = 0")

    @cached_property
    def c1(self) -> Verdict:
        """f is C^1 on R^2."""
        parts = [*self.c0, self._piece_continuity(1), self._boundary_match(1), self._origin_gradient()]
        return _all(parts, "f is C^1: F, F' continuous on each piece, no jumps, grad f(0) = 0")

    def _origin_gradient(self) -> Verdict:
        d = self.dF0
        if d is None:
            return unknown("cannot compute F'(0+)")
        if d == 0:
            return proved("F'(0+) = 0")
        return refuted(
            f"the gradient is not continuous at the origin: df/de2(0, h) -> {_show(d)} as h -> 0+ "
            f"but -> {_show(-d)} as h -> 0- (F'(0+) = {_show(d)})",
            {"e1": "0", "e2": "0", "F'(0+)": _show(d)})

    @cached_property
    def c2(self) -> Verdict:
        parts = [self.c1, self._piece_continuity(2), self._boundary_match(2)]
        d2 = self.d2F0
        if d2 is None:
            parts.append(unknown("cannot compute F''(0+)"))
        elif d2 in (sp.oo, -sp.oo):
            parts.append(refuted(
                f"d2f/de2^2 (0, h) = F''(h) -> {_show(d2)} as h -> 0+: not continuous at the origin",
                {"e1": "0", "e2": "h -> 0+", "limit": _show(d2)}))
        else:
            parts.append(proved(f"F''(0+) = {_show(d2)} = lim F'(s)/s"))
        return _all(parts, "f is C^2: F'' continuous on each piece, no jumps, F''(0+) finite")

    @cached_property
    def p5(self) -> Verdict:
        """P5, decided once: P6 needs it too."""
        return verify_p5(self)

    @cached_property
    def slope_sign(self):
        """F' > 0 on (0, oo) as a kernel theorem, else F' >= 0 (zeros on
        circles: enough for P1 and P6), else None; for an F of one formula.
        F' > 0 (P5's lemma, which P1, P6 and kf use too) gets twice a lemma's
        work when a lemma's runs out (2 - 2 log(1 + s^2)/s^2: 0/0 at 0)."""
        dF = derivative(self.kernel_F, S)
        positive, why = sign_theorems(dF, S, 0, sp.oo)
        if positive is None and why == SPENT:
            positive = sign_theorems(dF, S, 0, sp.oo, work=2 * WORK)[0]
        return (positive or sign_theorems(dF, S, 0, sp.oo, strict=False)[0] or [None])[0]

    @cached_property
    def slope_theorem(self):
        """F' > 0 on (0, oo) (one formula: else F' >= 0) as one kernel
        theorem, or None: when there is one, the search need not show F' >= 0."""
        if _single_formula(self) is not None:
            return self.slope_sign
        return piecewise_sign_theorem(derivative(self.F, S), self.profile.ends, S)[0]

    @cached_property
    def open_branch(self):
        """(G, kernel theorems F = G on (0, oo), and F(0) = G(0) if so) when
        the Piecewise profile follows one branch G at every s > 0 and the
        search's profile is that G too; else (F, []).  P3 and P8 see s > 0
        only, so F = G on (0, oo) is enough for them."""
        if self.profile is None or len(self.profile.pieces) != 1:
            return self.F, []
        from .design_certificate import _profile      # the F the certificate's links read
        G, theorems = one_branch_theorems(_profile(self.f), S)
        return (G, theorems) if theorems and G == self.profile.pieces[0].expr else (self.F, [])

    @cached_property
    def one_branch(self):
        """`open_branch` when F(0) = G(0) too: then F = G on [0, oo) and every
        property's lemmas are about G; else (F, [])."""
        G, theorems = self.open_branch
        return (G, theorems) if len(theorems) > 1 else (self.F, [])

    @property
    def kernel_F(self):
        """The profile the kernel's lemmas are about (`one_branch`)."""
        return self.one_branch[0]

    @cached_property
    def reduction(self) -> list:
        """The kernel's theorems of an elliptic reduction (r != 1): f(e1, e2)
        = F(sqrt(e1^2 + r e2^2)) and r > 0; [] when r = 1 (P4 carries it) or
        the kernel refuses."""
        return radial_theorems(self.f, self.F, E1, E2, S, self.ratio) if self.reduced and self.ratio != 1 else []

    @cached_property
    def kf(self) -> KfCertificate:
        """kf = sqrt(r) sup|F'|: |df/de2| = r |e2| |F'(s)|/s <= sqrt(r) |F'(s)|,
        with equality on e1 = 0.  For r != 1 the kernel's theorems about F'
        follow those of the reduction."""
        cert = certify_kf(self)
        scaled = scale(cert, sp.sqrt(self.ratio))
        scaled.kernel = self.reduction + self.one_branch[1] + cert.kernel \
            if cert.kernel and (self.ratio == 1 or self.reduction) else []
        scaled.unchecked = ([] if scaled.kernel and self.reduction else [REDUCTION]) + cert.unchecked
        return scaled


def _show(v):
    return "undecided" if v is None else str(v)


def _short(v) -> str:
    """An exact constant as written, or 8 digits of it when that runs past
    60 characters (the witness keeps it exactly): from an Arb enclosure whose
    ends agree to 8 digits, at up to 32,768 bits (SymPy's evalf gave
    -1.0E-400 for log(1 + 10^-400) - 10^-400 + 10^-800/2 - 10^-1200/3, which
    is -2.5E-1601)."""
    text = str(v)
    for bits in kernel_arb.SIGN_BITS if len(text) > 60 else ():
        try:
            iv = kernel_arb.evaluate(v, bits=bits)
        except (kernel_arb.Undefined, TypeError, ValueError):
            break
        lo, hi = (x.str(8, radius=False) for x in (iv.lo, iv.hi))
        if lo == hi and not lo.startswith("0e"):
            return f"{lo} (8 digits)"
    return text


def _lemmas(v: Verdict, lemma: Verdict, unchecked: str, extra=None) -> Verdict:
    """v with the kernel theorems of `lemma` and the facts still resting on
    the search alone: the radial reduction (P4) and `unchecked` -- unless
    `extra`, the proposer for that fact, gives kernel theorems for it."""
    # a side fact's theorems (lemma is not v) only beside the main lemma's: alone
    # they are not the claim the property's link expects first (P3, P5)
    found = extra() if extra is not None and (lemma is v or lemma.details.get("kernel")) else []
    v.details["kernel"] = lemma.details.get("kernel", []) + found
    v.details["unchecked"] = [REDUCTION, *lemma.details.get("unchecked", []), *([] if found else [unchecked])]
    return v


def _single_formula(a: Analysis):
    """F when the profile is one formula on (0, oo) (no Piecewise), else None."""
    return a.kernel_F if len(a.profile.pieces) == 1 and not a.kernel_F.has(sp.Piecewise) else None


def _all(parts, what) -> Verdict:
    for v in parts:
        if v.refuted:
            return v
    for v in parts:
        if not v.proved:
            return v
    return proved(what)


# --------------------------------------------------------------------------
# the properties

def verify_p2(a: Analysis) -> Verdict:
    """P2: f(0, 0) = 0, by exact evaluation."""
    v = at_point(a.f, (0, 0))
    if v.has(sp.Piecewise) or v.free_symbols:
        return unknown("cannot evaluate f at the origin exactly")
    sgn = exact_sign(v)
    if sgn == 0:
        return proved("f(0, 0) = 0 exactly", kernel=origin_value_theorems(v), unchecked=[])
    if sgn is None and v.has(sp.nan):   # (at_point: a condition read before the branch has no sign the kernel decides)
        return unknown("cannot read f at the origin: a condition of f there, or a part of f, has no value or sign "
                       "that the kernel decides")
    if sgn is None:
        return unknown(f"cannot decide whether f(0, 0) = {v} is zero")
    return refuted(f"f(0, 0) = {_short(v)} != 0", {"e1": "0", "e2": "0", "f": str(v)})


def verify_p4(a: Analysis) -> Verdict:
    """P4: e1 df/de2 = e2 df/de1 (radial symmetry)."""
    v = a.p4
    if v.proved:
        theorems = radial_theorems(a.f, a.F, E1, E2, S)
        v.details.update(kernel=theorems, unchecked=[] if theorems else [
            "f(e1, e2) = F(sqrt(e1^2 + e2^2)) at every point of the plane (the kernel did not accept the "
            "identity, or did not show f defined everywhere)"])
    return v


def _needs_profile(a: Analysis, name: str) -> Verdict | None:
    if not a.reduced:
        return _non_radial(a, name)
    if a.profile is None:
        return _switch_on_the_axis(a.f, name) or unknown(f"radial, but {a.split[1].reason}")
    return None


def _switch_on_the_axis(f, name: str) -> Verdict | None:
    """P1, P5, P6 (P7) of f = Piecewise((A, l < r), (B, True)) (a Max or a
    Min) whose condition switches on the e1 (e2) axis where SymPy finds no
    exact point (log(1 + rho) = rho/2): the kernel's crossing witness on a
    bracket of each switch (`_switches`)."""
    if name not in ("P1", "P5", "P6", "P7"):
        return None
    c, other = ("e2", "e1") if name == "P7" else ("e1", "e2")
    for near, q1, q2 in _switches(f, c):
        found = refuted(f"df/d{c} does not exist on the {c} axis at {c} = {near}, in [{q1}, {q2}], where "
                        f"{f.args[0][1]} switches: the two branches meet there at an angle or a step",
                        {c: near, other: "0", "crossing": [str(q1), str(q2)]})
        if refutation_theorems(name, found, f)[0] is not None:
            return found
    return None


@functools.lru_cache(maxsize=16)
def _switches(f, v: str) -> tuple:
    """(c to 12 digits, q1, q2) for the first three sign changes of r - l
    along the v axis, f = Piecewise((A, l < r), (B, True)): found on a grid of
    [10^-4, 10^8], narrowed by bisection in 30-digit mpmath, bracketed by
    rationals q1 < c < q2 about 2^-30 apart (relative to c above 1)."""
    try:
        g = sp.lambdify(H, crossing_parts(f, 0, E2 if v == "e2" else E1)[0], modules="mpmath")
    except (CertificateError, TypeError, ValueError):
        return ()

    def sign(t):
        try:
            value = g(t)
        except (ValueError, ZeroDivisionError, TypeError, OverflowError):
            return 0
        return int(mpmath.sign(value)) if isinstance(value, mpmath.mpf) else 0
    out = []
    with mpmath.workdps(30):
        grid = [mpmath.mpf(10) ** (mpmath.mpf(k) / 60 - 4) for k in range(721)]
        signs = [sign(t) for t in grid]
        for a, b in [(a, b) for a, b, sa, sb in zip(grid, grid[1:], signs, signs[1:]) if sa * sb == -1][:3]:
            sa = sign(a)
            for _ in range(80):
                m = (a + b) / 2
                a, b = (m, b) if sign(m) == sa else (a, m)
            scale = 2 ** (30 - max(0, int(mpmath.floor(mpmath.log(b, 2)))))
            q1, q2 = (sp.Rational(int(x), scale) for x in (mpmath.floor(a * scale), mpmath.ceil(b * scale)))
            if 0 < q1 < q2:
                out.append((mpmath.nstr(a, 12), q1, q2))
    return tuple(out)


def verify_p1(a: Analysis) -> Verdict:
    """P1: df/de1, df/de2 exist and are continuous; kf = sup|df/de2| finite."""
    early = _needs_profile(a, "P1")
    if early:
        return early
    c1 = a.c1
    if c1.refuted:
        return c1
    kf = a.kf
    if kf.unbounded_witness is not None:
        return refuted(f"kf is infinite: {kf.reason}", kf.unbounded_witness)
    if not c1.proved:
        return c1
    if kf.upper is None:
        return unknown(f"C^1 proved, but no finite bound on |df/de2| found: {kf.reason}")
    v = proved(f"{c1.reason}; kf = sup|F'| in {show_interval(kf.lower, kf.upper, 9)}")
    if kf.kernel:
        # F' > 0 and F' <= c on (0, oo) (`certify.sup_theorems`), or |F'| <= c (`certify.sup_abs_theorems`)
        own = kf.kernel[len(a.reduction) + len(a.one_branch[1]):]
        bound = (own[:1], own[1]) if own[0].claim.kind == "sign" else ([], own[0])
    else:       # P1 needs some finite bound only: F' >= 0 and F' <= U, U about 1/8 above the enclosure of kf
        bound = _p1_bound(a, decimal_beyond(Fraction(kf.upper) * Fraction(9, 8), 1, 2))
        if bound is None:
            return _lemmas(v, v, "f is C^1 with kf finite (continuity and the bound are the search's)")
    signed, upper = bound
    return _lemmas(v, v, "f is C^1 (continuity at the origin)",     # (Piecewise: F, F' continuous at the end)
                   lambda: [*signed, *origin[:2], upper, *origin[2:]]
                   if (origin := origin_theorems(a.kernel_F, S, a.profile.ends)) else [])


def _p1_bound(a: Analysis, U):
    """([F' >= 0], F' <= U) on (0, oo) as kernel theorems for a profile
    that is one formula, or None."""
    F = _single_formula(a)
    if F is None:
        return None
    positive = a.slope_sign
    upper = sup_upper_theorem(derivative(F, S), U, S) if positive else None
    return ([positive], upper) if upper else None


def _positive_on_pieces(a: Analysis, k: int, what: str) -> Verdict:
    """F^(k) > 0 on every open piece and at every boundary point: the
    kernel's theorems when they cover it all, else the search."""
    prof = a.profile
    found = _piece_theorems(a, k, what) if _sampled_positive(a, k) else {"kernel": []}
    if len(found["kernel"]) == 1 and not found["unchecked"]:
        c = found["kernel"][0].claim        # (the proposer may return a weaker claim than it was asked for)
        if (c.want, c.strict, c.lo, c.hi, c.lo_open) == (1, True, "Integer(0)", "oo", True):
            return proved(f"{what} on (0, oo) (the kernel's sign rules)", **found)
    for piece in prof.pieces:
        v = prove_sign(a.derivative(piece.expr, k), S, piece.lo, piece.hi, want=1, lo_open=True, hi_open=True)
        if v.refuted:
            return refuted(f"{what} fails at |e| = {v.witness}: {v.reason}", _at(v.witness))
        if not v.proved:
            return unknown(f"{what} on ({piece.lo}, {piece.hi}): {v.reason}")
    for b in prof.boundaries:
        e = a.derivative(prof.at_point[b], k) if k == 0 else a.derivative(
            next(p.expr for p in prof.pieces if p.lo == b), k)
        val = one_sided_value(e, b, +1)
        sgn = None if val is None else (1 if val == sp.oo else exact_sign(val))
        if sgn is None:
            return unknown(f"cannot decide the sign of {what} at the boundary s = {b}")
        if sgn <= 0:
            return refuted(f"{what} fails at the boundary |e| = {b} (value {val})", _at(b))
    return proved(f"{what} on (0, oo) (interval arithmetic, s = 1/t on the tail, Taylor at zeros)",
                  **_piece_theorems(a, k, what))


def _sampled_positive(a: Analysis, k: int, points: int = 8) -> bool:
    """F^(k) > 0 at `points` inner points of every piece (Arb, 64 bits, or
    256 where 64 cancel to nothing: 1 - tanh(4 s^2)^2 at s = 3; an unbounded
    piece sampled up to `tail_start`): only then is the kernel asked first."""
    for p in a.profile.pieces:
        e, hi = a.derivative(p.expr, k), p.hi if p.hi != sp.oo else tail_start(p.lo)
        for j in range(1, points + 1):
            x = p.lo + (hi - p.lo) * sp.Rational(j, points + 1)
            try:
                if not any(value_at(e, S, x, prec=bits).is_positive() for bits in (64, 256)):
                    return False
            except Undefined:
                return False
    return True


def _derivative(e, k: int):
    """The k-th derivative in s, as the kernel takes it (one order at a time)."""
    for _ in range(k):
        e = derivative(e, S)
    return e


def _piece_theorems(a: Analysis, k: int, what: str) -> dict:
    """The kernel's part of `_positive_on_pieces`: one theorem about the
    Piecewise F^(k) on (0, oo) when the kernel takes it, else one per piece
    with the boundaries left to the search."""
    prof = a.profile
    if len(prof.pieces) > 1:
        whole, _ = piecewise_sign_theorem(_derivative(a.F, k), a.profile.ends, S)
        if whole is not None and whole.claim.strict:
            return {"kernel": [whole], "unchecked": []}
    kernel, unchecked = [], []
    for piece in prof.pieces:
        theorems, gap = sign_theorems(_derivative(piece.expr, k), S, piece.lo, piece.hi)
        if theorems is not None and not all(t.claim.want == 1 and t.claim.strict for t in theorems):
            theorems, gap = None, "only F^(k) >= 0"      # (the proposer may return a weaker claim than asked)
        kernel += theorems or []
        if theorems is None:
            unchecked.append(f"{what} on ({piece.lo}, {piece.hi}) (kernel: {gap})")
    return {"kernel": kernel,
            "unchecked": unchecked + [f"{what} at the boundary s = {b} (one-sided limit)" for b in prof.boundaries]}


def verify_p3(a: Analysis) -> Verdict:
    """P3: f > 0 away from the origin, and f radially unbounded."""
    early = _needs_profile(a, "P3")
    if early:
        return early
    pos = _positive_on_pieces(a, 0, "F(s) > 0")
    if pos.refuted:
        return refuted(f"f is not positive: {pos.reason}", pos.witness)
    if not pos.proved and (found := _negative_near_origin(a.f, one_sided_value(a.profile.pieces[0].expr, 0, +1))):
        return found
    defined = a.c0[0]       # F continuous, so defined, on every open piece
    if not defined.proved:
        return unknown(f"f may be undefined somewhere: {defined.reason}")
    last = a.profile.pieces[-1]
    if pos.proved and far_out_trend(last.expr, S) > 0 and (growth := _growth(a)):     # the kernel's, no limit needed
        return _lemmas(proved(f"{pos.reason}; F(s) -> oo as s -> oo (the kernel's divergence rules)"), pos,
                       "F(s) -> oo as s -> oo", lambda: growth)
    try:
        lim = limit_at_infinity(last.expr, S)
    except NoLimit as exc:
        growth = _grows_without_bound(a.derivative(last.expr, 1), last.lo)
        if growth is None and (bound := _bounded_above(a.f)) is not None:
            return refuted(f"f is not radially unbounded: f(h, 0) <= {bound} for all h > 0 (the kernel's sign "
                           "rules)", {"direction": "every", "bound": str(bound)})
        if growth is None:
            return unknown(f"{pos.reason}; cannot decide whether f -> oo ({exc})")
        if not pos.proved:
            return pos
        return _lemmas(proved(f"{pos.reason}; {growth}"), pos, "F(s) -> oo as s -> oo (growth of F')",
                       lambda: _growth(a))
    if lim != sp.oo:
        return refuted(f"f is not radially unbounded: f(e) -> {lim} as |e| -> oo in every direction "
                       "(limit calculus on F(1/t), t -> 0+)",
                       {"direction": "every", "limit": str(lim)})
    if not pos.proved:
        return pos
    return _lemmas(proved(f"{pos.reason}; F(s) -> oo as s -> oo (limit calculus on F(1/t))"), pos,
                   "F(s) -> oo as s -> oo (limit calculus)", lambda: _growth(a))


def _negative_near_origin(f, L) -> Verdict | None:
    """P3 where f tends to L < 0 at the origin (F(0+) of a radial f, else
    f(0, 0)), however small (log(1 + rho) - 10^-400, or - exp(-10^4)): the
    kernel's `value` witness at (s, 0) for s = |L|/2^j (a corner at 0) or
    sqrt(|L|)/2^j (a smooth minimum), exact expressions such as
    exp(-5000)/2, whose sign Arb decides with up to 32,768 bits."""
    if L is None or not L.is_number or L.has(sp.nan, sp.zoo, sp.oo, -sp.oo) or exact_sign(L) != -1:
        return None
    for s in (sp.sqrt(-L) / 2, -L / 2, sp.sqrt(-L) / 16, -L / 16):
        found = refuted(f"f is not positive: f(s, 0) < 0 for s = {_short(s)}, near the origin, where f tends to "
                        f"{_short(L)} < 0", {"e1": str(s), "e2": "0"})
        if refutation_theorems("P3", found, f)[0] is not None:
            return found
    return None


def _bounded_above(f):
    """M with f(h, 0) <= M for every h > 0 as a kernel theorem (the witness
    "bounded" of P3's refutation proves it again, from the lemma cache), M
    the integer above f's largest value at h = 1, 16, ..., 2^60 (256-bit
    Arb; f's limit at oo may be beyond the limit calculus: log(1 + s^2)/(1 +
    log(1 + s^2))); None when not shown."""
    ray = along_ray(f, (1, 0))
    try:
        top = max(value_at(ray, H, 2 ** k, prec=256).upper_float() for k in range(0, 64, 4))
    except (Undefined, ValueError, OverflowError):
        return None
    if not math.isfinite(top) or top > 1e6:
        return None
    bound = sp.Integer(math.floor(top)) + 1
    return bound if sup_upper_theorem(ray, bound, H, work=2 * WORK) is not None else None


def _growth(a: Analysis) -> list:
    if len(a.profile.pieces) > 1:
        return growth_theorems(a.F, S, a.profile.pieces[-1].lo)
    F = a.open_branch[0]
    return growth_theorems(F, S) if not F.has(sp.Piecewise) else []


def _grows_without_bound(dF, lo) -> str | None:
    """F -> oo from a lower bound c > 0 on F' (F >= F(R) + c (s - R)) or on
    s F' (F >= F(R) + c log(s/R)) over [R, oo), by interval arithmetic on the
    t-form; a description of the argument, or None."""
    R = tail_start(lo)
    for rate, what in ((dF, "F' >= {c} on [{R}, oo), so F grows at least linearly"),
                       (S * dF, "s F'(s) >= {c} on [{R}, oo), so F grows at least like log s")):
        try:
            box = enclose(tail_form(rate, S), T, 0, 1 / R)
        except Undefined:
            continue
        if box.is_positive():
            return what.format(c=f"{box.lower_float():.6g}", R=R)
    return None


def verify_p5(a: Analysis) -> Verdict:
    """P5: (df/de1) tanh(e1) > 0 for e1 != 0, = 0 for e1 = 0."""
    early = _needs_profile(a, "P5")
    if early:
        return early
    exists = a.gradient_exists
    if exists.refuted:
        return refuted(f"df/de1 does not exist everywhere: {exists.reason}", exists.witness)
    pos = _positive_on_pieces(a, 1, "F'(s) > 0")
    if not pos.proved:
        return pos
    if not exists.proved:
        return unknown(f"{pos.reason}, but {exists.reason}")
    return _lemmas(proved(f"df/de1 tanh(e1) = F'(s) e1 tanh(e1)/s with {pos.reason}; "
                          "df/de1 = 0 on e1 = 0 (F'(0+) = 0 at the origin)"), pos,
                   "df/de1 exists on R^2 (F'(0+) = 0 at the origin)",
                   lambda: origin_theorems(a.kernel_F, S, a.profile.ends))


def verify_p6(a: Analysis) -> Verdict:
    """P6: df/de1 = k e1 h(e1, e2), k > 0 constant, 0 <= h <= 1."""
    early = _needs_profile(a, "P6")
    if early:
        return early
    p5 = a.p5
    exists = a.gradient_exists
    if exists.refuted:
        return refuted(f"df/de1 does not exist everywhere: {exists.reason}", exists.witness)
    if not p5.proved:
        # h >= 0 needs F' >= 0; a point with F' < 0 refutes P6 for every k > 0
        for p in a.profile.pieces:
            v = prove_sign(a.derivative(p.expr, 1), S, p.lo, p.hi, want=1, strict=False)
            if v.refuted:
                return refuted(f"h = F'(s)/(k s) < 0 at |e| = {v.witness} for every k > 0", _at(v.witness))
            if not v.proved:
                return unknown(f"the sign of h = F'(s)/(k s) is undecided: {v.reason}")
    G = [sp.together(a.derivative(p.expr, 1) / S) if not p.expr.has(sp.Function) else
         a.derivative(p.expr, 1) / S for p in a.profile.pieces]
    g0 = one_sided_value(G[0], 0, +1)
    if g0 in (sp.oo,):
        return refuted("F'(s)/s -> oo as s -> 0+, so no constant k bounds h = F'(s)/(k s) by 1",
                       {"e1": "h -> 0+", "e2": "0", "limit": "oo"})
    sup = certify_sup(a, G, "F'(s)/s", near_zero=a.derivative(a.profile.pieces[0].expr, 2),
                      bound_by=lambda c: bool(_p6_theorems(a, c, exact=True)))
    if sup.unbounded_witness is not None:
        return refuted(f"no constant k bounds h = F'(s)/(k s) by 1: {sup.reason}", sup.unbounded_witness)
    if sup.upper is None:
        return unknown(f"no finite bound for F'(s)/s found: {sup.reason}")
    if not exists.proved:
        return unknown(f"k = {sup.show()}, but {exists.reason}")
    k = sup.exact if sup.exact is not None else decimal_beyond(sup.upper, 1, 7)
    if not k > 0:       # F' >= 0 and F'(s)/s <= 0: F' = 0, and h = 0 serves with any k > 0
        k = sp.Integer(1)
    # the kernel needs some k: the exact sup, else (or when that bound has no room) one about 1/8 above it;
    # the report gives the k whose h <= 1 the kernel checked, and the search's sup beside it
    loose = decimal_beyond(Fraction(sup.upper if sup.exact is not None else k) * Fraction(9, 8), 1, 2)
    tries = [(k, True), (loose, False)] if sup.exact is not None else [(loose, False)]
    checked, theorems = next(((c, th) for c, exact in tries for th in [_p6_theorems(a, c, exact)] if th), (k, []))
    smallest = f"sup F'(s)/s = {sup.show()}" + ("" if checked == k else
                                                 f"; the kernel checks F'(s)/s <= {exact_text(checked)}")
    k = checked
    h = a.derivative(a.kernel_F, 1) / (k * S)    # F = G on [0, oo) (`one_branch`): G' is F' also at a point value
    # for the report only: simplify takes seconds on a large h (and expand multiplies it out)
    h = (sp.simplify(h) if sp.count_ops(h) <= 40 else h).subs(S, a.radius)
    shown = exact_text(h) if len(exact_text(h)) <= 400 else f"F'(s)/(k s), s = |e| ({sp.count_ops(h)} operations; in the JSON report)"
    v = proved(f"k = {exact_text(k)} ({smallest}), h = F'(s)/(k s) in [0, 1]: h(e1, e2) = {shown}",
               k=str(k), k_float=float_of(k), h=str(h))
    # df/de1 at the origin: F, F' continuous at 0+ with F'(0+) = 0 (P5's lemmas; for a Piecewise F
    # they end with the continuity on (0, oo) that `_piecewise_p6` gave)
    origin = origin_theorems(a.kernel_F, S, a.profile.ends) if theorems else []
    return _lemmas(v, v, "0 <= h <= 1 (the bound of F'(s)/s is the search's)",
                   lambda: theorems[:2] + origin if origin else theorems)


def _p6_theorems(a: Analysis, k, exact=False) -> list:
    """F' >= 0 (so h >= 0) and F'(s)/s <= k (so h <= 1), both on (0, oo).
    P6 asks for some constant k: when the search only encloses sup F'(s)/s,
    the kernel is asked for a k about 1/8 above it (a bound with no room
    would need a cover of ever finer boxes near the maximum).  `exact`: k is
    the sup itself, a bound with no room that a looser k can replace, so its
    lemmas spend a pool of their own (`certify.exploring`; k = 4/sqrt(pi) +
    2, reached only as s -> 0 in erf(rho) + atan(rho), spent the whole budget
    of the design and left none to the looser k)."""
    if exact:
        with exploring("exact"):
            return _p6_theorems(a, k)
    F = _single_formula(a)
    if F is None:
        return _piecewise_p6(a, k)
    positive = a.slope_sign         # h >= 0
    return [positive, upper] if positive and (upper := sup_upper_theorem(derivative(F, S) / S, k, S)) else []




def _piecewise_p6(a: Analysis, k) -> list:
    """`_p6_theorems` for a Piecewise F: F' > 0 and k - F'/s >= 0 through
    its branches, then F and F' continuous on (0, oo)."""
    dF, ends = derivative(a.F, S), a.profile.ends
    positive, _ = piecewise_sign_theorem(dF, ends, S)
    # (k - F'/s on each piece: a quotient by s, with 1/8 of room, took up to twice the default work of a lemma)
    gap, _ = piecewise_sign_theorem(k - dF / S, ends, S, strict=False, work=6 * WORK) if positive else (None, "")
    upper = sup_upper_theorem(dF / S, k, S, gap) if gap else None
    try:
        return [positive, upper, *continuity_pair(a.F, S, ends)] if upper else []
    except NoProof:
        return []


def verify_p7(a: Analysis) -> Verdict:
    """P7: d2f/de2^2 and d2f/de1de2 exist and are continuous."""
    early = _needs_profile(a, "P7")
    if early:
        return early
    v = a.c2
    if not v.proved:
        return _on_e2_axis(v, a.ratio) if v.refuted else v
    v = proved(v.reason, **v.details)
    return _lemmas(v, v, "f is C^2 (continuity of F'' and F'/s, also at the origin)",
                   lambda: smoothness_theorems(a.kernel_F, S, 2, a.profile.ends))


def verify_p8(a: Analysis) -> Verdict:
    """P8: lim_{e2 -> 0} df/de2 = 0 for every e1."""
    early = _needs_profile(a, "P8")
    if early:
        return early
    d = a.dF0
    if d is None:
        return unknown("cannot compute F'(0+)")
    if d != 0:
        return refuted(f"df/de2(0, e2) = F'(|e2|) sign(e2) -> {_show(d)} != 0 as e2 -> 0+",
                       {"e1": "0", "e2": "-> 0+", "limit": _show(d)})
    for piece in a.profile.pieces:
        dF = a.derivative(piece.expr, 1)
        for c, side in ((piece.lo, +1), (piece.hi, -1)):
            if c == sp.oo or (c == 0 and side > 0):
                continue
            v = one_sided_value(dF, c, side)
            if v is None or v in (sp.oo, -sp.oo):
                return unknown(f"cannot bound F' near s = {c}")
        cont = continuous_on(dF, piece.lo, piece.hi, closed=False)
        if not cont.proved:
            return unknown(f"F' on ({piece.lo}, {piece.hi}): {cont.reason}")
    v = proved("F'(0+) = 0, and F' is bounded near every s > 0, so F'(s) e2/s -> 0 as e2 -> 0")
    return _lemmas(v, v, "F' bounded near every s > 0 and F'(0+) = 0",
                   lambda: smoothness_theorems(a.open_branch[0], S, 1, a.profile.ends))


# --------------------------------------------------------------------------
# f that is not (known to be) radial: refute what can be refuted

_RAYS = [(1, 0), (0, 1), (1, 1), (-1, 2), (3, -1), (-2, -3)]


def _non_radial(a: Analysis, name: str) -> Verdict:
    f = a.f
    if name == "P3":
        for dx, dy in _RAYS:
            try:
                lim = limit_right(prepare(f.subs({E1: dx / X, E2: dy / X})), X).value
            except (NoLimit, ZeroDivisionError, TypeError, ValueError):
                continue
            if lim != sp.oo:
                return refuted(f"f -> {lim} along the ray through ({dx}, {dy}): not radially unbounded",
                               {"direction": [dx, dy], "limit": str(lim)})
    if name == "P1":
        g = sp.diff(f, E2)
        for dx, dy in _RAYS:
            try:
                lim = limit_right(prepare(g.subs({E1: dx / X, E2: dy / X})), X).value
            except (NoLimit, ZeroDivisionError, TypeError, ValueError):
                continue
            found = refuted(f"|df/de2| -> oo along the ray through ({dx}, {dy}): kf is infinite",
                            {"direction": [dx, dy], "limit": str(lim)}) if lim in (sp.oo, -sp.oo) else None
            if found is not None and _stands(name, found, f):
                return found
    if name == "P6" and not f.has(*SMOOTH_ONLY):    # df/de1(h, 0)/h unbounded: no k with df/de1 = k e1 h, h <= 1
        g = derivative(f, E1)
        for where, h in (("oo", 1 / X), ("0+", X)):
            try:
                lim = limit_right(prepare(sp.expand_mul(g.xreplace({E1: h, E2: sp.Integer(0)}) / h)), X).value
            except (NoLimit, ZeroDivisionError, TypeError, ValueError):
                continue
            if lim == sp.oo:
                return refuted(f"df/de1(h, 0)/h -> oo as h -> {where}: no constant k bounds df/de1 / e1",
                               {"e1": where, "e2": "0", "limit": "oo"})
    if name in ("P3", "P5", "P6"):
        found = _fails_along_a_line(f, name)
        if found is not None and _stands(name, found, f):
            return found
    if name == "P3" and (found := _negative_near_origin(f, at_point(f, (0, 0)))):
        return found
    if name == "P8" and not f.has(*SMOOTH_ONLY):   # else df/de2's formula may be a branch's taken on a line only
        found = _e2_limit_not_zero(f)
        if found is not None:
            return found
    found = _fails_on_a_grid(f, name) or _jump_across_a_line(f, name) or _switch_on_the_axis(f, name) or \
        {"P1": _p1_along_e2, "P3": _p3_separable, "P5": _p5_along_e1, "P6": _p6_along_e1}.get(name, lambda f: None)(f)
    if found is not None:
        return found
    return unknown("f is not radial; this verifier proves properties of radial f only "
                   "(P4 " + a.p4.status + "), P3 of some f = f(e1, 0) + f(0, e2), and P1 and P5-P8 of "
                   "some f analytic on the plane")


_LINES_TRIED = 4


def _fails_on_a_grid(f, name: str) -> Verdict | None:
    """A point of a fixed grid (quarters up to 3 on each axis) where P3 (f >
    0) or P5 (df/de1 tanh(e1) > 0) fails in interval arithmetic; the kernel
    re-checks the witness (`value`, `slope`).  Also tried for a radial f whose
    profile the search cannot follow (0**rho + log(1 + rho) - 1, which is
    log(1 + rho) - 1 < 0 near the origin, and 0 there)."""
    expr = {"P3": f, "P5": sp.diff(f, E1) * sp.tanh(E1)}.get(name)
    if expr is None:
        return None
    fn = IntervalFunction(expr, [E1, E2], mode="range", prec=200)
    grid = [sp.Rational(k, 4) for k in (-12, -7, -4, -2, -1, 1, 2, 4, 7, 12)]
    for x in grid:
        for y in grid + [0]:
            try:
                val = fn(Interval.point(x), Interval.point(y))
                nonpositive, shown = val.is_nonpositive(), f"in [{val.lower_float():.6g}, {val.upper_float():.6g}]"
            except Undefined:         # (0**rho: SymPy's value at the point, an exact constant; a Piecewise's
                at = at_point(expr, (x, y))     # conditions by the kernel's signs, not SymPy's 2-digit comparison)
                nonpositive, shown = not at.has(sp.nan, sp.zoo) and exact_sign(at) in (0, -1), f"{at}"
            if nonpositive and (x, y) != (0, 0):
                v = refuted(f"fails at (e1, e2) = ({x}, {y}): value {shown}", {"e1": str(x), "e2": str(y)})
                if _stands(name, v, f):
                    return v
    return None


def _jump_across_a_line(f, name: str) -> Verdict | None:
    """P1, P5, P6 (f jumps in the e1 direction), P1, P7 (in e2, or df/de2
    or its slope in e1 jumps in the e1 direction) of a
    Piecewise f with a condition that switches across a line e1 = c or
    e2 = c, c rational: the kernel's jump witness at a point of that line
    (`design_certificate`, kind "jump"), tried at two points off the axes,
    on the first `_LINES_TRIED` lines (each try costs seconds: 59 lines of
    apparent jumps took a minute)."""
    if name not in ("P1", "P5", "P6", "P7") or not isinstance(f, sp.Piecewise):
        return None
    directions = [v for v in (E1, E2) if any(name in r for k, r in _JUMPS.items() if k[0] == v.name)]   # refuting `name`
    lines = []
    for rel in sorted(f.atoms(sp.Rel), key=sp.default_sort_key):
        d = rel.rhs - rel.lhs
        for v in directions:
            line = d.as_poly(v) if d.free_symbols == {v} else None
            c = -line.nth(0) / line.nth(1) if line is not None and line.degree() == 1 else None
            if c is not None and c.is_Rational and (v, c) not in lines:
                lines.append((v, c))
    for v, c in lines[:_LINES_TRIED]:
        for other in (sp.Integer(1), sp.Integer(-1)):
            x, y = (c, other) if v == E1 else (other, c)
            found = refuted(f"f or a derivative jumps across the line {v} = {c} at ({x}, {y})",
                            {"e1": str(x), "e2": str(y), "jump": v.name})
            if refutation_theorems(name, found, f)[0] is not None:
                return found
    return None


def _stands(name: str, v: Verdict, f) -> bool:
    """A refutation of P1, P5 or P6 found through the formula of a partial
    derivative stands for an f with Piecewise, Max, Min or sign only where
    the kernel checks a witness of it: there the formula may be that of a
    branch taken on a line only (Eq(e1, 1), or Max(e1^2, e2^2) on the
    diagonal), unrelated to f's derivative."""
    return name not in ("P1", "P5", "P6") or not f.has(*SMOOTH_ONLY) or refutation_theorems(name, v, f)[0] is not None


_LINES = [(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, 1), (1, -1), (-1, -1)]
_PROBES = tuple(map(sp.Rational, (1, -1, 2, -2, "1/2", "-1/2")))     # e1 = 0 (P6) and e2 -> 0 (P8) probes


def _fails_along_a_line(f, name: str) -> Verdict | None:
    """A point where P3 (f > 0), P5 (sign df/de1 = sign e1) or P6 (e1 df/de1
    >= 0, and df/de1 = k e1 h = 0 on e1 = 0) fails, found by the univariate
    sign search on the half-lines from the origin through the axes and the
    diagonals (f(s d) for s > 0), or on the e2 axis (P6: df/de1(0, y) != 0,
    for f without Piecewise, Max, Min, sign).
    The witness is a point of the plane; the kernel re-checks it (`value`,
    `slope`, `step`)."""
    if name == "P6" and not f.has(*SMOOTH_ONLY):     # (the kernel checks a slope of such an f only)
        g = derivative(f, E1)
        for y in _PROBES:
            try:
                box = value_at(g.xreplace({E1: sp.Integer(0), E2: y}), S, 0, prec=128)
            except (Undefined, TypeError, ValueError):
                continue
            if box.is_positive() or box.is_negative():
                return refuted(f"df/de1(0, {y}) != 0, but df/de1 = k e1 h vanishes on e1 = 0",
                               {"e1": "0", "e2": str(y)})
    for dx, dy in _LINES:
        if name != "P3" and dx == 0:
            continue
        e = f if name == "P3" else derivative(f, E1) * dx
        try:
            e = e.xreplace({E1: dx * S, E2: dy * S})
        except TypeError:           # a Piecewise condition with no real value on this half-line (log(e1), e1 < 0)
            continue
        v = prove_sign(e, S, 0, sp.oo, want=1, strict=name != "P6", budget=MAX_BOXES // 4)
        if v.refuted and v.witness is not None and exact_sign(v.witness) == 1:
            x, y = sp.expand(dx * v.witness), sp.expand(dy * v.witness)
            what = {"P3": "f <= 0", "P5": "df/de1 tanh(e1) <= 0", "P6": "e1 df/de1 < 0"}[name]
            # a branch's formula may hold on a line only (Eq(e1, 1)): such a refutation stands only
            # where the kernel checks f's own values (`_stands`), and says so (red team 29)
            branch = " by the formula of a branch of f, whose own df/de1 may not exist there; the kernel " \
                     "checks values of f near it" if name != "P3" and f.has(*SMOOTH_ONLY) else ""
            return refuted(f"{what} at (e1, e2) = ({x}, {y}) (on the half-line through ({dx}, {dy})){branch}",
                           {"e1": str(x), "e2": str(y)})
    return None


def _e2_limit_not_zero(f) -> Verdict | None:
    """P8 fails at e1 = x when df/de2(x, h) is defined on [0, w] (so
    continuous there, and tends to its value at h = 0) and that interval
    enclosure excludes 0; the kernel re-checks it (`e2_limit`)."""
    g = derivative(f, E2)
    for x in _PROBES:
        at = g.xreplace({E1: x, E2: S})
        try:
            box = enclose(at, S, 0, sp.Rational(1, 64))
        except (Undefined, TypeError, ValueError):
            continue
        if box.is_positive() or box.is_negative():
            limit = at.xreplace({S: sp.Integer(0)})
            return refuted(f"df/de2({x}, e2) -> {limit} != 0 as e2 -> 0+",
                           {"e1": str(x), "e2": "0", "approach": "e2", "limit": str(limit)})
    return None


def _smooth_on_plane(f, name: str) -> Verdict | None:
    """P7 or P8 of an f, radial or not, without Abs, Piecewise, Max, Min or
    sign, whose formula the kernel shows defined at every point of the plane
    (`continuous_on_plane`): f is then analytic there, so C^2 (P7); P8 when
    also df/de2 is shown defined there and df/de2(e1, 0) is exactly 0."""
    if name not in ("P7", "P8") or f.has(*SMOOTH_ONLY, sp.Abs):
        return None
    g = derivative(f, E2)
    if name == "P8" and g.xreplace({E2: sp.Integer(0)}) != 0:
        return None
    theorems = plane_theorems(f, E1, E2, [g] if name == "P8" else [])
    if not theorems:
        return None
    return proved("f is analytic on the plane (its formula is defined at every point and built from functions "
                  "analytic on their domains), so C^2" if name == "P7" else
                  "df/de2 is continuous on the plane (f analytic there) and df/de2(e1, 0) = 0 exactly, so "
                  "df/de2 -> 0 as e2 -> 0", kernel=theorems, unchecked=[])


def _phi_of_e1(f):
    """df/de1 when it is phi(e1), free of e2, and f has no Abs, Piecewise,
    Max, Min or sign (the plane route's f); else None."""
    phi = derivative(f, E1)
    return None if f.has(*SMOOTH_ONLY, sp.Abs) or phi.has(E2) or not phi.has(E1) else phi


def _p5_along_e1(f) -> Verdict | None:
    """P5 of an f analytic on the plane (`continuous_on_plane`) whose df/de1
    = phi(e1) does not depend on e2 (f = g(e1) + h(e2), for instance):
    phi(s) > 0 and -phi(-s) > 0 for s > 0, kernel sign theorems."""
    if _phi_of_e1(f) is None:
        return None
    plane = plane_theorems(f, E1, E2, [])
    sides = [sign_theorems(e, S, 0, sp.oo)[0] for e in e1_sides(f)]
    if not plane or not all(t is not None and len(t) == 1 for t in sides):
        return None
    return proved("df/de1 = phi(e1) does not depend on e2 (f analytic on the plane), and phi(s) > 0, -phi(-s) > 0 "
                  "for s > 0 (the kernel's sign rules): df/de1 tanh(e1) > 0 for e1 != 0",
                  kernel=plane + sides[0] + sides[1], unchecked=[])


def _p6_along_e1(f) -> Verdict | None:
    """P6 of an f as in `_p5_along_e1`: phi(s), -phi(-s) >= 0 and phi(s)/s,
    -phi(-s)/s <= k on (0, oo), kernel theorems, for a k proposed about 1/8
    above the largest of those ratios at sample points (the kernel decides);
    then h = phi(e1)/(k e1) lies in [0, 1], and phi(0) = 0 (|phi(s)| <= k s)."""
    phi = _phi_of_e1(f)
    if phi is None:
        return None
    sides = e1_sides(f)
    k = _proposed_bound([e / S for e in sides])
    if k is None:
        return None
    plane = plane_theorems(f, E1, E2, [])
    signs = [sign_theorems(e, S, 0, sp.oo, strict=False)[0] for e in sides]
    if not plane or not all(t is not None and len(t) == 1 for t in signs):
        return None
    uppers = [sup_upper_theorem(e / S, k, S) for e in sides]
    if None in uppers:
        return None
    h = phi / (k * E1)
    return proved(f"df/de1 = phi(e1) does not depend on e2 (f analytic on the plane), phi(e1) e1 >= 0 and "
                  f"phi(e1)/e1 <= k = {exact_text(k)} (the kernel's sign rules): h = phi(e1)/(k e1) in [0, 1]",
                  kernel=plane + signs[0] + signs[1] + uppers, unchecked=[], k=str(k), k_float=float_of(k), h=str(h))


def _proposed_bound(exprs):
    """A rational about 1/8 above the largest value of the exprs (in s) at
    s = 2^(j/2), |j| <= 60, or None (also when that value is 10^12 or more:
    exp(2^30) as a Fraction would take hours): a proposal only, the kernel
    decides."""
    try:
        top = sp.lambdify(S, sp.Max(*exprs), "mpmath")
        top = max((v for j in range(-60, 61) for v in [top(mpmath.mpf(2) ** (j / 2))] if mpmath.isfinite(v)),
                  default=None)
    except (ArithmeticError, TypeError, ValueError, NameError, mpmath.libmp.NoConvergence):
        return None
    if top is None or not 0 < top < 10 ** 12:
        return None
    return decimal_beyond(Fraction(str(mpmath.nstr(top, 12))) * Fraction(9, 8), 1, 2)


def _p1_along_e2(f) -> Verdict | None:
    """P1 of an f analytic on the plane (`continuous_on_plane`, no Abs)
    whose df/de2 = psi(e2) does not depend on e1 (f = g(e1) + h(e2), for
    instance): +-psi(s), +-psi(-s) <= U on (0, oo), kernel theorems, for a
    U proposed about 1/8 above sampled values (kf itself: `kf.certify_kf_along_e2`)."""
    sides = psi_sides(f)
    if sides is None:
        return None
    U = _proposed_bound(sides)
    plane = plane_theorems(f, E1, E2, []) if U is not None else []
    if not plane:
        return None
    uppers = [sup_upper_theorem(e, U, S) for e in sides]
    if None in uppers:
        return None
    return proved(f"f is analytic on the plane, so C^1; df/de2 = psi(e2) does not depend on e1, and "
                  f"|psi| <= {U} (the kernel's bounds on both half-axes): kf <= {U} is finite",
                  kernel=plane + uppers, unchecked=[])


def _p3_separable(f) -> Verdict | None:
    """P3 of an f defined on the plane with f(e1, e2) = f(e1, 0) + f(0, e2)
    (a separable g(e1) + h(e2), g(0) + h(0) = 0): f on each half-axis is
    > 0 for s > 0 and -> oo as s -> oo, kernel theorems (the argument is
    `design_certificate._link_plane`'s)."""
    if f.has(*SMOOTH_ONLY):
        return None
    split = separable_theorems(f, E1, E2, axis_split(f))
    if not split:
        return None
    halves = half_axes(f)
    signs = [sign_theorems(u, S, 0, sp.oo)[0] for u in halves]
    if not all(t is not None and len(t) == 1 for t in signs):
        return None
    growth = [growth_theorems(u, S) for u in halves]
    if not all(len(t) == 1 for t in growth):
        return None
    return proved("f(e1, e2) = f(e1, 0) + f(0, e2) on the plane, and on each half-axis f > 0 and f -> oo "
                  "(the kernel's sign and divergence rules): f > 0 off the origin, and f >= each term",
                  kernel=split + [t for ts in signs + growth for t in ts], unchecked=[])


def _each_branch(f, name: str) -> Verdict | None:
    """P3, P5 or P6 of a Piecewise f (folded; its last condition True) whose
    every branch g is defined on the plane (for P5, P6 without Abs: analytic there) and radial,
    g = G(|e|) with G = g(s, 0), kernel theorems per branch (the argument is
    `design_certificate._link_branches`).  P3 whatever the conditions: G > 0
    on (0, oo) and G -> oo, so f(e), some G(|e|), is > 0 off the origin and
    f >= min G(|e|) -> oo (Min(r/2, log(1 + r)), whose profile's crossing no
    piece can follow).  P5, P6 when the conditions read e2 only (a branch
    chosen by the sign of e2): the branch does not change along e1, so df/de1
    = G'(|e|) e1/|e| of the branch taken; P5: G' > 0; P6: G' >= 0 and G'/s <= k,
    one k proposed about 1/8 above the sampled largest G'/s."""
    pw = sp.piecewise_fold(f)
    if not isinstance(pw, sp.Piecewise) or pw.args[-1].cond != sp.true or any(g.has(*SMOOTH_ONLY) for g, _ in pw.args) \
            or name != "P3" and any(g.has(sp.Abs) or c.free_symbols - {E2} for g, c in pw.args) \
            or not relations_defined(pw):
        return None
    profiles = [branch_profile(g) for g, _ in pw.args]
    k = _proposed_bound([derivative(G, S) / S for G in profiles]) if name == "P6" else None
    if name == "P6" and k is None:
        return None
    theorems = []
    for (g, _), G in zip(pw.args, profiles):
        try:
            parts = plane_theorems(g, E1, E2, []) + [K.identity_plane(lhs=g, rhs=G.xreplace({S: RHO}), x=E1, y=E2)]
        except (K.KernelError, Undefined):
            return None
        dG = derivative(G, S)
        sign = sign_theorems(G if name == "P3" else dG, S, 0, sp.oo, strict=name != "P6")[0] \
            if len(parts) == 2 else None
        more = growth_theorems(G, S) if name == "P3" else [sup_upper_theorem(dG / S, k, S)] if name == "P6" else []
        if sign is None or len(sign) != 1 or None in more or len(more) != (name != "P5"):
            return None
        theorems += parts + sign + more
    if name == "P3":
        return proved("every branch of f is defined on the plane and radial, G(|e|) with G > 0 on (0, oo) and G -> oo "
                      "(the kernel's rules): f(e) is one of them, so f > 0 off the origin and f -> oo",
                      kernel=theorems, unchecked=[])
    why = ("the conditions read e2 only, so along e1 f is one branch G(|e|), each defined on the plane, and df/de1 = "
           "G'(|e|) e1/|e| with ")
    if name == "P5":
        return proved(why + "G' > 0 on (0, oo) (the kernel's sign rules): df/de1 tanh(e1) > 0 for e1 != 0",
                      kernel=theorems, unchecked=[])
    h = sp.Piecewise(*[(derivative(G, S).xreplace({S: RHO}) / (k * RHO), c) for G, (_, c) in zip(profiles, pw.args)])
    return proved(why + f"G' >= 0 and G'(s)/s <= k = {exact_text(k)} on (0, oo) (the kernel's rules): h = G'(|e|)/(k |e|) in "
                  "[0, 1], and h = 0 at the origin", kernel=theorems, unchecked=[], k=str(k), k_float=float_of(k),
                  h=str(h))


def _or_else(verify, fallback):
    """`verify`, or where it leaves the property undecided or without kernel
    theorems, `fallback(f)` when that decides it."""
    def run(a: Analysis) -> Verdict:
        v = verify(a)
        if v.refuted or (v.proved and v.details.get("kernel")):
            return v
        return fallback(a.f) or v
    run.__doc__ = verify.__doc__
    return run


def _through_reduction(verify, open_only=False):
    """Say so when a verdict rests on an elliptic reduction f = F(s),
    s = sqrt(e1^2 + r e2^2), r != 1 (then df/de1 = F'(s) e1/s and
    df/de2 = r F'(s) e2/s, and every argument above goes through with this s).
    Lemmas about the one branch G of F follow F = G (`open_only`: on (0, oo)
    is enough, P3 and P8)."""
    def run(a: Analysis) -> Verdict:
        v = verify(a)
        branch = a.open_branch[1] if open_only and a.reduced else a.one_branch[1] if a.reduced else []
        if v.proved and v.details.get("kernel") and branch:     # lemmas about G, not F
            v = replace(v, details={**v.details, "kernel": branch + v.details["kernel"]})
        if a.reduced and a.ratio != 1 and not v.refuted:
            v = replace(v, reason=f"with s = {a.radius} (f = F(s) is a symbolic identity; df/de1 = "
                                  f"F'(s) e1/s, df/de2 = {a.ratio} F'(s) e2/s): {v.reason}")
            if v.proved and v.details.get("kernel") and a.reduction:    # the reduction, kernel-checked
                v = replace(v, details={**v.details, "kernel": a.reduction + v.details["kernel"],
                                        "unchecked": [u for u in v.details["unchecked"] if u != REDUCTION]})
        return v
    run.__doc__ = verify.__doc__
    return run


VERIFIERS = {"P1": _through_reduction(verify_p1), "P2": verify_p2,
             "P3": _or_else(_through_reduction(verify_p3, True),
                            lambda f: _each_branch(f, "P3") or _fails_on_a_grid(f, "P3")),
             "P4": verify_p4, "P5": _or_else(_through_reduction(lambda a: a.p5),
                                             lambda f: _each_branch(f, "P5") or _fails_on_a_grid(f, "P5")),
             "P6": _or_else(_through_reduction(verify_p6), lambda f: _each_branch(f, "P6")),
             "P7": _or_else(_through_reduction(verify_p7), lambda f: _smooth_on_plane(f, "P7")),
             "P8": _or_else(_through_reduction(verify_p8, True), lambda f: _smooth_on_plane(f, "P8"))}
