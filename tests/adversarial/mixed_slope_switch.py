"""A switch across the line e1 = 1 that leaves f and df/de2 continuous but
not the mixed second derivative: log(1 + rho) + atan(e1) q for e1 >= 1 and
log(1 + rho) + (pi/4) q otherwise, with q = e2^2/(1 + e2^2).

By hand: atan(1) = pi/4, so f is continuous across e1 = 1, and so is
df/de2 = 2 e2/(1 + rho) + c(e1) 2 e2/(1 + e2^2)^2 (c = atan(e1) or pi/4).
d2f/de1de2 = -4 e1 e2/(1 + rho)^2 + c'(e1) 2 e2/(1 + e2^2)^2 has c' = 1/(1 + e1^2)
on the right and 0 on the left: at (1, 1) the limits are -4/9 + 1/4 = -7/36
and -4/9, so P7 fails.  df/de1 = 2 e1/(1 + rho) + c'(e1) q jumps too (by
1/4 at (1, 1)): P1, P5 and P6 fail.  f(0, 0) = 0 (P2); not radial (P4)."""
import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
q = e2**2 / (1 + e2**2)
f = sp.Piecewise((sp.log(1 + rho) + sp.atan(e1) * q, e1 >= 1), (sp.log(1 + rho) + sp.pi / 4 * q, True))
