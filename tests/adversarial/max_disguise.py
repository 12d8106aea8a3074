"""max(rho/2, sqrt(rho) - 1/2) = rho/2 everywhere ((sqrt(rho) - 1)^2 >= 0): radial only up to
rewriting the Piecewise conditions, kf infinite like the baseline (38)."""
import sympy as sp
e1, e2 = sp.symbols("e1 e2", real=True)
r = e1**2 + e2**2
f = sp.Max(r/2, sp.sqrt(r) - sp.Rational(1,2))
