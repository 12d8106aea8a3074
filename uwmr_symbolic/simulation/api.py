"""`simulate_design`: run every gain scenario of a design on its path.

A scenario named ``circle`` or ``lemniscate`` runs the paper's experiment
(SPEC.md, Section 5); any other scenario needs a reference passed in
`references` ({name: Reference} or {name: Scenario}).

    circle      reference (2) from xr = yr = thr = 0, Vr = 0.5 m/s, Wr = 1 rad/s
                (diameter 1 m, centre (0, 0.5), counter-clockwise); robot at
                (2.00 m, 2.00 m, -2 pi rad); 80 s; RMS window 60-80 s
    lemniscate  (39)-(43), thr(0) = atan2(2, 1) = 1.1071 rad, continuous after;
                robot at (-1.00 m, -1.80 m, -pi rad); 200 s; RMS window 160-200 s

For each scenario: the continuous-time loop and the 100 Hz digital loop, each
driven by the generated C (ctypes) and by the generated Python module (the
two trajectories compared), and the paper's unsaturated baseline (38) as
printed (continuous time, gains of the same scenario in
`designs/unsaturated_baseline.py`).  With baseline="both" the generated code
of that file -- law (9) with f = rho/2, which keeps tanh in V and in the k2
term -- runs too, as "baseline_generated"."""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import reference as refs
from .controllers import load_controllers
from .loop import run_continuous, run_digital
from .metrics import ANG_TOL, POS_TOL, f_numeric, metrics

REFERENCE_SLACK = 1e-9
BASELINE = Path(__file__).resolve().parents[2] / "designs" / "unsaturated_baseline.py"


@dataclass
class Scenario:
    name: str
    reference: refs.Reference
    pose0: tuple
    window: tuple
    description: str = ""

    @property
    def duration(self) -> float:
        return self.reference.t1 - self.reference.t0


_PAPER: dict = {}


def paper_scenario(name: str) -> Scenario:
    if name not in _PAPER:
        if name == "circle":
            _PAPER[name] = Scenario("circle", refs.circle(), (2.0, 2.0, -2 * math.pi), (60.0, 80.0),
                                    "paper circle: diameter 1 m, centre (0, 0.5), reference from (0, 0) "
                                    "heading 0; robot from (2, 2, -2 pi); 80 s")
        elif name == "lemniscate":
            _PAPER[name] = Scenario("lemniscate", refs.lemniscate(), (-1.0, -1.8, -math.pi), (160.0, 200.0),
                                    "paper lemniscate (39)-(43); robot from (-1, -1.8, -pi); 200 s")
        else:
            raise KeyError(name)
    return _PAPER[name]


def scenario_for(name: str, references=None) -> Scenario | None:
    references = references or {}
    if name in references:
        r = references[name]
        if isinstance(r, Scenario):
            return r
        # a bare Reference: start 0.5 m beside the reference, same heading;
        # RMS over the last quarter of the run
        xr, yr, thr, _, _ = r.at(r.t0)
        dur = r.t1 - r.t0
        return Scenario(name, r, (xr - 0.5, yr - 0.5, thr), (r.t1 - dur / 4, r.t1),
                        f"{r.description}; robot from reference start - (0.5, 0.5) m")
    if name in ("circle", "lemniscate"):
        return paper_scenario(name)
    return None


def _float_gains(g: dict) -> dict:
    return {k: float(v) for k, v in g.items()}


def reference_speeds(ref: refs.Reference, gains: dict, dt: float = 1e-3) -> dict:
    """The reference's largest |vr| and |wr| on a grid of step dt (a lower
    bound of each sup) against the scenario's Vr_max and Wr_max, with which
    bound (10) was checked: `within` is false when the grid shows the
    reference beyond them by more than REFERENCE_SLACK (relative: the
    rounding of a spline's derivative through long or far waypoints), and
    `beyond` then says so in one line."""
    t = np.linspace(ref.t0, ref.t1, max(2, int(math.ceil((ref.t1 - ref.t0) / dt)) + 1))
    _, _, _, vr, wr = ref(t)
    out = dict(max_abs_vr=float(np.max(np.abs(vr))), max_abs_wr=float(np.max(np.abs(wr))),
               Vr_max=float(gains["Vr_max"]), Wr_max=float(gains["Wr_max"]))
    beyond = [f"|{n}| reaches {out['max_abs_' + n]:.9g} at t = {t[np.argmax(np.abs(a))]:.6g} s, beyond "
              f"{n.capitalize()}_max = {limit:.6g}"
              for n, a, limit in (("vr", vr, out["Vr_max"]), ("wr", wr, out["Wr_max"]))
              if out["max_abs_" + n] > limit * (1 + REFERENCE_SLACK)]
    out.update(within=not beyond, beyond="; ".join(beyond) or None)
    return out


