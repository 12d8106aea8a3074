"""Bounded design: f = 1 - exp(-(e1^2 + e2^2)).  P3 refuted (not radially unbounded).

Hand derivation (rho = e1^2 + e2^2, s = |e|, F(s) = 1 - exp(-s^2)):
  df/de1 = 2 e1 exp(-rho), df/de2 = 2 e2 exp(-rho), F'(s) = 2 s exp(-s^2).
  d/ds F' = 2 exp(-s^2)(1 - 2 s^2) = 0 at s^2 = 1/2:
  F'(1/sqrt(2)) = sqrt(2) exp(-1/2) ~= 0.8577638849607.
P1 proved: entire partials; kf = sqrt(2) exp(-1/2), attained at (0, 1/sqrt(2)).
P2 proved: 1 - e^0 = 0.
P3 REFUTED: 0 < f < 1 for e != 0, so f is bounded, not radially unbounded
   (positivity holds, unboundedness fails; e.g. f(10, 0) = 1 - e^-100 < 1).
P4 proved (radial).
P5 proved: 2 e1 tanh(e1) exp(-rho) > 0 for e1 != 0.
P6 proved: k = 2, h = exp(-rho) in (0, 1].
P7 proved (entire).  P8 proved: 2 e2 exp(-rho) -> 0.
Gains: V = 0.75 <= 0.75; W = 1.0 + 0.5*0.5*kf + 0.5 = 1.5 + kf/4 = 1.71444097124017...
   with Wmax = 1.714440971241 (W below it by ~8e-13): ok.  Exit status 1 (P3).
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "bounded Gaussian bowl"
description = "f = 1 - exp(-|e|^2): positive definite but bounded"
f = 1 - sp.exp(-(e1**2 + e2**2))

gains = {
    "just_above_by_1e-12": dict(k1=0.25, k2=0.5, lam=0.5, Vmax=0.75, Wmax=1.714440971241, Vr_max=0.5, Wr_max=1.0),
}
