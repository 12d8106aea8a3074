"""A `Report` in a notebook: the HTML table of `Report._repr_html_` and the
plot of the radial profile F (`Report.plot_profile`)."""
from __future__ import annotations

import html
import math

import numpy as np
import sympy as sp
from matplotlib.figure import Figure

from .report import MARK, kf_upper_text, no_w_bound, status_text, to_dict

COLOR = {"proved": "#1a7f37", "refuted": "#cf222e", "unknown": "#9a6700"}


def _latex_f(report) -> str:
    d = report.design
    params = ", ".join(f"{sp.latex(sp.Symbol(k))} = {sp.latex(v)}" for k, v in d.params.items())
    return (rf"\(f(e_1, e_2) = {sp.latex(d.f_source)}\)"
            + (rf" with \({params}\)" if params else ""))


def _kf_text(d: dict) -> str:
    kf = d["kf"]
    if kf["upper"] is None:
        return f"kf {'infinite' if kf.get('unbounded') else 'undecided'}: {kf['reason']}"
    att = {True: "attained", False: "approached at infinity, not attained", None: "attainment undecided"}
    if kf["exact"] is not None:
        digits = f" = {kf['exact_digits']}…" if kf.get("exact_digits") else ""
        return f"kf = {kf['exact']}{digits} ({att[kf['attained']]})"
    return f"kf in {kf['enclosure']} ({att[kf['attained']]})"


def report_html(report) -> str:
    """Verdicts of P1-P8 with their reasons, kf, bound (10) per gain scenario,
    the proof replay and the outcome, with f in LaTeX."""
    d = to_dict(report)
    esc = html.escape
    if d.get("error") is not None:
        return f"<div><b>{esc(d['design'])}</b>: unusable design: {esc(d['error'])}</div>"
    parts = [f"<div><b>{esc(d.get('name') or '')}</b> <small>({esc(d['design'])})</small><br>"]
    if report.design is not None:
        parts.append(f"<p>{esc(_latex_f(report))}</p>")
    rows = "".join(f"<tr><td>{p}</td><td style='color:{COLOR[v['verdict']]}'><b>{MARK[v['verdict']].strip()}</b>"
                   f"</td><td style='text-align:left'>{esc(v['reason'])}"
                   + ("" if v.get("witness") is None or v["verdict"] == "proved"
                      else f"<br><small>witness: {esc(str(v['witness']))}</small>") + "</td></tr>"
                   for p, v in d["properties"].items())
    parts.append(f"<table><tr><th>property</th><th>verdict</th><th>reason</th></tr>{rows}</table>")
    parts.append(f"<p>{esc(_kf_text(d))}</p>")
    if d["gains"]:
        word = {True: "PASS", False: "FAIL", None: "unchecked"}
        grows = "".join(
            f"<tr><td>{esc(n)}</td><td>{t['V_bound']}</td><td>{t['V_margin']} {word[g['V_ok']]}</td>"
            f"<td>{t['W_bound'] or no_w_bound(g, '∞')}</td><td>{t['W_margin'] or '—'} {word[g['W_ok']]}</td>"
            f"<td>{t['lam_max'] or '?'}</td></tr>"
            for n, g in d["gains"].items() for t in [g["text"]])
        parts.append("<table><tr><th>bound (10)</th><th>|V| bound</th><th>margin</th><th>|W| bound</th>"
                     f"<th>margin</th><th>largest λ</th></tr>{grows}</table>")
    pr = d["proof_replay"]
    parts.append(f"<p>proof replay (11)-(19): {'not run' if not pr.get('steps') else 'ok' if pr.get('ok') else 'NOT ok'}<br>"
                 f"<b>{esc(status_text(d))}</b> (exit status {d['exit_status']}, {d['seconds']:.2f} s)</p></div>")
    return "".join(parts)


def profile_figure(report, s_max: float = 10.0, points: int = 2000) -> Figure:
    """F(s) = f(s, 0), F'(s) and F'(s)/s over 0 < s <= s_max (s = |(e1, e2)|
    for a radial f), with the certified kf of P1 (|F'| <= kf) and the k of P6
    (F'/s <= k) drawn as dashed lines."""
    from .profile import S, radial_profile
    if report.design is None:
        raise ValueError(f"the report is of an unusable design: {report.error}")
    F = radial_profile(report.design.f)
    dF = sp.diff(F, S)
    s = np.linspace(s_max / points, s_max, points)
    values = []
    for expr in (F, dF, dF / S):
        fn = sp.lambdify(S, expr, modules="numpy")
        with np.errstate(all="ignore"):
            values.append(np.asarray(fn(s), dtype=float) * np.ones_like(s))
    d = to_dict(report)
    fig = Figure(figsize=(10, 3.4))
    axes = fig.subplots(1, 3)
    for ax, y, label in zip(axes, values, ("F(s)", "F′(s)", "F′(s)/s")):
        ax.plot(s, y, lw=1.4)
        ax.set_title(label)
        ax.set_xlabel("s = |(e1, e2)|")
        ax.grid(alpha=0.3)
    kf = d["kf"]
    if kf["upper"] is not None:
        axes[1].axhline(kf["upper"], color="tab:red", ls="--", lw=1.0, label=f"kf = {_short(kf)}")
        axes[1].legend(fontsize=8, loc="lower right")
    k6 = d["properties"].get("P6", {}).get("k_float")
    if k6 is not None and math.isfinite(k6):
        axes[2].axhline(k6, color="tab:purple", ls="--", lw=1.0, label=f"k of P6 = {k6:.6g}")
        axes[2].legend(fontsize=8, loc="upper right")
    radial = d["properties"].get("P4", {}).get("verdict") == "proved"
    fig.suptitle(f"{d.get('name')}: radial profile F of f" + ("" if radial else " (f is not radial: f(s, 0))"),
                 fontsize=11)
    fig.tight_layout()
    return fig


def _short(kf: dict) -> str:
    return kf["exact"] if kf["exact"] is not None and len(kf["exact"]) <= 12 else kf_upper_text(kf)
