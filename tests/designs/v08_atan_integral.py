"""Valid design whose radial derivative is atan: F(s) = s atan(s) - log(1 + s^2)/2,
f = sqrt(rho) atan(sqrt(rho)) - log(1 + rho)/2, rho = e1^2 + e2^2.  kf = pi/2, not attained.

Hand derivation (s = |e|):
  F'(s) = atan(s) + s/(1+s^2) - s/(1+s^2) = atan(s);  F''(s) = 1/(1 + s^2).
  Smoothness at the origin: s atan(s) = sum_n (-1)^n s^(2n+2)/(2n+1) is a power series
  in rho = s^2 (radius 1) and log(1 + rho) is analytic there, so f is analytic near 0;
  away from 0 sqrt(rho) is analytic.  Hence f is C^oo on R^2.
P1 proved: |df/de2| = atan(s)|e2|/s <= atan(s) < pi/2, and along e1 = 0 it equals
   atan(|e2|) -> pi/2.  kf = pi/2, NOT attained.
P2 proved: F(0) = 0.
P3 proved: F(s) = int_0^s atan > 0 for s > 0, and F(s) >= (s - 1) atan(1) -> oo.
P4 proved (radial).
P5 proved: df/de1 = atan(s) e1/s, sign of e1.
P6 proved: k = 1, h = atan(s)/s in (0, 1].
P7 proved (C^oo).  P8 proved: |df/de2| <= |e2|.
Gains: V = 0.5 + 0.25 = 0.75 <= 0.75; W = 1.0 + 1.0*0.5*pi/2 + 0.2 = 1.2 + pi/4
   = 1.98539816... <= 2.0 (ok).  Exit status 0.
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "atan-slope design"
description = "F'(s) = atan(s); kf = pi/2 approached at infinity"
_s = sp.sqrt(e1**2 + e2**2)
f = _s * sp.atan(_s) - sp.log(1 + e1**2 + e2**2) / 2

gains = {
    "loose": dict(k1=0.25, k2=0.2, lam=1.0, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
