"""What a simulated run is checked against, as a JSON-able dict ("M").

    max_abs_v, max_abs_w      largest |V|, |W| commanded (over the whole run)
    v_ok, w_ok                max |V| <= Vmax, max |W| <= Wmax (slack 1e-12 relative,
                              for the last bit of floating-point rounding)
    rms {x, y, theta, v, w}   RMS of xt, yt, tht, V, W over the window (paper:
                              60-80 s circle, 160-200 s lemniscate)
    final_errors              xt, yt, tht (world frame) and e1, e2, e3 at the end
    converged                 final |(xt, yt)| <= pos_tol and |tht| <= ang_tol
                              (defaults 0.01 m, 0.01 rad; tht is NOT wrapped, so a
                              robot one full turn off has not converged)
    settle_time               first time after which the errors stay within the
                              tolerances (null: never)
    max_lyapunov_increase     continuous time only: the largest U(t_j) - U(t_i),
                              i < j, of U = lam f(e1, e2) + e3^2/2 on the 1 kHz grid
                              (0 when U never increases); lyapunov_ok compares it
                              with LYAP_TOL (1e-7 (1 + U(0))), the integration error
    c_python_max_diff         max over time of |pose_C - pose_Python| (m, rad)
    ok                        every applicable check above passed
"""
from __future__ import annotations

import contextlib
import math

import numpy as np

POS_TOL, ANG_TOL = 0.01, 0.01
LIMIT_SLACK = 1e-12
LYAP_REL_TOL = 1e-7
C_PY_TOL = {"continuous": 1e-6, "digital": 1e-9}
SLOW_POINTS = 20_000        # at most this many points of a run evaluated by mpmath (see `f_numeric`)


def f_numeric(f):
    """f(e1, e2) on arrays, as doubles, for U = lam f + e3^2/2 (15): numpy
    with scipy.special (erf, gamma and the like, which numpy lacks), and, at
    points where that gives no finite value (an overflow inside the formula:
    log cosh(300 |e|) at |e| = 3) or cannot take f at all, mpmath at 30
    digits, point by point (at most SLOW_POINTS of them).  NaN where neither
    gives a finite value."""
    import mpmath
    import sympy as sp

    from .. import e1, e2
    fast = slow = None
    with contextlib.suppress(Exception):
        fast = sp.lambdify((e1, e2), f, modules=["numpy", "scipy"])
    with contextlib.suppress(Exception):
        slow = sp.lambdify((e1, e2), f, modules="mpmath")

    def values(a, b):
        a, b = np.broadcast_arrays(np.asarray(a, dtype=float), np.asarray(b, dtype=float))
        out = np.full(a.shape, np.nan)
        if fast is not None:
            with np.errstate(all="ignore"), contextlib.suppress(Exception):
                out = np.asarray(fast(a, b), dtype=float) * np.ones(a.shape)
        bad = np.flatnonzero(~np.isfinite(out))
        if slow is not None and 0 < bad.size <= SLOW_POINTS:
            with mpmath.workdps(30):
                for i in bad:
                    with contextlib.suppress(Exception):
                        out.flat[i] = float(slow(mpmath.mpf(a.flat[i]), mpmath.mpf(b.flat[i])))   # (complex: NaN)
        return out
    return values


def _f(x) -> float | None:
    if x is None:
        return None
    x = float(x)
    return x if math.isfinite(x) else None


def window_mask(t, window):
    a, b = window
    return (t >= a - 1e-9) & (t <= b + 1e-9)


def metrics(tr, limits: dict, window, f_num=None, lam=None, other=None, verified=True,
            pos_tol=POS_TOL, ang_tol=ANG_TOL) -> dict:
    """M for one Trajectory `tr`; `other` is the same run with the other back-end."""
    Vmax, Wmax = float(limits["Vmax"]), float(limits["Wmax"])
    xt, yt, tht = tr.xr - tr.x, tr.yr - tr.y, tr.thr - tr.th
    m = window_mask(tr.t, window)
    if not m.any():
        m = np.ones_like(tr.t, dtype=bool)
    rms = {k: float(np.sqrt(np.mean(a[m] ** 2)))
           for k, a in zip(("x", "y", "theta", "v", "w"), (xt, yt, tht, tr.v, tr.w))}
    max_v, max_w = float(np.max(np.abs(tr.v))), float(np.max(np.abs(tr.w)))
    bad = (xt * xt + yt * yt > pos_tol ** 2) | (np.abs(tht) > ang_tol)
    idx = np.nonzero(bad)[0]
    if idx.size == 0:
        settle = float(tr.t[0])
    elif idx[-1] == len(tr.t) - 1:
        settle = None
    else:
        settle = float(tr.t[idx[-1] + 1])
    e1, e2, e3 = tr.e
    final = dict(x=float(xt[-1]), y=float(yt[-1]), theta=float(tht[-1]),
                 e1=float(e1[-1]), e2=float(e2[-1]), e3=float(e3[-1]))
    converged = bool(math.hypot(final["x"], final["y"]) <= pos_tol and abs(final["theta"]) <= ang_tol)
    out = dict(kind=tr.kind, max_abs_v=max_v, max_abs_w=max_w, Vmax=Vmax, Wmax=Wmax,
               v_ok=bool(max_v <= Vmax * (1 + LIMIT_SLACK)), w_ok=bool(max_w <= Wmax * (1 + LIMIT_SLACK)),
               rms=rms, rms_window=[float(window[0]), float(window[1])], final_errors=final,
               converged=converged, settle_time=settle, tolerances=dict(position=pos_tol, angle=ang_tol),
               max_lyapunov_increase=None, lyapunov_tol=None, lyapunov_ok=None,
               c_python_max_diff=None, c_python_ok=None)
    if tr.kind == "continuous" and f_num is not None:
        with np.errstate(all="ignore"):
            U = lam * f_num(e1, e2) + 0.5 * e3 * e3
        if not np.all(np.isfinite(U)):      # said, not skipped in silence
            j = int(np.flatnonzero(~np.isfinite(U))[0])
            out["lyapunov_note"] = (f"U = lam f(e1, e2) + e3^2/2 has no finite double value (or f could not be "
                                    f"evaluated) at {int(np.count_nonzero(~np.isfinite(U)))} points, first t = "
                                    f"{float(tr.t[j]):g} s")
        else:
            inc = float(np.max(U - np.minimum.accumulate(U)))
            tol = LYAP_REL_TOL * (1.0 + abs(float(U[0])))
            out.update(max_lyapunov_increase=inc, lyapunov_tol=tol,
                       lyapunov_ok=bool(inc <= tol) if verified else None)
            j = int(np.argmax(U - np.minimum.accumulate(U)))
            out["lyapunov_worst_time"] = float(tr.t[j])
    if other is not None:
        d = max(float(np.max(np.abs(tr.x - other.x))), float(np.max(np.abs(tr.y - other.y))),
                float(np.max(np.abs(tr.th - other.th))))
        out.update(c_python_max_diff=d, c_python_ok=bool(d <= C_PY_TOL[tr.kind]))
    checks = [out["v_ok"], out["w_ok"], out["converged"], out["lyapunov_ok"], out["c_python_ok"]]
    out["ok"] = all(c is not False for c in checks)
    out["failed"] = [name for name, c in zip(("V limit", "W limit", "convergence", "Lyapunov", "C = Python"),
                                             checks) if c is False]
    return out
