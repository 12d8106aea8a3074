"""Design certificates: what the kernel re-checks of a verifier's report.

A design certificate (format ``uwmr-design-certificate``, version 1) holds
the design's f (as ``srepr``, parameters substituted) and, per property
P1-P8, the verifier's status, the kernel certificate of the lemmas the
kernel has checked (`kernel.certificate`), and the list of facts that still
rest on the search code alone.  `check` re-applies every kernel step without
any search and also checks the *link* between the kernel's conclusions and
the property: that the claim proved is about this f —

* P2: the constant is f(0, 0) and its sign is 0;
* P3: the claims are F(s) > 0 on (0, oo) with F(s) = f(s, 0);
* P5: the claims are F'(s) > 0 on (0, oo) with F' = sympy.diff(F, s);
* P1, P3, P5-P8, kf rest on f = F(|e|): the checker itself requires the
  kernel-checked P4 identity, or, leading the property's own claims, the
  elliptic reduction f = F(sqrt(e1^2 + r e2^2)) with r > 0 (`_reduction`);
  otherwise the reduction is listed as resting on the search;

for a Piecewise F the claims are about the Piecewise itself (`select_branch`
and the other Piecewise rules of the kernel), and wherever the argument
differentiates F they include F and F' continuous on (0, oo); claims about
its pieces only leave the split of F to the search, and say so.  A
refuted property may carry a witness record and kernel theorems about it
(`link_refutation`: the claims must be exactly the negation the property
needs about this f at the witness).  A property whose kernel part checks,
links, and has no unchecked facts is "kernel-checked"; otherwise the checker
says what it rests on.
"""
from __future__ import annotations

import functools
import json
from dataclasses import dataclass, field

import sympy as sp

from . import e1 as E1, e2 as E2
from .certify import REDUCTION, to_certificate
from .files import write_text_atomic
from .kernel.certificate import CertificateError, check_certificate, read_json  # noqa: F401 (re-exported)
from .kernel.core import _TRUE_WHEN, KernelError, _const_sign, _holds, _lt, _srepr, derivative  # _TRUE_WHEN: when l < r (<=, >, >=) holds, the sign of r - l
from .kernel.parse import ParseError, parse
from .profile import S
from .verdict import PROPERTIES

FORMAT, VERSION = "uwmr-design-certificate", 2
SEARCH_ONLY = "the whole argument (no kernel rules for it yet)"
WITNESS_SEARCH = "the witness of the refutation (checked by the search's own high-precision arithmetic only)"
H = sp.Symbol("h", positive=True)       # distance from the origin along an axis or a ray (refutation witnesses)


def build(report) -> dict:
    """The certificate of a verified `verify.Report` (any verdicts)."""
    from .certify import refutation_theorems
    props = {}
    for name, v in report.properties.items():
        theorems = v.details.get("kernel") or []
        props[name] = {
            "status": str(v.status),
            "reason": v.reason,
            "kernel": to_certificate(theorems) if theorems else None,
            "unchecked": (list(v.details.get("unchecked") or []) or ([] if theorems else [SEARCH_ONLY]))
            if v.proved else [],
        }
        if v.refuted:
            try:
                theorems, witness, why = refutation_theorems(name, v, report.design.f)
            except Exception as exc:  # noqa: BLE001 - a proposer bug leaves the witness to the search, visibly
                theorems, witness, why = None, None, f"internal error of the proposer: {type(exc).__name__}: {exc}"
            props[name].update(kernel=to_certificate(theorems) if theorems else None, witness=witness,
                               unchecked=[] if theorems else [f"{WITNESS_SEARCH} ({why})"])
    kf = report.kf
    if kf is not None and kf.exact is not None:
        props["kf"] = {"status": "proved", "reason": kf.reason, "exact": _srepr(kf.exact),
                       "kernel": to_certificate(kf.kernel) if kf.kernel else None,
                       "unchecked": list(kf.unchecked) or ([] if kf.kernel else [SEARCH_ONLY])}
    elif kf is not None and kf.kernel and kf.kernel_bounds is not None:     # kf enclosed: lower <= kf <= upper
        lower, upper = (_srepr(sp.Rational(b.numerator, b.denominator)) for b in kf.kernel_bounds)
        props["kf"] = {"status": "proved", "reason": kf.reason, "exact": None, "lower": lower, "upper": upper,
                       "kernel": to_certificate(kf.kernel), "unchecked": list(kf.unchecked)}
    return {"format": FORMAT, "version": VERSION,
            "design": {"name": report.design.name, "file": str(report.path), "f": _srepr(report.design.f)},
            "properties": props}


def write(report, path) -> None:
    """Write the certificate of `report` to `path` (whole file or nothing)."""
    write_text_atomic(path, json.dumps(build(report), indent=1) + "\n")


@dataclass
class PropertyCheck:
    name: str
    status: str
    theorems: int = 0
    assumptions: list = field(default_factory=list)
    unchecked: list = field(default_factory=list)

    witness: str = ""           # refuted: what the kernel's conclusions show about f
    value: object = None        # proved: P6's k (the bound of its sup claims); kf's exact value, or (lower, upper)
    conclusions: list = field(default_factory=list, repr=False)     # the kernel theorems re-checked

    @property
    def kernel_checked(self) -> bool:
        """Proved, and nothing of the proof is left to the search."""
        return self.status == "proved" and self.theorems > 0 and not self.unchecked

    @property
    def refutation_checked(self) -> bool:
        """Refuted, with a witness the kernel checked and linked to f."""
        return self.status == "refuted" and self.theorems > 0 and not self.unchecked

    def line(self) -> str:
        if self.status not in ("proved", "refuted"):
            return f"{self.name}: {self.status} (nothing to check)"
        shown = "" if self.value is None or not self.kernel_checked else _shown(self.value, self.name)
        head = (f"{self.name}: {self.status}{shown}; {self.theorems} kernel theorem(s) re-checked"
                f" (rests on {', '.join(self.assumptions)})" if self.theorems else f"{self.name}: {self.status}")
        if not self.unchecked:
            return head + "; kernel-checked" + (f": {self.witness}" if self.witness else "")
        return head + "; still rests on the search for: " + "; ".join(self.unchecked)


def _shown(value, name) -> str:
    """ (k = ...) or (kf = ...), (kf in [L, U]) for a kernel-checked line;
    a number of more digits than Python prints, by its size."""
    try:
        return f" (kf in [{value[0]}, {value[1]}])" if isinstance(value, tuple) else \
            f" ({'k' if name == 'P6' else 'kf'} = {value})"
    except ValueError:          # (an integer beyond sys.get_int_max_str_digits)
        return " (a number too long to print)"


@functools.lru_cache(maxsize=256)
def _profile(f):
    """F(s) = f(s, 0), folded (each property's link asks for it again)."""
    return sp.piecewise_fold(f.xreplace({E1: S, E2: sp.Integer(0)}))


branch_profile = _profile       # (the proposer's name for it: a branch's G(s) = g(s, 0))


def _link_kf(dF, bounds, claims, k=1, cuts=None) -> list[str]:
    """kf = k c with k = sqrt(r) (1 for a radial f) and c = sup |F'| on
    (0, oo), by F' >= 0, F' <= c and sup F' >= c, or, when F' changes sign,
    by |F'| <= c and sup E >= c for E = F' or -F' (|F'| >= E).  `bounds`:
    (kf, kf) for an exact kf; (lower, upper) for an enclosure, shown by
    F' <= U and sup F' >= L with lower <= k L and k U <= upper.

    `cuts` not None: F is only known to be continuous with derivative F' on
    each open piece between finitely many cuts (F' continuous there and
    defined at every s > 0 when `cuts` is empty); F may jump.  Then kf is
    sup |df/de2| over the points where df/de2 exists, F' >= 0 suffices, and
    sup F' >= c must hold on an interval J without a cut of F' in its
    inside or at a closed end: there F' is continuous, so its sup over J is approached off the
    cuts of F too, at points (0, s) where df/de2 = F'(s).  On a cut circle
    s = b, where df/de2 exists (e2 != 0) F is differentiable at b, hence
    continuous, and by the mean value theorem on [b, b + h] F'(b) lies in
    [0, c]; at e2 = 0 it is 0."""
    on = (_srepr(S), "Integer(0)", "oo", True, True)
    got = [(c.kind, c.expr, (c.var, c.lo, c.hi, c.lo_open, c.hi_open), c.want, c.strict) for c in claims]
    sup = (on, 0, False)
    if len(claims) == 3:
        want = [[("sign", _srepr(dF), on, 1, True), ("sign", _srepr(dF), on, 1, False)],
                [("sup_upper", _srepr(dF), *sup)], [("sup_lower", _srepr(dF), *sup)]]
        if cuts is not None and _off_cuts(claims[2], cuts):
            got[2] = got[2][:2] + (on,) + got[2][3:]
    else:
        want = [[("sup_upper", _srepr(sp.Abs(dF)), *sup)],
                [("sup_lower", _srepr(dF), *sup), ("sup_lower", _srepr(-dF), *sup)]]
    lower, upper = bounds
    if lower == upper:
        ok = len(claims) >= 2 and claims[-2].other == claims[-1].other and _srepr(k * parse(claims[-1].other)) \
            == _srepr(lower)
    else:
        L, U = (sp.sympify(k * parse(c.other)) for c in claims[-1:-3:-1]) if len(claims) >= 2 else (None, None)
        ok = L is not None and _within_bounds(L, U, bounds)
    if not (ok and len(got) == len(want) and all(g in w for g, w in zip(got, want))):
        raise CertificateError(f"kf: the kernel's conclusions are not F' >= 0, F' <= U, sup F' >= L nor "
                               f"|F'| <= U, sup (+-F') >= L with sqrt(r) [L, U] inside [{lower}, {upper}]"
                               + (" and L = U" if lower == upper else ""))
    return []


