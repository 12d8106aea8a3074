"""Unusable as written: d/de1 sign(e1) does not exist on the line e1 = 0 (the difference quotient
is 1/h there), but SymPy differentiates sign's Piecewise branch by branch and gave 0, so P1-P8
were proved of log(1 + rho) (red team 27)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
f = sp.log(1 + e1**2 + e2**2) + sp.Derivative(sp.sign(e1), e1)
