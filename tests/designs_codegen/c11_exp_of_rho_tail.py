"""sqrt(1 + rho) - 1 + (1 - exp(-rho))/2: F'(s) = s/sqrt(1 + s^2) + s exp(-s^2),
whose tail form in t = 1/s holds exp(-1/t^2).  Not verified (the kernel leaves
P1, P3 and P6 unknown): generated with --force only."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
rho = e1**2 + e2**2
f = sp.sqrt(1 + rho) - 1 + sp.Rational(1, 2) * (1 - sp.exp(-rho))