def _within_bounds(L, U, bounds) -> bool:
    """lower <= L and U <= upper for bounds = (lower, upper), certified."""
    lower, upper = bounds
    return (lower == L or _lt(lower, L)) and (U == upper or _lt(U, upper))


def _off_cuts(claim, cuts) -> bool:
    """The claim's interval J lies in (0, oo), has inner points, and no cut
    lies inside it or at a closed end."""
    lo, hi = parse(claim.lo), parse(claim.hi)
    return claim.var == _srepr(S) and (lo == 0 or _lt(0, lo)) and _lt(lo, hi) and all(
        _lt(b, lo) or _lt(hi, b) or (b == lo and claim.lo_open) or (b == hi and claim.hi_open) for b in cuts)


def _link_p1_p6(name, F, claims) -> list[str]:
    """P1: F' > 0 on (0, oo); F and F' continuous at 0+ with F'(0) = 0;
    F' <= U.  Every expression in a kernel sign theorem is built from
    functions continuous where defined (the rules accept no others), so F' is
    continuous on (0, oo); with F'(0+) = 0 the gradient F'(|e|) e/|e| of
    f = F(|e|) is continuous on R^2, and |df/de2| <= U: P1.
    P6: F' >= 0 and F'(s)/s <= k with k > 0: h = F'/(k s) lies in [0, 1].
    (For a Piecewise F the continuity comes from a pair of claims instead:
    see `_link`.)"""
    dF = derivative(F, S)
    on = (_srepr(S), "Integer(0)", "oo", True, True)
    got = [(c.kind, c.expr, (c.var, c.lo, c.hi, c.lo_open, c.hi_open)) for c in claims]
    if name == "P1":
        signed = bool(claims) and claims[0].kind == "sign"     # F' > 0, or |F'| <= U (F' changes sign)
        if signed:
            ok = got[0] == ("sign", _srepr(dF), on) and claims[0].want == 1
            claims, got = claims[1:], got[1:]
        ok = ((not signed or ok) and len(claims) == 3
              and [g[:2] for g in got[:2]] == [("limit", _srepr(F)), ("limit", _srepr(dF))]
              and claims[0].lo == claims[1].lo == "Integer(0)" and claims[1].other == "Integer(0)"
              and got[2] == ("sup_upper", _srepr(dF if signed else sp.Abs(dF)), on))
    else:
        ok = (len(claims) in (2, 4) and got[0] == ("sign", _srepr(dF), on) and claims[0].want == 1
              and got[1] == ("sup_upper", _srepr(dF / S), on) and _positive(claims[1].other))
        if ok and len(claims) == 2:
            return [ORIGIN]
        ok = ok and _at_origin(F, dF, claims[2:])
    if not ok:
        raise CertificateError(f"{name}: the kernel's conclusions are not the ones {name} needs for this f")
    return []


#: what P5 and P6 need at the origin beside the signs on (0, oo): df/de1 exists there (f = |e|
#: has F' = 1 > 0 and F'/s = 1/s, and Piecewise((1, Eq(rho, 0)), (rho, True)) F' = 2s, F'/s = 2)
ORIGIN = "df/de1 exists on R^2 (F'(0+) = 0 at the origin)"


def _at_origin(F, dF, claims) -> bool:
    """The claims are F and F' continuous at 0+ (`continuous_at_end`: the
    one-sided limits are the values at 0) with F'(0+) = 0: then F has the
    one-sided derivative 0 at s = 0 (mean value theorem), so f = F(|e|)
    is differentiable at the origin with gradient 0."""
    return len(claims) == 2 and [(c.kind, c.expr, c.var, c.lo) for c in claims] == [
        ("limit", _srepr(F), _srepr(S), "Integer(0)"), ("limit", _srepr(dF), _srepr(S), "Integer(0)")] \
        and claims[1].other == "Integer(0)"


def _link_smooth(name, F, claims) -> list[str]:
    """P8: F' continuous on (0, oo) and F'(0+) = 0, so df/de2 = F'(s) e2/s
    -> 0 as e2 -> 0 (|e2|/s <= 1; at e1 = 0 it is F'(|e2|) sign(e2) -> 0).
    P7: also F'' continuous on (0, oo) and at 0+ (value L), F continuous at
    0+; then F'(s)/s = F''(xi) -> L, so the Hessian F'' e e^T/s^2 + (F'/s)(I - e e^T/s^2) of
    f = F(|e|) is continuous on R^2 \\ {0} and tends to L I at the origin.
    For a Piecewise F, also F continuous on (0, oo): a continuous function
    whose derivative off finitely many points (the boundaries) extends
    continuously is C^1 with that derivative (mean value theorem), so F'
    and F'' above are F's derivatives everywhere.
    P8 may instead rest on F and F' continuous on each open piece between
    finitely many cuts ("pieces"; F may jump): for fixed e1 != 0 and small
    e2 != 0, s lies in (|e1|, |e1| + d), inside one piece, where f = F(s)
    is differentiable and |df/de2| <= |F'(s)|, F' there being one expression
    continuous on the piece's closure in (0, oo), so bounded near |e1|."""
    d1 = derivative(F, S)
    order = 1 if name == "P8" else 2
    ds = [d1, derivative(d1, S)][:order]
    want = [("continuous", _srepr(d), "Integer(0)") for d in ds] + [
        ("limit", _srepr(d), "Integer(0)") for d in ([d1] if order == 1 else [*ds, F])] + [
        ("continuous", _srepr(F), "Integer(0)")] * F.has(sp.Piecewise)
    got = [("continuous" if c.kind == "pieces" and name == "P8" else c.kind, c.expr, c.lo) for c in claims]
    if got != want or claims[order].other != "Integer(0)" or any(c.var != _srepr(S) for c in claims):
        raise CertificateError(f"{name}: the kernel's conclusions are not the ones {name} needs for this f")
    return []


def _link(name, f, theorems, bounds=None) -> list[str]:
    """Facts the kernel's conclusions do not cover for property `name`."""
    claims = [t.claim for t in theorems]
    if name == "P2":
        ok = len(claims) == 1 and claims[0].kind == "value_sign" and claims[0].want == 0 \
            and claims[0].expr == _srepr(at_point(f, (0, 0)))
        if not ok:
            raise CertificateError("P2: the kernel's conclusion is not f(0, 0) = 0")
        return []
    if name == "P4":
        rhs = _profile(f).xreplace({S: sp.sqrt(E1 ** 2 + E2 ** 2)})
        if not (len(claims) == 2 and claims[0].kind == "identity_plane" and claims[0].expr == _srepr(f)
                and claims[0].other == _srepr(rhs) and claims[0].var == _srepr(sp.Tuple(E1, E2))
                and _defined_on_plane(claims[1], f)):
            raise CertificateError("P4: the kernel's conclusions are not f(e1, e2) = F(sqrt(e1^2 + e2^2)) and f "
                                   "defined at every point of the plane")
        return []
    if name not in ("P1", "P3", "P5", "P6", "P7", "P8", "kf"):
        return []
    if name in ("P1", "P3", "P5", "P6", "P7", "P8", "kf") and claims and (claims[0].kind, claims[0].var) == (
            "continuous", _srepr(sp.Tuple(E1, E2))):
        return _link_plane(name, f, claims, bounds)
    F = _profile(f)
    claims, k = _reduction(f, F, claims)
    claims, F = _one_branch(F, claims, open_only=name in ("P3", "P8"))
    dF = derivative(F, S)
    reduction = [] if k is not None else [REDUCTION]      # unless P4 is kernel-checked (see `check`)
    want = F if name == "P3" else dF
    piecewise = F.has(sp.Piecewise)
    if piecewise and name not in ("P7", "P8") and not (claims and claims[0].expr == _srepr(want)):
        return reduction + ["the kernel's claims are about the pieces of F (the split of F is the search's)"]
    return reduction + _link_reduced(name, F, dF, claims, k or 1, bounds)


