"""Unusable: with c = d = 0, f = log(1 + rho)(e1 + c)/(e1 + d) is log(1 + rho) e1/e1, which has no
value on the line e1 = 0 (red team 27).  Putting the params in with SymPy's evaluation made e1/e1
the number 1, and P1-P8 were proved of log(1 + rho)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
c, d = sp.symbols("c d", real=True)
f = sp.log(1 + e1**2 + e2**2) * (e1 + c) / (e1 + d)
params = {c: 0, d: 0}
