"""`make figures`: PNGs in the style of the paper's Figures 4-9.

For each path (circle: Figures 4-6, lemniscate: Figures 7-9) and each
design, plus the unsaturated baseline (38):

    figures/<path>_path.png      the paths in the plane with the reference (Fig. 4 / 7)
    figures/<path>_errors.png    xt, yt, tht against time (Fig. 5 / 8)
    figures/<path>_inputs.png    V and W against time with the +-limits (Fig. 6 / 9)

The runs are the 100 Hz digital loop with one sample of delay (as on the
robot), driven by the generated Python modules.  `path_figure`,
`errors_figure` and `inputs_figure` draw the same panels as matplotlib
Figures (no pyplot state) for `SimulationResult`'s plots.

    python -m uwmr_symbolic.simulation.figures [--out figures]
"""
from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from .api import _float_gains, paper_scenario  # noqa: E402
from .controllers import load_controllers, unsaturated_38  # noqa: E402
from .loop import run_digital  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
DESIGNS = [("design1_jiang", "Design 1"), ("design2_sqrt", "Design 2"), ("design3_logcosh", "Design 3"),
           ("design4_cosine", "Design 4"), ("design5_rational", "Design 5")]
COLORS = ["tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:brown"]
DPI = 80


def simulate_all(path: str, delay: int = 1):
    """[(label, color, Trajectory, gains)] for the baseline and the five designs."""
    from ..design import load_design
    sc = paper_scenario(path)
    runs = []
    base = load_design(ROOT / "designs" / "unsaturated_baseline.py")
    g = _float_gains(base.gains[path])
    runs.append(("Unsaturated (38)", "tab:red", run_digital(unsaturated_38, sc.reference, sc.pose0, g, delay=delay), g))
    for (stem, label), color in zip(DESIGNS, COLORS):
        d = ROOT / "designs" / f"{stem}.py"
        ctl = load_controllers(d)
        g = _float_gains(load_design(d).gains[path])
        runs.append((label, color, run_digital(ctl.python, sc.reference, sc.pose0, g, delay=delay), g))
    return sc, runs


def _grid(n):
    rows = 2 if n > 3 else 1
    return rows, math.ceil(n / rows)


def _save(fig, title: str, out: Path):
    fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    fig.savefig(out, dpi=DPI)


def _subplots(rows, cols, figsize, **kw):
    fig = Figure(figsize=figsize)
    return fig, fig.subplots(rows, cols, squeeze=False, **kw)


def plot_path(sc, runs, out: Path, fig_no: int):
    _save(path_figure(runs), f"Fig. {fig_no} (simulated): {sc.name}, path in the plane (100 Hz, 1 sample delay)", out)


def path_figure(runs) -> Figure:
    """One panel per run [(label, color, Trajectory, gains)]: robot and reference paths."""
    rows, cols = _grid(len(runs))
    fig, axes = _subplots(rows, cols, (3.3 * cols, 3.3 * rows), sharex=True, sharey=True)
    for ax, (label, color, tr, _) in zip(axes.flat, runs):
        ax.plot(tr.xr, tr.yr, "k--", lw=0.9, label="reference", zorder=3)
        ax.plot(tr.x, tr.y, color=color, lw=1.2, label="robot")
        ax.plot(tr.x[0], tr.y[0], "o", color=color, ms=4)
        ax.set_title(label, fontsize=10)
        ax.set_aspect("equal", adjustable="box")
        ax.grid(alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel("x [m]")
    for ax in axes[:, 0]:
        ax.set_ylabel("y [m]")
    for ax in list(axes.flat)[len(runs):]:
        ax.set_visible(False)
    axes.flat[0].legend(fontsize=7, loc="best")
    return fig


def plot_errors(sc, runs, out: Path, fig_no: int):
    _save(errors_figure(runs), f"Fig. {fig_no} (simulated): {sc.name}, position and orientation errors", out)


def errors_figure(runs) -> Figure:
    """xt, yt, tht of (5) against time, one curve per run."""
    fig, axes = _subplots(3, 1, (9, 7.5), sharex=True)
    axes = axes[:, 0]
    for label, color, tr, _ in runs:
        for ax, a in zip(axes, (tr.xr - tr.x, tr.yr - tr.y, tr.thr - tr.th)):
            ax.plot(tr.t, a, color=color, lw=1.0, label=label)
    for ax, name in zip(axes, ("x̃ [m]", "ỹ [m]", "θ̃ [rad]")):
        ax.set_ylabel(name)
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel("t [s]")
    axes[0].legend(fontsize=7, ncol=3, loc="upper right")
    return fig


def plot_inputs(sc, runs, out: Path, fig_no: int):
    _save(inputs_figure(runs), f"Fig. {fig_no} (simulated): {sc.name}, control inputs with the limits", out)


def inputs_figure(runs) -> Figure:
    """V and W against time, one curve per run, with the limits +-Vmax, +-Wmax of (6)."""
    fig, axes = _subplots(2, 1, (9, 6), sharex=True)
    axes = axes[:, 0]
    for label, color, tr, _ in runs:
        axes[0].plot(tr.t, tr.v, color=color, lw=0.9, label=label)
        axes[1].plot(tr.t, tr.w, color=color, lw=0.9, label=label)
    g = runs[-1][3]
    for ax, lim, name in ((axes[0], g["Vmax"], "V [m/s]"), (axes[1], g["Wmax"], "W [rad/s]")):
        for s in (1, -1):
            ax.axhline(s * lim, color="k", ls="--", lw=1.0)
        ax.set_ylabel(name)
        ax.grid(alpha=0.3)
        span = max(1.3 * lim, *(1.05 * float(np.max(np.abs(r[2].v if ax is axes[0] else r[2].w))) for r in runs))
        ax.set_ylim(-span, span)
    axes[0].text(0.0, g["Vmax"], f" +Vmax = {g['Vmax']:g} m/s", ha="left", va="bottom", fontsize=8)
    axes[1].text(0.0, g["Wmax"], f" +Wmax = {g['Wmax']:g} rad/s", ha="left", va="bottom", fontsize=8)
    axes[-1].set_xlabel("t [s]")
    axes[0].legend(fontsize=7, ncol=3, loc="lower right")
    return fig


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description="PNGs in the style of the paper's Figures 4-9")
    ap.add_argument("--out", default=str(ROOT / "figures"))
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for path, first in (("circle", 4), ("lemniscate", 7)):
        sc, runs = simulate_all(path)
        for fn, no, what in ((plot_path, first, "path"), (plot_errors, first + 1, "errors"),
                             (plot_inputs, first + 2, "inputs")):
            p = out / f"{path}_{what}.png"
            fn(sc, runs, p, no)
            written.append(p)
    total = sum(p.stat().st_size for p in written)
    for p in written:
        print(f"{p}  {p.stat().st_size / 1024:.0f} KiB")
    print(f"{len(written)} figures, {total / 1024:.0f} KiB in all")
    return 0


if __name__ == "__main__":
    sys.exit(main())
