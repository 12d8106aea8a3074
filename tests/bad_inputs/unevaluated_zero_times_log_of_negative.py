"""Unusable: f = log(1 + rho) + 0 log(-1 - rho), built with evaluate=False, has no real value
anywhere: log(-1 - rho) has none (red team 27).  Rebuilt with SymPy's evaluation, 0 times it
was the number 0, and P1-P8 were proved of log(1 + rho)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
rho = e1**2 + e2**2
f = sp.Add(sp.log(1 + rho), sp.Mul(0, sp.log(-1 - rho), evaluate=False), evaluate=False)
