"""Unusable: with its params f = log(1 + rho) (1 + c/d) is log(1 + rho) (1 + 0/0), which has no
value anywhere (red team 26).  SymPy's subs with a dict replaced c first, so 0/d became 0 before
d = 0 came in, and all of P1-P8 were "proved" of log(1 + rho)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
c, d = sp.symbols("c d", real=True)
f = sp.log(1 + e1**2 + e2**2) * (1 + c / d)
params = {c: 0, d: 0}
