"""Valid design: f = log(1 + (e1^2 + e2^2)^2)/4; kf = 3^(3/4)/4, attained.

Hand derivation (rho = e1^2 + e2^2, s = |e|, F(s) = log(1 + s^4)/4):
  df/de1 = e1 rho/(1 + rho^2), df/de2 = e2 rho/(1 + rho^2), F'(s) = s^3/(1 + s^4).
  d/ds [s^3/(1+s^4)] = (3 s^2 (1 + s^4) - 4 s^6)/(1+s^4)^2 = s^2 (3 - s^4)/(1+s^4)^2,
  zero at s^4 = 3: F'(3^(1/4)) = 3^(3/4)/(1 + 3) = 3^(3/4)/4 ~= 0.569877.
  F' -> 0 at 0 and at oo, so this is the global maximum.
P1 proved: rational partials, denominator >= 1; kf = 3^(3/4)/4 attained at
   (0, 3^(1/4)).
P2 proved: log 1 / 4 = 0.
P3 proved: rho^2 > 0 for e != 0; f -> oo.
P4 proved: e1 e2 rho/(1+rho^2) on both sides.
P5 proved: e1 tanh(e1) rho/(1+rho^2) > 0 for e1 != 0 (then rho >= e1^2 > 0).
P6 proved: k = 1/2, h = 2 rho/(1 + rho^2) in [0, 1] (AM-GM); h = 0 only at 0.
P7 proved: rational second partials with denominator (1+rho^2)^2 >= 1.
P8 proved: df/de2 -> 0 as e2 -> 0.
Gains (kf irrational, so the comparison needs exact arithmetic):
  W = 1.0 + 1.0*0.5*3^(3/4)/4 + 0.5 = 1.5 + 3^(3/4)/8 = 1.78493838211934...
  just_below: Wmax = 1.784938 < W (FAILS by ~3.8e-7).
  just_above: Wmax = 1.784939 > W (ok by ~6.2e-7).  V = 0.75 <= 0.75 in both.
Exit status 1 (a gain check fails).
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "log(1 + |e|^4)/4"
description = "kf = 3^(3/4)/4 attained at |e| = 3^(1/4)"
f = sp.log(1 + (e1**2 + e2**2)**2) / 4

gains = {
    "just_below": dict(k1=0.25, k2=0.5, lam=1.0, Vmax=0.75, Wmax=1.784938, Vr_max=0.5, Wr_max=1.0),
    "just_above": dict(k1=0.25, k2=0.5, lam=1.0, Vmax=0.75, Wmax=1.784939, Vr_max=0.5, Wr_max=1.0),
}
