"""Unusable: log(2 (e1 - 7)) and log(e1 - 7) have no real value for e1 < 7 (red team 22).  In SymPy's
complex arithmetic their imaginary parts, both pi, cancel, so f itself evaluates to the real
log(1 + rho) at every point, and f(0, 0) = log 14 - log 7 - log 2 = 0 had P2 "proved"."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
f = sp.log(1 + e1**2 + e2**2) + sp.log(2*(e1 - 7)) - sp.log(e1 - 7) - sp.log(2)