def _link_plane(name, f, claims, bounds=None) -> list[str]:
    """P5-P8 of any f (radial or not) from `continuous_on_plane`.  An f
    without Abs, Piecewise, Max, Min or sign whose formula is defined at
    every point of the plane is analytic there: each construct the kernel
    accepts but Abs is analytic on an open set holding its argument's values.
    So every partial derivative of f exists and is continuous (P7), and
    equals its SymPy formula wherever that is defined.  P8: also df/de2's
    formula g defined on the plane, and g(e1, 0) evaluates to exactly 0:
    df/de2 = g -> g(e1, 0) = 0 as e2 -> 0, at every e1.  P5 and P6: df/de1's
    formula is phi(e1), free of e2 (f = g(e1) + h(e2), for instance).  P5:
    phi(s) > 0 and -phi(-s) > 0 on (0, oo), so phi(e1) tanh(e1) > 0 for
    e1 != 0 (tanh(e1) has the sign of e1), and = 0 at e1 = 0.  P6: phi(s),
    -phi(-s) >= 0 and phi(s)/s, -phi(-s)/s <= k on (0, oo), one k > 0: h =
    phi(e1)/(k e1) lies in [0, 1] for e1 != 0, and phi(0) = 0 (|phi(s)| <= k s,
    phi continuous), so h = 0 serves at e1 = 0.

    P3 needs f defined on the plane only (Abs allowed), and f(e1, e2) =
    f(e1, 0) + f(0, e2) (`identity_plane`; at the origin it gives f(0, 0) =
    2 f(0, 0) = 0); then the four half-axis functions u(s) = f(s, 0),
    f(-s, 0), f(0, s), f(0, -s) > 0 for s > 0 make f > 0 off the origin (one
    term > 0, the other > 0 or f(0, 0) = 0), and u(s) -> oo for each makes f
    radially unbounded: f >= each term, and max(|e1|, |e2|) >= |e|/sqrt(2).
    P1: f analytic, so C^1; df/de2's formula is psi(e2), free of e1, and
    +-psi(s), +-psi(-s) <= U on (0, oo), one U: |df/de2| <= U off e2 = 0,
    and at e2 = 0 by continuity, so kf <= U is finite.  kf in [lower,
    upper]: those five claims with U <= upper, and sup E >= L on (0, oo) for
    one E of +-psi(+-s), L >= lower: |df/de2| >= E(s) at (0, +-s), so kf >= L."""
    if claims[0].expr != _srepr(f):        # claims about the branches of a Piecewise f
        return _link_branches(name, f, claims)
    g, phi = derivative(f, E2), derivative(f, E1)
    plane = (_srepr(sp.Tuple(E1, E2)), "-oo", "oo", True, True, 0, False)
    on = (_srepr(S), "Integer(0)", "oo", True, True)
    sides = e1_sides(f)
    want = [("continuous", _srepr(e), *plane) for e in ([f, g] if name == "P8" else [f])]
    ok = not f.has(*SMOOTH_ONLY, *([] if name == "P3" else [sp.Abs])) and (name not in ("P5", "P6")
                                                                          or not phi.has(E2))
    if name in ("P1", "kf"):
        want += [("sup_upper", _srepr(e), *on, 0, False) for e in e2_sides(f)]
        ok = ok and not g.has(E1) and len(claims) == 5 + (name == "kf") and len({c.other for c in claims[1:5]}) == 1
    if name == "kf" and ok:         # sup E >= L for one E of the four sides, and [L, U] inside the bounds
        want += [("sup_lower", claims[5].expr, *on, 0, False)]
        L, U = (parse(c.other) for c in (claims[5], claims[1]))
        ok = claims[5].expr in {w[1] for w in want[1:5]} and _within_bounds(L, U, bounds)
    if name == "P3":
        want += [("identity_plane", _srepr(f), plane[0], "", "", False, False, 0, False)]
        want += [("sign", _srepr(u), *on, 1, True) for u in half_axes(f)]
        want += [("diverges", _srepr(u), _srepr(S), c.lo, "oo", False, True, 0, False)
                 for u, c in zip(half_axes(f), claims[6:])]
        ok = ok and len(claims) == 10 and claims[1].other == _srepr(axis_split(f))
    if name == "P8":
        ok = ok and g.xreplace({E2: sp.Integer(0)}) == 0
    if name == "P5":
        want += [("sign", _srepr(e), *on, 1, True) for e in sides]
    if name == "P6":            # h >= 0 (weak or strict), and phi(s)/s <= k on both sides: h <= 1
        want += [("sign", _srepr(e), *on, 1, c.strict) for e, c in zip(sides, claims[1:3])]
        want += [("sup_upper", _srepr(e / S), *on, 0, False) for e in sides]
        ok = ok and len(claims) == 5 and claims[3].other == claims[4].other and _positive(claims[3].other)
    got = [(c.kind, c.expr, c.var, c.lo, c.hi, c.lo_open, c.hi_open, c.want, c.strict) for c in claims]
    if not ok or got != want:
        raise CertificateError(f"{name}: the kernel's conclusions are not those of f analytic on the plane "
                               "(P8: df/de2 = 0 at e2 = 0; P5, P6: df/de1 = phi(e1) signed, and bounded by k e1; "
                               "P3: f = f(e1, 0) + f(0, e2), each half-axis function > 0 and -> oo; "
                               "P1: df/de2 = psi(e2) bounded by one U)")
    return []


def relations_defined(pw) -> bool:
    """Both sides of every relation in the conditions of the Piecewise pw
    are defined on the plane (`defined_for_positive` with two real
    variables), so that at every point some branch is taken."""
    from .kernel.core import defined_for_positive
    return all(defined_for_positive(side, sp.Tuple(E1, E2)) is not None
               for _, c in pw.args for r in c.atoms(sp.Rel) for side in (r.lhs, r.rhs))


def _link_branches(name, f, claims) -> list[str]:
    """P3, P5, P6 of a Piecewise f (SymPy's `piecewise_fold` of the design's
    f) whose last condition is True and the two sides of every relation in
    whose conditions are defined on the plane (`defined_for_positive` with two
    real variables), so that at every point some branch is taken.  For each
    branch g in order: g defined, hence continuous, on the plane (and, without
    Abs, which P5 and P6 refuse, analytic); g(e1, e2) =
    G(sqrt(e1^2 + e2^2)) where both are defined, G = g(s, 0) (so g(e) =
    G(|e|) at e != 0, and dg/de1 = G'(|e|) e1/|e| there); then, on (0, oo):
    P3: G > 0 and G -> oo.  At e != 0, f(e) = G(|e|) > 0 for the branch
    taken there, and f(e) >= min over the branches of G(|e|), which tends to
    oo with |e| (finitely many branches): f is positive off the origin and
    radially unbounded.  The conditions are never read.
    P5, P6, and every condition free of e1: f is one branch g along each line
    e2 = c, so df/de1 = dg/de1 = G'(|e|) e1/|e| there (0 at the origin, g(e1, 0)
    being even and differentiable).  P5: G' > 0, so df/de1 has the sign of e1.
    P6: G' >= 0 and G'(s)/s <= k, one k > 0 for all branches: h = G'(|e|)/(k |e|)
    lies in [0, 1] (h = 0 at the origin)."""
    pw, xy = sp.piecewise_fold(f), sp.Tuple(E1, E2)
    plane, on = (_srepr(xy), "-oo", "oo", True, True, 0, False), (_srepr(S), "Integer(0)", "oo", True, True)
    n = {"P3": 4, "P5": 3, "P6": 4}.get(name, 0)
    branches = pw.args if isinstance(pw, sp.Piecewise) else ()
    ok = branches and pw.args[-1].cond == sp.true and n and len(claims) == n * len(pw.args) \
        and relations_defined(pw) and (name == "P3" or all(c.free_symbols <= {E2} for _, c in branches))
    want, bounds = [], set()
    for i, (g, _) in enumerate(branches if ok else ()):
        G, mine = _profile(g), claims[n * i:n * i + n]
        radial, dG = G.xreplace({S: sp.sqrt(E1 ** 2 + E2 ** 2)}), derivative(G, S)
        ok = ok and not g.has(*SMOOTH_ONLY, *([] if name == "P3" else [sp.Abs])) and mine[1].other == _srepr(radial)
        want += [("continuous", _srepr(g), *plane), ("identity_plane", _srepr(g), *plane[:1], "", "", False, False, 0,
                                                     False)]
        if name == "P3":
            want += [("sign", _srepr(G), *on, 1, True), ("diverges", _srepr(G), _srepr(S), mine[3].lo, "oo", False,
                                                          True, 0, False)]
        else:
            want += [("sign", _srepr(dG), *on, 1, name == "P5" or mine[2].strict)]
        if name == "P6":
            want += [("sup_upper", _srepr(dG / S), *on, 0, False)]
            bounds.add(mine[3].other)
    got = [(c.kind, c.expr, c.var, c.lo, c.hi, c.lo_open, c.hi_open, c.want, c.strict) for c in claims]
    if name == "P6" and ok:             # one k > 0 for all branches
        ok = len(bounds) == 1 and _positive(bounds.pop())
    if not ok or got != want:
        raise CertificateError(f"{name}: the kernel's conclusions are not, for each branch of f (its last condition "
                               "True, its relations defined on the plane; P5, P6: free of e1), g defined on the plane, "
                               "g = G(|e|), and G > 0, G -> oo (P3), G' > 0 (P5), G' >= 0, G'/s <= k (P6)")
    return []