def _verified(report) -> bool:
    from ..codegen import not_verified_reasons
    return not not_verified_reasons(report)


def run_pair(ctl, kind, sc, gains, backends=("c", "python"), **kw):
    """The same run with each back-end; returns {backend: Trajectory}."""
    fn = run_continuous if kind == "continuous" else run_digital
    return {b: fn(ctl.backend(b), sc.reference, sc.pose0, gains, **kw) for b in backends}


def simulate_scenario(ctl, design, sc: Scenario, gains: dict, verified=True, backends=("c", "python"),
                      delay=0, noise=None, seed=0, kinds=("continuous", "digital"), keep=False) -> dict:
    g = _float_gains(gains)
    f_num = f_numeric(design.f)
    out = {}
    for kind in kinds:
        kw = dict(delay=delay, noise=noise, seed=seed) if kind == "digital" else {}
        runs = run_pair(ctl, kind, sc, g, backends=backends, **kw)
        first = runs[backends[0]]
        other = runs[backends[1]] if len(backends) > 1 else None
        m = metrics(first, g, sc.window, f_num=f_num, lam=g["lam"], other=other, verified=verified)
        m["backend"] = backends[0]
        if kind == "continuous":
            m["integrator"] = dict(method=first.info["method"], rtol=first.info["rtol"],
                                   atol=first.info["atol"], nfev=first.info["nfev"])
        else:
            m["sampling"] = dict(rate_hz=1.0 / first.info["h"], delay_samples=delay,
                                 noise=list(noise) if noise else None, seed=seed)
        if keep:
            m["_trajectory"] = first
        out[kind] = m
    return out


def simulate_38(base_design, sc: Scenario, gains, keep=False) -> dict:
    """The paper's baseline (38) in continuous time (gains of designs/unsaturated_baseline.py)."""
    from .controllers import unsaturated_38
    g = _float_gains(gains)
    tr = run_continuous(unsaturated_38, sc.reference, sc.pose0, g)
    m = metrics(tr, g, sc.window, f_num=f_numeric(base_design.f), lam=g["lam"], verified=False)
    m["backend"] = "(38) as printed, numpy"
    m["integrator"] = dict(method=tr.info["method"], rtol=tr.info["rtol"], atol=tr.info["atol"],
                           nfev=tr.info["nfev"])
    if keep:
        m["_trajectory"] = tr
    return m


def _load(path, report=None):
    from ..verify import verify_design
    if report is None:
        report = verify_design(path)
    if report.design is None:
        raise ValueError(f"{path}: unusable design: {report.error}")
    return report


def simulate_design(design_path, report=None, monte_carlo=0, seed=0, references=None, delay=0,
                    noise=None, baseline=True, backends=("c", "python"), progress=None,
                    keep_trajectories=False) -> dict:
    """{scenario: {"continuous": M, "digital": M, "baseline": M, "ok": bool, ...}}.

    `report`: the verifier's Report (avoids verifying again).  `monte_carlo`:
    number of random initial poses per scenario (digital loop, batch), seeded
    by `seed`.  `delay` (samples) and `noise` ((sigma_xy, sigma_theta), seeded)
    apply to the digital loop.  A scenario without a known path is reported as
    skipped (ok stays true).  M["ok"] false marks a failed check; the
    scenario's "ok" is the conjunction over continuous and digital (the
    baseline is there for comparison and never counts).  With
    `keep_trajectories` each M also holds its `Trajectory` under
    "_trajectory"; `uwmr_symbolic.simulate` returns one scenario's runs with
    their trajectories as a `SimulationResult` instead."""
    report = _load(design_path, report)
    design = report.design
    verified = _verified(report)
    ctl = load_controllers(design_path, report=report)
    base = None
    result = {}
    for name, gains in design.gains.items():
        sc = scenario_for(name, references)
        if sc is None:
            result[name] = dict(skipped=f"no reference for scenario {name!r} (only circle and lemniscate are "
                                        f"built in; pass references={{{name!r}: Reference}})", ok=True)
            continue
        entry = simulate_scenario(ctl, design, sc, gains, verified=verified, backends=backends,
                                  delay=delay, noise=noise, seed=seed, keep=keep_trajectories)
        entry["baseline"] = entry["baseline_generated"] = None
        if baseline and name in ("circle", "lemniscate") and BASELINE.exists():
            if base is None:
                brep = _load(BASELINE)
                base = (brep.design, load_controllers(BASELINE, report=brep))
            bgains = base[0].gains.get(name)
            if bgains is not None:
                entry["baseline"] = simulate_38(base[0], sc, bgains, keep=keep_trajectories)
                if baseline == "both":
                    b = simulate_scenario(base[1], base[0], sc, bgains, verified=False, backends=("c",),
                                          kinds=("continuous",), keep=keep_trajectories)
                    entry["baseline_generated"] = b["continuous"]
        entry["scenario"] = dict(description=sc.description, initial_pose=list(sc.pose0),
                                 duration=sc.duration, rms_window=list(sc.window),
                                 reference=sc.reference.description)
        entry["reference_speeds"] = speeds = reference_speeds(sc.reference, gains)
        if not speeds["within"]:                    # a limit exceeded is not the controller's fault alone
            for kind in ("continuous", "digital"):
                entry[kind]["failed"] = [f"{c} (the reference exceeds Vr_max or Wr_max)" if c in ("V limit", "W limit")
                                         else c for c in entry[kind]["failed"]]
        if monte_carlo:
            entry["monte_carlo"] = monte_carlo_scenario(ctl, sc, gains, monte_carlo, seed=seed,
                                                        progress=progress, delay=delay)
        entry["ok"] = all(entry[k]["ok"] for k in ("continuous", "digital")) and (
            not monte_carlo or entry["monte_carlo"]["ok"])
        result[name] = entry
    return result


