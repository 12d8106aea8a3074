"""Closed loop (1) + (7) + (9): the unicycle driven by a generated controller.

* `run_continuous` -- continuous time: the commands are evaluated at every
  right-hand-side call of scipy's `solve_ivp` (DOP853, rtol = 1e-10,
  atol = 1e-10 on x [m], y [m], theta [rad] by default); the trajectory is
  then read on a uniform 1 kHz grid from the dense output.
* `run_digital` -- the paper's implementation: the pose is sampled every
  h = 0.01 s (100 Hz), the command computed from the sample is applied after
  `delay` samples and held constant (zero-order hold) until the next one.
  Under a constant (V, W) the unicycle is integrated exactly,
      (x, y) += V h sinc(W h/2) (cos, sin)(theta + W h/2),  theta += W h,
  so the digital loop has no integration error at all.  Before the first
  command arrives (delay > 0) the robot stands still.  Optional pose noise:
  seeded Gaussian noise on the measured x, y [m] and theta [rad].  Vectorised:
  `pose0` may hold N initial poses, simulated together (batch / Monte-Carlo).

Errors (7): e1 = cos th xt + sin th yt, e2 = -sin th xt + cos th yt,
e3 = thr - th with NO wrapping (xt = xr - x, yt = yr - y), computed by the
generated code that drives the loop (`control.errors`, see
`controllers.Backend`): C errors with the C law, Python with Python.  The
simulated headings are continuous, so the tracker that the firmware uses on
top of them (`_step`) would leave them as they are."""
from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp

RTOL, ATOL = 1e-10, 1e-10
SAMPLE_PERIOD = 0.01


def _errors(control):
    """The errors (7) that go with `control`: its own generated ones
    (`controllers.Backend.errors`), else the generated Python ones."""
    errors = getattr(control, "errors", None)
    if errors is None:
        from .controllers import generated_errors
        errors = generated_errors()
    return getattr(control, "control", control), errors


@dataclass
class Trajectory:
    """One simulated run (arrays over time; for a batch, time is axis 1)."""
    kind: str                  # "continuous" | "digital"
    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    th: np.ndarray
    xr: np.ndarray
    yr: np.ndarray
    thr: np.ndarray
    v: np.ndarray              # command applied at t (continuous: at t; digital: held on [t, t+h))
    w: np.ndarray
    e: tuple                   # (e1, e2, e3) at t
    info: dict = field(default_factory=dict)


def run_continuous(control, ref, pose0, gains, duration=None, rtol=RTOL, atol=ATOL,
                   grid_dt=1e-3, method="DOP853", max_step=0.05) -> Trajectory:
    """Integrate (1) under law (9) with `control(e1, e2, e3, vr, wr, k1, k2, lam) -> (v, w)`
    and its errors (7) `control.errors` (see `_errors`)."""
    k1, k2, lam = (float(gains[k]) for k in ("k1", "k2", "lam"))
    t1 = ref.t1 if duration is None else ref.t0 + duration
    fn = ref.fn
    buf = np.empty(1)
    law, errors = _errors(control)

    def rhs(t, s):
        buf[0] = t
        xr, yr, thr, vr, wr = fn(buf)
        x, y, th = (float(a) for a in s)
        e1, e2, e3 = errors(x, y, th, float(xr[0]), float(yr[0]), float(thr[0]))
        v, w = law(e1, e2, e3, float(vr[0]), float(wr[0]), k1, k2, lam)
        return (v * math.cos(th), v * math.sin(th), w)

    sol = solve_ivp(rhs, (ref.t0, t1), np.asarray(pose0, dtype=float), method=method,
                    rtol=rtol, atol=atol, dense_output=True, max_step=max_step)
    if not sol.success:
        raise RuntimeError(f"solve_ivp failed: {sol.message}")
    n = int(round((t1 - ref.t0) / grid_dt)) + 1
    t = np.linspace(ref.t0, t1, n)
    x, y, th = sol.sol(t)
    xr, yr, thr, vr, wr = ref(t)
    e = errors(x, y, th, xr, yr, thr)
    v, w = law(*e, vr, wr, k1, k2, lam)
    return Trajectory("continuous", t, x, y, th, xr, yr, thr, np.asarray(v), np.asarray(w), e,
                      dict(nfev=int(sol.nfev), method=method, rtol=rtol, atol=atol, sol=sol))


def zoh_step(x, y, th, v, w, h):
    """Exact motion of (1) over h under constant (v, w)."""
    half = 0.5 * w * h
    d = v * h * np.sinc(half / math.pi)      # numpy sinc(u) = sin(pi u)/(pi u)
    mid = th + half
    return x + d * np.cos(mid), y + d * np.sin(mid), th + w * h


