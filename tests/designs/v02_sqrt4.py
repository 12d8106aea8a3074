"""Valid design: f = sqrt(4 + e1^2 + e2^2) - 2; kf = 1, approached only as |e| -> oo.

Hand derivation (rho = e1^2 + e2^2, s = sqrt(rho), F(s) = sqrt(4 + s^2) - 2):
  df/de1 = e1/sqrt(4 + rho),  df/de2 = e2/sqrt(4 + rho); F'(s) = s/sqrt(4 + s^2).
P1 proved: 4 + rho >= 4 > 0, so the partials are smooth.  |df/de2| <= s/sqrt(4+s^2) < 1
   for every finite s, and s/sqrt(4+s^2) -> 1 as s -> oo (along e1 = 0 it is the
   value of |df/de2|).  kf = 1, NOT attained.
P2 proved: sqrt(4) - 2 = 0.
P3 proved: sqrt(4 + rho) > 2 for rho > 0; f ~ |e| -> oo.
P4 proved: e1 e2/sqrt(4+rho) on both sides.
P5 proved: e1 tanh(e1)/sqrt(4+rho) > 0 for e1 != 0.
P6 proved: k = 1/2, h = 2/sqrt(4 + rho) in (0, 1].
P7 proved: second partials are smooth (denominators (4+rho)^(3/2) >= 8).
P8 proved: e2/sqrt(4+rho) -> 0 as e2 -> 0.
Gains: loose: V = 0.5 + 0.2 = 0.7 <= 0.75 ok; W = 1.0 + 0.6*0.5*1 + 0.6 = 1.9 <= 2.0 ok.
Exit status 0.
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "sqrt(4 + |e|^2) - 2"
description = "kf = 1, approached at infinity"
f = sp.sqrt(4 + e1**2 + e2**2) - 2

gains = {
    "loose": dict(k1=0.2, k2=0.6, lam=0.6, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