def random_poses(sc: Scenario, n: int, seed: int = 0, radius: float = 3.0) -> np.ndarray:
    """N initial poses: position uniform in the disc of `radius` m around the
    reference's start, heading uniform in thr(0) + [-2 pi, 2 pi]."""
    rng = np.random.default_rng(seed)
    xr, yr, thr, _, _ = sc.reference.at(sc.reference.t0)
    r = radius * np.sqrt(rng.uniform(0, 1, n))
    a = rng.uniform(-math.pi, math.pi, n)
    th = thr + rng.uniform(-2 * math.pi, 2 * math.pi, n)
    return np.stack([xr + r * np.cos(a), yr + r * np.sin(a), th], axis=1)


def monte_carlo_scenario(ctl, sc: Scenario, gains, n: int, seed: int = 0, progress=None, delay=0,
                         radius: float = 3.0, max_witnesses: int = 10, backend="python") -> dict:
    """N random initial poses in one vectorised digital run (100 Hz)."""
    import sys
    g = _float_gains(gains)
    poses = random_poses(sc, n, seed, radius)
    if progress is None:
        progress = sys.stderr.isatty()
    tr = run_digital(ctl.backend(backend), sc.reference, poses, g, delay=delay, record=False,
                     tol=(POS_TOL, ANG_TOL), progress=progress, window=sc.window)
    info = tr.info
    xt, yt, tht = tr.xr[-1] - tr.x, tr.yr[-1] - tr.y, tr.thr[-1] - tr.th
    conv = (np.hypot(xt, yt) <= POS_TOL) & (np.abs(tht) <= ANG_TOL)
    v_ok = info["max_abs_v"] <= g["Vmax"] * (1 + 1e-12)
    w_ok = info["max_abs_w"] <= g["Wmax"] * (1 + 1e-12)
    settle = np.where(conv, info["settle_time"], np.inf)
    bad = np.nonzero(~conv | ~v_ok | ~w_ok)[0]
    witnesses = []
    for i in bad[:max_witnesses]:
        why = [w for w, c in (("not converged", conv[i]), ("|V| > Vmax", v_ok[i]), ("|W| > Wmax", w_ok[i])) if not c]
        witnesses.append(dict(index=int(i), seed=seed, pose=[float(a) for a in poses[i]], why=why,
                              final_errors=dict(x=float(xt[i]), y=float(yt[i]), theta=float(tht[i])),
                              max_abs_v=float(info["max_abs_v"][i]), max_abs_w=float(info["max_abs_w"][i])))
    slow = int(np.argmax(np.where(conv, settle, -np.inf))) if conv.any() else None
    return dict(n=n, seed=seed, backend=backend, sampling_hz=1.0 / info["h"], delay_samples=delay,
                pose_distribution=f"position uniform in the disc of radius {radius} m around the reference "
                                  f"start, heading thr(0) + U(-2 pi, 2 pi)",
                converged_share=float(conv.mean()), within_limits_share=float((v_ok & w_ok).mean()),
                max_abs_v=float(info["max_abs_v"].max()), max_abs_w=float(info["max_abs_w"].max()),
                slowest=None if slow is None else dict(index=slow, pose=[float(a) for a in poses[slow]],
                                                       settle_time=float(settle[slow])),
                failures=int(bad.size), witnesses=witnesses, ok=bool(bad.size == 0))


