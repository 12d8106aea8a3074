"""Radial slope vanishing on circles: f = u - sin(u), u = sqrt(1 + e1^2 + e2^2) - 1.

Hand derivation (s = |e|, q = u'(s) = s/sqrt(1+s^2) in [0, 1)):
  F(s) = u - sin u,  F'(s) = (1 - cos u) q,  df/de1 = (1 - cos u) e1/sqrt(1 + rho).
  f is analytic on R^2 (sqrt(1 + rho) is analytic, rho = e1^2 + e2^2 >= 0).
  F'(s) = 0 for s > 0 exactly when u = 2 pi n, n >= 1; the first such circle is
  u = 2 pi, i.e. rho = (2 pi + 1)^2 - 1 = 4 pi (pi + 1), s0 = 2 sqrt(pi (pi + 1)) ~= 7.2141.
P1 proved: |df/de2| <= (1 - cos u) q < 2, and at u = (2n+1) pi along e1 = 0 it equals
   2 q -> 2.  kf = 2, NOT attained.
P2 proved: 0 - sin 0 = 0.
P3 proved: u - sin u > 0 for u > 0 (sin u < u); f >= u - 1 -> oo.
P4 proved (radial).
P5 REFUTED: at (2 sqrt(pi (pi + 1)), 0), df/de1 = (1 - cos 2 pi) * ... = 0, so
   df/de1 tanh(e1) = 0, not > 0, with e1 != 0.
P6 proved: df/de1 = 2 e1 h with h = (1 - cos u)/(2 sqrt(1 + rho)) in [0, 1); h = 0 is allowed.
P7 proved (analytic).  P8 proved: |df/de2| <= 2|e2| -> 0.
Gains: V = 0.75 <= 0.75; W = 1 + 0.5*0.5*2 + 0.25 = 1.75 <= 2 ok.  Exit status 1 (P5).
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "u - sin(u)"
description = "radial slope (1 - cos u) u' vanishes where u = 2 pi n"
u = sp.sqrt(1 + e1**2 + e2**2) - 1
f = u - sp.sin(u)

gains = {
    "loose": dict(k1=0.25, k2=0.25, lam=0.5, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
