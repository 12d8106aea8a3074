"""Rendering a `Report` as a readable table or as one JSON object."""
from __future__ import annotations

import json
import math

import sympy as sp

from .interval import Interval
from .verify import Report

MARK = {"proved": "proved ", "refuted": "REFUTED", "unknown": "unknown"}


def _num(x):
    """A float for JSON (None for infinite/undecided)."""
    if x is None:
        return None
    v = float(sp.N(x, 30)) if isinstance(x, sp.Basic) else float(x)
    return v if math.isfinite(v) else None


def _jsonable(obj):
    if isinstance(obj, dict):
        return {str(k): _jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_jsonable(v) for v in obj]
    if isinstance(obj, (str, int, float, bool)) or obj is None:
        return obj
    return str(obj)


def to_dict(r: Report) -> dict:
    if r.error is not None:
        return {"design": str(r.path), "error": r.error, "exit_status": r.exit_status}
    kf = r.kf
    d = {
        "design": str(r.path),
        "name": r.design.name if r.design else None,
        "f": str(r.design.f) if r.design else None,
        "properties": {p: {"verdict": v.status, "reason": v.reason,
                           "witness": _jsonable(v.witness), **_jsonable(v.details)}
                       for p, v in r.properties.items()},
        "kf": {"exact": None if kf is None or kf.exact is None else str(kf.exact),
               "lower": None if kf is None or kf.lower is None else Interval.point(kf.lower).lower_float(),
               "upper": None if kf is None or kf.upper is None else Interval.point(kf.upper).upper_float(),
               "attained": None if kf is None else kf.attained,
               "reason": "undecided (f not radial or P1 not analysed)" if kf is None else kf.reason},
        "gains": {name: {"V_bound": _num(g.V_bound), "W_bound": _num(g.W_bound),
                         "V_margin": str(g.V_margin), "W_margin": None if g.W_margin is None else str(g.W_margin),
                         "V_ok": g.V_ok, "W_ok": g.W_ok, "lam_max": _num(g.lam_max),
                         "lam_max_exact": None if g.lam_max is None else str(g.lam_max)}
                  for name, g in r.gains.items()},
        "proof_replay": r.proof_replay,
        "seconds": round(r.seconds, 3),
        "exit_status": r.exit_status,
    }
    return d


def render_json(r: Report) -> str:
    return json.dumps(to_dict(r), indent=2)


def _fmt(x, digits=10):
    if x is None:
        return "inf"
    return f"{float(sp.N(x, 30)):.{digits}g}"


def render_text(r: Report) -> str:
    if r.error is not None:
        return f"{r.path}: {r.error}"
    lines = []
    title = r.design.name if r.design else r.path.name
    lines.append(f"{r.path}  —  {title}")
    if r.design:
        lines.append(f"  f = {r.design.f}")
    lines.append("")
    for p, v in r.properties.items():
        lines.append(f"  {p}  {MARK[v.status]}  {v.reason}")
        if v.witness is not None and not v.proved:
            lines.append(f"               witness: {json.dumps(_jsonable(v.witness))}")
    kf = r.kf
    lines.append("")
    if kf is None:
        lines.append("  kf: undecided")
    elif kf.upper is None:
        lines.append(f"  kf: {'infinite' if kf.unbounded_witness else 'undecided'} — {kf.reason}")
    else:
        att = {True: "attained", False: "approached at infinity, not attained", None: "attainment undecided"}
        exact = f"{kf.exact} = " if kf.exact is not None else ""
        lines.append(f"  kf = {exact}{float(kf.upper):.12g}  enclosure [{float(kf.lower):.12g}, "
                     f"{float(kf.upper):.12g}]  ({att[kf.attained]})")
    if r.gains:
        lines.append("")
        lines.append("  bound (10)     |V| bound  margin          |W| bound  margin          lam_max")
        for name, g in r.gains.items():
            v_ok = "PASS" if g.V_ok else "FAIL"
            w_ok = {True: "PASS", False: "FAIL", None: "????"}[g.W_ok]
            w_margin = "—" if g.W_margin is None else f"{float(sp.N(g.W_margin, 30)):+.3e}"
            lines.append(f"  {name:<12} {_fmt(g.V_bound, 8):>10}  {float(sp.N(g.V_margin, 30)):+.3e} {v_ok}"
                         f"  {_fmt(g.W_bound, 8):>10}  {w_margin} {w_ok}  {_fmt(g.lam_max, 8) if g.lam_max is not None else '?'}")
    lines.append("")
    pr = r.proof_replay
    lines.append(f"  proof replay: {'ok' if pr.get('ok') else 'NOT ok'} — "
                 + "; ".join(f"{k}: {'ok' if s['ok'] else 'no'}" for k, s in pr.get("steps", {}).items()))
    status = {0: "all properties proved, gains within the limits", 1: "REFUTED or a gain check fails",
              3: "inconclusive"}[r.exit_status]
    lines.append(f"  => {status}  ({r.seconds:.2f} s)")
    return "\n".join(lines)