def _num(x, fmt="{:.4g}"):
    return "-" if x is None else fmt.format(x)


def render_simulation_text(result: dict) -> str:
    """The simulation part of the text report."""
    lines = []
    for name, entry in result.items():
        if "skipped" in entry:
            lines.append(f"simulation {name}: skipped ({entry['skipped']})")
            continue
        sc = entry["scenario"]
        lines.append(f"simulation {name}: {'ok' if entry['ok'] else 'FAILED'} -- {sc['description']}")
        lines.append(f"  {'run':<11} {'max|V|':>8} {'max|W|':>8}  {'RMS xt':>8} {'yt':>8} {'tht':>8} "
                     f"{'V':>7} {'W':>7}  {'final |e|':>9} {'conv':>4} {'max dU':>8} {'C-Py':>8}  ok")
        for kind in ("continuous", "digital", "baseline", "baseline_generated"):
            m = entry.get(kind)
            if m is None:
                continue
            r = m["rms"]
            fe = m["final_errors"]
            flag_v = "" if m["v_ok"] else "!"
            flag_w = "" if m["w_ok"] else "!"
            label = {"baseline": "base (38)", "baseline_generated": "base f=r/2"}.get(kind, kind)
            lines.append(
                f"  {label:<11} {m['max_abs_v']:>7.4f}{flag_v or ' '} {m['max_abs_w']:>7.4f}{flag_w or ' '} "
                f"{r['x']:>8.2e} {r['y']:>8.2e} {r['theta']:>8.2e} {r['v']:>7.4f} {r['w']:>7.4f}  "
                f"{math.hypot(fe['x'], fe['y']):>9.2e} {'yes' if m['converged'] else 'no':>4} "
                f"{_num(m['max_lyapunov_increase'], '{:.1e}'):>8} {_num(m['c_python_max_diff'], '{:.1e}'):>8}  "
                + ("ok" if m["ok"] else "FAILED: " + ", ".join(m["failed"])) + ("  (comparison only)" if kind.startswith("baseline") else ""))
        if not entry["reference_speeds"]["within"]:
            lines.append(f"  the reference is beyond the scenario's declared limits: "
                         f"{entry['reference_speeds']['beyond']} (bound (10) was checked with them, so it does not "
                         f"cover this run)")
        for kind in ("continuous", "baseline"):
            if (entry.get(kind) or {}).get("lyapunov_note"):
                lines.append(f"  {kind}: {entry[kind]['lyapunov_note']}: max dU unchecked")
        m = entry["continuous"]
        lines.append(f"  limits Vmax = {m['Vmax']}, Wmax = {m['Wmax']} ('!' = exceeded); RMS over "
                     f"{sc['rms_window'][0]:g}-{sc['rms_window'][1]:g} s; converged: final |(xt, yt)| <= "
                     f"{m['tolerances']['position']} m and |tht| <= {m['tolerances']['angle']} rad")
        mc = entry.get("monte_carlo")
        if mc:
            lines.append(f"  monte-carlo: {mc['n']} poses (seed {mc['seed']}), converged {100 * mc['converged_share']:.1f}%, "
                         f"within limits {100 * mc['within_limits_share']:.1f}%, max|V| {mc['max_abs_v']:.4f}, "
                         f"max|W| {mc['max_abs_w']:.4f}")
            if mc["slowest"]:
                s = mc["slowest"]
                lines.append(f"    slowest: #{s['index']} from ({s['pose'][0]:.4f}, {s['pose'][1]:.4f}, "
                             f"{s['pose'][2]:.4f}) settles at {s['settle_time']:.2f} s")
            for w in mc["witnesses"]:
                lines.append(f"    witness #{w['index']} (seed {w['seed']}) from ({w['pose'][0]:.6f}, "
                             f"{w['pose'][1]:.6f}, {w['pose'][2]:.6f}): {', '.join(w['why'])}")
            if mc["failures"] > len(mc["witnesses"]):
                lines.append(f"    ... {mc['failures'] - len(mc['witnesses'])} more")
    return "\n".join(lines)
