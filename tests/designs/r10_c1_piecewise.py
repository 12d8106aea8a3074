"""C^1 but not C^2 Piecewise: f = rho/2 for rho <= 1, sqrt(rho) - 1/2 otherwise.

Hand derivation (rho = e1^2 + e2^2, s = |e|):
  F(s) = s^2/2 (s <= 1), s - 1/2 (s > 1): F(1) = 1/2 both; F'(1) = 1 both; F'' = 1 vs 0.
  df/de2 = e2 (s <= 1), e2/s (s > 1): continuous across s = 1 (e2/1 = e2), so f is C^1.
  d2f/de2^2 = F''(s) e2^2/s^2 + F'(s) e1^2/s^3: inside 1, outside e1^2/s^3.
  At (0, 1): inside -> 1, outside -> 0.  Along e1 = 0, df/de2(0, t) = t for |t| <= 1 and
  sign(t) for |t| > 1, whose t-derivative at t = 1 is 1 from the left, 0 from the right.
P1 proved: C^1; |df/de2| <= |e2| <= 1 inside, |e2|/s <= 1 outside; equality at (0, 1)
   and on the e2-axis beyond.  kf = 1, attained.
P2 proved.  P3 proved (s^2/2 > 0, s - 1/2 >= 1/2, unbounded).  P4 proved (radial).
P5 proved: df/de1 = e1 (inside) or e1/s (outside), sign of e1.
P6 proved: k = 1, h = 1 (inside) or 1/s in (0, 1) (outside).
P7 REFUTED: d2f/de2^2 does not exist at (0, 1) (one-sided values 1 and 0); the mixed
   partial also jumps on the circle (inside 0, outside -e1 e2/s^3).
P8 proved: |df/de2| <= |e2|.
Gains: V = 0.75 <= 0.75; W = 1 + 0.5*0.5*1 + 0.5 = 1.75 <= 2 ok.  Exit status 1 (P7).
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "quadratic-to-cone, C^1 only"
description = "second derivative jumps on the unit circle"
rho = e1**2 + e2**2
f = sp.Piecewise((rho / 2, rho <= 1), (sp.sqrt(rho) - sp.Rational(1, 2), True))

gains = {
    "loose": dict(k1=0.25, k2=0.5, lam=0.5, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
