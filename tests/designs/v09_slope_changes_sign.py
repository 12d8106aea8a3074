"""Radial design whose slope changes sign: f = log(1 + rho) - 2 rho/(1 + rho).

Hand derivation (rho = e1^2 + e2^2, s = |e|):
  F(s) = log(1 + s^2) - 2 s^2/(1 + s^2) = s^2 - 2 s^2 + O(s^4) = -s^2 + O(s^4) < 0 near 0.
  F'(s) = 2s/(1 + s^2) - 4s/(1 + s^2)^2 = 2s (s^2 - 1)/(1 + s^2)^2:
  negative on (0, 1), zero at 1, positive after, -> 0 as s -> oo.
  With g = (s^3 - s)/(1 + s^2)^2, g' = (-s^4 + 6 s^2 - 1)/(1 + s^2)^3, zero at
  s^2 = 3 -+ 2 sqrt(2), i.e. s = sqrt(2) -+ 1.  At s = 1 + sqrt(2): s^2 - 1 = 2 + 2 sqrt(2),
  1 + s^2 = 4 + 2 sqrt(2), 2s(s^2 - 1) = 4 (1 + sqrt(2))^2 = 4 (3 + 2 sqrt(2)) and
  (1 + s^2)^2 = 24 + 16 sqrt(2) = 8 (3 + 2 sqrt(2)): F' = 1/2.  At s = sqrt(2) - 1, the
  same computation gives F' = -1/2.  So sup |F'| = 1/2, attained on both sides.
  df/de1 = F'(s) e1/s = 2 e1 (rho - 1)/(1 + rho)^2 (rational, smooth).
P1 proved: |df/de2| <= |F'(s)| <= 1/2, kf = 1/2 attained at (0, 1 + sqrt(2)).
P2 proved: log 1 - 0 = 0.
P3 REFUTED: f(1/2, 0) = log(5/4) - 2/5 = 0.2231 - 0.4 < 0.
P4 proved (radial).
P5 REFUTED: df/de1(1/2, 0) = 2 (1/2)(-3/4)/(25/16) < 0.
P6 REFUTED: h = (rho - 1)/(k (1 + rho)^2) < 0 for rho < 1.
P7 proved (rational in e1, e2 and log(1 + rho), all smooth).  P8 proved: df/de2 =
   2 e2 (rho - 1)/(1 + rho)^2 -> 0 as e2 -> 0.
Gains: V = 0.5 + 0.25 = 0.75 <= 0.75; W = 1.0 + 0.5*0.5*(1/2) + 0.5 = 1.625 <= 2 ok.
Exit status 1.
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "slope changes sign"
description = "f = log(1+|e|^2) - 2|e|^2/(1+|e|^2): F' < 0 on (0, 1), sup |F'| = 1/2 on both sides"
rho = e1**2 + e2**2
f = sp.log(1 + rho) - 2 * rho / (1 + rho)

gains = {
    "loose": dict(k1=0.25, k2=0.5, lam=0.5, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
