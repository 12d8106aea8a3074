"""Valid C^2 Piecewise design (design 4 with the switch moved to u = pi/2).

With u = sqrt(e1^2 + e2^2 + 1) - 1:  f = 1 - cos(u) if u <= pi/2, else u - pi/2 + 1.
kf = 1, approached only as |e| -> oo.

Hand derivation (s = |e|, u(s) = sqrt(s^2+1) - 1, q = u'(s) = s/sqrt(s^2+1) in [0, 1),
u''(s) = (s^2+1)^(-3/2)):
  inner (u <= pi/2): F = 1 - cos u,      F' = sin(u) q,  F'' = cos(u) q^2 + sin(u) u''
  outer (u >  pi/2): F = u - pi/2 + 1,   F' = q,         F'' = u''
  At the switch u = pi/2 (circle s^2 = pi^2/4 + pi): F = 1 on both sides, F' = q on
  both sides (sin = 1), F'' = u'' on both sides (cos = 0, sin = 1).  So F is C^2.
  Near the origin f = 1 - cos(sqrt(rho+1) - 1) is analytic in rho = e1^2 + e2^2.
P1 proved: f is C^2 (radial, F C^2, analytic near 0).  |df/de2| = F'(s)|e2|/s <= F'(s)
   <= q(s) < 1, and along e1 = 0 in the outer region |df/de2| = q(s) -> 1.
   kf = 1, NOT attained.
P2 proved: 1 - cos 0 = 0.
P3 proved: 1 - cos u > 0 for 0 < u <= pi/2; u - pi/2 + 1 > 1 outside; f ~ |e| -> oo.
P4 proved: radial.
P5 proved: F'(s) > 0 for s > 0 (sin u > 0 on (0, pi/2], q > 0), df/de1 = F'(s) e1/s.
P6 proved: df/de1 = e1 F'(s)/s with F'(s)/s = sin(u)/sqrt(s^2+1) (inner) or
   1/sqrt(s^2+1) (outer), in [0, 1]: k = 1, h = F'(s)/s.
P7 proved: f is C^2 on R^2 (see above); the third derivative jumps, which is allowed.
P8 proved: |df/de2| <= |e2| F'(s)/s <= |e2| -> 0.
Gains (paper's circle gains for design 4): V = 0.5 + 0.25 = 0.75 <= 0.75;
   W = 1.0 + 0.6*0.5*1 + 0.7 = 2.0 <= 2.0 (margin exactly 0 in decimal; ok).
Exit status 0.
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "C^2 cosine design"
description = "design 4 with the switch at u = pi/2, where value, slope and curvature match"
u = sp.sqrt(e1**2 + e2**2 + 1) - 1
f = sp.Piecewise((1 - sp.cos(u), u <= sp.pi / 2), (u - sp.pi / 2 + 1, True))

gains = {
    "paper_circle": dict(k1=0.25, k2=0.7, lam=0.6, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
