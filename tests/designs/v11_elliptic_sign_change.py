"""Elliptic design whose slope changes sign: f = log(1 + q) - 2 q/(1 + q), q = e1^2 + 4 e2^2.

Hand derivation: f = F(s) with s = sqrt(e1^2 + r e2^2), r = 4, and the F of
v09_slope_changes_sign: F'(s) = 2s (s^2 - 1)/(1 + s^2)^2, sup |F'| = 1/2 attained at
s = 1 + sqrt(2) (and -1/2 at s = sqrt(2) - 1).
  df/de1 = 2 e1 (q - 1)/(1 + q)^2, df/de2 = 8 e2 (q - 1)/(1 + q)^2 = 4 F'(s) e2/s.
P1 proved: |df/de2| = 4 |e2| |F'(s)|/s <= 2 |F'(s)| <= 1 (2 |e2| <= s); equality at
   e1 = 0, 2 e2 = 1 + sqrt(2).  kf = sqrt(4) * 1/2 = 1, attained at (0, (1 + sqrt(2))/2).
P2 proved.  P3 REFUTED: f(1/2, 0) = log(5/4) - 2/5 < 0.
P4 REFUTED: f(1, 0) = log 2 - 1 != f(0, 1) = log 5 - 8/5 on the unit circle.
P5 REFUTED: df/de1(1/2, 0) = (-3/4)/(25/16) < 0.  P6 REFUTED (h < 0 for q < 1).
P7 proved (smooth).  P8 proved: 8 e2 (q - 1)/(1 + q)^2 -> 0 as e2 -> 0.
Gains: V = 0.5 + 0.25 = 0.75 <= 0.75; W = 1.0 + 0.5*0.5*1 + 0.5 = 1.75 <= 2 ok.
Exit status 1.
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "elliptic, slope changes sign"
description = "f = log(1+q) - 2q/(1+q), q = e1^2 + 4 e2^2: elliptic, F' < 0 near 0"
q = e1**2 + 4 * e2**2
f = sp.log(1 + q) - 2 * q / (1 + q)

gains = {
    "loose": dict(k1=0.25, k2=0.5, lam=0.5, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