def e1_sides(f) -> list:
    """phi(s), -phi(-s) for phi = df/de1 (P5, P6 when phi is free of e2)."""
    phi = derivative(f, E1)
    return [phi.xreplace({E1: S}), -phi.xreplace({E1: -S})]


def e2_sides(f) -> list:
    """psi(s), -psi(s), psi(-s), -psi(-s) for psi = df/de2 (P1 when psi is free of e1)."""
    return [sign * derivative(f, E2).xreplace({E2: side * S}) for side in (1, -1) for sign in (1, -1)]


def axis_split(f):
    """f(e1, 0) + f(0, e2): f itself when f is separable and f(0, 0) = 0."""
    return at_point(f, (E1, 0)) + at_point(f, (0, E2))


def half_axes(f) -> list:
    """f(s, 0), f(-s, 0), f(0, s), f(0, -s): f on the four half-axes, s > 0."""
    return [at_point(f, p) for p in ((S, 0), (-S, 0), (0, S), (0, -S))]


def _reduction(f, F, claims):
    """(the other claims, sqrt(r)) when the claims begin with the elliptic
    reduction f(e1, e2) = F(sqrt(e1^2 + r e2^2)), r > 0 and f defined on the plane, else (claims,
    None).  With s = sqrt(e1^2 + r e2^2), f = G(e1, sqrt(r) e2) for the
    radial G = F(|.|): a linear change of variables, so f has G's
    smoothness, positivity and growth; df/de1 = F'(s) e1/s as for a radial
    f (P5, P6), df/de2 = r F'(s) e2/s -> 0 as e2 -> 0 (P8), and since
    sqrt(r) |e2| <= s with equality on e1 = 0, sup |df/de2| = sqrt(r) sup |F'| (kf)."""
    if len(claims) >= 3 and claims[0].kind == "identity_plane" and claims[1].kind == "value_sign":
        r = parse(claims[1].expr)
        rhs = F.xreplace({S: sp.sqrt(E1 ** 2 + r * E2 ** 2)})
        if (claims[0].expr, claims[0].other, claims[0].var, claims[1].want) == (
                _srepr(f), _srepr(rhs), _srepr(sp.Tuple(E1, E2)), 1) and _defined_on_plane(claims[2], f):
            return claims[3:], sp.sqrt(r)
    return claims, None


def _defined_on_plane(claim, f) -> bool:
    """claim says that f has a real value at every point of the plane (an
    identity on the plane holds where both sides are defined)."""
    return (claim.kind, claim.expr, claim.var) == ("defined", _srepr(f), _srepr(sp.Tuple(E1, E2)))


def _one_branch(F, claims, open_only=False):
    """(the other claims, G) when F is a Piecewise and the claims begin with
    F = G on (0, oo) (an `identity` through `select_branch`) and F(0) - G(0)
    = 0 (`value_sign`), G free of Piecewise: then F and G agree at every
    s >= 0, and every property reduces to G; or, G being 0/0 at 0, G(0+) = L
    (a `limit` claim) and F(0) - L = 0: then F is G continued to 0, and the
    properties (which read G at 0 through its limits only) reduce to G too;
    else (claims, F).  (An origin given its own value, f = Piecewise((0,
    Eq(rho, 0)), (log(1 + rho), True)), or a Max whose first argument is
    the larger everywhere.)
    `open_only` (P3, P8: about s > 0 only): F = G on (0, oo) is enough."""
    if not (F.has(sp.Piecewise) and claims and claims[0].kind == "identity"):
        return claims, F
    G = parse(claims[0].other)
    if G.has(sp.Piecewise) or (claims[0].expr, claims[0].var, claims[0].lo, claims[0].hi, claims[0].lo_open,
                               claims[0].hi_open) != (_srepr(F), _srepr(S), "Integer(0)", "oo", True, True):
        return claims, F
    if len(claims) >= 2 and claims[1].kind == "value_sign" and claims[1].want == 0 and \
            claims[1].expr == _srepr(F.subs(S, 0) - G.subs(S, 0)):
        return claims[2:], G
    if len(claims) >= 3 and (claims[1].kind, claims[1].expr, claims[1].var, claims[1].lo) == (
            "limit", _srepr(G), _srepr(S), "Integer(0)") and claims[2].kind == "value_sign" and \
            claims[2].want == 0 and claims[2].expr == _srepr(F.subs(S, 0) - parse(claims[1].other)):
        return claims[3:], G            # G(0+) = F(0): F is G continued to 0
    return (claims[1:], G) if open_only else (claims, F)


def _link_reduced(name, F, dF, claims, k, bounds) -> list[str]:
    """The link of a property that reduces to the profile F (k = sqrt(r))."""
    want = F if name == "P3" else dF
    piecewise = F.has(sp.Piecewise)
    gap, cuts = [], None
    if piecewise and name in ("P1", "P5", "P6", "kf"):
        # F and F' continuous on (0, oo): F is C^1 with derivative F' across the boundaries too
        # (a continuous function whose derivative off finitely many points extends continuously)
        pair = [(_srepr(e), _srepr(S), "Integer(0)", "oo") for e in (F, dF)]
        got = [(c.kind, (c.expr, c.var, c.lo, c.hi)) for c in claims[-2:]]
        if got == [("continuous", p) for p in pair]:
            claims = claims[:-2]
        elif name == "kf" and [g[1] for g in got] == pair and {g[0] for g in got} <= {"continuous", "pieces"}:
            cuts = parse(claims[-1].other) if got[1][0] == "pieces" else ()       # F may jump (`_link_kf`)
            claims = claims[:-2]
        else:
            gap = ["F' exists at the boundaries of F's pieces (the search's)"]
    if name == "kf":
        return gap + _link_kf(dF, bounds, claims, k, cuts)
    if name in ("P1", "P6"):
        return gap + _link_p1_p6(name, F, claims)
    if name in ("P7", "P8"):
        return _link_smooth(name, F, claims)
    ok = len(claims) in (1, 2, 3) and claims[0].kind == "sign" and (
        claims[0].expr, claims[0].var, claims[0].lo, claims[0].hi, claims[0].lo_open, claims[0].hi_open,
        claims[0].want, claims[0].strict) == (_srepr(want), _srepr(S), "Integer(0)", "oo", True, True, 1, True)
    if not ok:
        raise CertificateError(f"{name}: the kernel's conclusion is not {'F' if name == 'P3' else 'dF/ds'} > 0 "
                               "on (0, oo) for this f")
    rest = [(c.kind, c.expr, c.var, c.lo) for c in claims[1:]]
    if not rest:            # the other half of the property is the search's (also where a note says so)
        return gap + [DIVERGES if name == "P3" else ORIGIN]
    if name == "P3" and not (len(rest) == 1 and rest[0][:3] == ("diverges", _srepr(F), _srepr(S))):
        raise CertificateError("P3: the second conclusion is not F(s) -> oo")
    if name == "P5" and not _at_origin(F, dF, claims[1:]):
        raise CertificateError("P5: the further conclusions are not F, F' continuous at 0+ with F'(0+) = 0")
    return gap


DIVERGES = "F(s) -> oo as s -> oo"


