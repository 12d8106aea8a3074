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

(for a Piecewise F the link is left to the search and listed as such).  A
property whose kernel part checks, links, and has no unchecked facts is
"kernel-checked"; otherwise the checker says what it rests on.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import sympy as sp

from . import e1 as E1, e2 as E2
from .certify import REDUCTION
from .kernel.certificate import CertificateError, check_certificate, to_certificate  # noqa: F401 (re-exported)
from .kernel.parse import ParseError, parse
from .profile import S

FORMAT, VERSION = "uwmr-design-certificate", 1
SEARCH_ONLY = "the whole argument (no kernel rules for it yet)"


def build(report) -> dict:
    """The certificate of a verified `verify.Report` (any verdicts)."""
    props = {}
    for name, v in report.properties.items():
        theorems = v.details.get("kernel") or []
        props[name] = {
            "status": str(v.status),
            "reason": v.reason,
            "kernel": to_certificate(theorems) if theorems else None,
            "unchecked": list(v.details.get("unchecked", [SEARCH_ONLY])) if v.proved else [],
        }
    kf = report.kf
    if kf is not None and kf.exact is not None:
        props["kf"] = {"status": "proved", "reason": kf.reason, "exact": sp.srepr(kf.exact),
                       "kernel": to_certificate(kf.kernel) if kf.kernel else None,
                       "unchecked": [REDUCTION, *kf.unchecked]}
    return {"format": FORMAT, "version": VERSION,
            "design": {"name": report.design.name, "file": str(report.path), "f": sp.srepr(report.design.f)},
            "properties": props}


def write(report, path) -> None:
    """Write the certificate of `report` to `path` (whole file or nothing)."""
    path = Path(path)
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(json.dumps(build(report), indent=1) + "\n")
    tmp.replace(path)


@dataclass
class PropertyCheck:
    name: str
    status: str
    theorems: int = 0
    assumptions: list = field(default_factory=list)
    unchecked: list = field(default_factory=list)

    @property
    def kernel_checked(self) -> bool:
        return self.status == "proved" and self.theorems > 0 and not self.unchecked

    def line(self) -> str:
        if self.status != "proved":
            return f"{self.name}: {self.status} (nothing to check)"
        head = (f"{self.name}: proved; {self.theorems} kernel theorem(s) re-checked"
                f" (rests on {', '.join(self.assumptions)})" if self.theorems else f"{self.name}: proved")
        if not self.unchecked:
            return head + "; kernel-checked"
        return head + "; still rests on the search for: " + "; ".join(self.unchecked)


def _profile(f):
    return sp.piecewise_fold(f.subs({E1: S, E2: 0}))


def _link_kf(dF, exact, claims) -> list[str]:
    """kf: F' > 0, F' <= kf and sup F' >= kf, all on (0, oo)."""
    on = (sp.srepr(dF), sp.srepr(S), "Integer(0)", "oo", True, True)
    got = [((c.expr, c.var, c.lo, c.hi, c.lo_open, c.hi_open), c.kind, c.want, c.strict, c.other) for c in claims]
    want = [(on, "sign", 1, True, ""), (on, "sup_upper", 0, False, sp.srepr(exact)),
            (on, "sup_lower", 0, False, sp.srepr(exact))]
    if got != want:
        raise CertificateError(f"kf: the kernel's conclusions are not F' > 0, F' <= kf, sup F' >= kf "
                               f"with kf = {exact}")
    return []


def _link_p1_p6(name, F, claims) -> list[str]:
    """P1: F' > 0 on (0, oo); F and F' continuous at 0+ with F'(0) = 0;
    F' <= U.  Every expression in a kernel sign theorem is built from
    functions continuous where defined (the rules accept no others), so F' is
    continuous on (0, oo); with F'(0+) = 0 the gradient F'(|e|) e/|e| of
    f = F(|e|) is continuous on R^2, and |df/de2| <= U: P1.
    P6: F' > 0 and F'(s)/s <= k with k > 0: h = F'/(k s) lies in [0, 1]."""
    dF = sp.diff(F, S)
    on = (sp.srepr(S), "Integer(0)", "oo", True, True)
    got = [(c.kind, c.expr, (c.var, c.lo, c.hi, c.lo_open, c.hi_open)) for c in claims]
    if name == "P1":
        ok = (len(claims) == 4 and got[0] == ("sign", sp.srepr(dF), on) and claims[0].want == 1
              and [g[:2] for g in got[1:3]] == [("limit", sp.srepr(F)), ("limit", sp.srepr(dF))]
              and claims[1].lo == claims[2].lo == "Integer(0)" and claims[2].other == "Integer(0)"
              and got[3] == ("sup_upper", sp.srepr(dF), on))
    else:
        ok = (len(claims) == 2 and got[0] == ("sign", sp.srepr(dF), on) and claims[0].want == 1
              and got[1] == ("sup_upper", sp.srepr(dF / S), on) and parse(claims[1].other).is_positive)
    if not ok:
        raise CertificateError(f"{name}: the kernel's conclusions are not the ones {name} needs for this f")
    return []


