"""The verifier: load a design, decide P1-P8, certify kf, replay the proof,
check the gains against bound (10).  Returns a `Report`.

The search proposes; `design_certificate` re-checks the certificate of its
verdicts in the trusted kernel (``Report.kernel`` says what it re-checked).
With ``kernel_only`` (the default; ``--trust-search`` turns it off) only the
kernel's verdicts count: a proof or refutation it did not re-check becomes
"unknown".

This module is callable: ``from uwmr_symbolic import verify; verify(f, params,
gains)`` is `uwmr_symbolic.api.verify` (see its documentation)."""
from __future__ import annotations

import time
from dataclasses import dataclass, field, replace
from pathlib import Path

import sympy as sp

from .certify import design_budget
from .design import Design, DesignError, load_design
from .gains import GainCheck, check_gains
from .kf import SupCertificate, certify_kf_along_e2, show
from .limits import MAX_ROOT_DEGREE
from .properties import PROPERTIES, VERIFIERS, Analysis
from .replay import replay
from . import timeouts
from .timeouts import TimeLimit, time_limit
from .verdict import Verdict, refuted, unknown

DEFAULT_TIMEOUT = 60.0

EXIT_OK, EXIT_REFUTED, EXIT_UNUSABLE, EXIT_INCONCLUSIVE = 0, 1, 2, 3
SEARCH_ONLY = "not re-checked by the kernel (the search says "     # the start of `kernel_verdict`'s reason


def deep_roots(f: sp.Expr) -> list:
    """The exponents of f beyond MAX_ROOT_DEGREE on a homogeneous polynomial
    base; none for f = c P^(p/q) alone (c rho^1.0000000000000002 is decided
    at once: there is no sum to bring to a common denominator)."""
    from . import e1 as E1, e2 as E2
    if f.as_coeff_Mul()[1].is_Pow:
        return []
    out = set()
    for p in f.atoms(sp.Pow):
        if p.exp.is_Rational and p.exp.q > MAX_ROOT_DEGREE and p.base.has(E1, E2) \
                and p.base.is_polynomial(E1, E2) and sp.Poly(p.base, E1, E2).is_homogeneous:
            out.add(p.exp)
    return sorted(out, key=lambda x: x.q)


@dataclass
class Report:
    """The verifier's result for one design: the verdict of each property
    P1-P8 (``properties``), the certified kf of P1 (``kf``), bound (10) per
    gain scenario (``gains``), the replay of the Lyapunov argument (11)-(19)
    (``proof_replay``) and ``exit_status`` (0 proved, 1 refuted or a gain
    check fails, 2 unusable, 3 inconclusive).  In a notebook it shows as a
    table; ``to_dict()`` is the JSON of ``--format json``."""
    path: Path
    design: Design | None
    properties: dict[str, Verdict]
    kf: SupCertificate | None
    gains: dict[str, GainCheck] = field(default_factory=dict)
    proof_replay: dict = field(default_factory=lambda: {"ok": False, "steps": {}})
    seconds: float = 0.0
    error: str | None = None      # unusable input
    # some step ran out of time (--timeout, or a search step's own cap such as certify.WALL_CAP):
    # the result depends on the time given
    timed_out: bool = False
    certificate: dict | None = None   # the design certificate of the search's verdicts (`design_certificate`)
    kernel: dict | None = None        # what the kernel re-checked of it (`kernel_summary`)
    kernel_only: bool = False         # made as by default: what rests on the search alone does not count

    @property
    def exit_status(self) -> int:
        if self.error is not None:
            return EXIT_UNUSABLE
        verdicts = list(self.properties.values())
        gains_fail = any(g.V_ok is False or g.W_ok is False for g in self.gains.values())
        if any(v.refuted for v in verdicts) or gains_fail:
            return EXIT_REFUTED
        if set(self.properties) == set(PROPERTIES) and all(v.proved for v in verdicts) and self.proof_replay.get("ok") \
                and all(g.V_ok and g.W_ok for g in self.gains.values()):
            return EXIT_OK
        return EXIT_INCONCLUSIVE

    def to_dict(self) -> dict:
        """The report as JSON-able data (the object ``--format json`` prints)."""
        from .report import to_dict
        return to_dict(self)

    def __str__(self) -> str:
        from .report import render_text
        return render_text(self)

    def _repr_html_(self) -> str:
        from .display import report_html
        return report_html(self)

    def plot_profile(self, s_max: float = 10.0):
        """A matplotlib Figure of F(s), F'(s) and F'(s)/s (f = F(|(e1, e2)|))
        with the certified kf of P1 and the k of P6."""
        from .display import profile_figure
        return profile_figure(self, s_max)