# ---------------------------------------------------------------- refutations
#
# A refuted property's certificate holds a *witness record* {"kind": ...,
# "points": [[x, y], ...] (srepr), "var": "e1" | "e2"} and kernel theorems.
# The link below recomputes from f and the record the exact constants the
# kernel's claims must be about, and checks that the signs claimed are the
# negation the property needs.  Why each kind refutes (P_ = the property):
#
# value  f(p) for one exact point p.  P2: p = (0, 0) and f(p) != 0.  P3 (f > 0
#        away from the origin): p != (0, 0) and f(p) <= 0.
# circle f(q) - f(p) != 0 for rational p, q with |p| = |q|.  P4: if f were
#        differentiable on the circle with e1 df/de2 - e2 df/de1 = 0 (the
#        derivative of f along the circle), f would be constant on it.
# slope  df/de1 (sympy.diff) at one exact point p = (x, y), f without
#        Piecewise, Max, Min or sign.  P5 needs df/de1 tanh(e1) > 0 for x != 0,
#        i.e. the sign of df/de1 at p is sign(x): refuted by a sign 0 or
#        -sign(x) (on x = 0, tanh(0) = 0 and P5 asks nothing more); P6
#        (df/de1 = k e1 h, k > 0, 0 <= h <= 1) by the sign -sign(x), and on
#        x = 0, where k e1 h = 0, by any sign other than 0.  Where
#        df/de1 does not exist at p both properties fail anyway; where it
#        exists, the derivative of the accepted constructs (the kernel's
#        evaluator takes no other) is the value of SymPy's formula wherever that
#        is defined ("sympy-diff").  Piecewise is excluded: a branch taken only
#        at p (Eq conditions) has a derivative unrelated to f's.
# step   f(q) - f(p) with p = (x1, y), q = (x2, y), x1 < x2 both > 0 or both
#        < 0 (side = their sign): no derivative at all, so any f.  If P5
#        held, g(t) = f(t, y) would be differentiable on [x1, x2] with g' of
#        sign `side` (mean value theorem): f(q) - f(p) of sign 0 or -side
#        refutes it; P6 (g' = k t h of sign 0 or side) is refuted by -side.
# origin_jump  for v = e2 (or e1): E+(h) = df/dv at (0, h) (v = h, the other
#        variable 0) and E-(h) = df/dv at (0, -h), h > 0, continuous on
#        [0, w] with values L+, L- at 0 (`continuous_at_end`), and
#        L+ - L- != 0.  If phi(t) = f(0, t) (f(t, 0) for e1) were
#        differentiable near 0, the mean value theorem would give
#        phi'(0) = L+ = L-.  So df/dv does not exist near the origin, or
#        has no limit at it: v = e2 refutes P1 (df/de2 continuous), P7 (d2f/de2^2
#        exists, so df/de2 does) and P8 (lim df/de2 = 0 as e2 -> 0 at e1 = 0);
#        v = e1 refutes P1, P5 and P6 (both need df/de1 to exist everywhere).
#        Like slope, refused for f with Piecewise, Max, Min or sign.
# e2_limit  E(h) = df/de2 (sympy.diff) at (x, h), continuous on [0, w] with
#        value L at 0 (`continuous_at_end`), and L != 0: df/de2(x, e2) has the
#        one-sided limit L != 0 as e2 -> 0+, so not the limit 0 that P8 asks
#        for at e1 = x (where df/de2 does not exist near (x, 0), P8 fails
#        anyway).  Like slope, refused for f with Piecewise, Max, Min or sign.
# bounded  f(h dx, h dy) <= M for all h > 0 (`sup_upper`, M finite), or
#        f(h dx, h dy) -> M as h -> oo (`limit_oo`, M finite), (dx, dy) !=
#        (0, 0): f does not tend to oo along that ray, so P3 fails.
# unbounded  E(h) -> +oo as h -> oo (at "oo": `diverges_by_growth` of E) or
#        as h -> 0+ (at "0": `diverges_by_growth` of E(1/h)), for E = df/de2 at
#        (0, h) (var e2): |df/de2| has no finite bound kf, P1 fails; at "0"
#        df/de2 is also unbounded on the e2 axis near the origin, so it has
#        no limit 0 there (P8) and is not continuous there, as it would be
#        were d2f/de2^2 to exist near the origin (P7); for E =
#        df/de1 at (h, 0), divided by h (var e1): P6's df/de1 = k e1 h with
#        0 <= h <= 1 would give E <= k; at "0" with "divided": false, E =
#        df/de1(h, 0) itself: were df/de1 to exist near the origin, g(t) =
#        f(t, 0) would have g'(0) = lim (g(t) - g(0))/t = lim g'(xi_t) = oo
#        (mean value theorem), so it does not exist: P1, P5, P6;
#        for E = d2f/de2^2 at (0, h) (var e2,
#        order 2, at "0" only): not continuous at the origin, P7 fails.
#        f without Piecewise, Max, Min, sign.
# jump   f a Piecewise (at the top), b exact, w > 0: for h in (0, w], branch
#        iL of f applies at (b - h, 0) and branch iR at (b + h, 0) -- kernel
#        sign theorems, on (0, w], that every earlier condition is false and
#        that condition true (a relation l < r, l <= r, ... is true exactly
#        where r - l has the matching sign; the first true condition picks
#        the branch) --, the two branches tend to L-, L+ as h -> 0+
#        (`continuous_at_end`), and L+ - L- (or f(b, 0) - L+, or f(b, 0) -
#        L-) != 0.  Then t -> f(t, 0) is not continuous at b, so df/de1 does
#        not exist at (b, 0): P1, P5, P6 fail.  With "var": "e2" the same
#        along the e2 axis at (0, b), and with "order": k (1, 2; only L+ - L-,
#        branches without Piecewise, Max, Min, sign) about the k-th
#        derivatives of the branches in e2 (sympy.diff): g(t) = f(0, t) is
#        the branch on each side, so g^(k) has one-sided limits L-, L+ at b;
#        if d^k f/de2^k existed and were continuous at (0, b) they would be
#        equal.  Order 0 or 1: df/de2 is not continuous at (0, b) (P1), and
#        d2f/de2^2 cannot exist there (P7); order 2: P7.  Along the e1 axis
#        with order 1, g(t) = f(t, 0): were df/de1 to exist near (b, 0), g'(b)
#        = lim (g(b + h) - g(b))/h = g'(xi_h) -> L+ (mean value theorem), and
#        L- likewise, so df/de1 does not exist somewhere near (b, 0): P1, P5,
#        P6 (each needs df/de1 everywhere).  The point may be (b, c) with c
#        rational (var e1; (c, b) for var e2): the same on the line e2 = c
#        (e1 = c) instead of the axis, so a switch across a line away from the
#        origin is seen too.
# crossing  f = Piecewise((A, l REL r), (B, True)), REL one of <, <=, >, >=
#        (a Max or a Min), both branches and the condition without Piecewise,
#        Max, Min, sign; rational 0 < q1 < q2 on the e1 axis, d(t) = r - l at
#        (t, 0).  Kernel sign theorems on the closed [q1, q2]: d' strictly
#        signed; d(q1), d(q2) of opposite strict signs (`value_sign`); the gap
#        A - B ("order": 0) or dA/de1 - dB/de1 ("order": 1) strictly signed;
#        and M - E >= 0, M a number, for each E of d, A, B (and dA/de1, dB/de1
#        for order 1), all at (t, 0), so that each is defined on [q1, q2] (a
#        sign claim says so; the gap alone might have cancelled a term that
#        both branches share).  Then d is C^1 and strictly monotone, with one
#        root c in (q1, q2): the condition holds on one side of c and fails
#        on the other, so g(t) = f(t, 0) is A on one side and B on the other.
#        Were df/de1 to exist at (c, 0), g would be continuous at c, so A(c)
#        = B(c) (A and B are continuous on [q1, q2]), and differentiable
#        there, so A'(c) = B'(c) (its one-sided difference quotients; A and
#        B are C^1 where they and their derivatives are defined).  The gap
#        says one of these fails at c: df/de1 does not exist at (c, 0), and
#        P1, P5, P6 fail.  Rests on sympy-diff.  The crossing c need not be
#        exact (log(1 + rho) = rho/2 at rho = 2.513...).  With "var": "e2" the
#        same on the e2 axis, at (0, t): df/de2 does not exist at (0, c), so
#        P1 fails, and so does P7 (d2f/de2^2 at (0, c) is the derivative of
#        t -> df/de2(0, t) at c).

SMOOTH_ONLY = (sp.Piecewise, sp.Max, sp.Min, sp.sign)
_REFUTES = {"value": ("P2", "P3"), "circle": ("P4",), "slope": ("P5", "P6"), "step": ("P5", "P6"),
            "e2_limit": ("P8",), "origin_jump": ("P1", "P5", "P6", "P7", "P8"), "bounded": ("P3",),
            "unbounded": ("P1", "P5", "P6", "P7", "P8"), "jump": ("P1", "P5", "P6", "P7"),
            "crossing": ("P1", "P5", "P6", "P7")}
_JUMPS = {("e1", 0): ("P1", "P5", "P6"), ("e1", 1): ("P1", "P5", "P6"), ("e2", 0): ("P1", "P7"), ("e2", 1): ("P1", "P7"),
          ("e2", 2): ("P7",), ("e1", 1, "mixed"): ("P1", "P7"), ("e1", 2, "mixed"): ("P7",)}
_UNBOUNDED = {("P1", "e2", 1, "oo"), ("P1", "e2", 1, "0"), ("P6", "e1", 1, "oo"), ("P6", "e1", 1, "0"),
              ("P7", "e2", 2, "0"), ("P7", "e2", 1, "0"), ("P8", "e2", 1, "0"),
              ("P1", "e1", 1, "0", "plain"), ("P5", "e1", 1, "0", "plain"), ("P6", "e1", 1, "0", "plain")}