def run_digital(control, ref, pose0, gains, duration=None, h=SAMPLE_PERIOD, delay=0,
                noise=None, seed=0, record=True, limits=None, tol=None, progress=False,
                window=None) -> Trajectory:
    """The sampled loop (100 Hz by default) with zero-order hold.

    pose0: (3,) or (N, 3).  noise: None or (sigma_xy [m], sigma_theta [rad]).
    record=False keeps only running statistics (for large batches): the
    result's arrays then hold the final state, and `info` holds per-trajectory
    max |v|, max |w|, the time the errors last exceeded `tol` = (pos [m], ang [rad])
    and, when `window` = (ta, tb) is given, sums for the RMS over it."""
    k1, k2, lam = (float(gains[k]) for k in ("k1", "k2", "lam"))
    law, errors = _errors(control)
    t1 = ref.t1 if duration is None else ref.t0 + duration
    steps = int(round((t1 - ref.t0) / h))
    tk = ref.t0 + h * np.arange(steps + 1)
    XR, YR, THR, VR, WR = ref(tk)
    pose0 = np.asarray(pose0, dtype=float)
    single = pose0.ndim == 1
    P = np.atleast_2d(pose0)
    n = P.shape[0]
    x, y, th = P[:, 0].copy(), P[:, 1].copy(), P[:, 2].copy()
    rng = np.random.default_rng(seed) if noise is not None else None
    queue = [(np.zeros(n), np.zeros(n))] * delay
    if record:
        rec = np.empty((7, n, steps + 1))
    else:
        vmax = np.zeros(n)
        wmax = np.zeros(n)
        pos_tol, ang_tol = tol if tol is not None else (0.01, 0.01)
        last_bad = np.full(n, -1, dtype=np.int64)
        if window is not None:
            ka, kb = (int(round((w - ref.t0) / h)) for w in window)
            acc = np.zeros((5, n))
    bar = None
    if progress:
        from tqdm import tqdm
        bar = tqdm(total=steps, file=sys.stderr, unit="step", desc="digital loop", mininterval=0.2,
                   leave=False)
        tick = max(1, steps // 100)
    for k in range(steps + 1):
        xm, ym, thm = x, y, th
        if rng is not None:
            xm = x + rng.normal(0.0, noise[0], n)
            ym = y + rng.normal(0.0, noise[0], n)
            thm = th + rng.normal(0.0, noise[1], n)
        xr, yr, thr = XR[k], YR[k], THR[k]
        e1, e2, e3 = errors(xm, ym, thm, xr, yr, thr)
        vw = law(e1, e2, e3, VR[k], WR[k], k1, k2, lam)
        if delay:
            queue.append(vw)
            v, w = queue.pop(0)
        else:
            v, w = vw
        v = np.broadcast_to(v, (n,))
        w = np.broadcast_to(w, (n,))
        if record:
            rec[0, :, k], rec[1, :, k], rec[2, :, k] = x, y, th
            rec[3, :, k], rec[4, :, k] = v, w
        else:
            np.maximum(vmax, np.abs(v), out=vmax)
            np.maximum(wmax, np.abs(w), out=wmax)
            # true (noise-free) errors in the world frame
            ex, ey, et = xr - x, yr - y, thr - th
            bad = (ex * ex + ey * ey > pos_tol * pos_tol) | (np.abs(et) > ang_tol)
            last_bad[bad] = k
            if window is not None and ka <= k <= kb:
                acc[0] += ex * ex
                acc[1] += ey * ey
                acc[2] += et * et
                acc[3] += v * v
                acc[4] += w * w
        if k < steps:
            x, y, th = zoh_step(x, y, th, v, w, h)
        if bar is not None and k % tick == 0:
            bar.update(min(tick, steps - bar.n))
    if bar is not None:
        bar.close()
    info = dict(h=h, delay=delay, noise=noise, seed=seed, n=n)
    if record:
        X, Y, TH, V, W = (rec[i] for i in range(5))
        if single:
            X, Y, TH, V, W = X[0], Y[0], TH[0], V[0], W[0]
        e = errors(X, Y, TH, XR, YR, THR)
        return Trajectory("digital", tk, X, Y, TH, XR, YR, THR, V, W, e, info)
    info.update(max_abs_v=vmax, max_abs_w=wmax, last_bad=last_bad,
                settle_time=np.where(last_bad < steps, tk[np.minimum(last_bad + 1, steps)], np.inf))
    if window is not None:
        info["rms"] = np.sqrt(acc / (kb - ka + 1))
    e = errors(x, y, th, XR[-1], YR[-1], THR[-1])
    return Trajectory("digital", tk[-1:], x, y, th, XR[-1:], YR[-1:], THR[-1:], None, None, e, info)
