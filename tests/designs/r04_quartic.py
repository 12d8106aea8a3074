"""Unbounded slope: f = (e1^2 + e2^2)^2.  kf is infinite.

Hand derivation (rho = e1^2 + e2^2): df/de1 = 4 rho e1, df/de2 = 4 rho e2.
P1 REFUTED: |df/de2(0, t)| = 4 t^3 -> oo, so no finite kf (e.g. 4000 at (0, 10)).
   kf = oo (exact: none, upper: unbounded, attained: none).
P2 proved.  P3 proved (rho^2 > 0, unbounded).  P4 proved (4 rho e1 e2 both sides).
P5 proved: 4 rho e1 tanh(e1) > 0 for e1 != 0 (rho >= e1^2 > 0).
P6 REFUTED: df/de1 = k e1 h forces h = 4 rho/k, unbounded, so h <= 1 fails for any k.
P7 proved (polynomial).  P8 proved: 4 rho e2 -> 0 as e2 -> 0.
Gains: V = 0.75 <= 0.75 ok; W bound = 1 + lam*Vr_max*oo + k2 = oo > Wmax: W FAILS.
Exit status 1.
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "quartic bowl"
description = "f = |e|^4: kf infinite"
f = (e1**2 + e2**2)**2

gains = {
    "any": dict(k1=0.25, k2=0.5, lam=0.5, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
