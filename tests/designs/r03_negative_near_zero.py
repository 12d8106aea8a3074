"""Radial design negative near the origin: f = sqrt(1 + rho) - 1 - log(1 + rho).

Hand derivation (rho = e1^2 + e2^2, s = |e|, q = s/sqrt(1+s^2)):
  F(s) = sqrt(1+s^2) - 1 - log(1+s^2) = s^2/2 - s^2 + O(s^4) = -s^2/2 + O(s^4) < 0 near 0.
  F'(s) = s/sqrt(1+s^2) - 2s/(1+s^2) = s (sqrt(1+s^2) - 2)/(1+s^2),
  negative on (0, sqrt(3)), zero at s = sqrt(3), positive after; F(s) ~ s -> oo;
  F itself is negative on (0, s*) with s* ~= 3.3675 (numerical root of F).
  df/de1 = F'(s) e1/s = e1 (1/sqrt(1+rho) - 2/(1+rho)).
P1 proved: smooth partials; -1 <= -2s/(1+s^2) < F'(s) < q < 1 for s > 0, and
   F'(s) -> 1 as s -> oo.  kf = 1, NOT attained.
P2 proved: 1 - 1 - 0 = 0.
P3 REFUTED: f(1, 0) = sqrt(2) - 1 - log 2 = -0.2789... < 0.
P4 proved (radial).
P5 REFUTED: df/de1(1, 0) = 1/sqrt(2) - 1 < 0, so df/de1 tanh(e1) < 0 at (1, 0).
P6 REFUTED: df/de1 = e1 (1/sqrt(1+rho) - 2/(1+rho)); h would have to be
   (1/sqrt(1+rho) - 2/(1+rho))/k < 0 for 0 < rho < 3.
P7 proved (smooth).  P8 proved: |df/de2| <= |e2| * |F'(s)/s| <= 3|e2| -> 0.
Gains: V = 0.6 + 0.2 = 0.8 > 0.75 (V FAILS); W = 1.0 + 0.5*0.6*1 + 0.5 = 1.8 <= 2 ok.
Exit status 1.
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "dips below zero"
description = "f = sqrt(1+|e|^2) - 1 - log(1+|e|^2): negative for 0 < |e| < ~3.3675"
rho = e1**2 + e2**2
f = sp.sqrt(1 + rho) - 1 - sp.log(1 + rho)

gains = {
    "V_too_big": dict(k1=0.2, k2=0.5, lam=0.5, Vmax=0.75, Wmax=2.0, Vr_max=0.6, Wr_max=1.0),
}