def _timed_out(what: str, timeout: float) -> Verdict:
    return unknown(f"{what} did not finish within --timeout {timeout:g} s")


def load_with_limit(path, timeout: float = DEFAULT_TIMEOUT, start: float | None = None) -> Design | Report:
    """Load a design file within `timeout`: the `Design`, or the final `Report`
    when the file is unusable or loading it timed out."""
    path = Path(path)
    start = time.monotonic() if start is None else start
    try:
        with time_limit(timeout):
            return load_design(path)
    except DesignError as exc:
        return Report(path, None, {}, None, error=str(exc), seconds=time.monotonic() - start)
    except TimeLimit:
        what = "loading the design file (running it, then reading f and checking it at sample points)"
        props = {p: _timed_out(what, timeout) for p in PROPERTIES}
        return Report(path, None, props, None, seconds=time.monotonic() - start, timed_out=True)


def verify_design(path, timeout: float = DEFAULT_TIMEOUT, kernel_only: bool = True) -> Report:
    """Verify one design file (never raises for bad input: see Report.error)."""
    start = time.monotonic()
    loaded = load_with_limit(path, timeout, start)
    if isinstance(loaded, Report):
        return loaded
    return verify_loaded(loaded, timeout, start, kernel_only)


def verify_loaded(design: Design, timeout: float = DEFAULT_TIMEOUT, start: float | None = None,
                  kernel_only: bool = True) -> Report:
    """Decide P1-P8, kf, the proof replay and the gains of a loaded design;
    `start` (time.monotonic()) is when the `timeout` began to run.  With
    `kernel_only` (the default) only the kernel's verdicts count
    (`kernel_verdict`) and bound (10) is checked only with a kernel-checked
    kf."""
    start = time.monotonic() if start is None else start
    deep = deep_roots(design.f)
    if deep:
        why = (f"f has a power of e1, e2 or rho with the exponent {deep[-1]}, whose denominator is above "
               f"{MAX_ROOT_DEGREE}, the most the symbolic search takes: nothing was decided (a float exponent "
               f"is read as its decimal, 0.7 as 7/10 but 2/3 as 3333333333333333/5000000000000000: write "
               f"sp.Rational(2, 3))")
        return Report(design.path, design, {p: unknown(why) for p in PROPERTIES}, None,
                      seconds=time.monotonic() - start)
    try:
        with design_budget(design.f):       # the kernel proposer's work budget for this design
            return _verify(design, timeout, start, kernel_only)
    except RecursionError:                  # SymPy recurses once per level of f (diff, subs, printing)
        why = "f is nested too deeply for SymPy (Python's recursion limit was reached): nothing was decided"
        return Report(design.path, design, {p: unknown(why) for p in PROPERTIES}, None,
                      seconds=time.monotonic() - start)


def kernel_summary(checked) -> dict:
    """Which verdicts the kernel checked (a proof with nothing left to the
    search, a refutation with a kernel-checked witness), from the re-checked
    design certificate, and which rest on the search."""
    ok = [c.name for c in checked if c.kernel_checked or c.refutation_checked]
    return {"checked": ok, "search": [c.name for c in checked if c.status in ("proved", "refuted") and
                                      c.name not in ok]}


