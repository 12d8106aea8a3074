"""Unusable: f = log(1 + rho) (e1^2/rho + e2^2/rho) is 0/0 at the origin (red team 26).  Substituting
e1 = 0 first left e2^2/e2^2, which SymPy makes 1, so the loader saw f(0, 0) = 0; with
--trust-search P1 was then "proved" (grad f(0) = 0)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
rho = e1**2 + e2**2
f = sp.log(1 + rho) * (e1**2 / rho + e2**2 / rho)