def _link_smooth(name, F, claims) -> list[str]:
    """P8: F' continuous on (0, oo) and F'(0+) = 0, so df/de2 = F'(s) e2/s
    -> 0 as e2 -> 0 (|e2|/s <= 1; at e1 = 0 it is F'(|e2|) sign(e2) -> 0).
    P7: also F'' continuous on (0, oo) and at 0+ (value L), F continuous at
    0+; then F'(s)/s = F''(xi) -> L, so the Hessian F'' e e^T/s^2 + (F'/s)(I - e e^T/s^2) of
    f = F(|e|) is continuous on R^2 \\ {0} and tends to L I at the origin."""
    d1 = sp.diff(F, S)
    order = 1 if name == "P8" else 2
    ds = [d1, sp.diff(d1, S)][:order]
    want = [("continuous", sp.srepr(d), "Integer(0)") for d in ds] + [
        ("limit", sp.srepr(d), "Integer(0)") for d in ([d1] if order == 1 else [*ds, F])]
    got = [(c.kind, c.expr, c.lo) for c in claims]
    if got != want or claims[order].other != "Integer(0)" or any(c.var != sp.srepr(S) for c in claims):
        raise CertificateError(f"{name}: the kernel's conclusions are not the ones {name} needs for this f")
    return []


def _link(name, f, theorems, exact=None) -> list[str]:
    """Facts the kernel's conclusions do not cover for property `name`."""
    claims = [t.claim for t in theorems]
    if name == "P2":
        ok = len(claims) == 1 and claims[0].kind == "value_sign" and claims[0].want == 0 \
            and claims[0].expr == sp.srepr(f.subs({E1: 0, E2: 0}))
        if not ok:
            raise CertificateError("P2: the kernel's conclusion is not f(0, 0) = 0")
        return []
    if name == "P4":
        rhs = _profile(f).subs(S, sp.sqrt(E1 ** 2 + E2 ** 2))
        if not (len(claims) == 1 and claims[0].kind == "identity_plane" and claims[0].expr == sp.srepr(f)
                and claims[0].other == sp.srepr(rhs) and claims[0].var == sp.srepr(sp.Tuple(E1, E2))):
            raise CertificateError("P4: the kernel's conclusion is not f(e1, e2) = F(sqrt(e1^2 + e2^2))")
        return []
    if name not in ("P1", "P3", "P5", "P6", "P7", "P8", "kf"):
        return []
    F = _profile(f)
    if F.has(sp.Piecewise):
        return ["the kernel's claims are about the pieces of F (the split of F is the search's)"]
    if name == "kf":
        return _link_kf(sp.diff(F, S), exact, claims)
    if name in ("P1", "P6"):
        return _link_p1_p6(name, F, claims)
    if name in ("P7", "P8"):
        return _link_smooth(name, F, claims)
    dF = sp.diff(F, S)
    want = F if name == "P3" else dF
    ok = len(claims) in (1, 2, 3) and claims[0].kind == "sign" and (
        claims[0].expr, claims[0].var, claims[0].lo, claims[0].hi, claims[0].lo_open, claims[0].hi_open,
        claims[0].want, claims[0].strict) == (sp.srepr(want), sp.srepr(S), "Integer(0)", "oo", True, True, 1, True)
    if not ok:
        raise CertificateError(f"{name}: the kernel's conclusion is not {'F' if name == 'P3' else 'dF/ds'} > 0 "
                               "on (0, oo) for this f")
    rest = [(c.kind, c.expr, c.var, c.lo) for c in claims[1:]]
    if name == "P3" and rest and not (len(rest) == 1 and rest[0][:3] == ("diverges", sp.srepr(F), sp.srepr(S))):
        raise CertificateError("P3: the second conclusion is not F(s) -> oo")
    if name == "P5" and rest and not (
            len(rest) == 2 and [r[:4] for r in rest] == [("limit", sp.srepr(F), sp.srepr(S), "Integer(0)"),
                                                         ("limit", sp.srepr(dF), sp.srepr(S), "Integer(0)")]
            and claims[2].other == "Integer(0)"):
        raise CertificateError("P5: the further conclusions are not F, F' continuous at 0+ with F'(0+) = 0")
    return []


def check(data) -> list[PropertyCheck]:
    """Re-check a design certificate (a dict or JSON text).  Raises
    CertificateError naming the first property or step that fails."""
    if isinstance(data, (str, bytes)):
        try:
            data = json.loads(data)
        except json.JSONDecodeError as exc:
            raise CertificateError(f"not JSON: {exc}") from None
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise CertificateError(f"not a design certificate (format must be {FORMAT!r})")
    if data.get("version") != VERSION:
        raise CertificateError(f"design certificate version {data.get('version')!r} is not supported: "
                               f"this checker reads version {VERSION} only")
    try:
        f = parse(data["design"]["f"], design=True)
        props = data["properties"]
        out = []
        for name in sorted(props):
            entry = props[name]
            pc = PropertyCheck(name, entry["status"], unchecked=list(entry["unchecked"]))
            if entry["kernel"] is not None:
                try:
                    theorems = check_certificate(entry["kernel"])
                except CertificateError as exc:
                    raise CertificateError(f"{name}: {exc}") from None
                pc.theorems = len(theorems)
                pc.assumptions = sorted(set().union(*[t.assumptions for t in theorems]))
                exact = parse(entry["exact"]) if name == "kf" else None
                pc.unchecked += _link(name, f, theorems, exact)
                if name not in ("P2", "P4"):        # the link differentiates F itself
                    pc.assumptions = sorted(set(pc.assumptions) | {"sympy-diff"})
            elif pc.status == "proved" and not pc.unchecked:
                raise CertificateError(f"{name}: proved with neither kernel theorems nor unchecked facts")
            out.append(pc)
        p4 = next((c for c in out if c.name == "P4"), None)
        if p4 is not None and p4.kernel_checked:        # the reduction is the identity P4 rests on
            for c in out:
                c.unchecked = [u for u in c.unchecked if u != REDUCTION]
    except (KeyError, TypeError, ParseError) as exc:
        raise CertificateError(f"malformed design certificate: {type(exc).__name__}: {exc}") from None
    return out
