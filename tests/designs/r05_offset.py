"""f(0,0) != 0: f = sqrt(1 + e1^2 + e2^2).  Only P2 is refuted.

Hand derivation (rho = e1^2 + e2^2, s = |e|): df/de1 = e1/sqrt(1+rho),
df/de2 = e2/sqrt(1+rho), F'(s) = s/sqrt(1+s^2).
P1 proved: smooth; |df/de2| <= s/sqrt(1+s^2) < 1, -> 1 along e1 = 0.  kf = 1, NOT attained.
P2 REFUTED: f(0, 0) = 1.
P3 proved as read here (f > 0 for e != 0 and radially unbounded): f >= 1 > 0, f ~ |e|.
P4 proved (radial).  P5 proved: e1 tanh(e1)/sqrt(1+rho) > 0.
P6 proved: k = 1, h = 1/sqrt(1+rho) in (0, 1].
P7 proved (smooth).  P8 proved.
Gains: V = 0.75 <= 0.75; W = 1 + 0.5*0.5*1 + 0.5 = 1.75 <= 2 ok.  Exit status 1 (P2).
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "offset hyperboloid"
description = "f = sqrt(1 + |e|^2): f(0,0) = 1"
f = sp.sqrt(1 + e1**2 + e2**2)

gains = {
    "loose": dict(k1=0.25, k2=0.5, lam=0.5, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