def at_point(f, p):
    """f at the point p = (e1, e2) (numbers or expressions): each subterm
    with the point put in, except that a Piecewise's conditions are read
    in order up to the first that holds, as the Piecewise is (a later one
    may have no value there: log(e1^2 + e2^2) > 0 at the origin), and an
    And (Or) is false (true) when one of its parts is, whatever the others.
    At a point of numbers a relation l < r (<=, >, >=, =, !=) is read from
    the kernel's sign of r - l there (`_const_sign`; |u|, sign, Max, Min read
    as the Piecewise they are), never from SymPy's comparison, which
    evaluates to 2 digits and took log(1 + 10^-40) < 10^-40 - 10^-80/2 +
    10^-120/3 - 10^-160/4 for true (red team 23: a branch that never applies
    gave f(-3, -3) = -1, and a true P3 was refuted).  Where a condition read
    before it has no value or no sign the kernel decides, neither has f: nan.
    On a line (p holding e1 or e2) a condition is SymPy's, as substituted."""
    point = {E1: sp.sympify(p[0], strict=True), E2: sp.sympify(p[1], strict=True)}
    numbers = all(v.is_number for v in point.values())
    if numbers:     # Abs of a constant asks SymPy's sign of it: |g| - g, g = log(1 + x) - T4(x) > 0, gave -2 g
        f = f.replace(lambda e: isinstance(e, (sp.Abs, sp.sign, sp.Max, sp.Min, sp.Heaviside)),
                      lambda e: e.rewrite(sp.Piecewise))

    def sign_ok(d, want, strict):       # want (r - l) > 0 (>= 0) at p, by the kernel
        try:
            s = _const_sign(at(d), zero=True)
        except KernelError:
            return False
        return s == want or (not strict and s == 0)

    def truth(c):           # c at p, or None where it has no value
        if not numbers:
            if isinstance(c, (sp.And, sp.Or)):
                parts = [truth(a) for a in c.args]
                decides = sp.false if isinstance(c, sp.And) else sp.true
                return decides if decides in parts else None if None in parts else c.func(*parts)
            try:
                return c.xreplace(point)
            except TypeError:   # SymPy compares no zoo or non-real number
                return None
        c = c.to_nnf() if c.has(sp.ITE) else c      # (|u| < 1 rewritten: ITE(u >= 0, u < 1, u > -1))
        try:
            return next((sp.true if t else sp.false for t in (True, False) if _holds(c, t, sign_ok)), None)
        except KernelError:     # not a relation, And, Or or Not
            return None

    def at(e):
        if not e.has(sp.Piecewise):
            return e.xreplace(point)
        if not isinstance(e, sp.Piecewise):
            return e.func(*[at(a) for a in e.args])
        pairs = []
        for value, cond in e.args:
            c = truth(cond)
            if c is None:
                c, value = sp.true, sp.nan
            if c != sp.false:
                pairs.append((at(value), c))
            if c == sp.true:
                break
        return sp.Piecewise(*pairs) if pairs else sp.nan
    return at(f)


def axis_derivative(f, v, side):
    """df/dv at distance h > 0 from the origin along the v axis, on the side
    `side` (+1, -1), the other variable 0: an expression in H."""
    other = E2 if v == E1 else E1
    return derivative(f, v).xreplace({other: sp.Integer(0), v: side * H})


def e2_limit_expr(f, x):
    """df/de2 at (x, h), h > 0: an expression in H (witness e2_limit)."""
    return derivative(f, E2).xreplace({E1: x, E2: H})


def along_ray(f, direction):
    """f(h dx, h dy) for h > 0: an expression in H."""
    return f.xreplace({E1: direction[0] * H, E2: direction[1] * H})


def growing(f, v, order=1, at="oo", divided=True):
    """The expression whose divergence as h -> oo refutes P1 (v = e2: df/de2
    at (0, h)), P6 (v = e1: df/de1 at (h, 0), divided by h unless not
    `divided`) or P7 (order 2: d2f/de2^2 at (0, h)); at "0", the same with h
    replaced by 1/h."""
    e = axis_derivative(f if order == 1 else derivative(f, v), v, 1)
    e = e if v == E2 or not divided else e / H
    return e if at == "oo" else e.xreplace({H: 1 / H})


def _on_axis(v, b, side, other=0):
    """The point b + side*h of the line parallel to the v axis on which the
    other variable is `other` (the v axis itself by default)."""
    return {v: b + side * H, (E2 if v == E1 else E1): sp.sympify(other, strict=True)}


def branch_conditions(f, b, side, i, w, v=E1, other=0):
    """For the jump witness: what the kernel must show so that branch i of
    the Piecewise f applies at the point b + side*h of the v line (`_on_axis`) for every
    h in (0, w]: one entry per condition up to i (none for a final True),
    each a list of the acceptable (expression in H, want, strict) sign claims."""
    if not isinstance(f, sp.Piecewise) or not 0 <= i < len(f.args):
        raise CertificateError("jump: f is not a Piecewise with that branch")
    at = _on_axis(v, b, side, other)
    out = []
    for j, (_, cond) in enumerate(f.args[:i + 1]):
        truth = j == i
        if cond is sp.true:
            if not truth:
                raise CertificateError("jump: a condition True before the branch")
            continue
        # an Or is true where one of its relations is (one entry, any of them), false where all are
        # false (one entry each); an And the other way round
        rels = cond.args if isinstance(cond, (sp.Or, sp.And)) else (cond,)
        if not all(isinstance(r, (*_TRUE_WHEN, sp.Eq, sp.Ne)) for r in rels):
            raise CertificateError(f"jump: condition {cond} is not a relation or an And or Or of relations")
        entries = [_relation_claims(r, at, truth) for r in rels]
        if len(rels) > 1 and truth == isinstance(cond, sp.Or):
            entries = [[c for e in entries for c in e]]
        out.extend(entries)
    return out


def _relation_claims(rel, at, truth):
    """The sign claims (expression in H, want, strict), any one of which shows
    the relation `truth` at the point `at` (Eq and Ne: only where r - l is
    strictly signed, so Eq false and Ne true)."""
    d = rel.rhs.xreplace(at) - rel.lhs.xreplace(at)
    if isinstance(rel, (sp.Eq, sp.Ne)):
        if truth != isinstance(rel, sp.Ne):
            raise CertificateError(f"jump: {rel} cannot be shown {truth} by a sign")
        return [(d, 1, True), (d, -1, True)]
    want, strict = _TRUE_WHEN[type(rel)]
    return [(d, want, strict)] if truth else [(d, -want, not strict)]


def jump_parts(f, b, branches, w, v=E1, order=0, other=0, mixed=False):
    """The one-sided branch expressions (their order-th derivatives in v;
    `mixed`: the first of them in e2 instead) at the points b - h and b + h
    of the v line (`_on_axis`)."""
    parts = [f.args[i][0] for i in branches]
    for k in range(order):                      # one order at a time (SymPy's diff(e, v, 2) can be far slower)
        parts = [derivative(e, E2 if mixed and k == 0 else v) for e in parts]
    return [e.xreplace(_on_axis(v, b, side, other)) for e, side in zip(parts, (-1, 1))]


def _tail_branch(f, v, witness, claims, at, order, bad):
    """(the claims after the branch's, branch i's expression) for an
    `unbounded` witness of a Piecewise f with "branch": i and "from": R:
    the claims must begin with the signs (on h in (0, oo)) that make branch
    i apply at R + h of the v axis; then f = G_i on the open half-line
    t > R of that axis, so df/dv there is dG_i/dv (a partial derivative along
    the axis sees only f on it).  Only at infinity, order 1, G_i without
    Piecewise, Max, Min, sign."""
    i, R = witness.get("branch"), parse(witness.get("from", "nan"))
    if not (isinstance(f, sp.Piecewise) and type(i) is int and 0 <= i < len(f.args) and at == "oo" and order == 1
            and R.is_Rational and R >= 0) or f.args[i][0].has(*SMOOTH_ONLY):
        raise bad
    on = (_srepr(H), "Integer(0)", "oo", True, True)
    conds = branch_conditions(f, R, 1, i, sp.oo, v)
    if len(claims) <= len(conds) or not all(_one_of(c, options, on) for c, options in zip(claims, conds)):
        raise bad
    return claims[len(conds):], f.args[i][0]


def chosen_by_e1(f, branches) -> bool:
    """Every condition of the Piecewise f up to the later branch is free of
    e2: where such a branch applies at (b + h, c) it applies on the whole
    line e1 = b + h, so near a jump line e1 = b it is f on an open strip."""
    return not any(c.has(E2) for _, c in f.args[:max(branches) + 1])


def _one_of(c, options, on) -> bool:
    """The claim c is a sign claim on the interval `on` that shows one of
    the acceptable (expression, want, strict) of `branch_conditions`."""
    return c is not None and c.kind == "sign" and (c.var, c.lo, c.hi, c.lo_open, c.hi_open) == on and any(
        c.expr == _srepr(e) and c.want == want and (c.strict or not strict) for e, want, strict in options)


def _link_jump(name, f, claims, witness, bad) -> str:
    v, order, mixed = witness.get("var", "e1"), witness.get("order", 0), witness.get("mixed", False) is True
    if name not in _JUMPS.get((v, order, "mixed") if mixed else (v, order), ()):
        raise CertificateError(f"{name}: a jump of the order-{order} derivative in {v} does not refute {name}")
    v = {"e1": E1, "e2": E2}[v]
    (x, y), = [tuple(_real(c) for c in p) for p in witness.get("points", [])]
    b, other = (x, y) if v == E1 else (y, x)
    branches, w = witness.get("branches"), _real(witness.get("width"))
    if not isinstance(other, sp.Rational) or not (isinstance(branches, list) and len(branches) == 2
                                                  and all(type(i) is int and 0 <= i < len(f.args) for i in branches)):
        raise bad
    if order and any(f.args[i][0].has(*SMOOTH_ONLY) for i in branches):
        raise CertificateError(f"{name}: a jump of a derivative needs branches without Piecewise, Max, Min or sign")
    if mixed and not chosen_by_e1(f, branches):
        raise CertificateError(f"{name}: a jump of a derivative in e2 needs branches chosen by e1 alone")
    on = (_srepr(H), "Integer(0)", _srepr(w), True, False)
    k = 0
    limits = []
    for side, i, part in zip((-1, 1), branches, jump_parts(f, b, branches, w, v, order, other, mixed)):
        for options in branch_conditions(f, b, side, i, w, v, other):
            if not _one_of(claims[k] if k < len(claims) else None, options, on):
                raise bad
            k += 1
        c = claims[k] if k < len(claims) else None
        if c is None or (c.kind, c.expr, c.var, c.lo, c.hi) != ("limit", _srepr(part), _srepr(H), "Integer(0)",
                                                                 _srepr(w)):
            raise bad
        limits.append(parse(c.other))
        k += 1
    value = at_point(f, (x, y))
    gaps = {"sides": limits[1] - limits[0], "left": value - limits[0], "right": value - limits[1]}
    gap = gaps.get(witness.get("compare")) if order == 0 or witness.get("compare") == "sides" else None
    if gap is None or len(claims) != k + 1 or claims[k].kind != "value_sign" or claims[k].expr != _srepr(gap) \
            or claims[k].want == 0:
        raise bad
    what = {1: "df/de2", 2: "d2f/de1de2"}[order] if mixed else {0: "f", 1: f"df/d{v}", 2: f"d2f/d{v}^2"}[order]
    along = f"t, {other}" if v == E1 else f"{other}, t"
    return (f"{what}({along}) jumps at t = {b}: left limit {limits[0]}, right limit {limits[1]}"
            + (f", value {value}" if order == 0 else ""))


