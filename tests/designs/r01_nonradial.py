"""Non-radial design: f = log(1 + e1^2 + 2 e2^2).  Only P4 is refuted.

Hand derivation (D = 1 + e1^2 + 2 e2^2 >= 1):
  df/de1 = 2 e1/D,  df/de2 = 4 e2/D.
P1 proved: rational partials, D >= 1.  |df/de2| <= 4|e2|/(1 + 2 e2^2) (e1 = 0 is worst);
   with t = sqrt(2)|e2|: 4|e2|/(1+2e2^2) = sqrt(2) * 2t/(1+t^2) <= sqrt(2), equality at
   t = 1.  kf = sqrt(2), attained at (0, 1/sqrt(2)).
P2 proved: log 1 = 0.
P3 proved: D > 1 for e != 0; f >= log(1 + |e|^2) -> oo.
P4 REFUTED: e1 df/de2 - e2 df/de1 = (4 - 2) e1 e2/D = 2 e1 e2/D, nonzero e.g. at (1, 1)
   (value 2/4 = 1/2).
P5 proved: 2 e1 tanh(e1)/D > 0 for e1 != 0.
P6 proved: k = 2, h = 1/D in (0, 1].
P7 proved: rational second partials, denominators D^2 >= 1.
P8 proved: 4 e2/D -> 0 as e2 -> 0.
Gains: V = 0.75 <= 0.75; W = 1.0 + 0.5*0.5*sqrt(2) + 0.5 = 1.5 + sqrt(2)/4 = 1.8536 <= 2 ok.
Exit status 1 (P4 refuted).
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "non-radial log"
description = "f = log(1 + e1^2 + 2 e2^2): P4 fails"
f = sp.log(1 + e1**2 + 2 * e2**2)

gains = {
    "loose": dict(k1=0.25, k2=0.5, lam=0.5, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
