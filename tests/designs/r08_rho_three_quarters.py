"""f = log(1 + (e1^2 + e2^2)^(3/4)): C^1 with bounded gradient, but F'(s)/s is unbounded.

Hand derivation (s = |e|, F(s) = log(1 + s^(3/2))):
  F'(s) = (3/2) s^(1/2)/(1 + s^(3/2)),  df/de1 = F'(s) e1/s = (3/2) e1 s^(-1/2)/(1 + s^(3/2)).
  |grad f| = F'(s) -> 0 as s -> 0, so f is C^1 with grad f(0) = 0.
  Max of F': d/ds [s^(1/2)/(1+s^(3/2))] = 0  <=>  (1/2) s^(-1/2)(1 + s^(3/2)) = (3/2) s
  <=>  1 + s^(3/2) = 3 s^(3/2)  <=>  s^(3/2) = 1/2, s = 2^(-2/3).
  F'(2^(-2/3)) = (3/2) 2^(-1/3)/(3/2) = 2^(-1/3) ~= 0.7937005.
P1 proved: C^1; kf = 2^(-1/3), attained at (0, 2^(-2/3)).
P2 proved.  P3 proved (s^(3/2) > 0, log unbounded).  P4 proved (radial).
P5 proved: F'(s) > 0 for s > 0.
P6 REFUTED: h = F'(s)/(k s) = (3/2) s^(-1/2)/(k (1 + s^(3/2))) -> oo as s -> 0.
P7 REFUTED: along e1 = 0, d2f/de2^2(0, t) = F''(t) ~ (3/4) t^(-1/2) -> oo; the second
   partial does not exist at the origin (d/dt of F'(|t|) sign(t) at 0 is infinite).
P8 proved: |df/de2| <= F'(s) -> 0 at the origin; for e1 != 0, e2 -> 0 gives 0.
Gains: V = 0.75 <= 0.75; W = 1 + 0.5*0.5*2^(-1/3) + 0.5 = 1.698 <= 2 ok.  Exit status 1.
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "rho^(3/4) log"
description = "C^1 with bounded gradient, not C^2 at the origin"
f = sp.log(1 + (e1**2 + e2**2)**sp.Rational(3, 4))

gains = {
    "loose": dict(k1=0.25, k2=0.5, lam=0.5, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