def crossing_parts(f, order, v=E1):
    """For the crossing witness of f = Piecewise((A, l REL r), (B, True)):
    d = r - l, d', the gap (A - B, or their v-derivatives' for order 1) and
    the expressions to be shown defined, all at h > 0 on the v axis."""
    if not (isinstance(f, sp.Piecewise) and len(f.args) == 2 and f.args[1][1] is sp.true
            and type(f.args[0][1]) in _TRUE_WHEN and not any(x.has(*SMOOTH_ONLY) for x in (*f.args[0], f.args[1][0]))):
        raise CertificateError("crossing: f is not Piecewise((A, l < r), (B, True)) with smooth parts")
    on = _on_axis(v, 0, 1)
    (a, cond), (b, _) = f.args
    d = (cond.rhs - cond.lhs).xreplace(on)
    parts = [e.xreplace(on) for e in ([a, b] if order == 0 else [derivative(a, v), derivative(b, v)])]
    defined = [d, a.xreplace(on), b.xreplace(on)] + (parts if order else [])
    return d, derivative(d, H), parts[0] - parts[1], defined


def _link_crossing(name, f, claims, witness, bad) -> str:
    order, v = witness.get("order"), witness.get("var", "e1")
    if name not in {"e1": ("P1", "P5", "P6"), "e2": ("P1", "P7")}.get(v, ()):
        raise CertificateError(f"{name}: a crossing on the {v} axis does not refute {name}")
    v = {"e1": E1, "e2": E2}[v]
    points = [tuple(_real(c) for c in p) for p in witness.get("points", [])]
    if order not in (0, 1) or type(order) is not int or len(points) != 2 or any(len(p) != 2 for p in points):
        raise bad
    (q1, o1), (q2, o2) = points if v == E1 else [p[::-1] for p in points]
    if not (q1.is_Rational and q2.is_Rational and 0 < q1 < q2 and o1 == o2 == 0):
        raise bad
    d, dd, gap, defined = crossing_parts(f, order, v)
    on = (_srepr(H), _srepr(q1), _srepr(q2), False, False)

    def sign(c, e=None):        # a sign claim on [q1, q2] (about e if given)
        return c.kind == "sign" and (c.var, c.lo, c.hi, c.lo_open, c.hi_open) == on and (e is None or c.expr == _srepr(e))
    if len(claims) != 4 + len(defined) or not (sign(claims[0], dd) and claims[0].strict and sign(claims[3], gap)
                                               and claims[3].strict):
        raise bad
    ends = claims[1:3]
    if [(c.kind, c.expr) for c in ends] != [("value_sign", _srepr(d.xreplace({H: q}))) for q in (q1, q2)] \
            or ends[0].want * ends[1].want != -1:
        raise bad
    for c, e in zip(claims[4:], defined):       # M - E >= 0 for a number M: E is defined on [q1, q2]
        if not (sign(c) and c.want == 1 and (parse(c.expr) + e).is_number):
            raise bad
    return (f"df/d{v} does not exist where {f.args[0][1]} switches on the {v} axis, between {q1} and {q2}: "
            f"there the branches' {'slopes' if order else 'values'} differ")


def witness_values(kind, f, points) -> list:
    """The exact constants whose signs the kernel must claim (kinds value,
    circle, slope, step); the proposer uses this too."""
    if kind == "value":
        return [at_point(f, points[0])]
    if kind in ("circle", "step"):
        return [at_point(f, points[1]) - at_point(f, points[0])]
    if kind == "slope":
        return [at_point(derivative(f, E1), points[0])]
    raise CertificateError(f"unknown witness kind {kind!r}")


def _positive(text) -> bool:
    """The constant of a claim is > 0, by the kernel's sign (SymPy's
    `is_positive` of a number evaluates it to 2 digits)."""
    try:
        return _sign(parse(text)) == 1
    except (CertificateError, ParseError):
        return False


def _sign(c) -> int:
    try:
        return _const_sign(c)
    except KernelError as exc:
        raise CertificateError(f"witness: {exc}") from None


def _real(text) -> sp.Expr:
    """A witness's coordinate, direction or width: an exact, finite, real
    constant (Arb evaluates it with a decided sign), never I, oo or nan: at
    (1, 2 I), where f = log(1 + e1^2 + e2^2)/2 is log(1/2)/2 < 0, a true P3
    had been "refuted"."""
    c = parse(text, design=True)
    c = sp.Integer(c) if type(c) is int else c          # "1" reads as the int 1
    if not (isinstance(c, sp.Expr) and c.is_number and c not in (sp.oo, -sp.oo)):
        raise CertificateError(f"witness: {text} is not a finite number")
    _sign(c)
    return c


