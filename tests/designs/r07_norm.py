"""Non-differentiable norm: f = sqrt(e1^2 + e2^2) = |e|.

Hand derivation: for e != 0, df/de1 = e1/|e|, df/de2 = e2/|e|.  At the origin
f(t, 0) = |t| and f(0, t) = |t| are not differentiable at t = 0, so neither partial
exists at (0, 0).
P1 REFUTED: no partials at (0, 0).  kf (sup over the points where df/de2 exists):
   |e2|/|e| <= 1, equality on the e2-axis, e.g. (0, 1).  kf = 1, attained.
P2 proved: |0| = 0.
P3 proved: |e| > 0 for e != 0, unbounded.
P4 proved: e1 e2/|e| = e2 e1/|e| wherever the partials exist (radial).
P5 REFUTED: for e1 != 0, (e1/|e|) tanh(e1) > 0, but df/de1 does not exist at the
   origin, so the second half of P5 ("= 0 for e1 = 0") fails there; P5 is refuted
   wherever df/de1 does not exist.  Witness (0, 0).
P6 REFUTED: df/de1 = k e1 h needs h = 1/(k |e|), unbounded as e -> 0.
P7 REFUTED: d2f/de2^2 = e1^2/|e|^3 blows up at the origin (e.g. along (t, 0) it is 1/t);
   it does not exist at (0, 0).
P8 REFUTED: at e1 = 0, df/de2(0, e2) = sign(e2): the limit as e2 -> 0 does not exist
   (+1 from above, -1 from below).
Gains: V = 0.75 <= 0.75; W = 1 + 0.5*0.5*1 + 0.5 = 1.75 <= 2 ok.  Exit status 1.
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "Euclidean norm"
description = "f = |e|: not differentiable at the origin"
f = sp.sqrt(e1**2 + e2**2)

gains = {
    "loose": dict(k1=0.25, k2=0.5, lam=0.5, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