def _kernel_check(search: Report) -> tuple[dict | None, dict]:
    """The design certificate of the search's verdicts and what the kernel
    re-checked of it.  A property whose kernel theorems do not re-check (a
    proposer bug) is left to the search in the certificate, and the others
    are checked again; the failures are named ("failed").  A certificate
    that fails as a whole leaves every verdict to the search ("error")."""
    from . import design_certificate as certificates
    cert = certificates.build(search)
    failed, refuted_by = [], {}
    while True:
        try:
            summary = kernel_summary(certificates.check(cert))
            return cert, summary | ({"failed": failed} if failed else {}) | (
                {"refuted_by": refuted_by} if refuted_by else {})          # [[property, why], ...]; {P1: P5}
        except certificates.CertificateError as exc:
            by = getattr(exc, "refuted_by", None)
            if by is not None:      # the search proved what another property's checked witness refutes
                refuted_by[exc.prop] = by
                cert["properties"][exc.prop] = dict(cert["properties"][by])
                continue
            entry = cert["properties"].get(getattr(exc, "prop", None))
            if entry is None or entry["kernel"] is None:
                decided = [p for p, v in search.properties.items() if v.proved or v.refuted]
                return cert, {"checked": [], "search": decided + (["kf"] if "kf" in cert["properties"] else []),
                              "error": f"the certificate does not re-check: {exc}"}
            failed.append([exc.prop, str(exc)])
            entry["kernel"] = None
            what = "the witness of the refutation" if entry["status"] == "refuted" else "the whole argument"
            entry["unchecked"] = [f"{what} (the proposer's kernel theorems do not re-check: {exc})"]


def kernel_verdict(name: str, v: Verdict, kernel: dict) -> Verdict:
    """The verdict that counts: the search's when the kernel re-checked it (or
    it is unknown), else unknown, its reason saying what the search found."""
    if name not in kernel["search"]:
        return v
    return unknown(f"{SEARCH_ONLY}{v.status}, which counts only with --trust-search: {v.reason})")


def kf_checked(certificate: dict | None, kernel: dict) -> bool:
    """The kernel checked kf: its value, or that it is infinite, by a checked
    refutation of P1 whose witness is df/de2 -> oo (kind "unbounded", var
    e2: df/de1 -> oo says nothing of kf = sup |df/de2| unless f is radial)."""
    if "kf" in kernel["checked"]:
        return True
    witness = (certificate or {}).get("properties", {}).get("P1", {}).get("witness") or {}
    return "P1" in kernel["checked"] and (witness.get("kind"), witness.get("var")) == ("unbounded", "e2")


def _gains(design: Design, kf: SupCertificate | None) -> dict[str, GainCheck]:
    """Bound (10) per gain scenario with the certified kf (None: kf undecided,
    or not re-checked by the kernel, and the W bound is left undecided)."""
    kf_for_gains = kf_lower = None
    if kf is not None and kf.upper is not None:
        kf_for_gains = kf.exact if kf.exact is not None else sp.Rational(kf.upper.numerator, kf.upper.denominator)
        if kf.exact is None and kf.lower is not None:
            kf_lower = sp.Rational(kf.lower.numerator, kf.lower.denominator)
    kf_known = kf_for_gains is not None or (kf is not None and kf.unbounded_witness is not None)
    return check_gains(design.gains, kf_for_gains, kf_known, kf_lower)


AFTER_DEADLINE = 8.0    # seconds past --timeout that kf, the kernel's re-check and the replay share (< batch.HARD_GRACE)


def stage_seconds(deadline: float, least: float, now: float) -> float:
    """Time limit of a stage after the properties: what is left of --timeout,
    at least `least` s, but never past deadline + AFTER_DEADLINE, so that the
    stages together stay inside the parent's kill limit (`batch.hard_limit`)."""
    return max(min(max(deadline - now, least), deadline + AFTER_DEADLINE - now), 0.001)