def link_refutation(name, f, theorems, witness) -> tuple[str, bool]:
    """Check that the kernel's conclusions refute property `name` of f (see
    the table above); (what they show, whether the link used sympy.diff).
    Raises CertificateError otherwise."""
    if not isinstance(witness, dict) or witness.get("kind") not in _REFUTES:
        raise CertificateError(f"{name}: no known witness kind")
    kind = witness["kind"]
    if name not in _REFUTES[kind]:
        raise CertificateError(f"{name}: a witness of kind {kind!r} does not refute {name}")
    claims = [t.claim for t in theorems]
    bad = CertificateError(f"{name}: the kernel's conclusions are not the witness {kind!r} about this f")
    tail = kind == "unbounded" and "branch" in witness          # f = branch i of a Piecewise beyond R
    if kind in ("slope", "origin_jump", "unbounded", "e2_limit") and f.has(*SMOOTH_ONLY) and not tail:
        raise CertificateError(f"{name}: a {kind} witness needs an f without Piecewise, Max, Min or sign")
    if kind == "origin_jump":
        v = {"e1": E1, "e2": E2}.get(witness.get("var"))
        if v is None or name not in {E1: ("P1", "P5", "P6"), E2: ("P1", "P7", "P8")}[v]:
            raise CertificateError(f"{name}: an origin jump of df/d{witness.get('var')} does not refute {name}")
        ends = [axis_derivative(f, v, side) for side in (1, -1)]
        if not (len(claims) == 3 and [(c.kind, c.expr, c.var, c.lo) for c in claims[:2]]
                == [("limit", _srepr(e), _srepr(H), "Integer(0)") for e in ends]):
            raise bad
        jump = parse(claims[0].other) - parse(claims[1].other)
        if not (claims[2].kind == "value_sign" and claims[2].expr == _srepr(jump) and claims[2].want != 0):
            raise bad
        return (f"df/d{v} -> {parse(claims[0].other)} and {parse(claims[1].other)} "
                f"along the {v} axis on either side of the origin"), True
    if kind == "e2_limit":
        points = witness.get("points") or [()]
        p = tuple(_real(c) for c in points[0])
        if len(points) != 1 or len(p) != 2 or _sign(p[1]) != 0:
            raise bad
        if not (len(claims) == 2 and (claims[0].kind, claims[0].expr, claims[0].var, claims[0].lo)
                == ("limit", _srepr(e2_limit_expr(f, p[0])), _srepr(H), "Integer(0)")
                and claims[1].kind == "value_sign" and claims[1].expr == claims[0].other and claims[1].want != 0):
            raise bad
        return f"df/de2({p[0]}, h) -> {parse(claims[0].other)} != 0 as h -> 0+", True
    on_h = (_srepr(H), "Integer(0)", "oo", True)
    if kind == "bounded":
        d = tuple(_real(c) for c in witness.get("direction", ()))
        if len(d) != 2 or (_sign(d[0]) == 0 and _sign(d[1]) == 0):
            raise bad
        c = claims[0] if len(claims) == 1 else None
        if not (c is not None and c.expr == _srepr(along_ray(f, d)) and parse(c.other) not in (sp.oo, -sp.oo) and
                (c.kind, c.var, c.lo, c.hi, c.lo_open) in (("sup_upper", *on_h), ("limit_oo", _srepr(H), "", "oo", False))):
            raise bad
        return f"f({d[0] * H}, {d[1] * H}) {'<=' if c.kind == 'sup_upper' else '->'} {parse(c.other)} " \
               f"{'for all h > 0' if c.kind == 'sup_upper' else 'as h -> oo'}", False
    if kind == "unbounded":
        divided = witness.get("divided", True) is not False
        how = (name, witness.get("var"), witness.get("order", 1), witness.get("at", "oo")) + (() if divided else
                                                                                              ("plain",))
        if how not in _UNBOUNDED:
            raise CertificateError(f"{name}: a divergence {how[1:]} does not refute {name}")
        v, order, at = {"e1": E1, "e2": E2}[how[1]], how[2], how[3]
        g = f
        if tail:
            claims, g = _tail_branch(f, v, witness, claims, at, order, bad)
        if not (len(claims) == 1 and claims[0].kind == "diverges"
                and claims[0].expr == _srepr(growing(g, v, order, at, divided)) and claims[0].var == _srepr(H)):
            raise bad
        what = {(E2, 1): "df/de2(0, h)", (E1, 1): "df/de1(h, 0)/h" if divided else "df/de1(h, 0)",
                (E2, 2): "d2f/de2^2(0, h)"}[(v, order)]
        return f"{what} -> oo as h -> {'oo' if at == 'oo' else '0+'}", True
    if kind == "jump":
        return _link_jump(name, f, claims, witness, bad), bool(witness.get("order", 0))
    if kind == "crossing":
        return _link_crossing(name, f, claims, witness, bad), True
    points = [tuple(_real(c) for c in p) for p in witness.get("points", [])]
    if len(points) != (2 if kind in ("circle", "step") else 1) or any(len(p) != 2 for p in points):
        raise bad
    values = witness_values(kind, f, points)
    if not (len(claims) == 1 and claims[0].kind == "value_sign" and claims[0].expr == _srepr(values[0])):
        raise bad
    want = claims[0].want
    p = points[0]
    if kind == "value":
        origin = _sign(p[0]) == 0 and _sign(p[1]) == 0
        ok = (origin and want != 0) if name == "P2" else (not origin and want <= 0)
        what = f"f{p} {'!= 0' if name == 'P2' else '<= 0'}"
    elif kind == "circle":
        q = points[1]
        ok = (all(c.is_Rational for c in (*p, *q)) and p[0] ** 2 + p[1] ** 2 == q[0] ** 2 + q[1] ** 2
              and want != 0)
        what = f"f{q} != f{p} on the circle of radius {sp.sqrt(p[0] ** 2 + p[1] ** 2)}"
    elif kind == "slope":
        side = _sign(p[0])      # P5 holds trivially on e1 = 0 (tanh 0 = 0); P6's k e1 h vanishes there
        ok = (side != 0 and want * side <= 0) if name == "P5" else (want * side < 0 if side else want != 0)
        what = f"df/de1{p} has sign {want}"
    else:
        q = points[1]
        side = 1 if _lt(0, p[0]) else (-1 if _lt(q[0], 0) else 0)
        ok = (p[1] == q[1] and _lt(p[0], q[0]) and side != 0
              and (want * side <= 0 if name == "P5" else want * side < 0))
        what = f"f{q} - f{p} has sign {want}"
    if not ok:
        raise CertificateError(f"{name}: the kernel's claim ({what}) does not refute {name}")
    return what, kind == "slope"


def _malformed(exc) -> str:
    return f"no entry {exc}" if isinstance(exc, KeyError) else f"{type(exc).__name__}: {exc}"


def _check_property(name, entry, f) -> PropertyCheck:
    """Re-check one property's entry of a design certificate against f."""
    if not (isinstance(entry["unchecked"], list) and all(isinstance(u, str) for u in entry["unchecked"])):
        raise CertificateError(f"{name}: 'unchecked' must be a list of texts")
    pc = PropertyCheck(name, entry["status"], unchecked=list(entry["unchecked"]))
    if entry["kernel"] is not None:
        try:
            theorems = check_certificate(entry["kernel"])
        except CertificateError as exc:
            raise CertificateError(f"{name}: {exc}") from None
        pc.theorems, pc.conclusions = len(theorems), theorems
        pc.assumptions = sorted(set().union(*[t.assumptions for t in theorems]))
        if pc.status == "refuted":
            pc.witness, diff = link_refutation(name, f, theorems, entry["witness"])
            if diff:                        # the link differentiates f itself
                pc.assumptions = sorted(set(pc.assumptions) | {"sympy-diff"})
        elif pc.status == "proved":
            bounds = None if name != "kf" else (parse(entry["exact"]),) * 2 if entry["exact"] is not None \
                else (parse(entry["lower"]), parse(entry["upper"]))
            if bounds is not None and not all(b.is_number and b.is_finite for b in bounds):
                raise CertificateError(f"kf: [{bounds[0]}, {bounds[1]}] is not an enclosure by finite numbers")
            pc.unchecked += [u for u in _link(name, f, theorems, bounds)     # (a note may say more)
                             if not any(x.startswith(u) for x in pc.unchecked)]
            if name == "P6":        # (each link asks one k of every sup claim of h)
                ks = {t.claim.other for t in theorems if t.claim.kind == "sup_upper"}
                pc.value = parse(ks.pop()) if len(ks) == 1 else None
            elif name == "kf":
                pc.value = bounds[0] if bounds[0] == bounds[1] else bounds
            if name not in ("P2", "P4"):        # the link differentiates F itself
                pc.assumptions = sorted(set(pc.assumptions) | {"sympy-diff"})
        else:
            raise CertificateError(f"{name}: kernel theorems for a verdict {pc.status!r}")
    elif pc.status == "refuted" and not pc.unchecked:     # as written before witnesses were checked
        pc.unchecked = [WITNESS_SEARCH]
    elif pc.status == "proved" and not pc.unchecked:
        raise CertificateError(f"{name}: proved with neither kernel theorems nor unchecked facts")
    return pc


def _refute_contradictions(f, props, out) -> None:
    """A certificate contradicts itself when it calls a property proved that the
    kernel-checked witness of another refutes as well (origin_jump refutes P1,
    P5-P8, `_REFUTES`): CertificateError naming it (`prop`) and the property
    whose witness refutes it (`refuted_by`)."""
    for c in (c for c in out if c.refutation_checked):
        witness = props[c.name]["witness"]
        for d in (d for d in out if d.status == "proved" and d.name in _REFUTES[witness["kind"]]):
            try:
                link_refutation(d.name, f, c.conclusions, witness)
            except CertificateError:
                continue
            error = CertificateError(f"{d.name}: the certificate says proved, but the kernel-checked witness "
                                     f"of {c.name} refutes {d.name} too ({c.witness})")
            error.prop, error.refuted_by = d.name, c.name
            raise error


def check(data) -> list[PropertyCheck]:
    """Re-check a design certificate (a dict or JSON text).  Raises
    CertificateError naming the first property or step that fails."""
    data = read_json(data)
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise CertificateError(f"not a design certificate (format must be {FORMAT!r})")
    if data.get("version") != VERSION:
        raise CertificateError(f"design certificate version {data.get('version')!r} is not supported: "
                               f"this checker reads version {VERSION} only")
    try:
        try:
            f = parse(data["design"]["f"], design=True)
        except ParseError as exc:
            raise CertificateError(f"the checker cannot read the design's f ({exc}): nothing can be re-checked; "
                                   f"the kernel reads exp, log, sqrt and powers, trigonometric and hyperbolic "
                                   f"functions and their inverses, erf, Abs, Max, Min, Piecewise") from None
        if at_point(f, (0, 0)).has(sp.nan, sp.zoo):      # the links read F(0+) as F(0) (`kernel.limit_by_taylor`)
            raise CertificateError("the design's f is undefined at the origin")
        props = data["properties"]
        names = set(props) if isinstance(props, dict) else set()
        if not names or not names <= {*PROPERTIES, "kf"}:
            raise CertificateError(f"the certificate's properties must be among P1-P8 and kf, and they are "
                                   f"{', '.join(sorted(names)) or 'none'}")
        out = []
        for name in sorted(props):
            try:
                out.append(_check_property(name, props[name], f))
            except (CertificateError, KeyError, TypeError, ValueError, IndexError, AttributeError) as exc:
                error = exc if isinstance(exc, CertificateError) else \
                    CertificateError(f"malformed design certificate ({name}): {_malformed(exc)}")
                error.prop = name               # (`verify._kernel_check` leaves that verdict to the search)
                raise error from None
        _refute_contradictions(f, props, out)
        p4 = next((c for c in out if c.name == "P4"), None)
        if p4 is not None and p4.kernel_checked:        # the reduction is the identity P4 rests on
            for c in out:
                c.unchecked = [u for u in c.unchecked if u != REDUCTION]
    except CertificateError:
        raise
    except (KeyError, TypeError, ValueError, IndexError, AttributeError) as exc:     # (ParseError is a ValueError)
        raise CertificateError(f"malformed design certificate: {_malformed(exc)}") from None
    return out
