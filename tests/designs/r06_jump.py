"""Discontinuous Piecewise: f jumps by +1 across the circle |e| = 2.

f = log(1 + rho) if rho <= 4, else log(1 + rho) + 1   (rho = e1^2 + e2^2).

Hand derivation: off the circle rho = 4 both branches have the partials
  df/de1 = 2 e1/(1 + rho), df/de2 = 2 e2/(1 + rho)  (the constant 1 has none).
  On the circle f is not continuous: f(2, 0) = log 5, but f(2 + t, 0) = log(1 + (2+t)^2) + 1
  -> log 5 + 1 as t -> 0+.  At every point of the circle moving along e1 (for e1 != 0)
  or along e2 (for e2 != 0) crosses the circle, and at (0, +-2) / (+-2, 0) moving along
  the tangent axis leaves the disc; so neither partial exists anywhere on the circle.
P1 REFUTED: the partials do not exist on the circle (witness (2, 0)).
   kf, read as sup |df/de2| over the points where it exists: |2 e2/(1+rho)| <= 2s/(1+s^2)
   <= 1 with equality at (0, 1) (inside the disc, |e| = 1 != 2).  kf = 1, attained.
P2 proved: log 1 = 0 (the origin is inside the disc).
P3 proved: f > 0 for e != 0 (log(1+rho) > 0 and + 1 outside), f -> oo.
P4 proved: radial; e1 df/de2 = e2 df/de1 wherever both partials exist.
P5 REFUTED: df/de1 does not exist at (2, 0), where e1 = 2 != 0 (nor anywhere on the circle).
P6 REFUTED: df/de1 = k e1 h cannot hold on the circle, where df/de1 does not exist.
P7 REFUTED: second partials do not exist on the circle.
P8 proved: for |e1| != 2 the points (e1, e2), e2 small, are off the circle; for |e1| = 2
   and e2 != 0 they are outside it (rho > 4).  Either way df/de2 = 2 e2/(1+rho) -> 0.
Gains (with kf = 1): V = 0.75 <= 0.75; W = 1 + 0.5*0.5*1 + 0.5 = 1.75 <= 2 ok.
Exit status 1.
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "jump across |e| = 2"
description = "log(1+|e|^2), plus 1 outside the circle of radius 2"
rho = e1**2 + e2**2
f = sp.Piecewise((sp.log(1 + rho), rho <= 4), (sp.log(1 + rho) + 1, True))

gains = {
    "loose": dict(k1=0.25, k2=0.5, lam=0.5, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