def _verify(design: Design, timeout: float, start: float, kernel_only: bool = True) -> Report:
    path = design.path
    deadline = start + timeout
    timed_out = False
    expired_before = timeouts.expired
    analysis = Analysis(design)
    props: dict[str, Verdict] = {}
    # P4 first: it decides whether the radial reduction is available
    for name in ("P4", "P2", "P1", "P3", "P5", "P6", "P7", "P8"):
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            props[name] = _timed_out(name, timeout)
            timed_out = True
            continue
        try:
            with time_limit(remaining):
                props[name] = VERIFIERS[name](analysis)
        except TimeLimit:
            props[name] = _timed_out(name, timeout)
            timed_out = True
        except OverflowError as exc:        # SymPy's integer factoring of a huge number (python-flint's float())
            props[name] = unknown(f"SymPy failed on a huge number while deciding {name} (OverflowError: {exc})")
    props = {p: props[p] for p in PROPERTIES}
    kf = None
    try:
        with time_limit(stage_seconds(deadline, 1.0, time.monotonic())):
            if analysis.reduced and analysis.profile is not None:
                kf = analysis.kf    # sup |F'| over the pieces, also when P1 fails
            elif props["P1"].proved:
                kf = certify_kf_along_e2(design.f)      # df/de2 = psi(e2): sup |psi|
    except TimeLimit:
        kf = None
        timed_out = True
    except OverflowError:       # (as above: P1 says so)
        kf = None
    try:
        with time_limit(stage_seconds(deadline, 5.0, time.monotonic())), design_budget(design.f):   # the witnesses' own budget
            certificate, kernel = _kernel_check(Report(path, design, props, kf))
    except TimeLimit:
        certificate, kernel = None, {"checked": [], "search": [p for p, v in props.items() if v.proved or v.refuted],
                                     "stopped": "the kernel's re-check did not finish within --timeout"}
        timed_out = True
    try:        # after the kernel's re-check, which the verdicts need: the grace goes to it first
        with time_limit(stage_seconds(deadline, 5.0, time.monotonic())):
            proof = replay(design.f, analysis.p4.proved)
    except TimeLimit:
        proof = {"ok": False, "steps": {"replay": {"ok": False, "detail": "timed out"}}}
        timed_out = True
    for p, by in kernel.get("refuted_by", {}).items():      # (`_kernel_check`)
        props[p] = refuted(f"the witness of {by} refutes {p} as well: {props[by].reason} (the search had "
                           f"proved {p}, wrongly: {props[p].reason})", props[by].witness)
        certificate["properties"][p]["reason"] = props[p].reason
    # a verdict the kernel checked leaves nothing to the search (P4's identity included, `design_certificate.check`)
    props = {p: replace(v, details={**v.details, "unchecked": []}) if p in kernel["checked"] and v.details.get(
        "unchecked") else v for p, v in props.items()}
    if kernel_only:
        props = {p: kernel_verdict(p, v, kernel) for p, v in props.items()}
    checked_kf = kf
    if kernel_only:     # the kernel's kf: exact, infinite, or its own enclosure (`kf.kernel_bounds`)
        checked_kf = kf if kf_checked(certificate, kernel) else None
        if checked_kf is not None and kf.exact is None and kf.kernel_bounds is not None:
            L, U = kf.kernel_bounds
            checked_kf = replace(kf, lower=L, upper=U, reason=f"the kernel's enclosure: sup |F'| in "
                                             f"[{show(L)}, {show(U)}] (the search's: {kf.reason})")
            kf = checked_kf         # the report shows the enclosure the gain checks use
    gains = _gains(design, checked_kf)
    timed_out = timed_out or timeouts.expired != expired_before
    return Report(path, design, props, kf, gains, proof, seconds=time.monotonic() - start,
                  timed_out=timed_out, certificate=certificate, kernel=kernel, kernel_only=kernel_only)
