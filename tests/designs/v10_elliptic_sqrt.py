"""Elliptic design: f = sqrt(1 + e1^2 + 3 e2^2) - 1.  Only P4 is refuted.

Hand derivation (q = e1^2 + 3 e2^2, s = sqrt(q), F(s) = sqrt(1 + s^2) - 1):
  f = F(s) with s = sqrt(e1^2 + r e2^2), r = 3.  F'(s) = s/sqrt(1 + s^2) in (0, 1), -> 1.
  df/de1 = e1/sqrt(1 + q), df/de2 = 3 e2/sqrt(1 + q).
P1 proved: |df/de2| = 3|e2|/sqrt(1 + q) <= 3|e2|/sqrt(1 + 3 e2^2) < sqrt(3)
   (e1 = 0 is worst), -> sqrt(3) as e2 -> oo.  kf = sqrt(3), NOT attained.
P2 proved: sqrt(1) - 1 = 0.
P3 proved: q > 0 for e != 0, f >= sqrt(1 + |e|^2) - 1 -> oo.
P4 REFUTED: f(1, 0) = sqrt(2) - 1 != f(0, 1) = 1 on the unit circle.
P5 proved: e1 tanh(e1)/sqrt(1 + q) > 0 for e1 != 0.
P6 proved: k = 1, h = 1/sqrt(1 + q) in (0, 1].
P7 proved (smooth, 1 + q >= 1).  P8 proved: 3 e2/sqrt(1 + q) -> 0 as e2 -> 0.
Gains: V = 0.5 + 0.25 = 0.75 <= 0.75; W = 1.0 + 0.5*0.5*sqrt(3) + 0.5 = 1.933 <= 2 ok.
Exit status 1 (P4 refuted).
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "elliptic sqrt"
description = "f = sqrt(1 + e1^2 + 3 e2^2) - 1: radial in (e1, sqrt(3) e2), P4 fails"
f = sp.sqrt(1 + e1**2 + 3 * e2**2) - 1

gains = {
    "loose": dict(k1=0.25, k2=0.5, lam=0.5, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
