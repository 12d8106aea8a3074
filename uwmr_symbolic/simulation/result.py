"""`SimulationResult`: one closed-loop simulation of a design on one path,
returned by `uwmr_symbolic.simulate`, with its trajectories, checks and plots
(Figures 4-9 of the paper: path, errors (5), inputs with the limits (6), and
the Lyapunov function U of (15) along the run)."""
from __future__ import annotations

import html
from dataclasses import dataclass, field

import numpy as np
import sympy as sp
from matplotlib.figure import Figure

from .api import Scenario
from .loop import Trajectory

LABELS = {"continuous": "continuous time", "digital": "100 Hz digital", "baseline": "unsaturated (38)"}
COLORS = {"continuous": "tab:blue", "digital": "tab:green", "baseline": "tab:red"}


def jsonable(obj):
    """Plain Python (dict, list, str, float, int, bool, None) for json.dumps."""
    if isinstance(obj, dict):
        return {str(k): jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [jsonable(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return jsonable(obj.tolist())
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, (str, int, float, bool)) or obj is None:
        return obj
    return str(obj)


@dataclass
class SimulationResult:
    """A design's controller (9) in closed loop with (1) along one reference.

    ``runs[kind]`` holds the checks of each run (``continuous``, ``digital``,
    and ``baseline`` for the unsaturated controller (38) when asked):
    ``max_abs_v``, ``max_abs_w`` against ``Vmax``, ``Wmax`` of (6), ``rms`` over
    the scenario's window, ``converged``, ``max_lyapunov_increase`` of U (15),
    ``ok``.  ``trajectories[kind]`` is the `Trajectory` itself (arrays ``t``,
    ``x``, ``y``, ``th``, ``xr``, ``yr``, ``thr``, ``v``, ``w`` and ``e`` =
    (e1, e2, e3) of (7))."""

    name: str
    scenario: Scenario
    gains: dict
    runs: dict
    trajectories: dict[str, Trajectory] = field(repr=False)
    f: sp.Expr = field(repr=False, default=None)
    verified: bool = True

    @property
    def ok(self) -> bool:
        """Every run of the design itself passed its checks (the baseline (38)
        is there for comparison and never counts)."""
        return all(m["ok"] for kind, m in self.runs.items() if kind != "baseline")

    def lyapunov(self, kind: str = "continuous") -> tuple[np.ndarray, np.ndarray]:
        """(t, U(t)) with U = lam f(e1, e2) + e3^2/2, the function (15) whose
        derivative (19) is <= 0 along the closed loop."""
        from .metrics import f_numeric
        tr = self.trajectories[kind]
        a, b, c = tr.e
        return tr.t, self.gains["lam"] * f_numeric(self.f)(a, b) + 0.5 * c * c

    def to_dict(self) -> dict:
        """The checks as plain JSON-able data (no trajectories)."""
        sc = self.scenario
        return jsonable({"design": self.name, "ok": self.ok, "verified": self.verified, "gains": self.gains,
                         "scenario": {"name": sc.name, "description": sc.description,
                                      "initial_pose": list(sc.pose0), "duration": sc.duration,
                                      "rms_window": list(sc.window)},
                         "runs": self.runs})

    def _repr_html_(self) -> str:
        sc = self.scenario
        rows = []
        for kind, m in self.runs.items():
            r = m["rms"]
            v = f"{m['max_abs_v']:.4f}" + ("" if m["v_ok"] else " <b>&gt; Vmax</b>")
            w = f"{m['max_abs_w']:.4f}" + ("" if m["w_ok"] else " <b>&gt; Wmax</b>")
            status = "ok" if m["ok"] else "FAILED: " + html.escape(", ".join(m.get("failed", [])))
            rows.append(f"<tr><td>{LABELS.get(kind, kind)}</td><td>{v}</td><td>{w}</td>"
                        f"<td>{r['x']:.2e}</td><td>{r['y']:.2e}</td><td>{r['theta']:.2e}</td>"
                        f"<td>{'yes' if m['converged'] else 'no'}</td><td>{status}</td></tr>")
        head = ("<tr><th>run</th><th>max |V|</th><th>max |W|</th><th>RMS x̃</th><th>RMS ỹ</th><th>RMS θ̃</th>"
                "<th>converged</th><th>checks</th></tr>")
        return (f"<div><b>{html.escape(self.name)}</b> on <b>{html.escape(sc.name)}</b>: "
                f"{'ok' if self.ok else 'FAILED'}<br><small>{html.escape(sc.description)}; limits (6) "
                f"Vmax = {self.gains['Vmax']:g} m/s, Wmax = {self.gains['Wmax']:g} rad/s; RMS over "
                f"{sc.window[0]:g}-{sc.window[1]:g} s</small>"
                f"<table>{head}{''.join(rows)}</table></div>")

    # ---------------------------------------------------------------- plots

    def _runs(self, kinds):
        kinds = list(self.trajectories) if kinds is None else list(kinds)
        out = []
        for kind in kinds:
            g = self.gains if kind != "baseline" else {**self.gains, **{k: self.runs[kind][k]
                                                                         for k in ("Vmax", "Wmax")}}
            out.append((f"{self.name}, {LABELS.get(kind, kind)}" if kind != "baseline" else LABELS[kind],
                        COLORS.get(kind, "tab:gray"), self.trajectories[kind], g))
        return out

    def _title(self, fig: Figure, what: str) -> Figure:
        fig.suptitle(f"{self.name}, {self.scenario.name}: {what}", fontsize=11)
        fig.tight_layout()
        return fig

    def plot_path(self, kinds=None) -> Figure:
        """Robot and reference paths in the plane, one panel per run (Figures 4 and 7)."""
        from .figures import path_figure
        return self._title(path_figure(self._runs(kinds)), "path in the plane")

    def plot_errors(self, kinds=None) -> Figure:
        """x̃, ỹ, θ̃ of (5) against time (Figures 5 and 8)."""
        from .figures import errors_figure
        return self._title(errors_figure(self._runs(kinds)), "position and orientation errors")

    def plot_inputs(self, kinds=None) -> Figure:
        """V and W against time with the limits +-Vmax, +-Wmax of (6) (Figures 6 and 9)."""
        from .figures import inputs_figure
        return self._title(inputs_figure(self._runs(kinds)), "control inputs with the limits (6)")

    def plot_lyapunov(self, kinds=("continuous",)) -> Figure:
        """U(t) = lam f(e1, e2) + e3^2/2 of (15) along the runs (non-increasing by (19))."""
        fig = Figure(figsize=(8, 3.5))
        ax = fig.subplots()
        positive = True
        for kind in kinds:
            t, U = self.lyapunov(kind)
            positive = positive and bool(np.all(U > 0))
            ax.plot(t, U, color=COLORS.get(kind, "tab:gray"), lw=1.2, label=LABELS.get(kind, kind))
        if positive:
            ax.set_yscale("log")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("U = λ f(e1, e2) + e3²/2")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        return self._title(fig, "Lyapunov function (15) along the run")
