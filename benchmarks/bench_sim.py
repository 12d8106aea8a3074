"""Batch simulation vs a loop of solve_ivp calls (run by `make bench`).

1,000 random initial poses (seed 0, `api.random_poses`) on the paper's 80 s
circle with design 1's generated Python controller:

* batch: the 100 Hz digital loop, all 1,000 trajectories at once (vectorised
  numpy, exact zero-order-hold motion between samples, 8,000 steps);
* loop: one `solve_ivp` call per trajectory (RK45, rtol 1e-6, atol 1e-8, the
  command evaluated at every right-hand-side call, read at 100 Hz).  Timing
  all 1,000 would take minutes, so a subset of LOOP_SUBSET trajectories is
  timed and the figure extrapolated linearly (the runs are independent).

Goal: batch <= 2 s on the 2-core machine and >= 100x faster than the loop.
Both in the same run; the final positions of the subset are compared (they
differ by the sampling only: ~1e-6 m once converged)."""
from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from uwmr_symbolic.simulation.api import paper_scenario, random_poses  # noqa: E402
from uwmr_symbolic.simulation.controllers import load_controllers  # noqa: E402
from uwmr_symbolic.simulation.loop import run_digital  # noqa: E402

N, LOOP_SUBSET = 1000, 20
GOAL_S, GOAL_RATIO = 2.0, 100.0


def loop_one(control, ref, pose, g, t_eval):
    k1, k2, lam = g["k1"], g["k2"], g["lam"]
    buf = np.empty(1)

    def rhs(t, s):
        buf[0] = t
        xr, yr, thr, vr, wr = ref.fn(buf)
        x, y, th = s
        c, sn = math.cos(th), math.sin(th)
        xt, yt = float(xr[0]) - x, float(yr[0]) - y
        v, w = control(c * xt + sn * yt, -sn * xt + c * yt, float(thr[0]) - th, float(vr[0]), float(wr[0]),
                       k1, k2, lam)
        return (v * c, v * sn, w)

    return solve_ivp(rhs, (ref.t0, ref.t1), pose, rtol=1e-6, atol=1e-8, t_eval=t_eval).y[:, -1]


def main() -> int:
    sc = paper_scenario("circle")
    design = ROOT / "designs" / "design1_jiang.py"
    ctl = load_controllers(design)
    g = dict(k1=0.25, k2=0.7, lam=1.2, Vmax=0.75, Wmax=2.0)
    poses = random_poses(sc, N, seed=0)
    run_digital(ctl.python, sc.reference, poses[:10], g, duration=1.0, record=False)   # warm-up
    t = time.perf_counter()
    tr = run_digital(ctl.python, sc.reference, poses, g, record=False, window=sc.window)
    batch = time.perf_counter() - t
    t_eval = np.linspace(sc.reference.t0, sc.reference.t1, 8001)
    t = time.perf_counter()
    ends = np.array([loop_one(ctl.python, sc.reference, poses[i], g, t_eval) for i in range(LOOP_SUBSET)])
    loop_sub = time.perf_counter() - t
    loop = loop_sub * N / LOOP_SUBSET
    diff = np.max(np.hypot(ends[:, 0] - tr.x[:LOOP_SUBSET], ends[:, 1] - tr.y[:LOOP_SUBSET]))
    ratio = loop / batch
    print(f"bench_sim: {N} trajectories of the 80 s circle (design 1, generated Python), 100 Hz")
    print(f"  batch (vectorised digital loop, 8000 steps): {batch:8.3f} s   goal <= {GOAL_S} s: "
          f"{'met' if batch <= GOAL_S else 'MISSED'} ({batch / GOAL_S:.2f}x of the goal)")
    print(f"  loop of solve_ivp: {loop_sub:.3f} s for {LOOP_SUBSET} trajectories -> {loop:8.1f} s for {N} "
          f"(extrapolated)")
    print(f"  speed-up {ratio:8.1f}x   goal >= {GOAL_RATIO:.0f}x: {'met' if ratio >= GOAL_RATIO else 'MISSED'}")
    print(f"  per trajectory: batch {1e3 * batch / N:.2f} ms, loop {1e3 * loop / N:.1f} ms; "
          f"final positions batch vs loop differ by <= {diff:.1e} m (sampling, 100 Hz ZOH vs continuous)")
    print(f"  converged in the batch: {np.mean(np.hypot(tr.xr[-1] - tr.x, tr.yr[-1] - tr.y) <= 0.01) * 100:.1f} %")
    return 0


if __name__ == "__main__":
    sys.exit(main())
