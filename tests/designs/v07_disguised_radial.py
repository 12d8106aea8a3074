"""Valid design written in a non-obviously radial form:
f = log(1 + ((e1 + e2)^2 + (e1 - e2)^2)/8).

Hand derivation: (e1 + e2)^2 + (e1 - e2)^2 = 2 e1^2 + 2 e2^2, so f = log(1 + rho/4),
rho = e1^2 + e2^2.  F(s) = log(1 + s^2/4), F'(s) = (s/2)/(1 + s^2/4) = 2s/(4 + s^2).
  df/de1 = 2 e1/(4 + rho), df/de2 = 2 e2/(4 + rho).
  2s/(4 + s^2) <= 1/2 since 4 + s^2 >= 4s, equality at s = 2.
P1 proved: kf = 1/2, attained at (0, 2).
P2 proved.  P3 proved (rho/4 > 0, log unbounded).
P4 proved: e1 * 2 e2/(4+rho) = e2 * 2 e1/(4+rho) (after expanding the squares).
P5 proved: 2 e1 tanh(e1)/(4 + rho) > 0 for e1 != 0.
P6 proved: k = 1/2, h = 4/(4 + rho) in (0, 1].
P7 proved (rational).  P8 proved.
Gains: tight: V = 1.0 + 0.5 = 1.5 <= 1.5 (margin 0);
   W = 1.0 + 2.0*1.0*0.5 + 0.25 = 2.25 <= 2.25 (margin exactly 0).  Both ok.
Exit status 0.
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "disguised radial log"
description = "f = log(1 + ((e1+e2)^2 + (e1-e2)^2)/8) = log(1 + |e|^2/4)"
f = sp.log(1 + ((e1 + e2)**2 + (e1 - e2)**2) / 8)

gains = {
    "tight": dict(k1=0.5, k2=0.25, lam=2.0, Vmax=1.5, Wmax=2.25, Vr_max=1.0, Wr_max=1.0),
}
